#!/usr/bin/env bash
# Resize storm, run under xvfb-run by CTest: a fixed-length windowed run of a
# chapter while xdotool resizes its window as fast as it can, so that resizes
# land on any frame, the last one included. The run must end by itself with
# exit status 0, a clean validation report, and a screenshot of one of the
# sizes the window had, showing the triangle. One size is larger than the
# start, so the screenshot read-back buffers must grow mid-run.
#   window_resize_storm.sh CHAPTER_EXE OUT_DIR TITLE FRAMES CHECKER
set -u
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3 frames=$4 checker=$5
mkdir -p "$out"
name=$(basename "$exe")
shot="$out/$name.storm.png" err="$out/$name.storm.stderr"
rm -f "$shot"
"$exe" --validation --frames "$frames" --size 320x240 --screenshot "$shot" >/dev/null 2>"$err" &
pid=$!
window=$(find_window "$title")
[ -n "$window" ] || { echo "FAIL: no window titled '$title' appeared"; cat "$err"; kill "$pid"; exit 1; }
sizes=("300 200" "640 480" "200 300" "320 240" "250 250")
i=0
while kill -0 "$pid" 2>/dev/null; do
  xdotool windowsize "$window" ${sizes[$((i % 5))]} 2>/dev/null
  i=$((i + 1))
done
wait "$pid"
status=$?
grep -v '^\[validation' "$err" | grep -v 'swapchain recreated' || true
echo "$(grep -c 'swapchain recreated' "$err") recreations during $i resize requests"
[ $status -eq 0 ] || { echo "FAIL: exit status $status"; cat "$err"; exit 1; }
grep -q "validation: 0 warnings, 0 errors" "$err" || { echo "FAIL: validation was not clean"; cat "$err"; exit 1; }
size=$(grep -oE "wrote .* \((300x200|640x480|200x300|320x240|250x250)\)" "$err" | grep -oE '[0-9]+x[0-9]+' | tail -n 1)
[ -n "$size" ] || { echo "FAIL: no screenshot of a known size"; exit 1; }
check_triangle "$checker" "$shot" "${size%x*}" "${size#*x}" || { echo "FAIL: the $size screenshot is not the triangle"; cat "$err"; exit 1; }
[ "$(grep -c 'swapchain recreated' "$err")" -ge 2 ] || { echo "FAIL: the window was hardly resized"; exit 1; }
echo PASS
