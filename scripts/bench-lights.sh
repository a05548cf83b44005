#!/bin/sh
# The many-lights sweep of benchmarks/16_deferred.md and 17_tiled_deferred.md:
# runs chapter 16 with --benchmark on each light count, once per path, and
# prints one Markdown table row per count. Needs only the binaries and a
# POSIX shell:
#
#   scripts/bench-lights.sh build/release/bin/16_deferred [--size WxH] [--frames N]
#       [--tiled build/release/bin/17_tiled_deferred]
#
# --size defaults to 1280x720, --frames to 10. LIGHTS="1 16 64" in the
# environment runs other counts (default 1 16 64 256 1024 4096 16384 65536;
# lavapipe needs minutes per frame beyond a few thousand lights at 1280x720).
# Each run is offscreen (no surface: any GPU, no display needed), without
# validation; headless time makes the lights move the same in every run.
# Columns: device, lights, the forward path's one pass, the deferred path's
# two passes and their sum (GPU time of the named scopes, median / p95, in
# ms), and forward / deferred (medians): above 1, deferred is faster.
#
# --tiled adds chapter 17's two tiled paths, run in the same sweep on the
# same device: --shade fragment (scopes gbuffer, cull, lighting) and
# --shade compute (gbuffer, shade = cull and shade in one dispatch, copy), and
# the forward / tiled ratios. Without it the output is chapter 16's table.
set -eu
exe=${1:?usage: bench-lights.sh PATH/TO/16_deferred [--size WxH] [--frames N]}
shift
size=1280x720
frames=10
tiled=
while [ $# -gt 0 ]; do
    case "$1" in
        --size) size=${2:?--size needs WxH}; shift 2 ;;
        --frames) frames=${2:?--frames needs N}; shift 2 ;;
        --tiled) tiled=${2:?--tiled needs PATH/TO/17_tiled_deferred}; shift 2 ;;
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

# run_tiled SHADE LIGHTS: chapter 17's JSON line; its report of the tiles'
# light lists (mean, most, overflowed) goes to stderr.
run_tiled() {
    err=$(mktemp)
    if ! "$tiled" --offscreen --no-validation --benchmark --frames "$frames" --size "$size" \
            --shade "$1" --lights "$2" 2>"$err"; then
        echo "bench-lights.sh: tiled $1 with $2 lights failed: $(tail -n 1 "$err")" >&2
    fi
    grep "lights per lit tile" "$err" | sed "s/^/bench-lights.sh: $2 lights, $1: /" >&2 || true
    rm -f "$err"
}

if [ -n "$tiled" ]; then
    echo "| device | size | lights | forward ms | deferred ms (G-buffer + lighting) | tiled fragment: G-buffer + cull + lighting ms | tiled fragment ms | tiled compute: G-buffer + shade + copy ms | tiled compute ms | forward / tiled fragment | forward / tiled compute |"
    echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    for lights in ${LIGHTS:-1 16 64 256 1024 4096 16384 65536}; do
        fwd=$(run forward "$lights")
        def=$(run deferred "$lights")
        frag=$(run_tiled fragment "$lights")
        comp=$(run_tiled compute "$lights")
        device=$(printf '%s\n' "$frag$comp$def$fwd" | sed -n '1s/.*"device": "\([^"]*\)".*/\1/p')
        awk -v d="$device" -v s="$size" -v n="$lights" \
            -v f="$(field "$fwd" forward median)" \
            -v g="$(field "$def" gbuffer median)" -v l="$(field "$def" lighting median)" \
            -v fg="$(field "$frag" gbuffer median)" -v fc="$(field "$frag" cull median)" \
            -v fl="$(field "$frag" lighting median)" \
            -v cg="$(field "$comp" gbuffer median)" -v cs="$(field "$comp" shade median)" \
            -v cc="$(field "$comp" copy median)" '
            function ms(x) { return x == "" ? "n/a" : sprintf("%.3f", x) }
            function ratio(a, b) { return (a != "" && b != "" && b > 0) ? sprintf("%.1f", a / b) : "n/a" }
            BEGIN {
                deferred = (g != "" && l != "") ? g + l : ""
                frag = (fg != "" && fc != "" && fl != "") ? fg + fc + fl : ""
                comp = (cg != "" && cs != "" && cc != "") ? cg + cs + cc : ""
                printf "| %s | %s | %d | %s | %s | %s + %s + %s | %s | %s + %s + %s | %s | %s | %s |\n",
                    d, s, n, ms(f), ms(deferred), ms(fg), ms(fc), ms(fl), ms(frag),
                    ms(cg), ms(cs), ms(cc), ms(comp), ratio(f, frag), ratio(f, comp)
            }'
    done
    exit 0
fi

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
