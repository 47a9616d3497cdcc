#!/usr/bin/python3
"""Bowls as a top-down line scanner sees them (issue 38, 2), as OBJ.

Written unlike the other generators (polar grids, hexagonal disks, numpy grids, spline or eased
profile tables, clipped triangle lattices): each mesh is a set of scan lines across the bowl seen
from above, the lines at irregular spacing and each line's points at irregular spacing (a
scanner's jitter), consecutive lines stitched by a zipper (each triangle joins the two lines,
advancing on whichever line is behind: triangles of unequal shapes, no rings, no lattice), the
points raised by a closed-form height and moved along z by noise, some triangles removed as holes
(occlusions), then the whole turned about an oblique axis and moved off the origin. Standard
library only; one fixed seed. Shapes:
  footed_cap     a 20 cm bowl: a flat foot 7 cm across, then a sphere's arc (radius 7.5 cm)
                 rising to a rim 3.8 cm above the foot (wall 60 degrees there), tilted 25 degrees,
                 noise 0.2% of its size, 4 holes;
  paraboloid_scan  an 18 cm paraboloid 6 cm deep, tilted 35 degrees the other way, noise 0.3%,
                 3 holes.
Usage: bench/make_scanline_bowls.py OUTDIR
"""
import math
import os
import random
import sys

rand = random.Random(38_2_8)


def footed_cap(r):
    foot, sphere = 0.035, 0.075
    if r <= foot:
        return 0.0
    # A sphere's arc whose lowest point lies on the foot's edge (the wall leaves the foot level).
    d = min(r - foot, sphere * 0.999)
    return sphere - math.sqrt(sphere * sphere - d * d)


def paraboloid(r):
    return 0.06 * (r / 0.09) ** 2


def scan(height, rim, line_step, point_step, noise):
    lines = []
    y = -rim + rand.uniform(0.2, 0.6) * line_step
    while y < rim:
        half = math.sqrt(max(rim * rim - y * y, 0.0))
        if half > 0.3 * point_step:
            xs = [-half]
            while xs[-1] + point_step * 1.5 < half:
                xs.append(xs[-1] + point_step * rand.uniform(0.6, 1.4))
            xs.append(half)
            lines.append([(x, y) for x in xs])
        y += line_step * rand.uniform(0.7, 1.3)
    points, rows = [], []
    for line in lines:
        row = []
        for x, y in line:
            r = math.hypot(x, y)
            z = height(r) + rand.gauss(0.0, noise)
            row.append(len(points))
            points.append((x, y, z))
        rows.append(row)
    triangles = []
    for a, b in zip(rows, rows[1:]):
        i = j = 0
        while i + 1 < len(a) or j + 1 < len(b):
            # Advance on the line whose next point lies less far along x.
            if j + 1 >= len(b) or (i + 1 < len(a) and points[a[i + 1]][0] <= points[b[j + 1]][0]):
                triangles.append((a[i], a[i + 1], b[j]))
                i += 1
            else:
                triangles.append((a[i], b[j + 1], b[j]))
                j += 1
    return points, triangles


def punch(points, triangles, holes, radius):
    kept = []
    centres = []
    for _ in range(holes):
        angle, r = rand.uniform(0, 2 * math.pi), rand.uniform(0.2, 0.8) * radius
        centres.append((r * math.cos(angle), r * math.sin(angle), rand.uniform(0.5, 1.0)))
    for t in triangles:
        cx = sum(points[v][0] for v in t) / 3
        cy = sum(points[v][1] for v in t) / 3
        if any(math.hypot(cx - hx, cy - hy) < 0.07 * radius * s for hx, hy, s in centres):
            continue
        kept.append(t)
    return kept


def place(points, axis, angle, offset):
    ax = [c / math.sqrt(sum(a * a for a in axis)) for c in axis]
    c, s = math.cos(angle), math.sin(angle)
    out = []
    for p in points:
        dot = sum(a * b for a, b in zip(ax, p))
        cross = (ax[1] * p[2] - ax[2] * p[1], ax[2] * p[0] - ax[0] * p[2],
                 ax[0] * p[1] - ax[1] * p[0])
        q = [p[i] * c + cross[i] * s + ax[i] * dot * (1 - c) + offset[i] for i in range(3)]
        out.append(q)
    return out


def write(path, points, triangles):
    used = sorted({v for t in triangles for v in t})
    index = {v: i + 1 for i, v in enumerate(used)}
    with open(path, "w") as f:
        f.write("# bench/make_scanline_bowls.py\n")
        for v in used:
            f.write("v %.6f %.6f %.6f\n" % tuple(points[v]))
        for t in triangles:
            f.write("f %d %d %d\n" % tuple(index[v] for v in t))
    print("wrote %s %d vertices %d triangles" % (path, len(used), len(triangles)))


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    points, triangles = scan(footed_cap, 0.10, 0.0055, 0.005, 0.0004)
    triangles = punch(points, triangles, 4, 0.10)
    write(os.path.join(out, "footed_cap.obj"),
          place(points, (1.0, 0.4, 0.0), math.radians(25), (0.3, -0.1, 0.05)), triangles)
    points, triangles = scan(paraboloid, 0.09, 0.005, 0.0045, 0.0005)
    triangles = punch(points, triangles, 3, 0.09)
    write(os.path.join(out, "paraboloid_scan.obj"),
          place(points, (-0.3, 1.0, 0.2), math.radians(-35), (-0.2, 0.15, 0.4)), triangles)


if __name__ == "__main__":
    main()
