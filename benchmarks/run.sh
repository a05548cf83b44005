#!/usr/bin/env bash
# Benchmarks every drawing chapter with the shared --benchmark flag and prints
# one JSON line per chapter (CPU frame time from the runner's clock, GPU frame
# time from timestamp queries). Validation off: it would dominate the timings.
#   benchmarks/run.sh [BIN_DIR] [FRAMES] [WxH]
# Compare medians and ratios measured in one run; trust absolute times only
# from a real GPU (lavapipe shares the CPU with everything else).
set -euo pipefail
bin=${1:-build/release/bin}
frames=${2:-600}
size=${3:-1280x720}
for exe in "$bin"/[0-9][0-9]_*; do
  name=$(basename "$exe")
  case $name in 01_*|02_*) continue ;; esac   # text chapters draw nothing
  "$exe" --headless --no-validation --frames "$frames" --size "$size" --benchmark 2>/dev/null
done
