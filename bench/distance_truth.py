#!/usr/bin/python3
"""How far two triangle meshes lie apart, measured apart from curvefold (numpy only), to check the
figures `fit` and `distance` print.

Each mesh gets N area-uniform random points (40,000 by default, as issue 38's goals are measured);
every point is measured exactly to the other mesh's triangles (the closest point on a triangle,
brute force over the triangles near it). Printed, as `curvefold distance` defines them (docs/cli.md):
  Hausdorff = the larger of the two one-sided maxima (over the points and each mesh's vertices),
  Chamfer   = the mean of the two one-sided means,
each also as a share of B's bounding-box diagonal (B is the reference: the target).

Usage:
  bench/distance_truth.py A.obj B.obj [--samples N] [--seed S]
  bench/distance_truth.py --cases DIR   write the flat-sheet cases of docs/performance.md to DIR
                                        (sheet.obj and one target per case) and measure each
"""
import argparse
import os
import sys

import numpy as np

import target_folds


def read_obj(path):
    positions, faces = target_folds.read_obj(path)
    return np.array(positions, dtype=float), np.array(faces, dtype=np.int64)


def write_obj(path, positions, faces):
    with open(path, "w") as f:
        for p in positions:
            f.write("v %.17g %.17g %.17g\n" % tuple(p))
        for t in faces:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def triangles_with_area(positions, faces):
    a, b, c = positions[faces[:, 0]], positions[faces[:, 1]], positions[faces[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    keep = area > 0.0
    return a[keep], b[keep], c[keep], area[keep]


def sample(positions, faces, count, rng):
    a, b, c, area = triangles_with_area(positions, faces)
    pick = rng.choice(len(area), size=count, p=area / area.sum())
    r1 = np.sqrt(rng.random(count))[:, None]
    r2 = rng.random(count)[:, None]
    return (1 - r1) * a[pick] + r1 * (1 - r2) * b[pick] + r1 * r2 * c[pick]


def segment_distance(p, a, b):
    ab = b - a
    t = np.clip(np.einsum("...i,...i", p - a, ab) / np.maximum(np.einsum("...i,...i", ab, ab), 1e-300), 0, 1)
    return np.linalg.norm(p - a - t[..., None] * ab, axis=-1)


def point_triangle_distance(p, a, b, c):
    """Exact distance of points p (m, 1, 3) to triangles a, b, c (1, t, 3): (m, t)."""
    ab, ac, ap = b - a, c - a, p - a
    n = np.cross(ab, ac)
    n = n / np.linalg.norm(n, axis=-1, keepdims=True)
    # Barycentric coordinates of p's projection: inside, the distance is to the plane.
    d00 = np.einsum("...i,...i", ab, ab)
    d01 = np.einsum("...i,...i", ab, ac)
    d11 = np.einsum("...i,...i", ac, ac)
    d20 = np.einsum("...i,...i", ap, ab)
    d21 = np.einsum("...i,...i", ap, ac)
    denominator = d00 * d11 - d01 * d01
    v = (d11 * d20 - d01 * d21) / denominator
    w = (d00 * d21 - d01 * d20) / denominator
    inside = (v >= 0) & (w >= 0) & (v + w <= 1)
    plane = np.abs(np.einsum("...i,...i", ap, n))
    # Outside, the closest point lies on an edge.
    edges = np.minimum(np.minimum(segment_distance(p, a, b), segment_distance(p, b, c)),
                       segment_distance(p, c, a))
    return np.where(inside, plane, edges)


def distances_to_mesh(points, positions, faces, chunk=256):
    """Each point's exact distance to the mesh: points in spatial chunks, each against only the
    triangles whose bounding sphere can hold a point nearer than the point's upper bound (its
    nearest triangle centre)."""
    a, b, c, _ = triangles_with_area(positions, faces)
    centre = (a + b + c) / 3.0
    radius = np.max(np.stack([np.linalg.norm(x - centre, axis=1) for x in (a, b, c)]), axis=0)
    centre_squared = np.einsum("ij,ij->i", centre, centre)
    # Spatial order: points of one chunk lie close together, so few triangles are candidates.
    low, high = points.min(axis=0), points.max(axis=0)
    cell = ((points - low) / np.maximum(high - low, 1e-300) * 31.999).astype(np.int64)
    order = np.lexsort((cell[:, 2], cell[:, 1], cell[:, 0]))
    result = np.empty(len(points))
    for start in range(0, len(points), chunk):
        index = order[start:start + chunk]
        p = points[index]
        squared = np.einsum("ij,ij->i", p, p)[:, None] + centre_squared[None] - 2.0 * p @ centre.T
        to_centre = np.sqrt(np.maximum(squared, 0.0))
        upper = to_centre.min(axis=1) * (1 + 1e-9) + 1e-12
        near = np.nonzero(((to_centre - radius[None]) <= upper[:, None]).any(axis=0))[0]
        d = point_triangle_distance(p[:, None, :], a[near][None], b[near][None], c[near][None])
        result[index] = d.min(axis=1)
    return result


def used_vertices(positions, faces):
    return positions[np.unique(faces)]


def measure(a_mesh, b_mesh, samples=40000, seed=1):
    rng = np.random.default_rng(seed)
    (pa, fa), (pb, fb) = a_mesh, b_mesh
    from_a = distances_to_mesh(sample(pa, fa, samples, rng), pb, fb)
    from_b = distances_to_mesh(sample(pb, fb, samples, rng), pa, fa)
    vertices_a = distances_to_mesh(used_vertices(pa, fa), pb, fb)
    vertices_b = distances_to_mesh(used_vertices(pb, fb), pa, fa)
    used = used_vertices(pb, fb)
    diagonal = float(np.linalg.norm(used.max(axis=0) - used.min(axis=0)))
    return {
        "fromAMax": max(from_a.max(), vertices_a.max()), "fromAMean": from_a.mean(),
        "fromBMax": max(from_b.max(), vertices_b.max()), "fromBMean": from_b.mean(),
        "hausdorff": max(from_a.max(), vertices_a.max(), from_b.max(), vertices_b.max()),
        "chamfer": 0.5 * (from_a.mean() + from_b.mean()),
        "diagonal": diagonal,
    }


def report(name, d):
    print("%-14s Hausdorff %8.2f mm (%6.2f%%)  Chamfer %8.3f mm (%6.3f%%)  "
          "A->B max %.2f mean %.3f  B->A max %.2f mean %.3f mm  diagonal %.4f m" % (
              name, 1e3 * d["hausdorff"], 100 * d["hausdorff"] / d["diagonal"], 1e3 * d["chamfer"],
              100 * d["chamfer"] / d["diagonal"], 1e3 * d["fromAMax"], 1e3 * d["fromAMean"],
              1e3 * d["fromBMax"], 1e3 * d["fromBMean"], d["diagonal"]))


# The cases: the default square sheet (0.2 m, z = 0, centred on the origin) against targets.
def grid(n, x0=-0.1, x1=0.1, y0=-0.1, y1=0.1, keep=None):
    """An n x n grid of [x0, x1] x [y0, y1] in z = 0, two triangles a cell; keep(i, j) drops cells."""
    xs, ys = np.linspace(x0, x1, n + 1), np.linspace(y0, y1, n + 1)
    positions = np.array([[x, y, 0.0] for y in ys for x in xs])
    faces = []
    for j in range(n):
        for i in range(n):
            if keep and not keep(i, j):
                continue
            v = j * (n + 1) + i
            faces += [[v, v + 1, v + n + 2], [v, v + n + 2, v + n + 1]]
    return positions, np.array(faces, dtype=np.int64)


def fold_up(positions, degrees):
    """The half x > 0 turned about the y axis by `degrees` (180: flat onto the other half)."""
    out = positions.copy()
    right = positions[:, 0] > 0
    t = np.radians(degrees)
    x = positions[right, 0]
    out[right, 0] = x * np.cos(t)
    out[right, 2] = x * np.sin(t)
    return out


def split4(positions, faces):
    """Each triangle into four (its edge midpoints), so the surface is the same."""
    positions = list(map(tuple, positions))
    index = {p: i for i, p in enumerate(positions)}
    def mid(i, j):
        p = tuple((np.array(positions[i]) + np.array(positions[j])) / 2)
        if p not in index:
            index[p] = len(positions)
            positions.append(p)
        return index[p]
    out = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
    return np.array(positions), np.array(out, dtype=np.int64)


def cases():
    sheet = grid(40)
    half = (fold_up(sheet[0], 90), sheet[1])
    # A nearly closed fold: the right half 1 mm over the left (180 degrees exactly would stack
    # two layers in one plane).
    closed = fold_up(sheet[0], 180)
    closed[sheet[0][:, 0] > 0, 2] += 0.001
    closed = (closed, sheet[1])
    # A thin flap far away: a strip 4 mm wide standing 150 mm up from the sheet's edge.
    flap_p = np.array([[0.1, -0.002, 0.0], [0.1, 0.002, 0.0], [0.1, 0.002, 0.15], [0.1, -0.002, 0.15]])
    flap = (np.vstack([sheet[0], flap_p]),
            np.vstack([sheet[1], np.array([[0, 1, 2], [0, 2, 3]]) + len(sheet[0])]))
    coarse_sheet = grid(2)  # 8 big triangles: samples on vertices alone would miss the faces
    coarse = (fold_up(coarse_sheet[0], 90), coarse_sheet[1])
    # Three square holes, 25 mm across.
    holes = grid(40, keep=lambda i, j: not any(a <= i < a + 5 and b <= j < b + 5
                                                for a, b in ((5, 5), (28, 10), (12, 28))))
    holed = (fold_up(holes[0], 60), holes[1])
    return sheet, {
        "half90": half,
        "half90_split": split4(*half),
        "half90_coarse": coarse,
        "closed_1mm": closed,
        "flap_far": flap,
        "holes_60": holed,
        "same": sheet,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("a", nargs="?")
    parser.add_argument("b", nargs="?")
    parser.add_argument("--samples", type=int, default=40000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--cases", metavar="DIR")
    args = parser.parse_args()
    if args.cases:
        os.makedirs(args.cases, exist_ok=True)
        sheet, targets = cases()
        write_obj(os.path.join(args.cases, "sheet.obj"), *sheet)
        for name, target in targets.items():
            write_obj(os.path.join(args.cases, name + ".obj"), *target)
            report(name, measure(sheet, target, args.samples, args.seed))
        return
    if not (args.a and args.b):
        parser.error("give A and B, or --cases DIR")
    report(os.path.basename(args.a), measure(read_obj(args.a), read_obj(args.b), args.samples, args.seed))


if __name__ == "__main__":
    sys.exit(main())
