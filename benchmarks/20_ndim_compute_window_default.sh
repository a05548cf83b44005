#!/usr/bin/env bash
# Chapter 20's default rasteriser (--raster auto) in a 1920x1080 window on a
# virtual X server this script starts (tests/with_xvfb.sh), validation off,
# beside chapter 03's empty window frame and the old default (--raster
# graphics), each run in turn, ROUNDS times: 250 4-cubes and 250 8-cubes.
# Prints each run's JSON line after a line naming it, then per scene the
# median over the rounds of the runner's whole-frame clock (fence wait,
# acquire, recording, submit, present) and of the GPU scopes.
#   benchmarks/20_ndim_compute_window_default.sh [BIN_DIR] [ROUNDS]
set -euo pipefail
# shellcheck source=benchmarks/in_window.sh
. "$(dirname "$0")/in_window.sh"
in_own_xvfb 1920x1080 "$0" "$@"
bin=${1:-build/release/bin}
rounds=${2:-3}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
run() {  # run LABEL FRAMES EXE ARGS...
  local label=$1 frames=$2 exe=$3
  shift 3
  echo "# $label: $exe $* --frames $frames" | tee -a "$out"
  "$bin/$exe" --no-validation --size 1920x1080 --benchmark --frames "$frames" "$@" 2>/dev/null |
    grep '^{' | tee -a "$out"
}
for round in $(seq "$rounds"); do
  echo "# round $round of $rounds" | tee -a "$out"
  run "empty" 300 03_swapchain
  for dim in 4 8; do
    run "many $dim auto" 30 20_ndim_compute --scene many --dim "$dim"
    run "many $dim graphics" 30 20_ndim_compute --scene many --dim "$dim" --raster graphics
  done
done
python3 - "$out" <<'PY'
import collections, json, statistics, sys
runs = collections.defaultdict(list)
for line in open(sys.argv[1]):
    if line.startswith('# '):
        label = line[2:].split(':')[0]
    else:
        runs[label].append(json.loads(line))
empty = statistics.median(r['cpu_frame_ms']['median'] for r in runs['empty'])
print(f"\nempty window frame (03_swapchain): {empty:.3f} ms (median of {len(runs['empty'])} runs)")
print("| scene | raster | frame ms | frame / empty | runs | GPU scopes, ms |")
print("|---|---|---:|---:|---|---|")
for label, rs in runs.items():
    if label == 'empty':
        continue
    ms = [r['cpu_frame_ms']['median'] for r in rs]
    scopes = collections.defaultdict(list)
    for r in rs:
        for k, v in r['gpu_scopes_ms'].items():
            scopes[k].append(v['median'])
    scope_text = ', '.join(f"{k} {statistics.median(v):.2f}" for k, v in scopes.items())
    scene, dim, raster = label.split()
    print(f"| 250 {dim}-cubes | {raster} | {statistics.median(ms):.1f} | "
          f"{statistics.median(ms) / empty:.0f} | {' / '.join(f'{m:.1f}' for m in ms)} | {scope_text} |")
PY
