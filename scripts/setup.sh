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

# ONNX Runtime (the diffusion models): the library from the PyPI wheel, loaded by full path.
ORT_VERSION=1.31.1
ORT_DIR="${XDG_DATA_HOME:-$HOME/.local/share}/dreamscene/onnxruntime"
if [ ! -f "$ORT_DIR/libonnxruntime.so.$ORT_VERSION" ]; then
  echo "installing ONNX Runtime $ORT_VERSION into $ORT_DIR"
  command -v python3 >/dev/null || { echo "python3 (with pip) is needed to fetch the onnxruntime wheel" >&2; exit 1; }
  tmp="$(mktemp -d)"
  python3 -m pip download --quiet --no-deps --only-binary=:all: "onnxruntime==$ORT_VERSION" -d "$tmp"
  mkdir -p "$ORT_DIR"
  python3 - "$tmp" "$ORT_DIR" "$ORT_VERSION" <<'PY'
import glob, os, sys, zipfile
tmp, out, ver = sys.argv[1:]
wheel = glob.glob(os.path.join(tmp, "onnxruntime-*.whl"))[0]
with zipfile.ZipFile(wheel) as z:
    for name in z.namelist():
        base = os.path.basename(name)
        if name.startswith("onnxruntime/capi/") and base.startswith("libonnxruntime"):
            with open(os.path.join(out, base), "wb") as f:
                f.write(z.read(name))
PY
  rm -rf "$tmp"
fi
test -f "$ORT_DIR/libonnxruntime.so.$ORT_VERSION" || { echo "ONNX Runtime library missing in $ORT_DIR" >&2; exit 1; }
