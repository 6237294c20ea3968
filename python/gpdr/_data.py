"""Triangle's files as the triangle package's dictionaries: loads, load and
get_data, over gpdr's own sample inputs (installed in the package's data
folder).

The files are read as Triangle reads them (docs/file-formats.md): one entry
per line, ``#`` comments, optional fields defaulting, indices in the
numbering the first vertex sets (0 or 1; 1 when no vertex says) and returned
counting from 0.  The keys and dtypes are the triangle package's: float64
coordinates, attributes and areas; int32 (``intc``) indices and markers;
every array two-dimensional.
"""

import os

import numpy as np

from ._core import Error

_DATA_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
_EXTENSIONS = ("node", "ele", "poly", "area", "edge", "neigh")


class _Lines:
    """The entry lines of one file: the fields of each line that holds any."""

    def __init__(self, text, name):
        self.name = name
        self.lines = []
        for number, line in enumerate(text.splitlines(), 1):
            fields = line.split("#", 1)[0].split()
            if fields:
                # A field may end with one comma ("50, 2, 0, 0"), as Triangle reads it.
                self.lines.append((number, [f[:-1] if f.endswith(",") else f for f in fields]))
        self.next_line = 0
        self.number = 0

    def more(self):
        return self.next_line < len(self.lines)

    def take(self, what):
        if not self.more():
            raise Error(f"{self.name}: the file ends before {what}")
        self.number, fields = self.lines[self.next_line]
        self.next_line += 1
        return fields

    def fail(self, reason):
        raise Error(f"{self.name}:{self.number}: {reason}")

    def real(self, fields, i, default=None):
        if i >= len(fields):
            if default is None:
                self.fail(f"field {i + 1} is missing")
            return default
        try:
            return float(fields[i])
        except ValueError:
            self.fail(f"'{fields[i]}' is not a number")

    def integer(self, fields, i, default=None):
        if i >= len(fields):
            if default is None:
                self.fail(f"field {i + 1} is missing")
            return default
        try:
            return int(fields[i])
        except ValueError:
            value = self.real(fields, i)
            if not value.is_integer():
                self.fail(f"'{fields[i]}' is not a whole number")
            return int(value)

    def header(self, what, defaults):
        fields = self.take(f"the {what} header")
        count = self.integer(fields, 0)
        if count < 0:
            self.fail(f"the {what} count is {count}")
        return [count] + [self.integer(fields, i + 1, d) for i, d in enumerate(defaults)]

    def entries(self, count, what):
        return [self.take(f"{what} {k + 1} of {count}") for k in range(count)]


