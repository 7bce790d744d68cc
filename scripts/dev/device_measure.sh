#!/usr/bin/env bash
# The measurements of a lent GPU machine (no network there), as recorded in the README's
# "Measured on a GPU": the kernel benchmarks, the GPU test files, the sd iteration split with the
# WebGPU provider on the full-size SD 2.1-shaped export, the UNet latencies and one `sd` scene.
#
# Prepared here, carried in the repository's ignored .dev/ and .gl/ folders:
#   .gl/*.deb        the Vulkan loader and validation layer (apt-get download libvulkan1
#                    vulkan-validationlayers libegl1 ...; unpacked with dpkg -x there)
#   .dev/ort.tar.xz  libonnxruntime.so.1.31.1, libonnxruntime_providers_shared.so and
#                    libonnxruntime_providers_webgpu.so (what scripts/setup.sh installs)
#   .dev/bin.tar.xz  target/release/dreamscene and release test binaries named t_NN_<file>
#                    (cargo test --release --no-run; built in /work/main, so that path is linked)
#   .dev/carry/      scripts/dev/make_full_export.sh's carry (graphs + weights.json);
#                    CARRY=.dev/carry16 for the fp16 one (make_full_export.sh DIR fp16)
#   .dev/taesd/      TAESD=.dev/taesd: scripts/dev/make_taesd_shaped.py's pair, added to the models
#   .dev/ortgpu.xz   the `onnxruntime-gpu` wheel's libonnxruntime.so.1.31.1 (xz), and in
#   $CUDA_STASH      its libonnxruntime_providers_cuda.so, carried by an earlier call (over 64 MiB
#                    with the rest: scripts/dev/fatbin_keep.py keeps only the device's machine
#                    code). The CUDA, cuBLAS and cuDNN libraries come from the machine's own
#                    Python (its nvidia-* wheels), as `scripts/setup.sh --cuda` takes them from PyPI.
# PROVIDER (default webgpu) is the provider of sd, unet, variants and scene.
# Usage there: bash scripts/dev/device_measure.sh [setup,doctor,bench,benchgen,sd,sd2,unet,variants,tests,scene]
# (the steps run in the order given)
# `variants` times the UNet under each of $VARIANTS (';'-separated DREAMSCENE_WEBGPU_OPTIONS).
# A step that would start after $BUDGET_S seconds (default 540) is skipped.
set -u
STEPS=${1:-setup,doctor,bench,sd,unet,tests,scene}
R=$(pwd); O=${OUT:-/tmp/out}; mkdir -p $O
log() { echo "== $(date -u +%T) $*"; }
T0=$(date +%s)
has() { [[ ",$STEPS," == *",$1,"* ]] || return 1
  if [ $(( $(date +%s) - T0 )) -gt ${BUDGET_S:-540} ]; then log "$1: not run (time)"; return 1; fi; }
