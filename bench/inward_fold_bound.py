#!/usr/bin/python3
"""How close, by Hausdorff distance, a tube narrowed by inward rings alone can come to a vase
(issue 38, 2; numpy only, apart from curvefold): a model, not a fit.

Why a bound: every fold the tube chains make (ring_folds.hpp: rings, corner rings, neck corner
rings) turns a part of the sheet toward the axis about a plane, and a point on its crease stays
where it was. So the sheet's outer envelope r(h) (its largest distance from the axis at each
height) is where the last cuts left their corners: at most the tube's radius R, and after a
plane cuts the corners, about the plane's own line there, so r(h) = min(R, affine functions of
h): a concave function of the height. A vase whose waist lies under a flaring lip wants a
V-shaped envelope, which no concave one follows. This script finds the concave envelope (the
minimum of R and up to four lines, by a random search with local steps) that minimises the larger
of: the farthest envelope point from the target's profile (each envelope point is a sheet point),
and the farthest target point from the region inside the envelope (an optimistic sheet that fills
it wherever needed). A target of revolution's distance to a point is the distance in the
meridian half-plane to its profile, so both are measured in (radius, height).

Limits: a model. Points also move along the axis under tilted planes, and a fold that turns a
part back out (a pleat's return, ring_folds.hpp's neckPleat) is outside it: the bound holds for
inward cuts only. The target's axis is the principal axis about which the radius varies least at
each height; the profile is the mean radius in 60 height bins.

Usage: bench/inward_fold_bound.py TARGET.obj [TARGET.obj ...] [--tries N] [--seed S]
Prints per target: the tube's radius R, the bound as a share of the diagonal, and the envelope.
"""
import argparse

import numpy as np


def read_vertices(path):
    out = []
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "v":
                out.append([float(x) for x in w[1:4]])
    return np.array(out, float)


def principal_axes(x, bins):
    """For each principal axis a of the centred points x: (spread, a, heights, radii, bin edges,
    bin of each point), spread the mean spread of the radius within a height bin over the mean
    radius (the axis of revolution spreads least)."""
    _, axes = np.linalg.eigh(np.cov(x.T))
    for k in range(3):
        a = axes[:, k]
        h = x @ a
        r = np.linalg.norm(x - np.outer(h, a), axis=1)
        edges = np.linspace(h.min(), h.max(), bins + 1)
        idx = np.clip(np.digitize(h, edges) - 1, 0, bins - 1)
        spread = np.mean([r[idx == i].std() for i in range(bins) if (idx == i).sum() > 2]) / r.mean()
        yield spread, a, h, r, edges, idx


def profile(verts, bins=60):
    """(heights, radii) of the mean radius by height about the best principal axis, from 0 up."""
    x = verts - verts.mean(0)
    best = None
    for spread, a, h, r, edges, idx in principal_axes(x, bins):
        if best is None or spread < best[0]:
            rad = np.array([r[idx == i].mean() if (idx == i).any() else np.nan for i in range(bins)])
            mid = 0.5 * (edges[1:] + edges[:-1]) - h.min()
            keep = ~np.isnan(rad)
            best = (spread, mid[keep], rad[keep], r.max(), h.max() - h.min())
    _, hs, rs, rmax, height = best
    return hs, rs, rmax, height


