"""Writes tests/data/clip/: a subset of the real CLIP BPE vocabulary (vocab.json + merges.txt in the
Hugging Face layout, real token ids) and reference token ids for a set of prompts.

Development-time only (the outputs are committed). It needs open_clip's reference tokenizer and its
vocabulary file, both from the `open_clip_torch` wheel, and the `ftfy` and `regex` packages:

    pip download open_clip_torch --no-deps -d /tmp/oc && cd /tmp/oc && unzip -o open_clip_torch*.whl \
        open_clip/tokenizer.py open_clip/bpe_simple_vocab_16e6.txt.gz
    pip install ftfy regex
    python3 scripts/dev/make_clip_fixture.py /tmp/oc/open_clip

Only the merges whose result occurs inside a word of the prompts are kept. BPE applies, at each step,
the lowest-ranked merge present in the word; every merge the full vocabulary applies to these words is
kept and the kept ones keep their relative order, so the subset tokenizes these prompts exactly as the
full vocabulary does, with the real ids.
"""
import gzip
import importlib.util
import json
import os
import sys
import types

src = sys.argv[1]
_torch = types.ModuleType("torch")  # the reference tokenizer imports it for annotations only
_torch.LongTensor = _torch.Tensor = object
sys.modules["torch"] = _torch
spec = importlib.util.spec_from_file_location("octok", os.path.join(src, "tokenizer.py"))
octok = importlib.util.module_from_spec(spec)
spec.loader.exec_module(octok)
bpe_path = os.path.join(src, "bpe_simple_vocab_16e6.txt.gz")
tok = octok.SimpleTokenizer(bpe_path)

NEG = "unrealistic, blurry, low quality, out of focus, ugly, low contrast, dull, dark, low-resolution, gloomy"
STYLE = "4k, 8k, best quality, ultra-detailed, finely detail, highres, high resolution"
prompts = [
    "a photo of a cat",
    "A DSLR photo of a cozy living room",
    "A DSLR photo of a wooden chair, front view, " + STYLE,
    "A DSLR photo of a wooden chair, side view, " + STYLE,
    "A DSLR photo of a wooden chair, back view, " + STYLE,
    "A DSLR photo of a wooden chair, overhead view, " + STYLE,
    NEG + ", side view, back view, overhead view",
    NEG + ", front view, back view, side view",
    "",
    "The cat's toy isn't here; it's 3.5m   away!!",
    "  Caf\u00e9 au LAIT\tat 9pm -- 100% #tasty ",
    "a red sofa with 2 cushions next to a low coffee table",
    "a living room with a sofa, a coffee table, a tv stand, a rug, a floor lamp, an armchair, a bookshelf, "
    "a plant, a side table, a painting on the wall, a window with curtains, a ceiling light, and a cozy "
    "reading corner with a blanket and pillows and many more things than fit, a desk, a chair, a "
    "mirror, a vase of flowers, a clock, a dog bed, a guitar, a record player, a fireplace and a piano",
    "a DSLR photo of a snowy mountain village at dusk, outdoor scene",
    "\u4e2d\u6587 emoji \U0001F600 ok",
]

cases = []
words = set()
for p in prompts:
    ids = tok.encode(p)
    full = [tok.encoder["<start_of_text>"]] + ids + [tok.encoder["<end_of_text>"]]
    cases.append({"prompt": p, "ids": full})
    text = octok.whitespace_clean(octok.basic_clean(p)).lower()
    for w in octok.re.findall(tok.pat, text):
        words.add("".join(tok.byte_encoder[b] for b in w.encode("utf-8")) + "</w>")

# The reference file: line 0 is a header, then merges in rank order.
lines = gzip.open(bpe_path).read().decode("utf-8").split("\n")
merges = [tuple(m.split()) for m in lines[1 : 49152 - 256 - 2 + 1]]
kept = [m for m in merges if any(m[0] + m[1] in w for w in words)]

vocab = {}
for v, i in tok.encoder.items():
    if i < 512 or i >= 49406:
        vocab[v] = i
for a, b in kept:
    vocab[a + b] = tok.encoder[a + b]
# Hugging Face names the special tokens differently from open_clip.
vocab["<|startoftext|>"] = vocab.pop("<start_of_text>")
vocab["<|endoftext|>"] = vocab.pop("<end_of_text>")

out = "tests/data/clip"
os.makedirs(out, exist_ok=True)
with open(os.path.join(out, "vocab.json"), "w") as f:
    json.dump(dict(sorted(vocab.items(), key=lambda kv: kv[1])), f, ensure_ascii=False, indent=0)
with open(os.path.join(out, "merges.txt"), "w") as f:
    f.write("#version: 0.2\n")
    for a, b in kept:
        f.write(f"{a} {b}\n")
with open(os.path.join(out, "cases.json"), "w") as f:
    json.dump({"source": "open_clip SimpleTokenizer, bpe_simple_vocab_16e6", "cases": cases}, f,
              ensure_ascii=False, indent=1)
print(f"{len(kept)} merges, {len(vocab)} tokens, {len(cases)} prompts")
