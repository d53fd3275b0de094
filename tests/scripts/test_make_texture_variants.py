#!/usr/bin/env python3
"""scripts/make-texture-variants.py on a hand-built AC3D level with one 2x1 RLE SGI texture."""
import importlib.util
import os
import struct
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts",
                      "make-texture-variants.py")


def read(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def load_script():
    spec = importlib.util.spec_from_file_location("make_texture_variants", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def rle_sgi_2x1():
    """A 2x1 RGB image, RLE: red a run of two 200s, green the literal pair 10 20, blue a run of
    two 100s. One row per channel, each ended by a zero count byte."""
    rows = [bytes([0x02, 200, 0x00]), bytes([0x82, 10, 20, 0x00]), bytes([0x02, 100, 0x00])]
    header = struct.pack(">hBBHHHH", 474, 1, 1, 3, 2, 1, 3)
    header += b"\0" * (512 - len(header))
    tables = 512 + 2 * 4 * 3
    starts, at = [], tables
    for row in rows:
        starts.append(at)
        at += len(row)
    return (header + struct.pack(">3I", *starts) + struct.pack(">3I", *[len(r) for r in rows]) +
            b"".join(rows))


def level(objects):
    """An AC3D world of `objects` one-triangle objects, each with a base texture (the SGI file)
    and a second texture line (a PNG) that must stay as it is."""
    out = ["AC3Db", 'MATERIAL "" rgb 1 1 1 amb 1 1 1 emis 0 0 0 spec 0 0 0 shi 0 trans 0',
           "OBJECT world", f"kids {objects}"]
    for i in range(objects):
        out += ["OBJECT poly", f'name "o{i}"', 'texture "grass.rgb" base',
                'texture "line.png" tiled', "numvert 3", "0 0 0", "1 0 0", "0 0 1",
                "numsurf 1", "SURF 0x10", "mat 0", "refs 3", "0 0 0", "1 1 0", "2 0 1",
                "kids 0"]
    return "\n".join(out) + "\n"


class MakeTextureVariants(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.src = os.path.join(self.tmp.name, "src")
        os.makedirs(self.src)
        with open(os.path.join(self.src, "grass.rgb"), "wb") as f:
            f.write(rle_sgi_2x1())
        with open(os.path.join(self.src, "line.png"), "wb") as f:
            f.write(b"not read by the script")
        with open(os.path.join(self.src, "level.ac"), "w") as f:
            f.write(level(40))

    def tearDown(self):
        self.tmp.cleanup()

    def run_script(self, out_dir, variants=5):
        out = os.path.join(self.tmp.name, out_dir, "level.ac")
        subprocess.run([sys.executable, SCRIPT, os.path.join(self.src, "level.ac"), out,
                        str(variants)], check=True, capture_output=True)
        return out

    def test_rle_image_decodes_to_its_runs_and_literals(self):
        xs, ys, zs, planes = load_script().read_sgi(os.path.join(self.src, "grass.rgb"))
        self.assertEqual((xs, ys, zs), (2, 1, 3))
        self.assertEqual([list(p) for p in planes], [[200, 200], [10, 20], [100, 100]])

    def test_each_variant_scales_one_colour_channel(self):
        out = self.run_script("a")
        read_sgi = load_script().read_sgi
        # Variant j scales channel j mod 3 by 1 - 0.03 * ceil(j / 3), rounded to nearest:
        # j=1 green x0.97 (10 -> 9.7 -> 10, 20 -> 19.4 -> 19); j=2 blue x0.97 (100 -> 97);
        # j=3 red x0.97 (200 -> 194); j=4 green x0.94 (10 -> 9.4 -> 9, 20 -> 18.8 -> 19).
        expected = {1: [[200, 200], [10, 19], [100, 100]],
                    2: [[200, 200], [10, 20], [97, 97]],
                    3: [[194, 194], [10, 20], [100, 100]],
                    4: [[200, 200], [9, 19], [100, 100]]}
        for j, planes in expected.items():
            path = os.path.join(os.path.dirname(out), f"grass-v{j}.rgb")
            self.assertEqual([list(p) for p in read_sgi(path)[3]], planes, f"variant {j}")

    def test_only_the_base_texture_line_is_renamed(self):
        out = self.run_script("a")
        lines = read(out).splitlines()
        base = [l for l in lines if l.endswith('" base')]
        tiled = [l for l in lines if l.endswith('" tiled')]
        self.assertEqual(len(base), 40)
        self.assertEqual(set(tiled), {'texture "line.png" tiled'})
        # 40 objects drawing from 5 variants (seed 1): every variant is used, the original too.
        names = {l.split('"')[1] for l in base}
        self.assertEqual(names, {"grass.rgb"} | {f"grass-v{j}.rgb" for j in range(1, 5)})
        self.assertTrue(os.path.isfile(os.path.join(os.path.dirname(out), "grass.rgb")))
        self.assertFalse(os.path.islink(os.path.join(os.path.dirname(out), "grass.rgb")))

    def test_output_is_a_function_of_the_inputs(self):
        a, b = self.run_script("a"), self.run_script("b")
        self.assertEqual(read(a, "rb"), read(b, "rb"))
        for j in range(1, 5):
            name = f"grass-v{j}.rgb"
            self.assertEqual(read(os.path.join(os.path.dirname(a), name), "rb"),
                             read(os.path.join(os.path.dirname(b), name), "rb"))


if __name__ == "__main__":
    unittest.main()
