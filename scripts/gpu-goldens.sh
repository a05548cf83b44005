#!/usr/bin/env bash
# Every golden image's run, again, on whatever Vulkan device the loader picks
# (the GPU machine: ../shared/DEVICE.md), its picture kept: the pictures in
# tests/golden/other/gpu-*/ were made this way on an NVIDIA H200.
#
#   scripts/gpu-goldens.sh OUT_DIR [BUILD_DIR]     (default build/release)
#
# The runs are the tests that own a golden image (the checker's --blesses),
# read from CTest's own list, each with --offscreen for --headless (a GPU
# machine has no headless surface). Each picture is OUT_DIR/NAME.png, named
# after its golden image, with the run's output beside it (NAME.log); one line
# per run: its exit status and validation report.
set -u
out=${1:?usage: scripts/gpu-goldens.sh OUT_DIR [BUILD_DIR]}
build=${2:-build/release}
mkdir -p "$out"
(cd "$build" && ctest --show-only=json-v1) | python3 -c '
import json, sys
for test in json.load(sys.stdin)["tests"]:
    command = test.get("command") or []
    if "--blesses" not in command:
        continue
    golden = command[command.index("--golden") + 1].rsplit("/", 1)[-1][:-4]
    args = ["--offscreen" if a == "--headless" else a for a in command[command.index("--") + 1:]]
    print(golden + "|" + command[command.index("--exe") + 1] + "|" + " ".join(args))
' | while IFS='|' read -r name exe args; do
  # shellcheck disable=SC2086  # args are words
  "$exe" $args --screenshot "$out/$name.png" >"$out/$name.log" 2>&1
  echo "$name: exit $?, $(grep -h 'validation:' "$out/$name.log" | tail -n 1)"
done
