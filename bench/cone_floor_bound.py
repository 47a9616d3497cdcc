#!/usr/bin/python3
"""How near a cup a cone start could come if its open floor end were closed (issue 38, 2), numpy.
Usage: bench/cone_floor_bound.py FIT.obj FIT.log TARGET.obj OUT.obj

A placed cone (`fit --from cone` on a cup) is a frustum: its narrow end is open, and the fit's
rings narrow it only so far (ring_folds.hpp), so the cup's floor centre stays as far from the
sheet as the hole's radius (its Hausdorff point). This closes that end of the exported fit
(FIT.obj, `curvefold export --obj`) with a flat fan to the axis (the axis read from the fit's
`from:` line in FIT.log, "axis (...) through (...)"): a floor of paper turned flat, the best a
ring folding the cone's extended lower band inward could lay there, distance-wise. It writes the
closed mesh to OUT.obj and prints the hole's radius and the judge's line (judge_distance.py:
hausdorff chamfer diag hausdorff% chamfer%) for OUT against TARGET. A bound to decide whether
such a floor is worth building, not a design: the fan is no fold and `check` does not apply.
"""
import collections
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from judge_distance import read_obj  # noqa: E402


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: cone_floor_bound.py FIT.obj FIT.log TARGET.obj OUT.obj")
    fit, log, target, out = sys.argv[1:5]
    verts, faces = read_obj(fit)
    found = re.search(r"axis \(([^)]*)\) through \(([^)]*)\)", open(log).read())
    if not found:
        sys.exit(f"error: {log} names no placed axis (a fit from a placed cone prints one)")
    axis = np.array([float(x) for x in found.group(1).split(",")])
    axis /= np.linalg.norm(axis)
    point = np.array([float(x) for x in found.group(2).split(",")])
    # Boundary vertices (edges of one triangle), their height along the axis and radius from it.
    uses = collections.Counter()
    for f in faces:
        for u, v in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            uses[(min(u, v), max(u, v))] += 1
    rim = np.array(sorted({x for e, k in uses.items() if k == 1 for x in e}))
    height = (verts[rim] - point) @ axis
    radius = np.linalg.norm(verts[rim] - point - np.outer(height, axis), axis=1)
    # The narrow end: of the boundary within 15% of the height range of either end, the one of
    # smaller mean radius (the slit's vertices between the ends are left out).
    lo, hi = height.min(), height.max()
    ends = [height < lo + 0.15 * (hi - lo), height > hi - 0.15 * (hi - lo)]
    end = min(ends, key=lambda s: radius[s].mean())
    centre = point + height[end].mean() * axis
    side = np.cross(axis, [1.0, 0.0, 0.0])
    if np.linalg.norm(side) < 0.1:
        side = np.cross(axis, [0.0, 1.0, 0.0])
    side /= np.linalg.norm(side)
    offset = verts[rim[end]] - centre
    turn = np.arctan2(offset @ np.cross(axis, side), offset @ side)
    ring = rim[end][np.argsort(turn)]
    fan = [(len(verts), ring[i], ring[(i + 1) % len(ring)]) for i in range(len(ring))]
    partial = out + ".partial"  # written whole, then moved over OUT
    with open(partial, "w") as o:
        for p in np.vstack([verts, centre]):
            o.write("v %.9g %.9g %.9g\n" % tuple(p))
        for f in np.vstack([faces, np.array(fan)]):
            o.write("f %d %d %d\n" % tuple(np.asarray(f) + 1))
    os.replace(partial, out)
    print(f"hole radius {radius[end].mean():.6g}")
    judge = os.path.join(os.path.dirname(os.path.abspath(__file__)), "judge_distance.py")
    os.execv(sys.executable, [sys.executable, judge, out, target])


if __name__ == "__main__":
    main()
