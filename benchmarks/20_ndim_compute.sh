#!/usr/bin/env bash
# Chapter 20's benchmark (benchmarks/20_ndim_compute.md): one n-cube and 250
# n-cubes at n = 4, 8, 12, at 1920x1080, validation off, with the lines drawn
# by the graphics pipeline, the compute rasteriser and the binned one
# (RASTERS, default "graphics compute binned"); one JSON line per
# run (--benchmark: frame times and the GPU scopes "pose", "transform" and
# "raster"), each preceded by a line naming its arguments. Fewer frames where a frame takes
# long (the median of a few frames is still a median).
#   benchmarks/20_ndim_compute.sh [BIN_DIR] [FRAME_SCALE] [PATH]
# FRAME_SCALE (default 1) multiplies every frame count: a fast GPU wants more.
# PATH: headless (default) or offscreen (a GPU driver without
# VK_EXT_headless_surface).
set -euo pipefail
bin=${1:-build/release/bin}
scale=${2:-1}
path=--${3:-headless}
size=1920x1080
run() {
  local frames=$(($1 * scale))
  shift
  for raster in ${RASTERS:-graphics compute binned}; do
    echo "# 20_ndim_compute $* --raster $raster --frames $frames"
    "$bin/20_ndim_compute" "$path" --no-validation --size "$size" --benchmark \
      --frames "$frames" "$@" --raster "$raster" 2>"$log"
  done
}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
echo "# 03_swapchain (an empty frame) --frames $((300 * scale))"
"$bin/03_swapchain" "$path" --no-validation --size "$size" --benchmark --frames $((300 * scale)) \
  2>/dev/null
run 300 --scene cube --dim 4
run 200 --scene cube --dim 8
run 20 --scene cube --dim 12
run 200 --scene many --dim 4
run 20 --scene many --dim 8
run 3 --scene many --dim 12