def pair_forbids(hd, i, j, th, tr, offsets=5, between=16):
    """Whether target profile points i and j (heights th, radii tr) rule out Hausdorff distance hd
    for a concave envelope: the sheet must reach within hd of each, so the envelope stands at
    least on the chord between two such reach points; some height between must then hold an
    envelope point no nearer the profile than hd, for every choice of the two reach points."""
    # The reach points at the target points' own heights: where that chord stays inside the
    # profile, an envelope on it lies on the target, and no choice is ruled out.
    f = np.linspace(0.05, 0.95, between)
    mid_y = th[i] + (th[j] - th[i]) * f
    if (tr[i] - hd + (tr[j] - tr[i]) * f <= np.interp(mid_y, th, tr)).all():
        return False
    ya = th[i] + hd * np.linspace(-1, 1, offsets)
    yb = th[j] + hd * np.linspace(-1, 1, offsets)
    ra = tr[i] - np.sqrt(np.clip(hd ** 2 - (ya - th[i]) ** 2, 0, None))  # the lowest reach points
    rb = tr[j] - np.sqrt(np.clip(hd ** 2 - (yb - th[j]) ** 2, 0, None))
    Ya, Yb = np.meshgrid(ya, yb, indexing="ij")
    Ra, Rb = np.meshgrid(ra, rb, indexing="ij")
    y = Ya[..., None] + (Yb - Ya)[..., None] * f  # heights between, per choice
    r = Ra[..., None] + (Rb - Ra)[..., None] * f  # the chord there
    # The nearest an envelope point at height y, radius >= r, may lie to the profile (the
    # polyline through the bins' points, resampled finely).
    fh = np.linspace(th[0], th[-1], 4 * len(th))
    fr = np.interp(fh, th, tr)
    dy = y[..., None] - fh
    dr = np.clip(r[..., None] - fr, 0, None)
    nearest = np.sqrt(dy ** 2 + dr ** 2).min(-1)
    return bool((nearest.max(-1) > hd).all())


def bound(th, tr, lo, hi, steps=12, pairs=None):
    """The smallest Hausdorff distance no pair of profile points (`pairs`, all unless given)
    forbids (bisection)."""
    n = len(th)
    if pairs is None:
        pairs = [(i, j) for i in range(n) for j in range(i + 2, n)]
    worst = None
    for _ in range(steps):
        hd = 0.5 * (lo + hi)
        tried = ([worst] if worst else []) + pairs  # the pair that ruled out the last try first
        forbidding = next(((i, j) for i, j in tried if pair_forbids(hd, i, j, th, tr)), None)
        if forbidding is None:
            hi = hd
        else:
            lo, worst = hd, forbidding
    return lo, worst


def break_bound(th, tr, lo, hi, steps=12):
    """bound() for an envelope concave on each side of one profile point k (no chord spans it):
    the smallest distance for which some k leaves no forbidding pair on one side, and that k (of
    those, the narrowest profile point)."""
    n = len(th)
    pairs = [(i, j) for i in range(n) for j in range(i + 2, n)]
    at = None
    for _ in range(steps):
        hd = 0.5 * (lo + hi)
        forbidding = [(i, j) for i, j in pairs if pair_forbids(hd, i, j, th, tr)]
        free = [k for k in range(2, n - 2) if not any(j <= k or i >= k for i, j in forbidding)]
        if free:
            hi, at = hd, min(free, key=lambda k: tr[k])
        else:
            lo = hd
    return lo, at


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("targets", nargs="+")
    ap.add_argument("--break", dest="split", action="store_true",
                    help="also the bound for an envelope concave on each side of one height (a "
                    "free break: the least over the bins' heights)")
    args = ap.parse_args()
    for path in args.targets:
        verts = read_vertices(path)
        diag = np.linalg.norm(verts.max(0) - verts.min(0))
        hs, rs, R, height = profile(verts, bins=30)
        hd, pair = bound(hs, rs, 0.0, R)
        where = "" if pair is None else (f" (the profile's points at heights {hs[pair[0]]:.4g} and "
                                         f"{hs[pair[1]]:.4g}, radii {rs[pair[0]]:.4g} and {rs[pair[1]]:.4g})")
        print(f"{path}: diagonal {diag:.4g}, height {height:.4g}: a concave envelope stays at least "
              f"{hd:.4g} ({100 * hd / diag:.2f}% of the diagonal) from it{where}", flush=True)
        if args.split:
            broken, k = break_bound(hs, rs, 0.0, hd)
            at = "" if k is None else f" at height {hs[k]:.4g}, radius {rs[k]:.4g}"
            print(f"{path}: with one free break ({at.strip() or 'none found'}): {broken:.4g} "
                  f"({100 * broken / diag:.2f}% of the diagonal)", flush=True)


if __name__ == "__main__":
    main()
