#!/usr/bin/python3
"""Where a fitted vase lies farthest from its target (issue 38, 2; numpy only, apart from
curvefold): the distance judge_distance.py measures, traced to heights and radii about the
target's axis, so a miss can be named (a neck corner, the lip, the belly cut in).

Each side's area-uniform samples are measured exactly to the other mesh (judge_distance.py's
`distances`). The axis is the target's principal axis about which its radius varies least at
each height (inward_fold_bound.py's `profile` rule), through the target's centroid. Printed:
  - the Hausdorff and Chamfer distances (of the target's diagonal), as judge_distance.py prints;
  - the `--far` farthest sheet samples and target samples: height, radius, angle about the axis,
    distance, and the target's mean radius at that height (a sheet point far outside it is a
    corner left standing; far inside, a flap cut past the profile);
  - by height band (`--bands`): the target's mean radius, the sheet's mean and largest radius,
    and the farthest distance of each side's samples in the band.
With `--design D.curvefold.json`, each far sheet sample also names the fold planes it lies
nearest (a corner lies on two creases of one ring; a flap on one side of a plane).

Usage: bench/trace_far_points.py SHEET.obj TARGET.obj [--samples N] [--seed S] [--far K]
       [--bands B] [--design D.curvefold.json]
Limits: a model of revolution: the target's mean radius by height says nothing of a target that
is not one; the sheet's `vt` lines are ignored.
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from inward_fold_bound import principal_axes  # noqa: E402
from judge_distance import distances, pair_parser, read_obj, sample  # noqa: E402


def target_axis(verts):
    """The principal axis about which the radius varies least by height, through the centroid,
    pointing along its largest component's positive direction."""
    centre = verts.mean(0)
    axis = min(principal_axes(verts - centre, 30), key=lambda c: c[0])[1]
    # An eigenvector's sign is arbitrary: heights are read along the axis's largest component.
    return centre, axis if axis[np.argmax(np.abs(axis))] > 0 else -axis


def cylindrical(points, centre, axis):
    """(height, radius, angle in degrees) of each point about the axis."""
    x = points - centre
    h = x @ axis
    across = x - np.outer(h, axis)
    u = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(axis, u)
    return h, np.linalg.norm(across, axis=1), np.degrees(np.arctan2(across @ v, across @ u))


def fold_planes(path):
    """The design's fold planes as (index, point, normal)."""
    with open(path) as f:
        design = json.load(f)
    out = []
    for i, fold in enumerate(design.get("folds", [])):
        plane = fold.get("plane", fold)
        p, n = plane.get("point"), plane.get("normal")
        if p is None or n is None:
            continue
        n = np.array(n, float)
        out.append((i, np.array(p, float), n / np.linalg.norm(n)))
    return out


def main():
    ap = pair_parser()  # a: the sheet, b: the target
    ap.add_argument("--far", type=int, default=8)
    ap.add_argument("--bands", type=int, default=20)
    ap.add_argument("--design")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    vs, fs = read_obj(a.a)
    vt, ft = read_obj(a.b)
    ps, pt = sample(vs, fs, a.samples, rng), sample(vt, ft, a.samples, rng)
    ds, dt = distances(ps, vt, ft), distances(pt, vs, fs)
    diag = np.linalg.norm(vt.max(0) - vt.min(0))
    print("hausdorff %.4f%% chamfer %.4f%% (diagonal %.6g)" %
          (100 * max(ds.max(), dt.max()) / diag, 100 * 0.5 * (ds.mean() + dt.mean()) / diag, diag))
    centre, axis = target_axis(vt)
    hs, rs, angs = cylindrical(ps, centre, axis)
    ht, rt, angt = cylindrical(pt, centre, axis)
    lo, hi = ht.min(), ht.max()
    edges = np.linspace(lo, hi, a.bands + 1)

    def target_radius(h):
        i = np.clip(np.digitize(h, edges) - 1, 0, a.bands - 1)
        return np.array([rt[(ht >= edges[k]) & (ht <= edges[k + 1])].mean() for k in np.atleast_1d(i)])

    planes = fold_planes(a.design) if a.design else []
    print("axis (%.4f %.4f %.4f) through (%.4g %.4g %.4g); heights from the target's lowest" %
          (*axis, *centre))
    for name, d, h, r, ang in (("sheet", ds, hs, rs, angs), ("target", dt, ht, rt, angt)):
        print("farthest %s samples: height, radius, angle, distance, target's mean radius there" % name)
        for i in np.argsort(-d)[:a.far]:
            line = "  %.4g %.4g %6.1f %.4g (%.2f%%) %.4g" % (
                h[i] - lo, r[i], ang[i], d[i], 100 * d[i] / diag, target_radius(h[i])[0])
            if name == "sheet" and planes:
                near = sorted((abs((ps[i] - p) @ n), k) for k, p, n in planes)[:2]
                line += "  nearest planes " + ", ".join("%d (%.3g)" % (k, dd) for dd, k in near)
            print(line)
    print("band: height, target mean radius, sheet mean / largest radius, farthest sheet / target sample")
    for k in range(a.bands):
        s = (hs >= edges[k]) & (hs < edges[k + 1])
        t = (ht >= edges[k]) & (ht < edges[k + 1])
        if not t.any():
            continue
        print("  %.4g %.4g %s %s %.4g" % (
            0.5 * (edges[k] + edges[k + 1]) - lo, rt[t].mean(),
            "%.4g / %.4g" % (rs[s].mean(), rs[s].max()) if s.any() else "- / -",
            "%.4g" % ds[s].max() if s.any() else "-", dt[t].max()))


if __name__ == "__main__":
    main()
