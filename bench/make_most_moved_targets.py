#!/usr/bin/env python3
"""Reachable fit targets whose every fold moves all of the sheet but a small part of it (issue 38,
1), through the command line alone, for `reach_targets.py fit`.

    /usr/bin/python3 bench/make_most_moved_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 1-2,3-4,5-8] [--surfaces a,b] [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --evaluations 300 --kind-only

Unlike the other generators (each grabs a point and drags it some share of the diagonal: the part
a fold moves is whatever lies on the grab's side of the bisector plane, mostly the smaller part),
each fold here is chosen by the part it leaves: a uniform direction, and a plane across it that
leaves 2-15% of the sheet's vertices (as it lies, folds and all) behind it; the vertex farthest
ahead of the plane is grabbed and dropped at its mirror image, so the fold turns over the rest of
the sheet and every crease made before it, and a later fold whose plane crosses an earlier crease
inside the part it leaves splits that crease into two planes. Default parameters, every
catalogue surface. A fold is kept when it moved the sheet and `check` passes whole. Targets are
the OBJ less its `vt` lines; manifest.jsonl as `reach_targets.py make` writes it.
"""
from target_folds import cli_generator_main, unit_vector

RECIPES = ["most-moved"]


def choose(vertices, faces, diag, rng):
    """The plane across a uniform direction that leaves 2-15% of the vertices behind it; the
    vertex farthest ahead grabbed, dropped at its mirror image."""
    direction = unit_vector(rng)
    along = sorted(sum(v[k] * direction[k] for k in range(3)) for v in vertices)
    left = rng.uniform(0.02, 0.15)
    level = along[int(left * (len(along) - 1))]
    ahead = max(vertices, key=lambda v: sum(v[k] * direction[k] for k in range(3)))
    over = sum(ahead[k] * direction[k] for k in range(3)) - level
    return ahead, [ahead[k] - 2.0 * over * direction[k] for k in range(3)]


if __name__ == "__main__":
    cli_generator_main(__doc__.splitlines()[0], RECIPES, "1-2,3-4,5-8",
                       lambda recipe, vertices, faces, diag, rng: choose(vertices, faces, diag, rng))
