#!/usr/bin/python3
"""Cup targets for `curvefold fit` made apart from curvefold (issue 38, 2), in pure Python.

Unlike the other bowl generators (a radius or height formula swept on rings or grids), each
meridian is written as its wall's angle along its own arc length s: flat (0 degrees) across the
bottom, a rounded heel (the angle rising smoothly over a fillet), then a wall whose angle follows
a random smooth function (a few sine terms of random phase). The mesh is not gridded: points
scattered by dart throwing (uneven density) in the disk of the meridian's length, each point at
distance s from the centre and azimuth a placed at the meridian's (r(s), z(s)) turned by a, joined
by a Delaunay triangulation of the disk (bench/make_saddle_delaunay.py's).
  wavy_cup_mm.obj     millimetres: a bottom 50 mm across, a 12 mm heel, a wall of 74 degrees
                      that wavers by up to 9 degrees, about 60 mm deep; tilted 20 degrees, off
                      the origin;
  fillet_cup.obj      metres: a small cup 7 cm across, a bottom 2.4 cm across and a heel 2.5 cm
                      long (of a 6.9 cm meridian), the wall 80 degrees wavering by 5, 4.6 cm deep;
  tulip_cup.obj       metres: a narrow bottom 3 cm across, a 1 cm heel, the wall steepening from
                      60 to 82 degrees and flaring out to 68 at the lip, about 7.7 cm across and
                      6 deep, turned 65 degrees about an oblique axis, points twice as dense on
                      one side.
Usage: bench/make_cup16_targets.py OUTDIR [--seed N] (deterministic for a seed).
"""
import argparse
import math
import os
import random

from formula_meshes import place, write_obj
from make_saddle_delaunay import darts, delaunay


def meridian(bottom, heel, wall, length, steps=4000):
    """(s, r, z) along a meridian of arc length `length`: flat to s = bottom, the angle rising
    over a quarter-circle-like heel of arc `heel` to wall(s) (radians from the bottom's plane)."""
    out, r, z = [(0.0, 0.0, 0.0)], 0.0, 0.0
    ds = length / steps
    for i in range(steps):
        s = (i + 0.5) * ds
        if s < bottom:
            angle = 0.0
        elif s < bottom + heel:
            t = (s - bottom) / heel
            angle = wall(s) * (3 * t * t - 2 * t ** 3)  # smooth start and end
        else:
            angle = wall(s)
        r += ds * math.cos(angle)
        z += ds * math.sin(angle)
        out.append(((i + 1) * ds, r, z))
    return out


def wavering(base, amplitude, terms, rng, length):
    """An angle function base(s) plus a random smooth wave of at most `amplitude` radians."""
    waves = [(rng.uniform(0.5, 2.5) * 2 * math.pi / length, rng.uniform(0, 2 * math.pi),
              rng.uniform(0.3, 1.0)) for _ in range(terms)]
    total = sum(w for _, _, w in waves)
    return lambda s: base(s) + amplitude * sum(w * math.sin(k * s + p) for k, p, w in waves) / total


def at(table, s):
    """The meridian's (r, z) at arc length s (linear between the table's steps)."""
    step = table[1][0]
    i = min(int(s / step), len(table) - 2)
    f = (s - table[i][0]) / step
    return (table[i][1] + f * (table[i + 1][1] - table[i][1]),
            table[i][2] + f * (table[i + 1][2] - table[i][2]))


def cup(table, spacing, rng, rim_count):
    """Scattered points over the disk of the meridian's length, lifted onto the cup."""
    length = table[-1][0]
    # The rim's points moved inward at random by up to 0.3% (points on one circle tie Delaunay).
    pts = [(length * (1 - 0.003 * rng.random()) * math.cos(a),
            length * (1 - 0.003 * rng.random()) * math.sin(a))
           for a in (2 * math.pi * k / rim_count for k in range(rim_count))]
    pts += [q for q in darts(lambda x, y: math.hypot(x, y) < 0.97 * length,
                             ((-length, -length), (length, length)), spacing, rng, 12000)]
    # Triangulated in the unit disk: delaunay's enclosing triangle spans 100 units.
    tris = delaunay([(x / length, y / length) for x, y in pts])
    verts = []
    for x, y in pts:
        s = math.hypot(x, y)
        r, z = at(table, s)
        c, d = (x / s, y / s) if s > 0 else (1.0, 0.0)
        verts.append((r * c, r * d, z))
    return verts, tris


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("dir")
    parser.add_argument("--seed", type=int, default=16)
    args = parser.parse_args()
    os.makedirs(args.dir, exist_ok=True)
    rng = random.Random(args.seed)
    deg = math.pi / 180
    source = "bench/make_cup16_targets.py"

    # Millimetres: a flat bottom 50 mm across, a heel, a wavering 74 degree wall, 62 mm deep.
    wall = wavering(lambda s: 74 * deg, 9 * deg, 3, rng, 70.0)
    table = meridian(25.0, 12.0, wall, 25.0 + 12.0 + 55.0)
    verts, tris = cup(table, lambda x, y: 4.2 + 1.2 * (x + 100) / 200, rng, 90)
    verts = [place(p, 35, 20, (40.0, -25.0, 12.0)) for p in verts]
    write_obj(os.path.join(args.dir, "wavy_cup_mm.obj"),
              "a cup in mm, a heel and a wall wavering about 74 degrees, scattered points",
              source, verts, tris)

    # Metres: a long heel (2.5 cm of a 6.9 cm meridian), the wall about 80.
    wall = wavering(lambda s: 80 * deg, 5 * deg, 2, rng, 0.05)
    table = meridian(0.012, 0.025, wall, 0.012 + 0.025 + 0.032)
    verts, tris = cup(table, lambda x, y: 0.0036, rng, 72)
    write_obj(os.path.join(args.dir, "fillet_cup.obj"),
              "a small cup, a rounded heel, a wall about 80 degrees, scattered points", source,
              verts, tris)

    # Metres: a narrow bottom, the wall steepening 60 -> 82 degrees, then a lip flaring to 68.
    def tulip(s):
        t = min(max((s - 0.025) / 0.05, 0.0), 1.0)
        return (60 + 22 * math.sin(math.pi * 0.5 * min(t / 0.7, 1.0)) - 14 * max(t - 0.7, 0) / 0.3) * deg
    wall = wavering(tulip, 3 * deg, 2, rng, 0.07)
    table = meridian(0.015, 0.01, wall, 0.015 + 0.01 + 0.055)
    verts, tris = cup(table, lambda x, y: 0.0028 if x > 0 else 0.0042, rng, 80)
    verts = [place(p, 65, -65, (0.3, 0.12, -0.05)) for p in verts]
    write_obj(os.path.join(args.dir, "tulip_cup.obj"),
              "a tulip cup: wall 60 -> 82 -> 68 degrees, tilted, uneven scattered points", source,
              verts, tris)


if __name__ == "__main__":
    main()
