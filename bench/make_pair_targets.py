#!/usr/bin/env python3
"""Reachable fit targets folded in mirror pairs, as plain folds (issue 38, 1), for
`reach_targets.py fit`.

    PYTHONPATH=build/python /usr/bin/python3 bench/make_pair_targets.py OUT [--per-surface K]
        [--seed S] [--buckets 1-2,3-4,5-8] [--surfaces a,b]
    /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --time 60

Unlike the other generators, each fold here is followed by its mirror image, made as a fold of its
own: a designer folding the left wing, then the right one to match, without the design's
`--symmetry` (`make_symmetric_targets.py` and `reach_targets.py`'s `symmetric` recipe fold with it,
and `fit` is told it; here it is not). The mirror is one of the surface's own (`surfaces()`:
`mirror:AXIS`, through the middle of the sheet's bounding box). A pair: a vertex of the folded form
with its mirror image on the form (its distance from the bounding box's middle at least half the
farthest's) dragged 10-35% of the diagonal in a uniform direction, then the grab's mirror image
dropped at the drop's mirror image. So the second fold's plane is the first's mirror image, and
where the first fold's flap reached across the mirror the second folds that flap with the rest
(folds that cut the first's crease). Fold counts are even where the bucket allows (1-2: 2). Every catalogue
surface with a mirror, at its default parameters; a fold is kept when it moved a vertex and the
design passes `check` whole (a pair whose second fold is refused is undone whole). Targets are
`export --obj` less its `vt` lines; manifest.jsonl as `reach_targets.py make` writes it, the
recipe `mirror-pairs` and no symmetry.
"""
import math

from target_folds import diagonal, fold_if_whole, module_generator_main, unit_vector


def mirror_of(symmetry, centre):
    """The reflection through the sheet's mirror `mirror:AXIS` (through `centre`)."""
    axis = "xyz".index(symmetry.split(":")[1])

    def reflect(p):
        q = list(p)
        q[axis] = 2.0 * centre[axis] - p[axis]
        return q

    return reflect


def nearest(vertices, p):
    return min(range(len(vertices)), key=lambda k: math.dist(vertices[k], p))


def make_one(cf, surface, folds, rng):
    mirrors = [s for s in cf.surfaces()[surface].get("symmetries", []) if s.startswith("mirror:")]
    if not mirrors:
        return None
    design = cf.Design.new(surface)
    first = design.vertices.tolist()
    centre = [(min(v[i] for v in first) + max(v[i] for v in first)) / 2.0 for i in range(3)]
    reflect = mirror_of(rng.choice(mirrors), centre)
    diag = diagonal(first)
    made, tries = 0, 0
    while made < folds and tries < 100 * folds:
        tries += 1
        vertices = design.vertices.tolist()
        lo = [min(v[i] for v in vertices) for i in range(3)]
        hi = [max(v[i] for v in vertices) for i in range(3)]
        middle = [(lo[i] + hi[i]) / 2.0 for i in range(3)]
        far = max(math.dist(v, middle) for v in vertices)
        grab = vertices[rng.randrange(len(vertices))]
        if math.dist(grab, middle) < 0.5 * far:
            continue
        direction = unit_vector(rng)
        length = rng.uniform(0.10, 0.35) * diag
        drop = [grab[i] + length * direction[i] for i in range(3)]
        # Its mirror image must be on the form too, and not the grab itself (a vertex on the mirror).
        image = reflect(grab)
        if math.dist(image, grab) < 0.05 * diag:
            continue
        if math.dist(vertices[nearest(vertices, image)], image) > 1e-6 * diag:
            continue
        if not fold_if_whole(design, grab, drop):
            continue
        if made + 1 == folds:  # an odd count: the last fold alone
            made += 1
            break
        if not fold_if_whole(design, image, reflect(drop)):
            design.undo()
            continue
        made += 2
    return design if made == folds else None


def pair_count(rng, lo, hi):
    folds = rng.randint(lo, hi)
    return folds + (folds % 2 if folds < hi else 0)  # whole pairs where the bucket allows


def main():
    module_generator_main(__doc__.splitlines()[0], "mirror-pairs", make_one, 8, pair_count)


if __name__ == "__main__":
    main()
