#!/usr/bin/env bash
# Makes a full-size Stable Diffusion 2.1 base-shaped ONNX export with random weights (the real
# architecture and sizes: UNet 866 M, VAE 84 M, text encoder 340 M parameters), by the same
# exporter as scripts/dev/make_exported_fixture.sh, `optimum-cli export onnx --task
# text-to-image`, then strips it into a carry of a few MiB (scripts/dev/weightless.py) that a
# machine without network turns back into a runnable export with `weightless.py fill`.
#
#   scripts/dev/make_full_export.sh OUT_DIR [fp32|fp16]
#   -> OUT_DIR/export (about 5.2 GB fp32), OUT_DIR/carry (graphs + weights.json + tokenizer)
#
# Needs network for pip and ~12 GB of RAM (the export's peak). fp16 on a CPU-only machine takes
# about half an hour (PyTorch's fp16 convolutions on CPU are slow; see
# shared/reference/sd-export-facts.md); the VAE's dummy input is kept small for that reason.
set -euo pipefail
out=${1:?usage: make_full_export.sh OUT_DIR [fp32|fp16]}
dtype=${2:-fp32}
root=$(cd "$(dirname "$0")/../.." && pwd)
venv=${VENV:-/tmp/dreamscene-export-venv}
mkdir -p "$out"
if [ ! -x "$venv/bin/optimum-cli" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install -q -U pip
    "$venv/bin/pip" install -q torch diffusers "transformers<4.58" optimum-onnx onnx onnxruntime
fi
"$venv/bin/python" - "$root" "$out/pipeline" <<'PYEOF'
import json, sys

import torch
from diffusers import AutoencoderKL, DDIMScheduler, StableDiffusionPipeline, UNet2DConditionModel
from transformers import CLIPTextConfig, CLIPTextModel, CLIPTokenizer

root, dst = sys.argv[1], sys.argv[2]
torch.manual_seed(0)
# SD 2.1 base's configurations (Hugging Face model cards' config.json values).
te = CLIPTextModel(CLIPTextConfig(
    vocab_size=49408, hidden_size=1024, intermediate_size=4096, num_hidden_layers=23,
    num_attention_heads=16, max_position_embeddings=77, projection_dim=512, hidden_act="gelu",
    bos_token_id=0, eos_token_id=2, pad_token_id=1))
unet = UNet2DConditionModel(
    sample_size=64, in_channels=4, out_channels=4, layers_per_block=2,
    block_out_channels=(320, 640, 1280, 1280),
    down_block_types=("CrossAttnDownBlock2D",) * 3 + ("DownBlock2D",),
    up_block_types=("UpBlock2D",) + ("CrossAttnUpBlock2D",) * 3,
    cross_attention_dim=1024, attention_head_dim=(5, 10, 20, 20), use_linear_projection=True)
vae = AutoencoderKL(
    in_channels=3, out_channels=3, down_block_types=("DownEncoderBlock2D",) * 4,
    up_block_types=("UpDecoderBlock2D",) * 4, block_out_channels=(128, 256, 512, 512),
    layers_per_block=2, latent_channels=4, sample_size=64)
sched = DDIMScheduler(beta_start=0.00085, beta_end=0.012, beta_schedule="scaled_linear",
                      clip_sample=False, set_alpha_to_one=False, steps_offset=1,
                      prediction_type="epsilon")
# The real CLIP BPE files when the project has them (tests/data/clip holds a subset only).
tok = CLIPTokenizer(f"{root}/tests/data/clip/vocab.json", f"{root}/tests/data/clip/merges.txt",
                    pad_token="!", model_max_length=77)
StableDiffusionPipeline(vae=vae, text_encoder=te, tokenizer=tok, unet=unet, scheduler=sched,
                        safety_checker=None, feature_extractor=None,
                        requires_safety_checker=False).save_pretrained(dst)
PYEOF
extra=()
if [ "$dtype" = fp16 ]; then extra=(--dtype fp16 --atol 1.0 --height 8 --width 8); fi
"$venv/bin/optimum-cli" export onnx --model "$out/pipeline" --task text-to-image "${extra[@]}" \
    "$out/export"
rm -rf "$out/pipeline"
"$venv/bin/python" "$root/scripts/dev/weightless.py" strip "$out/export" "$out/carry"
du -sh "$out/export" "$out/carry"
echo "carry $out/carry to the GPU machine, then: python3 scripts/dev/weightless.py fill DIR"
