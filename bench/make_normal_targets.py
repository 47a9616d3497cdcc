#!/usr/bin/env python3
"""Reachable fit targets made by drags along the form's own normal (issue 38, 1), for
`reach_targets.py fit`.

    PYTHONPATH=build/python /usr/bin/python3 bench/make_normal_targets.py OUT [--per-surface K]
        [--seed S] [--buckets 1-2,3-4,5-8] [--surfaces a,b]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --time 60

Unlike the other generators, whose drags go in a uniform direction (reach_targets.py,
make_drag_targets.py, make_pair_targets.py, make_outer_third_targets.sh), toward the centroid
(make_rim_targets.py's rim-tuck) or from a plane chosen first (make_plane_targets.py), each fold
here pushes a point of the folded form along the form's own normal there, in or out, as a finger
dents paper: any vertex of the form (anywhere, rim or middle, uniform over the vertices), dragged
5-30% of the diagonal along its vertex normal (area-weighted normals of its triangles as the form
lies now) with a random sign, tilted off the normal by 10-50 degrees toward a uniform direction in
the tangent plane. The bisector plane then lies nearly parallel to the surface there: on a curved
sheet it cuts a cap off (a dent or a pop), on a flat one it cuts a flap whose crease lies
d / (2 sin tilt) from the grab (a short tilt reaches far), and where it misses the sheet the fold
moves the whole sheet. Every catalogue surface at its default parameters; a fold kept when it moved
the sheet and the design passes `check` whole. Targets are `export --obj` less its `vt` lines;
manifest.jsonl as `reach_targets.py make` writes it, the recipe `normal-push` and no symmetry.
"""
import math

from target_folds import diagonal, fold_if_whole, module_generator_main, unit_vector


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalised(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v] if n > 1e-12 else None


def vertex_normal(vertices, triangles, v):
    """The area-weighted normal of the triangles around vertex v (None where they cancel)."""
    total = [0.0, 0.0, 0.0]
    for t in triangles:
        if v not in t:
            continue
        a, b, c = (vertices[int(i)] for i in t)
        n = cross([b[i] - a[i] for i in range(3)], [c[i] - a[i] for i in range(3)])
        total = [total[i] + n[i] for i in range(3)]
    return normalised(total)


def make_one(cf, surface, folds, rng):
    design = cf.Design.new(surface)
    diag = diagonal(design.vertices.tolist())
    made, tries = 0, 0
    while made < folds and tries < 60 * folds:
        tries += 1
        vertices = design.vertices.tolist()
        triangles = design.triangles.tolist()
        v = rng.randrange(len(vertices))
        normal = vertex_normal(vertices, triangles, v)
        if normal is None:
            continue
        # A tangent direction: a uniform direction less its part along the normal.
        d = unit_vector(rng)
        tangent = normalised([d[i] - sum(d[j] * normal[j] for j in range(3)) * normal[i]
                              for i in range(3)])
        if tangent is None:
            continue
        tilt = math.radians(rng.uniform(10.0, 50.0))
        sign = rng.choice((-1.0, 1.0))
        direction = [sign * math.cos(tilt) * normal[i] + math.sin(tilt) * tangent[i]
                     for i in range(3)]
        length = rng.uniform(0.05, 0.30) * diag
        grab = vertices[v]
        if fold_if_whole(design, grab, [grab[i] + length * direction[i] for i in range(3)]):
            made += 1
    return design if made == folds else None


def main():
    module_generator_main(__doc__.splitlines()[0], "normal-push", make_one, 4)


if __name__ == "__main__":
    main()
