#!/usr/bin/env python3
"""Independent check of the proxies' error bound in an HLOD Studio package.

Every proxy of a package built with `--compression none` must lie within its node's error budget
(hlod.json nodes[i].errorBudget, scene units) of the original triangles under that node. This
script checks that from the files alone, in plain Python (no code shared with the C++ pipeline):
it reads the source glTF/GLB, places every leaf's primitive by the source's node hierarchy, reads
each proxy tile's GLB, places it by the tile's matrix or translation, and measures the distance
of every proxy vertex, edge midpoint and triangle centroid to the nearest original triangle of
the node's leaves (a uniform grid narrows the candidates; the distance itself is exact).

Usage: scripts/check-proxy-bounds.py PACKAGE_DIR [SOURCE.glb] [--slack 1e-4]
Exit status 0 when every point is within budget·(1+slack) (float32 storage of positions), 1 when
some are not (they are listed, worst first), 2 on bad input. Only glTF/GLB sources with plain
(uncompressed) buffers are read.
"""

import json
import math
import os
import struct
import sys
from collections import defaultdict

COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
FORMATS = {5120: ("b", 127.0), 5121: ("B", 255.0), 5122: ("h", 32767.0), 5123: ("H", 65535.0),
           5125: ("I", None), 5126: ("f", None)}


def fail(path, problem):
    print(f"check-proxy-bounds: {path}: {problem}", file=sys.stderr)
    sys.exit(2)


def read_gltf(path):
    """The glTF JSON and its binary buffers (GLB chunk or external .bin files)."""
    try:
        data = open(path, "rb").read()
    except OSError as e:
        fail(path, e.strerror)
    if data[:4] == b"glTF":
        length = struct.unpack_from("<I", data, 12)[0]
        doc = json.loads(data[20:20 + length])
        rest = 20 + length
        binary = b""
        if rest + 8 <= len(data):
            blen = struct.unpack_from("<I", data, rest)[0]
            binary = data[rest + 8:rest + 8 + blen]
        buffers = []
        for b in doc.get("buffers", []):
            if "uri" in b:
                buffers.append(open(os.path.join(os.path.dirname(path), b["uri"]), "rb").read())
            else:
                buffers.append(binary)
        return doc, buffers
    try:
        doc = json.loads(data)
    except ValueError:
        fail(path, "neither GLB nor glTF JSON")
    buffers = [open(os.path.join(os.path.dirname(path), b["uri"]), "rb").read()
               for b in doc.get("buffers", [])]
    return doc, buffers


def accessor(doc, buffers, index, path):
    """The accessor's elements as tuples of floats (normalized integers mapped to [-1, 1])."""
    a = doc["accessors"][index]
    if "sparse" in a or "bufferView" not in a:
        fail(path, f"accessor {index} is sparse or has no buffer view (not supported)")
    view = doc["bufferViews"][a["bufferView"]]
    if "extensions" in view:
        fail(path, "compressed buffer views: build the package with --compression none")
    fmt, scale = FORMATS[a["componentType"]]
    n = COMPONENTS[a["type"]]
    size = struct.calcsize(fmt)
    stride = view.get("byteStride", size * n)
    base = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    buf = buffers[view["buffer"]]
    out = []
    for i in range(a["count"]):
        v = struct.unpack_from("<" + fmt * n, buf, base + i * stride)
        if a.get("normalized") and scale:
            v = tuple(max(x / scale, -1.0) for x in v)
        out.append(v)
    return out


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def local_matrix(node):
    if "matrix" in node:
        m = node["matrix"]
        return [[m[c * 4 + r] for c in range(4)] for r in range(4)]
    tx, ty, tz = node.get("translation", [0, 0, 0])
    x, y, z, w = node.get("rotation", [0, 0, 0, 1])
    sx, sy, sz = node.get("scale", [1, 1, 1])
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[0][0] * sx, r[0][1] * sy, r[0][2] * sz, tx],
            [r[1][0] * sx, r[1][1] * sy, r[1][2] * sz, ty],
            [r[2][0] * sx, r[2][1] * sy, r[2][2] * sz, tz],
            [0, 0, 0, 1]]


def transform(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3))


