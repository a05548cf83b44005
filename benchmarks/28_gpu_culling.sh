#!/usr/bin/env bash
# Chapter 28's benchmark (book/perf_28_gpu_culling.md): the same field drawn
# with --cull none, frustum and occlusion, ROUNDS rounds (default 3) taken in
# turn, headless, validation off. Each run prints the runner's JSON line
# (gpu_frame_ms: the whole frame by GPU timestamps; gpu_scopes_ms: the early
# cull and draw, the pyramid, the late cull and draw) and the chapter's last
# line (what the last frame drew and culled). PATHS (default "indirect")
# names the --path values to run in turn: "indirect task" adds the task path.
# MESHLET_CULL (default "on off") names the task path's --meshlet-cull
# values to run in turn (book/28b_task_path.md); the indirect path has none.
#
#   [PATHS="indirect task"] [MESHLET_CULL="on off"] [CULLS="none frustum occlusion"] \
#     benchmarks/28_gpu_culling.sh [BIN_DIR] [WxH] [FRAMES] [INSTANCES...]
set -euo pipefail
bin=${1:-build/release/bin}
size=${2:-1920x1080}
frames=${3:-300}
shift $(( $# < 3 ? $# : 3 ))
instances=${*:-100000}
rounds=${ROUNDS:-3}
paths=${PATHS:-indirect}
meshlet_culls=${MESHLET_CULL:-on off}
culls=${CULLS:-none frustum occlusion}
err=$(mktemp)
trap 'rm -f "$err"' EXIT
echo "# $(nproc) processors; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for n in $instances; do
  for round in $(seq "$rounds"); do
    for path in $paths; do
      variants=("")
      [ "$path" = task ] && read -r -a variants <<<"$meshlet_culls"
      for meshlet in "${variants[@]}"; do
        extra=()
        [ -n "$meshlet" ] && extra=(--meshlet-cull "$meshlet")
        for cull in $culls; do
          echo "# round $round: 28_gpu_culling --instances $n --path $path ${extra[*]} --cull $cull --frames $frames --size $size"
          "$bin/28_gpu_culling" --headless --no-validation --size "$size" --frames "$frames" \
            --instances "$n" --path "$path" "${extra[@]}" --cull "$cull" --benchmark 2>"$err"
          grep -h -E "triangles|last frame" "$err" || true
        done
      done
    done
  done
done
echo "# load average: $(cut -d' ' -f1-3 /proc/loadavg)"
