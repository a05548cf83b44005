#!/usr/bin/env bash
# Resize storm, run under xvfb-run by CTest with a real window manager: while
# the chapter runs, the script sends resizes as fast as xdotool can, without
# waiting for any, so that they land on every part of the frame loop; then one
# last size that the storm never used, and waits until the chapter has
# presented a frame at it and kept at most one retired swapchain. Whatever happened in between, the end is known:
# close, exit 0, clean validation, and a screenshot of the triangle at the last
# size. One storm size is larger than the start (the read-back buffers grow).
#   window_resize_storm.sh CHAPTER_EXE OUT_DIR TITLE RESIZES CHECKER [PICTURE: triangle (default) or any]
set -u
# shellcheck source=window_test_helpers.sh
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3 resizes=$4 checker=$5 picture=${6:-triangle}
mkdir -p "$out"
shot="$out/$(basename "$exe").storm.png"
rm -f "$shot"
start_wm
start_chapter "$out/$(basename "$exe").storm.stderr" "$exe" --validation --size 320x240 --screenshot "$shot"
window=$(find_window "$title") || fail "no window titled '$title' appeared"
wait_line 0 "presented a frame at 320x240"
sizes=("300 200" "640 480" "200 300" "320 240" "250 250" "17 9")
for i in $(seq 0 $((resizes - 1))); do
  read -r w h <<<"${sizes[$((i % ${#sizes[@]}))]}"
  xdotool windowsize "$window" "$w" "$h" 2>/dev/null || fail "xdotool could not resize the window"
done
resize "$window" 301 199
echo "$(grep -c 'swapchain recreated' "$err") recreations for $resizes + 1 resize requests"
# The storm retired many swapchains; as frames go on at the last size their
# presents end and they must go, down to at most the newest one.
last=$(grep -n 'swapchain recreated' "$err" | tail -n 1 | cut -d: -f1)
wait_line "$((last - 1))" "retired swapchains down to [01] kept"
grep 'retired swapchains down to' "$err" | tail -n 1
# STORM_RETIREMENT: how old swapchains must have been retired, as the
# recreation lines say it ("their present fences signal", "a later present ends").
if [ -n "${STORM_RETIREMENT:-}" ] && ! grep -q "retired kept until $STORM_RETIREMENT" "$err"; then
  fail "no recreation line says the old swapchains were kept until $STORM_RETIREMENT"
fi
close_with_wm "$window"
grep -v '^\[validation' "$err" | grep -v -E 'swapchain recreated|presented a frame'
expect_clean_exit "$shot" 301 199
check_last_frame "$picture" "$checker" "$shot" 301 199 || fail "the last frame is not the chapter's picture"
echo PASS
