#!/usr/bin/env python3
"""Write a TAESD-shaped autoencoder pair with random weights into a model directory.

    make_taesd_shaped.py MODEL_DIR [--seed N]

Writes MODEL_DIR/taesd_encoder/model.onnx and MODEL_DIR/taesd_decoder/model.onnx with the layer
shapes of the published tiny autoencoder for Stable Diffusion (64 channels, 3x3 convolutions,
residual blocks of three convolutions, three stride-2 steps down and three nearest-neighbour
upsamplings back; about 1.2 M weights each side), fp32, inputs and outputs named as dreamscene's
pipeline expects (`sample` -> `latent_sample` and back). The weights are random: the pair is for
timing an iteration (`bench --generate --prior sd`), not for pictures. A few MiB, so it travels
to a machine without network as it is.

Needs `onnx` and `numpy` (pip install onnx numpy).
"""
import os
import sys

import numpy as np
import onnx
from onnx import TensorProto, helper, numpy_helper

CH = 64
LATENT = 4


class Graph:
    def __init__(self, rng):
        self.rng = rng
        self.nodes = []
        self.inits = []
        self.n = 0

    def name(self, base):
        self.n += 1
        return f"{base}_{self.n}"

    def conv(self, x, cin, cout, stride=1, bias=True):
        w = self.name("w")
        std = (2.0 / (cin * 9)) ** 0.5
        self.inits.append(numpy_helper.from_array(
            (self.rng.standard_normal((cout, cin, 3, 3)) * std).astype(np.float32), w))
        inputs = [x, w]
        if bias:
            b = self.name("b")
            self.inits.append(numpy_helper.from_array(np.zeros(cout, np.float32), b))
            inputs.append(b)
        y = self.name("conv")
        self.nodes.append(helper.make_node("Conv", inputs, [y], kernel_shape=[3, 3],
                                           pads=[1, 1, 1, 1], strides=[stride, stride]))
        return y

    def op(self, kind, inputs, **attrs):
        y = self.name(kind.lower())
        self.nodes.append(helper.make_node(kind, inputs, [y], **attrs))
        return y

    def relu(self, x):
        return self.op("Relu", [x])

    def block(self, x):
        h = self.relu(self.conv(x, CH, CH))
        h = self.relu(self.conv(h, CH, CH))
        h = self.conv(h, CH, CH)
        return self.relu(self.op("Add", [h, x]))

    def const(self, value):
        c = self.name("c")
        self.inits.append(numpy_helper.from_array(np.array(value, np.float32), c))
        return c

    def model(self, name, x_in, y_out, x_shape, y_shape):
        g = helper.make_graph(
            self.nodes, name,
            [helper.make_tensor_value_info(x_in, TensorProto.FLOAT, x_shape)],
            [helper.make_tensor_value_info(y_out, TensorProto.FLOAT, y_shape)],
            self.inits)
        m = helper.make_model(g, opset_imports=[helper.make_opsetid("", 17)])
        m.ir_version = 8
        onnx.checker.check_model(m)
        return m


def encoder(rng):
    g = Graph(rng)
    x = g.conv("sample", 3, CH)
    x = g.block(x)
    for _ in range(3):
        x = g.conv(x, CH, CH, stride=2, bias=False)
        for _ in range(3):
            x = g.block(x)
    x = g.conv(x, CH, LATENT)
    g.nodes[-1].output[0] = "latent_sample"
    return g.model("taesd_encoder", "sample", "latent_sample",
                   ["batch_size", 3, "height", "width"],
                   ["batch_size", LATENT, "height_latent", "width_latent"])


def decoder(rng):
    g = Graph(rng)
    # soft clamp of the latents: tanh(x / 3) * 3
    x = g.op("Mul", [g.op("Tanh", [g.op("Div", ["latent_sample", g.const(3.0)])]), g.const(3.0)])
    x = g.relu(g.conv(x, LATENT, CH))
    for i in range(3):
        for _ in range(3):
            x = g.block(x)
        x = g.op("Resize", [x, "", g.const([1.0, 1.0, 2.0, 2.0])], mode="nearest")
        x = g.conv(x, CH, CH, bias=False)
    x = g.block(x)
    x = g.conv(x, CH, 3)
    g.nodes[-1].output[0] = "sample"
    return g.model("taesd_decoder", "latent_sample", "sample",
                   ["batch_size", LATENT, "height_latent", "width_latent"],
                   ["batch_size", 3, "height", "width"])


def main(argv):
    if len(argv) < 2 or argv[1].startswith("-"):
        sys.exit(__doc__)
    out = argv[1]
    seed = int(argv[argv.index("--seed") + 1]) if "--seed" in argv else 0
    rng = np.random.default_rng(seed)
    for sub, m in (("taesd_encoder", encoder(rng)), ("taesd_decoder", decoder(rng))):
        os.makedirs(os.path.join(out, sub), exist_ok=True)
        path = os.path.join(out, sub, "model.onnx")
        onnx.save(m, path)
        n = sum(int(np.prod(t.dims)) for t in m.graph.initializer)
        print(f"{path}: {n / 1e6:.2f} M weights, {os.path.getsize(path) / 2**20:.1f} MiB")


if __name__ == "__main__":
    main(sys.argv)
