#!/usr/bin/env bash
# Installs what the tutorial needs, for the system it finds in /etc/os-release,
# as root (or a user with sudo):
#
#   scripts/install-deps.sh [--dry-run]
#
#   Debian 12     Debian's packages, plus bookworm-backports for lavapipe 25.x
#                 and Catch2 3 (writes that one apt source if it is missing).
#   Debian 13     Debian's own packages only: trixie has lavapipe 25.x and
#                 Catch2 3 itself, so no apt source is written.
#   Ubuntu 24.04  Ubuntu's own packages only: no apt source is written and no
#                 Debian archive is ever used (mixing archives can break a
#                 desktop). Says which chapters and tests Ubuntu's versions touch.
#   anything else changes nothing, prints what to install (Debian, Ubuntu,
#                 Fedora and Arch names) and exits with status 3.
#
# --dry-run          print what would be done; run nothing, write nothing.
# VKT_OS_RELEASE     read this file instead of /etc/os-release (--dry-run only:
#                    tests/install_deps_detection.sh pretends to be other systems).
# VKT_APT_SOURCES_DIR  where Debian 12's backports source goes
#                    (default /etc/apt/sources.list.d).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

# --- What each system needs, by its own package names -----------------------
# The same names on Debian 12 and 13 and Ubuntu 24.04. The last two lines are for
# other tools of the project (charts, diagrams, linting and formatting, the
# fuzzers' nlohmann/json.hpp, gdb for a stuck window test's threads).
apt_common=(
  build-essential cmake ninja-build pkg-config
  libvulkan-dev vulkan-validationlayers glslang-tools vulkan-tools
  libglfw3-dev libglm-dev libtinygltf-dev libpng-dev libjpeg-dev libstb-dev libx11-dev
  libimgui-dev
  xvfb xauth xdotool openbox wmctrl stress-ng
  python3 python3-markdown python3-pygments libjs-katex
  python3-matplotlib python3-pil fonts-dejavu-core graphviz shellcheck clang clang-tidy
  clang-format nlohmann-json3-dev gdb
)
# Debian 12: clang is clang 14, too old for the fuzzers and clang-tidy (it
# cannot parse GCC 12's <source_location>), so the fuzz preset names clang++-16;
# each clang's runtime (libFuzzer, LeakSanitizer) is its own package. lavapipe
# 25.x and Catch2 3 come from bookworm-backports (Debian 12's own are Mesa 22.3
# and Catch2 2.x).
debian12_main=(chromium libclang-rt-14-dev clang-16 libclang-rt-16-dev clang-tidy-16)
debian12_backports=(mesa-vulkan-drivers catch2)
# Debian 13: everything from its own archive. Its clang is 19, new enough for
# the fuzzers as it is (the fuzz-clang preset uses the system's clang++; the
# fuzz preset names clang++-16, which trixie does not have).
debian13_extra=(chromium libclang-rt-19-dev mesa-vulkan-drivers catch2)
# Ubuntu 24.04: clang, clang-tidy and clang-format are 18, new enough as they
# are (the fuzz-clang preset uses that clang++). Its chromium deb only
# installs the snap, so it is left out (see ubuntu_notes).
ubuntu2404_extra=(libclang-rt-18-dev mesa-vulkan-drivers catch2)
# Printed only: names as we believe them, not tried here.
fedora_packages=(
  gcc-c++ cmake ninja-build pkgconf-pkg-config
  vulkan-loader-devel vulkan-headers vulkan-validation-layers glslang vulkan-tools
  mesa-vulkan-drivers glfw-devel glm-devel tinygltf-devel libpng-devel libjpeg-turbo-devel
  stb-devel catch-devel libX11-devel imgui-devel
  xorg-x11-server-Xvfb xorg-x11-xauth xdotool openbox wmctrl stress-ng
  python3 python3-markdown python3-pygments python3-matplotlib graphviz chromium js-katex
  ShellCheck clang clang-tools-extra compiler-rt json-devel gdb
)
arch_packages=(
  base-devel cmake ninja pkgconf
  vulkan-icd-loader vulkan-headers vulkan-validation-layers glslang vulkan-tools
  vulkan-swrast glfw glm tinygltf libpng libjpeg-turbo stb catch2 libx11 imgui
  xorg-server-xvfb xorg-xauth xdotool openbox wmctrl stress-ng
  python python-markdown python-pygments python-matplotlib graphviz chromium katex
  shellcheck clang compiler-rt nlohmann-json gdb
)

say() { printf 'install-deps: %s\n' "$*"; }
die() {
  say "$2" >&2
  exit "$1"
}

dry_run=false
for arg in "$@"; do
  case $arg in
    --dry-run) dry_run=true ;;
    -h | --help)
      sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *) die 2 "unknown argument '$arg' (usage: scripts/install-deps.sh [--dry-run])" ;;
  esac
done

os_release=${VKT_OS_RELEASE:-/etc/os-release}
if [ -n "${VKT_OS_RELEASE:-}" ] && ! $dry_run; then
  # A fake os-release must never steer a real install on the real machine.
  die 2 "VKT_OS_RELEASE describes a pretend system: use it with --dry-run only"
