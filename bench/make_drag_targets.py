#!/usr/bin/env python3
"""Drag targets by issue 38's own recipe, on every catalogue surface, with two variants (issue 38,
1), for `reach_targets.py fit`.

    PYTHONPATH=build/python /usr/bin/python3 bench/make_drag_targets.py OUT [--per-surface K]
        [--seed S] [--buckets 3-4,5-8] [--variants outer,centre,remeshed] [--surfaces a,b]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --time 30

Unlike `reach_targets.py` (surfaces taken in turn from a shuffled list, a few per bucket) and
`make_symmetric_targets.py` (planes drawn, symmetric sheets), this takes every surface of the
catalogue at its default parameters, K targets per surface and bucket, and drags as the issue says:
each fold grabs a vertex of the folded form and drops it 10-35% of the diagonal away in a uniform
3D direction; it is kept when the design passes `check` whole (and the fold moved something).
Variants (recipe names in the manifest):
  drag-outer     the grabbed vertex in the outer third of the sheet as it lies: its distance from
                 the bounding box's centre at least 2/3 of the farthest vertex's.
  drag-centre    the grabbed vertex in the inner third: at most 1/3 of the farthest's (a fold
                 through the middle of the sheet, a flap that is half of it); on a tube, whose
                 centre is off the sheet, the tenth of the vertices nearest the centre.
  drag-remeshed  as drag-outer, but the target is written on a mesh of its own: each triangle
                 split 1->4 at its edges' midpoints (shared midpoints welded) and the vertices
                 listed in a shuffled order, so no target vertex index or position set is the
                 design's (hidden targets need not share our mesh).
Targets are written as `export --obj` writes them less the `vt` lines (the development); the
remeshed ones from the folded vertices and triangles. manifest.jsonl lines are as `reach_targets.py
make` writes them (name, recipe, bucket, surface, parameters, symmetry, folds).
"""
import argparse
import math
import os

from target_folds import cases, fold_if_whole, record_case, unit_vector, write_target
VARIANTS = ["outer", "centre", "remeshed"]


def bounding_box(vertices):
    lo = [min(v[i] for v in vertices) for i in range(3)]
    hi = [max(v[i] for v in vertices) for i in range(3)]
    return lo, hi


def grab_candidates(vertices, variant):
    lo, hi = bounding_box(vertices)
    centre = [(lo[i] + hi[i]) / 2.0 for i in range(3)]
    far = max(math.dist(v, centre) for v in vertices)
    if variant == "centre":
        inner = [v for v in vertices if math.dist(v, centre) <= far / 3.0]
        # A tube's centre lies on its axis, off the sheet: then the tenth of the vertices nearest it.
        nearest = sorted(vertices, key=lambda v: math.dist(v, centre))[: max(1, len(vertices) // 10)]
        return inner or nearest
    return [v for v in vertices if math.dist(v, centre) >= 2.0 * far / 3.0]


def make_one(cf, surface, variant, folds, rng):
    design = cf.Design.new(surface)
    lo, hi = bounding_box(design.vertices.tolist())
    diag = math.dist(lo, hi)
    made, tries = 0, 0
    while made < folds and tries < 50 * folds:
        tries += 1
        vertices = design.vertices.tolist()
        candidates = grab_candidates(vertices, variant)
        if not candidates:
            return None
        grab = rng.choice(candidates)
        direction = unit_vector(rng)
        length = rng.uniform(0.10, 0.35) * diag
        drop = [grab[i] + length * direction[i] for i in range(3)]
        if not fold_if_whole(design, grab, drop):
            continue
        made += 1
    return design if made == folds else None


def write_remeshed(design, path, rng):
    """Each triangle split 1->4 at its edges' midpoints, vertices in a shuffled order."""
    points = [tuple(v) for v in design.vertices.tolist()]
    triangles = [tuple(int(i) for i in t) for t in design.triangles.tolist()]
    midpoint = {}

    def middle(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint:
            midpoint[key] = len(points)
            points.append(tuple((points[a][i] + points[b][i]) / 2.0 for i in range(3)))
        return midpoint[key]

    split = []
    for a, b, c in triangles:
        ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
        split += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    order = list(range(len(points)))
    rng.shuffle(order)
    new_index = {old: new for new, old in enumerate(order)}
    with open(path, "w") as out:
        out.write("# drag-remeshed target: the folded form split 1->4, vertices shuffled\n")
        for old in order:
            out.write("v %.9g %.9g %.9g\n" % points[old])
        for t in split:
            out.write("f %d %d %d\n" % tuple(new_index[i] + 1 for i in t))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--per-surface", type=int, default=3, help="targets per surface and bucket")
    parser.add_argument("--seed", default="1")
    parser.add_argument("--buckets", default="3-4,5-8")
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--surfaces", default="", help="only these catalogue surfaces (a,b)")
    args = parser.parse_args()
    import curvefold as cf

    surfaces = sorted(cf.surfaces())
    if args.surfaces:
        surfaces = [s for s in surfaces if s in args.surfaces.split(",")]
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "manifest.jsonl"), "w") as manifest:
        for variant, bucket, (lo, hi), surface, rng in cases(
                args.seed, args.variants.split(","), args.buckets.split(","), surfaces):
            recipe = "drag-" + variant
            made = 0
            for _ in range(4 * args.per_surface):
                if made >= args.per_surface:
                    break
                folds = rng.randint(lo, hi)
                design = make_one(cf, surface, variant, folds, rng)
                if design is None:
                    continue
                name = f"{recipe}-{bucket}-{made:02d}-{surface}"
                target = os.path.join(args.out, name + ".obj")
                if variant == "remeshed":
                    write_remeshed(design, target, rng)
                else:
                    write_target(design, target)
                design.save(os.path.join(args.out, name + ".curvefold.json"))
                record_case(manifest, name, recipe, bucket, surface, folds)
                made += 1


if __name__ == "__main__":
    main()
