#!/usr/bin/python3
"""Vases with an elliptic cross-section for `fit` (issue 38, 2), made apart from curvefold and unlike
the other generators (make_revolution_targets.py: Catmull-Rom rings; make_smooth_targets.py: numpy
grids; make_vase_targets.awk: Bezier and sine profiles; make_spiral_vases.py: one helix): the
Python standard library only, the profile a sum of Gaussian bumps on a taper, the cross-section an
ellipse (not a circle: the target is only nearly of revolution), rings of vertices whose count
follows the ring's circumference (fan triangles between rings of unequal counts), an axis tilted
off every coordinate axis and an offset centre.

Usage: bench/make_gourd_vases.py OUTDIR
Writes gourd_elliptic.obj (two bellies and a waist, ellipse 1 : 0.88, 24 cm) and
flask_elliptic.obj (a round body into a long narrow neck, ellipse 1 : 0.92, 22 cm, with a hole).
"""
import math
import os
import sys


def gourd(t):
    """Height 0..0.24 m; radius: a lower belly of 7 cm, a waist of 3.6 cm, an upper belly of 5 cm."""
    h = 0.24 * t
    r = 0.028 + 0.045 * math.exp(-((t - 0.28) / 0.17) ** 2) + 0.025 * math.exp(-((t - 0.76) / 0.12) ** 2)
    return h, r


def flask(t):
    """Height 0..0.22 m: a round body 8 cm wide at a fifth of the height into a neck of 2.2 cm."""
    h = 0.22 * t
    r = 0.022 + 0.058 * math.exp(-((t - 0.3) / 0.22) ** 2)
    return h, r


def rotate(p, axis, degrees):
    a = math.radians(degrees)
    n = math.sqrt(sum(c * c for c in axis))
    k = [c / n for c in axis]
    c, s = math.cos(a), math.sin(a)
    d = sum(k[i] * p[i] for i in range(3))
    cross = (k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0])
    return tuple(p[i] * c + cross[i] * s + k[i] * d * (1 - c) for i in range(3))


def shape(profile, squash, rings, spacing, axis, degrees, offset, hole=None):
    verts, faces, starts = [], [], []
    for j in range(rings + 1):
        h, r = profile(j / rings)
        count = max(12, int(round(2 * math.pi * r / spacing)))
        starts.append((len(verts), count))
        phase = 0.5 * j  # rings turned by half a step each: no column of vertices
        for i in range(count):
            a = 2 * math.pi * (i + phase) / count
            p = (r * math.cos(a), h, squash * r * math.sin(a))
            q = rotate(p, axis, degrees)
            verts.append(tuple(q[k] + offset[k] for k in range(3)))
    for j in range(rings):
        (s0, n0), (s1, n1) = starts[j], starts[j + 1]
        i0 = i1 = 0
        # March around both rings at once, each triangle advancing the ring that lags in angle.
        while i0 < n0 or i1 < n1:
            if i1 >= n1 or (i0 < n0 and (i0 + 1) / n0 <= (i1 + 1) / n1):
                faces.append((s0 + i0 % n0, s0 + (i0 + 1) % n0, s1 + i1 % n1))
                i0 += 1
            else:
                faces.append((s0 + i0 % n0, s1 + (i1 + 1) % n1, s1 + i1 % n1))
                i1 += 1
    if hole:
        centre, radius = hole
        faces = [f for f in faces
                 if math.dist([sum(verts[v][k] for v in f) / 3 for k in range(3)], centre) > radius]
    return verts, faces


def write(path, comment, verts, faces):
    used = sorted({v for f in faces for v in f})
    index = {v: i + 1 for i, v in enumerate(used)}
    with open(path, "w") as out:
        out.write("# %s (bench/make_gourd_vases.py)\n" % comment)
        for v in used:
            out.write("v %.6f %.6f %.6f\n" % verts[v])
        for f in faces:
            out.write("f %d %d %d\n" % tuple(index[v] for v in f))
    print("wrote %s %d vertices %d triangles" % (path, len(used), len(faces)))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_gourd_vases.py OUTDIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    verts, faces = shape(gourd, 0.88, 48, 0.006, (1.0, 0.3, 0.5), 40.0, (0.3, -0.1, 0.05))
    write(os.path.join(out, "gourd_elliptic.obj"),
          "a gourd, two bellies and a waist, elliptic 1 : 0.88, axis tilted 40 degrees", verts, faces)
    # The hole: on the body's wide side, 1.5 cm across (a scanner's gap).
    centre = rotate((0.07, 0.06, 0.0), (0.2, 0.1, 1.0), -25.0)
    verts, faces = shape(flask, 0.92, 40, 0.007, (0.2, 0.1, 1.0), -25.0, (0.0, 0.0, 0.0),
                         hole=(centre, 0.015))
    write(os.path.join(out, "flask_elliptic.obj"),
          "a flask, round body into a long neck, elliptic 1 : 0.92, axis tilted 25 degrees, one hole",
          verts, faces)


if __name__ == "__main__":
    main()
