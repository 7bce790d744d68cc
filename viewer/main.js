// The `dreamscene view` page: the scene's splats drawn by Spark in three.js, in the project's
// world frame (z up, metres). Mouse orbits, pans and zooms (OrbitControls); W A S D Q E fly the
// camera and its orbit centre together. Everything is served by `dreamscene view` itself.
//
// Rendered-frame signal (for tests and scripts): `window.dreamscene.framesAfterLoad` counts the
// frames drawn since the splats finished loading, and `document.body.dataset.state` becomes
// "rendered" once FRAMES_FOR_SIGNAL of them are drawn and two of them with Spark's sort settled
// (it sorts splats in a worker: frames before its first result show nothing).
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { SparkRenderer, SplatMesh } from "@sparkjsdev/spark";

const FRAMES_FOR_SIGNAL = 8;
const state = { framesAfterLoad: 0, settledFrames: 0, signalled: false, loaded: false, error: null };
window.dreamscene = state;
const status = document.getElementById("status");

function fail(message) {
  state.error = String(message);
  document.body.dataset.state = "error";
  status.textContent = `error: ${message}`;
}

async function main() {
  const info = await (await fetch("/scene-info.json")).json();
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.setClearColor(new THREE.Color(...info.background), 1);
  document.body.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(
    info.camera.fov_y_deg, window.innerWidth / window.innerHeight, 0.05, 1000);
  camera.up.set(0, 0, 1);
  // Spark calls onDirty when a sort (or LoD update) finishes and the view needs drawing again.
  let pendingFrame = false;
  const spark = new SparkRenderer({ renderer, onDirty: () => { pendingFrame = true; } });
  scene.add(spark);

  const controls = new OrbitControls(camera, renderer.domElement);
  const reset = () => {
    camera.position.set(...info.camera.position);
    controls.target.set(...info.camera.target);
    controls.update();
  };
  reset();

  const bytes = new Uint8Array(await (await fetch("/scene.ply")).arrayBuffer());
  const splats = new SplatMesh({ fileBytes: bytes, fileType: "ply" });
  scene.add(splats);
  await splats.initialized;
  state.loaded = true;
  status.textContent = `${info.name}: ${info.gaussians} Gaussians`;

  const keys = new Set();
  window.addEventListener("keydown", (e) => {
    if (e.code === "KeyR") reset();
    keys.add(e.code);
  });
  window.addEventListener("keyup", (e) => keys.delete(e.code));
  window.addEventListener("resize", () => {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
  });

  let last = performance.now();
  const forward = new THREE.Vector3();
  const right = new THREE.Vector3();
  const up = new THREE.Vector3(0, 0, 1);
  // Draw on demand: for a second and at least FRAMES_FOR_SIGNAL frames after loading or any
  // camera change (Spark re-sorts in a worker and needs frames to show the new order), then idle,
  // so a slow CPU renderer leaves the page responsive.
  let changedAt = performance.now();
  let framesSinceChange = 0;
  const changed = () => {
    changedAt = performance.now();
    framesSinceChange = 0;
  };
  controls.addEventListener("change", changed);
  window.addEventListener("resize", changed);
  renderer.setAnimationLoop(() => {
    const now = performance.now();
    const step = info.fly_speed * Math.min((now - last) / 1000, 0.1);
    last = now;
    camera.getWorldDirection(forward);
    right.crossVectors(forward, up).normalize();
    const move = new THREE.Vector3();
    if (keys.has("KeyW")) move.add(forward);
    if (keys.has("KeyS")) move.sub(forward);
    if (keys.has("KeyD")) move.add(right);
    if (keys.has("KeyA")) move.sub(right);
    if (keys.has("KeyE")) move.add(up);
    if (keys.has("KeyQ")) move.sub(up);
    if (move.lengthSq() > 0) {
      move.normalize().multiplyScalar(step);
      camera.position.add(move);
      controls.target.add(move);
      changed();
    }
    controls.update();
    const idle = framesSinceChange >= FRAMES_FOR_SIGNAL && now - changedAt > 1000;
    if (idle && state.signalled && !pendingFrame) return;
    pendingFrame = false;
    framesSinceChange += 1;
    renderer.render(scene, camera);
    state.framesAfterLoad += 1;
    // Settled: Spark has splats in its sorted order for a recent view and no sort is pending.
    const settled = spark.activeSplats > 0 && spark.orderingTexture && !spark.sorting && !spark.sortDirty;
    if (settled) state.settledFrames += 1;
    if (!state.signalled && state.settledFrames >= 2 && state.framesAfterLoad >= FRAMES_FOR_SIGNAL) {
      state.signalled = true;
      document.body.dataset.state = "rendered";
    }
  });
}

main().catch((e) => fail(e && e.message ? e.message : e));
