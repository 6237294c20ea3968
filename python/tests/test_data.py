"""load, loads and get_data (the triangle package's readers) over gpdr's
samples, and a script written for the triangle package run with
`import gpdr as triangle`."""
import numpy as np
import pytest

import gpdr

NODE = """# a comment line
4 2 1 1
1  0 0  10  5   # trailing comment
2  1 0  20  5
3  1 1  30  0
4  0 1  40  0
"""

POLY = """0 2 1 1
4 1
1 1 2 7
2 2 3 7
3 3 4 7
4 4 1 7
1
1 0.5 0.5
2
1 0.25 0.25 3 0.01
2 0.75 0.75 0.5
"""

ELE = """2 3 1
1 1 2 3 1.5
2 1 3 4 2.5
"""

AREA = """2
1 0.1
2
"""

NEIGH = """2 3
1 -1 2 -1
2 -1 -1 1
"""

VEDGE = """3 0
1 1 2
2 1 -1 0.5 -1
3 2 -1 -1 0.5
"""


def test_loads_every_file():
    data = gpdr.loads(node=NODE, poly=POLY, ele=ELE, area=AREA, neigh=NEIGH)
    assert data["vertices"].tolist() == [[0, 0], [1, 0], [1, 1], [0, 1]]
    assert data["vertex_attributes"].tolist() == [[10], [20], [30], [40]]
    assert data["vertex_markers"].tolist() == [[5], [5], [0], [0]]
    assert data["segments"].tolist() == [[0, 1], [1, 2], [2, 3], [3, 0]]
    assert data["segment_markers"].tolist() == [[7]] * 4
    assert data["holes"].tolist() == [[0.5, 0.5]]
    # One value after x y: both the attribute and the area bound, as Triangle reads it.
    assert data["regions"].tolist() == [[0.25, 0.25, 3, 0.01], [0.75, 0.75, 0.5, 0.5]]
    assert data["triangles"].tolist() == [[0, 1, 2], [0, 2, 3]]
    assert data["triangle_attributes"].tolist() == [[1.5], [2.5]]
    assert data["triangle_max_area"].tolist() == [[0.1], [-1]]
    assert data["triangle_neighbors"].tolist() == [[-1, 1, -1], [-1, -1, 0]]
    for key, value in data.items():
        assert value.ndim == 2, key
        assert value.dtype in (np.float64, np.intc), key


def test_loads_a_voronoi_edge_file():
    data = gpdr.loads(edge=VEDGE)
    assert data["edges"].tolist() == [[0, 1]]
    assert data["ray_origins"].tolist() == [[0], [1]]
    assert data["ray_directions"].tolist() == [[0.5, -1], [-1, 0.5]]


def test_loads_reports_the_line():
    with pytest.raises(gpdr.Error, match="node:3: 'x' is not a number"):
        gpdr.loads(node="2 2 0 0\n1 0 0\n2 x 1\n")
    with pytest.raises(gpdr.Error, match="ends before vertex 3 of 3"):
        gpdr.loads(node="3 2 0 0\n1 0 0\n2 1 1\n")


@pytest.mark.parametrize("name", gpdr.get_data_names())
@pytest.mark.filterwarnings("ignore::gpdr.MeshWarning")
def test_every_sample_meshes(name):
    data = gpdr.get_data(name)
    switches = "pcq" if "segments" in data else "q"
    mesh = gpdr.triangulate(data, switches)
    assert len(mesh["triangles"]) > 0


def test_the_samples():
    assert {"pipe", "flow", "points", "letter", "face", "dots", "spiral", "box_hole",
            "circle_hole", "nested_hex", "nested_hex2", "nested_hex3"} <= set(
                gpdr.get_data_names())
    # nested_hex3.poly has no vertices: they come from nested_hex3.node, numbered from 0.
    hexes = gpdr.get_data("nested_hex3")
    assert len(hexes["vertices"]) > 0 and hexes["segments"].min() == 0
    with pytest.raises(gpdr.Error, match="no sample named"):
        gpdr.get_data("A")


def test_a_script_for_the_triangle_package():
    """What a user of the triangle package writes, with gpdr in its place."""
    import gpdr as triangle

    letter = triangle.get_data("letter")
    mesh = triangle.triangulate(letter, "pq30")
    assert set(mesh) >= {"vertices", "vertex_markers", "triangles", "segments",
                         "segment_markers", "holes"}
    # A result goes back in, extra keys and all, to be refined.
    finer = triangle.triangulate(triangle.triangulate(mesh, "rpen"), "rpa0.05")
    assert len(finer["triangles"]) > 2 * len(mesh["triangles"])

    points = np.random.default_rng(7).random((100, 2))
    assert triangle.delaunay(points).shape[1] == 3
    assert triangle.convex_hull(points).shape[1] == 2
    vertices, edges, ray_origins, ray_directions = triangle.voronoi(points)
    assert len(ray_origins) == len(ray_directions) == len(triangle.convex_hull(points))
