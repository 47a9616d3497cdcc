#!/usr/bin/python3
"""Smooth targets a designer brings, for `fit` (issue 38, 2), made apart from curvefold.

Standard library only, unlike the other generators: each surface is a quad strip over (around,
along) whose every quad is split along a diagonal chosen at random, the rings rotated by a random
phase each (so no meridian is a line of edges), axes along odd directions, and noise added along
the surface normal. Writes OUTDIR/NAME.obj for:
  lamp_bulge_scan  a lampshade that bulges at two thirds of its height, 24 cm tall, axis along
                   (0.3, 1, 0.2), noise 0.3% of the diagonal along the normal, six triangles removed
  cone_lamp        a conical lamp 16 cm tall, 4 cm across at the top, 26 cm at the bottom, its
                   side slightly concave, axis along -z
  dish_tilted      a shallow dish 30 cm across and 2.5 cm deep with a flat middle (a tanh
                   profile), axis tilted 50 degrees
Usage: bench/make_designer_shapes.py OUTDIR
"""
import math
import os
import random
import sys

rnd = random.Random(20261205 + 5)


def normalized(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def frame(axis):
    """Two unit vectors across `axis` and the axis itself."""
    w = normalized(axis)
    helper = [1.0, 0.0, 0.0] if abs(w[0]) < 0.8 else [0.0, 1.0, 0.0]
    u = normalized(cross(helper, w))
    v = cross(w, u)
    return u, v, w


def revolve(radius, height, rings, around, axis, closed_centre=False):
    """Vertices radius(t) about the axis at height(t), t in [0, 1] over `rings` rings."""
    u, v, w = frame(axis)
    verts = []
    for j in range(rings + 1):
        t = j / rings
        phase = rnd.uniform(0.0, 2.0 * math.pi / around)
        r, h = radius(t), height(t)
        for i in range(around):
            a = phase + 2.0 * math.pi * i / around
            c, s = math.cos(a) * r, math.sin(a) * r
            verts.append([c * u[k] + s * v[k] + h * w[k] for k in range(3)])
    faces = []
    for j in range(rings):
        for i in range(around):
            a = j * around + i
            b = j * around + (i + 1) % around
            c = (j + 1) * around + (i + 1) % around
            d = (j + 1) * around + i
            if rnd.random() < 0.5:
                faces += [(a, b, c), (a, c, d)]
            else:
                faces += [(a, b, d), (b, c, d)]
    if closed_centre:  # a fan over ring 0 to a centre vertex
        centre = len(verts)
        h0 = height(0.0)
        verts.append([h0 * w[k] for k in range(3)])
        for i in range(around):
            faces.append((centre, (i + 1) % around, i))
    return verts, faces


def diagonal(verts):
    lo = [min(p[k] for p in verts) for k in range(3)]
    hi = [max(p[k] for p in verts) for k in range(3)]
    return math.sqrt(sum((hi[k] - lo[k]) ** 2 for k in range(3)))


def vertex_normals(verts, faces):
    normals = [[0.0, 0.0, 0.0] for _ in verts]
    for f in faces:
        p = [verts[i] for i in f]
        n = cross([p[1][k] - p[0][k] for k in range(3)], [p[2][k] - p[0][k] for k in range(3)])
        for i in f:
            for k in range(3):
                normals[i][k] += n[k]
    return [normalized(n) if any(n) else [0.0, 0.0, 1.0] for n in normals]


def scan(verts, faces, noise_fraction, holes):
    """Noise along the normal (a fraction of the diagonal) and `holes` triangles removed."""
    sigma = noise_fraction * diagonal(verts)
    normals = vertex_normals(verts, faces)
    noisy = [[p[k] + rnd.gauss(0.0, sigma) * n[k] for k in range(3)] for p, n in zip(verts, normals)]
    kept = list(faces)
    for _ in range(holes):
        kept.pop(rnd.randrange(len(kept) // 5, len(kept) * 4 // 5))
    return noisy, kept


def write(path, comment, verts, faces):
    tmp = path + ".tmp"
    with open(tmp, "w") as out:
        out.write("# " + comment + "\n")
        for p in verts:
            out.write("v %.6f %.6f %.6f\n" % tuple(p))
        for f in faces:
            out.write("f %d %d %d\n" % (f[0] + 1, f[1] + 1, f[2] + 1))
    os.replace(tmp, path)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_designer_shapes.py OUTDIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)

    # A lampshade: narrowing upward, with a bulge at two thirds of its height.
    verts, faces = revolve(lambda t: 0.10 - 0.035 * t + 0.022 * math.exp(-((t - 0.65) / 0.18) ** 2),
                           lambda t: 0.24 * t, 30, 56, (0.3, 1.0, 0.2))
    verts, faces = scan(verts, faces, 0.003, 6)
    write(os.path.join(out, "lamp_bulge_scan.obj"),
          "lampshade with a bulge, scanned: noise 0.3% of the diagonal, 6 triangles removed",
          verts, faces)

    # A cone-like lamp: 2 cm radius at the top, 13 cm at the bottom, its side sagging inward.
    verts, faces = revolve(lambda t: 0.02 + 0.11 * t - 0.012 * math.sin(math.pi * t),
                           lambda t: -0.16 * t, 24, 48, (0.0, 0.0, -1.0))
    write(os.path.join(out, "cone_lamp.obj"), "conical lamp, concave side", verts, faces)

    # A shallow dish with a flat middle, 15 cm in radius, 2.5 cm deep, tilted.
    tilt = math.radians(50.0)
    verts, faces = revolve(lambda t: 0.005 + 0.145 * t,
                           lambda t: 0.025 * (1.0 + math.tanh((t - 0.75) / 0.12)) / 2.0,
                           20, 60, (math.sin(tilt), 0.0, math.cos(tilt)), closed_centre=True)
    write(os.path.join(out, "dish_tilted.obj"), "shallow dish, flat middle, tilted 50 degrees",
          verts, faces)


if __name__ == "__main__":
    main()
