#!/usr/bin/env python3
"""Reachable fit targets dented from the middle of the sheet by short drags, in metres or in
millimetres and moved anywhere (issue 38, 1), through the command line alone, for
`reach_targets.py fit`.

    /usr/bin/python3 bench/make_interior_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 1-2,3-4,5-8] [--recipes interior,interior-mm] [--surfaces a,b]
        [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --evaluations 300 --kind-only

Unlike the other generators (grabs anywhere, on the rim, in the outer or inner third of the
bounding box, on a crease, at the point nearest one in space; drags of 3-60%; targets in the
catalogue's frame and in metres), each fold grabs a vertex deep inside the sheet as it lies: its
distance from every rim vertex at least 15% of the diagonal (the deepest tenth of the vertices
where none is that deep), and drags it only 2-10% of the diagonal, in a uniform direction, so the
folds turn small caps and short flaps out of the middle of the sheet. Sheets at parameters drawn
by this generator's own rules, on every catalogue surface (a size, a radius, a height, a cone's
angle and truncation, a star's points, a sine, a helix's turns). Recipes: `interior`, the target
as `export --obj` writes it (metres); `interior-mm`, the same rule, the target then turned by a
uniform rotation, moved 0.2-2 diagonals off the origin and written in millimetres (every
coordinate times 1000), as a designer's CAD file would be. A fold is kept when it moved the sheet
and `check` passes whole. Targets are the OBJ less its `vt` lines; manifest.jsonl as
`reach_targets.py make` writes it (with the parameters, and for `interior-mm` its `units`).
"""
import json
import math
import os
import random

from target_folds import boundary_vertices, cli_generator_main, unit_vector

RECIPES = ["interior", "interior-mm"]


# Each parameter drawn uniformly in its range, or chosen from a list (its ranges drawn first, in
# turn); a star's points are chosen after its outer radius. A cone's top radius and a star's inner
# radius are shares of the base and outer radius drawn before them.
RANGES = {
    "square": {"size": (0.12, 0.5)},
    "rectangle": {"width": (0.1, 0.45), "height": (0.1, 0.25)},
    "disk": {"radius": (0.07, 0.25)},
    "star": {"outer_radius": (0.08, 0.2), "points": [3, 5, 9, 10], "inner_radius": (0.45, 0.8)},
    "cylinder": {"radius": (0.04, 0.1), "height": (0.08, 0.25), "angle": [360.0, (120.0, 300.0)]},
    "half_cylinder": {"radius": (0.05, 0.12), "height": (0.08, 0.25)},
    "cone": {"base_radius": (0.06, 0.14), "height": (0.05, 0.15), "top_radius": [0.0, (0.3, 0.6)],
             "angle": [360.0, (200.0, 300.0)]},
    "swept_curve": {"amplitude": (0.008, 0.025), "wavelength": (0.1, 0.25)},
    "helix_tangent": {"radius": (0.035, 0.07), "pitch": (0.1, 0.2), "turns": (0.6, 1.2)},
}
SHARE_OF = {"top_radius": "base_radius", "inner_radius": "outer_radius"}


def drawn_parameters(surface, rng):
    """The sheet's parameters by this generator's rules (lengths in metres)."""
    drawn = {}
    for name, spec in RANGES.get(surface, {}).items():
        share = SHARE_OF.get(name)
        def value(x):
            if not isinstance(x, tuple):
                return x
            return rng.uniform(*x) * (drawn[share] if share else 1.0)
        drawn[name] = rng.choice([value(x) for x in spec]) if isinstance(spec, list) else value(spec)
    return drawn


def choose(vertices, faces, diag, rng):
    """A vertex deep inside the sheet as it lies, dragged 2-10% of the diagonal."""
    rim = boundary_vertices(faces)
    if not rim:
        return None
    rim_points = [vertices[i] for i in rim[:: 1 + len(rim) // 400]]
    depth = []
    for i in range(0, len(vertices), 1 + len(vertices) // 1500):
        p = vertices[i]
        depth.append((min(math.dist(p, q) for q in rim_points), i))
    depth.sort(reverse=True)
    deep = [i for d, i in depth if d >= 0.15 * diag] or [i for d, i in depth[: 1 + len(depth) // 10]]
    grab = vertices[rng.choice(deep)]
    length = rng.uniform(0.02, 0.10) * diag
    direction = unit_vector(rng)
    return grab, [grab[k] + length * direction[k] for k in range(3)]


def rotation(rng):
    """A uniform rotation (a uniform unit quaternion), as rows."""
    w, x, y, z = unit_vector(rng, 4)
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def to_millimetres(out, seed):
    """Every `interior-mm` target turned, moved and scaled to millimetres in place (its own
    random stream, from the seed and its name); the manifest notes the units."""
    path = os.path.join(out, "manifest.jsonl")
    entries = [json.loads(line) for line in open(path)]
    for entry in entries:
        if entry["recipe"] != "interior-mm":
            continue
        rng = random.Random(f"{seed}/move/{entry['name']}")
        obj = os.path.join(out, entry["name"] + ".obj")
        lines = open(obj).read().splitlines()
        points = [[float(x) for x in l.split()[1:4]] for l in lines if l.startswith("v ")]
        lo = [min(p[i] for p in points) for i in range(3)]
        hi = [max(p[i] for p in points) for i in range(3)]
        diag = math.dist(lo, hi)
        turn = rotation(rng)
        shift = [c * diag * rng.uniform(0.2, 2.0) for c in unit_vector(rng)]
        written = []
        for l in lines:
            if l.startswith("v "):
                p = [float(x) for x in l.split()[1:4]]
                q = [sum(turn[r][c] * p[c] for c in range(3)) + shift[r] for r in range(3)]
                l = "v " + " ".join(f"{1000.0 * x:.9g}" for x in q)
            written.append(l)
        with open(obj, "w") as f:
            f.write("\n".join(written) + "\n")
        entry["units"] = "mm"
    with open(path, "w") as f:
        for entry in entries:
            f.write(json.dumps(entry) + "\n")


if __name__ == "__main__":
    import sys
    cli_generator_main(
        __doc__.splitlines()[0], RECIPES, "1-2,3-4,5-8",
        lambda recipe, vertices, faces, diag, rng: choose(vertices, faces, diag, rng),
        lambda recipe, surface, rng: drawn_parameters(surface, rng))
    out = next(a for a in sys.argv[1:] if not a.startswith("--") and
               sys.argv[sys.argv.index(a) - 1] not in
               ("--per-surface", "--seed", "--buckets", "--recipes", "--surfaces", "--curvefold"))
    seed = sys.argv[sys.argv.index("--seed") + 1] if "--seed" in sys.argv else "1"
    to_millimetres(out, seed)
