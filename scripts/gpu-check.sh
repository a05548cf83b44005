#!/usr/bin/env bash
# What we run on a real GPU (see ../shared/DEVICE.md for the machine): every
# chapter with validation, every drawing chapter's picture against the lavapipe
# golden image, then the benchmarks. Results go to OUT_DIR.
#   scripts/gpu-check.sh OUT_DIR [BIN_DIR]   (BIN_DIR defaults to build/release/bin)
set -u
out=${1:?usage: scripts/gpu-check.sh OUT_DIR [BIN_DIR]}
bin=${2:-build/release/bin}
mkdir -p "$out"
status=0
vulkaninfo --summary 2>/dev/null | grep -E 'deviceName|apiVersion|driverInfo' | tee "$out/device.txt"
for c in 01_instance 02_device; do
  "$bin/$c" --validation >"$out/$c.txt" 2>&1; rc=$?
  echo "$c --validation: exit $rc, $(grep -h 'validation:' "$out/$c.txt" | tail -n 1)"
  [ $rc -eq 0 ] || status=1
done
# Every blessed golden test, run exactly as CTest runs it (the same arguments
# and hand-worked pixels; the build writes them to bin/golden_tests.txt).
manifest=$bin/golden_tests.txt
[ -f "$manifest" ] || { echo "no $manifest: build with CMake first"; exit 1; }
# Pictures whose details the specification leaves to each implementation:
# the default run is reported but not counted, and the same view without that
# feature must match its own lavapipe reference (tests/chapters/NN_name.cmake).
declare -A implementation_defined=(
  [09_textures]="anisotropic filtering|--anisotropy 1|tests/golden/09_textures_anisotropy_off.png"
)
# Chapters that need a device extension some GPUs lack. Where this device
# really lacks it (vulkaninfo does not list it), the expected result is the
# chapter's one line naming it and exit status 1: reported, not counted as a
# failure. Anything else there (another exit, no such line) is a failure.
declare -A needs_extension=(
  [24_ray_queries]=VK_KHR_ray_query
)
device_offers() {  # device_offers EXTENSION: vulkaninfo lists it (or cannot say)
  command -v vulkaninfo >/dev/null || return 0
  vulkaninfo 2>/dev/null | grep -q -E "^[[:space:]]*$1[[:space:]]*:"
}
check() {  # check NAME CHAPTER GOLDEN PIXELS ARGS: one run against one reference
  # shellcheck disable=SC2086  # pixels and args are words
  "$bin/vkt_chapter_check" --exe "$bin/$2" --out "$out" --name "gpu.$1" --golden "$3" \
    --tolerance across-devices \
    $4 -- $5 >"$out/gpu.$1.check.txt" 2>&1
}
while IFS='|' read -r c pixels args; do
  [ -x "$bin/$c" ] || continue
  extension=${needs_extension[$c]:-}
  if [ -n "$extension" ] && ! device_offers "$extension"; then
    # shellcheck disable=SC2086  # args are words
    "$bin/$c" $args >"$out/gpu.$c.stderr" 2>&1; rc=$?
    said=$(grep -h -m1 "lacks the extension $extension" "$out/gpu.$c.stderr")
    if [ $rc -eq 1 ] && [ -n "$said" ]; then
      echo "$c: expected on this device, which lacks $extension: exit 1, not counted; $said"
    else
      echo "$c: this device lacks $extension, but the chapter exited $rc without naming it: FAIL"
      status=1
    fi
    continue
  fi
  check "$c" "$c" "tests/golden/$c.png" "$pixels" "$args"; rc=$?
  result=$(grep -h -E '^picture|^FAIL' "$out/gpu.$c.check.txt" | tr '\n' ' ')
  if [ -n "${implementation_defined[$c]:-}" ]; then
    IFS='|' read -r feature extra golden <<<"${implementation_defined[$c]}"
    echo "$c picture vs lavapipe golden ($args): exit $rc, not counted ($feature is implementation-defined); $result"
    check "$c.without" "$c" "$golden" "$pixels" "$args $extra"; rc=$?
    args="$args $extra"
    result=$(grep -h -E '^picture|^FAIL' "$out/gpu.$c.without.check.txt" | tr '\n' ' ')
  fi
  echo "$c picture vs lavapipe golden ($args): exit $rc; $result"
  grep -h -E "^$c: " "$out/gpu.$c.stderr" | head -n 1
  [ $rc -eq 0 ] || status=1
