#!/usr/bin/env bash
# Chapter 19's benchmark (benchmarks/19_ndim_gpu.md): the default scene, one
# n-cube and 250 n-cubes at n = 4, 8, 12, at 1920x1080, validation off; one
# JSON line per run, each preceded by a line naming its arguments and followed
# by the chapter's CPU time per frame (writing the transforms, recording the
# draws). The largest cases also with the edges in chapter 18's order
# (--edge-order axis), where a vertex's edges lie far apart. Fewer frames
# where a frame takes long (the median of a few frames is still a median).
#   benchmarks/19_ndim_gpu.sh [BIN_DIR] [FRAME_SCALE] [PATH]
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
  echo "# 19_ndim_gpu $* --frames $frames"
  "$bin/19_ndim_gpu" "$path" --no-validation --size "$size" --benchmark --frames "$frames" "$@" \
    2>"$log"
  grep -h "CPU transforms" "$log" || true
}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
echo "# 03_swapchain (an empty frame) --frames $((300 * scale))"
"$bin/03_swapchain" "$path" --no-validation --size "$size" --benchmark --frames $((300 * scale)) \
  2>/dev/null
run 300 --scene default
run 300 --scene cube --dim 4
run 300 --scene cube --dim 8
run 30 --scene cube --dim 12
run 30 --scene cube --dim 12 --edge-order axis
run 100 --scene many --dim 4
run 10 --scene many --dim 8
run 3 --scene many --dim 12
run 3 --scene many --dim 12 --edge-order axis
