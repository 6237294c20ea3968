#!/usr/bin/env python3
"""Writes the project's generated sample inputs into poly-samples/.

The GPDR paper measures two models it does not publish: a pipe cross-section
(graded around (200, 200) by its function (10)) and the upper half of a
cylinder-flow channel.  These are our own versions of them:

  pipe.poly  a pipe of radius 200 centred at (200, 200) holding seven tubes;
             800 segments on the pipe, 120 and 100 on the tubes
             (holes): one of radius 30 in the middle, six of radius 25 on a
             ring of radius 110.
  flow.poly  the upper half of a channel [0, 30] x [0, 10] with a cylinder of
             radius 1 centred at (8, 0) on its symmetry line.
  points.node  500 pseudo-random points in the unit square (fixed seed).

It also writes the inputs the tests read, into tests/data/, each made to
exercise a part of Triangle's file formats and of the mesher:

  letter.poly      an "R": a non-convex outline with curved parts and a hole
                   in its bowl; one vertex attribute, boundary markers.
  box_hole.poly    a box whose only closed loop is its square hole, plus one
                   side and two diagonals as segments: without -c every
                   triangle is eaten; with -c the diagonals split it into two
                   regions (attributes, one with an area bound).  Special
                   vertex and segment markers, comments after entries.
  dots.node        100 pseudo-random points in [-1, 1]^2 (fixed seed), no
                   attributes, no markers.
  spiral.node      30 points on an Archimedean spiral; one attribute (the
                   angle) and markers.
  nested_hex.poly  a rectangle holding a hexagon with a nested hexagonal hole
                   (the ring between them cut by three spokes that share the
                   hexagons' vertices into regions with attributes and area
                   bounds) and a second hexagonal hole.
  nested_hex2.poly nested hexagons in a square, without markers: segments
                   that pass through vertices, overlap collinear segments or
                   repeat one, and chains of collinear segments meeting at
                   shared vertices; four regions, one hole.
  nested_hex3.poly the .poly with no vertices: they come from nested_hex3.node
                   (numbered from 0, one attribute); regions and two holes.
  face.poly        an oval face: two eyes (closed loops, holes), a mouth, a
                   nose and eyebrows (open polylines, internal segments) and
                   freckles (lone vertices); blank lines and comments.
  circle_hole.poly a rectangle with a circular hole of 300 segments and a
                   ring of 20 free vertices around it.

Numbers are written with at most six decimals, so the files do not depend on
the last bit of the platform's sin and cos.

Run it from anywhere: python3 scripts/make-samples.py
"""
import math
import os
import random

from pslg import circle, write_poly as write_poly_at

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
OUT = os.path.join(ROOT, "poly-samples")
TEST_DATA = os.path.join(ROOT, "tests", "data")
MADE_BY = "Made by scripts/make-samples.py."


def write_poly(name, comment, loops, holes, markers):
    write_poly_at(os.path.join(OUT, name), comment, loops, holes, markers)


def pipe():
    loops = [circle(200, 200, 200, 800), circle(200, 200, 30, 120)]
    holes = [(200.0, 200.0)]
    for k in range(6):
        a = 2 * math.pi * k / 6
        cx, cy = 200 + 110 * math.cos(a), 200 + 110 * math.sin(a)
        loops.append(circle(cx, cy, 25, 100))
        holes.append((cx, cy))
    write_poly("pipe.poly",
               ["Pipe cross-section: a pipe of radius 200 around (200, 200) holding seven tubes.",
                "Made by scripts/make-samples.py.  Marker 1: outer wall, 2: tube walls."],
               loops, holes, [1] + [2] * 7)


def flow():
    # Upper half of a channel with a cylinder of radius 1 at (8, 0): the
    # bottom edge is the symmetry line, broken by the half-cylinder.
    # The walls are divided as a flow solver's boundary layer would want them:
    # 160 pieces on the half-cylinder, 0.1 along the symmetry line, 0.25 on
    # the inlet, outlet and top wall.
    def line(p, q, n):
        return [(p[0] + (q[0] - p[0]) * k / n, p[1] + (q[1] - p[1]) * k / n) for k in range(n)]
    arc = [(8 + math.cos(math.pi - math.pi * k / 160), math.sin(math.pi - math.pi * k / 160))
           for k in range(160)]
    # sin(pi) is 1.2e-16 in floating point: put the arc's end exactly on the
    # axis, or it leaves a 1e-15 radian angle against the axis segments.
    arc[0] = (7.0, 0.0)
    outline = (line((0.0, 0.0), (7.0, 0.0), 70) + arc + line((9.0, 0.0), (30.0, 0.0), 210) +
               line((30.0, 0.0), (30.0, 10.0), 40) + line((30.0, 10.0), (0.0, 10.0), 120) +
               line((0.0, 10.0), (0.0, 0.0), 40))
    write_poly("flow.poly",
               ["Upper half of a cylinder-flow channel [0,30]x[0,10], cylinder of radius 1 at (8, 0).",
                "Made by scripts/make-samples.py."],
               [outline], [], [1])


