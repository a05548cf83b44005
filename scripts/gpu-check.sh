#!/usr/bin/env bash
# What we run on a real GPU (see ../shared/DEVICE.md for the machine): every
# chapter with validation, every drawing chapter's picture against the lavapipe
# golden image, then the benchmarks. Results go to OUT_DIR.
#   scripts/gpu-check.sh OUT_DIR
set -u
out=${1:?usage: scripts/gpu-check.sh OUT_DIR}
bin=build/release/bin
mkdir -p "$out"
status=0
vulkaninfo --summary 2>/dev/null | grep -E 'deviceName|apiVersion|driverInfo' | tee "$out/device.txt"
for c in 01_instance 02_device; do
  "$bin/$c" --validation >"$out/$c.txt" 2>&1; rc=$?
  echo "$c --validation: exit $rc, $(grep -h 'validation:' "$out/$c.txt" | tail -n 1)"
  [ $rc -eq 0 ] || status=1
done
# Every drawing chapter that has a reference picture, with its own defaults.
for golden in tests/golden/[0-9][0-9]_*.png; do
  c=$(basename "$golden" .png)
  [ -x "$bin/$c" ] || continue
  "$bin/vkt_chapter_check" --exe "$bin/$c" --out "$out" --name "gpu.$c" --golden "tests/golden/$c.png" \
    -- --headless --validation --frames 10 --size 320x240 >"$out/gpu.$c.check.txt" 2>&1; rc=$?
  echo "$c picture vs lavapipe golden: exit $rc; $(grep -h -E '^picture|^FAIL' "$out/gpu.$c.check.txt")"
  grep -h -E "^$c: " "$out/gpu.$c.stderr" | head -n 1
  [ $rc -eq 0 ] || status=1
done
echo "benchmarks (1280x720, 2000 frames, validation off):"
benchmarks/run.sh "$bin" 2000 1280x720 | tee "$out/benchmarks.jsonl"
exit $status
