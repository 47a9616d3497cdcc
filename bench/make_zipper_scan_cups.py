#!/usr/bin/python3
"""Steep cups as noisy scans stitched ring to ring, for `curvefold fit` (issue 38, 2), numpy.
Usage: bench/make_zipper_scan_cups.py OUTDIR [--seed N] (deterministic for a seed).

Unlike the other cup generators (a grid of rows and columns around the axis, a lattice, or an
implicit solid marched to tetrahedra), each cup here is meshed in its own unrolling: the meridian
from the floor's centre is measured by arc length s, and a point of the cup at (s, azimuth) lies
at s (cos, sin) of the azimuth in a disk, so floor, heel and wall are one disk. Rings of that disk
are drawn every h of arc, each with as many points as its circumference holds (so rings differ
in count: no columns), its points jittered in angle and the ring turned by a random phase; the
centre is one point fanned to the first ring, and each pair of neighbouring rings is stitched by
a zipper (whichever side's next point comes first in angle closes the next triangle), so the
triangles are as irregular as the rings' counts make them. Then every vertex is moved by
Gaussian noise, two holes are cut in the wall (triangles whose centre lies within a random sphere
dropped), and the cup is turned and moved off the origin.
- zipper_tumbler (metres): a floor of radius 2.8 cm, a heel rounded over 7 mm, a wall leaning 8
  degrees outward that bulges 2 mm at mid-height, 7.5 cm tall, noise 0.1 mm, tilted 55 degrees.
- zipper_stein_mm (mm): a near-upright stein (radius 40 mm at the floor, a heel of 12 mm, wall
  leaning 3 degrees), 95 mm deep with a 4 mm lip flared out over its last 10 mm, noise 0.25 mm,
  tilted 20 degrees.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from formula_meshes import folder_and_seed, place, write_obj  # noqa: E402


def meridian(floor, heel, lean_deg, height, bulge, lip, lip_height, steps=2000):
    """The cup's meridian from the floor's centre to the rim as (r, z) points, dense."""
    lean = math.tan(math.radians(lean_deg))
    pts = [(floor * t, 0.0) for t in np.linspace(0.0, 1.0, 200, endpoint=False)]
    for a in np.linspace(-math.pi / 2, 0.0, 200, endpoint=False):  # the heel's quarter circle
        pts.append((floor + heel * math.cos(a), heel + heel * math.sin(a)))
    wall = height - heel
    for t in np.linspace(0.0, 1.0, steps):
        z = heel + t * wall
        r = floor + heel + (z - heel) * lean + bulge * math.sin(math.pi * t)
        if z > height - lip_height:
            u = (z - (height - lip_height)) / lip_height
            r += lip * u * u
        pts.append((r, z))
    return np.array(pts)


def stitched_cup(rng, profile, spacing, noise, holes):
    """Vertices and triangles of the cup of revolution of `profile`, meshed as above."""
    seg = np.hypot(np.diff(profile[:, 0]), np.diff(profile[:, 1]))
    arc = np.concatenate([[0.0], np.cumsum(seg)])
    rings = []
    verts = [(0.0, 0.0, 0.0)]
    for s in np.arange(spacing, arc[-1] + 1e-12, spacing):
        r = float(np.interp(s, arc, profile[:, 0]))
        z = float(np.interp(s, arc, profile[:, 1]))
        n = max(6, int(round(2 * math.pi * r / spacing)))
        phase = rng.uniform(0.0, 2 * math.pi)
        angles = np.sort((phase + (np.arange(n) + rng.uniform(-0.3, 0.3, n)) * 2 * math.pi / n)
                         % (2 * math.pi))
        ring = []
        for a in angles:
            ring.append((len(verts), a))
            verts.append((r * math.cos(a), r * math.sin(a), z))
        rings.append(ring)
    tris = []
    first = rings[0]
    for i in range(len(first)):
        tris.append((0, first[(i + 1) % len(first)][0], first[i][0]))
    for inner, outer in zip(rings, rings[1:]):
        # Unwrap both rings' angles to start from the inner ring's first point.
        start = inner[0][1]
        a = [((ang - start) % (2 * math.pi), v) for v, ang in inner]
        b = sorted(((ang - start) % (2 * math.pi), v) for v, ang in outer)
        a.append((2 * math.pi, inner[0][0]))
        b.append((b[0][0] + 2 * math.pi, b[0][1]))
        i = j = 0
        while i < len(a) - 1 or j < len(b) - 1:
            take_inner = j >= len(b) - 1 or (i < len(a) - 1 and a[i + 1][0] <= b[j + 1][0])
            if take_inner:
                tris.append((a[i][1], a[i + 1][1], b[j][1]))
                i += 1
            else:
                tris.append((a[i][1], b[j + 1][1], b[j][1]))
                j += 1
    verts = np.array(verts) + rng.normal(0.0, noise, (len(verts), 3))
    keep = []
    for t in tris:
        c = verts[list(t)].mean(axis=0)
        if all(np.linalg.norm(c - centre) > radius for centre, radius in holes):
            keep.append(t)
    return verts, keep


def hole_on_wall(rng, profile, fraction, radius):
    """A sphere about a point of the wall at `fraction` of the height, at a random azimuth."""
    z = fraction * profile[-1, 1]
    r = float(np.interp(z, profile[400:, 1], profile[400:, 0]))
    a = rng.uniform(0.0, 2 * math.pi)
    return (np.array([r * math.cos(a), r * math.sin(a), z]), radius)


def write_cup(folder, name, comment, rng, profile, spacing, noise, hole_radius, yaw, tilt, shift):
    holes = [hole_on_wall(rng, profile, f, hole_radius) for f in (0.35, 0.7)]
    verts, tris = stitched_cup(rng, profile, spacing, noise, holes)
    # The cup stands along z here; `place` turns it about z, tilts it about x and moves it.
    placed = [place(tuple(v), yaw, tilt, shift) for v in verts]
    write_obj(os.path.join(folder, name + ".obj"), comment, "bench/make_zipper_scan_cups.py",
              placed, tris)
    print("%s: %d triangles" % (name, len(tris)))


def main():
    args, rng = folder_and_seed(__doc__, 24)
    folder = args.out
    tumbler = meridian(0.028, 0.007, 8.0, 0.075, 0.002, 0.0, 0.01)
    write_cup(folder, "zipper_tumbler", "a steep tumbler, zipper-stitched rings, noisy, two holes",
              rng, tumbler, 0.0035, 1e-4, 0.006, 30.0, 55.0, (0.12, -0.05, 0.3))
    stein = meridian(40.0, 12.0, 3.0, 95.0, 0.0, 4.0, 10.0)
    write_cup(folder, "zipper_stein_mm", "a stein in mm, zipper-stitched rings, noisy, two holes",
              rng, stein, 4.2, 0.25, 7.0, -40.0, 20.0, (30.0, 12.0, -8.0))


if __name__ == "__main__":
    main()
