#!/usr/bin/env python3
"""Reachable fit targets whose every fold grabs the part the fold before it moved (issue 38, 1),
through the command line alone, for `reach_targets.py fit`.

    /usr/bin/python3 bench/make_chase_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 1-2,3-4,5-8] [--surfaces a,b] [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --evaluations 300 --kind-only

Unlike the other generators (a grab anywhere on the form, or a plane chosen by what it leaves),
each fold here chases the one before: the grab is a vertex of the part the last fold moved (the
vertices whose place changed; the first fold a rim vertex), and the plane lies between the grab
and the form's centroid, at 25-75% of the way, its normal that way tilted by up to 35 degrees; the
grab is dropped at its mirror image. So a flap is folded, then its own tip folded again, then the
tip of that, and each crease cuts the flap the fold before made (and the creases it carries).
Default parameters, every catalogue surface. A fold is kept when it moved the sheet and `check`
passes whole. Targets are the OBJ less its `vt` lines; manifest.jsonl as `reach_targets.py make`
writes it.
"""
import math

import target_folds
from target_folds import boundary_vertices, cli_generator_main, unit_vector

RECIPES = ["chase"]


class Chaser:
    """Remembers the form each fold was chosen on, so the next knows which vertices moved."""

    def __init__(self):
        self.seen = None  # the vertices of the form the last choice was made on
        self.moved = []   # indices of the vertices the last kept fold moved

    def choose(self, vertices, faces, diag, rng):
        if self.seen is None:
            self.moved = []  # a new sheet: its first fold grabs the rim
        elif [tuple(v) for v in vertices] != self.seen:
            # A fold was kept since the last choice: the vertices whose place changed.
            self.moved = [i for i in range(len(self.seen))
                          if math.dist(vertices[i], self.seen[i]) > 1e-9 * diag]
        self.seen = [tuple(v) for v in vertices]
        vertices = self.seen
        pool = self.moved or sorted(boundary_vertices(faces))
        grab = vertices[rng.choice(pool)]
        centre = [sum(v[k] for v in vertices) / len(vertices) for k in range(3)]
        toward = [centre[k] - grab[k] for k in range(3)]
        length = math.sqrt(sum(x * x for x in toward))
        if length < 1e-9 * diag:
            return None
        toward = [x / length for x in toward]
        # Tilt: a uniform direction's part across `toward`, scaled to a tangent of 0-35 degrees.
        u = unit_vector(rng)
        across = [u[k] - sum(u[j] * toward[j] for j in range(3)) * toward[k] for k in range(3)]
        norm = math.sqrt(sum(x * x for x in across)) or 1.0
        tilt = math.tan(math.radians(rng.uniform(0.0, 35.0)))
        normal = [toward[k] + tilt * across[k] / norm for k in range(3)]
        nl = math.sqrt(sum(x * x for x in normal))
        normal = [x / nl for x in normal]
        point = [grab[k] + rng.uniform(0.25, 0.75) * length * toward[k] for k in range(3)]
        ahead = sum((point[k] - grab[k]) * normal[k] for k in range(3))
        return grab, [grab[k] + 2.0 * ahead * normal[k] for k in range(3)]


if __name__ == "__main__":
    chaser = Chaser()
    fold_one_target = target_folds.fold_through_cli

    def fresh_target(*args, **kwargs):
        """Each target starts from its own sheet: nothing moved yet."""
        chaser.seen, chaser.moved = None, []
        return fold_one_target(*args, **kwargs)

    target_folds.fold_through_cli = fresh_target
    cli_generator_main(__doc__.splitlines()[0], RECIPES, "1-2,3-4,5-8",
                       lambda recipe, vertices, faces, diag, rng: chaser.choose(
                           vertices, faces, diag, rng))
