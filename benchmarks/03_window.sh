#!/usr/bin/env bash
# What a window frame costs before a chapter draws anything (chapter 03, issue
# 17's "window path"): chapter 03's empty frame at 1920x1080, validation off,
# four ways in turn on one virtual X server that this script starts
# (tests/with_xvfb.sh), so that every way sees the same machine:
#   window, drawn     straight into the swapchain image (the default)
#   window, copied    --copy-to-swapchain: into our own image, then copied
#   headless surface  --headless (lavapipe's surface is _UNORM: copied)
#   offscreen         --offscreen: no swapchain, no present
# Each is the median of the runner's whole-frame clock (fence wait, acquire,
# recording, submit, present) over FRAMES frames; the summary takes the median
# of ROUNDS rounds and the ratios within each round.
#   benchmarks/03_window.sh [BIN_DIR] [ROUNDS] [FRAMES]
set -euo pipefail
# shellcheck source=benchmarks/in_window.sh
. "$(dirname "$0")/in_window.sh"
in_own_xvfb 1920x1080 "$0" "$@"
bin=${1:-build/release/bin}
rounds=${2:-5}
frames=${3:-600}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for round in $(seq "$rounds"); do
  for way in "drawn:" "copied:--copy-to-swapchain" "headless:--headless" "offscreen:--offscreen"; do
    label=${way%%:*} flag=${way#*:}
    echo "# round $round: $label" | tee -a "$out"
    # shellcheck disable=SC2086  # $flag is one flag or none
    "$bin/03_swapchain" --no-validation --size 1920x1080 --benchmark --frames "$frames" $flag \
      2>/dev/null | grep '^{' | tee -a "$out"
  done
done
python3 - "$out" <<'PY'
import json, statistics, sys
ms, gpu, rounds, label = {}, {}, [], None
for line in open(sys.argv[1]):
    if line.startswith('# '):
        label = line.split(': ')[1].strip()
        if label == 'drawn':
            rounds.append({})
        continue
    d = json.loads(line)
    ms.setdefault(label, []).append(d['cpu_frame_ms']['median'])
    gpu.setdefault(label, []).append((d['gpu_frame_ms'] or {}).get('median'))
    rounds[-1][label] = d['cpu_frame_ms']['median']
print()
print('| way | frame ms (median of rounds) | GPU ms | / drawn (median) | each round (ms) |')
print('|---|---|---|---|---|')
for label in ms:
    ratio = statistics.median(r[label] / r['drawn'] for r in rounds)
    g = [x for x in gpu[label] if x is not None]
    print('| %s | %.3f | %s | %.2f | %s |' % (
        label, statistics.median(ms[label]), '%.3f' % statistics.median(g) if g else '-',
        ratio, ' / '.join('%.2f' % x for x in ms[label])))
PY
