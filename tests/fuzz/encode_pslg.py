#!/usr/bin/env python3
"""Writes a seed for the pipeline fuzz target (fuzz_pipeline) from a .poly
file with its vertices inline: the switch bytes as pslg_bytes.hpp lays them
out, then the PSLG on the target's 256 x 256 grid.

Coordinates are mapped back through the chosen grid map and rounded; when
they do not all fit the grid that way, the bounding box is scaled onto
-120..120 first (the shape is kept, exactness is not).  Vertices past
fuzz::max_vertices and the segments that use them are dropped.

    encode_pslg.py IN.poly OUT [--mode p|pq|pc|r] [--map K] [--angle DEG]
                   [--area K] [-D] [-Y] [-A] [--placement N]
"""
import argparse
import struct

MAX_VERTICES, MAX_SEGMENTS = 40, 60
ANGLES = [20, 25, 30, 33, 0, 10, 15, 34]
MAPS = [
    (1, 0), (0.1, 0), (0.001, 0), (0.1, 1e6), (1 / 3, 7), (1e5, 0), (1e-9, 1), (0.37, -11.3),
]


def data_lines(path):
    with open(path) as f:
        for line in f:
            fields = line.split("#", 1)[0].replace(",", " ").split()
            if fields:
                yield fields


def read_poly(path):
    lines = data_lines(path)
    n = int(next(lines)[0])
    if n == 0:
        raise SystemExit(f"{path}: vertices in a .node file are not supported")
    vertices = [tuple(map(float, next(lines)[1:3])) for _ in range(n)]
    m = int(next(lines)[0])
    segments = [tuple(int(v) for v in next(lines)[1:3]) for _ in range(m)]
    holes = []
    regions = []
    try:
        for _ in range(int(next(lines)[0])):
            holes.append(tuple(map(float, next(lines)[1:3])))
        for _ in range(int(next(lines)[0])):
            f = next(lines)
            regions.append(tuple(map(float, f[1:3])))
    except StopIteration:
        pass
    base = min((min(s) for s in segments), default=1)
    base = 0 if base == 0 else 1
    return vertices, [(a - base, b - base) for a, b in segments], holes, regions


def to_grid(points, scale, offset):
    grid = [round((v - offset) / scale) for p in points for v in p]
    if all(-128 <= g <= 127 for g in grid):
        return grid
    values = [v for p in points for v in p]
    lo, hi = min(values), max(values)
    span = (hi - lo) or 1.0
    return [round(-120 + 240 * (v - lo) / span) for v in values]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("poly")
    ap.add_argument("out")
    ap.add_argument("--mode", choices=["p", "pq", "pc", "r"], default="p")
    ap.add_argument("--map", type=int, default=0, choices=range(8))
    ap.add_argument("--angle", type=int, default=20, choices=ANGLES)
    ap.add_argument("--area", type=int, default=None, help="-a: the box's area / 2^(K+1)")
    ap.add_argument("--placement", type=int, default=3, choices=range(4))
    ap.add_argument("-D", action="store_true")
    ap.add_argument("-Y", action="store_true")
    ap.add_argument("-A", action="store_true")
    args = ap.parse_args()

    vertices, segments, holes, regions = read_poly(args.poly)
    vertices = vertices[:MAX_VERTICES]
    segments = [s for s in segments if max(s) < len(vertices)][:MAX_SEGMENTS]
    holes, regions = holes[:3], regions[:3]
    scale, offset = MAPS[args.map]
    grid = to_grid(vertices + holes + regions, scale, offset)

    b0 = ["p", "pq", "pc", "r"].index(args.mode)
    b0 |= args.D << 2 | (args.area is not None) << 3 | args.placement << 4
    b0 |= args.Y << 6 | args.A << 7
    b1 = ANGLES.index(args.angle) | args.map << 3
    b4 = len(holes) | len(regions) << 2 | (args.area or 0) << 4
    out = bytes([b0, b1, len(vertices), len(segments), b4])
    nv, nh = 2 * len(vertices), 2 * len(holes)
    out += struct.pack(f"{nv}b", *grid[:nv])
    out += bytes(v for s in segments for v in s)
    out += struct.pack(f"{nh}b", *grid[nv:nv + nh])
    for r in range(len(regions)):
        x, y = grid[nv + nh + 2 * r: nv + nh + 2 * r + 2]
        out += struct.pack("2b", x, y) + bytes([r + 1, 0])
    with open(args.out, "wb") as f:
        f.write(out)


if __name__ == "__main__":
    main()
