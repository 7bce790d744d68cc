"""Writes the four tiny ONNX graphs the provider probe (src/diffusion/probe.rs) runs on a GPU
provider and on the CPU provider to compare them, into src/diffusion/probe/ (committed; the
library embeds them):

- softmax_fp32.onnx / softmax_fp16.onnx: x float[N, H, S, T] -> Softmax(axis=-1) -> y float
  (the fp16 one casts to float16 around the Softmax, as an fp16 UNet's attention runs).
- conv_fp32.onnx / conv_fp16.onnx: x float[N, C, H, W], w float[K, C, 3, 3], b float[K] ->
  Conv(pads 1) -> y float (cast to float16 around the Conv in the fp16 one).

All shapes are dynamic: the probe feeds the run's sizes. Development-time only:
python3 scripts/dev/make_probe_graphs.py (needs `onnx`).
"""
import os

import onnx
from onnx import TensorProto, helper

OPSET = 17
OUT = os.path.join(os.path.dirname(__file__), "..", "..", "src", "diffusion", "probe")


def graph(name, op_nodes, inputs, half):
    nodes = []
    feeds = []
    for i in inputs:
        if half:
            nodes.append(helper.make_node("Cast", [i], [i + "_h"], to=TensorProto.FLOAT16))
            feeds.append(i + "_h")
        else:
            feeds.append(i)
    core_out = "y_h" if half else "y"
    nodes.extend(op_nodes(feeds, core_out))
    if half:
        nodes.append(helper.make_node("Cast", ["y_h"], ["y"], to=TensorProto.FLOAT))
    dims = {"x": ["n", "c", "h", "w"], "w": ["k", "c", "kh", "kw"], "b": ["k"]}
    ins = [helper.make_tensor_value_info(i, TensorProto.FLOAT, dims[i]) for i in inputs]
    out = helper.make_tensor_value_info("y", TensorProto.FLOAT, ["n", "k", "h", "w"] if len(inputs) > 1 else dims["x"])
    g = helper.make_graph(nodes, name, ins, [out])
    m = helper.make_model(g, opset_imports=[helper.make_opsetid("", OPSET)], producer_name="dreamscene")
    m.ir_version = 8
    onnx.checker.check_model(m)
    return m


def softmax(feeds, out):
    return [helper.make_node("Softmax", feeds, [out], axis=-1)]


def conv(feeds, out):
    return [helper.make_node("Conv", feeds, [out], pads=[1, 1, 1, 1])]


os.makedirs(OUT, exist_ok=True)
for half in (False, True):
    tag = "fp16" if half else "fp32"
    onnx.save(graph("softmax_" + tag, softmax, ["x"], half), os.path.join(OUT, f"softmax_{tag}.onnx"))
    onnx.save(graph("conv_" + tag, conv, ["x", "w", "b"], half), os.path.join(OUT, f"conv_{tag}.onnx"))
