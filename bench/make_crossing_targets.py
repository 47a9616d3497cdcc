#!/usr/bin/env python3
"""Reachable fit targets whose folds cut the creases made before them (issue 38, 1), through the
command line alone, for `reach_targets.py fit`.

    /usr/bin/python3 bench/make_crossing_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 1-2,3-4,5-8] [--surfaces a,b] [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --time 60

Unlike the other generators, which grab anywhere (a vertex, the outer third, the rim, the point
nearest one in space) with no regard to what is folded already, each fold after the first grabs
a vertex of an earlier crease (an edge whose faces turn by over 20 degrees) and drags it along
that crease, 10-40% of the diagonal, turned up to 30 degrees off it: the fold's bisector plane
then stands across the crease and cuts it (and the flap it bounds). The first fold grabs a
uniform vertex and drags it 15-45% of the diagonal in a uniform direction. Every catalogue
surface at its defaults (recipe `crossing`), or at parameters drawn by make_tangent_targets.py's
rules (`--recipes crossing-params`: another size, radius, cone angle, sine, helix). A fold is kept when it moved the sheet and `check`
passes whole. Targets are `export --obj` less its `vt` lines; manifest.jsonl as
`reach_targets.py make` writes it.
"""
import math

import numpy as np

from make_tangent_targets import drawn_parameters
from target_folds import cli_generator_main, unit_vector

RECIPES = ["crossing"]  # the default; `--recipes crossing-params` draws the parameters


def crease_edges(v, faces):
    """Edges whose two faces turn by over 20 degrees: (a, b) vertex index pairs."""
    tri = v[np.array(faces)]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    around = {}
    for f, (a, b, c) in enumerate(faces):
        for e in ((a, b), (b, c), (c, a)):
            around.setdefault((min(e), max(e)), []).append(f)
    cos20 = math.cos(math.radians(20.0))
    return [e for e, fs in around.items()
            if len(fs) == 2 and normals[fs[0]].dot(normals[fs[1]]) < cos20]


def turned_off(along, most_degrees, rng):
    """The unit vector `along` turned by up to `most_degrees` toward a uniform direction across
    it (None where the drawn direction lies along it)."""
    off = np.array(unit_vector(rng))
    off -= off.dot(along) * along
    if np.linalg.norm(off) < 1e-6:
        return None
    off /= np.linalg.norm(off)
    turn = math.radians(rng.uniform(0.0, most_degrees))
    return math.cos(turn) * along + math.sin(turn) * off


def choose(vertices, faces, diag, rng):
    v = np.array(vertices)
    creases = crease_edges(v, faces)
    if not creases:
        grab = v[rng.randrange(len(v))]
        return grab.tolist(), (grab + diag * rng.uniform(0.15, 0.45) * np.array(unit_vector(rng))).tolist()
    a, b = creases[rng.randrange(len(creases))]
    along = v[b] - v[a]
    if np.linalg.norm(along) < 1e-12:
        return None
    along /= np.linalg.norm(along)
    if rng.random() < 0.5:
        along = -along
    # Turned off the crease by up to 30 degrees in a uniform direction across it.
    direction = turned_off(along, 30.0, rng)
    if direction is None:
        return None
    grab = v[a if rng.random() < 0.5 else b]
    return grab.tolist(), (grab + diag * rng.uniform(0.10, 0.40) * direction).tolist()


if __name__ == "__main__":
    cli_generator_main(__doc__.splitlines()[0], RECIPES, "1-2,3-4,5-8",
                       lambda recipe, vertices, faces, diag, rng: choose(vertices, faces, diag, rng),
                       lambda recipe, surface, rng:
                       drawn_parameters(surface, rng) if recipe == "crossing-params" else {})
