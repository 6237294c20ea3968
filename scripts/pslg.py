"""Shapes and the .poly writer shared by the scripts that generate the
project's inputs (make-samples.py, make-models.py, make-coastline.py)."""
import math


def circle(cx, cy, r, n, phase=0.0):
    """n points on the circle of centre (cx, cy) and radius r, counter-clockwise."""
    return [(cx + r * math.cos(phase + 2 * math.pi * k / n),
             cy + r * math.sin(phase + 2 * math.pi * k / n)) for k in range(n)]


def fractal_star(cx, cy, radius, n, rng):
    """A star-shaped polygon of n points whose radius wanders by up to 30%:
    sines of doubling frequency and halving amplitude, with phases from rng."""
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


def write_poly(path, comment, loops, holes, markers, extra_segments=(), extra_marker=3):
    """Writes a .poly: loops are closed polylines (lists of points), one
    marker each; extra_segments are open polylines, with extra_marker;
    holes are points; comment is a list of lines for the header."""
    vertices, segments = [], []
    for loop, marker in zip(loops, markers):
        first = len(vertices)
        for p in loop:
            vertices.append((p, marker))
        for k in range(len(loop)):
            segments.append((first + k, first + (k + 1) % len(loop), marker))
    for line in extra_segments:
        first = len(vertices)
        for p in line:
            vertices.append((p, extra_marker))
        for k in range(len(line) - 1):
            segments.append((first + k, first + k + 1, extra_marker))
    with open(path, "w") as f:
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
