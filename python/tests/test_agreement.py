"""gpdr.triangulate against the gpdr program: for the same input and the
same switches, exactly the mesh the program writes, under every key of the
triangle package that the switches ask for, with its dtype."""
import os
import warnings

import numpy as np
import pytest

import gpdr
from conftest import random_pslg, write_poly

FLOAT_KEYS = {"vertices", "vertex_attributes", "triangle_attributes", "holes", "regions"}
INT_KEYS = {"vertex_markers", "triangles", "neighbors", "segments", "segment_markers", "edges",
            "edge_markers"}


def as_program_keys(mesh):
    """The module's keys as gpdr.load names the program's files' arrays."""
    return {("triangle_neighbors" if k == "neighbors" else k): v for k, v in mesh.items()}


def assert_same_mesh(mesh, files):
    for key, value in mesh.items():
        assert value.ndim == 2, key
        if key in FLOAT_KEYS:
            assert value.dtype == np.float64, key
        else:
            assert key in INT_KEYS, key
            assert value.dtype == np.int32, key
    mesh = as_program_keys(mesh)
    assert sorted(mesh) == sorted(files)
    for key in files:
        assert np.array_equal(mesh[key], files[key]), key


def triangulate_quietly(tri, switches, **extras):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", gpdr.MeshWarning)
        return gpdr.triangulate(tri, switches, **extras)


# (sample, switches): the classic inputs of tests/data/ and poly-samples/.
CLASSIC = [
    ("letter.poly", "pq30Aen"),
    ("letter.poly", "pa0.5o2"),
    ("face.poly", "pq"),
    ("face.poly", "pcDen"),
    ("box_hole.poly", "pcAa"),
    ("nested_hex.poly", "pqAa"),
    ("nested_hex2.poly", "pq25e"),
    ("nested_hex3.poly", "pqn"),
    ("circle_hole.poly", "pqB"),
    ("dots.node", "qen"),
    ("spiral.node", "q30"),
    ("spiral.node", "cBj"),
    ("pipe.poly", "pq"),
    ("flow.poly", "pq30a0.05Y"),
    ("points.node", "cqP"),
]


@pytest.mark.parametrize("sample, switches", CLASSIC)
def test_classic_inputs(program, sample, switches):
    path = program.copy_sample(sample)
    name = os.path.splitext(sample)[0]
    tri = gpdr.load(program.folder, name)
    _, files = program.run(switches, path)
    assert_same_mesh(triangulate_quietly(tri, switches), files)


@pytest.mark.parametrize("sample, switches", [("letter.poly", "pq32a0.05"),
                                              ("flow.poly", "pq30a0.02")])
def test_two_threads(program, sample, switches):
    """Two threads make the same mesh as the program's two threads."""
    path = program.copy_sample(sample)
    tri = gpdr.load(program.folder, os.path.splitext(sample)[0])
    _, files = program.run(switches, path, threads=2)
    assert_same_mesh(triangulate_quietly(tri, switches, threads=2), files)


def test_refining_a_mesh(program):
    """-r on a mesh the program wrote, with -p's segments and an .area file
    (triangle_max_area)."""
    program.copy_sample("letter.poly")
    first, _ = program.run("pq", "letter.poly")
    mesh = gpdr.load(program.folder, first)
    _, files = program.run("rpq30a0.1", first)
    assert_same_mesh(triangulate_quietly(mesh, "rpq30a0.1"), files)

    count = len(mesh["triangles"])
    bounds = np.where(np.arange(count) % 3 == 0, 0.02, -1.0)
    with open(os.path.join(program.folder, f"{first}.area"), "w") as f:
        f.write(f"{count}\n")
        for i, bound in enumerate(bounds):
            f.write(f"{i + 1} {bound!r}\n")
    _, files = program.run("ra", first)
    with_bounds = dict(mesh, triangle_max_area=bounds)
    assert_same_mesh(triangulate_quietly(with_bounds, "ra"), files)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("switches", ["pc", "pcq30a0.01en"])
def test_random_pslgs(program, seed, switches):
    tri = random_pslg(seed)
    path = os.path.join(program.folder, "random.poly")
    write_poly(path, tri)
    _, files = program.run(switches, path)
    assert_same_mesh(triangulate_quietly(tri, switches), files)
