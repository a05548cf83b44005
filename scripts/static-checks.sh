#!/usr/bin/env bash
# The static checks CI runs (.ci/run), each over the whole tree:
#   clang-tidy    .clang-tidy's checks over every source file of common/ and
#                 chapters/, compiled as the release build compiles them
#                 (build/release/compile_commands.json: configure it first)
#   clang-format  --dry-run --Werror over every C++ file (.clang-format)
#   ShellCheck    over scripts/*.sh, tests/*.sh and benchmarks/*.sh (.shellcheckrc)
# Each prints its findings; the exit status is 0 only if all three are clean.
#
#   scripts/static-checks.sh [JOBS]     JOBS clang-tidy processes (default: cores)
#   scripts/static-checks.sh --tidy-only [JOBS]    clang-tidy alone
#
# VKT_COMPILE_DB (default build/release/compile_commands.json) and VKT_TIDY
# (default: the newest clang-tidy 15+ found) name what the clang-tidy part
# uses; the fixtures in tests/static_fixtures/ use them to prove the script
# fails when clang-tidy fails (a crash, a broken .clang-tidy) or when it is
# given no source file at all: a check that cannot run must not pass.
#
# clang-tidy must be 15 or newer (Debian 12: clang-tidy-16): clang 14 cannot
# parse GCC 12's <source_location>, which every file includes.
#
# Every clang-tidy finding fails the run (the files once left out while they
# were being restructured are clean now).
set -u
cd "$(dirname "$0")/.." || exit 2
tidy_only=false
if [ "${1:-}" = "--tidy-only" ]; then
  tidy_only=true
  shift
fi
jobs=${1:-$(nproc)}
failed=()

tidy=${VKT_TIDY:-}
if [ -z "$tidy" ]; then
  for candidate in clang-tidy-16 clang-tidy-17 clang-tidy-15 clang-tidy; do
    command -v "$candidate" >/dev/null || continue
    version=$("$candidate" --version | grep -oE 'version [0-9]+' | grep -oE '[0-9]+')
    if [ "${version:-0}" -ge 15 ]; then tidy=$candidate; break; fi
  done
fi
[ -n "$tidy" ] || { echo "static-checks: no clang-tidy 15 or newer (apt install clang-tidy-16)"; exit 2; }
if ! $tidy_only; then
  for tool in clang-format shellcheck; do
    command -v "$tool" >/dev/null || { echo "static-checks: $tool is missing (apt install $tool)"; exit 2; }
  done
fi
db=${VKT_COMPILE_DB:-build/release/compile_commands.json}
[ -f "$db" ] || { echo "static-checks: no $db (cmake --preset release first)"; exit 2; }

# --- clang-tidy --------------------------------------------------------------
start=$SECONDS
out=$(mktemp -d -t static-checks.XXXXXX)
trap 'rm -rf "$out"' EXIT
mapfile -t sources < <(python3 - "$db" <<'PY'
import json, os, sys
root = os.getcwd() + "/"
for entry in json.load(open(sys.argv[1])):
    path = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
    rel = path[len(root):] if path.startswith(root) else path
    if rel.startswith(("common/", "chapters/")):
        print(rel)
PY
)
if [ "${#sources[@]}" -eq 0 ]; then
  echo "static-checks: $db names no source file of common/ or chapters/: clang-tidy checked nothing"
  exit 1
fi
# The configuration itself: a .clang-tidy that does not parse, or names a
# check that does not exist, must stop the run, not fall back to defaults.
if ! config_report=$("$tidy" --verify-config 2>&1) || grep -qE 'Error parsing|error:|unknown check' <<<"$config_report"; then
  printf '%s\n' "$config_report"
  echo "static-checks: $tidy --verify-config rejects .clang-tidy"
  exit 1
fi
# One process per file, JOBS at a time; each file's report in a file of its
# own, and its exit status beside it.
# shellcheck disable=SC2016  # the inner shell expands $1..$4, not this one
printf '%s\n' "${sources[@]}" | sort -u |
  xargs -P "$jobs" -I{} sh -c \
    'f="$4/$(echo "$3" | tr / _)"; "$1" -p "$2" --quiet "$3" >"$f.txt" 2>&1; echo $? >"$f.status"' \
    _ "$tidy" "$db" {} "$out"
# A file clang-tidy did not finish (a crash, a compile error, a bad option)
# fails the run whatever its report says. (A finding made an error by
# WarningsAsErrors also exits 1: that file is reported with its findings.)
broken=()
for status in "$out"/*.status; do
  [ -e "$status" ] || continue
  code=$(cat "$status")
  report=${status%.status}.txt
  if [ "$code" != 0 ] && ! grep -qE '^/.*:[0-9]+:[0-9]+: (error|warning): ' "$report"; then
    broken+=("$(basename "${status%.status}") (exit $code): $(grep -m1 -E 'error|Error|fault|Abort' "$report" || tail -n 1 "$report")")
  fi
done
checked=$(find "$out" -name '*.status' | wc -l)
if [ "$checked" -ne "$(printf '%s\n' "${sources[@]}" | sort -u | wc -l)" ]; then
  broken+=("only $checked of ${#sources[@]} files were checked")
fi
if [ "${#broken[@]}" -gt 0 ]; then
  echo "clang-tidy failed on ${#broken[@]} files:"
  printf '  %s\n' "${broken[@]}"
  failed+=(clang-tidy)
fi
# Findings, each once (a header's are found by every file that includes it).
mapfile -t findings < <(cat "$out"/*.txt | grep -E '^/.*:[0-9]+:[0-9]+: (error|warning): ' |
                        sed "s|^$PWD/||" | sort -u)
if [ "${#findings[@]}" -gt 0 ]; then
  echo "clang-tidy: ${#findings[@]} findings:"
  printf '  %s\n' "${findings[@]}"
  failed+=(clang-tidy)
fi
echo "clang-tidy ($tidy): ${#sources[@]} files, ${#findings[@]} findings, $((SECONDS - start)) s"
if $tidy_only; then
  [ "${#failed[@]}" -eq 0 ] || { echo "static checks FAILED: ${failed[*]}"; exit 1; }
  echo "static checks passed (clang-tidy only)"
  exit 0
fi

# --- clang-format ------------------------------------------------------------
start=$SECONDS
mapfile -t cpp < <(git ls-files '*.cpp' '*.hpp' '*.h')
[ "${#cpp[@]}" -gt 0 ] || { echo "static-checks: git ls-files found no C++ file"; exit 1; }
if ! clang-format --dry-run --Werror "${cpp[@]}"; then failed+=(clang-format); fi
echo "clang-format: ${#cpp[@]} files, $((SECONDS - start)) s"

# --- shellcheck --------------------------------------------------------------
start=$SECONDS
mapfile -t shells < <(git ls-files 'scripts/*.sh' 'tests/*.sh' 'benchmarks/*.sh' .ci/run)
[ "${#shells[@]}" -gt 0 ] || { echo "static-checks: git ls-files found no shell script"; exit 1; }
if ! shellcheck -x "${shells[@]}"; then failed+=(shellcheck); fi
echo "shellcheck: ${#shells[@]} files, $((SECONDS - start)) s"

if [ "${#failed[@]}" -gt 0 ]; then
  echo "static checks FAILED: ${failed[*]}"
  exit 1
fi
echo "static checks passed"
