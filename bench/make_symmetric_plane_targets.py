#!/usr/bin/env python3
"""Symmetric fit targets folded by planes near the symmetry's centre (issue 38, 1; sym19), a
second symmetric set beside judge17's `make_area_normal_targets.py`.

    PYTHONPATH=build/python /usr/bin/python3 bench/make_symmetric_plane_targets.py OUT [--seed S]
        [--per-surface K] [--buckets 1-2,3-4,5-6] [--surfaces a,b]

Unlike judge17's set (a quarter symmetric, each with one of the catalogue's listed symmetries,
grabs drawn by area, drags along the normal), every target here is symmetric, and the symmetry
is drawn from a list that favours what that set seldom drew: mirrors of order 2 on the square
and the disk, rotations of order 3-6 about the cylinder's, cone's and disk's axes (orders the
catalogue does not list but its meshes hold: 12 and 8 are its listed orders), the star's
five-fold turn. Unlike `make_symmetric_targets.py` (a plane through any vertex, the part a few
per cent of the diagonal beyond it), each fold is drawn plane first, of one of three kinds:
*crossing* (half the folds), a plane through a vertex 5-30% of the sheet's reach from its
bounding box's centre, its normal uniform, the grab 15% of the reach or more beyond it (so the
fold's images cut its crease and each other); *most* (35%), a plane through a vertex 55-90% out
with its normal leaning outward and the grab on the centre's side (the part moved is most of the
sheet, the class whose images move it whole); *whole* (15%, at most once, never first), a plane
past the sheet (the whole of it mirrored, which symmetric fits read as a motion); a kind that
finds no fold passing `check` in 40 tries gives way to a crossing fold. The drop is the grab mirrored through
the plane, so the fold is that plane's. A fold is kept when it moved
the sheet and `check` passes whole (`target_folds.fold_if_whole`; 60 tries per fold). Every catalogue surface
that has a symmetry, at its default parameters (written out in the manifest, so `fit
--symmetry` starts from the sheet the symmetry is of). Targets are `export --obj` less its `vt`
lines; OUT/manifest.jsonl (read by `bench/judge_fit_runner.py`) names the surface, symmetry
and fold count; OUT/designs/ keeps each design.
"""

import os
import sys

import curvefold as cf
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from target_folds import fold_if_whole, seeded_generator_main  # noqa: E402

# Per surface, the symmetries drawn from (each once as likely).
SYMMETRIES = {
    "square": ["mirror:x", "mirror:y", "rotational:4:z", "rotational:2:z"],
    "disk": ["mirror:x", "mirror:y", "rotational:3:z", "rotational:4:z", "rotational:6:z"],
    "cylinder": ["rotational:3:y", "rotational:4:y", "rotational:6:y", "mirror:x"],
    "cone": ["rotational:4:y", "rotational:2:y", "mirror:x"],
    "rectangle": ["mirror:x", "mirror:y", "rotational:2:z"],
    "star": ["rotational:5:z", "mirror:x"],
    "half_cylinder": ["mirror:y"],
    "swept_curve": ["mirror:y", "rotational:2:y"],
}


def unit(rng):
    while True:
        n = np.array([rng.gauss(0.0, 1.0) for _ in range(3)])
        if np.linalg.norm(n) > 1e-6:
            return n / np.linalg.norm(n)


def draw_fold(rng, design, centre, kind):
    """A plane of `kind` and a grab on its far side: the grab and its mirror image."""
    v = np.asarray(design.vertices, dtype=float)
    near = np.linalg.norm(v - centre, axis=1)
    reach = float(near.max())
    if kind == "whole":
        # A plane past the sheet: the whole of it mirrored (with a symmetry, its images none).
        d = unit(rng)
        q = centre + rng.uniform(1.05, 1.4) * reach * d
        g = v[rng.randrange(len(v))]
        return g.tolist(), (g - 2.0 * float((g - q) @ d) * d).tolist()
    # crossing: through a vertex near the centre (5-30% of the reach), so the fold's images cut
    # its crease and each other; most: through one 55-90% out, its normal leaning outward, and
    # the grab on the centre's side, so the part moved is most of the sheet.
    lo, hi = (0.05, 0.30) if kind == "crossing" else (0.55, 0.90)
    share = rng.uniform(lo, hi)
    ring = np.flatnonzero(np.abs(near - share * reach) < 0.08 * reach)
    if len(ring) == 0:
        ring = np.arange(len(v))
    q = v[rng.choice(ring.tolist())]
    n = unit(rng)
    if kind == "most":
        out = q - centre
        n = out / (np.linalg.norm(out) or 1.0) + 0.6 * n
        n /= np.linalg.norm(n)
    side = (v - q) @ n
    apart = np.abs(side)
    pick = side < -0.15 * reach if kind == "most" else (side > 0) & (apart >= 0.15 * reach)
    far = np.flatnonzero(pick)
    if len(far) == 0:
        return None
    g = v[rng.choice(far.tolist())]
    return g.tolist(), (g - 2.0 * float((g - q) @ n) * n).tolist()


def make_target(rng, surface, folds, symmetry, params):
    design = cf.Design.new(surface, symmetry=symmetry, **params)
    v0 = np.asarray(design.vertices, dtype=float)
    centre = 0.5 * (v0.min(axis=0) + v0.max(axis=0))
    steps = []
    whole = False
    for f in range(folds):
        # At most one whole-sheet fold, never first (that would only place the start); a kind
        # that finds no fold passing check in 40 tries gives way to a crossing fold.
        kind = rng.choices(["crossing", "most", "whole"], weights=[0.5, 0.35, 0.15])[0]
        if kind == "whole" and (whole or f == 0):
            kind = "crossing"
        for attempt in range(60):
            if attempt == 40:
                kind = "crossing"
            drawn = draw_fold(rng, design, centre, kind)
            if drawn is None:
                continue
            grab, to = drawn
            before = len(design.folds)
            if fold_if_whole(design, tuple(grab), tuple(to)):
                steps.append({"kind": kind, "folds_with_images": len(design.folds) - before})
                whole = whole or kind == "whole"
                break
        else:
            return None, None, None
    return design, params, steps


def main():
    seeded_generator_main(
        __doc__.splitlines()[0], "sp", "symmetric-plane", 19, "1-2,3-4,5-6",
        lambda catalogue: sorted(SYMMETRIES),
        lambda args, rng, catalogue, surface: rng.choice(SYMMETRIES[surface]), make_target)


if __name__ == "__main__":
    main()