export HOME=/tmp/dshome; mkdir -p $HOME/.local/share/dreamscene/onnxruntime
export NVICD=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
log setup
for f in .gl/*.deb; do dpkg -x $f / 2>/dev/null; done; ldconfig
tar -xJf .dev/ort.tar.xz -C $HOME/.local/share/dreamscene/onnxruntime
mkdir -p target/release && tar -xJf .dev/bin.tar.xz -C target/release
# the test binaries were built in /work/main: give them that path
mkdir -p /work && [ -e /work/main ] || ln -s "$R" /work/main
ls $NVICD 2>/dev/null && export VK_DRIVER_FILES=$NVICD VK_ICD_FILENAMES=$NVICD
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
export VK_LAYER_PATH=/usr/share/vulkan/explicit_layer.d
# the webgpu test's "Mesa 25" environment is the real GPU here
mkdir -p $HOME/.local/share/dreamscene/mesa25 && echo "export VK_DRIVER_FILES=${VK_DRIVER_FILES:-}" > $HOME/.local/share/dreamscene/mesa25/env.sh
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader
P=${PROVIDER:-webgpu}; CUDA_STASH=${CUDA_STASH:-/tmp/stash}
if [ -f $CUDA_STASH/libonnxruntime_providers_cuda.so ] && [ -f .dev/ortgpu.xz ]; then
  ORTD=$HOME/.local/share/dreamscene/onnxruntime
  xz -dc .dev/ortgpu.xz > $ORTD/libonnxruntime.so.1.31.1
  cp $CUDA_STASH/libonnxruntime_providers_cuda.so $ORTD/
  LIBS=$(python3 -c 'import nvidia; print(" ".join(nvidia.__path__))' 2>/dev/null)
  export LD_LIBRARY_PATH=$(find $LIBS -name 'lib*.so*' -printf '%h\n' | sort -u | tr '\n' ':')${LD_LIBRARY_PATH:-}
  log "cuda provider installed; CUDA libraries from $LIBS"
fi
M=/tmp/full
if [[ ",$STEPS," =~ ,(sd|sd2|unet|variants|scene), ]]; then
  # the weights are written while the first steps run
  rm -rf $M; cp -r ${CARRY:-.dev/carry} $M
  ( timeout 300 python3 scripts/dev/weightless.py fill $M > $O/fill.log 2>&1; echo "fill rc=$?" >> $O/fill.log ) &
  FILL=$!
fi
D=target/release/dreamscene
( nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits -lms 250 > $O/gpumem.txt 2>&1 & )
peak() { # peak() LABEL CMD... : runs CMD, samples its host RSS, prints peak host and device memory
  local label=$1; shift; local s0; s0=$(wc -l < $O/gpumem.txt)
  "$@" & local pid=$! hw=0
  while kill -0 $pid 2>/dev/null; do
    # the dreamscene process itself (CMD may be a wrapper such as timeout)
    h=$(ps -C dreamscene -o rss= 2>/dev/null | sort -n | tail -1); [ -n "$h" ] && [ "$h" -gt "$hw" ] && hw=$h; sleep 0.5; done
  wait $pid; local rc=$?
  local g; g=$(tail -n +$((s0+1)) $O/gpumem.txt | sort -n | tail -1)
  log "$label rc=$rc peak host ${hw} KiB, peak device ${g} MiB (whole GPU)"
}
weights() { [ -n "${FILL:-}" ] || return 0; log "waiting for the weights"; wait $FILL; FILL=; cat $O/fill.log; du -sh $M; }
step_doctor() { timeout 60 $D doctor --provider $P 2>&1 | tail -30; }
step_bench() { timeout ${BENCH_S:-60} $D bench --runs 3 2>&1 | tail -30; }
step_benchgen() { timeout 70 $D bench --generate --runs 2 2>&1 | tail -20; }
# TAESD=DIR: a tiny autoencoder pair (scripts/dev/make_taesd_shaped.py) for the per-iteration codec
taesd() { M2=/tmp/full_taesd; [ -d $M2 ] && return 0; mkdir -p $M2; for f in $M/*; do ln -sfn $f $M2/; done
  cp -r $TAESD/taesd_encoder $TAESD/taesd_decoder $M2/; }
step_sd() { weights
  peak sdgen timeout ${SD_S:-240} $D bench --generate --prior sd --models $M --provider $P --runs 1 --modes ${SD_MODES:-both} 2>&1 | tail -20
  if [ -n "${TAESD:-}" ] && has sd; then taesd; log "sd ($P, TAESD)"
    peak sdtaesd timeout ${SD_S:-240} $D bench --generate --prior sd --models $M2 --provider $P --runs 1 --modes batched 2>&1 | tail -20; fi; }
# the same iteration on a second provider (PROVIDER2, default webgpu), batched, for comparison
step_sd2() { weights; local m=$M; [ -n "${TAESD:-}" ] && { taesd; m=$M2; }
  peak sd2 timeout ${SD_S:-240} $D bench --generate --prior sd --models $m --provider ${PROVIDER2:-webgpu} --runs 1 --modes batched 2>&1 | tail -20; }
step_unet() { weights; peak unet timeout 100 $D bench --unet --models $M --provider $P --runs 2 2>&1 | tail -20; }
step_variants() { weights
  IFS=';' read -ra VS <<< "${VARIANTS:-;validationMode=disabled;preferredLayout=NCHW}"
  for v in "${VS[@]}"; do log "unet variant '$v'"
    [ $(( $(date +%s) - T0 )) -gt ${BUDGET_S:-540} ] && { log "variant '$v': not run (time)"; continue; }
    DREAMSCENE_WEBGPU_OPTIONS="$v" timeout 90 $D bench --unet --models $M --provider webgpu --runs 2 2>&1 | tail -9
  done; }
step_tests() { ( export DREAMSCENE_VALIDATION=1 DREAMSCENE_REQUIRE_VALIDATION=1
  t0=$(date +%s); for t in target/release/t_*; do n=${t##*/t_}; s=$(date +%s)
    [ "${n%%_*}" -lt "${TESTS_FROM:-0}" ] && continue
    [ $((s-t0)) -gt ${TESTS_S:-170} ] && { echo "$n: not run (time)"; continue; }
    r=$(timeout 60 $t --test-threads 4 2>&1 | grep -E "^test result|panicked|FAILED|failed" | head -5)
    echo "$n ($(( $(date +%s)-s )) s): $r"; done ); }
step_scene() { weights; echo '{"id":"bath","prompt":"a small bathroom","seed":0}' > /tmp/m.jsonl
  peak scene timeout ${SCENE_S:-200} $D batch /tmp/m.jsonl --out /tmp/b --prior sd --models $M --provider $P --object-iterations 3 --iterations 3 --recon-passes 1 --object-recon-passes 1 --resolution 256 --renders 2 2>&1 | tail -15
  $D batch --status /tmp/b 2>&1 | tail -5; cp /tmp/b/index.json $O/ 2>/dev/null; python3 -c "import json;print(json.dumps(json.load(open('/tmp/b/index.json')),indent=1)[:3000])"; }
# the steps run in the order given
for st in ${STEPS//,/ }; do [ "$st" = setup ] && continue
  if has $st; then log "$st ($P)"; step_$st; fi; done
log done
