#!/usr/bin/env bash
# Chapter 25's benchmark (book/perf_25_ray_tracing.md): the GPU scope "trace"
# (the one vkCmdTraceRaysKHR, one ray-generation invocation per pixel) with --bounces 0, 2
# (the default) and 8, headless, validation off. ROUNDS rounds, the settings
# taken in turn within each. One JSON line per run, each preceded by a line
# naming its arguments; then, per setting, the "trace" median of each round
# with their median and spread, and the ratio to --bounces 0 of each round.
#   benchmarks/25_ray_tracing.sh [BIN_DIR] [WxH] [FRAMES] [ROUNDS]
set -euo pipefail
bin=${1:-build/release/bin}
size=${2:-320x240}
frames=${3:-60}
rounds=${4:-5}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for round in $(seq 1 "$rounds"); do
  for bounces in 0 2 8; do
    echo "# round $round: 25_ray_tracing --bounces $bounces --frames $frames --size $size"
    "$bin/25_ray_tracing" --headless --no-validation --size "$size" --benchmark \
      --frames "$frames" --bounces "$bounces" 2>/dev/null
  done
done | tee "$log"
python3 - "$log" <<'PY'
import json, statistics, sys
runs = {}  # bounces -> the "trace" scope's median of each round
bounces = None
for line in open(sys.argv[1]):
    if line.startswith("# round"):
        words = line.split()
        bounces = int(words[words.index("--bounces") + 1])
    elif line.startswith("{"):
        runs.setdefault(bounces, []).append(json.loads(line)["gpu_scopes_ms"]["trace"]["median"])
for bounces in sorted(runs):
    medians = runs[bounces]
    ratios = [m / base for m, base in zip(medians, runs[0])]
    print(f"# --bounces {bounces}: trace median per round "
          + " ".join(f"{m:.2f}" for m in medians)
          + f" ms; median {statistics.median(medians):.2f}, spread {min(medians):.2f} to "
          f"{max(medians):.2f} ms; / --bounces 0 per round "
          + " ".join(f"{r:.2f}" for r in ratios)
          + f", median {statistics.median(ratios):.2f}")
PY
