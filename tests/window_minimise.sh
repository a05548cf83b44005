#!/usr/bin/env bash
# Minimise and restore, run under xvfb-run by CTest with a real window manager
# (openbox iconifies the window as a desktop would; on X11 the framebuffer
# keeps its size, so only the window manager's state says it is minimised).
# The chapter must notice (it says "minimised after N frames: waiting"), then
# neither record frames nor spin while minimised: its main thread must sleep
# in the event wait, using no CPU time; on restore it must recreate its
# swapchain and present again, then quit on Escape with exit 0, a clean
# validation report and the triangle in its screenshot.
#   window_minimise.sh CHAPTER_EXE OUT_DIR TITLE CHECKER [PICTURE: triangle (default) or any]
set -u
# shellcheck source=window_test_helpers.sh
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3 checker=$4 picture=${5:-triangle}
mkdir -p "$out"
shot="$out/$(basename "$exe").minimise.png"
rm -f "$shot"
start_wm
start_chapter "$out/$(basename "$exe").minimise.stderr" "$exe" --validation --size 320x240 --screenshot "$shot"
window=$(find_window "$title") || fail "no window titled '$title' appeared"
wait_line 0 "presented a frame at 320x240"

m=$(mark)
xdotool windowminimize "$window" || fail "xdotool could not minimise the window"
wait_line "$m" "minimised after [0-9]+ frames: waiting"
frames=$(tail -n "+$((m + 1))" "$err" | grep -oE "minimised after [0-9]+" | grep -oE "[0-9]+$")

# While minimised: the main thread must be asleep. Sample its CPU time and
# state 20 times; a thread blocked in glfwWaitEvents is charged nothing (a
# tick or two at most, for the window manager's events), while one that polls
# in a loop is charged most of the time it is given, however loaded the
# machine. The samples are spread out only to give a spinning loop the chance
# to show itself: a sleeping thread passes whatever the spacing. A slow
# machine may charge a sleeping thread more ticks for the same few events, so
# the ticks alone are not the verdict: the thread fails only if it was also
# seen asleep in fewer than 15 of the samples (a polling loop is seen running
# in nearly all of them).
before=$(main_thread_ticks)
sleeping=0
for _ in $(seq 20); do
  state=$(awk '{print $3}' "/proc/$pid/task/$pid/stat")
  [ "$state" = S ] && sleeping=$((sleeping + 1))
  sleep 0.05
done
used=$(($(main_thread_ticks) - before))
echo "while minimised: main thread asleep in $sleeping of 20 samples, $used clock ticks of CPU time"
[ "$used" -le 3 ] || [ "$sleeping" -ge 15 ] ||
  fail "the chapter spins while minimised ($used clock ticks of CPU time, asleep in $sleeping of 20 samples)"
grep -q "presented a frame" <(tail -n "+$((m + 1))" "$err") && fail "a frame was presented while minimised"

m=$(mark)
wmctrl -i -a "$window" || fail "wmctrl could not restore the window"
wait_line "$m" "restored, still at $frames frames"
wait_line "$m" "swapchain recreated at 320x240"
wait_line "$m" "presented a frame at 320x240"
close_with_escape "$window"
grep -v '^\[validation' "$err"
expect_clean_exit "$shot" 320 240
check_last_frame "$picture" "$checker" "$shot" 320 240 || fail "the frame after restoring is not the chapter's picture"
echo PASS
