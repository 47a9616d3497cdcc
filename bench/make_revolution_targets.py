#!/usr/bin/python3
"""Surfaces of revolution for `fit` (issue 38, 2), made apart from curvefold and unlike the other
generators (scripts/make-example-targets.sh: awk grids; bench/make_smooth_targets.py: numpy
grids): the Python standard library only, profiles given as (height, radius) polylines smoothed
by Catmull-Rom splines, rings of vertices staggered by half a step (equilateral-ish triangles,
no quads split along a diagonal), each shape at its own resolution, scale and axis.

Usage: bench/make_revolution_targets.py OUTDIR
Writes lampshade_bulge.obj, wine_glass.obj, shallow_dish.obj, urn_tilted.obj, pot_coarse.obj.
"""
import math
import os
import sys


def catmull_rom(points, per_segment):
    """A smooth curve through (h, r) points, `per_segment` steps between each pair."""
    padded = [points[0]] + list(points) + [points[-1]]
    out = []
    for i in range(1, len(padded) - 2):
        p0, p1, p2, p3 = padded[i - 1], padded[i], padded[i + 1], padded[i + 2]
        for s in range(per_segment):
            t = s / per_segment
            out.append(tuple(
                0.5 * (2 * p1[k] + (-p0[k] + p2[k]) * t + (2 * p0[k] - 5 * p1[k] + 4 * p2[k] - p3[k]) * t * t +
                       (-p0[k] + 3 * p1[k] - 3 * p2[k] + p3[k]) * t ** 3) for k in range(2)))
    out.append(points[-1])
    return out


def revolve(profile, around, axis_tilt_degrees=0.0, tilt_about=(1.0, 0.0, 0.0), offset=(0, 0, 0)):
    """Rings of `around` vertices at each profile point, alternate rings turned by half a step; the
    axis is z, then tilted about `tilt_about` and moved by `offset`."""
    a = math.radians(axis_tilt_degrees)
    kx, ky, kz = tilt_about
    n = math.sqrt(kx * kx + ky * ky + kz * kz)
    kx, ky, kz = kx / n, ky / n, kz / n

    def rotate(p):  # Rodrigues
        x, y, z = p
        c, s = math.cos(a), math.sin(a)
        dot = kx * x + ky * y + kz * z
        cx, cy, cz = ky * z - kz * y, kz * x - kx * z, kx * y - ky * x
        return tuple(v * c + w * s + k * dot * (1 - c) + o
                     for v, w, k, o in zip((x, y, z), (cx, cy, cz), (kx, ky, kz), offset))

    verts, faces = [], []
    for j, (h, r) in enumerate(profile):
        shift = 0.5 if j % 2 else 0.0
        for i in range(around):
            phi = 2 * math.pi * (i + shift) / around
            verts.append(rotate((r * math.cos(phi), r * math.sin(phi), h)))
    centre_rings = []
    for j in range(len(profile) - 1):
        for i in range(around):
            a0, a1 = j * around + i, j * around + (i + 1) % around
            b0, b1 = (j + 1) * around + i, (j + 1) * around + (i + 1) % around
            if j % 2 == 0:  # the ring above is turned forward by half a step
                faces += [(a0, a1, b0), (a1, b1, b0)]
            else:  # this ring is the turned one
                faces += [(a0, b1, b0), (a0, a1, b1)]
    return verts, faces


def write(path, comment, verts, faces):
    with open(path, "w") as out:
        out.write("# %s (bench/make_revolution_targets.py)\n" % comment)
        for v in verts:
            out.write("v %.7f %.7f %.7f\n" % v)
        for f in faces:
            out.write("f %d %d %d\n" % (f[0] + 1, f[1] + 1, f[2] + 1))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_revolution_targets.py OUTDIR")
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    shapes = {
        # A drum lampshade with a bulge two thirds up: 24 cm tall, 9 cm radius at the ends,
        # 12 cm at the bulge; along z.
        "lampshade_bulge": ("a lampshade bulging two thirds up", catmull_rom(
            [(-0.12, 0.09), (-0.04, 0.095), (0.04, 0.12), (0.09, 0.105), (0.12, 0.09)], 10), 56,
            0.0, (1, 0, 0), (0, 0, 0)),
        # A wine glass's bowl (no stem): narrow at the bottom, widest in the middle, closing in a
        # little at the rim; 12 cm tall, axis tilted 30 degrees about x.
        "wine_glass": ("the bowl of a wine glass, its axis tilted", catmull_rom(
            [(0.0, 0.012), (0.02, 0.035), (0.06, 0.045), (0.1, 0.041), (0.12, 0.038)], 8), 40,
            30.0, (1, 0, 0), (0.01, -0.02, 0.0)),
        # A shallow dish: a flat bottom of 6 cm radius rising to a rim 14 cm out, 2.5 cm high.
        "shallow_dish": ("a shallow dish with a flat bottom", catmull_rom(
            [(0.0, 0.005), (0.0, 0.06), (0.008, 0.1), (0.025, 0.14)], 10), 72,
            0.0, (1, 0, 0), (0, 0, 0)),
        # An urn: belly, waist and a flared mouth, 30 cm tall, lying along x.
        "urn_tilted": ("an urn with a waist and a flared mouth, lying along x", catmull_rom(
            [(-0.15, 0.05), (-0.08, 0.1), (0.0, 0.08), (0.08, 0.05), (0.15, 0.08)], 8), 48,
            90.0, (0, 1, 0), (0, 0, 0)),
        # A flower pot widening upward, coarse (16 around, 6 rings).
        "pot_coarse": ("a coarse flower pot", catmull_rom(
            [(0.0, 0.05), (0.07, 0.065), (0.14, 0.085)], 3), 16, 0.0, (1, 0, 0), (0, 0, 0)),
    }
    for name, (comment, profile, around, tilt, about, offset) in shapes.items():
        verts, faces = revolve(profile, around, tilt, about, offset)
        write(os.path.join(outdir, name + ".obj"), comment, verts, faces)


if __name__ == "__main__":
    main()
