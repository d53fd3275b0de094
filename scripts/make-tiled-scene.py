#!/usr/bin/env python3
"""Writes a large instanced benchmark scene: N copies of a GLB's scene on a square grid.

Usage: scripts/make-tiled-scene.py IN.glb OUT.glb N [--gap FRACTION]

The copies share the source's meshes (glTF nodes referencing the same meshes), so the output
is an instanced plant: the meshes are stored once, the node tree N times, each copy under its
own translated root node. The grid spacing is the scene's largest horizontal extent times
(1 + gap), default gap 0.2. Used by the benchmarks (docs/benchmarks.md: "the engine tiled 100
times"); the generated file is not kept in the repository.
"""
import argparse
import copy
import json
import math
import struct
import sys


def read_glb(path):
    data = open(path, "rb").read()
    magic, version, length = struct.unpack_from("<III", data, 0)
    if magic != 0x46546C67 or version != 2:
        sys.exit(f"{path}: not a glTF 2.0 binary")
    offset, doc, blob = 12, None, b""
    while offset < length:
        chunk_len, chunk_type = struct.unpack_from("<II", data, offset)
        body = data[offset + 8 : offset + 8 + chunk_len]
        if chunk_type == 0x4E4F534A:
            doc = json.loads(body)
        elif chunk_type == 0x004E4942:
            blob = body
        offset += 8 + chunk_len
    return doc, blob


def write_glb(path, doc, blob):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * ((4 - len(text) % 4) % 4)
    blob += b"\0" * ((4 - len(blob) % 4) % 4)
    total = 12 + 8 + len(text) + (8 + len(blob) if blob else 0)
    with open(path, "wb") as out:
        out.write(struct.pack("<III", 0x46546C67, 2, total))
        out.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        if blob:
            out.write(struct.pack("<II", len(blob), 0x004E4942) + blob)


def matmul(a, b):  # column-major 4x4
    return [sum(a[r + 4 * k] * b[k + 4 * c] for k in range(4)) for c in range(4) for r in range(4)]


def local_matrix(node):
    if "matrix" in node:
        return list(node["matrix"])
    t = node.get("translation", [0, 0, 0])
    x, y, z, w = node.get("rotation", [0, 0, 0, 1])
    s = node.get("scale", [1, 1, 1])
    r = [1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w),
         2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
         2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)]
    return [r[0] * s[0], r[1] * s[0], r[2] * s[0], 0, r[3] * s[1], r[4] * s[1], r[5] * s[1], 0,
            r[6] * s[2], r[7] * s[2], r[8] * s[2], 0, t[0], t[1], t[2], 1]


def scene_bounds(doc):
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    ident = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
    stack = [(n, ident) for n in doc["scenes"][doc.get("scene", 0)]["nodes"]]
    while stack:
        idx, parent = stack.pop()
        node = doc["nodes"][idx]
        world = matmul(parent, local_matrix(node))
        for prim in doc["meshes"][node["mesh"]]["primitives"] if "mesh" in node else []:
            acc = doc["accessors"][prim["attributes"]["POSITION"]]
            for corner in range(8):
                p = [acc["max"][i] if corner >> i & 1 else acc["min"][i] for i in range(3)]
                for i in range(3):
                    v = sum(world[i + 4 * k] * p[k] for k in range(3)) + world[12 + i]
                    lo[i], hi[i] = min(lo[i], v), max(hi[i], v)
        stack.extend((c, world) for c in node.get("children", []))
    return lo, hi


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("copies", type=int)
    ap.add_argument("--gap", type=float, default=0.2)
    args = ap.parse_args()
    if args.copies < 1:
        sys.exit("copies must be at least 1")
    doc, blob = read_glb(args.input)
    lo, hi = scene_bounds(doc)
    step = max(hi[0] - lo[0], hi[2] - lo[2]) * (1.0 + args.gap)
    side = math.ceil(math.sqrt(args.copies))
    source_nodes = doc["nodes"]
    roots = doc["scenes"][doc.get("scene", 0)]["nodes"]
    nodes, new_roots = [], []
    for copy_index in range(args.copies):
        base = len(nodes)
        for node in source_nodes:
            clone = copy.deepcopy(node)
            clone.pop("camera", None)
            if "children" in clone:
                clone["children"] = [base + c for c in clone["children"]]
            if "name" in clone:
                clone["name"] = f"{clone['name']}#{copy_index}"
            nodes.append(clone)
        row, col = divmod(copy_index, side)
        nodes.append({"name": f"copy{copy_index}", "translation": [col * step, 0.0, row * step],
                      "children": [base + r for r in roots]})
        new_roots.append(len(nodes) - 1)
    doc["nodes"] = nodes
    doc["scenes"] = [{"nodes": new_roots}]
    doc["scene"] = 0
    doc.pop("cameras", None)
    write_glb(args.output, doc, blob)


if __name__ == "__main__":
    main()
