#!/usr/bin/env bash
# Chapter 24's benchmark (book/perf_24_ray_queries.md): the top level's
# per-frame build, refitted (--tlas update) against built anew (--tlas
# rebuild), with the scene's 19 instances and with 16,384 more (--crowd),
# headless, validation off, shadows by ray queries. ROUNDS rounds, the
# settings taken in turn within each. One JSON line per run (GPU scopes
# "tlas": the build with its two barriers, "lit": the lit pass with its ray
# queries), each preceded by a line naming its arguments; then, per setting,
# the median of the "tlas" scope in each round, and the ratio rebuild/update
# of each round with its spread.
#   benchmarks/24_ray_queries.sh [BIN_DIR] [WxH] [FRAMES] [ROUNDS]
set -euo pipefail
bin=${1:-build/release/bin}
size=${2:-256x144}
frames=${3:-60}
rounds=${4:-5}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for round in $(seq 1 "$rounds"); do
  for crowd in 0 16384; do
    for tlas in update rebuild; do
      echo "# round $round: 24_ray_queries --crowd $crowd --tlas $tlas --frames $frames"
      "$bin/24_ray_queries" --headless --no-validation --size "$size" --benchmark \
        --frames "$frames" --crowd "$crowd" --tlas "$tlas" 2>/dev/null
    done
  done
done | tee "$log"
python3 - "$log" <<'PY'
import json, statistics, sys
runs = {}  # (crowd, tlas) -> the "tlas" scope's median of each round
args = None
for line in open(sys.argv[1]):
    if line.startswith("# round"):
        words = line.split()
        args = (int(words[words.index("--crowd") + 1]), words[words.index("--tlas") + 1])
    elif line.startswith("{"):
        runs.setdefault(args, []).append(json.loads(line)["gpu_scopes_ms"]["tlas"]["median"])
for crowd in sorted({c for c, _ in runs}):
    update, rebuild = runs[(crowd, "update")], runs[(crowd, "rebuild")]
    ratios = [r / u for u, r in zip(update, rebuild)]
    print(f"# {crowd + 19} instances: tlas median per round, update "
          + " ".join(f"{m:.4f}" for m in update) + " ms; rebuild "
          + " ".join(f"{m:.4f}" for m in rebuild) + " ms")
    print(f"# {crowd + 19} instances: rebuild / update, per round "
          + " ".join(f"{r:.2f}" for r in ratios)
          + f"; median {statistics.median(ratios):.2f}, spread {min(ratios):.2f} to {max(ratios):.2f}")
PY
