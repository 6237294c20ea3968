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
import random
import sys

from pslg import fractal_star, write_poly


def main():
    segments = int(sys.argv[1])
    out = sys.argv[2]
    rng = random.Random(7)
    R = 1000.0
    loops = [fractal_star(0, 0, R, max(3, segments // 2), rng)]
    grid = 10
    cell = 0.9 * R / grid
    centres = [(-0.45 * R + cell * (i + 0.5), -0.45 * R + cell * (j + 0.5)) for i in range(grid) for j in range(grid)]
    per_island = max(3, (segments - len(loops[0])) // len(centres))
    for cx, cy in centres:
        loops.append(fractal_star(cx, cy, cell / 4, per_island, rng))
    write_poly(out, [f"Fractal coastline with {len(centres)} islands: made by "
                     f"scripts/make-coastline.py {segments}"],
               loops, centres, [1] + [2] * (len(loops) - 1))

if __name__ == "__main__":
    main()
