#!/bin/sh
# Chapter 20 with the poses built on the GPU (issue 30): the checks, then the
# frame loop for 250 n-cubes (n = 4, 8, 12) and one 12-cube with each
# rasteriser. Run on the device machine (../shared/DEVICE.md), after its
# set-up, from the project's root:
#
#   benchmarks/20_ndim_compute_gpu_poses.sh [BIN_DIR] [BEFORE_BIN_DIR]
#
# BEFORE_BIN_DIR, if given, holds a build of the chapter from before the
# change (the CPU builds the poses), with its own shaders beside it
# (BEFORE_BIN_DIR/../shaders), run beside it. REPEAT (runs of each, default
# 3) and FRAMES (per run, default 200) change the sweep. Each benchmark line
# is the label, a tab and the chapter's --benchmark JSON; 1920x1080, offscreen.
set -u
bin=${1:-build/release/bin}
before=${2:-}
repeat=${REPEAT:-3}
frames=${FRAMES:-200}
status=0

check() {  # check ARGS...: one validated run; its own report and its exit status
    echo "\$ 20_ndim_compute $*"
    log=$(mktemp)
    "$bin/20_ndim_compute" "$@" >"$log" 2>&1
    rc=$?
    grep -E "^20_ndim_compute: (verify|validation)" "$log" | sed 's/^/    /'
    echo "    exit $rc"
    [ "$rc" -eq 0 ] || status=1
    rm -f "$log"
}

bench() {  # bench LABEL DIR ARGS...: REPEAT runs, one line each
    label=$1
    dir=$2
    shift 2
    i=0
    while [ "$i" -lt "$repeat" ]; do
        line=$("$dir/20_ndim_compute" --offscreen --no-validation --benchmark \
            --frames "$frames" --size 1920x1080 "$@" 2>/dev/null | grep '^{"chapter"')
        printf '%s\t%s\n' "$label" "$line"
        i=$((i + 1))
    done
}

echo "== checks"
check --offscreen --validation --frames 30 --size 1920x1080 --scene many --dim 12 --verify cpu
check --offscreen --validation --frames 30 --size 1920x1080 --scene many --dim 8 \
    --raster binned --verify raster
for raster in graphics compute binned; do
    golden=tests/golden/20_ndim_compute.png
    [ "$raster" = graphics ] || golden=tests/golden/20_ndim_compute_compute_raster.png
    echo "\$ vkt_chapter_check ... --raster $raster"
    "$bin/vkt_chapter_check" --exe "$bin/20_ndim_compute" --out "${TMPDIR:-/tmp}" \
        --name "gpu.20.$raster" --golden "$golden" --pixel 0,0,18,18,29 \
        --pixel 319,239,18,18,29 -- --offscreen --validation --frames 10 --size 320x240 \
        --raster "$raster" 2>&1 | grep -E "^picture|^FAIL" | sed 's/^/    /'
done

echo "== sweep (1920x1080, $frames frames, $repeat runs each)"
for raster in graphics compute binned; do
    for dim in 4 8 12; do
        bench "after $raster many $dim" "$bin" --scene many --dim "$dim" --raster "$raster"
        [ -z "$before" ] ||
            bench "before $raster many $dim" "$before" --scene many --dim "$dim" --raster "$raster"
    done
done
exit $status
