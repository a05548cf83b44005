#!/bin/sh
# Chapter 17's light binning on a GPU (benchmarks/17_tiled_deferred.md,
# "Binning"): the checks first, then the sweep of --cull tiled against
# --cull binned. Run on the device machine (../shared/DEVICE.md), after its
# set-up, from the project's root:
#
#   benchmarks/17_tiled_deferred_binned.sh [BIN_DIR] [WxH]
#
# BIN_DIR defaults to build/release/bin, the size to 1920x1080. LIGHTS (the
# sweep's counts, default "65536 1048576"), REPEAT (runs of each, default 3)
# and FRAMES (per run, default 100) change the sweep.
set -u
bin=${1:-build/release/bin}
size=${2:-1920x1080}
exe=$bin/17_tiled_deferred
status=0

# check ARGS...: one run of the chapter; its own report, and its exit status.
check() {
    echo "\$ 17_tiled_deferred $*"
    log=$(mktemp)
    "$exe" "$@" >"$log" 2>&1
    rc=$?
    grep -E "^17_tiled_deferred: " "$log" | grep -v -E "presented|offscreen, " | sed 's/^/    /'
    echo "    exit $rc"
    [ "$rc" -eq 0 ] || status=1
    rm -f "$log"
}

echo "== checks"
# Lists (as sets, tile by tile) and pictures of both culls, with validation,
# synchronisation validation included; a million lights overflow some lists
# at this size, whose counts are then compared.
check --offscreen --validation --frames 3 --size "$size" --lights 65536 --verify bins
check --offscreen --validation --frames 3 --size "$size" --lights 1048576 --verify bins
# Binned culling against chapter 16's brute-force lighting (both shades).
check --offscreen --validation --frames 3 --size 640x480 --lights 16384 --verify brute
# The frames themselves, validated, at a million lights.
check --offscreen --validation --frames 5 --size "$size" --lights 1048576 --shade compute
check --offscreen --validation --frames 5 --size "$size" --lights 1048576 --shade fragment
# The picture against lavapipe's golden image, both culls (as CTest runs it).
for cull in binned tiled; do
    echo "\$ vkt_chapter_check ... --cull $cull"
    "$bin/vkt_chapter_check" --exe "$exe" --out "${TMPDIR:-/tmp}" --name "gpu.17.$cull" \
        --golden tests/golden/17_tiled_deferred.png --pixel 0,0,39,39,56 --pixel 319,0,39,39,56 \
        -- --offscreen --validation --frames 10 --size 320x240 --cull "$cull" 2>&1 |
        grep -E "^picture|^FAIL" | sed 's/^/    /'
done

echo "== sweep"
echo "\$ LIGHTS=\"${LIGHTS:-65536 1048576}\" scripts/bench-lights.sh --binned $exe --size $size --frames ${FRAMES:-100} --repeat ${REPEAT:-3} --shade both"
LIGHTS="${LIGHTS:-65536 1048576}" scripts/bench-lights.sh --binned "$exe" --size "$size" \
    --frames "${FRAMES:-100}" --repeat "${REPEAT:-3}" --shade both 2>&1
exit $status
