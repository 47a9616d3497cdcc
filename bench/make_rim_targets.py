#!/usr/bin/env python3
"""Reachable fit targets folded through the command line alone, grabbed at the sheet's rim
(issue 38, 1), for `reach_targets.py fit`.

    /usr/bin/python3 bench/make_rim_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 3-4,5-8] [--recipes rim-short,rim-tuck] [--surfaces a,b]
        [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --time 60

Unlike the other generators (`reach_targets.py`, `make_drag_targets.py`,
`make_symmetric_targets.py`, which fold through the Python module), this one drives the
`curvefold` binary as a user at a shell would: `new`, then `fold DESIGN --vertex-near P --to Q`
(the grabbed point snapped by the command), `check` for every invariant (a fold whose design
fails is dropped: the design file of the step before is kept), and `export --obj`. It reads the
folded form back from that OBJ and grabs only boundary vertices (edges of one triangle), as a
designer pulls an edge or a corner of paper:
  rim-short  a rim vertex dragged 3-10% of the diagonal in a uniform 3D direction (small flaps
             and corners turned, many of them crossing earlier creases' flaps);
  rim-tuck   a rim vertex pulled toward the form's centroid by 20-60% of its distance to it and
             lifted 0-10% of the diagonal along a uniform direction (flaps tucked in across the
             sheet, so later folds cut the earlier creases).
Every catalogue surface at its default parameters. A fold is kept only when it moved a vertex
and `check` passes whole. Targets are the OBJ less its `vt` lines; manifest.jsonl as
`reach_targets.py make` writes it.
"""
from target_folds import boundary_vertices, cli_generator_main, unit_vector

RECIPES = ["rim-short", "rim-tuck"]


def choose(recipe, vertices, faces, diag, rng):
    """A vertex of the rim and where `recipe` drops it, or None (no rim)."""
    edge = boundary_vertices(faces)
    if not edge:
        return None
    grab = vertices[rng.choice(edge)]
    if recipe == "rim-short":
        d = unit_vector(rng)
        length = rng.uniform(0.03, 0.10) * diag
        return grab, [grab[i] + length * d[i] for i in range(3)]
    centre = [sum(v[i] for v in vertices) / len(vertices) for i in range(3)]
    t = rng.uniform(0.2, 0.6)
    d = unit_vector(rng)
    lift = rng.uniform(0.0, 0.10) * diag
    return grab, [grab[i] + t * (centre[i] - grab[i]) + lift * d[i] for i in range(3)]


if __name__ == "__main__":
    cli_generator_main(__doc__.splitlines()[0], RECIPES, "3-4,5-8", choose)
