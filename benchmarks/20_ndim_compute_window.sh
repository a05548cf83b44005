#!/usr/bin/env bash
# Chapter 20's benchmark as a reader sees it: in a 1920x1080 window, on a
# virtual X server this script starts (tests/with_xvfb.sh), validation off.
# The scenes are 20_ndim_compute.sh's (one n-cube and 250 n-cubes, n = 4, 8,
# 12), each drawn with --raster graphics, compute and binned. A window frame
# costs far more than a headless one (the copy to the swapchain image, the
# present), so every scene is reported as a ratio to chapter 03's empty
# window frame measured just before it in the same run: frame / empty, both
# the median of the runner's whole-frame clock (fence wait, acquire,
# recording, submit, present).
#   benchmarks/20_ndim_compute_window.sh [BIN_DIR] [ROUNDS] [FRAME_SCALE]
# ROUNDS (default 3): the whole sweep this many times; the summary takes the
# median ratio of the rounds. FRAME_SCALE (default 1) multiplies every frame
# count. Prints the raw JSON lines, each after a line naming the run, then a
# summary table. No window manager: its decorations would take pixels off a
# 1920x1080 window on a 1920x1080 screen.
set -euo pipefail
# shellcheck source=benchmarks/in_window.sh
. "$(dirname "$0")/in_window.sh"
in_own_xvfb 1920x1080 "$0" "$@"
bin=${1:-build/release/bin}
rounds=${2:-3}
scale=${3:-1}
size=1920x1080
out=$(mktemp)
trap 'rm -f "$out"' EXIT
# run LABEL FRAMES EXE ARGS...: one windowed run, its JSON line kept.
run() {
  local label=$1 frames=$(($2 * scale)) exe=$3
  shift 3
  echo "# round $round: $label: $(basename "$exe") $* --frames $frames" | tee -a "$out"
  "$bin/$exe" --no-validation --size "$size" --benchmark --frames "$frames" "$@" 2>/dev/null |
    grep '^{' | tee -a "$out"
}
scenes=("cube 4 300" "cube 8 200" "cube 12 30" "many 4 200" "many 8 30" "many 12 6")
for round in $(seq "$rounds"); do
  for s in "${scenes[@]}"; do
    read -r scene dim frames <<<"$s"
    for raster in graphics compute binned; do
      run "empty" 300 03_swapchain
      run "$scene $dim $raster" "$frames" 20_ndim_compute --scene "$scene" --dim "$dim" --raster "$raster"
    done
  done
done
python3 - "$out" <<'EOF'
import json, statistics, sys
# Pairs: each scene run after the empty frame measured just before it.
ratios, frames, empties, presentation = {}, {}, [], set()
empty = None
for line in open(sys.argv[1]):
    if line.startswith('# '):
        label = line.split(': ')[1]
        continue
    d = json.loads(line)
    presentation.add(d['presentation'])
    ms = d['cpu_frame_ms']['median']
    if label == 'empty':
        empty = ms
        empties.append(ms)
    else:
        ratios.setdefault(label, []).append(ms / empty)
        frames.setdefault(label, []).append(ms)
print()
print('presentation: ' + ', '.join(sorted(presentation)))
print('empty frame (03_swapchain), median of the runs: %.3f ms (%s)' %
      (statistics.median(empties), ', '.join('%.2f' % e for e in empties)))
print()
print('| scene | n | raster | frame ms (median of rounds) | frame / empty (median) | each round |')
print('|---|---|---|---|---|---|')
for label, r in ratios.items():
    scene, dim, raster = label.split()
    name = 'one n-cube' if scene == 'cube' else '250 n-cubes'
    print('| %s | %s | %s | %.3g | **%.3g** | %s |' % (
        name, dim, raster, statistics.median(frames[label]), statistics.median(r),
        ' / '.join('%.3g' % x for x in r)))
EOF
