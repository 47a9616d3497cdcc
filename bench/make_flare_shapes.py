#!/usr/bin/env python3
"""Flaring targets (issue 38, 2; branch flare26): lampshades, bells, trumpets and tulips whose
radius is a convex function of height (it grows faster and faster toward the lip), open at both
ends, as OBJ. Unlike the other generators in how each mesh is laid, not only in its profile:

  trumpet_mm      an exponential horn r = r0 + c (exp(k v) - 1), millimetres, axis tilted 35
                  degrees, meshed as ONE helical strip (each vertex a step further round and up
                  a spiral, triangles between consecutive turns: no ring of vertices at any height)
  tulip_cm        a tulip shade, its wall a power law r = r0 + (r1 - r0) v^2.6 with six shallow
                  petals (radius x (1 + 0.035 cos 6 phi)), centimetres, wide end up, rings
                  spaced by arc length (dense at the lip), its seam turned a little ring by ring
  hyper_shade     half a hyperboloid r = sqrt(a^2 + (b z)^2), metres, axis along x, every
                  vertex jittered along the wall (a fifth of a cell) and its rings' counts
                  alternating 48 / 56 (stitched by angle)
  skirt_bell_in   a bell whose lip turns out in its last fifth (a quadratic wall, then a steep
                  quartic skirt), inches, axis a random direction, off the origin
  soft_flare_cm   a gentle flare (r = r0 + s v + c v^2, c a quarter of s), centimetres, the
                  mildest: a cone comes within a few percent, so it must not get worse

Usage: bench/make_flare_shapes.py OUTDIR [--seed S]   (numpy; writes OUTDIR/NAME.obj and
OUTDIR/targets.tsv: name, units, height, narrow and wide radius in metres)
"""
import argparse
import math
import os

import numpy as np


def frame(axis):
    a = np.asarray(axis, float)
    a /= np.linalg.norm(a)
    other = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(other, a)
    u /= np.linalg.norm(u)
    return a, u, np.cross(a, u)


def place(points, axis, origin):
    a, u, w = frame(axis)
    p = np.asarray(points, float)
    return origin + np.outer(p[:, 0], u) + np.outer(p[:, 1], w) + np.outer(p[:, 2], a)


def write(path, comment, verts, faces):
    with open(path, "w") as f:
        f.write(f"# {comment}\n")
        for v in verts:
            f.write(f"v {v[0]:.7g} {v[1]:.7g} {v[2]:.7g}\n")
        for t in faces:
            f.write("f " + " ".join(str(i + 1) for i in t) + "\n")


