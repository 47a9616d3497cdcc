#!/usr/bin/python3
"""Where a fitted cup or bowl lies farthest from its target (issue 38, 2), numpy only.

Measures as bench/judge_distance.py does (40,000 area-uniform samples a side, exact distances)
and says, for each side (the sheet's samples to the target, the target's to the sheet), its
farthest point and where the samples past 6%, 5% and 4% of the diagonal lie in the cup's own
frame: r from the axis and z along it (the rim up). The axis is the normal of the target's open
boundary (its rim: a cup's rim is a level circle, so the normal is exact), or, for a closed
target, the principal axis whose spread stands apart from the other two (its sign not chosen). Then the distance at
the rim by azimuth (24 bins of 15 degrees): even all around means the sheet stops short of the
rim (too little paper), peaks every 2 pi / n mean a ring of n's corner paper.
With --normal X,Y,Z (a placed disk's normal, from the fit's `from:` line) it also prints the
angle between that normal and the rim's axis.

Usage: bench/trace_cup_farthest.py FIT.obj TARGET.obj [--normal X,Y,Z] [--samples N]
"""
import argparse
import os
import sys
from collections import Counter

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import judge_distance as judge  # noqa: E402


def rim_axis(verts, faces):
    """The normal of the target's open boundary and its centre (None when it has none)."""
    edges = Counter()
    for t in faces:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            edges[(min(a, b), max(a, b))] += 1
    rim = sorted({v for e, c in edges.items() if c == 1 for v in e})
    if len(rim) < 3:
        return None
    p = verts[rim]
    _, vectors = np.linalg.eigh(np.cov((p - p.mean(0)).T))
    return vectors[:, 0], p.mean(0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("fit")
    ap.add_argument("target")
    ap.add_argument("--normal")
    ap.add_argument("--samples", type=int, default=40000)
    args = ap.parse_args()
    rng = np.random.default_rng(1)
    va, fa = judge.read_obj(args.fit)
    vb, fb = judge.read_obj(args.target)
    sa = judge.sample(va, fa, args.samples, rng)
    sb = judge.sample(vb, fb, args.samples, rng)
    da = judge.distances(sa, vb, fb)
    db = judge.distances(sb, va, fa)
    diag = np.linalg.norm(vb.max(0) - vb.min(0))
    centre = sb.mean(0)
    rim = rim_axis(vb, fb)
    if rim is not None:
        axis, rim_centre = rim
        if (rim_centre - centre) @ axis < 0:  # the rim up
            axis = -axis
    else:
        spread, vectors = np.linalg.eigh(np.cov((sb - centre).T))
        apart = [abs(spread[k] - np.delete(spread, k).mean()) for k in range(3)]
        axis = vectors[:, int(np.argmax(apart))]

    def frame(p):
        q = p - centre
        z = q @ axis
        return np.linalg.norm(q - np.outer(z, axis), axis=1), z

    rb, zb = frame(sb)
    print("target: r up to %.4g, z %.4g..%.4g, diagonal %.4g" % (rb.max(), zb.min(), zb.max(), diag))
    if args.normal:
        n = np.array([float(x) for x in args.normal.split(",")])
        n /= np.linalg.norm(n)
        print("the normal given lies %.2f degrees off the rim's axis"
              % np.degrees(np.arccos(min(1.0, abs(n @ axis)))))
    e1 = np.cross(axis, [1.0, 0.0, 0.0])
    if np.linalg.norm(e1) < 0.1:
        e1 = np.cross(axis, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(axis, e1)
    for name, d, p in (("sheet -> target", da, sa), ("target -> sheet", db, sb)):
        r, z = frame(p)
        k = int(np.argmax(d))
        print("%s: farthest %.2f%% (mean %.3f%%) at r %.4g z %.4g"
              % (name, 100 * d.max() / diag, 100 * d.mean() / diag, r[k], z[k]))
        for share in (6, 5, 4):
            far = d > share / 100 * diag
            if far.any():
                print("  past %d%%: %d samples, r %.4g..%.4g, z %.4g..%.4g" % (
                    share, far.sum(), r[far].min(), r[far].max(), z[far].min(), z[far].max()))
        q = p - centre
        azimuth = np.degrees(np.arctan2(q @ e2, q @ e1)) % 360
        band = z > zb.max() - 0.05 * (zb.max() - zb.min())
        if band.any():
            bins = (azimuth[band] // 15).astype(int)
            print("  at the rim by azimuth (% of the diagonal): " + " ".join(
                "%.1f" % (100 * d[band][bins == b].max() / diag) if (bins == b).any() else "-"
                for b in range(24)))


if __name__ == "__main__":
    main()