def points():
    rng = random.Random(20261122)
    with open(os.path.join(OUT, "points.node"), "w") as f:
        f.write("# 500 pseudo-random points in the unit square.  Made by scripts/make-samples.py.\n")
        f.write("500 2 0 0\n")
        for i in range(500):
            f.write(f"{i + 1} {rng.random()!r} {rng.random()!r}\n")


# ---------------------------------------------------------------------------
# tests/data: the inputs the tests read.


def num(v):
    """A coordinate or attribute with at most six decimals, no trailing zeros."""
    text = f"{v:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def arc(cx, cy, r, start_degrees, end_degrees, n):
    """n + 1 points from start to end (degrees), both ends included."""
    out = []
    for k in range(n + 1):
        a = math.radians(start_degrees + (end_degrees - start_degrees) * k / n)
        out.append((cx + r * math.cos(a), cy + r * math.sin(a)))
    return out


def polygon(cx, cy, r, n, first_degrees=0.0):
    """The n corners of a regular polygon, counterclockwise."""
    return arc(cx, cy, r, first_degrees, first_degrees + 360, n)[:n]


def reverse(loop):
    """The same closed loop the other way round, from the same first entry."""
    return loop[:1] + loop[1:][::-1]


def subdivided(corners, pieces):
    """A closed polyline through `corners`, each side cut into `pieces`."""
    out = []
    for k, (p, q) in enumerate(zip(corners, corners[1:] + corners[:1])):
        n = pieces[k] if isinstance(pieces, (list, tuple)) else pieces
        out += [(p[0] + (q[0] - p[0]) * j / n, p[1] + (q[1] - p[1]) * j / n) for j in range(n)]
    return out


class Pslg:
    """A .node or .poly file built section by section.  Vertices and segments
    are numbered from `base`.  A section (vertices, segments, holes, regions)
    may hold comment lines, added with comment() ("" is a blank line), and an
    entry may carry a comment after it (its note)."""

    def __init__(self, attributes=0, markers=True, base=1):
        self.attributes, self.markers, self.base = attributes, markers, base
        self.vertices, self.segments, self.holes, self.regions = [], [], [], []
        self.count = 0

    def comment(self, section, text):
        section.append(text)

    def vertex(self, p, marker=0, attributes=(), note=None):
        assert len(attributes) == self.attributes
        self.vertices.append((p, marker, tuple(attributes), note))
        self.count += 1
        return self.count - 1

    def segment(self, a, b, marker=0, note=None):
        self.segments.append((a, b, marker, note))

    def loop(self, points, marker=0, closed=True, attributes=None):
        """Vertices for `points` and segments joining them in order (back to
        the first when closed); returns the vertices' numbers.  `attributes`
        maps a point to its attributes."""
        ids = [self.vertex(p, marker, attributes(p) if attributes else ()) for p in points]
        ends = len(ids) if closed else len(ids) - 1
        for k in range(ends):
            self.segment(ids[k], ids[(k + 1) % len(ids)], marker)
        return ids

    def hole(self, p, note=None):
        self.holes.append((p, note))

    def region(self, p, attribute, area, note=None):
        self.regions.append((p, attribute, area, note))

    @staticmethod
    def _lines(section, entry_text):
        out, index = [], 0
        for item in section:
            if isinstance(item, str):
                out.append(f"# {item}" if item else "")
                continue
            text = entry_text(index, item)
            note = item[-1]
            out.append(f"{text}  # {note}" if note else text)
            index += 1
        return out

    def _vertex_lines(self):
        def text(i, v):
            (x, y), marker, attributes, _ = v
            fields = [str(i + self.base), num(x), num(y)] + [num(a) for a in attributes]
            if self.markers:
                fields.append(str(marker))
            return " ".join(fields)

        header = f"{self.count} 2 {self.attributes} {1 if self.markers else 0}"
        return [header] + self._lines(self.vertices, text)

    def node_lines(self):
        return self._vertex_lines()

    def poly_lines(self, vertices=True):
        out = self._vertex_lines() if vertices else [f"0 2 {self.attributes} {int(self.markers)}"]

        def segment(i, s):
            a, b, marker, _ = s
            fields = [str(i + self.base), str(a + self.base), str(b + self.base)]
            if self.markers:
                fields.append(str(marker))
            return " ".join(fields)

        def hole(i, h):
            return f"{i + self.base} {num(h[0][0])} {num(h[0][1])}"

        def region(i, r):
            (x, y), attribute, area, _ = r
            return f"{i + self.base} {num(x)} {num(y)} {num(attribute)} {num(area)}"

        count = sum(1 for s in self.segments if not isinstance(s, str))
        out.append(f"{count} {1 if self.markers else 0}")
        out += self._lines(self.segments, segment)
        out.append(str(sum(1 for h in self.holes if not isinstance(h, str))))
        out += self._lines(self.holes, hole)
        if self.regions:
            out.append(str(sum(1 for r in self.regions if not isinstance(r, str))))
            out += self._lines(self.regions, region)
        return out


