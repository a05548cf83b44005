#!/usr/bin/env bash
# From a fresh machine to a chapter's picture, in one command (as root, or as a
# user with sudo):
#   scripts/quickstart.sh [NN_name]
# Installs the packages (scripts/install-deps.sh: Debian 12 with
# bookworm-backports, Debian 13 or Ubuntu 24.04 with their own archive; on any
# other system it changes nothing, says what to install, and this stops), configures and builds
# the release preset, and runs a chapter (the newest by default): in a window
# when there is a display, else headless, writing its picture to NN_name.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release
cmake --build --preset release

chapters=(chapters/[0-9][0-9]_*/)  # a glob sorts its matches: the last is the newest chapter
chapter=${1:-$(basename "${chapters[-1]}")}
exe=build/release/bin/$chapter
[ -x "$exe" ] || { echo "no chapter named '$chapter' (see chapters/)" >&2; exit 2; }
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  echo "running $chapter in a window (Esc closes it)"
  "$exe"
else
  "$exe" --headless --frames 60 --screenshot "$chapter.png"
  echo "no display: $chapter ran headless; its picture is $PWD/$chapter.png"
fi
