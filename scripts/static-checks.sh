#!/usr/bin/env bash
# The static checks CI runs (.ci/run), each over the whole tree:
#   clang-tidy    .clang-tidy's checks over every source file of common/ and
#                 chapters/, compiled as the release build compiles them
#                 (build/release/compile_commands.json: configure it first)
#   clang-format  --dry-run --Werror over every C++ file (.clang-format)
#   ShellCheck    over scripts/*.sh and tests/*.sh (.shellcheckrc)
# Each prints its findings; the exit status is 0 only if all three are clean.
#
#   scripts/static-checks.sh [JOBS]     JOBS clang-tidy processes (default: cores)
#
# clang-tidy must be 15 or newer (Debian 12: clang-tidy-16): clang 14 cannot
# parse GCC 12's <source_location>, which every file includes.
#
# Every clang-tidy finding fails the run (the files once left out while they
# were being restructured are clean now).
set -u
cd "$(dirname "$0")/.." || exit 2
jobs=${1:-$(nproc)}
failed=()

tidy=""
for candidate in clang-tidy-16 clang-tidy-17 clang-tidy-15 clang-tidy; do
  command -v "$candidate" >/dev/null || continue
  version=$("$candidate" --version | grep -oE 'version [0-9]+' | grep -oE '[0-9]+')
  if [ "${version:-0}" -ge 15 ]; then tidy=$candidate; break; fi
done
[ -n "$tidy" ] || { echo "static-checks: no clang-tidy 15 or newer (apt install clang-tidy-16)"; exit 2; }
for tool in clang-format shellcheck; do
  command -v "$tool" >/dev/null || { echo "static-checks: $tool is missing (apt install $tool)"; exit 2; }
done
db=build/release/compile_commands.json
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
# One process per file, JOBS at a time; each file's report in a file of its own.
# shellcheck disable=SC2016  # the inner shell expands $1..$4, not this one
printf '%s\n' "${sources[@]}" | sort -u |
  xargs -P "$jobs" -I{} sh -c '"$1" -p "$2" --quiet "$3" >"$4/$(echo "$3" | tr / _).txt" 2>&1' \
    _ "$tidy" "$db" {} "$out"
# Findings, each once (a header's are found by every file that includes it).
mapfile -t findings < <(cat "$out"/*.txt | grep -E '^/.*:[0-9]+:[0-9]+: (error|warning): ' |
                        sed "s|^$PWD/||" | sort -u)
if [ "${#findings[@]}" -gt 0 ]; then
  echo "clang-tidy: ${#findings[@]} findings:"
  printf '  %s\n' "${findings[@]}"
  failed+=(clang-tidy)
fi
echo "clang-tidy ($tidy): ${#sources[@]} files, ${#findings[@]} findings, $((SECONDS - start)) s"

# --- clang-format ------------------------------------------------------------
start=$SECONDS
mapfile -t cpp < <(git ls-files '*.cpp' '*.hpp' '*.h')
if ! clang-format --dry-run --Werror "${cpp[@]}"; then failed+=(clang-format); fi
echo "clang-format: ${#cpp[@]} files, $((SECONDS - start)) s"

# --- shellcheck --------------------------------------------------------------
start=$SECONDS
mapfile -t shells < <(git ls-files 'scripts/*.sh' 'tests/*.sh' .ci/run)
if ! shellcheck -x "${shells[@]}"; then failed+=(shellcheck); fi
echo "shellcheck: ${#shells[@]} files, $((SECONDS - start)) s"

if [ "${#failed[@]}" -gt 0 ]; then
  echo "static checks FAILED: ${failed[*]}"
  exit 1
fi
echo "static checks passed"
