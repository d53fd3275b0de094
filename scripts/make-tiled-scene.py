#!/usr/bin/env python3
"""Writes a large benchmark scene: N copies of a scene (GLB or AC3D) on a square grid.

Usage: scripts/make-tiled-scene.py IN OUT N [--gap FRACTION] [--unique] [--turn] [--seed S]

IN and OUT are both .glb, or both AC3D (.ac/.acc). By default the copies share the source's
meshes (glTF nodes referencing the same meshes), so the output is an instanced plant: the
meshes are stored once, the node tree N times, each copy under its own translated root node.
The grid spacing is the scene's largest horizontal extent times (1 + gap), default gap 0.2.

--unique  every copy gets meshes of its own whose vertices are moved by a pseudo-random
          offset of at most 1e-5 of the scene's extent per axis, so no copy can be shared
          (a plant or level of unique parts at the size of the tiled one). glTF: only the
          POSITION accessors are duplicated (indices, normals, uvs stay shared).
--turn    every copy is also turned about the up axis (+Y) by a pseudo-random angle, as plants
          and levels place their parts (rigid copies that are not translations).
--seed    seed of the offsets and angles (default 1); the output is a function of the inputs.

AC3D input: the copies are groups with `loc` (and `rot` for --turn) under one world; the
textures the file names are linked next to OUT when OUT is in another folder.
Used by the benchmarks (docs/benchmarks.md: "the engine tiled 100 times"); the generated file
is not kept in the repository.
"""
import argparse
import copy
import json
import math
import os
import random
import re
import shutil
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


def turn_quaternion(angle):  # about +Y
    return [0.0, math.sin(angle / 2), 0.0, math.cos(angle / 2)]


def unique_positions(doc, blob, copy_index, extent, rng, cache):
    """New POSITION accessors for every mesh of one copy; returns the mesh index map."""
    mesh_map = {}
    for mi, mesh in enumerate(list(doc["meshes"][: cache["source_meshes"]])):
        clone = copy.deepcopy(mesh)
        for prim in clone["primitives"]:
            acc = doc["accessors"][prim["attributes"]["POSITION"]]
            if acc.get("componentType") != 5126 or acc.get("type") != "VEC3" or "sparse" in acc:
                sys.exit("--unique needs float VEC3 positions without sparse storage")
            view = doc["bufferViews"][acc["bufferView"]]
            stride = view.get("byteStride", 12)
            start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
            out = bytearray()
            lo, hi = [math.inf] * 3, [-math.inf] * 3
            for i in range(acc["count"]):
                p = list(struct.unpack_from("<3f", blob, start + i * stride))
                for k in range(3):
                    p[k] += (rng.random() * 2.0 - 1.0) * 1e-5 * extent
                q = struct.unpack("<3f", struct.pack("<3f", *p))
                for k in range(3):
                    lo[k], hi[k] = min(lo[k], q[k]), max(hi[k], q[k])
                out += struct.pack("<3f", *q)
            pad = (4 - len(cache["blob"]) % 4) % 4
            cache["blob"] += b"\0" * pad
            doc["bufferViews"].append({"buffer": 0, "byteOffset": len(cache["blob"]),
                                       "byteLength": len(out)})
            cache["blob"] += bytes(out)
            new_acc = {"bufferView": len(doc["bufferViews"]) - 1, "componentType": 5126,
                       "count": acc["count"], "type": "VEC3", "min": lo, "max": hi}
            doc["accessors"].append(new_acc)
            prim["attributes"] = dict(prim["attributes"])
            prim["attributes"]["POSITION"] = len(doc["accessors"]) - 1
        if "name" in clone:
            clone["name"] = f"{clone['name']}#{copy_index}"
        doc["meshes"].append(clone)
        mesh_map[mi] = len(doc["meshes"]) - 1
    return mesh_map


def tile_glb(args, rng):
    doc, blob = read_glb(args.input)
    lo, hi = scene_bounds(doc)
    extent = max(hi[i] - lo[i] for i in range(3))
    step = max(hi[0] - lo[0], hi[2] - lo[2]) * (1.0 + args.gap)
    if args.turn:  # a turned copy needs the room of its horizontal diagonal
        step = math.hypot(hi[0] - lo[0], hi[2] - lo[2]) * (1.0 + args.gap)
    centre = [(lo[0] + hi[0]) / 2, 0.0, (lo[2] + hi[2]) / 2]
    side = math.ceil(math.sqrt(args.copies))
    source_nodes = doc["nodes"]
    roots = doc["scenes"][doc.get("scene", 0)]["nodes"]
    cache = {"blob": bytearray(blob), "source_meshes": len(doc.get("meshes", []))}
    if args.unique and len(doc.get("buffers", [])) != 1:
        sys.exit("--unique needs a GLB with exactly one buffer")
    nodes, new_roots = [], []
    for copy_index in range(args.copies):
        mesh_map = unique_positions(doc, cache["blob"], copy_index, extent, rng, cache) \
            if args.unique else None
        base = len(nodes)
        for node in source_nodes:
            clone = copy.deepcopy(node)
            clone.pop("camera", None)
            if "children" in clone:
                clone["children"] = [base + c for c in clone["children"]]
            if "name" in clone:
                clone["name"] = f"{clone['name']}#{copy_index}"
            if mesh_map is not None and "mesh" in clone:
                clone["mesh"] = mesh_map[clone["mesh"]]
            nodes.append(clone)
        row, col = divmod(copy_index, side)
        at = [col * step, 0.0, row * step]
        children = [base + r for r in roots]
        if args.turn:
            # Turn about the copy's own centre: the grid cell stays the copy's.
            nodes.append({"name": f"centre{copy_index}",
                          "translation": [-centre[0], 0.0, -centre[2]], "children": children})
            children = [len(nodes) - 1]
            nodes.append({"name": f"turn{copy_index}",
                          "rotation": turn_quaternion(rng.random() * 2 * math.pi),
                          "children": children})
            children = [len(nodes) - 1]
            at = [at[0] + centre[0], 0.0, at[2] + centre[2]]
        nodes.append({"name": f"copy{copy_index}", "translation": at, "children": children})
        new_roots.append(len(nodes) - 1)
    doc["nodes"] = nodes
    doc["scenes"] = [{"nodes": new_roots}]
    doc["scene"] = 0
    doc.pop("cameras", None)
    blob = bytes(cache["blob"])
    if doc.get("buffers"):
        doc["buffers"][0]["byteLength"] = len(blob)
    write_glb(args.output, doc, blob)


