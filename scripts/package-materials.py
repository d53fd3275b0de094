#!/usr/bin/env python3
"""Counts the materials of a package's GLBs, leaf tiles and proxies apart, by what an engine
draws (issue 28): alpha mode against whether the base colour texture has texels of alpha < 0.5
(a cut-out), doubleSided, emissive factor and texture.

Based on the glTF 2.0 GLB layout (12-byte header, JSON chunk, BIN chunk) and the PNG
specification (chunks, zlib-compressed scanlines with the five row filters); standard library
only. Only the JSON and the images are read, so plain and meshopt-compressed packages read
alike. A JPEG has no alpha; a PNG without an alpha channel (colour types 0, 2, 3) counts as
opaque; a 16-bit or interlaced PNG with alpha (a source PNG copied as is may be one) counts as
"alpha unknown".

Usage: scripts/package-materials.py PACKAGE_DIR [--json]
Prints one "kind what: count" line per counter (kind is leaf or proxy), or with --json one
JSON object of the same counters. Used by tests/app/PackageE2ETest.cpp: on a source format
without alpha modes (AC3D, CAD) no leaf material with a cut-out texture may be OPAQUE.
"""
import collections
import json
import os
import struct
import sys
import zlib

PNG_SIGNATURE = b'\x89PNG\r\n\x1a\n'


def unfilter_row(f, line, prev, ch):
    """Undoes one PNG row filter (PNG spec 9.2) in place."""
    for x in range(len(line)):
        a = line[x - ch] if x >= ch else 0
        b = prev[x]
        c = prev[x - ch] if x >= ch else 0
        if f == 1:
            line[x] = (line[x] + a) & 255
        elif f == 2:
            line[x] = (line[x] + b) & 255
        elif f == 3:
            line[x] = (line[x] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255


def png_min_alpha(data):
    """The smallest alpha (0..255) of an image's texels; 255 without alpha; None if unknown."""
    if data[:8] != PNG_SIGNATURE:
        return 255  # JPEG: no alpha
    pos, idat, header = 8, b'', None
    while pos + 8 <= len(data):
        n, t = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if t == b'IHDR':
            header = struct.unpack('>IIBBBBB', body)
        elif t == b'IDAT':
            idat += body
        pos += 12 + n
    if header is None:
        return None
    w, h, depth, ctype, _, _, interlace = header
    if ctype not in (4, 6):
        return 255
    if depth != 8 or interlace:
        return None
    ch = 4 if ctype == 6 else 2
    raw, stride = zlib.decompress(idat), w * ch
    prev, i, lo = bytearray(stride), 0, 255
    for _ in range(h):
        line = bytearray(raw[i + 1:i + 1 + stride])
        unfilter_row(raw[i], line, prev, ch)
        i += 1 + stride
        lo = min(lo, min(line[ch - 1::ch]))
        prev = line
    return lo


def read_glb(path):
    """(JSON, BIN chunk bytes) of a GLB file."""
    with open(path, 'rb') as f:
        d = f.read()
    if d[:4] != b'glTF':
        sys.exit(f'{path}: not a GLB file')
    jl = struct.unpack('<I', d[12:16])[0]
    j = json.loads(d[20:20 + jl])
    return j, (d[20 + jl + 8:] if len(d) > 20 + jl else b'')


def count(package):
    tiles = os.path.join(package, 'tiles')
    if not os.path.isdir(tiles):
        sys.exit(f'{package}: no tiles/ folder (not an hlod package)')
    alpha_of_file = {}

    def min_alpha(glb_dir, j, binc, tex):
        img = j['images'][j['textures'][tex]['source']]
        if 'uri' in img:
            path = os.path.normpath(os.path.join(glb_dir, img['uri']))
            if path not in alpha_of_file:
                with open(path, 'rb') as f:
                    alpha_of_file[path] = png_min_alpha(f.read())
            return alpha_of_file[path]
        v = j['bufferViews'][img['bufferView']]
        o = v.get('byteOffset', 0)
        return png_min_alpha(binc[o:o + v['byteLength']])

    c = collections.Counter()
    for name in sorted(os.listdir(tiles)):
        if not name.endswith('.glb'):
            continue
        j, binc = read_glb(os.path.join(tiles, name))
        kind = 'proxy' if any(m.get('name') == 'proxy' for m in j.get('meshes', [])) else 'leaf'
        for m in j.get('materials', []):
            mode = m.get('alphaMode', 'OPAQUE')
            c[f'{kind} materials'] += 1
            c[f'{kind} {mode}'] += 1
            t = m.get('pbrMetallicRoughness', {}).get('baseColorTexture')
            if t is not None:
                lo = min_alpha(tiles, j, binc, t['index'])
                if lo is None:
                    c[f'{kind} textured, alpha unknown: {mode}'] += 1
                elif lo < 128:
                    c[f'{kind} textured with alpha<0.5: {mode}'] += 1
            if m.get('doubleSided'):
                c[f'{kind} doubleSided'] += 1
            if 'emissiveFactor' in m:
                c[f'{kind} emissive'] += 1
                if 'emissiveTexture' in m:
                    c[f'{kind} emissive textured'] += 1
    return c


def main():
    args = [a for a in sys.argv[1:] if a != '--json']
    if len(args) != 1:
        sys.exit(__doc__.split('\n\n')[2])
    c = count(args[0])
    if '--json' in sys.argv[1:]:
        print(json.dumps(dict(sorted(c.items())), indent=1))
    else:
        for k in sorted(c):
            print(f'{k}: {c[k]}')


if __name__ == '__main__':
    main()
