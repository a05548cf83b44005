#!/usr/bin/env bash
# Chapter 26's benchmark (book/perf_26_mesh_shaders.md): the same model drawn
# chapter 15's way (one vkCmdDrawIndexedIndirect, vertex shader), by task and
# mesh shaders without culling, and by task and mesh shaders culling
# meshlets; each from the default view (the whole knot in sight) and with the
# gaze turned 30 degrees (about a third of the meshlets outside the frustum).
# Three rounds, the settings taken in turn within each round, headless,
# validation off. One JSON line per run (GPU scope "draw": the one draw
# command), each preceded by a line naming its arguments and followed by the
# chapter's line of what it submitted.
#   benchmarks/26_mesh_shaders.sh [BIN_DIR] [WxH] [FRAMES] [MODEL]
# TURNS="0 30" the gazes, ROUNDS=3 the rounds. The dense case, a knot of
# 1,966,080 triangles (book/perf_26_mesh_shaders.md):
#   python3 scripts/make_knot_model.py --rings 2560 --sides 384 --out knot_dense.glb
#   benchmarks/26_mesh_shaders.sh build/release/bin 1920x1080 300 knot_dense.glb
set -euo pipefail
bin=${1:-build/release/bin}
size=${2:-1920x1080}
frames=${3:-300}
model=()
[ $# -ge 4 ] && model=(--model "$4")
for round in $(seq "${ROUNDS:-3}"); do
  for turn in ${TURNS:-0 30}; do
    for draw in "--draw indirect" "--draw mesh --cull off" "--draw mesh --cull on"; do
      echo "# round $round: 26_mesh_shaders $draw --turn $turn --frames $frames"
      # shellcheck disable=SC2086  # $draw is two or four words
      "$bin/26_mesh_shaders" --headless --no-validation --size "$size" --benchmark \
        --frames "$frames" $draw --turn "$turn" "${model[@]}" 2>"${TMPDIR:-/tmp}/26_bench.err"
      grep -h -E "submitted|-> [0-9]+ meshlets" "${TMPDIR:-/tmp}/26_bench.err" || true
    done
  done
done
