#!/usr/bin/env python3
"""The picture gpdr writes with --svg: well-formed XML; for a small mesh one
<polygon> per triangle of the .ele file, at the .node file's coordinates, and
one <path> per segment of the .poly file; for a large mesh a density image
(a valid PNG: chunk CRCs, zlib checksum, size) under the size cap, with the
segments drawn; the same mesh always gives the same bytes.

    svg_test.py GPDR_EXE SOURCE_DIR
"""
import base64
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET
import zlib

from triangle_rows import triangle_rows

GPDR = None
SOURCE = None
SVG = "{http://www.w3.org/2000/svg}"
XLINK = "{http://www.w3.org/1999/xlink}"
# A picture of any mesh stays below this many bytes.
SIZE_CAP = 3 * 1024 * 1024


def run(folder, switches, sample):
    src = os.path.join(SOURCE, sample)
    shutil.copy(src, folder)
    name = os.path.basename(src)
    subprocess.run([GPDR, "-Q", *switches, "--svg", name], cwd=folder, check=True)
    return os.path.join(folder, os.path.splitext(name)[0] + ".1")


def png_chunks(png):
    """The chunks of a PNG, each checked against its CRC."""
    assert png[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, chunks = 8, []
    while at < len(png):
        (length,) = struct.unpack(">I", png[at : at + 4])
        kind = png[at + 4 : at + 8]
        data = png[at + 8 : at + 8 + length]
        (crc,) = struct.unpack(">I", png[at + 8 + length : at + 12 + length])
        assert zlib.crc32(kind + data) == crc, f"bad CRC in {kind}"
        chunks.append((kind, data))
        at += 12 + length
    return chunks


class Picture(unittest.TestCase):
    def test_small_mesh_has_a_shape_per_triangle_and_a_path_per_segment(self):
        for switches, sample in [
            (["-pcq30a0.05A"], "tests/data/box_hole.poly"),
            (["-pq25a1"], "tests/data/letter.poly"),
            (["-pq", "-o2"], "tests/data/face.poly"),
        ]:
            with self.subTest(sample=sample, switches=switches), tempfile.TemporaryDirectory() as d:
                stem = run(d, switches, sample)
                root = ET.parse(stem + ".svg").getroot()
                self.assertEqual(root.tag, SVG + "svg")
                node = triangle_rows(stem + ".node")
                ele = triangle_rows(stem + ".ele")
                poly = triangle_rows(stem + ".poly")
                base = int(node[1][0])
                xy = {int(r[0]) - base: (float(r[1]), float(r[2])) for r in node[1 : 1 + int(node[0][0])]}
                triangles = ele[1 : 1 + int(ele[0][0])]
                polygons = root.findall(f".//{SVG}g[@id='triangles']/{SVG}polygon")
                self.assertEqual(len(polygons), len(triangles))
                # The picture's frame: x' = m + (x - min x) s, y' = m + (max y - y) s.
                xs = [p[0] for p in xy.values()]
                ys = [p[1] for p in xy.values()]
                scale = 1000 / max(max(xs) - min(xs), max(ys) - min(ys))
                for polygon, t in zip(polygons, triangles):
                    self.assertRegex(polygon.get("fill"), r"^#[0-9a-f]{6}$")
                    points = [tuple(map(float, p.split(","))) for p in polygon.get("points").split()]
                    self.assertEqual(len(points), 3)
                    for (px, py), corner in zip(points, t[1:4]):
                        x, y = xy[int(corner) - base]
                        self.assertAlmostEqual(px, 12 + (x - min(xs)) * scale, delta=0.006)
                        self.assertAlmostEqual(py, 12 + (max(ys) - y) * scale, delta=0.006)
                paths = root.findall(f".//{SVG}g[@id='segments']/{SVG}path")
                self.assertEqual(len(paths), int(poly[1][0]))
                for path in paths:
                    self.assertRegex(path.get("d"), r"^M[-0-9.]+ [-0-9.]+L[-0-9.]+ [-0-9.]+$")
                legend = " ".join(t.text for t in root.iter(SVG + "text"))
                self.assertIn(f"{len(triangles)} triangles", legend)
                self.assertIn(f"{len(xy)} vertices", legend)
                self.assertRegex(legend, r"angles from [0-9.]+° to [0-9.]+°")

    def test_large_mesh_is_a_density_image_under_the_cap(self):
        with tempfile.TemporaryDirectory() as d:
            stem = run(d, ["-j1", "-pq20a2"], "poly-samples/pipe.poly")
            size = os.path.getsize(stem + ".svg")
            self.assertLess(size, SIZE_CAP)
            root = ET.parse(stem + ".svg").getroot()
            self.assertEqual(root.findall(f".//{SVG}polygon"), [])
            images = root.findall(f"{SVG}image")
            self.assertEqual(len(images), 1)
            href = images[0].get(XLINK + "href")
            prefix = "data:image/png;base64,"
            self.assertTrue(href.startswith(prefix))
            chunks = png_chunks(base64.b64decode(href[len(prefix) :], validate=True))
            kinds = [k for k, _ in chunks]
            self.assertEqual(kinds, [b"IHDR", b"PLTE", b"IDAT", b"IEND"])
            width, height, depth, colour = struct.unpack(">IIBB", chunks[0][1][:10])
            self.assertEqual((depth, colour), (8, 3))
            self.assertEqual(width, int(float(images[0].get("width"))))
            self.assertEqual(height, int(float(images[0].get("height"))))
            raw = zlib.decompress(chunks[2][1])  # checks the Adler-32 too
            self.assertEqual(len(raw), height * (width + 1))
            # Blank outside the pipe and in its holes, shaded inside.
            pixels = [raw[y * (width + 1) + 1 : (y + 1) * (width + 1)] for y in range(height)]
            self.assertEqual(pixels[0][0], 0)
            self.assertEqual(pixels[height // 2][width // 2], 0)  # the middle hole
            self.assertNotEqual(pixels[height // 2][width // 8], 0)
            # The segments: polylines, the pipe's circles among them.
            paths = root.findall(f".//{SVG}g[@id='segments']/{SVG}path")
            self.assertGreaterEqual(len(paths), 8)
            for path in paths:
                self.assertRegex(path.get("d"), r"^M[-0-9.]+ [-0-9.]+(L[-0-9.]+ [-0-9.]+)+$")

    def test_same_mesh_same_picture(self):
        pictures = []
        for switches in (["-j1", "-pc"], ["-j3", "-pc"], ["-j1", "-pc"]):
            with tempfile.TemporaryDirectory() as d:
                stem = run(d, switches, "poly-samples/flow.poly")
                with open(stem + ".svg", "rb") as f:
                    text = f.read()
                # The closing comment names the command, which differs.
                pictures.append(re.sub(rb"<!-- Generated by .* -->\n$", b"", text))
        self.assertEqual(pictures[0], pictures[1])
        self.assertEqual(pictures[0], pictures[2])
        # A density picture too, written on one thread and on three from
        # the same mesh (read back with -r, so that the mesh is the same).
        with tempfile.TemporaryDirectory() as d:
            stem = run(d, ["-j1", "-pq20a2"], "poly-samples/pipe.poly")
            large = []
            for threads in ("-j1", "-j3", "-j1"):
                subprocess.run([GPDR, "-Q", threads, "-rpNEP", "--svg", stem], cwd=d, check=True)
                with open(stem[:-2] + ".2.svg", "rb") as f:
                    large.append(re.sub(rb"<!-- Generated by .* -->\n$", b"", f.read()))
        self.assertIn(b"data:image/png;base64,", large[0])
        self.assertEqual(large[0], large[1])
        self.assertEqual(large[0], large[2])


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    GPDR = os.path.abspath(sys.argv[1])
    SOURCE = os.path.abspath(sys.argv[2])
    unittest.main(argv=sys.argv[:1], verbosity=2)
