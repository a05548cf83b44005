#!/usr/bin/env bash
# Chapter 22's benchmark (book/perf_22_shadows.md): the scene with 1, 2, 3
# and 4 cascades, and chapter 03's empty frame, at one size, validation off,
# headless. Three rounds, the settings taken in turn within each round. One
# JSON line per run (GPU scopes "shadow": every cascade's depth pass, "lit":
# the lit pass), each preceded by a line naming its arguments.
#   benchmarks/22_shadows.sh [BIN_DIR] [WxH] [FRAMES]
set -euo pipefail
bin=${1:-build/release/bin}
size=${2:-1920x1080}
frames=${3:-300}
for round in 1 2 3; do
  echo "# round $round: 03_swapchain (an empty frame) --frames $frames"
  "$bin/03_swapchain" --headless --no-validation --size "$size" --benchmark --frames "$frames" \
    2>/dev/null
  for cascades in 1 2 3 4; do
    echo "# round $round: 22_shadows --cascades $cascades --frames $frames"
    "$bin/22_shadows" --headless --no-validation --size "$size" --benchmark --frames "$frames" \
      --cascades "$cascades" 2>/dev/null
  done
done
