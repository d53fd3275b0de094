// Page side of render-tileset.mjs: loads /tiles/tileset.json with 3d-tiles-renderer's
// TilesRenderer (three.js), frames the tileset's bounding sphere, renders until loading has
// settled, then publishes a summary in window.__hlodResult for the driver to read.
//
// Query parameters: w, h (canvas size in CSS px = device px), errorTarget (px, default 16),
// timeoutMs (default 60000), settleMs (no loads pending for this long = settled, default 1000),
// bg (background colour as 6 hex digits, default 30343c), antialias (0 turns MSAA off),
// camera (JSON {eye, target, up, fovDeg, near, far} in the package's frame, the frame of its
// content and of `hlod bench`: Y up for scenes from glTF and AC3D; the view is then not framed
// automatically), shading (pbr: the glTF materials with two lights, the default; geometry or
// textured: the shading of `hlod bench`, bench-shading-three.js), cull (none: both sides of
// every surface in the bench shadings; default: as the glTF material says).
// window.__hlodShade(shading) switches the shading of everything loaded and renders once;
// window.__hlodView(camera) moves to another camera and resolves when its tiles are loaded.

import * as THREE from 'three';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';
import { TilesRenderer } from '3d-tiles-renderer';
import { GLTFExtensionsPlugin } from '3d-tiles-renderer/plugins';
import { applyBenchShading } from './bench-shading-three.js';

const params = new URLSearchParams(location.search);
const num = (name, fallback) => {
  const v = Number(params.get(name));
  return Number.isFinite(v) && v > 0 ? v : fallback;
};
const width = num('w', 800);
const height = num('h', 600);
const errorTarget = num('errorTarget', 16);
const timeoutMs = num('timeoutMs', 60000);
const settleMs = num('settleMs', 1000);
const background = parseInt(params.get('bg') || '30343c', 16);
const fixedCamera = params.get('camera') ? JSON.parse(params.get('camera')) : null;
let shading = params.get('shading') || 'pbr';
const cullBackFaces = params.get('cull') !== 'none';

const result = {
  done: false,
  timedOut: false,
  framed: false,
  tilesLoaded: 0, // tiles whose content (glTF) was parsed and added to the scene
  tilesFailed: 0, // load-error events: root tileset, external tilesets or tile content
  failures: [],
  sphere: null, // framed bounding sphere, world (Y-up) coordinates
  stats: null,
  elapsedMs: 0,
};
window.__hlodResult = result;

const renderer = new THREE.WebGLRenderer({
  antialias: params.get('antialias') !== '0',
  preserveDrawingBuffer: true,
});
renderer.setPixelRatio(1);
renderer.setSize(width, height);
renderer.setClearColor(background, 1);
document.body.appendChild(renderer.domElement);

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(45, width / height, 0.1, 1000);
scene.add(new THREE.AmbientLight(0xffffff, 0.8));
const sun = new THREE.DirectionalLight(0xffffff, 2.2);
scene.add(sun, sun.target);

const tiles = new TilesRenderer('/tiles/tileset.json');
tiles.errorTarget = errorTarget;
// Packages are compressed with EXT_meshopt_compression + KHR_mesh_quantization by default:
// three.js' GLTFLoader decodes them with meshoptimizer's decoder (WebAssembly).
tiles.registerPlugin(new GLTFExtensionsPlugin({ meshoptDecoder: MeshoptDecoder }));
// 3D Tiles are Z-up; three.js is Y-up. TilesRenderer already turns glTF (Y-up) content into the
// tileset's Z-up frame, so rotating the whole group makes the tileset's +Z the scene's +Y.
tiles.group.rotation.x = -Math.PI / 2;
scene.add(tiles.group);
tiles.setCamera(camera);
tiles.setResolutionFromRenderer(camera, renderer);

tiles.addEventListener('load-model', (e) => {
  result.tilesLoaded++;
  if (shading !== 'pbr') applyBenchShading(e.scene, shading, cullBackFaces);
});
tiles.addEventListener('load-error', (e) => {
  result.tilesFailed++;
  const message = e.error && e.error.message ? e.error.message : String(e.error);
  result.failures.push(`${e.url}: ${message}`);
  if (!e.tile) finish(); // the root tileset failed: nothing will ever load
});
tiles.addEventListener('load-root-tileset', () => (fixedCamera ? place(fixedCamera) : frame()));

// The camera of `view` (package frame: the tiles group's rotation takes the tileset's Z-up frame
// back to it, so scene and package coordinates agree).
function place(view) {
  camera.fov = view.fovDeg;
  camera.position.fromArray(view.eye);
  camera.up.fromArray(view.up);
  camera.lookAt(new THREE.Vector3().fromArray(view.target));
  const distance = camera.position.distanceTo(new THREE.Vector3().fromArray(view.target));
  camera.near = view.near || distance * 0.01;
  camera.far = view.far || distance * 100;
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld(true);
  const sphere = new THREE.Sphere();
  if (tiles.getBoundingSphere(sphere)) {
    tiles.group.updateMatrixWorld(true);
    sphere.applyMatrix4(tiles.group.matrixWorld);
    result.sphere = { center: sphere.center.toArray(), radius: sphere.radius };
  }
  result.framed = true;
  lastBusy = performance.now();
}

