"""Writes the tiny Stable Diffusion model directories the tests use, in the layout of Hugging Face
Optimum's ONNX export, with deterministic weights and golden outputs:

- tests/data/tiny-sd/      a small but complete pipeline: CLIP tokenizer files (the real-id subset in
                           tests/data/clip), text encoder, UNet with its weights as external data,
                           VAE encoder/decoder, a TAESD-style autoencoder pair, scheduler config,
                           model_index.json, and golden.json (outputs computed here with numpy, and
                           checked against ONNX Runtime when it is installed).
- tests/data/analytic-sd/  the same text encoder and VAE with an "analytic prior" UNet whose noise
                           prediction is the exact one for a point target chosen by the prompt:
                           eps = g(c) (x_t - sqrt(abar_t) z*(c)) / sqrt(1 - abar_t), where g(c) = 0 for a
                           prompt with no content tokens (an uninformative prior: eps = 0), else 1.

Development-time only (the outputs are committed): python3 scripts/dev/make_tiny_sd.py
Needs `onnx` and `numpy`; `onnxruntime` (optional) cross-checks the goldens.
"""
import json
import os
import shutil

import numpy as np
import onnx
from onnx import TensorProto, helper, numpy_helper

OPSET = 17
HIDDEN = 32
SEQ = 77
LATENT_C = 4
FACTOR = 8
VAE_SCALE = 0.18215
BOS, EOS = 49406, 49407
TRAIN_T = 1000
rng = np.random.RandomState(20261122)


def f32(a):
    return np.asarray(a, dtype=np.float32)


def init(name, arr):
    return numpy_helper.from_array(np.asarray(arr), name)


def save(model_proto, path, external=False):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    onnx.checker.check_model(model_proto)
    if external:
        # onnx appends to an existing data file: start from none.
        data = os.path.join(os.path.dirname(path), "model.onnx_data")
        if os.path.exists(data):
            os.remove(data)
        onnx.save_model(model_proto, path, save_as_external_data=True, all_tensors_to_one_file=True,
                        location="model.onnx_data", size_threshold=256)
    else:
        onnx.save_model(model_proto, path)


def model(graph):
    m = helper.make_model(graph, opset_imports=[helper.make_opsetid("", OPSET)],
                          producer_name="dreamscene tiny-sd")
    m.ir_version = 8
    return m


# ---------------------------------------------------------------- text encoder
TE_A = f32(rng.uniform(0.005, 0.05, HIDDEN - 1))
TE_MOD = 997
TE_B = f32(rng.uniform(-3, 3, HIDDEN - 1))
TE_W = f32(rng.normal(0, 1.0 / np.sqrt(HIDDEN - 1), (HIDDEN - 1, HIDDEN - 1)))


def text_encoder_graph():
    n = [
        helper.make_node("Mod", ["input_ids", "mod_i"], ["ids_m"]),
        helper.make_node("Cast", ["ids_m"], ["ids_f"], to=TensorProto.FLOAT),
        helper.make_node("Unsqueeze", ["ids_f", "ax2"], ["ids_u"]),
        helper.make_node("Greater", ["input_ids", "zero_i"], ["gt0"]),
        helper.make_node("Less", ["input_ids", "bos_i"], ["ltbos"]),
        helper.make_node("And", ["gt0", "ltbos"], ["is_content"]),
        helper.make_node("Cast", ["is_content"], ["content_f"], to=TensorProto.FLOAT),
        helper.make_node("Unsqueeze", ["content_f", "ax2"], ["content"]),
        helper.make_node("Mul", ["ids_u", "te_a"], ["phase0"]),
        helper.make_node("Add", ["phase0", "te_b"], ["phase"]),
        helper.make_node("Sin", ["phase"], ["feat"]),
        helper.make_node("MatMul", ["feat", "te_w"], ["mixed"]),
        helper.make_node("Tanh", ["mixed"], ["act"]),
        helper.make_node("Mul", ["act", "content"], ["masked"]),
        helper.make_node("CumSum", ["masked", "ax1"], ["causal"]),
        helper.make_node("Mul", ["causal", "tenth"], ["causal_s"]),
        helper.make_node("Add", ["masked", "causal_s"], ["h"]),
        helper.make_node("Concat", ["content", "h"], ["last_hidden_state"], axis=2),
        helper.make_node("ReduceMean", ["last_hidden_state"], ["pooler_output"], axes=[1], keepdims=0),
    ]
    inits = [init("ax2", np.array([2], np.int64)), init("ax1", np.array(1, np.int64)),
             init("zero_i", np.array(0, np.int32)), init("bos_i", np.array(BOS, np.int32)),
             init("mod_i", np.array(TE_MOD, np.int32)),
             init("te_a", TE_A), init("te_b", TE_B), init("te_w", TE_W), init("tenth", f32(0.1))]
    g = helper.make_graph(
        n, "text_encoder",
        [helper.make_tensor_value_info("input_ids", TensorProto.INT32, ["batch_size", "sequence_length"])],
        [helper.make_tensor_value_info("last_hidden_state", TensorProto.FLOAT,
                                       ["batch_size", "sequence_length", HIDDEN]),
         helper.make_tensor_value_info("pooler_output", TensorProto.FLOAT, ["batch_size", HIDDEN])],
        inits)
    return model(g)