fi
sources_dir=${VKT_APT_SOURCES_DIR:-/etc/apt/sources.list.d}

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

# run CMD...: the one way this script changes the machine (besides write_file).
run() {
  if $dry_run; then
    say "would run: $*"
  else
    say "running: $*"
    as_root "$@"
  fi
}

# write_file PATH DESCRIPTION < CONTENT: writes PATH unless it exists.
write_file() {
  if [ -e "$1" ]; then
    say "already there: $1 ($2)"
    cat >/dev/null
  elif $dry_run; then
    say "would write: $1 ($2)"
    cat >/dev/null
  else
    say "writing: $1 ($2)"
    as_root tee "$1" >/dev/null
  fi
}

# --- Which system is this? ---------------------------------------------------
# os-release is shell-like KEY=value lines; read it as data, never source it.
os_id='' os_version_id='' os_id_like='' os_pretty='' os_ubuntu_codename=''
[ -r "$os_release" ] || die 3 "cannot read $os_release: cannot tell which system this is; changed nothing"
while IFS='=' read -r key value || [ -n "$key" ]; do
  value=${value%\"} value=${value#\"} value=${value%\'} value=${value#\'}
  case $key in
    ID) os_id=$value ;;
    VERSION_ID) os_version_id=$value ;;
    ID_LIKE) os_id_like=$value ;;
    PRETTY_NAME) os_pretty=$value ;;
    UBUNTU_CODENAME) os_ubuntu_codename=$value ;;
  esac
done <"$os_release"

case "$os_id:$os_version_id" in
  debian:12) plan=debian-12 ;;
  debian:13) plan=debian-13 ;;
  ubuntu:24.04) plan=ubuntu-24.04 ;;
  *) plan=unsupported ;;
esac
# The line names the system as this script recognised it, then what
# os-release said, so a misreading shows at once.
case $plan in
  debian-12) recognised='Debian 12 (bookworm)' ;;
  debian-13) recognised='Debian 13 (trixie)' ;;
  ubuntu-24.04) recognised='Ubuntu 24.04 (noble)' ;;
  *) recognised='not one this script installs on' ;;
esac
say "system: $recognised (os-release: ID=${os_id:-none}, VERSION_ID=${os_version_id:-none}, PRETTY_NAME=\"${os_pretty:-none}\"; from $os_release)"
say "plan: $plan$($dry_run && echo ' (dry run: nothing is run or written)')"

# --- Debian 12: as it always was ----------------------------------------------
install_debian12() {
  write_file "$sources_dir/bookworm-backports.sources" "bookworm-backports, main" <<'SRC'
Types: deb
URIs: http://deb.debian.org/debian
Suites: bookworm-backports
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  run apt-get update -q
  run apt-get install -y -q --no-install-recommends "${apt_common[@]}" "${debian12_main[@]}"
  run apt-get install -y -q --no-install-recommends -t bookworm-backports "${debian12_backports[@]}"
}

# --- Debian 13: its own archive only --------------------------------------------
install_debian13() {
  say "Debian 13's own archive only (main); no apt source is written"
  run apt-get update -q
  run apt-get install -y -q --no-install-recommends "${apt_common[@]}" "${debian13_extra[@]}"
  say "note: the fuzz preset names clang++-16, which Debian 13 lacks: use" \
    "'cmake --workflow --preset fuzz-clang' (clang 19). clang-format 19 may lay out a" \
    "line differently from CI's 14 (Debian 12), so scripts/static-checks.sh can disagree."
}

