"""Bad input raises gpdr.Error (a ValueError) with gpdr's message and the
interpreter goes on; warnings go through the warnings module; nothing is
printed unless the switches ask for V without Q."""
import math
import os
import subprocess
import sys
import textwrap
import warnings

import numpy as np
import pytest

import gpdr
from conftest import SOURCE_DIR

SQUARE = [[0, 0], [1, 0], [1, 1], [0, 1]]

BAD_INPUT = [
    ({"vertices": SQUARE, "segments": [[0, 1], [1, 4]]}, "p",
     "segment 1 refers to vertex 4, but the vertices are 0 to 3"),
    ({"vertices": SQUARE, "segments": [[0, -1]]}, "p",
     "segment 0 refers to vertex -1, but the vertices are 0 to 3"),
    ({"vertices": [[0, 0], [1, math.nan], [1, 1]]}, "",
     "vertex 1 has a coordinate that is not a finite number"),
    ({"vertices": [[0, 0], [1, 0], [1, np.inf]]}, "",
     "vertex 2 has a coordinate that is not a finite number"),
    ({"vertices": SQUARE}, "q70", "-q70: the minimum angle must be at least 0 and below 60"),
    ({"vertices": SQUARE}, "a0", "-a0: the maximum area must be greater than zero"),
    ({"vertices": SQUARE}, "qa.", "-a. in qa.: '.' is not a number"),
    ({"vertices": SQUARE}, "o3", "write -o2"),
    ({"vertices": SQUARE}, "w", "weighted"),
    ({"vertices": [[0, 0], [1, 1]]}, "", "at least three"),
    ({"vertices": [[0, 0], [1, 1], [2, 2]]}, "", "collinear"),
    ({"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}, "", "tri['vertices'] has 3 columns, not 2"),
    ({"vertices": [["a", "b"]]}, "", "tri['vertices'] is not an array of numbers"),
    ({"vertices": SQUARE, "vertex_markers": [1, 2]}, "",
     "tri['vertex_markers'] has 2 rows, but tri['vertices'] has 4"),
    ({"points": SQUARE}, "", "unknown key 'points'"),
]


@pytest.mark.parametrize("tri, switches, message", BAD_INPUT)
def test_bad_input_raises_with_the_message(tri, switches, message):
    with pytest.raises(gpdr.Error) as raised:
        gpdr.triangulate(tri, switches)
    assert message in str(raised.value)
    assert isinstance(raised.value, ValueError)


def test_the_interpreter_goes_on():
    """Every bad input in one interpreter, which then meshes and exits
    normally, having printed nothing."""
    script = textwrap.dedent("""
        import math, gpdr
        cases = [({"vertices": [[0, 0], [1, 0], [1, 1]], "segments": [[0, 5]]}, "p"),
                 ({"vertices": [[0, 0], [1, math.nan], [1, 1]]}, ""),
                 ({"vertices": [[0, 0], [1, 0], [1, 1]]}, "q99")]
        for tri, switches in cases:
            try:
                gpdr.triangulate(tri, switches)
            except gpdr.Error:
                pass
            else:
                raise SystemExit("no error")
        gpdr.triangulate({"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]}, "q")
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "" and done.stderr == ""


def test_memory_check_raises_memory_error():
    with pytest.raises(MemoryError, match="memory"):
        gpdr.triangulate({"vertices": SQUARE}, "qa1e-14")


def test_check_finds_nothing_in_a_good_mesh():
    mesh = gpdr.triangulate({"vertices": SQUARE}, "qa0.01", check=True)
    assert len(mesh["triangles"]) > 100
    assert issubclass(gpdr.CheckError, RuntimeError)


def test_warnings_go_to_the_warnings_module():
    with pytest.warns(gpdr.MeshWarning, match="duplicate vertex"):
        mesh = gpdr.triangulate({"vertices": SQUARE + [[1, 1]]})
    assert len(mesh["vertices"]) == 5 and len(mesh["triangles"]) == 2
    with warnings.catch_warnings():
        warnings.simplefilter("error", gpdr.MeshWarning)
        with pytest.raises(gpdr.MeshWarning):
            gpdr.triangulate({"vertices": SQUARE + [[1, 1]]})


def test_nothing_is_printed_unless_V_without_Q(capfd):
    gpdr.triangulate({"vertices": SQUARE}, "q")
    gpdr.triangulate({"vertices": SQUARE}, "qVQ")
    assert capfd.readouterr() == ("", "")
    gpdr.triangulate({"vertices": SQUARE}, "qV")
    printed = capfd.readouterr()
    assert "Mesh triangles: 2" in printed.out and printed.err == ""


def test_inputs_are_array_likes():
    base = gpdr.triangulate({"vertices": np.array(SQUARE, dtype=np.float64)}, "qa0.1")
    for vertices in (SQUARE, [tuple(p) for p in SQUARE], np.array(SQUARE, dtype=np.float32),
                     np.array(SQUARE, dtype=np.int64), np.asfortranarray(SQUARE, dtype=float)):
        mesh = gpdr.triangulate({"vertices": vertices}, "qa0.1")
        assert np.array_equal(mesh["triangles"], base["triangles"])


def test_results_are_numpy_arrays_over_gpdrs_buffers():
    mesh = gpdr.triangulate({"vertices": SQUARE}, "qa0.01en")
    for key, array in mesh.items():
        assert not array.flags.owndata, key
        assert type(array.base).__name__ == "PyCapsule", key
        assert array.flags.c_contiguous and array.flags.writeable, key
    # The buffers outlive the dictionary.
    triangles = mesh.pop("triangles")
    del mesh
    assert triangles.max() < 1000 and triangles.min() >= 0


def test_threads_and_placement_keywords():
    one = gpdr.triangulate({"vertices": SQUARE}, "qa0.001")
    again = gpdr.triangulate({"vertices": SQUARE}, "qa0.001", threads=1)
    assert np.array_equal(one["triangles"], again["triangles"])
    two = gpdr.triangulate({"vertices": SQUARE}, "qa0.001", threads=2)
    four = gpdr.triangulate({"vertices": SQUARE}, "qa0.001", threads=4)
    assert np.array_equal(two["triangles"], four["triangles"])
    for placement in ("circumcentre", "off-centre", "optimisation", 0, 1, 2):
        mesh = gpdr.triangulate({"vertices": SQUARE}, "qa0.001", placement=placement)
        assert len(mesh["triangles"]) > 500
    with pytest.raises(gpdr.Error):
        gpdr.triangulate({"vertices": SQUARE}, "q", placement="nowhere")
    with pytest.raises(gpdr.Error):
        gpdr.triangulate({"vertices": SQUARE}, "q", threads=-1)


def test_an_angle_out_of_reach_warns_and_check_raises():
    # The channel model at 38 degrees: refinement does not converge, so the
    # mesh is the best one found, with a warning naming the angle reached;
    # with check=True (or the switch C) the unmet bound is a CheckError.
    with open(os.path.join(SOURCE_DIR, "tests", "data", "models", "channel.poly")) as f:
        channel = gpdr.loads(poly=f.read())
    with pytest.warns(gpdr.MeshWarning, match=r"reached \d+(\.\d+)? degrees of 38"):
        mesh = gpdr.triangulate(channel, "pq38")
    assert len(mesh["triangles"]) > 0
    for opts, extras in (("pq38", {"check": True}), ("pq38C", {})):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", gpdr.MeshWarning)
            with pytest.raises(gpdr.CheckError) as failure:
                gpdr.triangulate(channel, opts, **extras)
        assert any("38 degrees was not met" in p for p in failure.value.problems)
