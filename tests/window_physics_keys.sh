#!/usr/bin/env bash
# Chapter 14's P key, in a real window on its own X server with a window
# manager. Open-ended (no --frames), so the chapter takes its input from the
# window. Each step waits for the line the chapter writes when it reacts
# (never for the clock):
#   P          -> "P: added a 10-level pyramid and a 20-box tower (75 boxes,
#                 1077 bodies now)": 1000 boxes, the floor and the ramp, and
#                 the stacks' 55 + 20
#   P again    -> "P: the pyramid and the tower are already there"
#   Escape     -> exit 0 with a clean validation report.
#   window_physics_keys.sh CHAPTER_EXE OUT_DIR TITLE
set -u
# shellcheck source=window_test_helpers.sh
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3
mkdir -p "$out"
open_in_window "$out/$(basename "$exe").window_keys.stderr" "$title" "$exe" --validation \
  --size 320x240

m=$(mark)
xdotool key --window "$window" p || fail "xdotool could not press P"
wait_line "$m" "14_physics: P: added a 10-level pyramid and a 20-box tower \(75 boxes, 1077 bodies now\)"

# A second P adds nothing: the stacks stand where the first put them.
m=$(mark)
xdotool key --window "$window" p || fail "xdotool could not press P again"
wait_line "$m" "14_physics: P: the pyramid and the tower are already there"

quit_with_escape "$window"
echo PASS
