#!/usr/bin/env bash
# Chapter 15: one indirect multi-draw against a loop of draws, at 1,025 and
# 62,501 objects, two rounds (alternating, so a change in the machine's load
# shows as a difference between rounds). Validation off. Prints the JSON line
# of --benchmark (the "draw" GPU scope) and the chapter's own line with the CPU
# time to record the draws.
#   benchmarks/15_bindless.sh [BIN_DIR] [FRAMES] > benchmarks/results/15_bindless-<device>.txt
set -euo pipefail
bin=${1:-build/release/bin}
frames=${2:-200}
for round in 1 2; do
  for grid in 32 250; do
    for draw in indirect loop; do
      echo "round $round grid $grid draw $draw load $(cut -d' ' -f1-3 /proc/loadavg)"
      "$bin/15_bindless" --headless --no-validation --benchmark --frames "$frames" \
        --draw "$draw" --grid "$grid" 2>&1 | grep -E '^\{|recording the draws'
    done
  done
done
