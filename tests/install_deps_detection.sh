#!/usr/bin/env bash
# scripts/install-deps.sh reads os-release first and acts by what it finds. This
# runs its --dry-run against fake os-release files (Debian 12 and 13, Ubuntu 24.04,
# Fedora, an Ubuntu derivative, an unknown system, none at all) and checks the
# actions it names, that an unsupported system exits non-zero, and that nothing
# was written or run: every command that could change the machine is replaced
# by a stub that records the call, and the apt sources folder is an empty one
# of our own.
#
#   tests/install_deps_detection.sh <repository root>
set -uo pipefail
script=${1:?usage: install_deps_detection.sh <repository root>}/scripts/install-deps.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir "$work/bin" "$work/sources" "$work/os"
for cmd in apt-get apt-cache apt sudo tee dpkg dpkg-query snap dnf pacman add-apt-repository vulkaninfo; do
  printf '#!/bin/sh\necho "%s $*" >>"%s/calls"\nexit 1\n' "$cmd" "$work" >"$work/bin/$cmd"
  chmod +x "$work/bin/$cmd"
done

cat >"$work/os/debian-12" <<'EOF'
PRETTY_NAME="Debian GNU/Linux 12 (bookworm)"
NAME="Debian GNU/Linux"
VERSION_ID="12"
VERSION="12 (bookworm)"
VERSION_CODENAME=bookworm
ID=debian
EOF
cat >"$work/os/debian-13" <<'EOF'
PRETTY_NAME="Debian GNU/Linux 13 (trixie)"
NAME="Debian GNU/Linux"
VERSION_ID="13"
VERSION="13 (trixie)"
VERSION_CODENAME=trixie
ID=debian
EOF
cat >"$work/os/ubuntu-24.04" <<'EOF'
PRETTY_NAME="Ubuntu 24.04.2 LTS"
NAME="Ubuntu"
VERSION_ID="24.04"
VERSION="24.04.2 LTS (Noble Numbat)"
VERSION_CODENAME=noble
ID=ubuntu
ID_LIKE=debian
UBUNTU_CODENAME=noble
EOF
cat >"$work/os/fedora" <<'EOF'
NAME="Fedora Linux"
VERSION="40 (Workstation Edition)"
ID=fedora
VERSION_ID=40
PRETTY_NAME="Fedora Linux 40 (Workstation Edition)"
EOF
cat >"$work/os/mint" <<'EOF'
NAME="Linux Mint"
VERSION="22 (Wilma)"
ID=linuxmint
ID_LIKE="ubuntu debian"
PRETTY_NAME="Linux Mint 22"
VERSION_ID="22"
UBUNTU_CODENAME=noble
EOF
# No final newline, and a line a shell would run if the file were sourced.
# shellcheck disable=SC2016 # the $( ) must reach the file unexpanded
printf 'NAME=Plan9\nID=plan9\nVERSION_ID=4\nPRETTY_NAME="$(touch %s/sourced)"' "$work" >"$work/os/unknown"

passed=0 failed=0
check() { # check DESCRIPTION COMMAND...
  if "${@:2}"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAIL: $1"
  fi
}
has() { grep -qE -- "$1" "$out"; }
lacks() { ! grep -qE -- "$1" "$out"; }

# dry OS_FILE [SOURCES_DIR]: runs the dry run; sets $out and $status.
dry() {
  out=$work/out.$(basename "$1")
  PATH="$work/bin:$PATH" VKT_OS_RELEASE=$1 VKT_APT_SOURCES_DIR=${2:-$work/sources} \
    bash "$script" --dry-run >"$out" 2>&1
  status=$?
  echo "--- $(basename "$1"): exit $status"
  cat "$out"
}

dry "$work/os/debian-12"
check "debian-12: exit 0" test "$status" -eq 0
check "debian-12: plan" has '^install-deps: plan: debian-12'
check "debian-12: would write the backports source" \
  has "would write: $work/sources/bookworm-backports.sources \\(bookworm-backports, main\\)"
check "debian-12: apt-get update" has 'would run: apt-get update'
for pkg in libvulkan-dev libglfw3-dev libtinygltf-dev libpng-dev libjpeg-dev libstb-dev \
  glslang-tools python3-markdown python3-matplotlib graphviz chromium shellcheck clang-tidy clang \
  libclang-rt-14-dev clang-16 libclang-rt-16-dev clang-tidy-16 fonts-dejavu-core clang-format \
  nlohmann-json3-dev gdb; do
  check "debian-12: installs $pkg" has "would run: apt-get install .* $pkg( |\$)"
done
check "debian-12: Mesa and Catch2 from backports" \
  has 'would run: apt-get install .*-t bookworm-backports mesa-vulkan-drivers catch2$'
check "debian-12: no ccache" lacks ccache

mkdir "$work/sources-present"
touch "$work/sources-present/bookworm-backports.sources"
dry "$work/os/debian-12" "$work/sources-present"
check "debian-12, source already there: exit 0" test "$status" -eq 0
check "debian-12, source already there: not written again" has 'already there: .*bookworm-backports.sources'
check "debian-12, source already there: no write" lacks 'would write'

check "debian-12: the system named as recognised" has '^install-deps: system: Debian 12 \(bookworm\) \(os-release: ID=debian, VERSION_ID=12'