class _Reader:
    """Reads files into `data`, keeping the numbering base across them."""

    def __init__(self):
        self.data = {}
        self.base = 1

    def vertices(self, lines):
        count, _, attributes, markers = lines.header("vertex", (2, 0, 0))
        if count == 0:
            return
        rows = lines.entries(count, "vertex")
        self.base = 0 if lines.integer(rows[0], 0) == 0 else 1
        xy, values, marks = [], [], []
        for fields in rows:
            xy.append((lines.real(fields, 1), lines.real(fields, 2)))
            values.append([lines.real(fields, 3 + a, 0.0) for a in range(attributes)])
            if markers:
                marks.append(lines.integer(fields, 3 + attributes, 0))
        self.data["vertices"] = np.array(xy, dtype=np.float64).reshape(-1, 2)
        if attributes > 0:
            self.data["vertex_attributes"] = np.array(values, dtype=np.float64)
        if markers:
            self.data["vertex_markers"] = np.array(marks, dtype=np.intc).reshape(-1, 1)

    def indices(self, lines, fields, first, count):
        return [lines.integer(fields, first + i) - self.base for i in range(count)]

    def segments(self, lines):
        count, markers = lines.header("segment", (0,))
        rows = lines.entries(count, "segment")
        if count == 0:
            return
        self.data["segments"] = np.array(
            [self.indices(lines, f, 1, 2) for f in rows], dtype=np.intc).reshape(-1, 2)
        if markers:
            self.data["segment_markers"] = np.array(
                [lines.integer(f, 3, 0) for f in rows], dtype=np.intc).reshape(-1, 1)

    def holes(self, lines):
        count, = lines.header("hole", ())
        rows = lines.entries(count, "hole")
        if count > 0:
            self.data["holes"] = np.array(
                [(lines.real(f, 1), lines.real(f, 2)) for f in rows], dtype=np.float64)

    def regions(self, lines):
        count, = lines.header("region", ())
        rows = lines.entries(count, "region")
        table = []
        for f in rows:
            attribute = lines.real(f, 3)
            # One value after x y is both the attribute and the area bound, as in Triangle.
            table.append((lines.real(f, 1), lines.real(f, 2), attribute,
                          lines.real(f, 4, attribute)))
        if count > 0:
            self.data["regions"] = np.array(table, dtype=np.float64)

    def node(self, text):
        self.vertices(_Lines(text, "node"))

    def poly(self, text):
        lines = _Lines(text, "poly")
        self.vertices(lines)
        self.segments(lines)
        self.holes(lines)
        if lines.more():
            self.regions(lines)

    def ele(self, text):
        lines = _Lines(text, "ele")
        count, corners, attributes = lines.header("triangle", (3, 0))
        rows = lines.entries(count, "triangle")
        if count == 0:
            return
        self.data["triangles"] = np.array(
            [self.indices(lines, f, 1, corners) for f in rows], dtype=np.intc).reshape(-1, corners)
        if attributes > 0:
            self.data["triangle_attributes"] = np.array(
                [[lines.real(f, 1 + corners + a, 0.0) for a in range(attributes)] for f in rows],
                dtype=np.float64)

    def area(self, text):
        lines = _Lines(text, "area")
        count, = lines.header("area", ())
        rows = lines.entries(count, "area")
        if count > 0:
            # No value: no bound (-1), as Triangle reads it.
            self.data["triangle_max_area"] = np.array(
                [lines.real(f, 1, -1.0) for f in rows], dtype=np.float64).reshape(-1, 1)

    def edge(self, text):
        lines = _Lines(text, "edge")
        count, markers = lines.header("edge", (0,))
        edges, marks, origins, directions = [], [], [], []
        for f in lines.entries(count, "edge"):
            if lines.integer(f, 2) == -1:  # a ray of a Voronoi diagram (.v.edge)
                origins.append(lines.integer(f, 1) - self.base)
                directions.append((lines.real(f, 3), lines.real(f, 4)))
            else:
                edges.append(self.indices(lines, f, 1, 2))
                if markers:
                    marks.append(lines.integer(f, 3, 0))
        if edges:
            self.data["edges"] = np.array(edges, dtype=np.intc)
            if markers:
                self.data["edge_markers"] = np.array(marks, dtype=np.intc).reshape(-1, 1)
        if origins:
            self.data["ray_origins"] = np.array(origins, dtype=np.intc).reshape(-1, 1)
            self.data["ray_directions"] = np.array(directions, dtype=np.float64)

    def neigh(self, text):
        lines = _Lines(text, "neigh")
        count, per = lines.header("neighbour", (3,))
        rows = lines.entries(count, "neighbour")
        if count > 0:
            # -1 (no neighbour) stays -1 in either numbering.
            table = [[n if n == -1 else n - self.base
                      for n in (lines.integer(f, 1 + k) for k in range(per))] for f in rows]
            self.data["triangle_neighbors"] = np.array(table, dtype=np.intc)


def loads(node=None, ele=None, poly=None, area=None, edge=None, neigh=None):
    """The dictionary of a triangulation's files, given as strings: the
    contents of a .node, .ele, .poly, .area, .edge (or .v.edge) and .neigh
    file, any of them None.

    Keys: ``vertices``, ``vertex_attributes``, ``vertex_markers`` (.node, or
    the .poly's vertices); ``segments``, ``segment_markers``, ``holes``,
    ``regions`` (.poly); ``triangles``, ``triangle_attributes`` (.ele);
    ``triangle_max_area`` (.area); ``edges``, ``edge_markers``, and for a
    Voronoi diagram ``ray_origins``, ``ray_directions`` (.edge);
    ``triangle_neighbors`` (.neigh).  Raises :class:`Error` naming the file
    and line of anything malformed.
    """
    reader = _Reader()
    # Vertices first: the first vertex sets the numbering of every index.
    for text, read in ((node, reader.node), (poly, reader.poly), (ele, reader.ele),
                       (area, reader.area), (edge, reader.edge), (neigh, reader.neigh)):
        if text:
            read(text)
    return reader.data


def load(directory, name):
    """The dictionary of the files `name`.node, .ele, .poly, .area, .edge and
    .neigh that exist in `directory` (see :func:`loads`)."""
    texts = {}
    for ext in _EXTENSIONS:
        path = os.path.join(directory, f"{name}.{ext}")
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                texts[ext] = f.read()
    return loads(**texts)


def get_data_names():
    """The names :func:`get_data` knows: gpdr's sample inputs."""
    names = set()
    if os.path.isdir(_DATA_DIR):
        for file in os.listdir(_DATA_DIR):
            stem, ext = os.path.splitext(file)
            if ext[1:] in _EXTENSIONS:
                names.add(stem)
    return sorted(names)


def get_data(name):
    """One of gpdr's sample inputs, by name (:func:`get_data_names`): from
    poly-samples/ ``pipe``, ``flow``, ``points``; from tests/data/ ``letter``,
    ``face``, ``dots``, ``spiral``, ``box_hole``, ``circle_hole``,
    ``nested_hex``, ``nested_hex2``, ``nested_hex3``."""
    if name not in get_data_names():
        raise Error(f"no sample named '{name}'; the samples are {', '.join(get_data_names())}")
    return load(_DATA_DIR, name)
