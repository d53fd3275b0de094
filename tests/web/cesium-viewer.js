// Page side of render-tileset.mjs --runtime cesium: loads /tiles/tileset.json with CesiumJS
// (Cesium3DTileset) in a scene without globe, sky, imagery, terrain or ion (no network), frames
// the tileset or takes a given camera, renders until the tiles the view needs are loaded, then
// publishes a summary in window.__hlodResult, like viewer.js.
//
// Query parameters (as viewer.js): w, h, errorTarget (maximumScreenSpaceError, px), timeoutMs,
// settleMs, bg (6 hex digits), camera (JSON {eye, target, up, fovDeg, near, far} in the
// package's frame: content frame, Y up), shading (pbr: CesiumJS's own lighting, the default;
// geometry or textured: the shading of `hlod bench` as a CustomShader), place (LON,LAT,H in
// degrees and metres: the package's local frame put on the globe there with
// Transforms.eastNorthUpToFixedFrame, as the README tells users; the camera goes with it), cull
// (none: Cesium3DTileset.backFaceCulling off; default: as the glTF material says).
// window.__hlodShade(shading) switches the shading and resolves after the frames it needs;
// window.__hlodView(camera) moves to another camera and resolves when its tiles are loaded.
//
// Frames: glTF content is Y up and CesiumJS turns it Z up (3D Tiles 5.3.4): package (x, y, z)
// is (x, -z, y) in the tileset frame, then the model matrix (identity: the Earth's centre, or
// the east-north-up frame of `place`).

const Cesium = window.Cesium;
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
const bg = params.get('bg') || '30343c';
const fixedCamera = params.get('camera') ? JSON.parse(params.get('camera')) : null;
const place = params.get('place') ? params.get('place').split(',').map(Number) : null;
let shading = params.get('shading') || 'pbr';

const result = {
  done: false,
  timedOut: false,
  framed: false,
  tilesLoaded: 0,
  tilesFailed: 0,
  failures: [],
  sphere: null,
  stats: null,
  elapsedMs: 0,
};
window.__hlodResult = result;

// The shading of `hlod bench` (bench-shading-three.js says what and why). CesiumJS hands the
// custom shader the linear base colour (factor x decoded texture x COLOR_0) and, unlit, writes
// linearToSrgb of what it returns: so the bench's sRGB product goes back through srgbToLinear.
// Emission (material.emissive: factor x decoded texture) is added as the bench adds it, with
// gamma 2.2; unlit, CesiumJS itself would ignore it. MASK is tested after this (handleAlpha),
// on material.alpha.
function benchShader(kind) {
  if (kind === 'pbr') return undefined;
  return new Cesium.CustomShader({
    lightingModel: Cesium.LightingModel.UNLIT,
    uniforms: { u_geometry: { type: Cesium.UniformType.BOOL, value: kind === 'geometry' } },
    fragmentShaderText: `
      void fragmentMain(FragmentInput fsInput, inout czm_modelMaterial material) {
        vec3 n = normalize(fsInput.attributes.normalEC);
        if (!gl_FrontFacing) n = -n;
        float light = 0.15 + 0.85 * max(n.z, 0.0);
        vec3 c = u_geometry ? vec3(0.78, 0.78, 0.76) : czm_linearToSrgb(material.diffuse);
        vec3 lit = c * light;
        if (!u_geometry && any(greaterThan(material.emissive, vec3(0.0)))) {
          lit = pow(pow(lit, vec3(2.2)) + material.emissive, vec3(1.0 / 2.2));
        }
        material.diffuse = czm_srgbToLinear(lit);
        material.emissive = vec3(0.0);
        if (u_geometry) material.alpha = 1.0;
      }`,
  });
}

const container = document.getElementById('view');
container.style.width = `${width}px`;
container.style.height = `${height}px`;
const widget = new Cesium.CesiumWidget(container, {
  globe: false,
  skyBox: false,
  skyAtmosphere: false,
  baseLayer: false,
  scene3DOnly: true,
  shadows: false,
  requestRenderMode: false,
  useBrowserRecommendedResolution: false,
  msaaSamples: 1,
  creditContainer: document.getElementById('credits'),
  contextOptions: { webgl: { alpha: false, antialias: false, preserveDrawingBuffer: true } },
});
widget.resolutionScale = 1;
const scene = widget.scene;
scene.backgroundColor = Cesium.Color.fromBytes(
  parseInt(bg.slice(0, 2), 16), parseInt(bg.slice(2, 4), 16), parseInt(bg.slice(4, 6), 16), 255);
scene.fog.enabled = false;
scene.highDynamicRange = false;
scene.postProcessStages.fxaa.enabled = false;
if (scene.sun) scene.sun.show = false;
if (scene.moon) scene.moon.show = false;
scene.screenSpaceCameraController.enableInputs = false;

const modelMatrix = place
  ? Cesium.Transforms.eastNorthUpToFixedFrame(Cesium.Cartesian3.fromDegrees(place[0], place[1], place[2] || 0))
  : Cesium.Matrix4.IDENTITY;
