#!/usr/bin/env bash
# Benchmarks every drawing chapter with the shared --benchmark flag and prints
# one JSON line per chapter (CPU frame time from the runner's clock, GPU frame
# time from timestamp queries). Validation off: it would dominate the timings.
#   benchmarks/run.sh [BIN_DIR] [FRAMES] [WxH] [headless|window]
# headless (the default): the headless surface, or offscreen where the device
# has none. window: each chapter in a window of that size, as a reader runs
# it, on a virtual X server this script starts (tests/with_xvfb.sh; no window
# manager, whose decorations would take pixels off the window). The JSON's
# "presentation" says which each line was.
# Compare medians and ratios measured in one run; trust absolute times only
# from a real GPU (lavapipe shares the CPU with everything else).
set -euo pipefail
bin=${1:-build/release/bin}
frames=${2:-600}
size=${3:-1280x720}
mode=${4:-headless}
case $mode in
  headless) where=(--headless) ;;
  window)
    # shellcheck source=benchmarks/in_window.sh
    . "$(dirname "$0")/in_window.sh"
    in_own_xvfb "$size" "$0" "$@"
    where=() ;;
  *) echo "benchmarks/run.sh: the mode is headless or window, not '$mode'" >&2; exit 2 ;;
esac
for exe in "$bin"/[0-9][0-9]_*; do
  name=$(basename "$exe")
  case $name in 01_*|02_*) continue ;; esac   # text chapters draw nothing
  # A chapter the device cannot run (24_ray_queries without VK_KHR_ray_query)
  # prints no line here; the others go on.
  "$exe" "${where[@]}" --no-validation --frames "$frames" --size "$size" --benchmark 2>/dev/null ||
    echo "benchmarks/run.sh: $name exited $? with no benchmark (run it alone to see why)" >&2
done
