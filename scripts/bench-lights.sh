#!/bin/sh
# The many-lights sweep of benchmarks/16_deferred.md: runs chapter 16 with
# --benchmark on each light count, once per path, and prints one Markdown
# table row per count. Needs only the binary and a POSIX shell:
#
#   scripts/bench-lights.sh build/release/bin/16_deferred [--size WxH] [--frames N]
#
# --size defaults to 1280x720, --frames to 10. LIGHTS="1 16 64" in the
# environment runs other counts (default 1 16 64 256 1024 4096 16384 65536;
# lavapipe needs minutes per frame beyond a few thousand lights at 1280x720).
# Each run is offscreen (no surface: any GPU, no display needed), without
# validation; headless time makes the lights move the same in every run.
# Columns: device, lights, the forward path's one pass, the deferred path's
# two passes and their sum (GPU time of the named scopes, median / p95, in
# ms), and forward / deferred (medians): above 1, deferred is faster.
# The paths are listed in PATHS (chapter 17 adds its tiled path here).
set -eu
exe=${1:?usage: bench-lights.sh PATH/TO/16_deferred [--size WxH] [--frames N]}
shift
size=1280x720
frames=10
while [ $# -gt 0 ]; do
    case "$1" in
        --size) size=${2:?--size needs WxH}; shift 2 ;;
        --frames) frames=${2:?--frames needs N}; shift 2 ;;
        *) echo "bench-lights.sh: unknown argument '$1'" >&2; exit 2 ;;
    esac
done

# field JSON NAME STAT: the number after "STAT" inside the object "NAME": {...}.
field() {
    printf '%s\n' "$1" | sed -n "s/.*\"$2\": {[^}]*\"$3\": \([0-9.eE+-]*\).*/\1/p"
}

# run PATH LIGHTS: the chapter's JSON line, or nothing (and a note) on failure.
run() {
    err=$(mktemp)
    if ! "$exe" --offscreen --no-validation --benchmark --frames "$frames" --size "$size" \
            --path "$1" --lights "$2" 2>"$err"; then
        echo "bench-lights.sh: $1 with $2 lights failed: $(tail -n 1 "$err")" >&2
    fi
    rm -f "$err"
}

echo "| device | size | lights | forward ms (median / p95) | G-buffer ms | lighting ms | deferred ms (sum of medians) | forward / deferred |"
echo "|---|---|---:|---:|---:|---:|---:|---:|"
for lights in ${LIGHTS:-1 16 64 256 1024 4096 16384 65536}; do
    fwd=$(run forward "$lights")
    def=$(run deferred "$lights")
    device=$(printf '%s\n' "$def$fwd" | sed -n '1s/.*"device": "\([^"]*\)".*/\1/p')
    awk -v d="$device" -v s="$size" -v n="$lights" \
        -v f="$(field "$fwd" forward median)" -v f95="$(field "$fwd" forward p95)" \
        -v g="$(field "$def" gbuffer median)" -v g95="$(field "$def" gbuffer p95)" \
        -v l="$(field "$def" lighting median)" -v l95="$(field "$def" lighting p95)" '
        function ms(x) { return x == "" ? "n/a" : sprintf("%.3f", x) }
        BEGIN {
            total = (g != "" && l != "") ? g + l : ""
            ratio = (total != "" && f != "" && total > 0) ? sprintf("%.2f", f / total) : "n/a"
            printf "| %s | %s | %d | %s / %s | %s / %s | %s / %s | %s | %s |\n", d, s, n,
                ms(f), ms(f95), ms(g), ms(g95), ms(l), ms(l95), ms(total), ratio
        }'
done