def text_encoder_ref(ids):
    ids = np.asarray(ids, np.int64)
    content = ((ids > 0) & (ids < BOS)).astype(np.float64)[..., None]
    feat = np.sin((ids[..., None] % TE_MOD).astype(np.float64) * TE_A.astype(np.float64) + TE_B)
    masked = np.tanh(feat @ TE_W.astype(np.float64)) * content
    h = masked + 0.1 * np.cumsum(masked, axis=1)
    last = np.concatenate([content, h], axis=2)
    return last, last.mean(axis=1)


# ---------------------------------------------------------------- tiny UNet
UN_FREQ = f32(np.exp(-np.linspace(0, np.log(1000), 8)))
UN_TW = f32(rng.normal(0, 0.5, (8, LATENT_C)))
UN_CW = f32(rng.normal(0, 1.0, (HIDDEN, LATENT_C)))
UN_CONV = f32(rng.normal(0, 0.25, (LATENT_C, LATENT_C, 3, 3)))
UN_CB = f32(rng.normal(0, 0.1, LATENT_C))


def unet_graph():
    n = [
        helper.make_node("Cast", ["timestep"], ["t_f"], to=TensorProto.FLOAT),
        helper.make_node("Unsqueeze", ["t_f", "ax1"], ["t_u"]),
        helper.make_node("Mul", ["t_u", "freq"], ["t_ph"]),
        helper.make_node("Sin", ["t_ph"], ["t_sin"]),
        helper.make_node("MatMul", ["t_sin", "tw"], ["temb"]),
        helper.make_node("ReduceMean", ["encoder_hidden_states"], ["ctx"], axes=[1], keepdims=0),
        helper.make_node("MatMul", ["ctx", "cw"], ["cemb"]),
        helper.make_node("Add", ["temb", "cemb"], ["emb"]),
        helper.make_node("Unsqueeze", ["emb", "ax23"], ["emb4"]),
        helper.make_node("Conv", ["sample", "conv_w", "conv_b"], ["conv"], pads=[1, 1, 1, 1]),
        helper.make_node("Add", ["conv", "emb4"], ["pre"]),
        helper.make_node("Tanh", ["pre"], ["act"]),
        helper.make_node("Mul", ["act", "two"], ["out_sample"]),
    ]
    inits = [init("ax1", np.array([1], np.int64)), init("ax23", np.array([2, 3], np.int64)),
             init("freq", UN_FREQ), init("tw", UN_TW), init("cw", UN_CW), init("conv_w", UN_CONV),
             init("conv_b", UN_CB), init("two", f32(2.0))]
    g = helper.make_graph(
        n, "unet",
        [helper.make_tensor_value_info("sample", TensorProto.FLOAT,
                                       ["batch_size", LATENT_C, "height", "width"]),
         helper.make_tensor_value_info("timestep", TensorProto.INT64, ["steps"]),
         helper.make_tensor_value_info("encoder_hidden_states", TensorProto.FLOAT,
                                       ["batch_size", "sequence_length", HIDDEN])],
        [helper.make_tensor_value_info("out_sample", TensorProto.FLOAT,
                                       ["batch_size", LATENT_C, "height", "width"])],
        inits)
    return model(g)


