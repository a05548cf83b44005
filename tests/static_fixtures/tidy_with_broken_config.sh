#!/usr/bin/env bash
# The system's clang-tidy (15 or newer) given a configuration that does not
# parse: scripts/static-checks.sh must refuse to run it
# (tests/CMakeLists.txt, static.tidy_broken_config_fails).
here=$(cd "$(dirname "$0")" && pwd)
for candidate in clang-tidy-16 clang-tidy-17 clang-tidy-19 clang-tidy-18 clang-tidy-15 clang-tidy; do
  if command -v "$candidate" >/dev/null; then
    exec "$candidate" --config-file="$here/broken.clang-tidy" "$@"
  fi
done
echo "no clang-tidy (apt install clang-tidy-16)" >&2
exit 127
