#!/usr/bin/env bash
# The README's two commands, proven on a fresh Debian system (as root):
#
#   scripts/test-in-root.sh DIST [--keep] [--record]
#
#   DIST      bookworm (Debian 12) or trixie (Debian 13)
#   --keep    leave the root in place afterwards (its path is printed)
#   --record  also write the summary and any failing tests to
#             tests/roots/DIST.txt, the record kept in the repository
#
# Makes a minimal root with debootstrap from Debian's archive (minbase: apt
# and little else), puts a clean clone of the current commit in it (what is
# not committed is not tested, and the script says so), and inside it runs,
# exactly as the README writes them,
#
#   scripts/quickstart.sh
#   cmake --workflow --preset release
#
# The first installs the packages from the archive and builds; the second
# runs in a network namespace of its own with only loopback, which proves
# that nothing is downloaded at configure, build or test time, and keeps the
# root's virtual X servers apart from any on this machine (X's abstract
# sockets belong to a network namespace). It ends with one line: the
# commands, their exit status, the tests passed and the minutes taken.
#
# On the 2-core machine a run takes 4 to 30 minutes
# (tests/roots/ has the last record of each): too long for every CI run. Run
# both before a release, after any change to install-deps.sh, the CMake
# files or the packages a chapter needs, and when Debian moves a package.
#
# VKT_ROOTS_DIR   where roots are made (default /var/tmp/vkt-roots)
# VKT_MIRROR      the Debian archive (default http://deb.debian.org/debian)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
say() { printf 'test-in-root: %s\n' "$*"; }
die() {
  say "$2" >&2
  exit "$1"
}

dist='' keep=false record=false
for arg in "$@"; do
  case $arg in
    bookworm | trixie) dist=$arg ;;
    --keep) keep=true ;;
    --record) record=true ;;
    -h | --help)
      sed -n '2,31p' "$0" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *) die 2 "unknown argument '$arg' (usage: scripts/test-in-root.sh bookworm|trixie [--keep] [--record])" ;;
  esac
done
[ -n "$dist" ] || die 2 "which system? usage: scripts/test-in-root.sh bookworm|trixie [--keep] [--record]"
[ "$(id -u)" -eq 0 ] || die 2 "debootstrap, chroot and mount need root: run it as root (sudo)"
for tool in debootstrap git unshare ip mount chroot; do
  command -v "$tool" >/dev/null ||
    die 2 "$tool is missing (apt install debootstrap git util-linux iproute2 mount coreutils)"
done

commit=$(git -C "$repo" rev-parse HEAD)
short=${commit:0:7}
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no)" ]; then
  say "note: the work tree has uncommitted changes; the root tests commit $short only"
fi

mirror=${VKT_MIRROR:-http://deb.debian.org/debian}
roots=${VKT_ROOTS_DIR:-/var/tmp/vkt-roots}
root=$roots/$dist-$short-$$
cache=/var/cache/vkt-debootstrap/$dist  # the .debs, kept: a later run fetches less
logs=$roots/$dist-$short-$$.logs
mkdir -p "$roots" "$cache" "$logs"

mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" 2>/dev/null || true; done
  if $keep; then
    say "root kept: $root (logs: $logs)"
  else
    rm -rf --one-file-system "$root"
  fi
}
trap cleanup EXIT
mount_in() {  # mount_in TARGET MOUNT-ARGS...: mounts inside the root, undone on exit
  mkdir -p "$root$1"
  mount "${@:2}" "$root$1"
  mounted+=("$root$1")
}

start=$SECONDS
minutes() { awk -v s="$1" 'BEGIN { printf "%.1f", s / 60 }'; }

say "$dist: a minimal root in $root (debootstrap --variant=minbase, $mirror)"
debootstrap --variant=minbase --cache-dir="$cache" "$dist" "$root" "$mirror" >"$logs/debootstrap.log" 2>&1 ||
  die 1 "debootstrap failed: see $logs/debootstrap.log"