def conv3x3_ref(x, w, b):
    B, C, H, W = x.shape
    p = np.pad(x, ((0, 0), (0, 0), (1, 1), (1, 1)))
    out = np.zeros((B, w.shape[0], H, W))
    for dy in range(3):
        for dx in range(3):
            out += np.einsum("bchw,oc->bohw", p[:, :, dy:dy + H, dx:dx + W], w[:, :, dy, dx])
    return out + b[None, :, None, None]


def unet_ref(sample, t, ehs):
    t = np.asarray(t, np.float64).reshape(-1, 1)
    temb = np.sin(t * UN_FREQ.astype(np.float64)) @ UN_TW.astype(np.float64)
    cemb = ehs.mean(axis=1) @ UN_CW.astype(np.float64)
    pre = conv3x3_ref(sample.astype(np.float64), UN_CONV.astype(np.float64), UN_CB.astype(np.float64))
    return 2.0 * np.tanh(pre + (temb + cemb)[:, :, None, None])


# ---------------------------------------------------------------- VAE (linear, patch-wise)
# The decoder maps each latent pixel to an 8x8 RGB patch: x = M (z / scale) + c; the encoder is its
# exact left inverse, so encode(decode(z)) = z. Its output is latent_parameters (mean, logvar).
DEC_M = f32(rng.normal(0, 0.15 * VAE_SCALE, (LATENT_C, 3, FACTOR, FACTOR)))  # images within [-1, 1]
DEC_C = f32(rng.normal(0, 0.05, 3))
_Mmat = DEC_M.reshape(LATENT_C, -1).astype(np.float64).T  # [192, 4]
ENC_P = f32(np.linalg.pinv(_Mmat).reshape(LATENT_C, 3, FACTOR, FACTOR))  # [4, 192]
ENC_B = f32(-(np.linalg.pinv(_Mmat) @ np.repeat(DEC_C.astype(np.float64), FACTOR * FACTOR)))


