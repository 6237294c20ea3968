"""triunsuitable=: a Python callable and a shared object's triunsuitable(),
each grading a mesh, checked by the areas of its triangles."""
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import gpdr
from conftest import centroids, triangle_areas, write_poly

SQUARE = {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]],
          "segments": [[0, 1], [1, 2], [2, 3], [3, 0]]}

# The bound of the grading: fine on the left, coarse on the right.
GRADING_C = """
int triunsuitable(double *org, double *dest, double *apex, double area) {
    double x = (org[0] + dest[0] + apex[0]) / 3.0;
    return area > 0.0005 + 0.01 * x;
}
"""


def bound(x):
    return 0.0005 + 0.01 * x


def python_grading(org, dest, apex, area):
    x = (org[0] + dest[0] + apex[0]) / 3.0
    return area > bound(x)


def assert_graded(mesh):
    areas = triangle_areas(mesh)
    x = centroids(mesh)[:, 0]
    assert (areas > 0).all()
    assert (areas <= bound(x)).all()
    # Finer where the bound is smaller: many more triangles on the left.
    assert (x < 0.25).sum() > 3 * (x > 0.75).sum()


@pytest.fixture(scope="module")
def grading_so(tmp_path_factory):
    compiler = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc")
    if not compiler:
        pytest.skip("no C compiler to build the plug-in with")
    folder = tmp_path_factory.mktemp("plugin")
    source = folder / "grading.c"
    source.write_text(GRADING_C)
    library = folder / "grading.so"
    # No fused multiply-add, so that the C test computes exactly what Python does.
    subprocess.run([compiler, "-shared", "-fPIC", "-O2", "-ffp-contract=off", "-o",
                    str(library), str(source)], check=True)
    return library


def test_python_callable_grades_the_mesh():
    calls = []

    def test(org, dest, apex, area):
        calls.append((org, dest, apex, area))
        return python_grading(org, dest, apex, area)

    mesh = gpdr.triangulate(SQUARE, "pq", triunsuitable=test)
    assert_graded(mesh)
    assert len(mesh["triangles"]) > 400
    org, dest, apex, area = calls[0]
    assert isinstance(org, tuple) and len(org) == 2 and isinstance(area, float)
    # Counter-clockwise corners, and the area is theirs.
    twice = (dest[0] - org[0]) * (apex[1] - org[1]) - (dest[1] - org[1]) * (apex[0] - org[0])
    assert twice > 0 and abs(0.5 * twice - area) <= 1e-12 * area


def test_python_callable_sees_the_attributes():
    seen = set()

    def test(org, dest, apex, area):
        seen.add(len(org))
        return area > 0.1

    tri = dict(SQUARE, vertex_attributes=[[1.0], [2.0], [3.0], [4.0]])
    mesh = gpdr.triangulate(tri, "p", triunsuitable=test)
    assert seen == {3}
    assert (triangle_areas(mesh) <= 0.1).all()


def test_python_callable_refines_on_one_thread():
    """A Python test makes the same mesh whatever threads= says."""
    one = gpdr.triangulate(SQUARE, "pq", triunsuitable=python_grading)
    four = gpdr.triangulate(SQUARE, "pq", triunsuitable=python_grading, threads=4)
    assert np.array_equal(one["triangles"], four["triangles"])


def test_python_callable_exception_propagates():
    class Refused(Exception):
        pass

    def test(org, dest, apex, area):
        raise Refused("no")

    with pytest.raises(Refused, match="no"):
        gpdr.triangulate(SQUARE, "pq", triunsuitable=test)
    # The interpreter and the module go on.
    assert_graded(gpdr.triangulate(SQUARE, "pq", triunsuitable=python_grading))


@pytest.mark.parametrize("threads", [1, 2])
def test_shared_object_grades_the_mesh(grading_so, threads):
    mesh = gpdr.triangulate(SQUARE, "pq", triunsuitable=str(grading_so), threads=threads)
    assert_graded(mesh)
    # A path object and bytes name the same library.
    again = gpdr.triangulate(SQUARE, "pq", triunsuitable=pathlib.Path(grading_so),
                             threads=threads)
    assert np.array_equal(mesh["triangles"], again["triangles"])


def test_shared_object_as_the_program_loads_it(grading_so, program):
    path = os.path.join(program.folder, "square.poly")
    write_poly(path, {k: np.array(v) for k, v in SQUARE.items()})
    _, files = program.run("pq", path, threads=2, extra=("--unsuitable", str(grading_so)))
    mesh = gpdr.triangulate(SQUARE, "pq", triunsuitable=os.fsencode(grading_so), threads=2)
    for key in ("vertices", "triangles", "segments"):
        assert np.array_equal(mesh[key], files[key]), key


def test_shared_object_and_python_agree(grading_so):
    """The same rule in C and in Python, on one thread: the same mesh."""
    from_c = gpdr.triangulate(SQUARE, "pq", triunsuitable=grading_so)
    from_python = gpdr.triangulate(SQUARE, "pq", triunsuitable=python_grading)
    assert np.array_equal(from_c["vertices"], from_python["vertices"])
    assert np.array_equal(from_c["triangles"], from_python["triangles"])


def test_bad_shared_objects(tmp_path):
    with pytest.raises(gpdr.Error, match="cannot load it as a shared object"):
        gpdr.triangulate(SQUARE, "pq", triunsuitable=str(tmp_path / "missing.so"))
    with pytest.raises(gpdr.Error, match="has no function triunsuitable"):
        gpdr.triangulate(SQUARE, "pq", triunsuitable=gpdr._core.__file__)
    with pytest.raises(TypeError):
        gpdr.triangulate(SQUARE, "pq", triunsuitable=42)
    with pytest.raises(gpdr.Error, match="triunsuitable"):
        gpdr.triangulate(SQUARE, "pqu")