NUMBER = re.compile(r"^-?[0-9.eE+-]+$")


def tile_ac3d(args, rng):
    lines = open(args.input, encoding="latin-1").read().splitlines()
    if not lines or not lines[0].startswith("AC3D"):
        sys.exit(f"{args.input}: not an AC3D file")
    world = next((i for i, l in enumerate(lines) if l.strip() == "OBJECT world"), None)
    if world is None or not lines[world + 1].startswith("kids "):
        sys.exit(f"{args.input}: expected 'OBJECT world' followed by 'kids N'")
    header, kids, body = lines[:world], int(lines[world + 1].split()[1]), lines[world + 2:]
    # Vertex lines (x y z [nx ny nz]) follow `numvert N`; bounds over them (objects' own `loc`
    # offsets are rare in tracks and ignored for the grid spacing, which only needs a size).
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    vertex_line = [False] * len(body)
    i = 0
    while i < len(body):
        if body[i].startswith("numvert "):
            n = int(body[i].split()[1])
            for j in range(i + 1, i + 1 + n):
                vertex_line[j] = True
                p = [float(x) for x in body[j].split()[:3]]
                for k in range(3):
                    lo[k], hi[k] = min(lo[k], p[k]), max(hi[k], p[k])
            i += n + 1
        else:
            i += 1
    if lo[0] == math.inf:
        sys.exit(f"{args.input}: no vertices")
    extent = max(hi[k] - lo[k] for k in range(3))
    step = max(hi[0] - lo[0], hi[2] - lo[2]) * (1.0 + args.gap)
    if args.turn:
        step = math.hypot(hi[0] - lo[0], hi[2] - lo[2]) * (1.0 + args.gap)
    centre = [(lo[0] + hi[0]) / 2, 0.0, (lo[2] + hi[2]) / 2]
    side = math.ceil(math.sqrt(args.copies))
    out = header + ["OBJECT world", f"kids {args.copies}"]
    for copy_index in range(args.copies):
        row, col = divmod(copy_index, side)
        at = [col * step, 0.0, row * step]
        out += ["OBJECT group", f'name "copy{copy_index}"']
        if args.turn:
            a = rng.random() * 2 * math.pi
            c, s = math.cos(a), math.sin(a)
            # AC3D rot is a row-major 3x3 applied to the kids; turn about the copy's centre.
            out.append(f"rot {c:.9f} 0 {-s:.9f} 0 1 0 {s:.9f} 0 {c:.9f}")
            rx = c * centre[0] - s * centre[2]
            rz = s * centre[0] + c * centre[2]
            at = [at[0] + centre[0] - rx, 0.0, at[2] + centre[2] - rz]
        out += [f"loc {at[0]:.6f} {at[1]:.6f} {at[2]:.6f}", f"kids {kids}"]
        for j, line in enumerate(body):
            if args.unique and vertex_line[j]:
                parts = line.split()
                p = [float(x) + (rng.random() * 2.0 - 1.0) * 1e-5 * extent for x in parts[:3]]
                line = " ".join([f"{v:.7f}" for v in p] + parts[3:])
            if line.startswith("name "):
                line = line.rstrip('"') + f'#{copy_index}"' if line.endswith('"') else line
            out.append(line)
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(args.output, "w", encoding="latin-1") as f:
        f.write("\n".join(out) + "\n")
    src_dir = os.path.dirname(os.path.abspath(args.input))
    dst_dir = os.path.dirname(os.path.abspath(args.output))
    if src_dir != dst_dir:
        for name in sorted(set(l.split('"')[1] for l in lines if l.startswith("texture \""))):
            src, dst = os.path.join(src_dir, name), os.path.join(dst_dir, name)
            if os.path.exists(src) and not os.path.lexists(dst):
                os.makedirs(os.path.dirname(dst), exist_ok=True)
                # A copy, not a link: importers refuse textures resolving outside the scene.
                shutil.copyfile(src, dst)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("copies", type=int)
    ap.add_argument("--gap", type=float, default=0.2)
    ap.add_argument("--unique", action="store_true")
    ap.add_argument("--turn", action="store_true")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    if args.copies < 1:
        sys.exit("copies must be at least 1")
    rng = random.Random(args.seed)
    ext_in = os.path.splitext(args.input)[1].lower()
    ext_out = os.path.splitext(args.output)[1].lower()
    if ext_in == ".glb" and ext_out == ".glb":
        tile_glb(args, rng)
    elif ext_in in (".ac", ".acc") and ext_out in (".ac", ".acc"):
        tile_ac3d(args, rng)
    else:
        sys.exit("IN and OUT must both be .glb or both be AC3D (.ac/.acc)")


if __name__ == "__main__":
    main()