def write_lines(name, comment, lines):
    os.makedirs(TEST_DATA, exist_ok=True)
    with open(os.path.join(TEST_DATA, name), "w") as f:
        for line in comment:
            f.write(f"# {line}\n" if line else "#\n")
        for line in lines:
            f.write(line + "\n")


def letter():
    # An "R": stem, bowl (an arc of radius 3 around (3.6, 7)) and leg; the
    # bowl's counter is a D of straight left side and half circle of radius
    # 1.5 around (3.1, 7).  The attribute is the ramp 0.1 x - 0.05 y.
    g = Pslg(attributes=1)
    ramp = lambda p: (0.1 * p[0] - 0.05 * p[1],)
    outline = ([(0, 0), (1.6, 0), (1.6, 4), (2.7, 4), (4.6, 0), (6.4, 0)] +
               arc(3.6, 7, 3, -70, 90, 16) + [(0, 10)])
    g.comment(g.vertices, "The outline: stem, leg and bowl, counterclockwise.")
    g.comment(g.segments, "The outline.")
    g.loop(outline, 2, attributes=ramp)
    g.comment(g.vertices, "The counter of the bowl, clockwise.")
    g.comment(g.segments, "The counter.")
    counter = [(1.6, 8.5)] + arc(3.1, 7, 1.5, 90, -90, 8) + [(1.6, 5.5)]
    g.loop(counter, 3, attributes=ramp)
    g.hole((3.0, 7.0), "inside the counter")
    write_lines("letter.poly",
                ["The letter R: a non-convex outline with a hole in its bowl.", MADE_BY,
                 "One vertex attribute (a linear ramp); markers 2 outline, 3 counter."],
                g.poly_lines())


def box_hole():
    g = Pslg()
    g.comment(g.vertices, "The box's corners: no segments close them.")
    c = [g.vertex((0, 0)), g.vertex((4, 0)), g.vertex((4, 4), 7, note="a special marker"),
         g.vertex((0, 4))]
    g.comment(g.vertices, "The square hole.")
    h = [g.vertex(p) for p in [(1.5, 1.5), (2.5, 1.5), (2.5, 2.5), (1.5, 2.5)]]
    g.segment(c[3], c[0], 5, "the box's left side")
    g.comment(g.segments, "The hole, clockwise.")
    g.segment(h[0], h[3], 0)
    g.segment(h[3], h[2], 10, "a special marker")
    g.segment(h[2], h[1], 0)
    g.segment(h[1], h[0], 0)
    g.comment(g.segments, "Diagonals from the hole to two corners: with -c they split the box.")
    g.segment(h[0], c[0], 4)
    g.segment(h[2], c[2], 4)
    g.hole((2, 2), "the middle of the square")
    g.region((3, 1), 1, 0.05, "below the diagonals, area bound 0.05")
    g.region((1, 3), 2, -1, "above them, no area bound")
    write_lines("box_hole.poly",
                ["A box [0,4]x[0,4] with a square hole; only the hole is a closed loop.",
                 MADE_BY],
                g.poly_lines())


def dots():
    rng = random.Random(20261123)
    g = Pslg(markers=False)
    for _ in range(100):
        g.vertex((rng.uniform(-1, 1), rng.uniform(-1, 1)))
    write_lines("dots.node",
                ["100 pseudo-random points in [-1,1]x[-1,1].  " + MADE_BY], g.node_lines())


def spiral():
    # r = 0.3 angle, a point every 0.75 radians from the centre outwards;
    # the points of the last turn have marker 1.
    g = Pslg(attributes=1)
    g.comment(g.vertices, "Each point's attribute is its angle along the spiral.")
    last = 0.75 * 29
    for k in range(30):
        a = 0.75 * k
        marker = 1 if a > last - 2 * math.pi else 0
        g.vertex((0.3 * a * math.cos(a), 0.3 * a * math.sin(a)), marker, (a,))
    write_lines("spiral.node",
                ["30 points on an Archimedean spiral.", MADE_BY], g.node_lines())


