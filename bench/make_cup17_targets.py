#!/usr/bin/python3
"""Steep round cups for `curvefold fit` made apart from curvefold (issue 38, 2), in pure Python.

Unlike the other bowl generators (a formula on a grid, a lattice or scattered points), each
azimuth has its own meridian: a flat bottom (or none), a rounded heel (a circular arc), then a
straight wall at an angle that varies around the axis, cut at one height so the rim is level. The
mesh is rings spun at even steps of each meridian's own length, each ring with as many points as
its circumference holds (so rings differ in count and are turned against each other), stitched
ring to ring by a merge on the azimuth, the centre a fan.
  flare_cup_mm.obj       millimetres: a bottom 52 mm across, a 10 mm heel, the wall 76 degrees
                         varying by 3 around the axis (three lobes), 55 mm deep; turned 25
                         degrees, off the origin;
  round_bottom_cup.obj   metres: no flat bottom, a round heel of 3 cm radius turning into a wall
                         of 82 degrees, about 6.8 cm across and 5.5 deep; tilted 40 degrees about
                         an oblique axis;
  beaker_mm.obj          millimetres: a coarse mesh (about 700 triangles) with 0.2 mm of noise,
                         a bottom 60 mm across, a 6 mm heel, the wall 82 degrees (78 to 86 around
                         the axis, one lobe), 70 mm deep: deeper than its bottom is wide.
Usage: bench/make_cup17_targets.py OUTDIR [--seed N] (deterministic for a seed).
"""
import argparse
import math
import os
import random

from formula_meshes import place, write_obj


def meridian(bottom, heel, wall, depth):
    """(r, z) along a meridian at arc length s, with its length: flat to `bottom`, a circular heel
    of radius `heel` turning to `wall` radians, then straight up to height `depth`."""
    arc = heel * wall
    rise = heel * (1.0 - math.cos(wall))
    straight = (depth - rise) / math.sin(wall)

    def at(s):
        if s <= bottom:
            return s, 0.0
        if s <= bottom + arc:
            a = (s - bottom) / heel
            return bottom + heel * math.sin(a), heel * (1.0 - math.cos(a))
        t = s - bottom - arc
        return (bottom + heel * math.sin(wall) + t * math.cos(wall), rise + t * math.sin(wall))

    return at, bottom + arc + straight


def spun_cup(bottom, heel, wall_of, depth, rings, spacing, rng):
    """Vertices and triangles: rings at fractions of each azimuth's meridian length."""
    verts = [(0.0, 0.0, 0.0)]
    tris = []
    previous = [0]  # the centre
    previous_az = [0.0]
    for i in range(1, rings + 1):
        t = i / rings
        mean_r = 0.0
        for k in range(8):
            at, length = meridian(bottom, heel, wall_of(2.0 * math.pi * k / 8), depth)
            mean_r += at(t * length)[0] / 8
        count = max(6, int(round(2.0 * math.pi * mean_r / spacing)))
        offset = rng.random() * 2.0 * math.pi / count
        ring, azimuths = [], []
        for j in range(count):
            a = offset + 2.0 * math.pi * j / count
            at, length = meridian(bottom, heel, wall_of(a), depth)
            r, z = at(t * length)
            ring.append(len(verts))
            azimuths.append(a)
            verts.append((r * math.cos(a), r * math.sin(a), z))
        if len(previous) == 1:
            for j in range(count):
                tris.append((0, ring[(j + 1) % count], ring[j]))
        else:
            tris += stitch(previous, previous_az, ring, azimuths)
        previous, previous_az = ring, azimuths
    return verts, tris


def stitch(inner, inner_az, outer, outer_az):
    """Triangles between two closed rings of any counts, merged by azimuth (both increasing)."""
    def unwrap(az, start):
        return [a if a >= start else a + 2.0 * math.pi for a in az]

    start = min(inner_az[0], outer_az[0])
    ia, oa = unwrap(inner_az, start), unwrap(outer_az, start)
    io = sorted(range(len(inner)), key=lambda j: ia[j])
    oo = sorted(range(len(outer)), key=lambda j: oa[j])
    i = o = 0
    n, m = len(inner), len(outer)
    tris = []
    while i < n or o < m:
        a, b = inner[io[i % n]], outer[oo[o % m]]
        next_i = ia[io[(i + 1) % n]] + (2.0 * math.pi if i + 1 >= n else 0.0)
        next_o = oa[oo[(o + 1) % m]] + (2.0 * math.pi if o + 1 >= m else 0.0)
        if o < m and (i >= n or next_o <= next_i):
            tris.append((a, outer[oo[(o + 1) % m]], b))
            o += 1
        else:
            tris.append((a, inner[io[(i + 1) % n]], b))
            i += 1
    return tris


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=17)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    os.makedirs(args.out, exist_ok=True)
    me = "bench/make_cup17_targets.py"
    deg = math.radians

    phase = rng.random() * 2.0 * math.pi
    verts, tris = spun_cup(26.0, 10.0, lambda a: deg(76.0 + 3.0 * math.sin(3.0 * a + phase)), 55.0,
                           34, 2.6, rng)
    verts = [place(v, 25.0, 0.0, (140.0, -35.0, 60.0)) for v in verts]
    write_obj(os.path.join(args.out, "flare_cup_mm.obj"),
              "steep cup in mm, wall 73-79 degrees in three lobes", me, verts, tris)

    verts, tris = spun_cup(0.0, 0.03, lambda a: deg(82.0), 0.055, 30, 0.0028, rng)
    verts = [place(place(v, 35.0, 40.0, (0.0, 0.0, 0.0)), -20.0, 0.0, (0.02, 0.01, -0.03))
             for v in verts]
    write_obj(os.path.join(args.out, "round_bottom_cup.obj"),
              "round-bottomed cup in metres, no flat bottom", me, verts, tris)

    phase = rng.random() * 2.0 * math.pi
    verts, tris = spun_cup(30.0, 6.0, lambda a: deg(82.0 + 4.0 * math.sin(a + phase)), 70.0, 14,
                           8.0, rng)
    verts = [tuple(c + rng.gauss(0.0, 0.2) for c in v) for v in verts]
    verts = [place(v, -60.0, 15.0, (0.0, 0.0, 0.0)) for v in verts]
    write_obj(os.path.join(args.out, "beaker_mm.obj"),
              "beaker in mm, wall 78-86 degrees, coarse, noisy", me, verts, tris)


if __name__ == "__main__":
    main()
