#!/usr/bin/env bash
# Window resize test, run under xvfb-run by CTest with a real window manager:
# the chapter runs open-ended in a window with validation; the script resizes
# the window to a larger size, to a tiny one and to one of odd width, each time
# waiting until the chapter has recreated its swapchain and presented a frame
# at that size, then closes the window with the window manager's close. The
# chapter must exit 0 with a clean validation report and a screenshot of its
# last frame, at the last size, showing the triangle.
#   window_resize.sh CHAPTER_EXE OUT_DIR TITLE CHECKER [PICTURE: triangle (default) or any]
set -u
# shellcheck source=window_test_helpers.sh
. "$(dirname "$0")/window_test_helpers.sh"
exe=$1 out=$2 title=$3 checker=$4 picture=${5:-triangle}
mkdir -p "$out"
shot="$out/$(basename "$exe").resized.png"
rm -f "$shot"
start_wm
start_chapter "$out/$(basename "$exe").resized.stderr" "$exe" --validation --size 320x240 --screenshot "$shot"
window=$(find_window "$title") || fail "no window titled '$title' appeared"
wait_line 0 "presented a frame at 320x240"
resize "$window" 640 480   # larger than the start: the read-back buffers grow
resize "$window" 8 8       # tiny
resize "$window" 333 201   # odd width: rows are not a multiple of 4 or 8 pixels
close_with_wm "$window"
grep -v '^\[validation' "$err"
expect_clean_exit "$shot" 333 201
check_last_frame "$picture" "$checker" "$shot" 333 201 || fail "the last frame is not the chapter's picture"
echo PASS
