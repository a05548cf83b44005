#!/usr/bin/env bash
# Chapter 18's keys, in a real window on its own X server with a window manager.
# Open-ended (no --frames), so the chapter takes its input from the window.
# Each step waits for the line the chapter writes when it reacts (never for
# the clock):
#   1 and F4 held       -> "turning in plane (0,1)", "moving along axis 3"
#   R while they are held -> "reset 1 turned planes and 1 moved axes": the
#                          keys really changed the angle and the position
#   Shift and 2 held    -> "turning in plane (0,2) backwards"
#   O, Space            -> "orthographic projection", "spin paused"
#   Escape              -> exit 0 with a clean validation report.
#   window_ndim_keys.sh CHAPTER_EXE OUT_DIR TITLE
set -u
# shellcheck source=window_test_helpers.sh
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3
mkdir -p "$out"
open_in_window "$out/$(basename "$exe").window_keys.stderr" "$title" "$exe" --validation \
  --size 320x240

m=$(mark)
xdotool keydown --window "$window" 1 F4 || fail "xdotool could not press 1 and F4"
wait_line "$m" "turning in plane \(0,1\)$"
wait_line "$m" "moving along axis 3$"
xdotool key --window "$window" r || fail "xdotool could not press R"
wait_line "$m" "reset 1 turned planes and 1 moved axes"
xdotool keyup --window "$window" 1 F4

# Held, not tapped: turning follows the keys held when a frame starts, and a
# press and release that both arrive between two frames hold nothing (under
# load that failed 3 runs in 9).
m=$(mark)
xdotool keydown --window "$window" Shift_L 2 || fail "xdotool could not press Shift and 2"
wait_line "$m" "turning in plane \(0,2\) backwards"
xdotool keyup --window "$window" 2 Shift_L

m=$(mark)
xdotool key --window "$window" o space || fail "xdotool could not press O and Space"
wait_line "$m" "orthographic projection"
wait_line "$m" "spin paused"

quit_with_escape "$window"
echo PASS