done <"$manifest"
# Chapters that check themselves against a CPU reference do so on the GPU too.
if [ -x "$bin/16_deferred" ]; then
  for v in cpu additivity forward; do
    "$bin/16_deferred" --offscreen --validation --frames 10 --size 320x240 --verify $v \
      >"$out/16_deferred.verify_$v.txt" 2>&1; rc=$?
    echo "16_deferred --verify $v: exit $rc; $(grep -h -i -E 'verify|differ|error' "$out/16_deferred.verify_$v.txt" | tail -n 2 | tr '\n' ' ')"
    [ $rc -eq 0 ] || status=1
  done
fi
# Chapter 23: the sphere grid against the CPU reference and the white furnace
# (uniform sky), the furnace and the BRDF table through the image-based light,
# the start-up cost of the image-based light in GPU time, and the uniform
# sky's, the glTF model's and the bloom's pictures against their lavapipe
# goldens.
if [ -x "$bin/23_materials" ]; then
  for v in "cpu --sky uniform" "furnace --scene furnace --sky uniform" \
           "furnace --scene furnace --sky environment" "lut --sky environment"; do
    name=$(echo "$v" | tr -d -- '-' | tr ' ' '_')
    # shellcheck disable=SC2086  # the check and its scene are words
    "$bin/23_materials" --offscreen --validation --frames 10 --size 320x240 --verify $v \
      >"$out/23_materials.verify_$name.txt" 2>&1; rc=$?
    echo "23_materials --verify $v: exit $rc; $(grep -h -i -E 'verify|error|image-based' "$out/23_materials.verify_$name.txt" | tail -n 3 | tr '\n' ' ')"
    [ $rc -eq 0 ] || status=1
  done
  # NAME|PIXELS|ARGS, as tests/chapters/23_materials.cmake has them (the bloom
  # lights the corner a little: no hand-worked pixel there).
  for run in "uniform|--pixel 0,0,59,69,92|--sky uniform" \
             "model|--pixel 0,0,59,69,92|--sky uniform --model assets/gltf/pbr_cubes.gltf" \
             "bloom||--sky uniform --bloom 0.3" \
             "bloom_karis||--sky uniform --bloom 0.3 --bloom-average karis"; do
    IFS='|' read -r name pixels extra <<<"$run"
    check "23_materials.$name" 23_materials "tests/golden/23_materials_$name.png" "$pixels" \
      "--headless --validation --frames 10 --size 320x240 $extra"; rc=$?
    echo "23_materials $extra picture vs lavapipe golden: exit $rc; $(grep -h -E '^picture|^FAIL' "$out/gpu.23_materials.$name.check.txt" | tr '\n' ' ')"
    [ $rc -eq 0 ] || status=1
  done
fi
# The debug views that draw a chapter's own images (tests/chapters/22_shadows.cmake,
# 23_materials.cmake, 28_gpu_culling.cmake): each against its own lavapipe golden. 24's --view boxes
# needs VK_KHR_ray_query, checked above with the chapter.
for run in "22_shadows|22_shadows_map|320x240|--cascades 3 --view map" \
           "23_materials|23_materials_view_sky|640x480|--sky environment --view sky" \
           "23_materials|23_materials_view_irradiance|640x480|--sky environment --view irradiance" \
           "23_materials|23_materials_view_prefiltered|640x480|--sky environment --view prefiltered" \
           "23_materials|23_materials_view_brdf|640x480|--sky environment --view brdf --tone-map clamp" \
           "23_materials|23_materials_view_bloom|640x480|--sky uniform --bloom 0.3 --view bloom" \
           "23_materials|23_materials_exposure_minus_2|320x240|--sky uniform --exposure -2" \
           "23_materials|23_materials_exposure_plus_2|320x240|--sky uniform --exposure 2" \
           "23_materials|23_materials_term_d|320x240|--sky uniform --tone-map clamp --term d" \
           "23_materials|23_materials_term_f|320x240|--sky uniform --tone-map clamp --term f" \
           "23_materials|23_materials_term_v|320x240|--sky uniform --tone-map clamp --term v" \
           "28_gpu_culling|28_gpu_culling_pyramid|320x240|--instances 4096 --view pyramid --level 1" \
           "28_gpu_culling|28_gpu_culling_culled|320x240|--instances 4096 --view culled" \
           "28_gpu_culling|28_gpu_culling_task_culled|320x240|--instances 4096 --path task --view culled"; do
  IFS='|' read -r chapter name size extra <<<"$run"
  [ -x "$bin/$chapter" ] || continue
  check "$name" "$chapter" "tests/golden/$name.png" "" \
    "--headless --validation --frames 10 --size $size $extra"; rc=$?
  echo "$chapter $extra picture vs lavapipe golden: exit $rc; $(grep -h -E '^picture|^FAIL' "$out/gpu.$name.check.txt" | tr '\n' ' ')"
  [ $rc -eq 0 ] || status=1
