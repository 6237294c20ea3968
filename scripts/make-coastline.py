#!/usr/bin/env python3
"""Writes a large PSLG for benchmarks: a fractal coastline with islands.

    python3 scripts/make-coastline.py SEGMENTS OUT.poly

The coast and every island are star-shaped polygons, r(phi) = R (1 + noise),
with noise a sum of sines of doubling frequency and halving amplitude (a
Weierstrass-like fractal) bounded by 0.3 in size, so each polygon is simple
by construction and none touches another: islands sit in the cells of a grid
inside radius 0.45 R, where the coast (r >= 0.7 R) never comes.  Half the
segments go to the coast, half to the islands; each island is a hole.
"""
import math
import random
import sys


def star(cx, cy, radius, n, rng):
    terms = []
    amplitude = 0.15
    frequency = 3
    while frequency < n / 2 and amplitude > 1e-4:
        terms.append((amplitude, frequency, rng.uniform(0, 2 * math.pi)))
        amplitude /= 2
        frequency *= 2
    points = []
    for k in range(n):
        phi = 2 * math.pi * k / n
        noise = sum(a * math.sin(f * phi + p) for a, f, p in terms)  # |noise| < 0.3
        r = radius * (1 + noise)
        points.append((cx + r * math.cos(phi), cy + r * math.sin(phi)))
    return points


def main():
    segments = int(sys.argv[1])
    out = sys.argv[2]
    rng = random.Random(7)
    R = 1000.0
    loops = [star(0, 0, R, max(3, segments // 2), rng)]
    grid = 10
    cell = 0.9 * R / grid
    centres = [(-0.45 * R + cell * (i + 0.5), -0.45 * R + cell * (j + 0.5)) for i in range(grid) for j in range(grid)]
    per_island = max(3, (segments - len(loops[0])) // len(centres))
    for cx, cy in centres:
        loops.append(star(cx, cy, cell / 4, per_island, rng))
    with open(out, "w") as f:
        f.write(f"# Fractal coastline with {len(centres)} islands: made by scripts/make-coastline.py {segments}\n")
        total = sum(len(l) for l in loops)
        f.write(f"{total} 2 0 1\n")
        index = 1
        for m, loop in enumerate(loops):
            for x, y in loop:
                f.write(f"{index} {x!r} {y!r} {1 if m == 0 else 2}\n")
                index += 1
        f.write(f"{total} 1\n")
        index, first = 1, 1
        for m, loop in enumerate(loops):
            for k in range(len(loop)):
                a = first + k
                b = first + (k + 1) % len(loop)
                f.write(f"{index} {a} {b} {1 if m == 0 else 2}\n")
                index += 1
            first += len(loop)
        f.write(f"{len(centres)}\n")
        for i, (cx, cy) in enumerate(centres, 1):
            f.write(f"{i} {cx!r} {cy!r}\n")


if __name__ == "__main__":
    main()