def vae_decoder_graph(scale_inside=1.0, name="vae_decoder", channels=LATENT_C):
    n = [helper.make_node("Mul", ["latent_sample", "s"], ["zs"]),
         helper.make_node("ConvTranspose", ["zs", "m", "c"], ["sample"], strides=[FACTOR, FACTOR])]
    m = np.concatenate([DEC_M] * (channels // LATENT_C + 1))[:channels]
    g = helper.make_graph(
        n, name,
        [helper.make_tensor_value_info("latent_sample", TensorProto.FLOAT,
                                       ["batch_size", channels, "latent_height", "latent_width"])],
        [helper.make_tensor_value_info("sample", TensorProto.FLOAT, ["batch_size", 3, "height", "width"])],
        [init("m", m), init("c", DEC_C), init("s", f32(scale_inside))])
    return model(g)


def vae_encoder_graph(params_output=True, scale_inside=1.0, name="vae_encoder"):
    out = "latent_parameters" if params_output else "latent_sample"
    n = [helper.make_node("Conv", ["sample", "p", "b"], ["mean0"], strides=[FACTOR, FACTOR]),
         helper.make_node("Mul", ["mean0", "s"], ["mean"])]
    if params_output:
        n += [helper.make_node("Mul", ["mean", "zero"], ["z0"]),
              helper.make_node("Add", ["z0", "logvar"], ["lv"]),
              helper.make_node("Concat", ["mean", "lv"], [out], axis=1)]
        inits = [init("zero", f32(0.0)), init("logvar", f32(-30.0))]
        ch = 2 * LATENT_C
    else:
        n[-1].output[0] = out
        inits = []
        ch = LATENT_C
    g = helper.make_graph(
        n, name,
        [helper.make_tensor_value_info("sample", TensorProto.FLOAT, ["batch_size", 3, "height", "width"])],
        [helper.make_tensor_value_info(out, TensorProto.FLOAT,
                                       ["batch_size", ch, "latent_height", "latent_width"])],
        inits + [init("p", ENC_P), init("b", ENC_B), init("s", f32(scale_inside))])
    return model(g)


def vae_decode_ref(z_unscaled):
    B, C, h, w = z_unscaled.shape
    x = np.einsum("bchw,cokl->bohkwl", z_unscaled.astype(np.float64), DEC_M.astype(np.float64))
    return x.reshape(B, 3, h * FACTOR, w * FACTOR) + DEC_C[None, :, None, None]


def vae_encode_ref(x):
    B, _, H, W = x.shape
    h, w = H // FACTOR, W // FACTOR
    p = x.astype(np.float64).reshape(B, 3, h, FACTOR, w, FACTOR)
    return np.einsum("bohkwl,cokl->bchw", p, ENC_P.astype(np.float64)) + ENC_B[None, :, None, None]


# ---------------------------------------------------------------- analytic UNet
AN_H = AN_W = 8
AN_WZ = f32(rng.normal(0, 1.0, (HIDDEN - 1, LATENT_C * AN_H * AN_W)))


def alphas_cumprod():
    betas = np.linspace(0.00085 ** 0.5, 0.012 ** 0.5, TRAIN_T, dtype=np.float64) ** 2
    return np.cumprod(1.0 - betas)


def analytic_unet_graph():
    ab = f32(alphas_cumprod())
    n = [
        # abar_t by table look-up (timestep is float here, as some exports have it)
        helper.make_node("Cast", ["timestep"], ["t_i"], to=TensorProto.INT64),
        helper.make_node("Gather", ["abar", "t_i"], ["ab"], axis=0),
        helper.make_node("Reshape", ["ab", "shape_b111"], ["ab4"]),
        helper.make_node("Sqrt", ["ab4"], ["sab"]),
        helper.make_node("Sub", ["one", "ab4"], ["omab"]),
        helper.make_node("Sqrt", ["omab"], ["somab"]),
        # the gate: 1 when any token is a content token
        helper.make_node("Slice", ["encoder_hidden_states", "s0", "s1", "s2"], ["content"]),
        helper.make_node("ReduceMax", ["content"], ["gate"], axes=[1, 2], keepdims=0),
        helper.make_node("Reshape", ["gate", "shape_b111"], ["gate4"]),
        # z* = normalise(mean_tokens(h) Wz)
        helper.make_node("Slice", ["encoder_hidden_states", "s1", "s_end", "s2"], ["h"]),
        helper.make_node("ReduceMean", ["h"], ["hm"], axes=[1], keepdims=0),
        helper.make_node("MatMul", ["hm", "wz"], ["v"]),
        helper.make_node("Mul", ["v", "v"], ["v2"]),
        helper.make_node("ReduceMean", ["v2"], ["ms"], axes=[1], keepdims=1),
        helper.make_node("Add", ["ms", "tiny"], ["ms_e"]),
        helper.make_node("Sqrt", ["ms_e"], ["rms"]),
        helper.make_node("Div", ["v", "rms"], ["vn"]),
        helper.make_node("Reshape", ["vn", "shape_lat"], ["zstar"]),
        helper.make_node("Mul", ["zstar", "sab"], ["szs"]),
        helper.make_node("Sub", ["sample", "szs"], ["diff"]),
        helper.make_node("Div", ["diff", "somab"], ["eps"]),
        helper.make_node("Mul", ["eps", "gate4"], ["out_sample"]),
    ]
    inits = [init("abar", ab), init("shape_b111", np.array([-1, 1, 1, 1], np.int64)),
             init("one", f32(1.0)), init("tiny", f32(1e-12)),
             init("s0", np.array([0], np.int64)), init("s1", np.array([1], np.int64)),
             init("s2", np.array([2], np.int64)), init("s_end", np.array([HIDDEN], np.int64)),
             init("wz", AN_WZ), init("shape_lat", np.array([-1, LATENT_C, AN_H, AN_W], np.int64))]
    g = helper.make_graph(
        n, "analytic_unet",
        [helper.make_tensor_value_info("sample", TensorProto.FLOAT, ["batch_size", LATENT_C, AN_H, AN_W]),
         helper.make_tensor_value_info("timestep", TensorProto.FLOAT, ["steps"]),
         helper.make_tensor_value_info("encoder_hidden_states", TensorProto.FLOAT,
                                       ["batch_size", "sequence_length", HIDDEN])],
        [helper.make_tensor_value_info("out_sample", TensorProto.FLOAT, ["batch_size", LATENT_C, AN_H, AN_W])],
        inits)
    return model(g)


def zstar_ref(ehs):
    v = ehs[:, :, 1:].mean(axis=1) @ AN_WZ.astype(np.float64)
    v = v / np.sqrt((v * v).mean(axis=1, keepdims=True) + 1e-12)
    return v.reshape(-1, LATENT_C, AN_H, AN_W)


def with_fp16_io(m):
    """The same model with float16 inputs and outputs (as an fp16 export declares them)."""
    g = m.graph
    casts_in, casts_out = [], []
    for i in g.input:
        if i.type.tensor_type.elem_type == TensorProto.FLOAT:
            inner = i.name + "_f32"
            for node in g.node:
                for k, name in enumerate(node.input):
                    if name == i.name:
                        node.input[k] = inner
            casts_in.append(helper.make_node("Cast", [i.name], [inner], to=TensorProto.FLOAT))
            i.type.tensor_type.elem_type = TensorProto.FLOAT16
    for o in g.output:
        inner = o.name + "_f32"
        for node in g.node:
            for k, name in enumerate(node.output):
                if name == o.name:
                    node.output[k] = inner
        casts_out.append(helper.make_node("Cast", [inner], [o.name], to=TensorProto.FLOAT16))
        o.type.tensor_type.elem_type = TensorProto.FLOAT16
    nodes = casts_in + list(g.node) + casts_out
    del g.node[:]
    g.node.extend(nodes)
    return m


# ---------------------------------------------------------------- files
def pad_ids(ids):
    ids = list(ids[:SEQ - 1]) if len(ids) > SEQ else list(ids)
    if ids[-1] != EOS:
        ids[-1] = EOS
    return ids + [0] * (SEQ - len(ids))


def write_common(root):
    if os.path.isdir(root):
        shutil.rmtree(root)
    os.makedirs(os.path.join(root, "tokenizer"))
    for f in ("vocab.json", "merges.txt"):
        shutil.copy(os.path.join("tests/data/clip", f), os.path.join(root, "tokenizer", f))
    special = {"bos_token": {"content": "<|startoftext|>", "lstrip": False, "normalized": True,
                             "rstrip": False, "single_word": False},
               "eos_token": {"content": "<|endoftext|>", "lstrip": False, "normalized": True,
                             "rstrip": False, "single_word": False},
               "pad_token": "!", "unk_token": {"content": "<|endoftext|>", "lstrip": False,
                                               "normalized": True, "rstrip": False, "single_word": False}}
    json.dump(special, open(os.path.join(root, "tokenizer/special_tokens_map.json"), "w"), indent=2)
    json.dump({"model_max_length": SEQ, "do_lower_case": True, "pad_token": "!",
               "tokenizer_class": "CLIPTokenizer", "bos_token": "<|startoftext|>",
               "eos_token": "<|endoftext|>", "unk_token": "<|endoftext|>"},
              open(os.path.join(root, "tokenizer/tokenizer_config.json"), "w"), indent=2)
    os.makedirs(os.path.join(root, "scheduler"))
    json.dump({"_class_name": "DDIMScheduler", "beta_end": 0.012, "beta_schedule": "scaled_linear",
               "beta_start": 0.00085, "clip_sample": False, "num_train_timesteps": TRAIN_T,
               "prediction_type": "epsilon", "set_alpha_to_one": False, "steps_offset": 1,
               "timestep_spacing": "leading"},
              open(os.path.join(root, "scheduler/scheduler_config.json"), "w"), indent=2)
    json.dump({"_class_name": "ORTStableDiffusionPipeline", "_diffusers_version": "0.30.0",
               "scheduler": ["diffusers", "DDIMScheduler"], "text_encoder": ["transformers", "CLIPTextModel"],
               "tokenizer": ["transformers", "CLIPTokenizer"], "unet": ["diffusers", "UNet2DConditionModel"],
               "vae_decoder": ["diffusers", "AutoencoderKL"], "vae_encoder": ["diffusers", "AutoencoderKL"]},
              open(os.path.join(root, "model_index.json"), "w"), indent=2)
    save(text_encoder_graph(), os.path.join(root, "text_encoder/model.onnx"))
    save(vae_encoder_graph(), os.path.join(root, "vae_encoder/model.onnx"))
    save(vae_decoder_graph(), os.path.join(root, "vae_decoder/model.onnx"))
    for sub in ("vae_encoder", "vae_decoder"):
        json.dump({"_class_name": "AutoencoderKL", "latent_channels": LATENT_C, "scaling_factor": VAE_SCALE,
                   "sample_size": 64, "block_out_channels": [8, 8, 8, 8]},
                  open(os.path.join(root, sub, "config.json"), "w"), indent=2)


def main():
    cases = json.load(open("tests/data/clip/cases.json"))["cases"]
    by_prompt = {c["prompt"]: c["ids"] for c in cases}
    prompts = ["a photo of a cat", "A DSLR photo of a cozy living room", ""]
    ids = np.array([pad_ids(by_prompt[p]) for p in prompts], np.int32)
    last, pooled = text_encoder_ref(ids)

    root = "tests/data/tiny-sd"
    write_common(root)
    save(unet_graph(), os.path.join(root, "unet/model.onnx"), external=True)
    # A decoder for 8-channel latents: loads, but does not fit a 4-channel UNet.
    save(vae_decoder_graph(channels=2 * LATENT_C), "tests/data/broken/vae_decoder_8ch/model.onnx")
    # The same UNet as an fp16 export declares it (float16 sample, states and output).
    save(with_fp16_io(unet_graph()), "tests/data/fp16-unet/model.onnx", external=True)
    json.dump({"_class_name": "UNet2DConditionModel", "in_channels": LATENT_C, "out_channels": LATENT_C,
               "cross_attention_dim": HIDDEN, "sample_size": 8}, open(os.path.join(root, "unet/config.json"), "w"),
              indent=2)
    json.dump({"_class_name": "CLIPTextModel", "hidden_size": HIDDEN, "max_position_embeddings": SEQ},
              open(os.path.join(root, "text_encoder/config.json"), "w"), indent=2)
    # A TAESD-style pair: latents in the UNet's (scaled) space, so its scaling factor is 1.
    save(vae_encoder_graph(params_output=False, scale_inside=VAE_SCALE, name="taesd_encoder"),
         os.path.join(root, "taesd_encoder/model.onnx"))
    save(vae_decoder_graph(scale_inside=1.0 / VAE_SCALE, name="taesd_decoder"),
         os.path.join(root, "taesd_decoder/model.onnx"))
    for sub in ("taesd_encoder", "taesd_decoder"):
        json.dump({"_class_name": "AutoencoderTiny", "latent_channels": LATENT_C, "scaling_factor": 1.0},
                  open(os.path.join(root, sub, "config.json"), "w"), indent=2)

    h = w = 8
    lat = np.sin(np.arange(2 * LATENT_C * h * w) * 0.37).reshape(2, LATENT_C, h, w)
    t = np.array([500, 500])
    u = unet_ref(lat, t, last[:2])
    img = np.cos(np.arange(1 * 3 * 64 * 64) * 0.011).reshape(1, 3, 64, 64) * 0.8
    z_unscaled = lat[:1] / VAE_SCALE
    dec = vae_decode_ref(z_unscaled)
    enc = vae_encode_ref(img)
    golden = {
        "prompts": prompts,
        "input_ids": ids.tolist(),
        "pooler_output": pooled.tolist(),
        "last_hidden_state_sum": last.sum(axis=(1, 2)).tolist(),
        "last_hidden_state_row1": last[:, 1, :].tolist(),
        "unet": {"sample": "sin(0.37 i), shape [2,4,8,8]", "timestep": 500,
                 "conditions": prompts[:2], "out_sample": u.reshape(-1).tolist()},
        "vae_decoder": {"latent": "the UNet sample's first item (scaled latent)",
                        "sample_sum": float(dec.sum()), "sample_first": dec.reshape(-1)[:16].tolist()},
        "vae_encoder": {"image": "0.8 cos(0.011 i), shape [1,3,64,64]",
                        "latent_unscaled_mean": enc.reshape(-1).tolist()},
    }
    json.dump(golden, open(os.path.join(root, "golden.json"), "w"), indent=1)

    aroot = "tests/data/analytic-sd"
    write_common(aroot)
    save(analytic_unet_graph(), os.path.join(aroot, "unet/model.onnx"), external=True)
    json.dump({"_class_name": "UNet2DConditionModel", "in_channels": LATENT_C, "out_channels": LATENT_C,
               "cross_attention_dim": HIDDEN, "sample_size": AN_H},
              open(os.path.join(aroot, "unet/config.json"), "w"), indent=2)
    json.dump({"_class_name": "CLIPTextModel", "hidden_size": HIDDEN, "max_position_embeddings": SEQ},
              open(os.path.join(aroot, "text_encoder/config.json"), "w"), indent=2)
    zs = zstar_ref(last)
    json.dump({"prompts": prompts, "zstar": zs.reshape(len(prompts), -1).tolist(),
               "gate": [float(last[i, :, 0].max()) for i in range(len(prompts))]},
              open(os.path.join(aroot, "golden.json"), "w"), indent=1)

    try:
        import onnxruntime as ort
    except ImportError:
        print("onnxruntime not installed: goldens not cross-checked")
        return
    te = ort.InferenceSession(os.path.join(root, "text_encoder/model.onnx"))
    o_last, o_pool = te.run(None, {"input_ids": ids})
    assert np.allclose(o_last, last, atol=2e-5), ("text encoder", np.abs(o_last - last).max())
    assert np.allclose(o_pool, pooled, atol=1e-5)
    un = ort.InferenceSession(os.path.join(root, "unet/model.onnx"))
    o = un.run(None, {"sample": f32(lat), "timestep": t.astype(np.int64),
                      "encoder_hidden_states": o_last[:2]})[0]
    assert np.allclose(o, u, atol=1e-4), ("unet", np.abs(o - u).max())
    un16 = ort.InferenceSession("tests/data/fp16-unet/model.onnx")
    o16 = un16.run(None, {"sample": lat.astype(np.float16), "timestep": t.astype(np.int64),
                          "encoder_hidden_states": o_last[:2].astype(np.float16)})[0]
    assert o16.dtype == np.float16 and np.allclose(o16, u, atol=2e-2), ("fp16 unet", np.abs(o16 - u).max())
    de = ort.InferenceSession(os.path.join(root, "vae_decoder/model.onnx"))
    assert np.allclose(de.run(None, {"latent_sample": f32(z_unscaled)})[0], dec, atol=1e-4), "decoder"
    en = ort.InferenceSession(os.path.join(root, "vae_encoder/model.onnx"))
    params = en.run(None, {"sample": f32(img)})[0]
    assert np.allclose(params[:, :LATENT_C], enc, atol=1e-4), "encoder"
    rt = vae_encode_ref(vae_decode_ref(z_unscaled))
    assert np.allclose(rt, z_unscaled, atol=1e-6), "VAE round trip"
    an = ort.InferenceSession(os.path.join(aroot, "unet/model.onnx"))
    ab = alphas_cumprod()
    x = f32(np.cos(np.arange(3 * 256) * 0.3).reshape(3, LATENT_C, AN_H, AN_W))
    tt = np.array([10.0, 500.0, 900.0], np.float32)
    o = an.run(None, {"sample": x, "timestep": tt, "encoder_hidden_states": o_last})[0]
    a = ab[tt.astype(int)].reshape(-1, 1, 1, 1)
    gate = last[:, :, 0].max(axis=1).reshape(-1, 1, 1, 1)
    ref = gate * (x - np.sqrt(a) * zs) / np.sqrt(1 - a)
    assert np.allclose(o, ref, atol=1e-3, rtol=1e-4), ("analytic", np.abs(o - ref).max())
    print("goldens cross-checked with onnxruntime", ort.__version__)


if __name__ == "__main__":
    main()
