#!/usr/bin/env bash
# Installs everything the tutorial needs on Debian 12 (bookworm), as root.
# Lavapipe 25.x (mesa-vulkan-drivers) and Catch2 3 come from bookworm-backports.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

sudo_if_needed() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

if [ ! -f /etc/apt/sources.list.d/bookworm-backports.sources ]; then
  sudo_if_needed tee /etc/apt/sources.list.d/bookworm-backports.sources >/dev/null <<'SRC'
Types: deb
URIs: http://deb.debian.org/debian
Suites: bookworm-backports
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
fi

sudo_if_needed apt-get update -q
sudo_if_needed apt-get install -y -q --no-install-recommends \
  build-essential cmake ninja-build pkg-config \
  libvulkan-dev vulkan-validationlayers glslang-tools vulkan-tools \
  libglfw3-dev libglm-dev libtinygltf-dev libstb-dev xvfb xauth xdotool openbox wmctrl \
  stress-ng \
  python3 python3-markdown python3-pygments
sudo_if_needed apt-get install -y -q --no-install-recommends -t bookworm-backports \
  mesa-vulkan-drivers catch2
