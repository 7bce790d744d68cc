// Outside readers of the engine-ready glb, for tests/export_engine.rs. Each prints what a
// third-party library decodes, as JSON on stdout; the test judges it.
//
//   node engine.mjs three FILE.glb            three.js GLTFLoader (+ its KHR_gaussian_splatting
//                                             plugin): nodes, parents, extras, physics blocks,
//                                             world transforms and boxes, decoded splat count
//   node engine.mjs features FILE.glb         @gltf-transform/extensions: EXT_mesh_features
//                                             feature ids and the _FEATURE_ID_0 histogram
//   node engine.mjs recast FILE.glb Q.json    recast-navigation: a Detour navmesh built from the
//                                             glb's `navmesh` node, and the path of each query
//                                             {from, to} (glTF frame) after snapping both ends
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { pathToFileURL } from 'node:url';
import path from 'node:path';

const [kind, file, extra] = process.argv.slice(2);
const bytes = new Uint8Array(readFileSync(file));
const here = path.dirname(new URL(import.meta.url).pathname);
const viewer = path.join(here, '..', '..', 'viewer', 'node_modules');
const out = (v) => process.stdout.write(JSON.stringify(v));

async function three() {
  const THREE = await import(pathToFileURL(path.join(viewer, 'three', 'build', 'three.module.js')));
  const jsm = (p) => pathToFileURL(path.join(viewer, 'three', 'examples', 'jsm', p));
  const { GLTFLoader } = await import(jsm('loaders/GLTFLoader.js'));
  const { GLTFGaussianSplatLoaderExtension } = await import(jsm('loaders/GLTFGaussianSplatLoaderExtension.js'));
  const loader = new GLTFLoader();
  loader.register((p) => new GLTFGaussianSplatLoaderExtension(p));
  const g = await loader.parseAsync(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), '');
  g.scene.updateMatrixWorld(true);
  const nodes = {};
  let splats = 0;
  g.scene.traverse((o) => {
    if (o.splatGeometry) splats += o.splatGeometry.getAttribute('position').count;
    if (!o.name) return;
    const p = new THREE.Vector3();
    const q = new THREE.Quaternion();
    o.matrixWorld.decompose(p, q, new THREE.Vector3());
    const entry = {
      parent: o.parent ? o.parent.name : null,
      extras: o.userData ?? {},
      world_position: p.toArray(),
      world_quaternion: q.toArray(),
    };
    if (o.isMesh) {
      const b = new THREE.Box3().setFromObject(o);
      entry.world_box = [b.min.toArray(), b.max.toArray()];
      entry.triangles = (o.geometry.index ? o.geometry.index.count : o.geometry.getAttribute('position').count) / 3;
    }
    // Only the first object of a name (three names a node's mesh after the node too).
    if (!(o.name in nodes)) nodes[o.name] = entry;
  });
  out({ nodes, splats });
}

async function features() {
  const { NodeIO } = await import('@gltf-transform/core');
  const { ALL_EXTENSIONS } = await import('@gltf-transform/extensions');
  const doc = await new NodeIO().registerExtensions(ALL_EXTENSIONS).readBinary(bytes);
  const result = [];
  for (const mesh of doc.getRoot().listMeshes()) {
    for (const prim of mesh.listPrimitives()) {
      const ext = prim.getExtension('EXT_mesh_features');
      if (!ext) continue;
      const ids = ext.listFeatureIDs().map((f) => ({
        featureCount: f.getFeatureCount(), attribute: f.getAttribute(), label: f.getLabel(),
      }));
      const hist = {};
      for (const v of prim.getAttribute('_FEATURE_ID_0').getArray()) hist[v] = (hist[v] ?? 0) + 1;
      result.push({ mesh: mesh.getName(), featureIds: ids, histogram: hist });
    }
  }
  out(result);
}

async function recast() {
  const require = createRequire(import.meta.url);
  const { init, NavMeshQuery } = await import(pathToFileURL(require.resolve('recast-navigation')));
  const { generateSoloNavMesh } = await import(pathToFileURL(require.resolve('recast-navigation/generators')));
  // The navmesh node's triangles, straight from the glb (no transform: it sits at the root).
  const jsonLen = new DataView(bytes.buffer, bytes.byteOffset).getUint32(12, true);
  const doc = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLen)));
  const bin = bytes.subarray(20 + jsonLen + 8);
  const node = doc.nodes.find((n) => n.name === 'navmesh');
  const prim = doc.meshes[node.mesh].primitives[0];
  const read = (acc, Ctor, comps) => {
    const a = doc.accessors[acc];
    const v = doc.bufferViews[a.bufferView];
    const start = bin.byteOffset + (v.byteOffset ?? 0) + (a.byteOffset ?? 0);
    return new Ctor(bin.buffer.slice(start, start + a.count * comps * Ctor.BYTES_PER_ELEMENT));
  };
  const positions = read(prim.attributes.POSITION, Float32Array, 3);
  const indices = read(prim.indices, Uint32Array, 1);
  await init();
  // Recast re-voxelises the mesh: its cells must be finer than the mesh's own (a corridor one or
  // two mesh cells wide is lost at a voxel of half a cell), so take a quarter of the cell the
  // navmesh's extras give.
  const cs = node.extras.cell / 4, ch = 0.05;
  const { success, navMesh } = generateSoloNavMesh(positions, indices, {
    cs, ch, walkableRadius: 0, walkableHeight: Math.ceil(1.8 / ch), walkableClimb: Math.floor(0.3 / ch),
    walkableSlopeAngle: 45, maxEdgeLen: 12 / cs, maxSimplificationError: 1.3, minRegionArea: 8,
    mergeRegionArea: 20, maxVertsPerPoly: 6, detailSampleDist: 6, detailSampleMaxError: 1,
  });
  if (!success) { out({ success }); return; }
  const q = new NavMeshQuery(navMesh);
  const v = (a) => ({ x: a[0], y: a[1], z: a[2] });
  const queries = JSON.parse(readFileSync(extra, 'utf8'));
  const paths = queries.map(({ from, to }) => {
    const a = q.findClosestPoint(v(from));
    const b = q.findClosestPoint(v(to));
    const r = q.computePath(a.point, b.point);
    return {
      from_snapped: [a.point.x, a.point.y, a.point.z],
      to_snapped: [b.point.x, b.point.y, b.point.z],
      success: r.success,
      path: (r.path ?? []).map((p) => [p.x, p.y, p.z]),
    };
  });
  out({ success, paths });
}

if (kind === 'three') await three();
else if (kind === 'features') await features();
else if (kind === 'recast') await recast();
else { process.stderr.write(`unknown reader ${kind}\n`); process.exit(2); }