done
# Chapter 21's settings panel drawn headless (--overlay on, page 21b). What it
# shows depends on the device (a button per sample count it offers, the
# memory the attachments take), so not against lavapipe's golden: the run
# must be validation-clean, name its widgets, and differ from the same run
# without the panel.
if [ -x "$bin/21_multisampling" ]; then
  for panel in on off; do
    "$bin/21_multisampling" --headless --validation --frames 3 --size 640x480 --overlay $panel \
      --screenshot "$out/gpu.21_multisampling_overlay_$panel.png" \
      >"$out/gpu.21_multisampling_overlay_$panel.txt" 2>&1 || status=1
  done
  "$bin/vkt_chapter_check" --compare "$out/gpu.21_multisampling_overlay_off.png" \
    "$out/gpu.21_multisampling_overlay_on.png" >"$out/gpu.21_multisampling_overlay.check.txt" 2>&1
  grep -q "^differs" "$out/gpu.21_multisampling_overlay.check.txt" || status=1
  echo "21_multisampling --overlay on: $(grep -h -E "overlay: 'Samples|validation:" "$out/gpu.21_multisampling_overlay_on.txt" | tr '\n' ' ')against --overlay off: $(grep -h -E '^(differs|same)' "$out/gpu.21_multisampling_overlay.check.txt" | cut -d: -f1)"
fi
# Chapter 25 lays its shader binding table out by the device's alignments and
# caps its recursion by the device's maxRayRecursionDepth: both lines, and the
# picture without reflections against its own lavapipe golden.
if [ -x "$bin/25_ray_tracing" ]; then
  grep -h -E '^25_ray_tracing: (shader binding table|[0-9]+ bounces)' "$out/gpu.25_ray_tracing.stderr"
  check 25_ray_tracing.no_bounces 25_ray_tracing tests/golden/25_ray_tracing_no_bounces.png \
    "--pixel 0,0,214,227,242,2 --pixel 72,168,57,57,55,2 --pixel 160,112,174,174,174,3" \
    "--offscreen --validation --frames 10 --size 320x240 --bounces 0"; rc=$?
  echo "25_ray_tracing --bounces 0 picture vs lavapipe golden: exit $rc; $(grep -h -E '^picture|^FAIL' "$out/gpu.25_ray_tracing.no_bounces.check.txt" | tr '\n' ' ')"
  [ $rc -eq 0 ] || status=1
fi
# Chapter 26: the meshlet view and chapter 15's indirect draw against their
# lavapipe references, and the task shader's culled counts beside the CPU's
# for the same view (they must agree; lavapipe: 65 of 389, all facing away),
# and the culled view (--turn 30: the task shader's verdicts as colours).
if [ -x "$bin/26_mesh_shaders" ]; then
  m26="--headless --validation --frames 10 --size 320x240"
  for v in "meshlets|tests/golden/26_mesh_shaders_meshlets.png|--view meshlets" \
           "indirect|tests/golden/26_mesh_shaders.png|--draw indirect" \
           "turn_30|tests/golden/26_mesh_shaders.png|--turn 30" \
           "view_culled|tests/golden/26_mesh_shaders_culled.png|--turn 30 --view culled"; do
    IFS='|' read -r name golden extra <<<"$v"
    [ "$name" = turn_30 ] && golden=""  # counts only: the picture is not blessed
    if [ -n "$golden" ]; then
      check "26_mesh_shaders.$name" 26_mesh_shaders "$golden" "--pixel 0,0,196,206,218,1" "$m26 $extra"; rc=$?
    else
      # shellcheck disable=SC2086  # the arguments are words
      "$bin/26_mesh_shaders" $m26 $extra >"$out/gpu.26_mesh_shaders.$name.stderr" 2>&1; rc=$?
    fi
    echo "26_mesh_shaders $extra: exit $rc; $(grep -h -E '^picture|^FAIL' "$out/gpu.26_mesh_shaders.$name.check.txt" 2>/dev/null | tr '\n' ' ')"
    [ $rc -eq 0 ] || status=1
  done
  grep -h -E "culled|the CPU culls|submitted" "$out"/gpu.26_mesh_shaders*.stderr
