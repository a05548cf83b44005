#!/usr/bin/env bash
# Chapter 18's benchmark (benchmarks/18_ndim_cpu.md): the default scene, one
# n-cube and 250 n-cubes at n = 4, 8, 12, at 1920x1080, validation off; one
# JSON line per run, each preceded by a line naming its arguments and followed
# by the chapter's CPU-only time. Fewer frames
# where a frame takes long (the median of a few frames is still a median).
#   benchmarks/18_ndim_cpu.sh [BIN_DIR]
set -euo pipefail
bin=${1:-build/release/bin}
size=1920x1080
run() {
  local frames=$1
  shift
  echo "# 18_ndim_cpu $* --frames $frames"
  # stdout: the runner's JSON; stderr: the chapter's own line with the CPU
  # time of the transform, projection and writing of the lines alone.
  "$bin/18_ndim_cpu" --headless --no-validation --size "$size" --benchmark --frames "$frames" "$@" \
    2>"$log"
  grep -h "CPU transform" "$log" || true
}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
echo "# 03_swapchain (an empty frame) --frames 300"
"$bin/03_swapchain" --headless --no-validation --size "$size" --benchmark --frames 300 2>/dev/null
run 300 --scene default
run 300 --scene cube --dim 4
run 300 --scene cube --dim 8
run 60 --scene cube --dim 12
run 60 --scene cube --dim 12 --matrix rows
run 200 --scene many --dim 4
run 30 --scene many --dim 8
run 30 --scene many --dim 8 --matrix rows
run 5 --scene many --dim 12
run 5 --scene many --dim 12 --matrix rows
