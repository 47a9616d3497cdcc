#!/usr/bin/python3
"""Saddle targets for `curvefold fit` made apart from curvefold (issue 38, 2), in pure Python.

Unlike scripts/make-example-targets.sh (one awk grid in the catalogue's frame) and
bench/make_smooth_targets.py (numpy grids): polar rings over a disk, a coarse grid with
alternating diagonals, a long fine rectangle, turns about and tilts off the vertical, a monkey
saddle (three valleys, which no set of parallel pleats follows), and a scan with noise and holes.
Usage: bench/make_saddle_targets.py OUTDIR
"""
import math
import os
import random
import sys

from formula_meshes import place, write_obj


def disk(radius, rings, height):
    """Concentric rings of 6 * k vertices (k = 1..rings), fan-stitched between rings."""
    verts = [(0.0, 0.0, height(0.0, 0.0))]
    starts = [0]
    for k in range(1, rings + 1):
        starts.append(len(verts))
        r = radius * k / rings
        for i in range(6 * k):
            a = 2 * math.pi * i / (6 * k)
            x, y = r * math.cos(a), r * math.sin(a)
            verts.append((x, y, height(x, y)))
    tris = []
    for i in range(6):
        tris.append((0, 1 + i, 1 + (i + 1) % 6))
    for k in range(1, rings):
        inner, outer = starts[k], starts[k + 1]
        n_in, n_out = 6 * k, 6 * (k + 1)
        i = j = 0
        while i < n_in or j < n_out:
            # advance whichever ring lags in angle
            if j < n_out and (i >= n_in or (j + 1) / n_out <= (i + 1) / n_in):
                tris.append((inner + i % n_in, outer + j, outer + (j + 1) % n_out))
                j += 1
            else:
                tris.append((inner + i % n_in, outer + j % n_out, inner + (i + 1) % n_in))
                i += 1
    return verts, tris


def grid(width, depth, nx, ny, height, alternate=True):
    verts = []
    for j in range(ny + 1):
        for i in range(nx + 1):
            x = -width / 2 + width * i / nx
            y = -depth / 2 + depth * j / ny
            verts.append((x, y, height(x, y)))
    tris = []
    for j in range(ny):
        for i in range(nx):
            a = j * (nx + 1) + i
            b, c, d = a + 1, a + nx + 1, a + nx + 2
            if alternate and (i + j) % 2:
                tris += [(a, b, c), (b, d, c)]
            else:
                tris += [(a, b, d), (a, d, c)]
    return verts, tris


def write(path, comment, verts, tris):
    write_obj(path, comment, "bench/make_saddle_targets.py", verts, tris, number="%.9g", used_only=False)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_saddle_targets.py OUTDIR")
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    rng = random.Random(38)

    # A hypar z = x y / c over a 24 cm disk, turned 30 degrees and tilted 15.
    v, t = disk(0.12, 14, lambda x, y: x * y / 0.2)
    write(os.path.join(outdir, "hypar_disk.obj"), "hypar z = xy/0.2 over a disk r 12 cm, turned 30, tilted 15",
          [place(p, 30, 15, (0.05, -0.02, 0.3)) for p in v], t)

    # z = (x^2 - y^2) / 0.5 over a 40 cm square, coarse (8 x 8, alternating diagonals), turned 30.
    v, t = grid(0.4, 0.4, 8, 8, lambda x, y: (x * x - y * y) / 0.5)
    write(os.path.join(outdir, "saddle_coarse.obj"), "z = (x^2-y^2)/0.5 over 40 cm, 8x8, turned 30",
          [place(p, 30, 0, (0, 0, 0)) for p in v], t)

    # A long gentle saddle z = (x^2 / 0.6 - y^2 / 0.3) over 30 x 15 cm, fine (90 x 45).
    v, t = grid(0.3, 0.15, 90, 45, lambda x, y: x * x / 0.6 - y * y / 0.3, alternate=False)
    write(os.path.join(outdir, "saddle_long.obj"), "z = x^2/0.6 - y^2/0.3 over 30 x 15 cm, 90x45",
          [place(p, -10, 25, (0, 0, 0)) for p in v], t)

    # A monkey saddle z = (x^3 - 3 x y^2) / 0.03 over a disk r 10 cm.
    v, t = disk(0.1, 12, lambda x, y: (x ** 3 - 3 * x * y * y) / 0.03)
    write(os.path.join(outdir, "monkey_disk.obj"), "monkey saddle z = (x^3-3xy^2)/0.03 over a disk r 10 cm", v, t)

    # A scanned hypar z = x y / 0.25 over 30 cm: noise 0.5 mm along z, two holes.
    v, t = grid(0.3, 0.3, 40, 40, lambda x, y: x * y / 0.25)
    v = [(x + rng.gauss(0, 0.0003), y + rng.gauss(0, 0.0003), z + rng.gauss(0, 0.0005)) for x, y, z in v]
    holes = [((0.05, 0.04), 0.025), ((-0.07, -0.06), 0.018)]

    def kept(tri):
        cx = sum(v[i][0] for i in tri) / 3
        cy = sum(v[i][1] for i in tri) / 3
        return all(math.hypot(cx - hx, cy - hy) > r for (hx, hy), r in holes)

    t = [tri for tri in t if kept(tri)]
    used = sorted({i for tri in t for i in tri})
    index = {old: new for new, old in enumerate(used)}
    write(os.path.join(outdir, "hypar_scan.obj"), "hypar z = xy/0.25 over 30 cm, noise, two holes",
          [place(v[i], 55, -20, (0.1, 0.1, 0)) for i in used],
          [tuple(index[i] for i in tri) for tri in t])


if __name__ == "__main__":
    main()
