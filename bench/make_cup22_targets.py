#!/usr/bin/python3
"""Steep round cups of a new kind for `curvefold fit` made apart from curvefold (issue 38, 2), numpy.
Usage: bench/make_cup22_targets.py OUTDIR [--seed N] (deterministic for a seed).

Unlike the other cup generators, the profile is a superellipse and the mesh is a lattice in
(azimuth, height), not in arc length: each meridian's points sit at even steps of height along
the wall and of radius across the bottom, so the triangles stretch where the heel turns, and the
quads are split along alternating diagonals.
- superellipse_cup_mm (mm): the lower half of |r / a|^p + |z / h|^p = 1 with p = 3.2 (a flat
  bottom rounding into an almost upright wall), a = 38 mm, depth 42 mm, turned 30 degrees about
  z and tilted 25 about x, moved off the origin.
- holed_cup (metres): p = 4.5 (steeper: the wall upright over its top two thirds), a = 3.3 cm,
  depth 4.8 cm, 0.25 mm of noise along each point's normal, a hole of 9 mm through the wall and
  another of 6 mm through the bottom, tilted 60 degrees (a scan of a tumbler with its handle
  sawn off).
- oval_super_cup (metres): p = 3.6, the cross-sections stretched 1.08 : 1 (not oblong enough to be
  read as oval), depth 5 cm on a 3.5 cm radius, the rim cut sloping by 3 mm around (a cup whose
  rim is not level).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from formula_meshes import folder_and_seed, place, vertex_normals, write_obj  # noqa: E402


def superellipse_cup(a, depth, p, azimuths, levels, rim_slope=0.0, stretch=1.0):
    """Points and triangles of the cup |r/a|^p + |z/depth - 1|^p = 1, z from 0 (bottom) to depth.

    Rows: `levels` heights up the wall (even in height) after `levels // 2` radii across the
    bottom's flat middle (even in radius); one apex at the centre."""
    rows = []  # each a list of (r, z) along one meridian row
    flat = a * 0.35
    for i in range(1, levels // 2 + 1):
        r = flat * i / (levels // 2)
        rows.append(r)
    verts = [(0.0, 0.0, 0.0)]
    profile = []
    for r in rows:  # bottom: z from the curve at r
        t = min(1.0, r / a)
        z = depth * (1.0 - (1.0 - t**p) ** (1.0 / p))
        profile.append((r, z))
    z0 = profile[-1][1]
    for j in range(1, levels + 1):
        z = z0 + (depth - z0) * j / levels
        u = 1.0 - z / depth
        r = a * (1.0 - abs(u) ** p) ** (1.0 / p)
        profile.append((r, z))
    ring_start = []
    for r, z in profile:
        ring_start.append(len(verts))
        for k in range(azimuths):
            phi = 2.0 * math.pi * k / azimuths
            dz = rim_slope * math.cos(phi) * z / depth
            verts.append((r * math.cos(phi) * stretch, r * math.sin(phi), z + dz))
    tris = []
    first = ring_start[0]
    for k in range(azimuths):
        tris.append((0, first + k, first + (k + 1) % azimuths))
    for i in range(len(profile) - 1):
        lo, hi = ring_start[i], ring_start[i + 1]
        for k in range(azimuths):
            a0, a1 = lo + k, lo + (k + 1) % azimuths
            b0, b1 = hi + k, hi + (k + 1) % azimuths
            if (i + k) % 2 == 0:
                tris += [(a0, a1, b1), (a0, b1, b0)]
            else:
                tris += [(a0, a1, b0), (a1, b1, b0)]
    return verts, tris


def main():
    args, rng = folder_and_seed(__doc__.splitlines()[0], 22)
    me = os.path.relpath(__file__)

    v, t = superellipse_cup(38.0, 42.0, 3.2, 72, 28)
    v = [place(p, 30.0, 25.0, (12.0, -7.0, 30.0)) for p in v]
    write_obj(os.path.join(args.out, "superellipse_cup_mm.obj"),
              "superellipse cup, p 3.2, 38 mm radius, 42 mm deep, in mm", me, v, t, "%.5f")

    v, t = superellipse_cup(0.033, 0.048, 4.5, 64, 30)
    n = vertex_normals(v, t)
    v = [[p[c] + 0.00025 * float(rng.standard_normal()) * n[i][c] for c in range(3)]
         for i, p in enumerate(v)]
    wall_hole = (0.033, 0.0, 0.030)
    bottom_hole = (0.012, 0.006, 0.0)

    def inside(p, centre, radius):
        return sum((p[c] - centre[c]) ** 2 for c in range(3)) < radius * radius

    kept = [tri for tri in t
            if not any(inside(v[i], wall_hole, 0.0045) or inside(v[i], bottom_hole, 0.003)
                       for i in tri)]
    v = [place(p, -15.0, 60.0, (0.02, 0.01, -0.01)) for p in v]
    write_obj(os.path.join(args.out, "holed_cup.obj"),
              "superellipse tumbler, p 4.5, noise 0.25 mm, holes in wall and bottom, metres",
              me, v, kept, "%.8f")

    v, t = superellipse_cup(0.035, 0.050, 3.6, 80, 26, rim_slope=0.003, stretch=1.08)
    v = [place(p, 70.0, -35.0, (-0.01, 0.0, 0.005)) for p in v]
    write_obj(os.path.join(args.out, "oval_super_cup.obj"),
              "superellipse cup stretched 1.08, rim sloping 3 mm, metres", me, v, t, "%.8f")


if __name__ == "__main__":
    main()
