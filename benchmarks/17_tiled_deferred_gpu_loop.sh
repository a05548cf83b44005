#!/bin/sh
# Chapter 17 with the lights moved on the GPU (issue 30): the checks, then
# the frame loop at 65,536 and 1,048,576 lights for each shading path, and
# the fragment path's experiment (--shade lists: the same lighting as a
# compute pass; --view heat: the same launch with no light loop). Run on the
# device machine (../shared/DEVICE.md), after its set-up, from the root:
#
#   benchmarks/17_tiled_deferred_gpu_loop.sh [BIN_DIR] [WxH] [BEFORE_EXE]
#
# BIN_DIR defaults to build/release/bin, the size to 1920x1080. BEFORE_EXE,
# if given, is a build of the chapter from before the change (lights moved by
# the CPU), run beside it. REPEAT (runs of each, default 3) and FRAMES (per
# run, default 100) change the sweep. Each benchmark line is the label, a
# tab and the chapter's --benchmark JSON.
set -u
bin=${1:-build/release/bin}
size=${2:-1920x1080}
before=${3:-}
exe=$bin/17_tiled_deferred
repeat=${REPEAT:-3}
frames=${FRAMES:-100}
status=0

check() {  # check ARGS...: one validated run; its own report and its exit status
    echo "\$ 17_tiled_deferred $*"
    log=$(mktemp)
    "$exe" "$@" >"$log" 2>&1
    rc=$?
    grep -E "^17_tiled_deferred: " "$log" | grep -v -E "presented|offscreen, " | sed 's/^/    /'
    echo "    exit $rc"
    [ "$rc" -eq 0 ] || status=1
    rm -f "$log"
}

bench() {  # bench LABEL EXE ARGS...: REPEAT runs, one line each
    label=$1
    program=$2
    shift 2
    i=0
    while [ "$i" -lt "$repeat" ]; do
        line=$("$program" --offscreen --no-validation --benchmark --frames "$frames" \
            --size "$size" "$@" 2>&1 | grep '^{"chapter"')
        printf '%s\t%s\n' "$label" "$line"
        i=$((i + 1))
    done
}

echo "== checks"
# The motion against the CPU and the lists of both culls, at a million lights.
check --offscreen --validation --frames 3 --size "$size" --lights 1048576 --verify bins
check --offscreen --validation --frames 3 --size 640x480 --lights 16384 --verify brute
for shade in compute fragment lists; do
    check --offscreen --validation --frames 5 --size "$size" --lights 1048576 --shade "$shade"
    echo "\$ vkt_chapter_check ... --shade $shade"
    "$bin/vkt_chapter_check" --exe "$exe" --out "${TMPDIR:-/tmp}" --name "gpu.17.$shade" \
        --golden tests/golden/17_tiled_deferred.png --pixel 0,0,39,39,56 --pixel 319,0,39,39,56 \
        -- --offscreen --validation --frames 10 --size 320x240 --shade "$shade" 2>&1 |
        grep -E "^picture|^FAIL" | sed 's/^/    /'
done

echo "== sweep (size $size, $frames frames, $repeat runs each)"
for lights in 65536 1048576; do
    for shade in compute fragment lists; do
        bench "after $shade $lights lit" "$exe" --lights "$lights" --shade "$shade"
    done
done
for shade in fragment lists; do
    bench "after $shade 1048576 heat" "$exe" --lights 1048576 --shade "$shade" --view heat
done
if [ -n "$before" ]; then
    for shade in compute fragment; do
        bench "before $shade 1048576 lit" "$before" --lights 1048576 --shade "$shade"
    done
fi
exit $status
