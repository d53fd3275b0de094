// The shading of `hlod bench` (app/cli/bench/OffscreenRenderer.h) as three.js materials, so a
// frame of the runtime can be compared pixel for pixel with the bench's frame of the same
// camera. The runtime still decides everything else: which tiles, their geometry (decoded from
// EXT_meshopt_compression), transforms, textures and their filtering, alpha modes, culling.
//
// bench: colour in sRGB values times a headlight term, no gamma handling (VTK):
//   geometry:  c = (0.78, 0.78, 0.76)
//   textured:  c = sRGB(baseColorFactor x COLOR_0) x baseColorTexture (sRGB texels as stored);
//              alpha = factor.a x COLOR_0.a x texel.a, MASK discards alpha < alphaCutoff
//   lit = c x (0.15 + 0.85 max(0, n.z)), n the view-space normal turned towards the eye on
//   back faces (VTK's two-sided lighting with its light at the camera);
//   out = lit, plus in textured shading the emission added in linear terms with the bench's
//   gamma 2.2: (lit^2.2 + emissiveFactor x emissiveTexture^2.2)^(1/2.2) (VtkSurfaceLook.h).
// Here the texture is sampled as stored (NoColorSpace) and the result written as is (a
// ShaderMaterial gets no output colour-space conversion), exactly that product.
// Culling: the glTF material's side (three.js: back faces culled unless doubleSided), as an
// engine draws; `cullBackFaces` false draws both sides of everything (a bench that does not
// cull, see tests/web/README.md).

import * as THREE from 'three';

const vertexShader = /* glsl */ `
  uniform vec4 factor;
  varying vec3 vNormal;
  varying vec3 vViewPosition;
  varying vec2 vUv;
  varying vec4 vColor;
  float toSrgb(float c) {
    c = clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
  }
  void main() {
    vec4 lin = factor;
    #if defined( USE_COLOR_ALPHA )
      lin *= color;
    #elif defined( USE_COLOR )
      lin.rgb *= color;
    #endif
    // bench converts per vertex (VTK interpolates the vertex colours it is given).
    vColor = vec4(toSrgb(lin.r), toSrgb(lin.g), toSrgb(lin.b), lin.a);
    vUv = uv;
    vNormal = normalize(normalMatrix * normal);
    vec4 mv = modelViewMatrix * vec4(position, 1.0);
    vViewPosition = mv.xyz;
    gl_Position = projectionMatrix * mv;
  }
`;

const fragmentShader = /* glsl */ `
  uniform bool geometryShading;
  uniform bool hasMap;
  uniform bool hasNormal;
  uniform sampler2D map;
  uniform float alphaCutoff;
  uniform vec3 emissive;
  uniform bool hasEmissiveMap;
  uniform sampler2D emissiveMap;
  varying vec3 vNormal;
  varying vec3 vViewPosition;
  varying vec2 vUv;
  varying vec4 vColor;
  void main() {
    vec4 c = vec4(0.78, 0.78, 0.76, 1.0);
    if (!geometryShading) {
      c = vColor;
      if (hasMap) c *= texture2D(map, vUv);
      if (c.a < alphaCutoff) discard;
    }
    vec3 n = hasNormal ? normalize(vNormal)
                       : normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
    if (!gl_FrontFacing && hasNormal) n = -n;
    if (!hasNormal && n.z < 0.0) n = -n;
    vec3 lit = c.rgb * (0.15 + 0.85 * max(n.z, 0.0));
    if (!geometryShading && any(greaterThan(emissive, vec3(0.0)))) {
      vec3 e = emissive;
      if (hasEmissiveMap) e *= pow(texture2D(emissiveMap, vUv).rgb, vec3(2.2));
      lit = pow(pow(max(lit, vec3(0.0)), vec3(2.2)) + e, vec3(1.0 / 2.2));
    }
    gl_FragColor = vec4(lit, geometryShading ? 1.0 : c.a);
  }
`;

/** The bench-like material replacing a glTF `source` material (MeshStandardMaterial). */
export function benchMaterial(source, geometry, shading, cullBackFaces = true) {
  const geometryShading = shading === 'geometry';
  const map = !geometryShading && source.map ? source.map : null;
  const emissiveMap = !geometryShading && source.emissiveMap ? source.emissiveMap : null;
  for (const t of [map, emissiveMap]) {
    if (t && t.colorSpace !== THREE.NoColorSpace) {
      t.colorSpace = THREE.NoColorSpace; // texels as stored, as the bench multiplies them
      t.needsUpdate = true;
    }
  }
  const hasUv = geometry.hasAttribute('uv');
  const hasColor = geometry.hasAttribute('color');
  const c = source.color;
  const material = new THREE.ShaderMaterial({
    vertexShader,
    fragmentShader,
    uniforms: {
      factor: { value: new THREE.Vector4(c.r, c.g, c.b, source.opacity) },
      geometryShading: { value: geometryShading },
      hasMap: { value: map !== null && hasUv },
      emissive: { value: source.emissive ? source.emissive.clone().multiplyScalar(source.emissiveIntensity ?? 1) : new THREE.Color(0, 0, 0) },
      hasEmissiveMap: { value: emissiveMap !== null && hasUv },
      emissiveMap: { value: emissiveMap },
      hasNormal: { value: geometry.hasAttribute('normal') },
      map: { value: map },
      alphaCutoff: { value: !geometryShading && source.alphaTest > 0 ? source.alphaTest : 0.0 },
    },
    vertexColors: hasColor,
    transparent: !geometryShading && source.transparent,
    side: cullBackFaces ? source.side : THREE.DoubleSide,
  });
  return material;
}

/**
 * Gives every mesh under `root` the bench material of `shading`; the glTF materials are kept
 * on the meshes (userData) so the shading can be switched again.
 */
export function applyBenchShading(root, shading, cullBackFaces = true) {
  root.traverse((o) => {
    if (!o.isMesh) return;
    if (!o.userData.gltfMaterial) o.userData.gltfMaterial = o.material;
    const source = o.userData.gltfMaterial;
    if (Array.isArray(source)) {
      o.material = source.map((m) => benchMaterial(m, o.geometry, shading, cullBackFaces));
    } else {
      o.material = benchMaterial(source, o.geometry, shading, cullBackFaces);
    }
  });
}
