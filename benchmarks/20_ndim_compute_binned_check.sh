#!/usr/bin/env bash
# Chapter 20's binned rasteriser on a GPU (benchmarks/20_ndim_compute_binned.md):
# first --verify raster with validation on in four scenes at 1920x1080 (the
# binned picture must equal the compute rasteriser's, word for word), then
# 250 12-cubes, binned and compute in turn, three rounds of 400 frames, the
# pixels stored into the target by the resolve pass (--to-target store).
#   benchmarks/20_ndim_compute_binned_check.sh [BIN_DIR]
set -euo pipefail
bin=${1:-build/release/bin}
echo "== checks: --verify raster, validation on"
for scene in "many 12" "many 8" "cube 12" "many 4"; do
  read -r kind dim <<<"$scene"
  echo "\$ 20_ndim_compute --offscreen --validation --frames 3 --size 1920x1080 --scene $kind --dim $dim --raster binned --verify raster"
  "$bin/20_ndim_compute" --offscreen --validation --frames 3 --size 1920x1080 --scene "$kind" \
    --dim "$dim" --raster binned --verify raster 2>&1 | grep -E "verify|validation:"
done
echo "== 250 12-cubes, three rounds of 400 frames, --to-target store"
echo "# 20_ndim_compute --offscreen --no-validation --size 1920x1080 --benchmark --frames 400 --scene many --dim 12 --raster R --to-target store"
for round in 1 2 3; do
  for raster in binned compute; do
    echo "# round $round $raster"
    "$bin/20_ndim_compute" --offscreen --no-validation --size 1920x1080 --benchmark --frames 400 \
      --scene many --dim 12 --raster "$raster" --to-target store 2>/dev/null
  done
done
