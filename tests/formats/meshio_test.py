#!/usr/bin/env python3
"""meshio (Debian's python3-meshio) reads the .vtu and .msh files gpdr writes
with --vtk and --gmsh, and what it reads is exactly the mesh of gpdr's own
.node, .ele and .poly files: the same points, triangles (three- and six-node),
vertex markers and attributes, region attributes and segments, whatever the
numbering base (-z) and with or without markers (-B).

    meshio_test.py GPDR_EXE SOURCE_DIR
"""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from triangle_rows import triangle_rows

try:
    import meshio
except ImportError:
    sys.exit("meshio_test: python3-meshio is not installed (scripts/setup.sh installs it)")

GPDR = None
SOURCE = None


def read_node(path):
    rows = triangle_rows(path)
    n, _, na, nm = (int(x) for x in rows[0])
    body = rows[1 : 1 + n]
    base = int(body[0][0]) if body else 1
    xy = np.array([[float(r[1]), float(r[2])] for r in body])
    attributes = np.array([[float(x) for x in r[3 : 3 + na]] for r in body]).reshape(n, na)
    markers = np.array([int(r[3 + na]) for r in body]) if nm else None
    return xy, attributes, markers, base


def read_ele(path, base):
    rows = triangle_rows(path)
    m, nc, na = (int(x) for x in rows[0])
    body = rows[1 : 1 + m]
    corners = np.array([[int(x) - base for x in r[1 : 1 + nc]] for r in body]).reshape(m, nc)
    attributes = np.array([[float(x) for x in r[1 + nc : 1 + nc + na]] for r in body]).reshape(m, na)
    return corners, attributes


def read_poly_segments(path, base):
    """The segments of an output .poly (its vertices are in the .node)."""
    rows = triangle_rows(path)
    count, has_markers = int(rows[1][0]), int(rows[1][1])
    body = rows[2 : 2 + count]
    ends = [(int(r[1]) - base, int(r[2]) - base) for r in body]
    markers = [int(r[3]) if has_markers else None for r in body]
    return ends, markers


def smallest_angles(xy, corners):
    p = [xy[corners[:, k]] for k in range(3)]
    angles = []
    for k in range(3):
        u = p[(k + 1) % 3] - p[k]
        v = p[(k + 2) % 3] - p[k]
        cross = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
        angles.append(np.degrees(np.arctan2(cross, (u * v).sum(axis=1))))
    return np.min(angles, axis=0)


def areas(xy, corners):
    a, b, c = (xy[corners[:, k]] for k in range(3))
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1]))


# Triangle's six-node order (the midpoint opposite each corner) -> VTK's and
# gmsh's (the midpoints of edges 01, 12, 20).
SIX_NODE_ORDER = [0, 1, 2, 5, 3, 4]


class Case:
    def __init__(self, sample, switches, stem):
        self.sample, self.switches, self.stem = sample, switches, stem

    def run(self, folder):
        name = os.path.basename(self.sample)
        # A .poly with no vertices of its own takes them from its .node.
        for path in (self.sample, os.path.splitext(self.sample)[0] + ".node"):
            if os.path.exists(path):
                with open(path, "rb") as src:
                    with open(os.path.join(folder, os.path.basename(path)), "wb") as dst:
                        dst.write(src.read())
        command = [GPDR, "-Q", *self.switches, "--vtk", "--gmsh", name]
        subprocess.run(command, cwd=folder, check=True)
        out = os.path.join(folder, self.stem)
        xy, vattr, vmarkers, base = read_node(out + ".node")
        corners, tattr = read_ele(out + ".ele", base)
        segments = None
        if os.path.exists(out + ".poly"):
            segments = read_poly_segments(out + ".poly", base)
        return out, xy, vattr, vmarkers, corners, tattr, segments


def data(name):
    return os.path.join(SOURCE, "tests", "data", name)


def samples(name):
    return os.path.join(SOURCE, "poly-samples", name)


# Markers, regions (-A), holes; vertex attributes; six-node triangles;
# numbering from zero; no markers; a point set with attributes.
def cases():
    return [
    Case(data("box_hole.poly"), ["-pcq30a0.05A"], "box_hole.1"),
    Case(data("letter.poly"), ["-pq25a1"], "letter.1"),
    Case(data("letter.poly"), ["-pq", "-o2", "-z"], "letter.1"),
    Case(data("nested_hex3.poly"), ["-pq28A"], "nested_hex3.1"),
    Case(data("box_hole.poly"), ["-pcqA", "-o2", "-B"], "box_hole.1"),
    Case(data("spiral.node"), ["-q"], "spiral.1"),
    Case(samples("pipe.poly"), ["-pq20a5"], "pipe.1"),
    ]