dry "$work/os/debian-13"
check "debian-13: exit 0" test "$status" -eq 0
check "debian-13: plan" has '^install-deps: plan: debian-13'
check "debian-13: the system named as recognised" has '^install-deps: system: Debian 13 \(trixie\) \(os-release: ID=debian, VERSION_ID=13'
check "debian-13: apt-get update" has 'would run: apt-get update'
for pkg in libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers catch2 libglfw3-dev libglm-dev \
  libtinygltf-dev libpng-dev libjpeg-dev libstb-dev glslang-tools python3-matplotlib graphviz \
  chromium shellcheck clang clang-tidy libclang-rt-19-dev clang-format nlohmann-json3-dev gdb; do
  check "debian-13: installs $pkg" has "would run: apt-get install .* $pkg( |\$)"
done
check "debian-13: no apt source written" lacks 'would write|already there|sources\.list'
check "debian-13: no backports" lacks 'backports'
check "debian-13: no clang-16 (trixie has none)" lacks 'would run: apt-get install .*(clang-16|clang-tidy-16|libclang-rt-16-dev)'
check "debian-13: names the fuzz-clang preset" has 'preset fuzz-clang'

dry "$work/os/ubuntu-24.04"
check "ubuntu-24.04: exit 0" test "$status" -eq 0
check "ubuntu-24.04: the system named as recognised" has '^install-deps: system: Ubuntu 24.04 \(noble\)'

check "ubuntu-24.04: plan" has '^install-deps: plan: ubuntu-24.04'
check "ubuntu-24.04: apt-get update" has 'would run: apt-get update'
for pkg in libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers catch2 libglfw3-dev libglm-dev \
  libtinygltf-dev libpng-dev libjpeg-dev libstb-dev glslang-tools python3-matplotlib graphviz \
  shellcheck clang clang-tidy libclang-rt-18-dev clang-format nlohmann-json3-dev gdb; do
  check "ubuntu-24.04: installs $pkg" has "would run: apt-get install .* $pkg( |\$)"
done
check "ubuntu-24.04: no apt source written" lacks 'would write|already there|sources\.list'
check "ubuntu-24.04: never a Debian archive" lacks 'bookworm|backports|debian\.org'
check "ubuntu-24.04: no Debian clang runtime" lacks 'libclang-rt-14-dev'
check "ubuntu-24.04: chromium not installed" lacks 'would run: apt-get install .*chromium'
check "ubuntu-24.04: chromium skipped, with why" has 'chromium: skipped: .* snap'
check "ubuntu-24.04: the browser test is said to be skipped" has 'browser test is skipped'
check "ubuntu-24.04: names the headless-surface tests" has 'chapter\.04_triangle\.no_display'
check "ubuntu-24.04: names the chapters by feature" has 'maintenance4 \(13, 17, 20\)'
check "ubuntu-24.04: would check lavapipe" has 'would check: .*VK_EXT_headless_surface'
# Debian's versioned clang (the fuzz preset's clang++-16) is not Ubuntu's: the
# notes send the reader to the preset that uses Ubuntu's own clang++ (18).
check "ubuntu-24.04: no Debian-versioned clang" lacks 'would run: apt-get install .*(clang-16|clang-tidy-16|libclang-rt-16-dev)'
check "ubuntu-24.04: names the fuzz-clang preset" has 'preset fuzz-clang'

dry "$work/os/fedora"
check "fedora: exit 3" test "$status" -eq 3
check "fedora: changed nothing" has 'Changed nothing'
check "fedora: dnf names" has 'sudo dnf install .*vulkan-loader-devel.* libpng-devel libjpeg-turbo-devel .*python3-matplotlib .*clang-tools-extra'
check "fedora: runs nothing" lacks 'would run|would write'
check "fedora: the fuzzers' json and gdb" has 'sudo dnf install .* json-devel gdb'

dry "$work/os/mint"
check "ubuntu derivative: exit 3" test "$status" -eq 3
check "ubuntu derivative: not named as a system it installs on" has '^install-deps: system: not one this script installs on \(os-release: ID=linuxmint'

check "ubuntu derivative: apt names" has 'sudo apt-get install .*libvulkan-dev'
check "ubuntu derivative: points at the Ubuntu 24.04 names" has 'built on Ubuntu 24.04'
check "ubuntu derivative: runs nothing" lacks 'would run|would write'

dry "$work/os/unknown"
check "unknown: exit 3" test "$status" -eq 3
check "unknown: changed nothing" has 'Changed nothing'
check "unknown: Fedora names" has 'sudo dnf install '
check "unknown: Arch names" has 'sudo pacman -S --needed .*vulkan-swrast'
check "unknown: Arch's json and gdb" has 'sudo pacman -S --needed .* nlohmann-json gdb'
check "unknown: Debian/Ubuntu names" has 'sudo apt-get install '
check "unknown: runs nothing" lacks 'would run|would write'
check "unknown: os-release read as data, not run" test ! -e "$work/sourced"

dry "$work/os/missing"
check "no os-release: exit non-zero" test "$status" -ne 0
check "no os-release: says so" has "cannot read $work/os/missing"

# A fake os-release without --dry-run is refused before anything happens.
out=$work/out.real
PATH="$work/bin:$PATH" VKT_OS_RELEASE=$work/os/ubuntu-24.04 VKT_APT_SOURCES_DIR=$work/sources \
  bash "$script" >"$out" 2>&1
status=$?
check "fake os-release without --dry-run: exit 2" test "$status" -eq 2
check "fake os-release without --dry-run: refused" has 'use it with --dry-run only'

check "nothing was run: no stub was called" test ! -e "$work/calls"
[ -e "$work/calls" ] && cat "$work/calls"
check "nothing was written into the apt sources folder" test -z "$(ls -A "$work/sources")"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
