#!/usr/bin/env bash
# Window resize test, run under xvfb-run by CTest: opens a chapter in a window
# with validation, resizes the window twice with xdotool, closes it with Esc,
# and checks that the swapchain was recreated at each size, that the last
# frame has the last size and the right picture, and that validation stayed
# silent.
#   window_resize.sh CHAPTER_EXE OUT_DIR TITLE CHECKER
set -u
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3 checker=$4
mkdir -p "$out"
name=$(basename "$exe")
shot="$out/$name.resized.png" err="$out/$name.resized.stderr"
rm -f "$shot"
"$exe" --validation --size 320x240 --screenshot "$shot" >/dev/null 2>"$err" &
pid=$!
window=$(find_window "$title")
fail() { echo "FAIL: $*"; cat "$err"; kill "$pid" 2>/dev/null; exit 1; }
[ -n "$window" ] || fail "no window titled '$title' appeared"
wait_for() {  # a line in stderr, up to 20 s
  for _ in $(seq 200); do grep -q "$1" "$err" && return 0; sleep 0.1; done
  fail "stderr never said: $1"
}
sleep 0.5
xdotool windowsize "$window" 500 300
wait_for "swapchain recreated at 500x300"
xdotool windowsize "$window" 200 400
wait_for "swapchain recreated at 200x400"
sleep 0.5
xdotool key --window "$window" Escape
wait "$pid"
status=$?
cat "$err"
[ $status -eq 0 ] || fail "exit status $status"
grep -q "validation: 0 warnings, 0 errors" "$err" || fail "validation was not clean"
grep -q "wrote .* (200x400)" "$err" || fail "the last frame was not 200x400"
check_triangle "$checker" "$shot" 200 400 || fail "the last frame is not the triangle"
echo PASS
