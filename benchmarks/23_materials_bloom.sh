#!/usr/bin/env bash
# Chapter 23d's bloom: what the eleven dispatches cost a frame, against the
# scene pass and the full-screen tone-map pass beside them.
#
#   benchmarks/23_materials_bloom.sh [BIN] [RUNS] [WxH] [FRAMES]
#                                    (default build/release/bin, 7, 320x240, 100)
#
# RUNS rounds of --bloom 0.3 and of no bloom, in turn, FRAMES frames each,
# under the environment (--sky environment), headless, validation off,
# --benchmark; one JSON line per run (GPU scopes
# "scene", "bloom": the chain down and up, "tone map"), each preceded by a
# line naming its arguments. Then, per round, the medians side by side.
# Without a GPU, point the loader at lavapipe:
# VK_DRIVER_FILES=/usr/share/vulkan/icd.d/lvp_icd.json.
set -euo pipefail
bin=${1:-build/release/bin}
runs=${2:-7}
size=${3:-320x240}
frames=${4:-100}
exe="$bin/23_materials"
[ -x "$exe" ] || { echo "23_materials_bloom: no $exe (cmake --build --preset release)"; exit 2; }
echo "# $0 $bin $runs $size $frames; load average $(cut -d' ' -f1 /proc/loadavg) before; at $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for run in $(seq "$runs"); do
  for bloom in 0.3 none; do
    flags=()
    [ "$bloom" = none ] || flags=(--bloom "$bloom")
    echo "# round $run: --bloom $bloom --size $size --frames $frames"
    "$exe" --headless --no-validation --frames "$frames" --size "$size" --benchmark --sky environment \
      "${flags[@]}" \
      2>/dev/null | tail -n 1 | tee -a "$out"
  done
done
echo "# load average $(cut -d' ' -f1 /proc/loadavg) after"
# Medians per round: bloom's own scope, and what it adds to the GPU frame.
python3 - "$out" <<'PY'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
print("# round: bloom ms | tone map ms | bloom / tone map | scene ms | GPU frame with, without (ms) | added")
for i in range(0, len(rows) - 1, 2):
    w, wo = rows[i], rows[i + 1]
    s = w["gpu_scopes_ms"]
    bloom, tone, scene = s["bloom"]["median"], s["tone map"]["median"], s["scene"]["median"]
    fw, fwo = w["gpu_frame_ms"]["median"], wo["gpu_frame_ms"]["median"]
    print(f"# {i // 2 + 1}: {bloom:.3f} | {tone:.3f} | {bloom / tone:.2f} | {scene:.3f} | "
          f"{fw:.3f}, {fwo:.3f} | {fw - fwo:+.3f}")
PY