# --- Ubuntu 24.04: Ubuntu's archive only ------------------------------------
# What Ubuntu 24.04 has that differs from Debian 12 + backports, chapter by
# chapter. Reasoned from what each chapter asks of the device, not run here.
ubuntu_notes() {
  cat <<'NOTES'
install-deps: notes for Ubuntu 24.04 (reasoned, not tested on Ubuntu here):
  - chromium: skipped: Ubuntu 24.04 ships it only as a snap (the chromium-browser
    deb installs the snap), and this script installs debs only. The book's
    browser test is skipped without it (CTest lists it as not run); to run it,
    `snap install chromium` and configure again (it finds /snap/bin/chromium).
  - lavapipe is Mesa 24.0 (noble) or 24.2 (noble-updates), not 25.0 as on Debian
    12: Vulkan 1.3, not 1.4. Every chapter asks for 1.3 only: dynamicRendering and
    synchronization2 (02-20), separateDepthStencilLayouts (08, 10-12, 14-17),
    maintenance4 (13, 17, 20), descriptor indexing, buffer device address and
    multi-draw indirect (15), shaderClipDistance (19). As far as we know
    lavapipe has offered all of these since before Mesa 24.0, so every chapter
    should run; a chapter that finds one missing names it and exits 1.
  - VK_EXT_headless_surface (--headless, chapters 03-20): not sure every Mesa
    24.x lavapipe offers it; the check below says. Without it --headless renders
    offscreen (the same picture), and three tests that demand the headless
    surface fail: chapter.04_triangle.no_display, .bad_display, .benchmark.
  - The reference pictures (tests/golden) come from Mesa 25.0.7 with LLVM 15.
    Another llvmpipe may round differently; the tolerance should absorb that,
    but it is not verified. A failing picture test leaves its picture and a
    difference image in build/release/tests/output/.
  - Validation layers 1.3.275 (Debian 12: 1.3.239); a newer layer may report
    something the older did not, and the tests count any report as a failure.
  - Catch2 3.4 (Debian 12 gets 3.7): SKIP() and catch_discover_tests'
    DISCOVERY_MODE, the newest features the tests use, came in 3.3.
  - glslang 14, CMake 3.28, GLFW 3.3.10, GCC 13: newer than Debian 12's.
  - clang, clang-tidy and clang-format are 18 (Debian 12: 14, and 16 for the
    fuzzers and clang-tidy). The fuzz preset names clang++-16, which this script
    does not install here: use `cmake --workflow --preset fuzz-clang` (the
    system's clang++). clang-format 18 may lay out a line differently from
    CI's 14: scripts/static-checks.sh can then disagree with CI.
NOTES
}

# After installing: what this machine's lavapipe actually offers.
ubuntu_check_lavapipe() {
  local icds=(/usr/share/vulkan/icd.d/lvp_icd*.json) summary
  say "lavapipe: mesa-vulkan-drivers $(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || echo '(not found)')"
  if [ ! -e "${icds[0]}" ] || ! summary=$(VK_DRIVER_FILES=${icds[0]} vulkaninfo --summary 2>/dev/null); then
    say "could not run vulkaninfo on lavapipe: its Vulkan version and headless surface are unchecked"
    return
  fi
  say "lavapipe: $(grep -m 1 -o 'apiVersion *= *[0-9.]*' <<<"$summary" || echo 'apiVersion unknown')"
  if grep -q VK_EXT_headless_surface <<<"$summary"; then
    say "VK_EXT_headless_surface: present: --headless presents to a swapchain, as on Debian 12"
  else
    say "VK_EXT_headless_surface: absent: --headless renders offscreen; the tests" \
      "chapter.04_triangle.no_display, .bad_display and .benchmark will fail"
  fi
}

install_ubuntu2404() {
  say "Ubuntu's own archive only (main and universe); no apt source is written"
  run apt-get update -q
  # openbox, xdotool, wmctrl, glslang-tools, catch2... live in universe.
  if $dry_run; then
    say "would check: universe is enabled (apt-cache policy openbox)"
  elif ! apt-cache policy openbox 2>/dev/null | grep -q 'Candidate: [0-9]'; then
    die 3 "Ubuntu's universe component is not enabled (openbox has no candidate): sudo add-apt-repository universe, then run this again; installed nothing"
  fi
  run apt-get install -y -q --no-install-recommends "${apt_common[@]}" "${ubuntu2404_extra[@]}"
  ubuntu_notes
  if $dry_run; then
    say "would check: lavapipe's Mesa version and VK_EXT_headless_surface (vulkaninfo)"
  else
    ubuntu_check_lavapipe
  fi
}

# --- Anything else: change nothing, say what to install ----------------------
print_lists() {
  local family=$1
  if [ "$family" = fedora ] || [ "$family" = all ]; then
    say "  Fedora:  sudo dnf install ${fedora_packages[*]}"
  fi
  if [ "$family" = arch ] || [ "$family" = all ]; then
    say "  Arch:    sudo pacman -S --needed ${arch_packages[*]}"
  fi
  if [ "$family" = apt ] || [ "$family" = all ]; then
    say "  Debian 12 and 13 / Ubuntu 24.04 (this script installs these there): sudo apt-get install ${apt_common[*]}"
    say "    plus on Debian 12: ${debian12_main[*]}, and from bookworm-backports: ${debian12_backports[*]}"
    say "    plus on Debian 13: ${debian13_extra[*]}"
    say "    plus on Ubuntu 24.04: ${ubuntu2404_extra[*]}"
  fi
}

unsupported() {
  local family=all like=" $os_id $os_id_like "
  case $like in
    *" fedora "* | *" rhel "*) family=fedora ;;
    *" arch "*) family=arch ;;
    *" debian "* | *" ubuntu "*) family=apt ;;
  esac
  say "this script installs only on Debian 12 and 13 and Ubuntu 24.04; this is ${os_pretty:-an unknown system}. Changed nothing."
  say "install these with your package manager (names as we believe them; not tested here):"
  print_lists "$family"
  if [ "$family" = apt ] && [ "$os_ubuntu_codename" = noble ]; then
    say "  this system says it is built on Ubuntu 24.04 (noble): the Ubuntu 24.04 names are the ones to try"
  fi
  [ "$family" = all ] || say "  (other systems' names: run with VKT_OS_RELEASE=/dev/null --dry-run)"
  say "  Windows and macOS: see README.md, 'Other systems' (LunarG Vulkan SDK, vcpkg or Homebrew)."
  exit 3
}

case $plan in
  debian-12) install_debian12 ;;
  debian-13) install_debian13 ;;
  ubuntu-24.04) install_ubuntu2404 ;;
  *) unsupported ;;
esac
say "done ($plan)"
