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
import argparse
import math
import os
import shutil

from target_folds import (boundary_vertices, cases, diagonal, export_obj, fmt, read_obj,
                          record_case, run, unit_vector)

RECIPES = ["rim-short", "rim-tuck"]



def make_one(cf, work, surface, recipe, folds, rng):
    design = os.path.join(work, "d.curvefold.json")
    trial = os.path.join(work, "t.curvefold.json")
    obj = os.path.join(work, "form.obj")
    if run([cf, "new", surface, "-o", design]).returncode != 0:
        return None
    export_obj(cf, design, obj)
    vertices, faces = read_obj(obj)
    diag = diagonal(vertices)
    made, tries = 0, 0
    while made < folds and tries < 30 * folds:
        tries += 1
        edge = boundary_vertices(faces)
        if not edge:
            return None
        grab = vertices[rng.choice(edge)]
        if recipe == "rim-short":
            d = unit_vector(rng)
            length = rng.uniform(0.03, 0.10) * diag
            drop = [grab[i] + length * d[i] for i in range(3)]
        else:
            centre = [sum(v[i] for v in vertices) / len(vertices) for i in range(3)]
            t = rng.uniform(0.2, 0.6)
            d = unit_vector(rng)
            lift = rng.uniform(0.0, 0.10) * diag
            drop = [grab[i] + t * (centre[i] - grab[i]) + lift * d[i] for i in range(3)]
        if math.dist(grab, drop) < 0.02 * diag:
            continue
        folded = run([cf, "fold", design, "--vertex-near", fmt(grab), "--to", fmt(drop), "-o", trial])
        if folded.returncode != 0 or run([cf, "check", trial]).returncode != 0:
            continue
        export_obj(cf, trial, obj)
        new_vertices, new_faces = read_obj(obj)
        moved = len(new_vertices) != len(vertices) or any(
            math.dist(a, b) > 1e-9 for a, b in zip(vertices, new_vertices))
        if not moved:
            continue
        shutil.copyfile(trial, design)
        vertices, faces = new_vertices, new_faces
        made += 1
    return design if made == folds else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--per-surface", type=int, default=1)
    parser.add_argument("--seed", default="1")
    parser.add_argument("--buckets", default="3-4,5-8")
    parser.add_argument("--recipes", default=",".join(RECIPES))
    parser.add_argument("--surfaces", default="")
    parser.add_argument("--curvefold", default="build/app/curvefold")
    args = parser.parse_args()
    cf = os.path.abspath(args.curvefold)
    # `surfaces` lists each as "name: what it is", its options indented below.
    listed = run([cf, "surfaces"]).stdout.splitlines()
    surfaces = sorted(l.split(":")[0] for l in listed
                      if l and not l[0].isspace() and ":" in l and " " not in l.split(":")[0])
    if args.surfaces:
        surfaces = [s for s in surfaces if s in args.surfaces.split(",")]
    os.makedirs(args.out, exist_ok=True)
    work = os.path.join(args.out, ".work")
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(args.out, "manifest.jsonl"), "w") as manifest:
        for recipe, bucket, (lo, hi), surface, rng in cases(
                args.seed, args.recipes.split(","), args.buckets.split(","), surfaces):
            made = 0
            for _ in range(3 * args.per_surface):
                if made >= args.per_surface:
                    break
                folds = rng.randint(lo, hi)
                design = make_one(cf, work, surface, recipe, folds, rng)
                if design is None:
                    continue
                name = f"{recipe}-{bucket}-{made:02d}-{surface}"
                export_obj(cf, design, os.path.join(args.out, name + ".obj"))
                shutil.copyfile(design, os.path.join(args.out, name + ".curvefold.json"))
                record_case(manifest, name, recipe, bucket, surface, folds)
                made += 1
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
