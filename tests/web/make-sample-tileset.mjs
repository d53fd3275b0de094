#!/usr/bin/env node
// Writes a tiny, hand-made OGC 3D Tiles 1.1 package for self-testing validate-glb.mjs and
// render-tileset.mjs without the C++ exporter:
//
//   root      grey low-poly proxy box (the union of both children), refine REPLACE
//   ├─ a.glb  red box
//   └─ b.glb  blue box (taller)
//
// Tileset coordinates are Z-up (3D Tiles); glTF content is Y-up, and per the 3D Tiles spec the
// runtime rotates glTF content by +90° about X, so a tileset point (X, Y, Z) is written to the
// glTF as (X, Z, -Y). The root carries a translation transform so that the viewer's framing is
// exercised away from the origin.
//
// The GLB encoder is deliberately minimal: one mesh, one primitive, POSITION + NORMAL + uint16
// indices, one material with baseColorFactor. It follows the glTF 2.0 binary layout rules the
// Khronos validator checks: 4-byte aligned chunks and buffer views, JSON chunk padded with
// spaces, BIN chunk padded with zeros, min/max on POSITION, targets on buffer views.
//
// Usage: node make-sample-tileset.mjs OUTDIR

import fs from 'node:fs';
import path from 'node:path';

const GL_ARRAY_BUFFER = 34962;
const GL_ELEMENT_ARRAY_BUFFER = 34963;
const GL_FLOAT = 5126;
const GL_UNSIGNED_SHORT = 5123;

/** Axis-aligned box in tileset (Z-up) coordinates -> per-face vertices in glTF (Y-up). */
function boxMesh(min, max) {
  const toGltf = ([x, y, z]) => [x, z, -y];
  // Each face: outward normal and its four corners, counter-clockwise seen from outside.
  const [x0, y0, z0] = min;
  const [x1, y1, z1] = max;
  const faces = [
    { n: [1, 0, 0], c: [[x1, y0, z0], [x1, y1, z0], [x1, y1, z1], [x1, y0, z1]] },
    { n: [-1, 0, 0], c: [[x0, y1, z0], [x0, y0, z0], [x0, y0, z1], [x0, y1, z1]] },
    { n: [0, 1, 0], c: [[x1, y1, z0], [x0, y1, z0], [x0, y1, z1], [x1, y1, z1]] },
    { n: [0, -1, 0], c: [[x0, y0, z0], [x1, y0, z0], [x1, y0, z1], [x0, y0, z1]] },
    { n: [0, 0, 1], c: [[x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]] },
    { n: [0, 0, -1], c: [[x0, y1, z0], [x1, y1, z0], [x1, y0, z0], [x0, y0, z0]] },
  ];
  const positions = [];
  const normals = [];
  const indices = [];
  for (const f of faces) {
    const base = positions.length / 3;
    for (const corner of f.c) {
      positions.push(...toGltf(corner));
      normals.push(...toGltf(f.n));
    }
    indices.push(base, base + 1, base + 2, base, base + 2, base + 3);
  }
  return {
    positions: new Float32Array(positions),
    normals: new Float32Array(normals),
    indices: new Uint16Array(indices),
  };
}

const pad4 = (n) => (n + 3) & ~3;

