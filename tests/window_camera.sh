#!/usr/bin/env bash
# Chapter 11's captured cursor and Escape, run under xvfb-run by CTest with a
# real window manager. Open-ended (no --frames), so the chapter takes its
# input from the window: the runner captures the cursor before the first
# frame and the chapter says so. Then, each step waiting for the chapter to
# say it reacted (never for the clock):
#   Escape        -> "cursor released"  (the first Escape must not quit)
#   a click       -> "cursor captured"  (the chapter is still running)
#   Escape        -> "cursor released"
#   Escape        -> the chapter exits 0 with a clean validation report.
#   window_camera.sh CHAPTER_EXE OUT_DIR TITLE
set -u
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3
mkdir -p "$out"
start_wm
start_chapter "$out/$(basename "$exe").escape.stderr" "$exe" --validation --size 320x240
window=$(find_window "$title") || fail "no window titled '$title' appeared"
wait_line 0 "cursor captured"
wait_line 0 "presented a frame at 320x240"

m=$(mark)
xdotool key --window "$window" Escape || fail "xdotool could not press Escape"
wait_line "$m" "cursor released"

# A click in the window captures the cursor again: proof that the first
# Escape did not quit.
m=$(mark)
xdotool mousemove --window "$window" 160 120 click 1 || fail "xdotool could not click"
wait_line "$m" "cursor captured"

m=$(mark)
xdotool key --window "$window" Escape || fail "xdotool could not press Escape"
wait_line "$m" "cursor released"
close_with_escape "$window"
grep -v '^\[validation' "$err"
[ "$status" -eq 0 ] || fail "exit status $status"
grep -q "validation: 0 warnings, 0 errors" "$err" || fail "validation was not clean"
[ "$(grep -c "cursor released" "$err")" -eq 2 ] || fail "expected exactly two releases"
echo PASS
