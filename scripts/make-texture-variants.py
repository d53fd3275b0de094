#!/usr/bin/env python3
"""Writes an AC3D level with more textures: every object's base texture becomes one of K variants.

Usage: scripts/make-texture-variants.py IN.ac|.acc OUT.ac|.acc K [--seed S]

Game levels carry many more textures than the shared TORCS track (a held-out TORCS track: 129
textures for 3,856 meshes; torcs-spring: 28), so a leaf group of the package holds more looks
and costs more draws (issue 27). This builds such a level from a real one, with the geometry
and the texture coordinates unchanged: each object's first `texture` line (its base colour,
Ac3dTextures.h) names variant j of its texture, j drawn per object from a seeded generator.
Variant 0 is the file itself (copied next to OUT: the importer reads no texture
that resolves outside the scene's folder, so a link would not do); variant j > 0 is an SGI image (uncompressed,
storage 0) whose red, green or blue channel (j mod 3) is scaled by 1 - 0.03 * ceil(j / 3), the
alpha left as it is, so cut-outs stay the same and every variant is a distinct image of nearly
the same colour. Only SGI (.rgb/.rgba/.sgi) textures get variants; other files stay shared.
The output is a function of the inputs and the seed. Format: SGI Image File Format
Specification (Haeberli, Silicon Graphics, version 1.0): 512-byte header, RLE rows through
start and length tables, or planes of rows when uncompressed.
"""
import argparse
import os
import random
import shutil
import struct
import sys


def read_sgi(path):
    with open(path, "rb") as f:
        data = f.read()
    magic, storage, bpc, _dim, xs, ys, zs = struct.unpack_from(">hBBHHHH", data, 0)
    if magic != 474 or bpc != 1:
        sys.exit(f"{path}: not an 8-bit SGI image")
    planes = []
    if storage == 0:
        for z in range(zs):
            start = 512 + z * xs * ys
            planes.append(bytearray(data[start : start + xs * ys]))
        return xs, ys, zs, planes
    starts = struct.unpack_from(f">{ys * zs}I", data, 512)
    for z in range(zs):
        plane = bytearray()
        for y in range(ys):
            at, row = starts[z * ys + y], bytearray()
            while len(row) < xs:
                count = data[at] & 0x7F
                literal = data[at] & 0x80
                at += 1
                if count == 0:
                    break
                if literal:
                    row += data[at : at + count]
                    at += count
                else:
                    row += bytes([data[at]]) * count
                    at += 1
            if len(row) != xs:
                sys.exit(f"{path}: RLE row {y} of channel {z} has {len(row)} pixels, not {xs}")
            plane += row
        planes.append(plane)
    return xs, ys, zs, planes


def write_sgi(path, xs, ys, zs, planes):
    header = struct.pack(">hBBHHHHII", 474, 0, 1, 3 if zs > 1 else 2, xs, ys, zs, 0, 255)
    header += b"\0" * (512 - len(header))
    with open(path, "wb") as out:
        out.write(header)
        for plane in planes:
            out.write(bytes(plane))


def variant(src, dst, j):
    xs, ys, zs, planes = read_sgi(src)
    channel = j % 3 if zs >= 3 else 0
    scale = 1.0 - 0.03 * ((j + 2) // 3)
    planes[channel] = bytearray(int(v * scale + 0.5) for v in planes[channel])
    write_sgi(dst, xs, ys, zs, planes)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("variants", type=int)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    if args.variants < 1:
        sys.exit("variants must be at least 1")
    rng = random.Random(args.seed)
    with open(args.input, encoding="latin-1") as f:
        lines = f.read().splitlines()
    if not lines or not lines[0].startswith("AC3D"):
        sys.exit(f"{args.input}: not an AC3D file")
    src_dir = os.path.dirname(os.path.abspath(args.input))
    dst_dir = os.path.dirname(os.path.abspath(args.output))
    os.makedirs(dst_dir, exist_ok=True)
    wanted, out, first = set(), [], False
    for line in lines:
        if line.startswith("OBJECT "):
            first = True
        elif line.startswith('texture "') and first:
            first = False
            name = line.split('"')[1]
            if name.lower().endswith((".rgb", ".rgba", ".sgi")) and \
                    os.path.exists(os.path.join(src_dir, name)):
                j = rng.randrange(args.variants)
                if j > 0:
                    stem, ext = os.path.splitext(name)
                    wanted.add((name, j))
                    line = line.replace(f'"{name}"', f'"{stem}-v{j}{ext}"', 1)
        out.append(line)
    with open(args.output, "w", encoding="latin-1") as f:
        f.write("\n".join(out) + "\n")
    if src_dir != dst_dir:
        for name in sorted(set(l.split('"')[1] for l in lines if l.startswith('texture "'))):
            src, dst = os.path.join(src_dir, name), os.path.join(dst_dir, name)
            if os.path.exists(src) and not os.path.lexists(dst):
                shutil.copyfile(src, dst)
    for name, j in sorted(wanted):
        stem, ext = os.path.splitext(name)
        variant(os.path.join(src_dir, name), os.path.join(dst_dir, f"{stem}-v{j}{ext}"), j)
    print(f"{args.output}: {len(wanted)} variant images written next to it")


if __name__ == "__main__":
    main()
