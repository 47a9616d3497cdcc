#!/usr/bin/python3
"""Steep cups marched from implicit solids for `curvefold fit` (issue 38, 2), numpy.
Usage: bench/make_cup23_targets.py OUTDIR [--seed N] (deterministic for a seed).

Unlike the other cup generators (profiles of revolution meshed in rings or lattices), each cup
here is the outside of a solid given only as a function f(x, y, z) < 0, marched to triangles by
marching tetrahedra on a jittered grid (six tetrahedra a cube), and cut open at its rim: the
triangles are as the grid cuts them (slivers and all, in no rings), the rim is ragged at the
grid's step, and on the tumbler and the mug the rim's height varies around the cup (an uneven
cut, not a level plane).
- marched_tumbler (metres): a tapered tumbler, a smooth union of a flat floor and a wall whose
  radius grows from 2.6 to 3.4 cm over 6 cm of height (the heel rounded over 6 mm), cut at
  5.2 cm with the rim rising 4 mm one way, tilted 40 degrees and moved off the origin.
- marched_mug_mm (mm): a near-upright mug (radius 36 mm at the floor, 38 at the rim, 62 mm deep)
  whose cross-section bulges in three lobes by 2 mm, heel rounded over 10 mm, cut by a wavy rim
  (3 mm waves, twice around), tilted 15 degrees.
- marched_beaker (metres): a conical beaker whose wall leans 20 degrees from upright (radius 2.2
  cm at the floor), a slightly domed floor (1.5 mm up at the centre), 5 cm deep, 0.15 mm of noise
  on every vertex, tilted 70 degrees.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from formula_meshes import folder_and_seed, place, write_obj  # noqa: E402

# The six tetrahedra of a cube, by corner index (corner c at (c & 1, (c >> 1) & 1, c >> 2)),
# all sharing the diagonal 0-7, so neighbouring cubes' faces split alike.
TETRAHEDRA = [(0, 1, 3, 7), (0, 3, 2, 7), (0, 2, 6, 7), (0, 6, 4, 7), (0, 4, 5, 7), (0, 5, 1, 7)]


def smooth_max(a, b, k):
    """max(a, b) rounded over width k (the polynomial smooth maximum)."""
    h = np.clip(0.5 + 0.5 * (a - b) / k, 0.0, 1.0)
    return b + (a - b) * h + k * h * (1.0 - h)


def march(f, lo, hi, step, rng, jitter=0.2):
    """Triangles of the surface f = 0 over the box [lo, hi] (grid `step`, each grid point moved
    by up to `jitter` of a step so no vertex lands on a grid plane), outward (toward f > 0)."""
    counts = [int(math.ceil((hi[i] - lo[i]) / step)) + 1 for i in range(3)]
    axes = [lo[i] + step * np.arange(counts[i]) for i in range(3)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1)
    grid = grid + rng.uniform(-jitter, jitter, grid.shape) * step
    values = f(grid[..., 0], grid[..., 1], grid[..., 2])
    values[np.abs(values) < 1e-12] = 1e-12
    nx, ny, nz = counts
    verts, tris, cut = [], [], {}

    def flat(i, j, k):
        return (i * ny + j) * nz + k

    pts = grid.reshape(-1, 3)
    vals = values.reshape(-1)

    def vertex(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in cut:
            t = vals[a] / (vals[a] - vals[b])
            cut[key] = len(verts)
            verts.append(pts[a] + t * (pts[b] - pts[a]))
        return cut[key]

    def emit(tri, outward_from, toward):
        a, b, c = (verts[v] for v in tri)
        n = np.cross(b - a, c - a)
        if np.dot(n, toward - outward_from) < 0:
            tri = (tri[0], tri[2], tri[1])
        tris.append(tri)

    for i in range(nx - 1):
        for j in range(ny - 1):
            for k in range(nz - 1):
                corners = [flat(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2)) for c in range(8)]
                signs = [vals[c] < 0 for c in corners]
                if all(signs) or not any(signs):
                    continue
                for tet in TETRAHEDRA:
                    ids = [corners[c] for c in tet]
                    inside = [v for v in ids if vals[v] < 0]
                    outside = [v for v in ids if vals[v] >= 0]
                    if not inside or not outside:
                        continue
                    centre_in = np.mean([pts[v] for v in inside], axis=0)
                    centre_out = np.mean([pts[v] for v in outside], axis=0)
                    if len(inside) == 1 or len(outside) == 1:
                        one = inside[0] if len(inside) == 1 else outside[0]
                        rest = outside if len(inside) == 1 else inside
                        emit(tuple(vertex(one, r) for r in rest), centre_in, centre_out)
                    else:
                        p, q = inside
                        r, s = outside
                        quad = [vertex(p, r), vertex(p, s), vertex(q, s), vertex(q, r)]
                        emit((quad[0], quad[1], quad[2]), centre_in, centre_out)
                        emit((quad[0], quad[2], quad[3]), centre_in, centre_out)
    return np.array(verts), tris


def open_cup(verts, tris, rim):
    """The triangles whose vertices all lie below the rim height rim(x, y), the rest dropped, and
    triangles of no area (a sliver whose corners merged) left out."""
    below = verts[:, 2] < rim(verts[:, 0], verts[:, 1])
    kept = []
    for t in tris:
        if not all(below[v] for v in t):
            continue
        a, b, c = (verts[v] for v in t)
        if np.linalg.norm(np.cross(b - a, c - a)) > 1e-14 * max(1.0, np.abs(a).max()) ** 2:
            kept.append(t)
    return largest_piece(kept)


def largest_piece(tris):
    """The triangles of the largest piece joined across edges (the cut can leave islands of a
    few triangles above a dip of the rim)."""
    parent = list(range(len(tris)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    first = {}
    for i, t in enumerate(tris):
        for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            key = (min(e), max(e))
            if key in first:
                parent[root(i)] = root(first[key])
            else:
                first[key] = i
    sizes = {}
    for i in range(len(tris)):
        sizes[root(i)] = sizes.get(root(i), 0) + 1
    biggest = max(sizes, key=sizes.get)
    return [t for i, t in enumerate(tris) if root(i) == biggest]


def write(folder, name, comment, verts, tris, yaw, tilt, shift, number):
    placed = [place(tuple(p), yaw, tilt, shift) for p in verts]
    write_obj(os.path.join(folder, name + ".obj"), comment, os.path.relpath(__file__), placed,
              tris, number)


def main():
    args, rng = folder_and_seed(__doc__.splitlines()[0], 23)

    # marched_tumbler: f < 0 inside a tapered solid standing on z = 0.
    def tumbler(x, y, z):
        radius = 0.026 + 0.008 * z / 0.06
        return smooth_max(np.hypot(x, y) - radius, -z, 0.006)

    v, t = march(tumbler, (-0.04, -0.04, -0.008), (0.04, 0.04, 0.062), 0.0048, rng)
    t = open_cup(v, t, lambda x, y: 0.052 + 0.002 * x / 0.03)
    write(args.out, "marched_tumbler", "tapered tumbler marched from an implicit solid, metres",
          v, t, 20.0, 40.0, (0.03, -0.01, 0.02), "%.8f")

    # marched_mug_mm: three lobes, a wavy rim.
    def mug(x, y, z):
        phi = np.arctan2(y, x)
        radius = 36.0 + 2.0 * z / 62.0 + 2.0 * np.cos(3.0 * phi)
        return smooth_max(np.hypot(x, y) - radius, -z, 10.0)

    v, t = march(mug, (-44.0, -44.0, -8.0), (44.0, 44.0, 70.0), 5.2, rng)
    t = open_cup(v, t, lambda x, y: 62.0 + 3.0 * np.cos(2.0 * np.arctan2(y, x)))
    write(args.out, "marched_mug_mm",
          "three-lobed mug marched from an implicit solid, wavy rim, in mm", v, t,
          -40.0, 15.0, (5.0, 20.0, -3.0), "%.5f")

    # marched_beaker: a cone leaning 20 degrees, a domed floor, noise.
    def beaker(x, y, z):
        r = np.hypot(x, y)
        floor = -(z - 0.0015 * np.clip(1.0 - (r / 0.022) ** 2, 0.0, 1.0))
        return smooth_max(r - (0.022 + z * math.tan(math.radians(20.0))), floor, 0.004)

    v, t = march(beaker, (-0.045, -0.045, -0.006), (0.045, 0.045, 0.058), 0.005, rng)
    t = open_cup(v, t, lambda x, y: 0.05 + 0.0 * x)
    v = v + rng.normal(0.0, 0.00015, v.shape)
    write(args.out, "marched_beaker",
          "leaning beaker marched from an implicit solid, noise, metres", v, t,
          65.0, 70.0, (-0.02, 0.0, 0.01), "%.8f")


if __name__ == "__main__":
    main()