def world_matrices(doc):
    """Node index -> world matrix over the default scene."""
    out = {}
    identity = [[float(i == j) for j in range(4)] for i in range(4)]
    scene = doc.get("scenes", [{"nodes": []}])[doc.get("scene", 0)]
    stack = [(n, identity) for n in scene["nodes"]]
    while stack:
        n, parent = stack.pop()
        m = mat_mul(parent, local_matrix(doc["nodes"][n]))
        out[n] = m
        stack.extend((c, m) for c in doc["nodes"][n].get("children", []))
    return out


def primitive_triangles(doc, buffers, prim, matrix, path):
    if prim.get("mode", 4) != 4:
        return []
    pos = [transform(matrix, p) for p in accessor(doc, buffers, prim["attributes"]["POSITION"], path)]
    if "indices" in prim:
        idx = [i[0] for i in accessor(doc, buffers, prim["indices"], path)]
    else:
        idx = list(range(len(pos)))
    return [(pos[idx[i]], pos[idx[i + 1]], pos[idx[i + 2]]) for i in range(0, len(idx) - 2, 3)]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def point_segment_distance(p, a, b):
    ab, ap = sub(b, a), sub(p, a)
    length2 = dot(ab, ab)
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, dot(ap, ab) / length2))
    d = sub(p, lerp(a, b, t))
    return math.sqrt(dot(d, d))


def lerp(a, b, t):
    return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]))


def closest_on_triangle(p, a, b, c):
    """The point of triangle abc nearest p (Ericson, Real-Time Collision Detection, 5.1.5):
    a corner, a point on an edge, or the projection onto the face."""
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return a
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return b
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        return lerp(a, b, d1 / (d1 - d3))
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return c
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        return lerp(a, c, d2 / (d2 - d6))
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        return lerp(b, c, (d4 - d3) / ((d4 - d3) + (d5 - d6)))
    denom = 1.0 / (va + vb + vc)
    v, w = vb * denom, vc * denom
    return (a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w,
            a[2] + ab[2] * v + ac[2] * w)


def point_triangle_distance(p, a, b, c):
    """Exact Euclidean distance; a degenerate triangle is its edges."""
    ab, ac = sub(b, a), sub(c, a)
    n = (ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0])
    if dot(n, n) <= 1e-30 * max(dot(ab, ab), dot(ac, ac)) ** 2:
        return min(point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                   point_segment_distance(p, c, a))
    d = sub(p, closest_on_triangle(p, a, b, c))
    return math.sqrt(dot(d, d))


class Grid:
    """Triangles binned by their bounding boxes into cubes of side `cell`."""

    def __init__(self, triangles, cell):
        self.cell = cell
        self.triangles = triangles
        self.bins = defaultdict(list)
        for t, (a, b, c) in enumerate(triangles):
            lo = [math.floor(min(a[i], b[i], c[i]) / cell) for i in range(3)]
            hi = [math.floor(max(a[i], b[i], c[i]) / cell) for i in range(3)]
            for x in range(lo[0], hi[0] + 1):
                for y in range(lo[1], hi[1] + 1):
                    for z in range(lo[2], hi[2] + 1):
                        self.bins[(x, y, z)].append(t)

    def nearest_within(self, p, radius):
        """The least distance from p to a triangle, searched up to `radius` (inf past it)."""
        lo = [math.floor((p[i] - radius) / self.cell) for i in range(3)]
        hi = [math.floor((p[i] + radius) / self.cell) for i in range(3)]
        best = math.inf
        seen = set()
        for x in range(lo[0], hi[0] + 1):
            for y in range(lo[1], hi[1] + 1):
                for z in range(lo[2], hi[2] + 1):
                    for t in self.bins.get((x, y, z), ()):
                        if t in seen:
                            continue
                        seen.add(t)
                        d = point_triangle_distance(p, *self.triangles[t])
                        if d < best:
                            best = d
        return best


