#!/usr/bin/env python3
"""Saddle targets meshed in offset rows and in rings, unlike the other saddle generators (issue 38, 2).

The grids, lattices, scatter, Delaunay, row scans and warped grids of bench/make_saddle_*.py lay
their vertices on one parameter grid; here each row (or ring) has as many vertices as its own
length needs, every other one shifted by half a step, zipped to the next (no two rows alike), so
no edge runs along a ruling or a principal direction of the saddle.

  hypar_steep_mm: a steep hyperbolic paraboloid z = x y / 50 over a 240 x 160 mm rectangle
                  (units of mm; corners at +-192 mm, slopes to 2.4 at the short ends), its rulings
                  along the rectangle's sides, so its principal directions run along the
                  diagonals; turned 35 degrees about z and 20 degrees about (1, 0, 0), centred at
                  (-300, 150, 80).
  saddle_ellipse_hole: z = 2.2 x^2 - 3.5 y^2 over an ellipse of 11 x 8 cm, meshed in rings about
                  its centre (each ring's vertex count grows with its length), a round hole of
                  2.2 cm at (3, -2) cm cut out, 0.3 mm of noise (seeded) along the normal, tilted
                  40 degrees about (0, 1, 1) and centred at (0.2, -0.1, 0.3).
  saddle_steep_turned: z = (x^2 - y^2) / 0.06 over an 18 cm square (slopes to 3 at the ends,
                  steeper than saddle_mm_thin), rows along the square's diagonal direction
                  turned 30 degrees about z, in metres at (0.05, 0.4, -0.1).

Usage: make_saddle_rings.py OUT_DIR   (numpy; writes OUT_DIR/NAME.obj and OUT_DIR/targets.tsv)
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_saddle_formulas import write as write_tuples, zip_rows  # noqa: E402


def offset_rows(half_x, half_y, spacing, height):
    """A rectangle in rows along x, every other row's inner vertices shifted by half a step."""
    positions, rows = [], []
    count_y = int(round(2 * half_y / spacing)) + 1
    for j in range(count_y):
        y = -half_y + 2 * half_y * j / (count_y - 1)
        count_x = int(round(2 * half_x / spacing)) + 1 + (j % 3)  # rows differ in count
        us = list(np.linspace(-half_x, half_x, count_x))
        if j % 2 == 1:  # shifted inner vertices, the ends kept on the outline
            us = [us[0]] + [u + 0.5 * (us[1] - us[0]) for u in us[:-1]][:-1] + [us[-1]]
            us = sorted(set(us))
        ids = []
        for x in us:
            ids.append(len(positions))
            positions.append((x, y, height(x, y)))
        rows.append((ids, us))
    return np.array(positions), zip_rows(rows)


def ellipse_rings(a, b, rings, spacing, height):
    """An ellipse meshed in rings about its centre (a fan at the middle), zipped ring to ring."""
    positions = [(0.0, 0.0, height(0.0, 0.0))]
    triangles, previous = [], None
    for r in range(1, rings + 1):
        s = r / rings
        length = 2 * np.pi * s * np.sqrt(0.5 * (a * a + b * b))
        count = max(6, int(round(length / spacing)))
        phase = 0.5 * (r % 2) * 2 * np.pi / count
        ids = []
        for i in range(count):
            t = phase + 2 * np.pi * i / count
            x, y = s * a * np.cos(t), s * b * np.sin(t)
            ids.append(len(positions))
            positions.append((x, y, height(x, y)))
        ts = [phase + 2 * np.pi * i / count for i in range(count)]
        if previous is None:
            triangles += [(0, ids[i], ids[(i + 1) % count]) for i in range(count)]
        else:
            # Zip the closed rings as open rows, each closed by repeating its first vertex.
            pa, pt = previous
            triangles += zip_rows([(pa + [pa[0]], pt + [pt[0] + 2 * np.pi]),
                                   (ids + [ids[0]], ts + [ts[0] + 2 * np.pi])])
        previous = (ids, ts)
    return np.array(positions), triangles


def facing_up(v, f):
    """Every triangle turned to face +z in the parameter plane (the zipped rows face either way)."""
    out = []
    for t in f:
        a, b, c = v[t[0], :2], v[t[1], :2], v[t[2], :2]
        area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        out.append(t if area > 0 else (t[0], t[2], t[1]))
    return out


def rotation(axis, degrees):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) * c + s * K + (1 - c) * np.outer(k, k)


def normals(v, f):
    n = np.zeros_like(v)
    f = np.asarray(f)
    fn = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    for c in range(3):
        np.add.at(n, f[:, c], fn)
    return n / np.maximum(np.linalg.norm(n, axis=1), 1e-30)[:, None]


def compact(v, f):
    used = sorted({i for t in f for i in t})
    index = {old: new for new, old in enumerate(used)}
    return v[used], [tuple(index[i] for i in t) for t in f]


def write(path, v, f):
    write_tuples(path, [tuple(p) for p in v], f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir")
    out = parser.parse_args().out_dir
    os.makedirs(out, exist_ok=True)
    rng = np.random.default_rng(2718)
    rows = []

    v, f = offset_rows(120.0, 80.0, 6.0, lambda x, y: x * y / 50.0)
    f = facing_up(v, f)
    v = v @ rotation([0, 0, 1], 35).T @ rotation([1, 0, 0], 20).T + [-300.0, 150.0, 80.0]
    write(os.path.join(out, "hypar_steep_mm.obj"), v, f)
    rows.append(("hypar_steep_mm", "square", len(v), len(f)))

    v, f = ellipse_rings(0.11, 0.08, 22, 0.006, lambda x, y: 2.2 * x * x - 3.5 * y * y)
    f = facing_up(v, f)
    hole = np.array([0.03, -0.02])
    f = [t for t in f if np.linalg.norm(v[list(t), :2].mean(axis=0) - hole) > 0.011]
    v, f = compact(v, f)
    v = v + normals(v, f) * rng.normal(0.0, 0.0003, (len(v), 1))
    v = v @ rotation([0, 1, 1], 40).T + [0.2, -0.1, 0.3]
    write(os.path.join(out, "saddle_ellipse_hole.obj"), v, f)
    rows.append(("saddle_ellipse_hole", "square", len(v), len(f)))

    v, f = offset_rows(0.09, 0.09, 0.005, lambda x, y: (x * x - y * y) / 0.06)
    f = facing_up(v, f)
    v = v @ rotation([0, 0, 1], 30).T + [0.05, 0.4, -0.1]
    write(os.path.join(out, "saddle_steep_turned.obj"), v, f)
    rows.append(("saddle_steep_turned", "square", len(v), len(f)))

    with open(os.path.join(out, "targets.tsv"), "w") as tsv:
        for name, kind, nv, nf in rows:
            tsv.write("%s\t%s\t%d\t%d\n" % (name, kind, nv, nf))
    for name, kind, nv, nf in rows:
        print("%-22s --from %-7s %6d v %6d f" % (name, kind, nv, nf))


if __name__ == "__main__":
    main()