def nested_hex():
    g = Pslg()
    g.comment(g.vertices, "The rectangle [0,3]x[0,2], a vertex every 0.125.")
    g.comment(g.segments, "The rectangle.")
    g.loop(subdivided([(0, 0), (3, 0), (3, 2), (0, 2)], [24, 16, 24, 16]), 1)
    g.comment(g.vertices, "Hexagon A around (1, 1): corners and side midpoints.")
    g.comment(g.segments, "Hexagon A.")
    outer = g.loop(subdivided(polygon(1, 1, 0.7, 6), 2), 2)
    g.comment(g.vertices, "Hexagon a inside A, a hole.")
    g.comment(g.segments, "Hexagon a, clockwise.")
    inner = reverse(g.loop(reverse(polygon(1, 1, 0.35, 6)), 3))  # counterclockwise again
    g.comment(g.segments, "Spokes from a's corners to A's: three regions between them.")
    for k in (0, 2, 4):
        g.segment(inner[k], outer[2 * k], 4)
    g.comment(g.vertices, "Hexagon B around (2.3, 1), a hole.")
    g.comment(g.segments, "Hexagon B.")
    g.loop(subdivided(polygon(2.3, 1, 0.45, 6), 2), 5)
    g.hole((1, 1), "inside a")
    g.hole((2.3, 1), "inside B")
    for k, (attribute, area) in enumerate([(1, 0.004), (2, 0.02), (3, -1)]):
        a = math.radians(60 + 120 * k)
        g.region((1 + 0.525 * math.cos(a), 1 + 0.525 * math.sin(a)), attribute, area)
    g.region((0.25, 1.75), 4, 0.05, "outside the hexagons")
    write_lines("nested_hex.poly",
                ["A rectangle with nested hexagons: the ring between A and a split into",
                 "three regions by spokes; a and B are holes.", MADE_BY,
                 "Markers: 1 rectangle, 2 A, 3 a, 4 spokes, 5 B."],
                g.poly_lines())


def nested_hex2():
    g = Pslg(markers=False)
    g.comment(g.vertices, "The square's corners and the middles of its bottom and top sides.")
    c = [g.vertex(p) for p in [(0, 0), (2, 0), (2, 2), (0, 2)]]
    bottom, top = g.vertex((1, 0)), g.vertex((1, 2))
    g.comment(g.vertices, "Two vertices on the top side, either side of its middle.")
    top_left, top_right = g.vertex((0.5, 2)), g.vertex((1.5, 2))
    g.comment(g.vertices, "Hexagon H around (1, 1), pointy top.")
    big = [g.vertex(p) for p in polygon(1, 1, 0.6, 6, 90)]
    g.comment(g.vertices, "Hexagon h inside H, a hole.")
    small = [g.vertex(p) for p in polygon(1, 1, 0.3, 6, 90)]
    g.comment(g.segments, "The square; its bottom and top sides pass through vertices.")
    for k in range(4):
        g.segment(c[k], c[(k + 1) % 4])
    g.comment(g.segments, "Collinear segments overlapping the square's sides, and a repeat.")
    g.segment(c[0], bottom, note="half of the bottom side")
    g.segment(top_left, top_right, note="straddles the top side's middle")
    g.segment(c[2], c[1], note="the right side again, reversed")
    g.comment(g.segments, "H and h.")
    for ring in (big, small):
        for k in range(6):
            g.segment(ring[k], ring[(k + 1) % 6])
    g.comment(g.segments, "A vertical line of segments meeting at shared vertices.")
    g.segment(bottom, big[3], note="to H's bottom corner")
    g.segment(bottom, small[3], note="through H's bottom corner to h's")
    g.segment(small[0], big[0])
    g.segment(big[0], top)
    g.hole((1, 1), "inside h")
    g.region((0.6, 1), 1, -1, "left half of the ring")
    g.region((1.4, 1), 2, 0.01, "right half of the ring")
    g.region((0.25, 1), 3, 0.02, "left of the line, outside H")
    g.region((1.75, 1), 4, -1, "right of the line, outside H")
    write_lines("nested_hex2.poly",
                ["Nested hexagons in a square, no markers: collinear segments that overlap,",
                 "pass through vertices or meet at shared vertices.", MADE_BY],
                g.poly_lines())


