"""delaunay, convex_hull and voronoi on random points, against the gpdr
program's .1.ele, -c hull (.1.poly) and .1.v.node / .1.v.edge."""
import os

import numpy as np
import pytest

import gpdr
from conftest import write_node


def random_points(seed, count=2000):
    return np.random.default_rng(seed).random((count, 2))


@pytest.mark.parametrize("seed", range(3))
def test_delaunay(program, seed):
    points = random_points(seed)
    write_node(os.path.join(program.folder, "points.node"), points)
    _, files = program.run("", "points.node")
    triangles = gpdr.delaunay(points)
    assert triangles.dtype == np.int32 and triangles.shape[1] == 3
    assert np.array_equal(triangles, files["triangles"])


@pytest.mark.parametrize("seed", range(3))
def test_convex_hull(program, seed):
    points = random_points(seed)
    write_node(os.path.join(program.folder, "points.node"), points)
    _, files = program.run("c", "points.node")
    hull = gpdr.convex_hull(points)
    assert hull.dtype == np.int32 and hull.shape[1] == 2
    assert np.array_equal(hull, files["segments"])
    # Every point is on the inner side of every hull edge (counter-clockwise).
    a, b = points[hull[:, 0]], points[hull[:, 1]]
    for p in points[::97]:
        cross = (b[:, 0] - a[:, 0]) * (p[1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (p[0] - a[:, 0])
        assert (cross >= 0).all() or (cross <= 0).all()


@pytest.mark.parametrize("seed", range(3))
def test_voronoi(program, seed):
    points = random_points(seed)
    write_node(os.path.join(program.folder, "points.node"), points)
    out, _ = program.run("v", "points.node")
    diagram = gpdr.load(program.folder, f"{out}.v")
    vertices, edges, ray_origins, ray_directions = gpdr.voronoi(points)
    assert vertices.dtype == np.float64 and vertices.shape[1] == 2
    assert edges.dtype == np.int32 and edges.shape[1] == 2
    assert ray_origins.dtype == np.int32 and ray_origins.ndim == 1
    assert ray_directions.dtype == np.float64 and ray_directions.shape == (len(ray_origins), 2)
    assert np.array_equal(vertices, diagram["vertices"])
    assert np.array_equal(edges, diagram["edges"])
    assert np.array_equal(ray_origins, diagram["ray_origins"][:, 0])
    assert np.array_equal(ray_directions, diagram["ray_directions"])
    # One Voronoi vertex per Delaunay triangle; one ray per hull edge.
    assert len(vertices) == len(gpdr.delaunay(points))
    assert len(ray_origins) == len(gpdr.convex_hull(points))


def test_the_triangle_packages_examples():
    """The examples of the triangle package's documentation, as sets (gpdr
    numbers triangles and hull edges in an order of its own)."""
    pts = [[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]]
    tri = gpdr.delaunay(pts)
    assert {frozenset(t) for t in tri.tolist()} == {
        frozenset(t) for t in [[1, 0, 2], [2, 4, 3], [4, 2, 0], [2, 3, 1]]}
    square = [[0, 0], [0, 1], [1, 1], [1, 0]]
    hull = gpdr.convex_hull(square)
    assert {frozenset(e) for e in hull.tolist()} == {
        frozenset(e) for e in [[3, 0], [2, 3], [1, 2], [0, 1]]}
    vertices, edges, ray_origins, ray_directions = gpdr.voronoi(pts)
    assert sorted(map(tuple, vertices.tolist())) == [(0.0, 0.5), (0.5, 0.0), (0.5, 1.0),
                                                     (1.0, 0.5)]
    assert len(edges) == 4 and len(ray_origins) == 4
    # Each ray leaves its vertex away from the centre of the square.
    for origin, direction in zip(ray_origins, ray_directions):
        assert np.dot(vertices[origin] - 0.5, direction) > 0
    t = gpdr.triangulate({"vertices": square}, "a0.2")
    assert t["vertices"].shape == (9, 2) and t["triangles"].shape == (8, 3)
    assert sorted(t["vertex_markers"][:, 0].tolist()) == [0] + [1] * 8
