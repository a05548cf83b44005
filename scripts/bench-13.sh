#!/bin/sh
# Chapter 13's benchmark sweep (benchmarks/13_compute.md): runs the chapter
# with --benchmark at 65,536, 1,048,576 and 16,777,216 particles and prints one
# Markdown table row per count. Needs only the binary and a POSIX shell:
#
#   scripts/bench-13.sh build/release/bin/13_compute [FRAMES] [MORE CHAPTER FLAGS...]
#
# FRAMES defaults to 100. COUNTS="65536 1048576" in the environment runs
# other counts (lavapipe needs ~20 s a frame to draw 16,777,216 points, so
# benchmarks/13_compute.md runs that count with fewer frames). Each run is offscreen (no surface, so it works on any
# GPU and on a machine with no display), without validation, at the default
# 800x600; headless time makes every frame exactly 2 fixed steps of 1/120 s.
# Columns: device, particles, GPU time of the "simulate" and "draw" scopes
# (median / p95), the whole frame on the GPU and on the CPU (median),
# particles per second (particles / GPU frame median) and particle steps per
# second in simulate (2 x particles / simulate median).
set -eu
exe=${1:?usage: bench-13.sh PATH/TO/13_compute [FRAMES] [MORE CHAPTER FLAGS...]}
frames=${2:-100}
if [ $# -ge 2 ]; then shift 2; else shift 1; fi

# field JSON PATH...: the number after "median"/"p95" inside the named object,
# e.g. field "$json" gpu_frame_ms median; "simulate" and "draw" live inside
# gpu_scopes_ms but their names are unique in the line.
field() {
    printf '%s\n' "$1" | sed -n "s/.*\"$2\": {[^}]*\"$3\": \([0-9.eE+-]*\).*/\1/p"
}

echo "| device | particles | simulate ms (median / p95) | draw ms (median / p95) | GPU frame ms | CPU frame ms | particles/s | particle steps/s (simulate) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for count in ${COUNTS:-65536 1048576 16777216}; do
    err=$(mktemp)
    if ! json=$("$exe" --offscreen --no-validation --benchmark --frames "$frames" --count "$count" "$@" 2>"$err"); then
        echo "| (failed at $count particles: $(tail -n 1 "$err")) |"
        rm -f "$err"
        continue
    fi
    rm -f "$err"
    device=$(printf '%s\n' "$json" | sed -n 's/.*"device": "\([^"]*\)".*/\1/p')
    sim=$(field "$json" simulate median); sim95=$(field "$json" simulate p95)
    draw=$(field "$json" draw median); draw95=$(field "$json" draw p95)
    gpu=$(field "$json" gpu_frame_ms median); cpu=$(field "$json" cpu_frame_ms median)
    awk -v d="$device" -v n="$count" -v s="$sim" -v s95="$sim95" -v dr="$draw" -v dr95="$draw95" \
        -v g="$gpu" -v c="$cpu" 'function rate(x) {
            if (x >= 1e9) return sprintf("%.2f G", x / 1e9)
            if (x >= 1e6) return sprintf("%.1f M", x / 1e6)
            return sprintf("%.0f k", x / 1e3) }
        function ms(x) { return x == "" ? "n/a" : sprintf("%.3f", x) }
        BEGIN {
            per_s = (g > 0) ? rate(n / (g / 1000)) : "n/a"
            steps_s = (s > 0) ? rate(2 * n / (s / 1000)) : "n/a"
            printf "| %s | %d | %s / %s | %s / %s | %s | %s | %s | %s |\n", d, n, ms(s), ms(s95),
                   ms(dr), ms(dr95), ms(g), ms(c), per_s, steps_s }'
done