/** Encodes one mesh with one material into a GLB (glTF 2.0 binary container). */
export function encodeGlb({ positions, normals, indices }, baseColorFactor, name) {
  // Buffer layout: [indices | pad][positions][normals]; every view starts 4-byte aligned.
  const idxBytes = indices.byteLength;
  const posOffset = pad4(idxBytes);
  const nrmOffset = posOffset + positions.byteLength;
  const binLength = nrmOffset + normals.byteLength;
  const bin = Buffer.alloc(pad4(binLength)); // zero padded
  Buffer.from(indices.buffer, indices.byteOffset, idxBytes).copy(bin, 0);
  Buffer.from(positions.buffer, positions.byteOffset, positions.byteLength).copy(bin, posOffset);
  Buffer.from(normals.buffer, normals.byteOffset, normals.byteLength).copy(bin, nrmOffset);

  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let k = 0; k < 3; ++k) {
      // Math.fround: min/max must equal the stored float32 values exactly.
      min[k] = Math.min(min[k], Math.fround(positions[i + k]));
      max[k] = Math.max(max[k], Math.fround(positions[i + k]));
    }
  }
  const vertexCount = positions.length / 3;
  const gltf = {
    asset: { version: '2.0', generator: 'HLOD Studio tests/web/make-sample-tileset.mjs' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0, name }],
    meshes: [
      {
        name,
        primitives: [{ attributes: { POSITION: 1, NORMAL: 2 }, indices: 0, material: 0, mode: 4 }],
      },
    ],
    materials: [
      {
        name: `${name}-material`,
        pbrMetallicRoughness: { baseColorFactor, metallicFactor: 0, roughnessFactor: 0.8 },
      },
    ],
    accessors: [
      { bufferView: 0, componentType: GL_UNSIGNED_SHORT, count: indices.length, type: 'SCALAR' },
      { bufferView: 1, componentType: GL_FLOAT, count: vertexCount, type: 'VEC3', min, max },
      { bufferView: 2, componentType: GL_FLOAT, count: vertexCount, type: 'VEC3' },
    ],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: idxBytes, target: GL_ELEMENT_ARRAY_BUFFER },
      { buffer: 0, byteOffset: posOffset, byteLength: positions.byteLength, target: GL_ARRAY_BUFFER },
      { buffer: 0, byteOffset: nrmOffset, byteLength: normals.byteLength, target: GL_ARRAY_BUFFER },
    ],
    buffers: [{ byteLength: bin.length }],
  };

  let jsonText = JSON.stringify(gltf);
  jsonText += ' '.repeat(pad4(Buffer.byteLength(jsonText)) - Buffer.byteLength(jsonText));
  const json = Buffer.from(jsonText, 'utf8');

  const header = Buffer.alloc(12);
  const total = 12 + 8 + json.length + 8 + bin.length;
  header.writeUInt32LE(0x46546c67, 0); // 'glTF'
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(total, 8);
  const jsonHeader = Buffer.alloc(8);
  jsonHeader.writeUInt32LE(json.length, 0);
  jsonHeader.writeUInt32LE(0x4e4f534a, 4); // 'JSON'
  const binHeader = Buffer.alloc(8);
  binHeader.writeUInt32LE(bin.length, 0);
  binHeader.writeUInt32LE(0x004e4942, 4); // 'BIN\0'
  return Buffer.concat([header, jsonHeader, json, binHeader, bin]);
}

/** 3D Tiles "box" bounding volume of an AABB: center followed by three half-axis vectors. */
function boxVolume(min, max) {
  const c = [0, 1, 2].map((k) => (min[k] + max[k]) / 2);
  const h = [0, 1, 2].map((k) => (max[k] - min[k]) / 2);
  return { box: [...c, h[0], 0, 0, 0, h[1], 0, 0, 0, h[2]] };
}

function main() {
  const outDir = process.argv[2];
  if (!outDir) {
    console.error('usage: node make-sample-tileset.mjs OUTDIR');
    process.exit(2);
  }
  fs.mkdirSync(outDir, { recursive: true });

  // Tileset (Z-up) extents in metres.
  const a = { min: [-6, -2, 0], max: [-1, 2, 4] };
  const b = { min: [1, -2, 0], max: [6, 2, 6] };
  const root = { min: [-6, -2, 0], max: [6, 2, 6] }; // proxy = union of the children

  const write = (file, box, color) =>
    fs.writeFileSync(path.join(outDir, file), encodeGlb(boxMesh(box.min, box.max), color, file));
  write('root.glb', root, [0.6, 0.6, 0.6, 1]);
  write('a.glb', a, [0.85, 0.15, 0.1, 1]);
  write('b.glb', b, [0.1, 0.3, 0.9, 1]);

  // geometricError: the proxy deviates from the children by up to 2 m (b is taller than a,
  // the gap between them is filled); leaves are exact (0). With the viewer's framing (~19 m
  // away, 45° field of view, 600 px high) the root's screen-space error is ~75 px > 16 px, so it
  // refines to the two children.
  const tileset = {
    asset: { version: '1.1', generator: 'HLOD Studio tests/web/make-sample-tileset.mjs' },
    geometricError: 4,
    root: {
      transform: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1000, -500, 20, 1],
      boundingVolume: boxVolume(root.min, root.max),
      geometricError: 2,
      refine: 'REPLACE',
      content: { uri: 'root.glb' },
      children: [
        { boundingVolume: boxVolume(a.min, a.max), geometricError: 0, content: { uri: 'a.glb' } },
        { boundingVolume: boxVolume(b.min, b.max), geometricError: 0, content: { uri: 'b.glb' } },
      ],
    },
  };
  fs.writeFileSync(path.join(outDir, 'tileset.json'), JSON.stringify(tileset, null, 2) + '\n');
  console.log(`wrote ${outDir}/tileset.json, root.glb, a.glb, b.glb`);
}

main();