def leaves_under(nodes, i):
    stack, out = [i], []
    while stack:
        n = stack.pop()
        if nodes[n]["children"]:
            stack.extend(nodes[n]["children"])
        else:
            out.append(n)
    return out


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    slack = 1e-4
    if "--slack" in argv:
        slack = float(argv[argv.index("--slack") + 1])
        args.remove(argv[argv.index("--slack") + 1])
    if not args:
        print(__doc__, file=sys.stderr)
        return 2
    package = args[0]
    manifest_path = os.path.join(package, "hlod.json")
    try:
        manifest = json.load(open(manifest_path))
    except (OSError, ValueError) as e:
        fail(manifest_path, str(e))
    if manifest.get("compression") != "none":
        fail(manifest_path, "package is compressed: build it with --compression none")
    source = args[1] if len(args) > 1 else manifest["source"]["inputs"][0]
    if len(manifest["source"]["inputs"]) != 1 and len(args) < 2:
        fail(manifest_path, "several source files: this check reads one glTF/GLB source")
    doc, buffers = read_gltf(source)
    worlds = world_matrices(doc)
    mesh_by_name = {m.get("name", f"mesh{i}"): i for i, m in enumerate(doc.get("meshes", []))}
    node_by_name = {n.get("name", f"node{i}"): i for i, n in enumerate(doc["nodes"])}
    nodes = manifest["nodes"]

    leaf_cache = {}

    def leaf_triangles(leaf):
        if leaf in leaf_cache:
            return leaf_cache[leaf]
        entry = nodes[leaf]
        mesh_name = manifest["meshes"][entry["mesh"]]["name"]
        prim = "0"
        if "#" in mesh_name and mesh_name not in mesh_by_name:
            mesh_name, _, prim = mesh_name.rpartition("#")
        gnode = node_by_name.get(entry["name"])
        if gnode is None or mesh_name not in mesh_by_name or gnode not in worlds:
            fail(source, f"leaf {entry['name']} ({mesh_name}) not found in the source")
        primitive = doc["meshes"][mesh_by_name[mesh_name]]["primitives"][int(prim)]
        tris = primitive_triangles(doc, buffers, primitive, worlds[gnode], source)
        leaf_cache[leaf] = tris
        return tris

    checked, tiles, outside = 0, 0, []
    for tile in manifest["tiles"]:
        node = tile.get("node")
        if tile["file"] < 0 or node is None or not nodes[node]["children"]:
            continue
        glb = os.path.join(package, manifest["files"][tile["file"]])
        pdoc, pbuf = read_gltf(glb)
        # The tile's placement in the scene frame: a column-major matrix (copies turned and
        # moved) or a translation.
        if "matrix" in tile:
            c = tile["matrix"]
            placed = [[c[col * 4 + row] for col in range(4)] for row in range(4)]
        else:
            offset = tile.get("translation", [0, 0, 0])
            placed = [[1, 0, 0, offset[0]], [0, 1, 0, offset[1]], [0, 0, 1, offset[2]],
                      [0, 0, 0, 1]]
        proxy = []
        for gi, gnode in world_matrices(pdoc).items():
            n = pdoc["nodes"][gi]
            if "mesh" not in n or pdoc["meshes"][n["mesh"]].get("name") != "proxy":
                continue
            m = mat_mul(placed, gnode)
            for prim in pdoc["meshes"][n["mesh"]]["primitives"]:
                proxy.extend(primitive_triangles(pdoc, pbuf, prim, m, glb))
        if not proxy:
            continue
        tiles += 1
        budget = nodes[node]["errorBudget"]
        originals = [t for leaf in leaves_under(nodes, node) for t in leaf_triangles(leaf)]
        grid = Grid(originals, max(budget, 1e-9) * 2)
        points = set()
        for a, b, c in proxy:
            points.update((a, b, c))
            points.update(tuple((x + y) / 2 for x, y in zip(u, v)) for u, v in ((a, b), (b, c), (c, a)))
            points.add(tuple((a[i] + b[i] + c[i]) / 3 for i in range(3)))
        limit = budget * (1 + slack)
        for p in points:
            checked += 1
            d = grid.nearest_within(p, limit)
            if d > limit:
                far = grid.nearest_within(p, budget * 8)
                outside.append((far / budget, node, nodes[node].get("level"), p, budget))
    outside.sort(reverse=True)
    print(f"{checked} points of {tiles} proxy tiles checked; {len(outside)} outside their node's "
          "budget")
    for ratio, node, level, p, budget in outside[:20]:
        ratio_text = f"{ratio:.4f}x" if math.isfinite(ratio) else "> 8x"
        print(f"  node {node} (level {level}): {ratio_text} the budget {budget:g} at "
              f"({p[0]:.6g}, {p[1]:.6g}, {p[2]:.6g})")
    return 1 if outside else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
