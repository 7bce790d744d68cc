#!/usr/bin/env python3
"""Carry a Stable Diffusion ONNX export to a machine without network in a few MiB.

    weightless.py strip EXPORT_DIR OUT_DIR   # graphs without their weights + weights.json
    weightless.py fill  OUT_DIR [--seed N]   # writes random weights of the recorded shapes back

`strip` copies every file of an Optimum export (tokenizer, configs, ...) and, for each
`*/model.onnx`, writes the graph without its float weights (integer and tiny initializers stay)
and records each removed weight's name, dtype and shape in `weights.json` beside it. External
data (`model.onnx_data`) is not copied. The full-size SD 2.1 export carries in a few MiB.

`fill` reads each `weights.json` and writes the model back with random weights (normal,
std 0.02; integer initializers such as shape constants are kept: they are tiny and are stored
in the stripped graph). Models over protobuf's 2 GB limit are saved with external data in
`model.onnx_data`, as Optimum does. Random weights do not change the cost of a run, which is
all a measurement needs (bench --generate --prior sd --models DIR).

Needs `onnx` and `numpy` (pip install onnx numpy).
"""
import json
import os
import shutil
import sys

import numpy as np
import onnx
from onnx import TensorProto, numpy_helper

# Initializers at most this many elements, or of integer types, stay in the stripped graph
# (shape constants, axes, small biases): together they are small and keep the graph exact.
KEEP_ELEMENTS = 64
INTEGER = {TensorProto.INT64, TensorProto.INT32, TensorProto.INT8, TensorProto.UINT8,
           TensorProto.BOOL, TensorProto.INT16}


def strip(src, dst):
    os.makedirs(dst, exist_ok=True)
    for root, _dirs, files in os.walk(src):
        rel = os.path.relpath(root, src)
        os.makedirs(os.path.join(dst, rel), exist_ok=True)
        for f in files:
            path = os.path.join(root, f)
            out = os.path.join(dst, rel, f)
            if f == "model.onnx":
                strip_model(path, out)
            elif f.endswith(".onnx_data") or f.endswith(".onnx.data"):
                continue
            else:
                shutil.copy(path, out)


def strip_model(path, out):
    m = onnx.load(path, load_external_data=True)
    record = []
    for t in m.graph.initializer:
        n = int(np.prod(t.dims)) if len(t.dims) else 1
        if t.data_type in INTEGER or n <= KEEP_ELEMENTS:
            continue
        record.append({"name": t.name, "dtype": int(t.data_type), "shape": list(t.dims)})
    names = {r["name"] for r in record}
    keep = [t for t in m.graph.initializer if t.name not in names]
    del m.graph.initializer[:]
    m.graph.initializer.extend(keep)
    onnx.save(m, out)
    with open(os.path.join(os.path.dirname(out), "weights.json"), "w") as f:
        json.dump({"model": "model.onnx", "weights": record}, f)
    size = sum(int(np.prod(r["shape"])) for r in record)
    print(f"{out}: {len(record)} weights ({size / 1e6:.1f} M values) stripped, "
          f"{len(keep)} small initializers kept, {os.path.getsize(out) / 2**20:.2f} MiB")


def fill(dst, seed):
    rng = np.random.default_rng(seed)
    for root, _dirs, files in os.walk(dst):
        if "weights.json" not in files:
            continue
        with open(os.path.join(root, "weights.json")) as f:
            rec = json.load(f)
        path = os.path.join(root, rec["model"])
        m = onnx.load(path, load_external_data=False)
        total = 0
        for w in rec["weights"]:
            dtype = onnx.helper.tensor_dtype_to_np_dtype(w["dtype"])
            a = (0.02 * rng.standard_normal(w["shape"], dtype=np.float32)).astype(dtype)
            total += a.nbytes
            m.graph.initializer.append(numpy_helper.from_array(a, w["name"]))
        external = total > 1_800_000_000
        if external:
            onnx.save(m, path, save_as_external_data=True, all_tensors_to_one_file=True,
                      location="model.onnx_data", size_threshold=1024)
        else:
            onnx.save(m, path)
        os.remove(os.path.join(root, "weights.json"))
        print(f"{path}: {len(rec['weights'])} weights written ({total / 2**20:.0f} MiB"
              f"{', external data' if external else ''})")


def main(argv):
    if len(argv) >= 3 and argv[0] == "strip":
        strip(argv[1], argv[2])
    elif len(argv) >= 2 and argv[0] == "fill":
        seed = int(argv[argv.index("--seed") + 1]) if "--seed" in argv else 0
        fill(argv[1], seed)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
