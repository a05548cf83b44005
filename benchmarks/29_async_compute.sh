#!/usr/bin/env bash
# Chapter 29's benchmark (book/perf_29_async_compute.md).
#
# For each --lamps N in LAMPS (default "48 512": the graphics work of a
# frame) and each --bloom-radius R in RADII (default "1": the compute work),
# ROUNDS rounds (default 5) of --queues single and --queues async in
# turn, headless, validation off, FRAMES frames at WxH: the runner's JSON line
# (cpu_frame_ms: the whole frame as the host sees it, which on a GPU-bound run
# is the GPU's pace; gpu_frame_ms times only the runner's own command buffer,
# the tone map alone in async) and the chapter's line "overlap (--queues Q,
# F frames): bloom X ms median, Y ms of it under graphics work (Z% of all
# bloom time)" and "gpu pace (--queues Q): a frame every X ms", from
# timestamps written on both queues.
#
#   benchmarks/29_async_compute.sh [BIN_DIR] [WxH] [FRAMES]
set -euo pipefail
bin=${1:-build/release/bin}
size=${2:-1920x1080}
frames=${3:-300}
rounds=${ROUNDS:-5}
lamps=${LAMPS:-48 512}
radii=${RADII:-1}
err=$(mktemp)
trap 'rm -f "$err"' EXIT
echo "# $(nproc) processors; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for n in $lamps; do
  for r in $radii; do
    for round in $(seq "$rounds"); do
      for queues in single async; do
        echo "# round $round: 29_async_compute --queues $queues --lamps $n --bloom-radius $r --frames $frames --size $size"
        "$bin/29_async_compute" --headless --no-validation --size "$size" --frames "$frames" \
          --lamps "$n" --bloom-radius "$r" --queues "$queues" --benchmark 2>"$err"
        grep -h -E "overlap|--queues|gpu pace" "$err" || true
      done
    done
  done
done
echo "# load average: $(cut -d' ' -f1-3 /proc/loadavg)"
