#!/usr/bin/env bash
# Chapter 23's image-based light: what it costs at start-up, and per frame
# against the uniform sky (the default, page 23's).
#
#   benchmarks/23_materials_ibl.sh [BIN] [RUNS]     (default build/release/bin, 7)
#
# Start-up: RUNS runs of one frame each; each prints the GPU time (timestamps)
# of the precompute, in total and per image. Per frame: RUNS alternating rounds
# of --sky environment and --sky uniform, 100 frames at 320x240 each, --benchmark
# (the 'scene' scope is the pass the two skies differ in). Without a GPU, point
# the loader at lavapipe: VK_DRIVER_FILES=/usr/share/vulkan/icd.d/lvp_icd.json.
set -euo pipefail
bin=${1:-build/release/bin}
runs=${2:-7}
exe="$bin/23_materials"
[ -x "$exe" ] || { echo "23_materials_ibl: no $exe (cmake --build --preset release)"; exit 2; }
echo "# $0 $bin $runs; load average $(cut -d' ' -f1 /proc/loadavg) before; at $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
for run in $(seq "$runs"); do
  echo "# start-up, run $run"
  "$exe" --headless --no-validation --frames 1 --size 320x240 --sky environment 2>&1 | grep "image-based light made"
done
for run in $(seq "$runs"); do
  for sky in environment uniform; do
    echo "# per frame, round $run: --sky $sky --frames 100"
    "$exe" --headless --no-validation --frames 100 --size 320x240 --benchmark --sky "$sky" 2>/dev/null | tail -n 1
  done
done
echo "# load average $(cut -d' ' -f1 /proc/loadavg) after"
