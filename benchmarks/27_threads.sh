#!/usr/bin/env bash
# Chapter 27's benchmark (book/perf_27_threads.md).
#
# Part 1, recording against threads: for each --threads N in THREADS (default
# "1 2 4"), ROUNDS rounds (default 5) taken in turn, headless, validation
# off: the runner's JSON line (cpu_frame_ms: the whole frame on the CPU;
# gpu_frame_ms) and the chapter's line "recording the draws on N threads took
# ... ms median" (fork to join, per frame).
#
# Part 2, start-up with the pipeline cache: ROUNDS pairs of runs of one frame
# with --pipeline-cache, the first without a file (cold), the second with the
# file the first saved (warm), each timed whole (process start to exit) and by
# the chapter's own line "the pipeline took ... ms". Mesa keeps a shader
# cache of its own on disk, which would make every "cold" run warm: it is
# turned off here (MESA_SHADER_CACHE_DISABLE=true), so only our file helps.
# On NVIDIA, turn its driver cache off as well (__GL_SHADER_DISK_CACHE=0).
#
#   benchmarks/27_threads.sh [BIN_DIR] [WxH] [FRAMES] [GRID]
set -euo pipefail
bin=${1:-build/release/bin}
size=${2:-1280x720}
frames=${3:-200}
grid=${4:-64}
rounds=${ROUNDS:-5}
threads=${THREADS:-1 2 4}
err=$(mktemp)
cache_dir=$(mktemp -d)
trap 'rm -rf "$err" "$cache_dir"' EXIT
echo "# $(nproc) processors; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for round in $(seq "$rounds"); do
  for n in $threads; do
    echo "# round $round: 27_threads --threads $n --grid $grid --frames $frames --size $size"
    "$bin/27_threads" --headless --no-validation --size "$size" --frames "$frames" \
      --grid "$grid" --threads "$n" --benchmark 2>"$err"
    grep -h "recording the draws" "$err" || true
  done
done
echo "# load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for round in $(seq "$rounds"); do
  rm -f "$cache_dir/pipeline.cache"
  for start in cold warm; do
    echo "# round $round: start-up, $start"
    t0=$(date +%s%N)
    MESA_SHADER_CACHE_DISABLE=true __GL_SHADER_DISK_CACHE=0 "$bin/27_threads" --headless --no-validation --size 320x240 \
      --frames 1 --grid "$grid" --pipeline-cache "$cache_dir/pipeline.cache" 2>"$err"
    t1=$(date +%s%N)
    grep -h -E "pipeline took|loaded|saved" "$err" || true
    echo "whole run: $(( (t1 - t0) / 1000000 )) ms"
  done
done
echo "# load average: $(cut -d' ' -f1-3 /proc/loadavg)"
