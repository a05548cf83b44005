#!/usr/bin/env bash
# Runs the tests with one CTest label (or all of them) COUNT times in a row,
# optionally while both cores are kept busy, and counts the failures. Use it
# after any change to the runner or the tests: a test that fails once in a
# hundred runs is a broken test.
#
#   scripts/repeat-tests.sh LABEL COUNT [--load]
#     LABEL   a CTest label (window, chapter, unit, book), "all", or
#             regex:REGEX for the tests whose names match REGEX
#     COUNT   how many times to run them
#     --load  keep every core busy meanwhile (stress-ng --cpu N, N = cores)
#
# Needs a release build (cmake --preset release && cmake --build --preset release).
# Prints one line per failing run (with the failing tests) and a summary; the
# exit status is 0 only if every run passed. Logs go to build/release/repeat/.
set -u
cd "$(dirname "$0")/.." || exit 2
label=${1:?usage: scripts/repeat-tests.sh LABEL COUNT [--load]}
count=${2:?usage: scripts/repeat-tests.sh LABEL COUNT [--load]}
load=${3:-}
logs=build/release/repeat
mkdir -p "$logs"
[ -f build/release/CTestTestfile.cmake ] || { echo "no release build: cmake --workflow --preset release first"; exit 2; }

select=(-L "$label")
[ "$label" = all ] && select=()
case $label in regex:*) select=(-R "${label#regex:}") ;; esac

stress=""
if [ "$load" = --load ]; then
  command -v stress-ng >/dev/null || { echo "--load needs stress-ng (apt install stress-ng)"; exit 2; }
  stress-ng --cpu "$(nproc)" --quiet &
  stress=$!
  # Continued as well as killed: a held (stopped) process takes no signal.
  trap 'kill $stress 2>/dev/null; pkill -CONT -P $stress; kill -CONT $stress 2>/dev/null; wait $stress 2>/dev/null' EXIT
fi

# One line per run in $logs/progress, so that a long repeat can be read (or
# stopped) before it ends; touch $logs/pause to hold it between runs.
: >"$logs/progress"
failures=0
tests_per_run=0
start=$(date +%s.%N)
for run in $(seq "$count"); do
  # A file named "pause" in the log folder holds the repeat (and its load)
  # between two runs, e.g. while a benchmark needs the machine quiet.
  if [ -e "$logs/pause" ]; then
    echo "paused before run $run" >>"$logs/progress"
    if [ -n "$stress" ]; then pkill -STOP -P "$stress"; kill -STOP "$stress"; fi
    while [ -e "$logs/pause" ]; do sleep 2; done
    if [ -n "$stress" ]; then kill -CONT "$stress"; pkill -CONT -P "$stress"; fi
  fi
  log="$logs/${label//[^A-Za-z0-9_.-]/_}.$run.log"
  if ctest --preset release "${select[@]}" >"$log" 2>&1; then
    rm -f "$log"
    echo "run $run passed" >>"$logs/progress"
  else
    echo "run $run FAILED" >>"$logs/progress"
    failures=$((failures + 1))
    echo "run $run FAILED: $(grep -E '^\s+[0-9]+ - ' "$log" | sed 's/^ *//' | tr '\n' ' ') (log: $log)"
  fi
  [ "$tests_per_run" -eq 0 ] && tests_per_run=$(ctest --preset release "${select[@]}" -N | grep -oE 'Total Tests: [0-9]+' | grep -oE '[0-9]+')
done
elapsed=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
printf '%s: %d runs of %d tests%s, %d failed, %.0f s in all (%.1f s per run)\n' \
  "$label" "$count" "$tests_per_run" "${stress:+ under load (stress-ng --cpu $(nproc))}" \
  "$failures" "$elapsed" "$(awk -v e="$elapsed" -v n="$count" 'BEGIN { print e / n }')"
[ "$failures" -eq 0 ]
