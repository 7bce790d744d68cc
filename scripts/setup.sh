#!/usr/bin/env bash
# Installs what dreamscene needs on Debian/Ubuntu: the Vulkan loader, Mesa's lavapipe CPU device,
# the Khronos validation layer (used by the tests), glslang (compiles the kernels at build time)
# and the ONNX Runtime library (runs the diffusion models; taken from the PyPI wheel).
#
# `bash scripts/setup.sh --cuda` (NVIDIA users): ONNX Runtime's CUDA build instead of the CPU one,
# with the CUDA and cuDNN runtime libraries it needs, all from PyPI wheels (see below).
set -euo pipefail
CUDA=0
for arg in "$@"; do
  case "$arg" in
    --cuda) CUDA=1 ;;
    *) echo "setup.sh: unknown option $arg (expected --cuda)" >&2; exit 2 ;;
  esac
done
apt_install() {
  local SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "$@"
}
# chromium and ffmpeg (ffprobe) are the outside clients of the viewer and video tests; g++ builds
# the bundled OpenH264 encoder (the openh264 crate); node and
# npm install the viewer's packages and the export tests' readers.
pkgs=(libvulkan1 mesa-vulkan-drivers vulkan-validationlayers glslang-tools chromium ffmpeg g++)
command -v npm >/dev/null || pkgs+=(nodejs npm)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  apt_install "${missing[@]}"
fi
command -v glslangValidator >/dev/null || { echo "glslangValidator still missing" >&2; exit 1; }

# ONNX Runtime (the diffusion models): the library from the PyPI wheel, loaded by full path.
ORT_VERSION=1.31.1
ORT_DIR="${XDG_DATA_HOME:-$HOME/.local/share}/dreamscene/onnxruntime"
if [ ! -f "$ORT_DIR/libonnxruntime.so.$ORT_VERSION" ]; then
  echo "installing ONNX Runtime $ORT_VERSION into $ORT_DIR"
  if ! python3 -m pip --version >/dev/null 2>&1; then
    echo "installing python3-pip (to fetch the onnxruntime wheel)"
    apt_install python3-pip
  fi
  tmp="$(mktemp -d)"
  python3 -m pip download --quiet --no-deps --only-binary=:all: "onnxruntime==$ORT_VERSION" -d "$tmp"
  mkdir -p "$ORT_DIR"
  python3 - "$tmp" "$ORT_DIR" <<'PY'
import glob, os, sys, zipfile
tmp, out = sys.argv[1:]
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

# --cuda: the CUDA build of the same ONNX Runtime (PyPI `onnxruntime-gpu`) replaces the CPU library
# (it runs the CPU provider too; its CUDA provider is a separate library loaded on demand), with
# the CUDA runtime, cuBLAS, cuFFT, cuRAND and cuDNN libraries of the `nvidia-*` wheels pip resolves
# for it (the `cuda` and `cudnn` extras; cuDNN is also a plain dependency). Everything lands flat
# in $ORT_DIR, and every library gets the run path $ORIGIN (patchelf), so the CUDA provider and
# cuDNN's own sub-libraries are found there without LD_LIBRARY_PATH. The NVIDIA driver
# (libcuda.so.1) comes from the system. Nothing here can be checked without an NVIDIA GPU:
# `dreamscene doctor --provider cuda` says whether the provider loads.
if [ "$CUDA" = 1 ] && [ ! -f "$ORT_DIR/libonnxruntime_providers_cuda.so" ]; then
  echo "installing ONNX Runtime $ORT_VERSION with CUDA (onnxruntime-gpu) into $ORT_DIR"
  command -v patchelf >/dev/null || apt_install patchelf
  command -v objdump >/dev/null || apt_install binutils
  tmp="$(mktemp -d)"
  python3 -m pip download --quiet --only-binary=:all: \
    "onnxruntime-gpu[cuda,cudnn]==$ORT_VERSION" -d "$tmp"
  python3 - "$tmp" "$ORT_DIR" <<'PY'
import glob, os, re, sys, zipfile
tmp, out = sys.argv[1:]
lib = re.compile(r"\.so(\.\d+)*$")
for wheel in glob.glob(os.path.join(tmp, "*.whl")):
    base = os.path.basename(wheel)
    with zipfile.ZipFile(wheel) as z:
        for name in z.namelist():
            f = os.path.basename(name)
            ours = base.startswith("onnxruntime_gpu-") and name.startswith("onnxruntime/capi/") \
                and f.startswith("libonnxruntime")
            # nvidia-* wheels keep their libraries in nvidia/<component>/lib/
            theirs = base.startswith("nvidia_") and "/lib/" in name and lib.search(f)
            if ours or theirs:
                with open(os.path.join(out, f), "wb") as o:
                    o.write(z.read(name))
