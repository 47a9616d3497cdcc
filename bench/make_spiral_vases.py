#!/usr/bin/python3
"""Vases for `fit` (issue 38, 2), made apart from curvefold and unlike the other generators
(scripts/make-example-targets.sh: awk rings about y; bench/make_smooth_targets.py: numpy grids;
bench/make_revolution_targets.py: Catmull-Rom rings; bench/make_vase_targets.awk: Bezier and sine
rings): the Python standard library only, the surface wound as ONE helix of vertices (each turn a
little higher than the last, triangles in a strip between consecutive turns: no ring of edges
lies in a plane), profiles from closed forms (a Gaussian waist, a teardrop bottle with a neck and
a rolled lip, an ogee), axes along oblique directions, one shape with noise along the normal.

Usage: bench/make_spiral_vases.py OUTDIR
Writes spiral_urn_oblique.obj, spiral_bottle_x.obj, spiral_ogee_noisy.obj.
"""
import math
import os
import random
import sys


def helix(profile, turns, per_turn, axis, offset=(0.0, 0.0, 0.0), noise=0.0, seed=7):
    """Vertices at angle 2 pi k / per_turn and profile parameter k / (turns * per_turn) (so the
    height climbs with the angle), the axis z turned onto `axis`; a strip of triangles joins vertex
    k to k + 1 and k + per_turn."""
    rnd = random.Random(seed)
    ax = [c / math.sqrt(sum(c * c for c in axis)) for c in axis]
    # A frame (u, v, ax) with ax as its third direction.
    helper = (1.0, 0.0, 0.0) if abs(ax[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = [helper[1] * ax[2] - helper[2] * ax[1], helper[2] * ax[0] - helper[0] * ax[2],
         helper[0] * ax[1] - helper[1] * ax[0]]
    n = math.sqrt(sum(c * c for c in u))
    u = [c / n for c in u]
    v = [ax[1] * u[2] - ax[2] * u[1], ax[2] * u[0] - ax[0] * u[2], ax[0] * u[1] - ax[1] * u[0]]
    count = turns * per_turn + 1
    verts = []
    for k in range(count):
        t = k / (count - 1)
        h, r = profile(t)
        r += noise * rnd.gauss(0.0, 1.0)
        a = 2.0 * math.pi * k / per_turn
        c, s = r * math.cos(a), r * math.sin(a)
        verts.append(tuple(c * u[i] + s * v[i] + h * ax[i] + offset[i] for i in range(3)))
    faces = []
    for k in range(count - per_turn - 1):
        faces.append((k, k + 1, k + per_turn))
        faces.append((k + 1, k + per_turn + 1, k + per_turn))
    return verts, faces


def urn(t):
    """30 cm tall: a belly of 10 cm, a Gaussian waist of 5.5 cm at two thirds, a flared mouth."""
    h = -0.15 + 0.3 * t
    r = 0.075 + 0.025 * math.sin(math.pi * t) - 0.035 * math.exp(-((t - 0.68) / 0.12) ** 2)
    return h, r + 0.02 * t * t


def bottle(t):
    """A teardrop bottle 24 cm tall: a 7 cm body narrowing to a 1.8 cm neck, then a rolled lip."""
    h = 0.24 * t
    body = 0.07 * math.sin(math.pi * min(1.0, t / 0.8)) ** 0.6
    neck = 0.018 + 0.006 * math.exp(-((t - 0.97) / 0.02) ** 2)
    blend = 1.0 / (1.0 + math.exp(-(t - 0.72) / 0.03))
    return h, max(0.015, (1.0 - blend) * body + blend * neck)


def ogee(t):
    """An ogee (S-curve) vase 20 cm tall: radius 4 cm at the foot to 9 cm at the shoulder."""
    h = 0.2 * t
    return h, 0.04 + 0.05 * (3.0 * t * t - 2.0 * t ** 3) - 0.012 * math.sin(2.0 * math.pi * t)


def write(path, comment, verts, faces):
    with open(path, "w") as out:
        out.write("# %s (bench/make_spiral_vases.py)\n" % comment)
        for p in verts:
            out.write("v %.7f %.7f %.7f\n" % p)
        for f in faces:
            out.write("f %d %d %d\n" % (f[0] + 1, f[1] + 1, f[2] + 1))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_spiral_vases.py OUTDIR")
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    shapes = {
        "spiral_urn_oblique": ("an urn with a waist, axis along (1, 2, -0.5)",
                               helix(urn, 40, 44, (1.0, 2.0, -0.5), (0.02, 0.0, -0.01))),
        "spiral_bottle_x": ("a bottle with a narrow neck and a lip, axis along x, coarse (12 around)",
                            helix(bottle, 24, 12, (1.0, 0.0, 0.0))),
        "spiral_ogee_noisy": ("an ogee vase, axis tilted 20 degrees, noise 0.5 mm",
                              helix(ogee, 36, 60, (0.0, math.cos(math.radians(20.0)),
                                                   math.sin(math.radians(20.0))),
                                    noise=0.0005)),
    }
    for name, (comment, (verts, faces)) in shapes.items():
        write(os.path.join(outdir, name + ".obj"), comment, verts, faces)


if __name__ == "__main__":
    main()
