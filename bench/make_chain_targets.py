#!/usr/bin/env python3
"""Reachable fit targets folded as a chain, each fold cutting the crease the fold before it made,
on curved sheets at extreme parameters (issue 38, 1), through the command line alone, for
`reach_targets.py fit`.

    /usr/bin/python3 bench/make_chain_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 3-4,5-8] [--surfaces a,b] [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --evaluations 300

Unlike the other generators (a grab anywhere, or on any earlier crease, dragged in a drawn
direction; sheets at the defaults or at moderate parameters), each fold after the first is
placed by its plane: through a point of the newest crease (the sharp edges the last fold made),
its normal the crease's direction there turned up to 35 degrees off it, so the plane cuts that
crease across; the vertex grabbed lies 5-40% of the diagonal from the plane on either side and is
dropped at its mirror image (the fold is that plane's). The first fold grabs a uniform vertex and
drags it 15-45% of the diagonal in a uniform direction. The sheets (recipe `chain-extreme`): a
helix's tangent developable of 1-2.5 turns on a narrow radius, a swept sine either steep (its
amplitude a quarter to a half of its wavelength) or nearly flat (2-4 mm), a cone either thin or
nearly flat, a narrow tube. A fold is kept when it moved the sheet and `check` passes whole.
Targets are `export --obj` less its `vt` lines; manifest.jsonl as `reach_targets.py make` writes it
(with the parameters).
"""

import numpy as np

from make_crossing_targets import crease_edges, turned_off
from target_folds import cli_generator_main, unit_vector

RECIPES = ["chain-extreme"]
SURFACES = ["helix_tangent", "swept_curve", "cone", "cylinder"]


def extreme_parameters(surface, rng):
    """The sheet's parameters at the ends of sense (lengths in metres); {} for other surfaces."""
    u = rng.uniform
    if surface == "helix_tangent":
        return {"radius": u(0.015, 0.03), "pitch": u(0.05, 0.2), "turns": u(1.0, 2.5)}
    if surface == "swept_curve":
        wavelength = u(0.06, 0.14)
        if rng.random() < 0.5:
            return {"amplitude": wavelength * u(0.25, 0.5), "wavelength": wavelength}
        return {"amplitude": u(0.002, 0.004), "wavelength": wavelength}
    if surface == "cone":
        if rng.random() < 0.5:
            return {"base_radius": u(0.02, 0.035), "height": u(0.15, 0.25)}
        return {"base_radius": u(0.1, 0.15), "height": u(0.015, 0.03)}
    if surface == "cylinder":
        return {"radius": u(0.012, 0.02), "height": u(0.15, 0.3)}
    return {}


def sharp_edges(v, faces):
    """Edges whose two faces turn by over 20 degrees (make_crossing_targets.py's): (midpoint,
    unit direction) arrays."""
    edges = crease_edges(v, faces)
    if not edges:
        return np.zeros((0, 3)), np.zeros((0, 3))
    a = v[np.array([e[0] for e in edges])]
    b = v[np.array([e[1] for e in edges])]
    d = b - a
    return 0.5 * (a + b), d / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-300)


class Chain:
    """The fold chooser of one target: remembers the form's sharp edges, so the newest crease is
    the sharp edges the last kept fold added."""

    def __init__(self):
        self.form = None
        self.sharp = np.zeros((0, 3))
        self.newest = (np.zeros((0, 3)), np.zeros((0, 3)))

    def update(self, v, faces, diag):
        key = (len(v), round(float(v.sum()), 12))
        if key == self.form:
            return
        self.form = key
        mid, direction = sharp_edges(v, faces)
        if len(self.sharp) and len(mid):
            near = np.min(np.linalg.norm(mid[:, None, :] - self.sharp[None, :, :], axis=2), axis=1)
            new = near > 1e-3 * diag
        else:
            new = np.ones(len(mid), dtype=bool)
        if not len(mid):  # a fresh sheet (the next try): no crease yet
            self.newest = (mid, direction)
        elif new.any():  # else the last fold moved the sheet whole: its newest crease stays
            self.newest = (mid[new], direction[new])
        self.sharp = mid

    def __call__(self, vertices, faces, diag, rng):
        v = np.array(vertices)
        self.update(v, faces, diag)
        mid, direction = self.newest
        if not len(mid):
            grab = v[rng.randrange(len(v))]
            drop = grab + diag * rng.uniform(0.15, 0.45) * np.array(unit_vector(rng))
            return grab.tolist(), drop.tolist()
        k = rng.randrange(len(mid))
        point, along = mid[k], direction[k]
        normal = turned_off(along, 35.0, rng)
        if normal is None:
            return None
        side = (v - point) @ normal
        lo, hi = 0.05 * diag, 0.40 * diag
        sign = rng.choice([-1.0, 1.0])
        candidates = np.nonzero((sign * side >= lo) & (sign * side <= hi))[0]
        if not len(candidates):
            return None
        grab = v[candidates[rng.randrange(len(candidates))]]
        drop = grab - 2.0 * ((grab - point) @ normal) * normal
        return grab.tolist(), drop.tolist()


if __name__ == "__main__":
    chains = {}

    def choose(recipe, vertices, faces, diag, rng):
        # One chain per random stream (a target's): its remembered creases are its own.
        return chains.setdefault(id(rng), Chain())(vertices, faces, diag, rng)

    import sys
    if "--surfaces" not in sys.argv:
        sys.argv += ["--surfaces", ",".join(SURFACES)]
    cli_generator_main(__doc__.splitlines()[0], RECIPES, "3-4,5-8", choose,
                       lambda recipe, surface, rng: extreme_parameters(surface, rng))
