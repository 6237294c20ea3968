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

Run it from anywhere: python3 scripts/make-samples.py
"""
import math
import os
import random

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "poly-samples")


def circle(cx, cy, r, n):
    return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n))
            for k in range(n)]


def write_poly(name, comment, loops, holes, markers):
    """loops: closed polylines (lists of points); markers: one per loop."""
    vertices, segments = [], []
    for loop, marker in zip(loops, markers):
        first = len(vertices)
        for p in loop:
            vertices.append((p, marker))
        for k in range(len(loop)):
            segments.append((first + k, first + (k + 1) % len(loop), marker))
    with open(os.path.join(OUT, name), "w") as f:
        for line in comment:
            f.write(f"# {line}\n")
        f.write(f"{len(vertices)} 2 0 1\n")
        for i, ((x, y), m) in enumerate(vertices, 1):
            f.write(f"{i} {x!r} {y!r} {m}\n")
        f.write(f"{len(segments)} 1\n")
        for i, (a, b, m) in enumerate(segments, 1):
            f.write(f"{i} {a + 1} {b + 1} {m}\n")
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes, 1):
            f.write(f"{i} {x!r} {y!r}\n")


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


if __name__ == "__main__":
    pipe()
    flow()
    points()
