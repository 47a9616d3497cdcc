#!/usr/bin/env python3
"""Symmetric fit targets by a second rule (issue 38, 1), unlike `reach_targets.py`'s `symmetric`
recipe, for `reach_targets.py fit`.

    PYTHONPATH=build/python /usr/bin/python3 bench/make_symmetric_targets.py OUT [--per-bucket K]
        [--seed S] [--buckets 1-2,3-4,5-8]
    /usr/bin/python3 bench/reach_targets.py fit OUT --time 60 --only sym-mirror,sym-rotational

Where `reach_targets.py` draws a drag (a vertex and a direction), this draws the fold's plane: a
plane through a vertex of the folded form with a uniform normal, so every crease crosses the
sheet; the part moved is the side of a vertex 3-30% of the diagonal from the plane (grabbed and
dropped at its mirror image). The symmetries are chosen, not drawn from the surface's list: a
mirror (recipe `sym-mirror`) or a rotation of order 2 to 6, divisors of the surface's own
(`sym-rotational`), on the square, the disk, the cylinder and the cone at their defaults. A fold
counts once with its images; it is kept when it moves part of the sheet and the design passes
`check` whole. Targets are written as `export --obj` less its `vt` lines, with manifest.jsonl lines
as `reach_targets.py make` writes them.
"""
import argparse
import json
import math
import os
import random

from target_folds import BUCKETS, diagonal, fold_if_whole, write_target

SYMMETRIES = {
    "sym-mirror": {
        "square": ["mirror:x", "mirror:y"],
        "disk": ["mirror:x", "mirror:y"],
        "cylinder": ["mirror:x", "mirror:y", "mirror:z"],
        "cone": ["mirror:x", "mirror:z"],
    },
    "sym-rotational": {
        "square": ["rotational:2:z", "rotational:4:z"],
        "disk": ["rotational:3:z", "rotational:4:z", "rotational:6:z"],
        "cylinder": ["rotational:3:y", "rotational:4:y", "rotational:6:y"],
        "cone": ["rotational:2:y", "rotational:4:y"],
    },
}


def unit_vector(rng):
    while True:
        v = [rng.uniform(-1.0, 1.0) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in v))
        if 1e-3 < n <= 1.0:
            return [x / n for x in v]


def make_one(cf, surface, symmetry, folds, rng):
    design = cf.Design.new(surface, symmetry=symmetry)
    diag = diagonal(design.vertices.tolist())
    made, tries = 0, 0
    while made < folds and tries < 60 * folds:
        tries += 1
        vertices = design.vertices.tolist()
        through = vertices[rng.randrange(len(vertices))]
        normal = unit_vector(rng)
        side = [sum((v[i] - through[i]) * normal[i] for i in range(3)) for v in vertices]
        grabbable = [k for k, s in enumerate(side) if 0.03 * diag <= abs(s) <= 0.30 * diag]
        if not grabbable:
            continue
        k = rng.choice(grabbable)
        grab = vertices[k]
        drop = [grab[i] - 2.0 * side[k] * normal[i] for i in range(3)]
        if not fold_if_whole(design, grab, drop):
            continue
        made += 1
    return design if made == folds else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--per-bucket", type=int, default=4)
    parser.add_argument("--seed", default="1")
    parser.add_argument("--buckets", default="1-2,3-4,5-8")
    args = parser.parse_args()
    import curvefold as cf

    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "manifest.jsonl"), "w") as manifest:
        for recipe, by_surface in SYMMETRIES.items():
            surfaces = sorted(by_surface)
            for bucket in args.buckets.split(","):
                lo, hi = BUCKETS[bucket]
                rng = random.Random(f"{args.seed}/{recipe}/{bucket}")
                made, k = 0, rng.randrange(len(surfaces))
                for _ in range(6 * args.per_bucket):
                    if made >= args.per_bucket:
                        break
                    surface = surfaces[k % len(surfaces)]
                    k += 1
                    symmetry = rng.choice(by_surface[surface])
                    folds = rng.randint(lo, hi)
                    design = make_one(cf, surface, symmetry, folds, rng)
                    if design is None:
                        continue
                    name = f"{recipe}-{bucket}-{made:02d}-{surface}"
                    write_target(design, os.path.join(args.out, name + ".obj"))
                    design.save(os.path.join(args.out, name + ".curvefold.json"))
                    entry = {"name": name, "recipe": recipe, "bucket": bucket, "surface": surface,
                             "parameters": {}, "symmetry": symmetry, "folds": folds}
                    manifest.write(json.dumps(entry) + "\n")
                    manifest.flush()
                    print(name, folds, "folds", symmetry, flush=True)
                    made += 1


if __name__ == "__main__":
    main()
