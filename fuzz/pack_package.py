#!/usr/bin/env python3
"""Packs a package folder (hlod.json, tileset.json, tiles/*.glb) into one fuzz_package input:
sections "%%HLOD%% <relative path>\\n<bytes>". Usage: pack_package.py FOLDER OUTPUT"""
import os
import sys

folder, output = sys.argv[1], sys.argv[2]
with open(output, "wb") as out:
    for root, _, files in sorted(os.walk(folder)):
        for name in sorted(files):
            path = os.path.join(root, name)
            rel = os.path.relpath(path, folder).replace(os.sep, "/")
            out.write(b"%%HLOD%% " + rel.encode() + b"\n")
            with open(path, "rb") as f:
                out.write(f.read())