fi
frames=${BENCH_FRAMES:-2000}
echo "benchmarks (1280x720, $frames frames, validation off):"
benchmarks/run.sh "$bin" "$frames" 1280x720 | tee "$out/benchmarks.jsonl"
# The chapters' own sweeps (each explained in benchmarks/NN_name.md), bounded
# so that one slow sweep cannot eat the others' time.
# SWEEPS="13_compute lights" runs only those (a device run is limited to 10
# minutes: split the work over two runs if needed); SWEEPS=none runs none.
sweep() {
  local name=$1; shift
  case " ${SWEEPS:-all} " in *" all "*|*" $name "*) ;; *) return 0 ;; esac
  echo "== $name: $*"
  timeout "${SWEEP_SECONDS:-300}" "$@" >"$out/sweep.$name.txt" 2>&1
  echo "exit $?"
  cat "$out/sweep.$name.txt"
}
[ -x "$bin/13_compute" ] && sweep 13_compute scripts/bench-13.sh "$bin/13_compute" 100
[ -x "$bin/15_bindless" ] && sweep 15_bindless benchmarks/15_bindless.sh "$bin" 200
if [ -x "$bin/17_tiled_deferred" ]; then
  sweep lights scripts/bench-lights.sh "$bin/16_deferred" --tiled "$bin/17_tiled_deferred" --size 1920x1080 --frames 10
  # Chapter 17's binning: its checks, then --cull tiled against --cull binned.
  sweep binned benchmarks/17_tiled_deferred_binned.sh "$bin" 1920x1080
elif [ -x "$bin/16_deferred" ]; then
  sweep lights scripts/bench-lights.sh "$bin/16_deferred" --size 1920x1080 --frames 20
fi
[ -x "$bin/18_ndim_cpu" ] && sweep 18_ndim_cpu benchmarks/18_ndim_cpu.sh "$bin"
[ -x "$bin/19_ndim_gpu" ] && sweep 19_ndim_gpu benchmarks/19_ndim_gpu.sh "$bin" 1 offscreen
[ -x "$bin/20_ndim_compute" ] && sweep 20_ndim_compute benchmarks/20_ndim_compute.sh "$bin" 1 offscreen
[ -x "$bin/21_multisampling" ] && sweep 21_multisampling benchmarks/21_multisampling.sh "$bin"
[ -x "$bin/22_shadows" ] && sweep 22_shadows benchmarks/22_shadows.sh "$bin"
[ -x "$bin/23_materials" ] && sweep 23_materials benchmarks/23_materials_ibl.sh "$bin"
[ -x "$bin/23_materials" ] && sweep 23_materials_bloom benchmarks/23_materials_bloom.sh "$bin" 7 1920x1080 200
if [ -x "$bin/24_ray_queries" ] && device_offers VK_KHR_ray_query; then
  sweep 24_ray_queries benchmarks/24_ray_queries.sh "$bin" 1280x720 300 5
fi
[ -x "$bin/25_ray_tracing" ] && sweep 25_ray_tracing benchmarks/25_ray_tracing.sh "$bin" 1280x720 300 5
[ -x "$bin/26_mesh_shaders" ] && sweep 26_mesh_shaders benchmarks/26_mesh_shaders.sh "$bin"
# Chapter 27: recording on 1 to 16 threads (the GPU machine has 16 cores),
# then start-up with a cold and a warm pipeline cache.
[ -x "$bin/27_threads" ] && THREADS="1 2 4 8 16" sweep 27_threads benchmarks/27_threads.sh "$bin"
# Chapter 28: --cull none, frustum and occlusion at 1080p, 100,000 and
# 400,000 instances.
[ -x "$bin/28_gpu_culling" ] && sweep 28_gpu_culling benchmarks/28_gpu_culling.sh "$bin" 1920x1080 200 100000 400000
# Chapter 29: the bloom on one queue and on a compute queue, with 48 and 512 lamps.
[ -x "$bin/29_async_compute" ] && sweep 29_async_compute benchmarks/29_async_compute.sh "$bin"
exit $status
