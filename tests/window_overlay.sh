#!/usr/bin/env bash
# Overlay test, run under xvfb-run by CTest with a real window manager: the
# chapter runs in a window with validation and its overlay (chapter 21). The
# chapter says where each widget is ("overlay: 'LABEL' at X,Y WxH"); the
# script moves the pointer to the middle of WIDGET, clicks, and waits until
# the chapter says the setting changed as CHANGE says ("overlay: CHANGE").
# Then it closes the window: exit 0, clean validation, and a screenshot.
#   window_overlay.sh CHAPTER_EXE OUT_DIR TITLE WIDGET CHANGE [CHAPTER ARGS...]
set -u
# shellcheck source=window_test_helpers.sh
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3 widget=$4 change=$5
shift 5
mkdir -p "$out"
shot="$out/$(basename "$exe").overlay.png"
rm -f "$shot"
start_wm
start_chapter "$out/$(basename "$exe").overlay.stderr" "$exe" --validation --size 640x480 \
  --screenshot "$shot" "$@"
window=$(find_window "$title") || fail "no window titled '$title' appeared"
wait_line 0 "presented a frame at 640x480"
wait_line 0 "overlay: '$widget' at [0-9]+,[0-9]+ [0-9]+x[0-9]+"
# The widget's last reported place (it may move once the panel has its size).
read -r x y w h < <(grep -oE "overlay: '$widget' at [0-9]+,[0-9]+ [0-9]+x[0-9]+" "$err" | tail -n 1 |
  sed -E 's/.* at ([0-9]+),([0-9]+) ([0-9]+)x([0-9]+)/\1 \2 \3 \4/')
m=$(mark)
xdotool mousemove --window "$window" $((x + w / 2)) $((y + h / 2)) ||
  fail "xdotool could not move the pointer"
xdotool click --window "$window" 1 || fail "xdotool could not click"
wait_line "$m" "overlay: $change"
close_with_wm "$window"
grep -v '^\[validation' "$err"
expect_clean_exit "$shot" 640 480
echo PASS
