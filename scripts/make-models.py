#!/usr/bin/env python3
"""Writes the generated models of the quality benchmark and the refinement
tests into tests/data/models/ (fixed parameters: the same files every run).

  channel.poly    a channel [0, 40] x [0, 10] with obstacles (holes): two
                  cylinders, a square turned 30 degrees and a wedge with a
                  20-degree tip.
  pipe-section.poly  a pipe of radius 10 (96 segments) with a hole of radius
                  2.5 in the middle and five of radius 1.2 on a ring.
  coastline.poly  a fractal coastline (make-coastline.py's construction,
                  here with 600 segments on the coast) with three islands.
  star.poly       a ten-pointed star whose spikes meet at 12 degrees, with a
                  smaller star-shaped hole: sharp input angles.
  crossing.poly   a square crossed by segments that cross one another
                  (a tilted grid and a diagonal): the mesher inserts the
                  crossing points.

Run it from anywhere: python3 scripts/make-models.py
"""
import math
import os
import random

from pslg import circle, fractal_star, write_poly as write_poly_at

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "models")


def write_poly(name, comment, loops, holes, markers, extra_segments=()):
    os.makedirs(OUT, exist_ok=True)
    write_poly_at(os.path.join(OUT, name), comment, loops, holes, markers, extra_segments)


def channel():
    outer = [(0.0, 0.0), (40.0, 0.0), (40.0, 10.0), (0.0, 10.0)]
    loops = [outer, circle(8, 5, 1.0, 32), circle(16, 3, 0.6, 20)]
    holes = [(8.0, 5.0), (16.0, 3.0)]
    # A square of side 2 centred at (24, 6), turned 30 degrees.
    c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
    loops.append([(24 + c * x - s * y, 6 + s * x + c * y)
                  for x, y in [(-1, -1), (1, -1), (1, 1), (-1, 1)]])
    holes.append((24.0, 6.0))
    # A wedge pointing upstream with a 20-degree tip at (30, 4).
    half = math.radians(10)
    loops.append([(30.0, 4.0), (34.0, 4.0 - 4 * math.tan(half)), (34.0, 4.0 + 4 * math.tan(half))])
    holes.append((33.0, 4.0))
    write_poly("channel.poly", ["A channel with four obstacles: scripts/make-models.py"], loops,
               holes, [1, 2, 2, 2, 2])


def pipe_section():
    loops = [circle(0, 0, 10, 96), circle(0, 0, 2.5, 40)]
    holes = [(0.0, 0.0)]
    for k in range(5):
        a = 2 * math.pi * k / 5
        cx, cy = 6 * math.cos(a), 6 * math.sin(a)
        loops.append(circle(cx, cy, 1.2, 24))
        holes.append((cx, cy))
    write_poly("pipe-section.poly", ["A pipe section with six holes: scripts/make-models.py"], loops,
               holes, [1] + [2] * 6)


def coastline():
    rng = random.Random(21)
    loops = [fractal_star(0, 0, 1000, 600, rng)]
    centres = [(-250.0, -150.0), (200.0, -200.0), (0.0, 250.0)]
    for cx, cy in centres:
        loops.append(fractal_star(cx, cy, 120, 60, rng))
    write_poly("coastline.poly", ["A fractal coastline with three islands: scripts/make-models.py"],
               loops, centres, [1, 2, 2, 2])


def star():
    spikes = 10
    outer, inner = 10.0, 10.0 * math.sin(math.radians(6)) / math.sin(math.radians(180 - 6 - 18))
    # Tip angle 12 degrees: the spike's sides leave the tip at +-6 degrees
    # off the radius; the inner radius follows from the triangle tip, centre,
    # notch (angle at the centre 18 degrees).
    points = []
    for k in range(spikes):
        a = 2 * math.pi * k / spikes
        points.append((outer * math.cos(a), outer * math.sin(a)))
        b = a + math.pi / spikes
        points.append((inner * math.cos(b), inner * math.sin(b)))
    hole = []
    for k in range(5):
        a = 2 * math.pi * k / 5 + 0.3
        hole.append((0.9 * math.cos(a), 0.9 * math.sin(a)))
        b = a + math.pi / 5
        hole.append((0.4 * math.cos(b), 0.4 * math.sin(b)))
    write_poly("star.poly", ["A ten-pointed star with 12-degree tips: scripts/make-models.py"],
               [points, hole], [(0.0, 0.0)], [1, 2])


def crossing():
    square = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]
    # Four slightly tilted rows and four columns crossing them, and a
    # diagonal crossing both: 16 + 8 crossings, none within 0.3 of another.
    lines = [[(0.5, y), (9.5, y + 0.9)] for y in (1.3, 3.7, 5.9, 7.6)]
    lines += [[(x, 0.4), (x + 1.35, 9.4)] for x in (1.1, 3.2, 5.6, 7.4)]
    lines.append([(0.6, 9.0), (9.2, 0.7)])
    write_poly("crossing.poly", ["A square with crossing segments: scripts/make-models.py"],
               [square], [], [1], lines)


if __name__ == "__main__":
    channel()
    pipe_section()
    coastline()
    star()
    crossing()
