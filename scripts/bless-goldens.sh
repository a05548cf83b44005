#!/usr/bin/env bash
# Re-blesses the golden images after a reviewed change:
#   scripts/bless-goldens.sh                 every chapter
#   scripts/bless-goldens.sh 04_triangle     only the chapters named
# It builds the release preset, re-runs every test labelled bless of those
# chapters with VKT_BLESS=1 (the chapter's primary headless test, which
# copies its picture over tests/golden/NN_name.png, and the variants with a
# picture of their own, NN_name_variant.png), and then runs the chapter tests
# normally so the other variants (offscreen, window) are checked against the
# new pictures.
# Look at every changed picture (git diff --stat tests/golden) before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release >/dev/null
cmake --build --preset release
pattern="."
if [ $# -gt 0 ]; then pattern="^chapter\\.($(IFS='|'; echo "$*"))(\\.|\$)"; fi
VKT_BLESS=1 ctest --preset release -L bless -R "$pattern"
ctest --preset release -L chapter
{
  echo "# Golden images"
  echo
  echo "Reference pictures for the chapter regression tests, one per drawing chapter,"
  echo "rendered headless at 320x240 after 10 frames by scripts/bless-goldens.sh."
  echo "The text chapters 01_instance and 02_device have none: their tests check the"
  echo "exit status, a clean validation report and what they print (tests/CMakeLists.txt)."
  echo
  echo "Made with: $(vulkaninfo --summary 2>/dev/null | grep -m1 driverInfo | sed 's/^[[:space:]]*driverInfo *= *//' || echo unknown)"
  echo "on: $(vulkaninfo --summary 2>/dev/null | grep -m1 deviceName | sed 's/^[[:space:]]*deviceName *= *//' || echo unknown)"
} > tests/golden/README.md
git status --short tests/golden
