#!/usr/bin/env python3
"""Reachable fit targets folded through planes chosen first (issue 38, 1), through the command
line alone, for `reach_targets.py fit`.

    /usr/bin/python3 bench/make_plane_targets.py OUT [--per-surface K] [--seed S]
        [--buckets 1-2,3-4,5-8] [--recipes plane-cut,long-cut,centre-grab] [--surfaces a,b]
        [--curvefold build/app/curvefold]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --time 60

Unlike the other generators, which choose a grab and a drop (the plane is their bisector, so
many miss the sheet and move it whole), most folds here start from the plane:
  plane-cut    a plane through a point of the form (a vertex drawn uniformly) with a normal
               uniform on the sphere; a vertex on one side of it, at least 5% of the diagonal off
               the plane, is grabbed and dropped on its mirror image (`fold --vertex-near P --to
               R(P)`), so the fold is through that plane and always creases the sheet;
  long-cut     any vertex dragged 35-60% of the diagonal in a uniform direction, kept only when
               its plane separates the ends of an earlier crease (an edge whose faces meet at over
               20 degrees in the form), so every fold after the first cuts an earlier crease;
  centre-grab  a vertex in the inner third of the form (from its bounding box's centre, at most
               1/3 of the farthest vertex's distance) dragged 10-35% in a uniform direction.
Every catalogue surface at its default parameters; a fold kept when it moved a vertex and `check`
passes whole. Targets are the OBJ less its `vt` lines; manifest.jsonl as `reach_targets.py make`
writes it.
"""
import math

from target_folds import cli_generator_main, unit_vector

RECIPES = ["plane-cut", "long-cut", "centre-grab"]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def crease_edges(vertices, faces, degrees=20.0):
    """Edges whose two faces meet at more than `degrees` (the form's creases)."""
    normals, at = [], {}
    for f, t in enumerate(faces):
        n = cross(sub(vertices[t[1]], vertices[t[0]]), sub(vertices[t[2]], vertices[t[0]]))
        length = math.sqrt(dot(n, n)) or 1.0
        normals.append([x / length for x in n])
        for i in range(3):
            a, b = t[i], t[(i + 1) % 3]
            at.setdefault((min(a, b), max(a, b)), []).append(f)
    limit = math.cos(math.radians(degrees))
    return [e for e, fs in at.items() if len(fs) == 2 and dot(normals[fs[0]], normals[fs[1]]) < limit]


def choose(recipe, vertices, faces, diag, rng):
    """A grab and a drop for `recipe`, or None."""
    if recipe == "plane-cut":
        through = vertices[rng.randrange(len(vertices))]
        n = unit_vector(rng)
        side = rng.choice([-1.0, 1.0])
        far = [v for v in vertices if side * dot(sub(v, through), n) > 0.05 * diag]
        if not far:
            return None
        grab = far[rng.randrange(len(far))]
        d = dot(sub(grab, through), n)
        return grab, [grab[i] - 2.0 * d * n[i] for i in range(3)]
    if recipe == "long-cut":
        grab = vertices[rng.randrange(len(vertices))]
        n = unit_vector(rng)
        length = rng.uniform(0.35, 0.60) * diag
        drop = [grab[i] + length * n[i] for i in range(3)]
        creases = crease_edges(vertices, faces)
        if creases:
            mid = [0.5 * (grab[i] + drop[i]) for i in range(3)]
            cuts = any(dot(sub(vertices[a], mid), n) * dot(sub(vertices[b], mid), n) < 0.0
                       for a, b in creases)
            if not cuts:
                return None
        return grab, drop
    lo = [min(v[i] for v in vertices) for i in range(3)]
    hi = [max(v[i] for v in vertices) for i in range(3)]
    centre = [0.5 * (lo[i] + hi[i]) for i in range(3)]
    farthest = max(math.dist(v, centre) for v in vertices)
    inner = [v for v in vertices if math.dist(v, centre) <= farthest / 3.0]
    if not inner:
        return None
    grab = inner[rng.randrange(len(inner))]
    n = unit_vector(rng)
    length = rng.uniform(0.10, 0.35) * diag
    return grab, [grab[i] + length * n[i] for i in range(3)]



if __name__ == "__main__":
    cli_generator_main(__doc__.splitlines()[0], RECIPES, "1-2,3-4,5-8", choose)
