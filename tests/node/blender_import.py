# Blender's glTF importer as an outside reader of the engine-ready glb (tests/export_engine.rs):
#   blender -b --factory-startup --python tests/node/blender_import.py -- FILE.glb
# prints one line `RESULT {json}`: every object's type, parent, custom properties (the node
# extras) and, for meshes, the world-space bounding box (Blender's frame: z up, as the scene).
import json
import sys
import warnings

import bpy
import numpy
from mathutils import Vector

# Blender 3.4's importer uses numpy.bool, gone from numpy >= 1.24.
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

path = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=path, import_shading="FLAT")


def plain(v):
    if hasattr(v, "to_dict"):
        v = v.to_dict()
    elif hasattr(v, "to_list"):
        v = v.to_list()
    if isinstance(v, dict):
        return {k: plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    return v if isinstance(v, (int, float, str)) else str(v)


out = {}
for o in bpy.data.objects:
    e = {
        "type": o.type,
        "parent": o.parent.name if o.parent else None,
        "props": {k: plain(o[k]) for k in o.keys()},
    }
    if o.type == "MESH":
        pts = [o.matrix_world @ Vector(c) for c in o.bound_box]
        e["world_box"] = [[min(p[i] for p in pts) for i in range(3)],
                          [max(p[i] for p in pts) for i in range(3)]]
        e["vertices"] = len(o.data.vertices)
    out[o.name] = e
print("RESULT " + json.dumps(out))