def rings_mesh(rings):
    """Rings of (x, y, z) points, each closed, stitched by angle (any counts)."""
    verts, faces, starts = [], [], []
    for ring in rings:
        starts.append(len(verts))
        verts.extend(ring)
    for k in range(len(rings) - 1):
        a, b = rings[k], rings[k + 1]
        angle = lambda p: math.atan2(p[1], p[0]) % (2 * math.pi)
        ia = sorted(range(len(a)), key=lambda i: angle(a[i]))
        ib = sorted(range(len(b)), key=lambda i: angle(b[i]))
        i = j = 0
        na, nb = len(ia), len(ib)
        while i < na or j < nb:
            pa = starts[k] + ia[i % na]
            pb = starts[k + 1] + ib[j % nb]
            next_a = (i + 1) / na if i < na else 2.0
            next_b = (j + 1) / nb if j < nb else 2.0
            if next_a <= next_b:
                faces.append((pa, starts[k] + ia[(i + 1) % na], pb))
                i += 1
            else:
                faces.append((pa, starts[k + 1] + ib[(j + 1) % nb], pb))
                j += 1
    return np.array(verts), faces


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=26)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    os.makedirs(args.out, exist_ok=True)
    rows = []

    # Trumpet: one helical strip, millimetres.
    h = rng.uniform(0.16, 0.2)
    r0, r1 = rng.uniform(0.025, 0.035), rng.uniform(0.10, 0.12)
    k = 3.0
    radius = lambda v: r0 + (r1 - r0) * (math.exp(k * v) - 1) / (math.exp(k) - 1)
    per_turn, turns = 64, 40
    pts = []
    for i in range(per_turn * (turns + 1) + 1):
        v = min(i / (per_turn * turns), 1.0)
        phi = 2 * math.pi * i / per_turn
        pts.append((radius(v) * math.cos(phi), radius(v) * math.sin(phi), h * v))
    faces = []
    for i in range(len(pts) - per_turn - 1):
        faces.append((i, i + 1, i + per_turn))
        faces.append((i + 1, i + per_turn + 1, i + per_turn))
    tilt = math.radians(35)
    verts = place(pts, (math.sin(tilt), 0.0, math.cos(tilt)), np.zeros(3)) * 1000.0
    write(os.path.join(args.out, "trumpet_mm.obj"), "trumpet, one helical strip, mm", verts, faces)
    rows.append(("trumpet_mm", "mm", h, r0, r1))

    # Tulip shade: power-law wall with six shallow petals, rings by arc length, centimetres.
    h = rng.uniform(0.18, 0.24)
    r0, r1 = rng.uniform(0.03, 0.045), rng.uniform(0.13, 0.16)
    prof = lambda v: r0 + (r1 - r0) * v ** 2.6
    fine = np.linspace(0, 1, 2001)
    arc = np.concatenate([[0], np.cumsum(np.hypot(np.diff(fine) * h,
                                                  np.diff([prof(v) for v in fine])))])
    vs = np.interp(np.linspace(0, arc[-1], 36), arc, fine)
    rings = []
    for j, v in enumerate(vs):
        n = 60
        rings.append([(prof(v) * (1 + 0.035 * math.cos(6 * p)) * math.cos(p),
                       prof(v) * (1 + 0.035 * math.cos(6 * p)) * math.sin(p), h * v)
                      for p in (2 * math.pi * (i + 0.13 * j) / n for i in range(n))])
    verts, faces = rings_mesh(rings)
    verts = place(verts, (0.0, 0.0, 1.0), np.array([0.0, 0.0, 0.0])) * 100.0
    write(os.path.join(args.out, "tulip_cm.obj"), "tulip shade, six petals, cm", verts, faces)
    rows.append(("tulip_cm", "cm", h, r0, r1))

    # Half a hyperboloid, metres, axis along x, jittered, ring counts alternating.
    a, b, h = rng.uniform(0.04, 0.05), rng.uniform(1.1, 1.4), rng.uniform(0.12, 0.16)
    rings = []
    for j, z in enumerate(np.linspace(0, h, 30)):
        n = 48 if j % 2 == 0 else 56
        r = math.sqrt(a * a + (b * z) ** 2)
        ring = []
        for i in range(n):
            p = 2 * math.pi * (i + rng.uniform(-0.2, 0.2)) / n
            zz = z + (rng.uniform(-0.2, 0.2) * h / 29 if 0 < j < 29 else 0.0)
            rr = math.sqrt(a * a + (b * zz) ** 2)
            ring.append((rr * math.cos(p), rr * math.sin(p), zz))
        rings.append(ring)
    verts, faces = rings_mesh(rings)
    verts = place(verts, (1.0, 0.0, 0.0), np.array([0.05, -0.02, 0.3]))
    write(os.path.join(args.out, "hyper_shade.obj"), "half hyperboloid shade, m", verts, faces)
    rows.append(("hyper_shade", "m", h, a, math.sqrt(a * a + (b * h) ** 2)))

    # Skirt bell: quadratic wall, then a quartic skirt in its last fifth, inches.
    h = rng.uniform(0.2, 0.26)
    r0 = rng.uniform(0.035, 0.045)
    wall = lambda v: r0 + 0.06 * v * v
    skirt = lambda v: wall(v) + (0.5 * max(v - 0.8, 0.0) / 0.2) ** 4 * 0.5 * 0.16 + \
        0.1 * max(v - 0.8, 0.0)
    rings = [[(skirt(v) * math.cos(p), skirt(v) * math.sin(p), -h * v)
              for p in np.linspace(0, 2 * math.pi, 52, endpoint=False)]
             for v in np.linspace(0, 1, 40)]
    verts, faces = rings_mesh(rings)
    axis = rng.normal(size=3)
    verts = place(verts, axis, rng.uniform(-0.2, 0.2, 3)) / 0.0254
    write(os.path.join(args.out, "skirt_bell_in.obj"), "bell with a skirt, inches", verts, faces)
    rows.append(("skirt_bell_in", "in", h, r0, skirt(1.0)))

    # Soft flare: the mildest, centimetres.
    h = rng.uniform(0.2, 0.25)
    r0, s = rng.uniform(0.05, 0.06), rng.uniform(0.06, 0.08)
    soft = lambda v: r0 + s * v + 0.25 * s * v * v
    rings = [[(soft(v) * math.cos(p), soft(v) * math.sin(p), h * v)
              for p in np.linspace(0, 2 * math.pi, 64, endpoint=False)]
             for v in np.linspace(0, 1, 24)]
    verts, faces = rings_mesh(rings)
    verts = place(verts, (0.0, 1.0, 0.0), np.zeros(3)) * 100.0
    write(os.path.join(args.out, "soft_flare_cm.obj"), "gentle flare, cm", verts, faces)
    rows.append(("soft_flare_cm", "cm", h, r0, soft(1.0)))

    with open(os.path.join(args.out, "targets.tsv"), "w") as f:
        f.write("name\tunits\theight_m\tnarrow_m\twide_m\n")
        for row in rows:
            f.write("\t".join([row[0], row[1]] + [f"{x:.4f}" for x in row[2:]]) + "\n")


if __name__ == "__main__":
    main()
