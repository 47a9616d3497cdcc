#!/usr/bin/env python3
"""Reachable fit targets chosen by area and the normal (issue 38, 1; judge17), for an
independent judge of `curvefold fit`.

    PYTHONPATH=build/python /usr/bin/python3 bench/make_area_normal_targets.py OUT [--seed S]
        [--per-surface K] [--buckets 1-2,3-4,5-8] [--surfaces a,b] [--symmetric-share 0.25]

Written from issue 38's words alone ("any surface of the catalogue, any grab, any drag that
`check` passes"; "grab anywhere, short and long drags, folds that cut earlier creases, symmetric
designs"), unlike the other generators (uniform vertices, outer or inner third, the rim, mirror
pairs, planes drawn first, the nearest point to one in space, pushes along a vertex normal
tilted 10-50 degrees): the grab is the centroid of a triangle drawn by its area (so the grab is
area-uniform over the form as it lies, seldom a vertex, and on a folded flap as often as its
area says), in one of three regions drawn per fold: anywhere, a triangle with an edge on the
rim, or a triangle with no vertex on the rim. The drag is log-uniform 2-60% of the bounding
diagonal (short and long alike), its direction the triangle's normal with either sign plus a
uniform unit vector of length 0.9 (so it leans toward the normal, anywhere from along it to
nearly across it). A share of the targets (25% unless asked) is folded with one of the
surface's own symmetries (`surfaces()`), each fold counting once with its images. Every
catalogue surface at its default parameters. A fold is kept when it moved the sheet and `check`
passes whole (else it is undone and another drawn, 40 tries per fold). Targets are written by
`export --obj` less its `vt` lines (and the faces' `/vt` indices); OUT/manifest.jsonl names
each target's surface, symmetry (with the defaults written out then, so `fit` starts from the
sheet the symmetry is of) and fold count; OUT/designs/ keeps each design that made a target (for
build/bench/unfold_report).
"""

import math
import os
import sys

import curvefold as cf
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from target_folds import seeded_generator_main  # noqa: E402


def draw_fold(rng, design):
    """A grab (a triangle's centroid, drawn by area in a region) and a drop near the normal."""
    v = np.asarray(design.vertices, dtype=float)
    t = np.asarray(design.triangles, dtype=np.int64)
    diag = float(np.linalg.norm(v.max(axis=0) - v.min(axis=0)))
    edges = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    keys = edges[:, 0] * (len(v) + 1) + edges[:, 1]
    unique, counts = np.unique(keys, return_counts=True)
    rim_keys = unique[counts == 1]
    on_rim_edge = np.isin(keys, rim_keys).reshape(3, -1).any(axis=0)
    rim_vertex = np.zeros(len(v), bool)
    rim_vertex[edges[np.isin(keys, rim_keys)].ravel()] = True
    region = rng.choice(["anywhere", "rim", "interior"])
    mask = np.ones(len(t), bool)
    if region == "rim":
        mask = on_rim_edge
    elif region == "interior":
        mask = ~rim_vertex[t].any(axis=1)
    if not mask.any():
        mask = np.ones(len(t), bool)
    normals = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    areas = 0.5 * np.linalg.norm(normals, axis=1) * mask
    pick = rng.choices(range(len(t)), weights=areas.tolist())[0]
    grab = v[t[pick]].mean(axis=0)
    n = normals[pick] / (np.linalg.norm(normals[pick]) or 1.0)
    # A uniform direction by rejection in the cube (not target_folds.unit_vector's Gaussian: the
    # sets measured were drawn so).
    while True:
        u = np.array([rng.uniform(-1.0, 1.0) for _ in range(3)])
        if 1e-3 < np.linalg.norm(u) <= 1.0:
            u /= np.linalg.norm(u)
            break
    d = rng.choice([-1.0, 1.0]) * n + 0.9 * u
    d /= np.linalg.norm(d) or 1.0
    share = math.exp(rng.uniform(math.log(0.02), math.log(0.60)))
    return grab.tolist(), (grab + share * diag * d).tolist(), region, share


def make_target(rng, surface, folds, symmetry, defaults):
    params = dict(defaults) if symmetry else {}
    design = cf.Design.new(surface, symmetry=symmetry, **params) if symmetry else cf.Design.new(surface)
    steps = []
    for _ in range(folds):
        for _ in range(40):
            before = len(design.folds)
            grab, to, region, share = draw_fold(rng, design)
            try:
                result = design.fold(grab=tuple(grab), to=tuple(to))
            except ValueError:
                continue
            if not result.folded:
                if len(design.folds) > before:
                    design.undo()
                continue
            if design.check().passed:
                steps.append({"region": region, "drag": round(share, 4)})
                break
            design.undo()
        else:
            return None, None, None
    return design, params, steps


def draw_symmetry(args, rng, catalogue, surface):
    """One of the surface's own symmetries, for a share of the targets (--symmetric-share)."""
    if catalogue[surface]["symmetries"] and rng.random() < args.symmetric_share:
        return rng.choice(catalogue[surface]["symmetries"])
    return None


def main():
    seeded_generator_main(
        __doc__.splitlines()[0], "an", "area-normal", 17, "1-2,3-4,5-8", sorted, draw_symmetry,
        make_target,
        lambda p: p.add_argument("--symmetric-share", type=float, default=0.25))


if __name__ == "__main__":
    main()
