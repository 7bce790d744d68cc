// Independent readers for the export tests: each prints what a third-party library decodes from
// a file, as JSON on stdout, with no interpretation of its own.
//
//   node readers.mjs spz FILE       Niantic's SPZ decoder (@adobe/spz, its C++ library built to
//                                   WebAssembly), converting to the PLY (RDF) frame
//   node readers.mjs gltf FILE      @gltf-transform/core: the first primitive's attributes
//   node readers.mjs validate FILE  the Khronos glTF validator's report
import { readFileSync } from 'node:fs';

const [kind, file] = process.argv.slice(2);
const bytes = new Uint8Array(readFileSync(file));

if (kind === 'spz') {
  const { default: createModule } = await import('@adobe/spz');
  // The library logs what it reads; keep stdout for the JSON.
  const spz = await createModule({ print: (s) => process.stderr.write(`${s}\n`) });
  const c = spz.loadSpzFromBuffer(bytes, { to: spz.CoordinateSystem.RDF });
  const out = {
    numPoints: c.numPoints,
    shDegree: c.shDegree,
    positions: Array.from(c.positions),
    scales: Array.from(c.scales),
    rotations: Array.from(c.rotations),
    alphas: Array.from(c.alphas),
    colors: Array.from(c.colors),
    sh: Array.from(c.sh),
  };
  process.stdout.write(JSON.stringify(out));
} else if (kind === 'gltf') {
  const { NodeIO } = await import('@gltf-transform/core');
  const doc = await new NodeIO().readBinary(bytes);
  const root = doc.getRoot();
  const meshes = root.listMeshes();
  const prim = meshes[0].listPrimitives()[0];
  const attributes = {};
  for (const name of prim.listSemantics()) {
    const acc = prim.getAttribute(name);
    const values = [];
    const el = [];
    for (let i = 0; i < acc.getCount(); i++) {
      // getElement decodes normalized integer components to 0..1 floats.
      values.push(...acc.getElement(i, el));
    }
    attributes[name] = {
      type: acc.getType(),
      componentType: acc.getComponentType(),
      normalized: acc.getNormalized(),
      values,
    };
  }
  const json = JSON.parse(
    new TextDecoder().decode(bytes.subarray(20, 20 + new DataView(bytes.buffer).getUint32(12, true))),
  );
  process.stdout.write(JSON.stringify({
    meshes: meshes.length,
    nodes: root.listNodes().length,
    mode: prim.getMode(),
    attributes,
    extensionsUsed: json.extensionsUsed ?? [],
    primitiveExtensions: json.meshes[0].primitives[0].extensions ?? {},
  }));
} else if (kind === 'validate') {
  const validator = await import('gltf-validator');
  const report = await validator.validateBytes(bytes, { maxIssues: 100 });
  process.stdout.write(JSON.stringify(report));
} else {
  process.stderr.write(`unknown reader '${kind}'\n`);
  process.exit(2);
}
