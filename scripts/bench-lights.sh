#!/bin/sh
# The many-lights sweep of benchmarks/16_deferred.md and 17_tiled_deferred.md:
# runs chapter 16 with --benchmark on each light count, once per path, and
# prints one Markdown table row per count. Needs only the binaries and a
# POSIX shell:
#
#   scripts/bench-lights.sh build/release/bin/16_deferred [--size WxH] [--frames N]
#       [--tiled build/release/bin/17_tiled_deferred]
#   scripts/bench-lights.sh --binned build/release/bin/17_tiled_deferred [--size WxH]
#       [--frames N] [--repeat R] [--shade compute|fragment|both]
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
# These are chapter 17's first step, --cull tiled (every tile tests every
# light), which the script asks for by name.
#
# --binned compares chapter 17's two ways of culling, alone (no chapter 16):
# for each light count (LIGHTS, default 65536) and shade, R runs (--repeat,
# default 5) of --cull tiled and of --cull binned, alternating which goes
# first, so that a machine whose load drifts slows both alike. One row per run
# (the GPU frame's median and each scope's median, the CPU frame's median),
# then a row of medians over the runs and their ratio tiled / binned, and one
# of the fastest runs (load only ever adds time).
set -eu
binned=
if [ "${1:-}" = "--binned" ]; then
    binned=${2:?--binned needs PATH/TO/17_tiled_deferred}
    exe=
    shift 2
else
    exe=${1:?usage: bench-lights.sh PATH/TO/16_deferred [--size WxH] [--frames N]}
    shift
fi
size=1280x720
frames=10
tiled=
repeat=5
shades=compute
while [ $# -gt 0 ]; do
    case "$1" in
        --size) size=${2:?--size needs WxH}; shift 2 ;;
        --frames) frames=${2:?--frames needs N}; shift 2 ;;
        --tiled) tiled=${2:?--tiled needs PATH/TO/17_tiled_deferred}; shift 2 ;;
        --repeat) repeat=${2:?--repeat needs R}; shift 2 ;;
        --shade)
            case "${2:-}" in
                compute|fragment) shades=$2 ;;
                both) shades="compute fragment" ;;
                *) echo "bench-lights.sh: --shade wants compute, fragment or both" >&2; exit 2 ;;
            esac
            shift 2 ;;
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
            --shade "$1" --lights "$2" --cull tiled 2>"$err"; then
        echo "bench-lights.sh: tiled $1 with $2 lights failed: $(tail -n 1 "$err")" >&2
    fi
    grep "lights per lit tile" "$err" | sed "s/^/bench-lights.sh: $2 lights, $1: /" >&2 || true
    rm -f "$err"
}

# run_cull CULL SHADE LIGHTS: chapter 17's JSON line with --cull CULL; its
# report of the lists and bins goes to stderr.
run_cull() {
    err=$(mktemp)
    if ! "$binned" --offscreen --no-validation --benchmark --frames "$frames" --size "$size" \
            --cull "$1" --shade "$2" --lights "$3" 2>"$err"; then
        echo "bench-lights.sh: --cull $1 --shade $2 with $3 lights failed: $(tail -n 1 "$err")" >&2
    fi
    grep -E "lights per lit tile|bins:" "$err" | sed "s/^/bench-lights.sh: $3 lights, $1 $2: /" >&2 || true
    rm -f "$err"
}

# scopes JSON: "name median + name median ..." for the scopes the run timed.
scopes() {
    out=
    for name in gbuffer bin cull lighting shade copy; do
        v=$(field "$1" "$name" median)
        [ -n "$v" ] && out="$out${out:+ + }$name $v"
    done
    printf '%s\n' "${out:-n/a}"
}

if [ -n "$binned" ]; then
    echo "| device | size | lights | shade | run | tiled: GPU frame ms (scopes) | binned: GPU frame ms (scopes) | tiled / binned | CPU frame ms, tiled / binned |"
    echo "|---|---|---:|---|---|---|---|---:|---|"
    for lights in ${LIGHTS:-65536}; do
        for shade in $shades; do
            t_all='' b_all=''
            r=1
            while [ "$r" -le "$repeat" ]; do
                if [ $((r % 2)) -eq 1 ]; then
                    t=$(run_cull tiled "$shade" "$lights"); b=$(run_cull binned "$shade" "$lights")
                else
                    b=$(run_cull binned "$shade" "$lights"); t=$(run_cull tiled "$shade" "$lights")
                fi
                device=$(printf '%s\n' "$t$b" | sed -n '1s/.*"device": "\([^"]*\)".*/\1/p')
                tf=$(field "$t" gpu_frame_ms median); bf=$(field "$b" gpu_frame_ms median)
                t_all="$t_all $tf" b_all="$b_all $bf"
                awk -v d="$device" -v s="$size" -v n="$lights" -v sh="$shade" -v r="$r" \
                    -v tf="$tf" -v bf="$bf" -v ts="$(scopes "$t")" -v bs="$(scopes "$b")" \
                    -v tc="$(field "$t" cpu_frame_ms median)" -v bc="$(field "$b" cpu_frame_ms median)" '
                    BEGIN {
                        ratio = (tf != "" && bf != "" && bf > 0) ? sprintf("%.2f", tf / bf) : "n/a"
                        printf "| %s | %s | %d | %s | %d | %s (%s) | %s (%s) | %s | %s / %s |\n",
                            d, s, n, sh, r, tf, ts, bf, bs, ratio, tc, bc
                    }'
                r=$((r + 1))
            done
            # The medians over the runs, and their ratio.
            awk -v n="$lights" -v sh="$shade" -v t="$t_all" -v b="$b_all" '
                function median(list,    a, k, i, j, x) {
                    k = split(list, a, " ")
                    for (i = 2; i <= k; i++) { x = a[i]; for (j = i - 1; j > 0 && a[j] + 0 > x + 0; j--) a[j + 1] = a[j]; a[j + 1] = x }
                    return k == 0 ? "" : (k % 2 ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2)
                }
                function least(list,    a, k, i, m) {
                    k = split(list, a, " "); m = a[1]
                    for (i = 2; i <= k; i++) if (a[i] + 0 < m + 0) m = a[i]
                    return m
                }
                BEGIN {
                    mt = median(t); mb = median(b); lt = least(t); lb = least(b)
                    printf "| median of %d runs | | %d | %s | | %s | %s | **%s** | |\n", split(t, x, " "), n, sh,
                        mt, mb, (mt != "" && mb > 0) ? sprintf("%.2f", mt / mb) : "n/a"
                    printf "| fastest of %d runs | | %d | %s | | %s | %s | %s | |\n", split(t, x, " "), n, sh,
                        lt, lb, (lt != "" && lb > 0) ? sprintf("%.2f", lt / lb) : "n/a"
                }'
        done
    done
    exit 0
fi

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
