#!/usr/bin/env bash
# Installs what dreamscene needs on Debian/Ubuntu: the Vulkan loader, Mesa's lavapipe CPU device,
# the Khronos validation layer (used by the tests) and glslang (compiles the kernels at build time).
set -euo pipefail
pkgs=(libvulkan1 mesa-vulkan-drivers vulkan-validationlayers glslang-tools)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
command -v glslangValidator >/dev/null || { echo "glslangValidator still missing" >&2; exit 1; }
