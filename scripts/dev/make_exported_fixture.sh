#!/usr/bin/env bash
# Makes tests/data/exported-sd/: a tiny random-weight pipeline of Stable Diffusion's block types
# (CLIP text encoder; UNet with CrossAttnDownBlock2D / DownBlock2D / UNetMidBlock2DCrossAttn /
# UpBlock2D / CrossAttnUpBlock2D and linear attention projections as in SD 2.x; a 4-level
# AutoencoderKL, factor 8), exported by the real exporter, `optimum-cli export onnx --task
# text-to-image`, in fp32 (fp32/) and fp16 (fp16/), with golden.json: PyTorch's outputs for fixed
# inputs, so tests/exported_sd.rs holds the loader to what the exporter writes.
#
# Run once by hand; it needs network for pip (torch is large) and leaves nothing behind but the
# fixture (the venv in /tmp is removed unless KEEP_VENV=1). CI does not run it: the output is
# committed.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
venv=${VENV:-/tmp/dreamscene-export-venv}
work=$(mktemp -d /tmp/dreamscene-export.XXXXXX)
trap 'rm -rf "$work"' EXIT
if [ ! -x "$venv/bin/optimum-cli" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install -q -U pip
    "$venv/bin/pip" install -q torch diffusers "transformers<4.58" optimum-onnx onnx onnxruntime
fi
"$venv/bin/python" - "$root" "$work" <<'PYEOF'
import json, os, shutil, sys

import torch
from diffusers import AutoencoderKL, DDIMScheduler, StableDiffusionPipeline, UNet2DConditionModel
from transformers import CLIPTextConfig, CLIPTextModel, CLIPTokenizer

root, work = sys.argv[1], sys.argv[2]
# The tokenizer: the real CLIP vocabulary subset of tests/data/clip, renumbered 0..n-1 so the
# text encoder's embedding table stays small.
vocab = json.load(open(f"{root}/tests/data/clip/vocab.json"))
small = {t: i for i, t in enumerate(sorted(vocab, key=vocab.get))}
os.makedirs(f"{work}/tok")
json.dump(small, open(f"{work}/tok/vocab.json", "w"))
shutil.copy(f"{root}/tests/data/clip/merges.txt", f"{work}/tok/merges.txt")
tok = CLIPTokenizer(f"{work}/tok/vocab.json", f"{work}/tok/merges.txt", pad_token="!",
                    model_max_length=77)

torch.manual_seed(20261122)
hidden = 16
te = CLIPTextModel(CLIPTextConfig(
    vocab_size=len(small), hidden_size=hidden, intermediate_size=32, num_hidden_layers=2,
    num_attention_heads=2, max_position_embeddings=77, projection_dim=hidden, hidden_act="gelu",
    bos_token_id=small["<|startoftext|>"], eos_token_id=small["<|endoftext|>"], pad_token_id=0))
unet = UNet2DConditionModel(
    sample_size=8, in_channels=4, out_channels=4, layers_per_block=1, block_out_channels=(8, 16),
    down_block_types=("CrossAttnDownBlock2D", "DownBlock2D"),
    up_block_types=("UpBlock2D", "CrossAttnUpBlock2D"), cross_attention_dim=hidden,
    attention_head_dim=(2, 4), use_linear_projection=True, norm_num_groups=4)
vae = AutoencoderKL(
    in_channels=3, out_channels=3, down_block_types=("DownEncoderBlock2D",) * 4,
    up_block_types=("UpDecoderBlock2D",) * 4, block_out_channels=(4, 4, 8, 8), layers_per_block=1,
    latent_channels=4, norm_num_groups=4, sample_size=32)
# Random weights everywhere (some layers start at zero, which would hide wiring mistakes).
with torch.no_grad():
    for m in (te, unet, vae):
        for p in m.parameters():
            p.add_(0.1 * torch.randn_like(p))
sched = DDIMScheduler(beta_start=0.00085, beta_end=0.012, beta_schedule="scaled_linear",
                      clip_sample=False, set_alpha_to_one=False, steps_offset=1,
                      prediction_type="epsilon")
pipe = StableDiffusionPipeline(vae=vae, text_encoder=te, tokenizer=tok, unet=unet,
                               scheduler=sched, safety_checker=None, feature_extractor=None,
                               requires_safety_checker=False)
pipe.save_pretrained(f"{work}/pipe")

prompt = "A DSLR photo of a wooden chair"
ids = tok(prompt, padding="max_length", max_length=77, return_tensors="pt").input_ids
g = torch.Generator().manual_seed(1)
s = vae.config.scaling_factor
with torch.no_grad():
    emb = te(ids).last_hidden_state
    x = torch.randn(1, 4, 8, 8, generator=g)
    t = 500
    eps = unet(x, torch.tensor(t), encoder_hidden_states=emb).sample
    z = torch.randn(1, 4, 4, 4, generator=g)
    decoded = vae.decode(z / s).sample
    image = torch.rand(1, 3, 32, 32, generator=g) * 2 - 1
    mean = vae.encode(image).latent_dist.mean * s
flat = lambda a: [round(v, 7) for v in a.flatten().tolist()]
json.dump({
    "prompt": prompt, "input_ids": ids[0].tolist(), "last_hidden_state": flat(emb),
    "sample": flat(x), "timestep": t, "out_sample": flat(eps),
    "latent": flat(z), "decoded": flat(decoded),
    "image": flat(image), "latent_mean": flat(mean),
}, open(f"{work}/golden.json", "w"))
PYEOF
cli="$venv/bin/optimum-cli"
"$cli" export onnx --model "$work/pipe" --task text-to-image "$work/fp32"
"$cli" export onnx --model "$work/pipe" --task text-to-image --dtype fp16 --atol 0.05 "$work/fp16"
out=$root/tests/data/exported-sd
rm -rf "$out"
mkdir -p "$out"
cp -r "$work/fp32" "$work/fp16" "$work/golden.json" "$out/"
"$venv/bin/pip" freeze | grep -iE '^(torch|diffusers|transformers|optimum|optimum-onnx|onnx|onnxruntime)==' \
    >"$out/versions.txt"
[ -n "${KEEP_VENV:-}" ] || rm -rf "$venv"
du -sh "$out"
