"""Fixtures of the module's tests: the gpdr program to compare with, the
project's sample inputs, and random inputs.

CTest (python/tests/CMakeLists.txt) sets GPDR_EXE, GPDR_SOURCE_DIR, CC and
PYTHONPATH (the package assembled in the build tree).  Run by hand:

    GPDR_EXE=build-py/gpdr PYTHONPATH=build-py/python python3 -m pytest python/tests
"""
import os
import shutil
import subprocess

import numpy as np
import pytest

import gpdr

SOURCE_DIR = os.environ.get(
    "GPDR_SOURCE_DIR",
    os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))


def sample_path(name):
    """A sample input by file name, from poly-samples/ or tests/data/."""
    for folder in ("poly-samples", os.path.join("tests", "data")):
        path = os.path.join(SOURCE_DIR, folder, name)
        if os.path.exists(path):
            return path
    raise FileNotFoundError(name)


@pytest.fixture(scope="package")
def gpdr_exe():
    exe = os.environ.get("GPDR_EXE") or shutil.which("gpdr")
    if not exe or not os.path.exists(exe):
        pytest.skip("no gpdr program to compare with (set GPDR_EXE)")
    return os.path.abspath(exe)


class Program:
    """The gpdr program, run on files in a folder of its own."""

    def __init__(self, exe, folder):
        self.exe = exe
        self.folder = folder

    def copy_sample(self, name):
        """Copies a sample (and the .node a vertex-less .poly takes) here."""
        shutil.copy(sample_path(name), self.folder)
        stem, ext = os.path.splitext(name)
        if ext == ".poly":
            try:
                shutil.copy(sample_path(stem + ".node"), self.folder)
            except FileNotFoundError:
                pass
        return os.path.join(self.folder, name)

    def run(self, switches, input_file, threads=1, extra=()):
        """Runs `gpdr -Q<switches> --threads <threads> <extra> <input_file>`
        (one thread by default, as the module) and returns the name of the
        output files and their contents as one dictionary (gpdr.load)."""
        stem = os.path.basename(input_file)
        for ext in (".node", ".poly", ".ele", ".area"):
            if stem.endswith(ext):
                stem = stem[: -len(ext)]
                break
        parts = stem.rsplit(".", 1)
        if len(parts) == 2 and parts[1].isdigit():
            out = f"{parts[0]}.{int(parts[1]) + 1}"
        else:
            out = f"{stem}.1"
        # No file of an earlier run under the same name may pass for this one's.
        for ext in ("node", "ele", "poly", "edge", "neigh", "v.node", "v.edge"):
            path = os.path.join(self.folder, f"{out}.{ext}")
            if os.path.exists(path):
                os.remove(path)
        subprocess.run([self.exe, f"-Q{switches}", "--threads", str(threads), *extra, input_file],
                       cwd=self.folder, check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        return out, gpdr.load(self.folder, out)


@pytest.fixture
def program(gpdr_exe, tmp_path):
    return Program(gpdr_exe, str(tmp_path))


def write_node(path, vertices, attributes=None, markers=None):
    """A .node file holding exactly these doubles (repr round-trips)."""
    attributes = np.zeros((len(vertices), 0)) if attributes is None else attributes
    with open(path, "w") as f:
        f.write(f"{len(vertices)} 2 {attributes.shape[1]} {0 if markers is None else 1}\n")
        for i, (x, y) in enumerate(vertices):
            fields = [repr(float(x)), repr(float(y))] + [repr(float(a)) for a in attributes[i]]
            if markers is not None:
                fields.append(str(int(markers[i])))
            f.write(f"{i + 1} {' '.join(fields)}\n")


def write_poly(path, tri):
    """A .poly file of the dictionary `tri` (vertices, segments, holes)."""
    vertices = tri["vertices"]
    segments = tri.get("segments", np.zeros((0, 2), dtype=int))
    holes = tri.get("holes", np.zeros((0, 2)))
    with open(path, "w") as f:
        f.write(f"{len(vertices)} 2 0 0\n")
        for i, (x, y) in enumerate(vertices):
            f.write(f"{i + 1} {float(x)!r} {float(y)!r}\n")
        f.write(f"{len(segments)} 0\n")
        for i, (a, b) in enumerate(segments):
            f.write(f"{i + 1} {a + 1} {b + 1}\n")
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes):
            f.write(f"{i + 1} {float(x)!r} {float(y)!r}\n")


def random_pslg(seed, points=40, segments=12):
    """Random points in the unit square and random segments between them,
    crossing as they fall (gpdr splits them where they cross)."""
    rng = np.random.default_rng(seed)
    vertices = rng.random((points, 2))
    ends = []
    while len(ends) < segments:
        a, b = (int(v) for v in rng.integers(0, points, 2))
        if a != b:
            ends.append((a, b))
    return {"vertices": vertices, "segments": np.array(ends)}


def triangle_areas(mesh):
    """The area of each triangle of a mesh dictionary."""
    v = mesh["vertices"]
    a, b, c = (v[mesh["triangles"][:, k]] for k in range(3))
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1])
                  - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def centroids(mesh):
    v = mesh["vertices"]
    return v[mesh["triangles"][:, :3]].mean(axis=1)