PY
  rm -rf "$tmp"
  for f in "$ORT_DIR"/*.so*; do
    [ -L "$f" ] || patchelf --set-rpath '$ORIGIN' "$f"
  done
  # Every CUDA library the provider links against must now be here (libcuda is the driver's).
  missing_cuda=()
  for need in $(objdump -p "$ORT_DIR/libonnxruntime_providers_cuda.so" | awk '/NEEDED/{print $2}'); do
    case "$need" in
      libcuda.so*|libc.so*|libm.so*|libdl.so*|librt.so*|libpthread.so*|libstdc++.so*|libgcc_s.so*|ld-linux*) ;;
      *) [ -e "$ORT_DIR/$need" ] || missing_cuda+=("$need") ;;
    esac
  done
  if ((${#missing_cuda[@]})); then
    echo "the CUDA provider needs ${missing_cuda[*]}, which no wheel pip resolved provided; install" \
      "them (CUDA toolkit / cuDNN) and put them in $ORT_DIR" >&2
    exit 1
  fi
fi

# ONNX Runtime's WebGPU execution provider (a plugin library on Dawn, Vulkan on Linux; `--provider
# webgpu`), from the PyPI wheel `onnxruntime-ep-webgpu`, beside libonnxruntime.
WEBGPU_EP_VERSION=0.4.0
if [ ! -f "$ORT_DIR/libonnxruntime_providers_webgpu.so" ]; then
  echo "installing the WebGPU execution provider $WEBGPU_EP_VERSION into $ORT_DIR"
  tmp="$(mktemp -d)"
  python3 -m pip download --quiet --no-deps --only-binary=:all: \
    "onnxruntime-ep-webgpu==$WEBGPU_EP_VERSION" -d "$tmp"
  python3 - "$tmp" "$ORT_DIR" <<'PY'
import glob, os, sys, zipfile
tmp, out = sys.argv[1:]
wheel = glob.glob(os.path.join(tmp, "onnxruntime_ep_webgpu-*.whl"))[0]
with zipfile.ZipFile(wheel) as z:
    for name in z.namelist():
        if os.path.basename(name) == "libonnxruntime_providers_webgpu.so":
            with open(os.path.join(out, "libonnxruntime_providers_webgpu.so"), "wb") as f:
                f.write(z.read(name))
PY
  rm -rf "$tmp"
fi

# Mesa 25's lavapipe for the WebGPU EP's tests (Dawn rejects Debian 12's Mesa 22.3 lavapipe: no
# dynamic indexing of descriptor arrays). Fetched from bookworm-backports with a private apt state
# and extracted, so the system's driver (which the kernels' tests use) and apt sources stay as
# they are; only processes that source $MESA_DIR/env.sh see it.
MESA_DIR="${XDG_DATA_HOME:-$HOME/.local/share}/dreamscene/mesa25"
if [ ! -f "$MESA_DIR/env.sh" ] && grep -qs 'VERSION_CODENAME=bookworm' /etc/os-release; then
  echo "installing Mesa 25 lavapipe (bookworm-backports) privately into $MESA_DIR"
  A="$MESA_DIR/apt"
  mkdir -p "$A/lists/partial" "$A/cache/archives/partial" "$A/etc/preferences.d" "$MESA_DIR/debs"
  MIRROR=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null)
  echo "deb ${MIRROR:-http://deb.debian.org/debian} bookworm-backports main" > "$A/etc/sources.list"
  O=(-o "Dir::Etc::SourceList=$A/etc/sources.list" -o Dir::Etc::SourceParts=/dev/null
     -o "Dir::State::Lists=$A/lists" -o "Dir::Cache=$A/cache"
     -o Dir::Etc::Preferences=/dev/null -o "Dir::Etc::PreferencesParts=$A/etc/preferences.d")
  apt-get "${O[@]}" update -qq
  (cd "$MESA_DIR/debs" && apt-get "${O[@]}" download -qq mesa-vulkan-drivers/bookworm-backports \
    libdrm2/bookworm-backports libdrm-amdgpu1/bookworm-backports)
  for f in "$MESA_DIR"/debs/*.deb; do dpkg-deb -x "$f" "$MESA_DIR/root"; done
  L="$MESA_DIR/root/usr/lib/x86_64-linux-gnu"
  sed "s#\"libvulkan_lvp.so\"#\"$L/libvulkan_lvp.so\"#" \
    "$MESA_DIR/root/usr/share/vulkan/icd.d/lvp_icd.json" > "$MESA_DIR/lvp_icd.json"
  mkdir -p "$MESA_DIR/xdg" && chmod 700 "$MESA_DIR/xdg"
  cat > "$MESA_DIR/env.sh" <<EOT
export VK_DRIVER_FILES=$MESA_DIR/lvp_icd.json
export VK_ICD_FILENAMES=$MESA_DIR/lvp_icd.json
export LD_LIBRARY_PATH=$L
export XDG_RUNTIME_DIR=$MESA_DIR/xdg
EOT
  rm -rf "$A" "$MESA_DIR/debs"
fi

# The browser viewer's npm packages (Spark and three.js; playwright-core for the browser test),
# exactly as viewer/package-lock.json names them.
VIEWER_DIR="$(cd "$(dirname "$0")/.." && pwd)/viewer"
if [ ! -f "$VIEWER_DIR/node_modules/.package-lock.json" ] ||
   [ "$VIEWER_DIR/package-lock.json" -nt "$VIEWER_DIR/node_modules/.package-lock.json" ]; then
  echo "installing the viewer's npm packages into $VIEWER_DIR/node_modules"
  (cd "$VIEWER_DIR" && npm ci --no-audit --no-fund --loglevel=error)
fi
test -f "$VIEWER_DIR/node_modules/@sparkjsdev/spark/dist/spark.module.js" || { echo "viewer packages missing in $VIEWER_DIR/node_modules" >&2; exit 1; }

# The independent readers the export tests check files with (PlayCanvas splat-transform, Niantic's
# SPZ decoder, gltf-transform, the Khronos glTF validator), exactly as tests/node/package-lock.json
# names them, so the tests themselves need no network.
READERS_DIR="$(cd "$(dirname "$0")/.." && pwd)/tests/node"
if [ ! -f "$READERS_DIR/node_modules/.package-lock.json" ] ||
   [ "$READERS_DIR/package-lock.json" -nt "$READERS_DIR/node_modules/.package-lock.json" ]; then
  echo "installing the export tests' readers into $READERS_DIR/node_modules"
  (cd "$READERS_DIR" && npm ci --no-audit --no-fund --loglevel=error)
fi
test -x "$READERS_DIR/node_modules/.bin/splat-transform" || { echo "export test readers missing in $READERS_DIR/node_modules" >&2; exit 1; }

# The batch tests: a real single-node Slurm (started inside the test) and the offline Kubernetes
# schema check. A test whose tool is missing fails saying how to install it, unless
# DREAMSCENE_SKIP_EXTERNAL names it (comma-separated: blender, slurm, kubernetes-validate; or all).
slurm_pkgs=(slurmctld slurmd slurm-client munge)
slurm_missing=()
for p in "${slurm_pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || slurm_missing+=("$p")
done
if ((${#slurm_missing[@]})); then
  echo "installing (for the batch tests): ${slurm_missing[*]}"
  apt_install "${slurm_missing[@]}" || echo "could not install ${slurm_missing[*]}; tests/batch_slurm.rs will fail (DREAMSCENE_SKIP_EXTERNAL=slurm skips it)" >&2
fi
if ! command -v kubernetes-validate >/dev/null; then
  echo "installing kubernetes-validate (for the batch tests)"
  python3 -m pip install --quiet kubernetes-validate 2>/dev/null ||
    python3 -m pip install --quiet --break-system-packages kubernetes-validate ||
    echo "could not install kubernetes-validate; the job file test will fail (DREAMSCENE_SKIP_EXTERNAL=kubernetes-validate skips it)" >&2
fi
# Blender 3.4 (Debian) reads the engine-ready glb in tests/export_engine.rs; its glTF add-on needs
# numpy. Missing, the Blender checks fail unless DREAMSCENE_SKIP_EXTERNAL names blender.
if ! command -v blender >/dev/null; then
  echo "installing blender and python3-numpy (the engine export's DCC reader)"
  apt_install blender python3-numpy || echo "blender could not be installed; the Blender checks of tests/export_engine.rs and tests/engine_splats.rs will fail (DREAMSCENE_SKIP_EXTERNAL=blender skips them)" >&2
fi