// Tileset frame -> world: the model matrix. `w` 1 for points, 0 for directions.
function toWorld(v, w) {
  const local = Cesium.Cartesian3.fromArray(v);
  return w
    ? Cesium.Matrix4.multiplyByPoint(modelMatrix, local, new Cesium.Cartesian3())
    : Cesium.Matrix4.multiplyByPointAsVector(modelMatrix, local, new Cesium.Cartesian3());
}

// Package frame (Y up) -> tileset frame (Z up): (x, -z, y).
const zUp = (v) => [v[0], -v[2], v[1]];

// `view` {eye, target, up, fovDeg, near?, far?} in the tileset frame.
function placeCamera(view) {
  const eye = toWorld(view.eye, 1);
  const target = toWorld(view.target, 1);
  const C3 = Cesium.Cartesian3;
  const direction = C3.normalize(C3.subtract(target, eye, new C3()), new C3());
  const right = C3.normalize(C3.cross(direction, toWorld(view.up, 0), new C3()), new C3());
  const up = C3.cross(right, direction, new C3());
  scene.camera.setView({ destination: eye, orientation: { direction, up } });
  const frustum = scene.camera.frustum;
  const aspect = width / height;
  const fovY = Cesium.Math.toRadians(view.fovDeg);
  frustum.aspectRatio = aspect;
  // PerspectiveFrustum.fov is the horizontal angle when the view is wider than high.
  frustum.fov = aspect > 1 ? 2 * Math.atan(Math.tan(fovY / 2) * aspect) : fovY;
  const distance = C3.distance(eye, target);
  frustum.near = view.near || distance * 0.01;
  frustum.far = view.far || distance * 100;
}

const start = performance.now();
let lastBusy = start;
let viewStart = start; // when the current view was set (its timeout counts from there)
let onSettled = null; // resolves window.__hlodView's promise
let tileset = null;

function finish() {
  if (result.done) return;
  const s = tileset && tileset._statistics;
  result.stats = s
    ? { selected: s.selected, visited: s.visited, contentReady: s.numberOfTilesWithContentReady,
        pending: s.numberOfPendingRequests, processing: s.numberOfTilesProcessing }
    : null;
  result.elapsedMs = Math.round(performance.now() - start);
  result.done = true;
  if (onSettled) {
    const resolve = onSettled;
    onSettled = null;
    resolve(true);
  }
}

async function main() {
  try {
    tileset = await Cesium.Cesium3DTileset.fromUrl('/tiles/tileset.json', {
      maximumScreenSpaceError: errorTarget,
      dynamicScreenSpaceError: false,
      foveatedScreenSpaceError: false,
      skipLevelOfDetail: false,
      cullRequestsWhileMoving: false,
      progressiveResolutionHeightFraction: 0,
      modelMatrix,
      backFaceCulling: params.get('cull') !== 'none',
      customShader: benchShader(shading),
    });
  } catch (err) {
    result.tilesFailed++;
    result.failures.push(`/tiles/tileset.json: ${err && err.message ? err.message : err}`);
    finish();
    return;
  }
  tileset.tileLoad.addEventListener(() => result.tilesLoaded++);
  tileset.tileFailed.addEventListener((e) => {
    result.tilesFailed++;
    result.failures.push(`${e.url}: ${e.message}`);
  });
  scene.primitives.add(tileset);
  const sphere = tileset.boundingSphere;
  result.sphere = { center: Cesium.Cartesian3.pack(sphere.center, []), radius: sphere.radius };
  const hlod = tileset.extras && tileset.extras.hlod;
  if (fixedCamera) {
    placeCamera({ ...fixedCamera, eye: zUp(fixedCamera.eye), target: zUp(fixedCamera.target), up: zUp(fixedCamera.up) });
  } else if (hlod && hlod.view) {
    // The view the package suggests (README, "Placing a package"), moved with the model matrix.
    placeCamera({ ...hlod.view, fovDeg: hlod.view.fovYDegrees });
    result.viewFromPackage = true;
  } else {
    scene.camera.viewBoundingSphere(sphere, new Cesium.HeadingPitchRange(0.6, -0.5, sphere.radius * 2.5));
    scene.camera.lookAtTransform(Cesium.Matrix4.IDENTITY);
  }
  result.framed = true;
  lastBusy = performance.now();
  scene.postRender.addEventListener(() => {
    if (result.done) return;
    const now = performance.now();
    if (!tileset.tilesLoaded) lastBusy = now;
    if (now - lastBusy >= settleMs) finish();
    else if (now - viewStart >= timeoutMs) {
      result.timedOut = true;
      finish();
    }
  });
}

// Another camera (package frame, as the `camera` parameter): resolves once its tiles are loaded.
window.__hlodView = (view) =>
  new Promise((resolve) => {
    placeCamera({ ...view, eye: zUp(view.eye), target: zUp(view.target), up: zUp(view.up) });
    result.done = false;
    viewStart = performance.now();
    lastBusy = viewStart;
    onSettled = resolve;
  });

window.__hlodShade = (next) => {
  shading = next;
  tileset.customShader = benchShader(next);
  // Models rebuild their draw commands for a new shader; wait until the tiles are loaded and a
  // few frames have been drawn with it.
  return new Promise((resolve) => {
    let frames = 0;
    const remove = scene.postRender.addEventListener(() => {
      if (tileset.tilesLoaded && ++frames >= 10) {
        remove();
        resolve(true);
      }
    });
  });
};

main();
