#!/usr/bin/env bash
# Chapter 11's captured cursor, Escape, walking and mouse look, run under
# xvfb-run by CTest with a real window manager. Open-ended (no --frames), so
# the chapter takes its input from the window: the runner captures the cursor
# before the first frame and the chapter says so. Each step then waits for
# the chapter to say it reacted (never for the clock):
#   W held, Escape -> "cursor released at (x, y, z), yaw Y, pitch P": the
#                     first Escape does not quit, and the camera walked
#                     forward (z went down from the start, 8)
#   a click        -> "cursor captured" (the chapter is still running)
#   the mouse 300 px right, Escape
#                  -> "cursor released at ...": the yaw grew (turned right)
#   Escape         -> the chapter exits 0 with a clean validation report.
# Walking is scaled by the wall-clock frame time, so how far the camera gets
# depends on the speed of the machine; only the direction is checked.
#   window_camera.sh CHAPTER_EXE OUT_DIR TITLE
set -u
# shellcheck source=window_test_helpers.sh
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3
mkdir -p "$out"
open_in_window "$out/$(basename "$exe").window_camera.stderr" "$title" "$exe" --validation \
  --size 320x240 --speed 20
wait_line 0 "cursor captured"

# released_pose MARK: prints "x y z yaw pitch" from the first release after MARK.
released_pose() {
  tail -n "+$(($1 + 1))" "$err" | grep -m1 -oE "cursor released at .*, pitch [-0-9.]+" |
    sed -E 's/[^-0-9. ]+/ /g' | awk '{print $1, $2, $3, $4, $5}'
}

# W down, then Escape: both sent to the window (XSendEvent), so they arrive
# in this order, and the frame that sees the release also sees W held.
m=$(mark)
xdotool keydown --window "$window" w || fail "xdotool could not press W"
xdotool key --window "$window" Escape || fail "xdotool could not press Escape"
wait_line "$m" "cursor released at"
xdotool keyup --window "$window" w
read -r x y z yaw pitch <<<"$(released_pose "$m")"
echo "after W: position ($x, $y, $z), yaw $yaw, pitch $pitch"
awk -v z="$z" 'BEGIN { exit !(z < 7.99) }' || fail "W did not walk forward (z = $z, from 8)"

# A click in the window captures the cursor again: proof that the first
# Escape did not quit.
m=$(mark)
xdotool mousemove --window "$window" 160 120 click 1 || fail "xdotool could not click"
wait_line "$m" "cursor captured"

# The mouse 3 x 100 px to the right, then Escape, all through the X server's
# input queue (XTEST), so again in this order. The first movement after a
# capture only sets where the cursor is (vkt::InputAccumulator), so at least
# 200 px count: 0.5 rad at 0.0025 rad/px.
xdotool windowactivate --sync "$window" || fail "xdotool could not focus the window"
m=$(mark)
xdotool mousemove_relative -- 100 0 mousemove_relative -- 100 0 mousemove_relative -- 100 0 \
  key Escape || fail "xdotool could not move the mouse"
wait_line "$m" "cursor released at"
read -r _ _ _ yaw2 pitch2 <<<"$(released_pose "$m")"
echo "after the mouse: yaw $yaw2, pitch $pitch2"
awk -v a="$yaw" -v b="$yaw2" 'BEGIN { exit !(b > a + 0.1) }' ||
  fail "moving the mouse right did not turn right (yaw $yaw -> $yaw2)"

quit_with_escape "$window"
[ "$(grep -c "cursor released" "$err")" -eq 2 ] || fail "expected exactly two releases"
echo PASS