mount_in /proc -t proc proc
mount_in /sys -t sysfs sys
mount_in /dev --bind /dev
mount_in /dev/pts --bind /dev/pts
mount_in /dev/shm -t tmpfs shm  # chromium (the book's test) wants its own
cp /etc/resolv.conf "$root/etc/resolv.conf"
# Packages must not start services in the root.
printf '#!/bin/sh\nexit 101\n' >"$root/usr/sbin/policy-rc.d"
chmod +x "$root/usr/sbin/policy-rc.d"

git clone --quiet --no-hardlinks "$repo" "$root/root/tutorial"
git -C "$root/root/tutorial" checkout --quiet --detach "$commit"
say "$dist: a clean clone of $short in /root/tutorial"

# inside LOG COMMAND: runs COMMAND in the root's clone, with a clean
# environment (no DISPLAY: quickstart runs its chapter headless).
inside() {
  local log=$1
  shift
  chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    bash -c "cd /root/tutorial && $*" >"$log" 2>&1
}

t=$SECONDS
say "$dist: scripts/quickstart.sh (log: $logs/quickstart.log)"
quick_status=0
inside "$logs/quickstart.log" scripts/quickstart.sh || quick_status=$?
quick_time=$((SECONDS - t))
say "$dist: scripts/quickstart.sh exit $quick_status, $(minutes $quick_time) min"

workflow_status=0 workflow_time=0
if [ "$quick_status" -eq 0 ]; then
  t=$SECONDS
  say "$dist: cmake --workflow --preset release, offline (log: $logs/workflow.log)"
  # Its own network namespace: loopback only, its own X sockets.
  export -f inside
  export root
  # shellcheck disable=SC2016 # $1 is expanded by the inner bash
  unshare --net -- bash -c 'ip link set lo up && inside "$1" "cmake --workflow --preset release"' \
    _ "$logs/workflow.log" || workflow_status=$?
  workflow_time=$((SECONDS - t))
  say "$dist: cmake --workflow --preset release exit $workflow_status, $(minutes $workflow_time) min"
else
  say "$dist: the workflow is not run: quickstart failed (tail of its log follows)"
  tail -n 20 "$logs/quickstart.log" >&2
fi

# The accounting step's line ("release on debian:trixie: 797 tests, 797 run,
# 797 passed, 0 skipped as expected"), else CTest's own summary of the test
# step ("100% tests passed, 0 tests failed out of 537"), the first one.
tests='no tests ran'
if account_line=$(grep -E '^([0-9]+: )?account_tests: release on ' "$logs/workflow.log" 2>/dev/null | tail -n 1); then
  tests=$(sed -E 's/^.*account_tests: release on //' <<<"$account_line")
elif ctest_line=$(grep -E '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$logs/workflow.log" 2>/dev/null | head -n 1); then
  total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$ctest_line")
  failed=$(sed -E 's/.*passed, ([0-9]+) tests? failed.*/\1/' <<<"$ctest_line")
  tests="$((total - failed)) of $total tests passed"
fi
summary="$dist at $short: quickstart.sh exit $quick_status ($(minutes $quick_time) min), cmake --workflow --preset release exit $workflow_status ($(minutes $workflow_time) min), $tests; $(minutes $((SECONDS - start))) min in all"
failures=$(sed -n '/The following tests FAILED/,$p' "$logs/workflow.log" 2>/dev/null | grep -E '^\s+[0-9]+ - ' || true)

version() { chroot "$root" dpkg-query -W -f="\${Package} \${Version}" "$1" 2>/dev/null || echo "$1 unknown"; }
if $record; then
  mkdir -p "$repo/tests/roots"
  {
    echo "# scripts/test-in-root.sh $dist, $(date -u '+%Y-%m-%d %H:%M UTC'), on $(nproc) cores"
    echo "$summary"
    echo "$(version mesa-vulkan-drivers), $(version libtinygltf-dev), $(version catch2), $(version g++)"
    [ -z "$failures" ] || printf 'failed:\n%s\n' "$failures"
  } >"$repo/tests/roots/$dist.txt"
  say "recorded in tests/roots/$dist.txt"
fi
[ -z "$failures" ] || printf 'test-in-root: failed:\n%s\n' "$failures"
say "$summary"
[ "$quick_status" -eq 0 ] && [ "$workflow_status" -eq 0 ]
