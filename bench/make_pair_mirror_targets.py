#!/usr/bin/env python3
"""Reachable fit targets folded in mirrored pairs (issue 38, 1), through the command line alone,
for `reach_targets.py fit`.

    /usr/bin/python3 bench/make_pair_mirror_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 1-2,3-4,5-8] [--surfaces a,b] [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --evaluations 300 --kind-only

Unlike the other generators (each fold drawn on its own, or chasing the one before), the folds
come in pairs: a grab anywhere on the form dragged 8-40% of the diagonal in a uniform direction,
then the same fold mirrored through a plane fixed for the target (through the sheet's centroid,
its normal a random horizontal direction drawn once per target): the grab's mirror image (the
vertex nearest it) dragged to the drop's. The design declares no symmetry, so the fit reads both
folds; where the two do not meet, either order folds the same form (an unfolding meets it again
by another order, moved by another pose), and where the first moved the second's grab, the pair
is a fold and a fold of its result. A pair's second fold refused (it moves nothing, or `check`
fails) is dropped and a new pair drawn. Default parameters, every catalogue surface. Targets are
the OBJ less its `vt` lines; manifest.jsonl as `reach_targets.py make` writes it.
"""
import math

import target_folds
from target_folds import cli_generator_main, unit_vector

RECIPES = ["pair-mirror"]


def mirrored(point, centre, normal):
    """`point` reflected through the plane through `centre` with unit `normal`."""
    ahead = sum((point[k] - centre[k]) * normal[k] for k in range(3))
    return [point[k] - 2.0 * ahead * normal[k] for k in range(3)]


class Pairer:
    """Remembers the target's mirror, the last fold offered and whether it was kept."""

    def __init__(self):
        self.reset()

    def reset(self):
        self.seen = None      # the vertices of the form the last choice was made on
        self.mirror = None    # (centre, normal) of the target's mirror plane
        self.last = None      # (grab, drop) offered last, and whether it opened a pair
        self.opened = False

    def choose(self, vertices, faces, diag, rng):
        vertices = [tuple(v) for v in vertices]
        kept = self.seen is not None and vertices != self.seen
        if self.mirror is None:
            centre = [sum(v[k] for v in vertices) / len(vertices) for k in range(3)]
            angle = rng.uniform(0.0, math.pi)
            self.mirror = (centre, [math.cos(angle), math.sin(angle), 0.0])
        self.seen = vertices
        if kept and self.opened and self.last is not None:
            # The pair's first fold was kept: its mirror image next.
            grab, drop = self.last
            centre, normal = self.mirror
            self.opened = False
            self.last = None
            return mirrored(grab, centre, normal), mirrored(drop, centre, normal)
        grab = list(vertices[rng.randrange(len(vertices))])
        d = unit_vector(rng)
        length = rng.uniform(0.08, 0.40) * diag
        drop = [grab[k] + length * d[k] for k in range(3)]
        self.last, self.opened = (grab, drop), True
        return grab, drop


if __name__ == "__main__":
    pairer = Pairer()
    fold_one_target = target_folds.fold_through_cli

    def fresh_target(*args, **kwargs):
        """Each target starts from its own sheet, with a mirror of its own."""
        pairer.reset()
        return fold_one_target(*args, **kwargs)

    target_folds.fold_through_cli = fresh_target
    cli_generator_main(__doc__.splitlines()[0], RECIPES, "1-2,3-4,5-8",
                       lambda recipe, vertices, faces, diag, rng: pairer.choose(
                           vertices, faces, diag, rng))
