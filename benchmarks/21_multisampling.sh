#!/usr/bin/env bash
# Chapter 21's benchmark (book/perf_21_multisampling.md): the same scene at
# 1 sample, 4 samples, 4 samples with sample shading, and 8 samples where the
# device offers them, and chapter 03's empty frame, at one size, validation
# off, headless. Three rounds, the settings taken in turn within each round, so
# a change in the machine's load touches all of them alike. One JSON line per
# run, each preceded by a line naming its arguments; a count the device does
# not offer prints the chapter's one-line refusal instead.
#   benchmarks/21_multisampling.sh [BIN_DIR] [WxH] [FRAMES]
set -uo pipefail
bin=${1:-build/release/bin}
size=${2:-1920x1080}
frames=${3:-300}
for round in 1 2 3; do
  echo "# round $round: 03_swapchain (an empty frame) --frames $frames"
  "$bin/03_swapchain" --headless --no-validation --size "$size" --benchmark --frames "$frames" \
    2>/dev/null
  for args in "--samples 1" "--samples 4" "--samples 4 --sample-shading 1" "--samples 8"; do
    echo "# round $round: 21_multisampling $args --frames $frames"
    # shellcheck disable=SC2086  # args are words
    "$bin/21_multisampling" --headless --no-validation --size "$size" --benchmark \
      --frames "$frames" $args 2>&1 | grep -E '^\{|error:' || true
  done
done
