#!/usr/bin/env python3
"""Reachable fit targets whose every fold's plane passes through two vertices of the form as it
lies (issue 38, 1), through the command line alone, for `reach_targets.py fit`.

    /usr/bin/python3 bench/make_two_vertex_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 1-2,3-4,5-8] [--surfaces a,b] [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --evaluations 300 --kind-only

Unlike the other generators (a plane drawn from a drag, or set by what it leaves behind), each
fold's plane is drawn through two vertices of the form, 10-70% of the diagonal apart: most often
(7 in 10, once earlier folds made any) two vertices those folds cut (their creases' vertices, the
ones past the sheet's own count), so the plane runs along an earlier crease or crosses two; else
any two. Its normal is uniform about the line through them; a vertex 5-50% of the diagonal off
the plane is grabbed and dropped at its mirror image, written to nine digits as every generator
writes it: the plane made passes both vertices within that rounding, a hair off either side, the
case a crease read back and made again meets (a sliver beside a vertex the fold's own plane went
through). A fold is kept when it moved the sheet and `check` passes whole. Default parameters,
every catalogue surface. Targets are the OBJ less its `vt` lines; manifest.jsonl as
`reach_targets.py make` writes it.
"""
import math

import target_folds
from target_folds import cli_generator_main, unit_vector

RECIPES = ["two-vertex"]


class TwoVertexPlanes:
    """Remembers how many vertices the target's unfolded sheet has: those past it are creases'."""

    def __init__(self):
        self.sheet_vertices = None

    def choose(self, vertices, faces, diag, rng):
        if self.sheet_vertices is None:
            self.sheet_vertices = len(vertices)
        cut = list(range(self.sheet_vertices, len(vertices)))
        pool = cut if len(cut) >= 2 and rng.random() < 0.7 else list(range(len(vertices)))
        a = vertices[rng.choice(pool)]
        far = [i for i in pool if 0.1 * diag <= math.dist(vertices[i], a) <= 0.7 * diag]
        if not far:
            return None
        b = vertices[rng.choice(far)]
        line = [b[k] - a[k] for k in range(3)]
        length = math.sqrt(sum(x * x for x in line))
        line = [x / length for x in line]
        r = unit_vector(rng)
        along = sum(r[k] * line[k] for k in range(3))
        normal = [r[k] - along * line[k] for k in range(3)]
        size = math.sqrt(sum(x * x for x in normal))
        if size < 1e-6:
            return None
        normal = [x / size for x in normal]
        for _ in range(50):
            grab = vertices[rng.randrange(len(vertices))]
            ahead = sum((grab[k] - a[k]) * normal[k] for k in range(3))
            if 0.05 * diag <= abs(ahead) <= 0.5 * diag:
                return list(grab), [grab[k] - 2.0 * ahead * normal[k] for k in range(3)]
        return None


if __name__ == "__main__":
    planes = TwoVertexPlanes()
    fold_one_target = target_folds.fold_through_cli

    def fresh_target(*args, **kwargs):
        """Each target counts its own sheet's vertices."""
        planes.sheet_vertices = None
        return fold_one_target(*args, **kwargs)

    target_folds.fold_through_cli = fresh_target
    cli_generator_main(__doc__.splitlines()[0], RECIPES, "1-2,3-4,5-8",
                       lambda recipe, vertices, faces, diag, rng: planes.choose(
                           vertices, faces, diag, rng))
