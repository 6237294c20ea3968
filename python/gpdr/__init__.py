"""gpdr: Triangle's meshes for Python, from gpdr's parallel, exact mesher.

The functions of the ``triangle`` package, with the same arguments, keys,
dtypes and meanings, so that a script written for it runs with::

    import gpdr as triangle

plus gpdr's own keyword arguments (``threads``, ``placement``, ``check``,
``triunsuitable``, ``force``).  Errors are exceptions (:class:`Error`, a
``ValueError``, for bad input), warnings go through the :mod:`warnings`
module, and the GIL is released while meshing.  See docs/python.md.
"""

from ._core import CheckError, Error, MeshWarning, __version__
from ._core import run as _run
from ._data import get_data, get_data_names, load, loads

__all__ = [
    "triangulate",
    "delaunay",
    "convex_hull",
    "voronoi",
    "load",
    "loads",
    "get_data",
    "get_data_names",
    "Error",
    "CheckError",
    "MeshWarning",
    "__version__",
]


def triangulate(tri, opts="", *, threads=None, placement=None, check=False,
                triunsuitable=None, force=False):
    """Triangulates, and refines, the input dictionary `tri` as `opts` says.

    `tri` holds arrays (anything numpy reads as one) under the triangle
    package's keys: ``vertices`` (n x 2), and as the switches need them
    ``vertex_attributes``, ``vertex_markers``, ``segments``,
    ``segment_markers``, ``holes``, ``regions`` (x, y, attribute, area bound),
    ``triangles``, ``triangle_attributes``, ``triangle_max_area``.  Indices
    count from 0.

    `opts` holds Triangle's switches, read as Triangle's library reads them
    (``'pq30a0.1'``; no file names, no leading dash needed).  The result is
    a dictionary of numpy arrays with the same keys, plus ``neighbors`` (n),
    ``edges`` and ``edge_markers`` (e): float64 coordinates, int32 indices
    and markers, each array two-dimensional.

    gpdr's own keyword arguments:

    threads
        Threads to refine on (the switch ``jN``); default 1, 0 for every
        hardware thread.  A given number of threads makes the same mesh every
        time.
    placement
        Where Steiner points go: ``'circumcentre'``, ``'off-centre'``
        (Triangle's, the default) or ``'optimisation'``, or 0, 1, 2.
    check
        Check the mesh (the switch ``C``); raises :class:`CheckError`
        listing what is wrong, if anything is.
    triunsuitable
        Triangle's user test (implies the switch ``u``): a Python callable
        ``(org, dest, apex, area) -> bool``, each corner a tuple ``(x, y,
        *attributes)``, true to refine the triangle (called with the GIL held,
        so the call refines on one thread; an exception it raises stops the
        call and propagates); or the path of a shared object exporting
        ``int triunsuitable(double *org, double *dest, double *apex, double
        area)``, which runs without the GIL on every thread and must be
        thread-safe.
    force
        Refine even when the mesh the area bounds ask for is estimated to
        need more memory than the machine has (otherwise MemoryError).

    Raises :class:`Error` (a ValueError) with gpdr's message for bad input or
    switches, MemoryError, OverflowError if the mesh outgrows int32 indices,
    RuntimeError for an internal error of gpdr.
    """
    mesh, _ = _run(tri, opts, threads=threads, placement=placement, check=check,
                   triunsuitable=triunsuitable, force=force)
    return mesh


def delaunay(pts, **extras):
    """The Delaunay triangulation of the points `pts` (n x 2): its triangles,
    an m x 3 int32 array of indices into `pts`, counter-clockwise.

    Takes gpdr's keyword arguments as :func:`triangulate` does.
    """
    mesh, _ = _run({"vertices": pts}, "", **extras)
    return mesh["triangles"]


def convex_hull(pts, **extras):
    """The convex hull of the points `pts` (n x 2): its edges, an m x 2 int32
    array of indices into `pts`.

    Takes gpdr's keyword arguments as :func:`triangulate` does.
    """
    mesh, _ = _run({"vertices": pts}, "c", **extras)
    return mesh["segments"]


def voronoi(pts, **extras):
    """The Voronoi diagram of the points `pts` (n x 2), as four arrays:

    * the Voronoi vertices (m x 2 float64), the circumcentres of the Delaunay
      triangles;
    * the finite edges (k x 2 int32), pairs of Voronoi vertices;
    * the origins of the rays (int32, one per ray), Voronoi vertices;
    * the directions of the rays (float64, one row per ray), pointing outwards.

    Takes gpdr's keyword arguments as :func:`triangulate` does.
    """
    _, diagram = _run({"vertices": pts}, "v", **extras)
    edges = diagram["edges"]
    finite = edges[:, 1] != -1
    return (diagram["vertices"], edges[finite], edges[~finite][:, 0],
            diagram["normals"][~finite])
