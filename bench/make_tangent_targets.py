#!/usr/bin/env python3
"""Reachable fit targets grabbed at the surface point nearest a point in space and slid along the
surface (issue 38, 1), through the command line alone, for `reach_targets.py fit`.

    /usr/bin/python3 bench/make_tangent_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 1-2,3-4,5-8] [--recipes tangent,tangent-params] [--surfaces a,b]
        [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --time 60

Written from issue 38's words ("any surface of the catalogue, any grab, any drag that `check`
passes") as someone apart from the project would, unlike the other generators, which all grab a
vertex of the form (uniform, outer or inner third, rim, mirror pairs) and drag it in a uniform
direction, toward the centroid, along the normal or onto a mirror image:
  grab  the surface point nearest a point drawn uniformly in the form's bounding box grown by a
        tenth of its diagonal on every side (`fold --vertex-near P` snaps to it, so the grab is
        seldom a vertex, and the far parts of the form, whose regions of space are largest, are
        grabbed most);
  drag  along the surface there: a uniform direction in the plane of the nearest triangle,
        tilted 5-40 degrees off it toward either side, log-uniformly 5-60% of the diagonal long
        (the bisector plane stands across the sheet, so most folds turn a flap by 100-170 degrees
        or slide the sheet past its own edge).
Recipes: `tangent`, every catalogue surface at its defaults; `tangent-params`, at parameters
drawn here (another size, radius, height, cone angle, truncation, star points, sine, helix).
A fold is kept when it moved the sheet and `check` passes whole. Targets are `export --obj` less
its `vt` lines; manifest.jsonl as `reach_targets.py make` writes it (with the parameters).
"""
import math

import numpy as np

from judge_distance import closest_points_on_triangles
from target_folds import cli_generator_main, unit_vector

RECIPES = ["tangent", "tangent-params"]


def drawn_parameters(surface, rng):
    """The sheet's parameters by rules of this generator's own (lengths in metres)."""
    u = rng.uniform
    if surface == "square":
        return {"size": u(0.1, 0.4)}
    if surface == "rectangle":
        return {"width": u(0.15, 0.4), "height": u(0.08, 0.3)}
    if surface == "disk":
        return {"radius": u(0.05, 0.2)}
    if surface == "star":
        outer = u(0.06, 0.15)
        return {"points": rng.choice([4, 6, 7, 8]), "outer_radius": outer,
                "inner_radius": outer * u(0.35, 0.65)}
    if surface == "cylinder":
        return {"radius": u(0.03, 0.08), "height": u(0.1, 0.3),
                "angle": rng.choice([360.0, u(180.0, 330.0)])}
    if surface == "half_cylinder":
        return {"radius": u(0.04, 0.1), "height": u(0.12, 0.3)}
    if surface == "cone":
        base = u(0.05, 0.12)
        return {"base_radius": base, "height": u(0.06, 0.2),
                "top_radius": rng.choice([0.0, base * u(0.2, 0.5)]),
                "angle": rng.choice([360.0, u(240.0, 330.0)])}
    if surface == "swept_curve":
        return {"amplitude": u(0.005, 0.03), "wavelength": u(0.06, 0.2)}
    if surface == "helix_tangent":
        return {"radius": u(0.03, 0.06), "pitch": u(0.08, 0.16), "turns": u(0.5, 1.0)}
    return {}


def choose(vertices, faces, diag, rng):
    """The surface point nearest a point drawn in the grown bounding box, and its drop slid
    along the surface there."""
    v = np.array(vertices)
    tri = v[np.array(faces)]
    lo, hi = v.min(0) - 0.1 * diag, v.max(0) + 0.1 * diag
    p = np.array([rng.uniform(lo[i], hi[i]) for i in range(3)])
    near = closest_points_on_triangles(p[None], tri[:, 0], tri[:, 1], tri[:, 2])
    k = int(((near - p) ** 2).sum(1).argmin())
    grab = near[k]
    normal = np.cross(tri[k, 1] - tri[k, 0], tri[k, 2] - tri[k, 0])
    normal /= np.linalg.norm(normal)
    along = np.array(unit_vector(rng))
    along -= along.dot(normal) * normal
    if np.linalg.norm(along) < 1e-6:
        return None
    along /= np.linalg.norm(along)
    tilt = math.radians(rng.uniform(5.0, 40.0)) * rng.choice([-1.0, 1.0])
    direction = math.cos(tilt) * along + math.sin(tilt) * normal
    length = diag * math.exp(rng.uniform(math.log(0.05), math.log(0.60)))
    return grab.tolist(), (grab + length * direction).tolist()


if __name__ == "__main__":
    cli_generator_main(
        __doc__.splitlines()[0], RECIPES, "1-2,3-4,5-8",
        lambda recipe, vertices, faces, diag, rng: choose(vertices, faces, diag, rng),
        lambda recipe, surface, rng: drawn_parameters(surface, rng) if recipe == "tangent-params" else {})