window.__hlodShade = (next) => {
  shading = next;
  if (next !== 'pbr') applyBenchShading(tiles.group, next, cullBackFaces);
  renderer.render(scene, camera);
  return new Promise((resolve) => requestAnimationFrame(() => resolve(true)));
};

// Places the camera so the tileset's bounding sphere fills the view: from the view an HLOD
// Studio package suggests (tileset.json extras.hlod.view, in the tileset frame, as the README
// shows), else looking at its centre from above at a diagonal (front-right, ~30° elevation);
// with a sun from over the viewer's shoulder.
function frame() {
  const sphere = new THREE.Sphere();
  if (!tiles.getBoundingSphere(sphere)) return;
  tiles.group.updateMatrixWorld(true);
  sphere.applyMatrix4(tiles.group.matrixWorld); // tileset frame -> scene (Y-up)
  const radius = Math.max(sphere.radius, 1e-3);
  const extras = tiles.rootTileset && tiles.rootTileset.extras;
  const view = extras && extras.hlod && extras.hlod.view;
  if (view) {
    const m = tiles.group.matrixWorld;
    const toWorld = (v) => new THREE.Vector3().fromArray(v).applyMatrix4(m);
    place({
      eye: toWorld(view.eye).toArray(),
      target: toWorld(view.target).toArray(),
      up: new THREE.Vector3().fromArray(view.up).transformDirection(m).toArray(),
      fovDeg: view.fovYDegrees,
      far: (toWorld(view.eye).distanceTo(sphere.center) + radius) * 2,
    });
    const d = camera.position.distanceTo(sphere.center);
    sun.position.copy(sphere.center).add(new THREE.Vector3(-0.4, 1.0, 0.7).multiplyScalar(d));
    sun.target.position.copy(sphere.center);
    sun.target.updateMatrixWorld(true);
    result.viewFromPackage = true;
    return;
  }

  const halfV = THREE.MathUtils.degToRad(camera.fov / 2);
  const halfH = Math.atan(Math.tan(halfV) * camera.aspect);
  const distance = (radius / Math.sin(Math.min(halfV, halfH))) * 1.05;
  const dir = new THREE.Vector3(0.8, 0.6, 1.0).normalize();
  camera.position.copy(sphere.center).addScaledVector(dir, distance);
  camera.near = Math.max((distance - radius) * 0.5, distance * 1e-4);
  camera.far = (distance + radius) * 2;
  camera.up.set(0, 1, 0);
  camera.lookAt(sphere.center);
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld(true);

  sun.position.copy(sphere.center).add(new THREE.Vector3(-0.4, 1.0, 0.7).multiplyScalar(distance));
  sun.target.position.copy(sphere.center);
  sun.target.updateMatrixWorld(true);

  result.framed = true;
  result.sphere = { center: sphere.center.toArray(), radius: sphere.radius };
  lastBusy = performance.now(); // loading has to settle for the framed camera
}

const start = performance.now();
let lastBusy = start;
let viewStart = start; // when the current view was set (its timeout counts from there)
let onSettled = null; // resolves window.__hlodView's promise

function busy() {
  const s = tiles.stats;
  return !result.framed || tiles.isLoading || s.queued > 0 || s.downloading > 0 || s.parsing > 0;
}

function finish() {
  if (result.done) return;
  renderer.render(scene, camera);
  const s = tiles.stats;
  result.stats = { queued: s.queued, downloading: s.downloading, parsing: s.parsing, loaded: s.loaded,
    failed: s.failed, visible: s.visible, active: s.active };
  result.elapsedMs = Math.round(performance.now() - start);
  result.done = true;
  if (onSettled) {
    const resolve = onSettled;
    onSettled = null;
    resolve(true);
  }
}

function tick() {
  if (result.done) return;
  camera.updateMatrixWorld();
  tiles.update();
  renderer.render(scene, camera);
  const now = performance.now();
  if (busy()) lastBusy = now;
  if (now - lastBusy >= settleMs) {
    finish();
    return;
  }
  if (now - viewStart >= timeoutMs) {
    result.timedOut = true;
    finish();
    return;
  }
  requestAnimationFrame(tick);
}
requestAnimationFrame(tick);

// Another camera (as the `camera` parameter): resolves once loading has settled for it.
window.__hlodView = (view) =>
  new Promise((resolve) => {
    place(view);
    result.done = false;
    viewStart = performance.now();
    lastBusy = viewStart;
    onSettled = resolve;
    requestAnimationFrame(tick);
  });
