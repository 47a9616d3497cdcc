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

With `--frame height` (a saddle, a height field), each far sample is placed instead in the
target's height frame: its mean normal (the samples' least spread where the normals cancel) and,
across it, the directions of the least-squares quadric's stronger and weaker curvature: (s, t,
height), the quadric's height at (s, t), and the distance in (s, t) to the target's outline's
nearest sample (0 inside the outline: a far sheet sample with a positive one is paper standing
out past the target's rim; a far target sample inside is a wing the sheet does not reach).

Usage: bench/trace_far_points.py SHEET.obj TARGET.obj [--samples N] [--seed S] [--far K]
       [--bands B] [--design D.curvefold.json] [--frame axis|height]
Limits: a model of revolution (`axis`): the target's mean radius by height says nothing of a
target that is not one; `height` assumes one height field; the sheet's `vt` lines are ignored.
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


def height_frame(verts, faces, points):
    """(centre, normal, s axis, t axis, quadric) of the target's height frame (see above)."""
    p = verts[faces]
    cross = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    mean_normal = cross.sum(0) / np.linalg.norm(cross, axis=1).sum()  # area-weighted unit normals
    centre = points.mean(0)
    d = points - centre
    least = np.linalg.eigh(d.T @ d)[1][:, 0]
    n = mean_normal / np.linalg.norm(mean_normal) if np.linalg.norm(mean_normal) > 0.3 else least
    u = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    a, b, w = d @ u, d @ v, d @ n
    q = np.linalg.lstsq(np.stack([a * a, a * b, b * b, a, b, np.ones_like(a)], 1), w, rcond=None)[0]
    values, vectors = np.linalg.eigh(np.array([[2 * q[0], q[1]], [q[1], 2 * q[2]]]))
    order = np.argsort(-np.abs(values))
    s_axis = vectors[0, order[0]] * u + vectors[1, order[0]] * v
    return centre, n, s_axis, np.cross(n, s_axis), (q, u, v)


def height_coordinates(points, frame):
    centre, n, s_axis, t_axis, (q, u, v) = frame
    d = points - centre
    a, b = d @ u, d @ v
    quadric = q[0] * a * a + q[1] * a * b + q[2] * b * b + q[3] * a + q[4] * b + q[5]
    return d @ s_axis, d @ t_axis, d @ n, quadric


def outside_outline(st, target_st, spacing):
    """Distance in (s, t) from each point to the nearest target sample, less the samples' spacing."""
    out = np.empty(len(st))
    for i in range(0, len(st), 256):
        d = np.linalg.norm(st[i:i + 256, None, :] - target_st[None, :, :], axis=2).min(1)
        out[i:i + 256] = np.maximum(d - spacing, 0.0)
    return out


def trace_height(a, ps, pt, ds, dt, vt, ft, diag, planes):
    frame = height_frame(vt, ft, pt)
    ss, ts, hs, qs = height_coordinates(ps, frame)
    st, tt, ht, qt = height_coordinates(pt, frame)
    target_st = np.stack([st, tt], 1)
    spacing = 2.0 * np.sqrt((np.ptp(st) * np.ptp(tt)) / len(pt))
    print("height frame: normal (%.4f %.4f %.4f), s (%.4f %.4f %.4f) along the stronger curvature" %
          (*frame[1], *frame[2]))
    print("  target's s %.4g..%.4g, t %.4g..%.4g, height %.4g..%.4g" %
          (st.min(), st.max(), tt.min(), tt.max(), ht.min(), ht.max()))
    for name, d, s, t, h, q in (("sheet", ds, ss, ts, hs, qs), ("target", dt, st, tt, ht, qt)):
        far = np.argsort(-d)[:a.far]
        past = outside_outline(np.stack([s[far], t[far]], 1), target_st, spacing)
        print("farthest %s samples: s, t, height, quadric's height, past the outline, distance" % name)
        for k, i in enumerate(far):
            line = "  %.4g %.4g %.4g %.4g %.4g %.4g (%.2f%%)" % (
                s[i], t[i], h[i], q[i], past[k], d[i], 100 * d[i] / diag)
            if name == "sheet" and planes:
                near = sorted((abs((ps[i] - p) @ n), j) for j, p, n in planes)[:2]
                line += "  nearest planes " + ", ".join("%d (%.3g)" % (j, dd) for dd, j in near)
            print(line)


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
    ap.add_argument("--frame", choices=("axis", "height"), default="axis")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    vs, fs = read_obj(a.a)
    vt, ft = read_obj(a.b)
    ps, pt = sample(vs, fs, a.samples, rng), sample(vt, ft, a.samples, rng)
    ds, dt = distances(ps, vt, ft), distances(pt, vs, fs)
    diag = np.linalg.norm(vt.max(0) - vt.min(0))
    print("hausdorff %.4f%% chamfer %.4f%% (diagonal %.6g)" %
          (100 * max(ds.max(), dt.max()) / diag, 100 * 0.5 * (ds.mean() + dt.mean()) / diag, diag))
    planes = fold_planes(a.design) if a.design else []
    if a.frame == "height":
        trace_height(a, ps, pt, ds, dt, vt, ft, diag, planes)
        return
    centre, axis = target_axis(vt)
    hs, rs, angs = cylindrical(ps, centre, axis)
    ht, rt, angt = cylindrical(pt, centre, axis)
    lo, hi = ht.min(), ht.max()
    edges = np.linspace(lo, hi, a.bands + 1)

    def target_radius(h):
        i = np.clip(np.digitize(h, edges) - 1, 0, a.bands - 1)
        return np.array([rt[(ht >= edges[k]) & (ht <= edges[k + 1])].mean() for k in np.atleast_1d(i)])

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