class MeshioReadsGpdr(unittest.TestCase):
    def check_point_data(self, mesh, vmarkers, vattr):
        """The vertex markers (absent with -B) and attributes, as the .node has them."""
        if vmarkers is not None:
            self.assertTrue(np.array_equal(mesh.point_data["boundary_marker"], vmarkers))
        else:
            self.assertNotIn("boundary_marker", mesh.point_data)
        for a in range(vattr.shape[1]):
            self.assertTrue(np.array_equal(mesh.point_data[f"attribute_{a}"], vattr[:, a]))

    def each_case(self, check):
        for case in cases():
            with self.subTest(sample=os.path.basename(case.sample), switches=case.switches):
                with tempfile.TemporaryDirectory() as folder:
                    check(case, *case.run(folder))

    def test_vtu(self):
        def check(case, out, xy, vattr, vmarkers, corners, tattr, segments):
            mesh = meshio.read(out + ".vtu")
            self.assertEqual(mesh.points.shape, (len(xy), 3))
            self.assertTrue(np.array_equal(mesh.points[:, :2], xy))
            self.assertTrue(np.all(mesh.points[:, 2] == 0))
            self.assertEqual(len(mesh.cells), 1)
            block = mesh.cells[0]
            six = corners.shape[1] == 6
            self.assertEqual(block.type, "triangle6" if six else "triangle")
            expected = corners[:, SIX_NODE_ORDER] if six else corners
            self.assertTrue(np.array_equal(block.data, expected))
            self.check_point_data(mesh, vmarkers, vattr)
            for a in range(tattr.shape[1]):
                self.assertTrue(
                    np.array_equal(mesh.cell_data[f"region_attribute_{a}"][0], tattr[:, a])
                )
            self.assertNotIn(f"region_attribute_{tattr.shape[1]}", mesh.cell_data)
            three = corners[:, :3]
            # Single precision: the nearest float to the double.
            self.assertEqual(mesh.cell_data["min_angle"][0].dtype, np.float32)
            np.testing.assert_allclose(
                mesh.cell_data["min_angle"][0], smallest_angles(xy, three), rtol=1e-6
            )
            np.testing.assert_allclose(mesh.cell_data["area"][0], areas(xy, three), rtol=1e-6)
            self.assertTrue(np.all(mesh.cell_data["area"][0] > 0))

        self.each_case(check)

    def test_msh(self):
        def check(case, out, xy, vattr, vmarkers, corners, tattr, segments):
            mesh = meshio.read(out + ".msh")
            self.assertTrue(np.array_equal(mesh.points[:, :2], xy))
            self.assertTrue(np.all(mesh.points[:, 2] == 0))
            six = corners.shape[1] == 6
            # Physical groups: tag -> name, by dimension.
            names = {(int(v[1]), int(v[0])): k for k, v in mesh.field_data.items()}
            # The triangles, each with the region it is in, as a set.
            found = []
            lines = []
            for k, block in enumerate(mesh.cells):
                physical = mesh.cell_data["gmsh:physical"][k]
                if block.type in ("triangle", "triangle6"):
                    self.assertEqual(block.type, "triangle6" if six else "triangle")
                    name = names[(2, int(physical[0]))]
                    for row in block.data:
                        found.append((tuple(int(x) for x in row), name))
                else:
                    self.assertEqual(block.type, "line3" if six else "line")
                    name = names[(1, int(physical[0]))]
                    for row in block.data:
                        if six:
                            # The midpoint node, last, is the segment's midpoint.
                            np.testing.assert_allclose(
                                xy[row[2]], (xy[row[0]] + xy[row[1]]) / 2, rtol=0, atol=1e-12
                            )
                        lines.append((tuple(sorted(int(x) for x in row[:2])), name))
            ordered = corners[:, SIX_NODE_ORDER] if six else corners
            if tattr.shape[1] > 0:
                expected = [(tuple(int(x) for x in r), f"region {a:g}") for r, a in zip(ordered, tattr[:, 0])]
                # gpdr writes the attribute as the shortest decimal that reads
                # back the same; for these samples that is Python's {:g}.
            else:
                expected = [(tuple(int(x) for x in r), "domain") for r in ordered]
            self.assertEqual(sorted(found), sorted(expected))
            if segments is not None:
                ends, markers = segments
                want = []
                for (a, b), mk in zip(ends, markers):
                    name = f"boundary marker {mk}" if mk is not None else "segments"
                    want.append((tuple(sorted((a, b))), name))
                self.assertEqual(sorted(lines), sorted(want))
            self.check_point_data(mesh, vmarkers, vattr)

        self.each_case(check)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    GPDR = os.path.abspath(sys.argv[1])
    SOURCE = os.path.abspath(sys.argv[2])
    unittest.main(argv=sys.argv[:1], verbosity=2)
