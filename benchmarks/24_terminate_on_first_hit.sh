#!/usr/bin/env bash
# Chapter 24's first "Try it" (book/24_ray_queries.md), measured: the lit
# pass (GPU scope "lit", which holds the ray queries) with the shadow ray's
# gl_RayFlagsTerminateOnFirstHitEXT and without it. The chapter's built
# program and shaders are copied to a temporary folder, and scene.frag is
# compiled there a second time with the flag taken out; the source tree and
# the build are left as they are. ROUNDS rounds, the two shaders taken in
# turn within each, first one then the other in alternate rounds. One JSON
# line per run, each preceded by a line naming it; then the "lit" medians and
# the ratio without / with of each round, with their median and spread.
#   benchmarks/24_terminate_on_first_hit.sh [BUILD_DIR] [WxH] [FRAMES] [ROUNDS]
set -euo pipefail
build=${1:-build/release}
size=${2:-320x240}
frames=${3:-60}
rounds=${4:-7}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin" "$work/shaders" "$work/variant"
cp "$build/bin/24_ray_queries" "$work/bin/"
cp -r "$build/shaders/24_ray_queries" "$work/shaders/"
cp "$work/shaders/24_ray_queries/scene.frag.spv" "$work/variant/with.spv"
frag="$source_dir/shaders/24_ray_queries/scene.frag"
flag='gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsOpaqueEXT'
grep -q "$flag" "$frag" || { echo "$frag: rayQueryInitializeEXT: the flags are not '$flag'" >&2; exit 1; }
sed "s/$flag/gl_RayFlagsOpaqueEXT/" "$frag" > "$work/variant/scene.frag"
glslangValidator --quiet -V --target-env vulkan1.3 -I"$source_dir/shaders/common" \
  -I"$source_dir/shaders/24_ray_queries" -o "$work/variant/without.spv" "$work/variant/scene.frag"
log="$work/log"
for round in $(seq 1 "$rounds"); do
  order="with without"
  [ $((round % 2)) -eq 0 ] && order="without with"
  for variant in $order; do
    cp "$work/variant/$variant.spv" "$work/shaders/24_ray_queries/scene.frag.spv"
    echo "# round $round: $variant TerminateOnFirstHit: 24_ray_queries --headless --no-validation --benchmark --frames $frames --size $size"
    "$work/bin/24_ray_queries" --headless --no-validation --benchmark --frames "$frames" \
      --size "$size" 2>/dev/null | grep '^{'
  done
done | tee "$log"
python3 - "$log" <<'PY'
import json, statistics, sys
lit = {}  # "with" / "without" -> the "lit" scope's median of each round
variant = None
for line in open(sys.argv[1]):
    if line.startswith("# round"):
        variant = line.split(":")[1].split()[0]
    elif line.startswith("{"):
        lit.setdefault(variant, []).append(json.loads(line)["gpu_scopes_ms"]["lit"]["median"])
ratios = [b / a for a, b in zip(lit["with"], lit["without"])]
for variant in ("with", "without"):
    print(f"# lit median per round, {variant} the flag: " + " ".join(f"{m:.1f}" for m in lit[variant])
          + f" ms; median {statistics.median(lit[variant]):.1f} ms")
print("# without / with, per round " + " ".join(f"{r:.2f}" for r in ratios)
      + f"; median {statistics.median(ratios):.2f}, spread {min(ratios):.2f} to {max(ratios):.2f}")
PY