def nested_hex3():
    # Vertices numbered from 0, in the .node file; the attribute numbers the
    # loop a vertex belongs to.
    g = Pslg(attributes=1, base=0)
    loops = [([(0, 0), (3, 0), (3, 2), (0, 2)], 1, "the rectangle"),
             (polygon(1, 1, 0.7, 6), 2, "hexagon A"),
             (reverse(polygon(1, 1, 0.35, 6)), 3, "hexagon a inside A, clockwise"),
             (polygon(2.3, 1, 0.45, 6), 4, "hexagon B")]
    for k, (points, marker, name) in enumerate(loops):
        g.comment(g.vertices, name[:1].upper() + name[1:] + ".")
        g.comment(g.segments, name[:1].upper() + name[1:] + ".")
        g.loop(points, marker, attributes=lambda p, k=k: (k,))
    g.hole((1, 1), "inside a")
    g.hole((2.3, 1), "inside B")
    g.region((1, 1.5), 1, 0.01, "between A and a")
    g.region((0.2, 0.2), 2, -1, "outside the hexagons")
    write_lines("nested_hex3.node",
                ["The vertices of nested_hex3.poly, numbered from 0.", MADE_BY],
                g.node_lines())
    write_lines("nested_hex3.poly",
                ["Nested hexagons in a rectangle, a few vertices each; no vertices here:",
                 "they are in nested_hex3.node.", MADE_BY],
                g.poly_lines(vertices=False))


def face():
    g = Pslg()
    g.comment(g.vertices, "The outline, an oval of 32 vertices.")
    g.comment(g.segments, "The outline.")
    g.loop([(9 * x, 11 * y) for x, y in polygon(0, 0, 1, 32)], 1)
    g.comment(g.vertices, "")
    for side, marker in ((-1, 2), (1, 3)):
        name = "left" if side < 0 else "right"
        g.comment(g.vertices, f"The {name} eye, a closed loop (a hole).")
        g.comment(g.segments, f"The {name} eye.")
        g.loop([(3.5 * side + 1.6 * math.cos(a), 3.5 + math.sin(a))
                for a in (2 * math.pi * k / 8 for k in range(8))], marker)
        g.hole((3.5 * side, 3.5), f"the {name} eye")
    g.comment(g.vertices, "")
    g.comment(g.vertices, "The mouth, an open arc.")
    g.comment(g.segments, "The mouth: internal segments.")
    g.loop(arc(0, -2, 5, 210, 330, 8), 4, closed=False)
    g.comment(g.vertices, "The nose, an open V.")
    g.comment(g.segments, "The nose.")
    g.loop([(0, 2), (-1, -1), (0.8, -1.2)], 5, closed=False)
    g.comment(g.vertices, "The eyebrows.")
    g.comment(g.segments, "The eyebrows.")
    for side in (-1, 1):
        g.loop([(5.2 * side, 5.4), (3.5 * side, 6.2), (1.8 * side, 5.6)], 6, closed=False)
    g.comment(g.vertices, "")
    g.comment(g.vertices, "Freckles: lone vertices.")
    for p in [(-5, 0), (5, 0), (-5.5, -1), (5.5, -1)]:
        g.vertex(p, 0, note="a freckle")
    write_lines("face.poly",
                ["A face: an oval outline, eyes (holes), and a mouth, a nose and eyebrows",
                 "that enclose nothing.", MADE_BY,
                 "Markers: 1 outline, 2 and 3 eyes, 4 mouth, 5 nose, 6 eyebrows."],
                g.poly_lines())


def circle_hole():
    g = Pslg()
    g.comment(g.vertices, "The rectangle [0,6]x[0,4], a vertex every 0.5.")
    g.comment(g.segments, "The rectangle.")
    g.loop(subdivided([(0, 0), (6, 0), (6, 4), (0, 4)], [12, 8, 12, 8]), 1)
    g.comment(g.vertices, "The circle of radius 1 around (2.5, 2), clockwise.")
    g.comment(g.segments, "The circle.")
    g.loop(reverse(polygon(2.5, 2, 1, 300)), 2)
    g.comment(g.vertices, "Free vertices on a circle of radius 1.6 around the hole.")
    for p in polygon(2.5, 2, 1.6, 20, 9):
        g.vertex(p, 0)
    g.hole((2.5, 2), "the circle's centre")
    write_lines("circle_hole.poly",
                ["A rectangle with a circular hole of 300 segments.", MADE_BY,
                 "Markers: 1 rectangle, 2 circle, 0 free vertices."],
                g.poly_lines())


if __name__ == "__main__":
    pipe()
    flow()
    points()
    letter()
    box_hole()
    dots()
    spiral()
    nested_hex()
    nested_hex2()
    nested_hex3()
    face()
    circle_hole()
