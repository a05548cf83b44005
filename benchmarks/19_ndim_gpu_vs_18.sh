#!/usr/bin/env bash
# shellcheck disable=SC2086  # $args and $ch are split into words on purpose
# Chapters 18 and 19 side by side in one run (benchmarks/19_ndim_gpu.md):
# the same scenes, frame counts and size, one after the other, then the
# 250 12-cubes and one 12-cube at 64x48, where drawing the lines costs
# little and what is left is the work per vertex.
#   benchmarks/19_ndim_gpu_vs_18.sh [BIN_DIR]
set -u
bin=${1:-build/release/bin}
for args in "300 --scene default" "300 --scene cube --dim 4" "300 --scene cube --dim 8" "30 --scene cube --dim 12" "100 --scene many --dim 4" "10 --scene many --dim 8" "3 --scene many --dim 12"; do
  set -- $args; f=$1; shift
  for ch in 18_ndim_cpu 19_ndim_gpu; do
    echo "# $ch $* --frames $f 1920x1080"
    $bin/$ch --headless --no-validation --size 1920x1080 --benchmark --frames $f "$@" 2>/dev/null
  done
done
for ch in 18_ndim_cpu 19_ndim_gpu "19_ndim_gpu --edge-order axis"; do
  echo "# $ch --scene many --dim 12 --frames 3 64x48"
  $bin/$ch --headless --no-validation --size 64x48 --benchmark --frames 3 --scene many --dim 12 2>/dev/null
  echo "# $ch --scene cube --dim 12 --frames 30 64x48"
  $bin/$ch --headless --no-validation --size 64x48 --benchmark --frames 30 --scene cube --dim 12 2>/dev/null
done
