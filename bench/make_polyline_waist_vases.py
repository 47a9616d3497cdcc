#!/usr/bin/python3
"""Vases with a waist under a flaring lip for `fit` (issue 38, 2), made apart from curvefold and
unlike the other generators: the profile is a polyline of a few knots drawn at random (foot,
belly, waist, lip; straight between knots, so its creases are corners, not a smooth curve), the
surface is the polyline turned about the axis as conical frusta, and each frustum band is meshed
as rows of quads around an odd number of azimuth steps, every quad split into four triangles about
a vertex at its centre put back on the surface (a "centre fan": valence-4 vertices beside
valence-8 ones, which no other generator writes). Standard library only.

polyline_waist_cm: centimetres, 24 cm tall, a waist at about 0.75 of the height of about 0.3 of
the belly, axis along (-1, 0.2, 0.1), moved off the origin; open ends.
polyline_waist_low_m: metres, 0.2 m tall, the waist lower (about 0.6) and wider (about 0.45 of
the belly) under a long flare, axis tilted off z, moved off the origin; open ends.

Also writes OUTDIR/targets.tsv (name, start kind, description, vertices, faces).

Usage: bench/make_polyline_waist_vases.py OUTDIR [--seed N]
"""
import argparse
import math
import os
import random


def knots(rng, waist_at, waist, lip):
    """The profile's knots (t in [0, 1], radius as a share of the belly's)."""
    belly_at = rng.uniform(0.28, 0.4)
    return [
        (0.0, rng.uniform(0.45, 0.6)),
        (belly_at - 0.12, rng.uniform(0.85, 0.93)),
        (belly_at, 1.0),
        (belly_at + 0.15, rng.uniform(0.75, 0.85)),
        (waist_at, waist * rng.uniform(0.95, 1.05)),
        (min(1.0, waist_at + 0.08), waist + 0.35 * (lip - waist)),
        (1.0, lip * rng.uniform(0.95, 1.05)),
    ]


def radius_at(ks, t):
    for (t0, r0), (t1, r1) in zip(ks, ks[1:]):
        if t <= t1 or (t1, r1) == ks[-1]:
            s = 0.0 if t1 == t0 else (t - t0) / (t1 - t0)
            return r0 + s * (r1 - r0)
    return ks[-1][1]


def rows(ks, rows_per_unit):
    """The heights of the mesh's rows: each knot, and between knots as many as the band's length
    along the profile asks (so the rows follow the polyline's corners exactly)."""
    ts = [ks[0][0]]
    for (t0, r0), (t1, r1) in zip(ks, ks[1:]):
        n = max(1, int(round(math.hypot(t1 - t0, r1 - r0) * rows_per_unit)))
        ts += [t0 + (t1 - t0) * k / n for k in range(1, n + 1)]
    return ts


def frame(axis):
    a = [c / math.sqrt(sum(x * x for x in axis)) for c in axis]
    helper = [1.0, 0.0, 0.0] if abs(a[0]) < 0.9 else [0.0, 1.0, 0.0]
    u = [helper[1] * a[2] - helper[2] * a[1], helper[2] * a[0] - helper[0] * a[2],
         helper[0] * a[1] - helper[1] * a[0]]
    nu = math.sqrt(sum(x * x for x in u))
    u = [x / nu for x in u]
    v = [a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2], a[0] * u[1] - a[1] * u[0]]
    return a, u, v


def vase(ks, height, belly, segments, rows_per_unit, axis, centre):
    a, u, v = frame(axis)

    def point(t, phi):
        r = belly * radius_at(ks, t)
        h = height * (t - 0.5)
        return [centre[i] + h * a[i] + r * (math.cos(phi) * u[i] + math.sin(phi) * v[i])
                for i in range(3)]

    ts = rows(ks, rows_per_unit)
    verts, faces = [], []
    for t in ts:
        for i in range(segments):
            verts.append(point(t, 2 * math.pi * i / segments))
    for j in range(len(ts) - 1):
        for i in range(segments):
            a0 = j * segments + i
            b0 = j * segments + (i + 1) % segments
            c0 = (j + 1) * segments + (i + 1) % segments
            d0 = (j + 1) * segments + i
            # The quad's centre, on the surface (the band's middle height, the middle angle).
            centre_index = len(verts)
            verts.append(point(0.5 * (ts[j] + ts[j + 1]), 2 * math.pi * (i + 0.5) / segments))
            faces += [(a0, b0, centre_index), (b0, c0, centre_index), (c0, d0, centre_index),
                      (d0, a0, centre_index)]
    return verts, faces


def write_obj(path, comment, verts, faces):
    tmp = path + ".tmp"
    with open(tmp, "w") as out:
        out.write(f"# {comment}\n")
        for p in verts:
            out.write("v %.9g %.9g %.9g\n" % tuple(p))
        for f in faces:
            out.write("f " + " ".join(str(i + 1) for i in f) + "\n")
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("outdir")
    ap.add_argument("--seed", type=int, default=23)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    os.makedirs(args.outdir, exist_ok=True)
    rows_out = []

    ks = knots(rng, rng.uniform(0.72, 0.78), 0.3, 0.7)
    v, f = vase(ks, 24.0, 7.5, 41, 60, (-1.0, 0.2, 0.1), (12.0, -3.0, 40.0))
    name = "polyline_waist_cm"
    write_obj(os.path.join(args.outdir, name + ".obj"),
              f"{name}: polyline profile {ks}, cm (bench/make_polyline_waist_vases.py)", v, f)
    rows_out.append((name, "cylinder", "polyline waist at 0.75 under a flaring lip, cm", len(v), len(f)))

    ks = knots(rng, rng.uniform(0.58, 0.62), 0.45, 0.8)
    v, f = vase(ks, 0.2, 0.07, 37, 50, (0.15, -0.2, 1.0), (0.3, 0.1, -0.2))
    name = "polyline_waist_low_m"
    write_obj(os.path.join(args.outdir, name + ".obj"),
              f"{name}: polyline profile {ks}, m (bench/make_polyline_waist_vases.py)", v, f)
    rows_out.append((name, "cylinder", "polyline waist at 0.6 under a long flare, m", len(v), len(f)))

    with open(os.path.join(args.outdir, "targets.tsv"), "w") as out:
        for r in rows_out:
            out.write("\t".join(str(x) for x in r) + "\n")
    for r in rows_out:
        print(*r, sep="\t")


if __name__ == "__main__":
    main()
