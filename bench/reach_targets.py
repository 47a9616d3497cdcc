#!/usr/bin/env python3
"""Reachable fit targets made apart from the C++ test generators (issue 38, 1), and `fit` measured
on them.

This shares no code with tests/support: it folds designs through the Python module (`import
curvefold`, built in build/python), by rules of its own, and measures with the command line
(`curvefold fit`, `curvefold distance`). It is a benchmark, never a unit test's oracle.

    PYTHONPATH=build/python /usr/bin/python3 bench/reach_targets.py make OUT [--per-bucket K] [--seed S]
        [--recipes a,b] [--buckets 1-2,3-4,5-8] [--surfaces swept_curve,cone]
    /usr/bin/python3 bench/reach_targets.py fit OUT [--time 20] [--curvefold build/app/curvefold]
        [--only RECIPE] [--bucket 5-8] [--evaluations N] [--kind-only] [--label L]

Recipes (each target a catalogue surface; the surfaces taken in turn, a fold count drawn in the
bucket; a fold kept only when it moves part of the sheet and the design still passes `check`):
  vertex-any  default parameters; any vertex of the folded mesh grabbed (uniform over its
              vertices), dropped 5-50% of the sheet's diagonal away in a uniform 3D direction.
  params      each length parameter scaled by 0.6-1.6 (a cone truncated, a cylinder opened to
              200-330 degrees ...); any vertex, dragged 10-40%.
  onto-sheet  default parameters; a vertex on the sheet's boundary grabbed and dropped onto
              another vertex of the folded form, lifted 1-5 mm off it along a random direction
              (flaps laid over the sheet: folds of 150-180 degrees).
  symmetric   a design with one of the surface's symmetries (drawn from `surfaces()`), any
              vertex grabbed, dragged 5-30%; a fold counts once with its images. Its parameters
              (the defaults) are written out, so `fit` starts from the sheet the symmetry is of.
  outer-third issue 38's own: default parameters; a vertex in the outer third of the sheet as it
              lies (its distance from the bounding box's centre at least 2/3 of the farthest's)
              dropped 10-35% of the diagonal away in a uniform 3D direction.
  cuts        default parameters; after the first fold (as outer-third), each fold's plane is put
              through a point of an earlier crease (a uniform normal) and any vertex 5-50% of the
              diagonal from it grabbed and dropped at its mirror image: folds that cut creases.
  short-long  default parameters; any vertex; each drag either short (3-8% of the diagonal) or
              long (40-60%), evenly.
  bases       default parameters; as origami bases are folded (a square in half, corners to the
              centre: a blintz; an edge onto a crease: a kite): the form's farthest vertex along a
              uniform direction laid onto its vertex nearest its centroid, its farthest vertex the
              other way, or a point of an earlier crease, lifted off the form along its normal
              there (either side) so the fold turns by 150-180 degrees (at least 0.5 mm).
Each target is written as `export --obj` writes it, less its `vt` lines (the development), with a
line of manifest.jsonl naming its surface, parameters, symmetry and fold count.
"""
import argparse
import json
import math
import os
import random
import re
import resource
import subprocess
import sys
import time

from target_folds import (BUCKETS, boundary_vertices, diagonal, fold_if_whole, unit_vector,
                          write_target)
RECIPES = ["vertex-any", "params", "onto-sheet", "symmetric", "outer-third", "cuts", "short-long",
           "bases"]


def varied_parameters(cf, surface, rng):
    """Lengths scaled by 0.6-1.6; a few shape parameters moved within sense."""
    info = cf.surfaces()[surface]
    params = {}
    for name, p in info["parameters"].items():
        if name in ("resolution", "rotations", "hole_radius", "points"):
            continue
        default = p["default"]
        if name == "angle":
            params[name] = rng.uniform(200.0, 330.0)
        elif name == "top_radius":
            params[name] = rng.choice([0.0, rng.uniform(0.015, 0.04)])
        elif name == "ruling_start":
            continue
        elif default > 0.0:
            params[name] = default * rng.uniform(0.6, 1.6)
    if surface == "star":
        params["points"] = rng.choice([4, 6, 7])
    if surface == "star" and params.get("inner_radius", 0) >= params.get("outer_radius", 1):
        params["inner_radius"] = 0.5 * params["outer_radius"]
    if surface == "cone" and params.get("top_radius", 0.0) >= params.get("base_radius", 1.0):
        params["top_radius"] = 0.0
    return params


def vertex_normal(vertices, triangles, index):
    """The area-weighted normal of the faces around a vertex of the folded form."""
    n = [0.0, 0.0, 0.0]
    for t in triangles:
        if index not in t:
            continue
        a, b, c = (vertices[int(i)] for i in t)
        u = [b[i] - a[i] for i in range(3)]
        w = [c[i] - a[i] for i in range(3)]
        cross = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        n = [n[i] + cross[i] for i in range(3)]
    length = math.sqrt(sum(x * x for x in n))
    return [x / length for x in n] if length > 0 else None


def base_fold(design, vertices, rng, diag):
    """One fold as origami bases make them: a far vertex laid onto the centre, the far side or a
    crease, lifted off the form so the flap turns by 150-180 degrees."""
    u = unit_vector(rng)
    along = [sum(v[i] * u[i] for i in range(3)) for v in vertices]
    grab = vertices[max(range(len(vertices)), key=lambda k: along[k])]
    kind = rng.choice(["centre", "opposite", "crease"])
    if kind == "centre":
        centre = [sum(v[i] for v in vertices) / len(vertices) for i in range(3)]
        onto_index = min(range(len(vertices)), key=lambda k: math.dist(vertices[k], centre))
    elif kind == "opposite":
        onto_index = min(range(len(vertices)), key=lambda k: along[k])
    else:
        edges = design.creases()["edges"].tolist()
        if not edges:
            return None, None
        a, b = rng.choice(edges)
        onto_index = rng.choice([a, b])
    onto = vertices[onto_index]
    normal = vertex_normal(vertices, design.triangles.tolist(), onto_index)
    span = math.dist(grab, onto)
    if normal is None or span < 0.05 * diag:
        return None, None
    turn = rng.uniform(150.0, 180.0)
    lift = max(0.0005, span * math.tan(math.radians(180.0 - turn) / 2.0)) * rng.choice([-1.0, 1.0])
    return grab, [onto[i] + lift * normal[i] for i in range(3)]


def make_one(cf, recipe, surface, folds, rng):
    params = {}
    symmetry = None
    if recipe == "params":
        params = varied_parameters(cf, surface, rng)
    if recipe == "symmetric":
        symmetries = cf.surfaces()[surface].get("symmetries", [])
        if not symmetries:
            return None
        symmetry = rng.choice(symmetries)
        # Named in full: a symmetry is the catalogue sheet's, through its centre, and `fit`
        # without parameters may place a sheet on the target that lacks it (a cone's mirror:x).
        params = {name: p["default"] for name, p in cf.surfaces()[surface]["parameters"].items()
                  if name != "resolution"}
    try:
        design = cf.Design.new(surface, symmetry=symmetry, **params)
    except ValueError:
        return None
    diag = diagonal(design.vertices.tolist())
    lo, hi = {"vertex-any": (0.05, 0.5), "params": (0.10, 0.40), "symmetric": (0.05, 0.30)}.get(
        recipe, (0.0, 0.0))
    made = 0
    tries = 0
    while made < folds and tries < 40 * folds:
        tries += 1
        vertices = design.vertices.tolist()
        if recipe == "outer-third" or (recipe == "cuts" and made == 0):
            lo_box = [min(v[i] for v in vertices) for i in range(3)]
            hi_box = [max(v[i] for v in vertices) for i in range(3)]
            centre = [(lo_box[i] + hi_box[i]) / 2 for i in range(3)]
            far = max(math.dist(v, centre) for v in vertices)
            outer = [v for v in vertices if math.dist(v, centre) >= 2.0 / 3.0 * far]
            grab = rng.choice(outer)
            direction = unit_vector(rng)
            length = rng.uniform(0.10, 0.35) * diag
            drop = [grab[i] + length * direction[i] for i in range(3)]
        elif recipe == "cuts":
            edges = design.creases()["edges"].tolist()
            if not edges:
                return None
            a, b = rng.choice(edges)
            t = rng.random()
            on_crease = [vertices[a][i] + t * (vertices[b][i] - vertices[a][i]) for i in range(3)]
            normal = unit_vector(rng)
            grab = vertices[rng.randrange(len(vertices))]
            side = sum((grab[i] - on_crease[i]) * normal[i] for i in range(3))
            drop = [grab[i] - 2.0 * side * normal[i] for i in range(3)]
            if not 0.05 * diag <= math.dist(grab, drop) <= 0.5 * diag:
                continue
        elif recipe == "short-long":
            grab = vertices[rng.randrange(len(vertices))]
            direction = unit_vector(rng)
            length = (rng.uniform(0.03, 0.08) if rng.random() < 0.5 else rng.uniform(0.40, 0.60)) * diag
            drop = [grab[i] + length * direction[i] for i in range(3)]
        elif recipe == "onto-sheet":
            rim = boundary_vertices(design.triangles.tolist())
            if not rim:
                return None
            grab = vertices[rng.choice(rim)]
            onto = vertices[rng.randrange(len(vertices))]
            lift = rng.uniform(0.001, 0.005)
            direction = unit_vector(rng)
            drop = [onto[i] + lift * direction[i] for i in range(3)]
            if math.dist(grab, drop) < 0.05 * diag:
                continue
        elif recipe == "bases":
            grab, drop = base_fold(design, vertices, rng, diag)
            if grab is None:
                continue
        else:
            grab = vertices[rng.randrange(len(vertices))]
            direction = unit_vector(rng)
            length = rng.uniform(lo, hi) * diag
            drop = [grab[i] + length * direction[i] for i in range(3)]
        if not fold_if_whole(design, grab, drop):
            continue
        made += 1
    if made < folds:
        return None
    return design, params, symmetry


def command_make(args):
    import curvefold as cf

    os.makedirs(args.out, exist_ok=True)
    surfaces = list(cf.surfaces())
    manifest = open(os.path.join(args.out, "manifest.jsonl"), "w")
    for recipe in args.recipes.split(","):
        for bucket in args.buckets.split(","):
            lo, hi = BUCKETS[bucket]
            rng = random.Random(f"{args.seed}/{recipe}/{bucket}")
            order = surfaces[:]
            rng.shuffle(order)  # each bucket its own surfaces first
            if args.surfaces:
                order = [s for s in order if s in args.surfaces.split(",")]
            made, k = 0, 0
            while made < args.per_bucket and k < 8 * args.per_bucket:
                surface = order[k % len(order)]
                k += 1
                folds = rng.randint(lo, hi)
                got = make_one(cf, recipe, surface, folds, rng)
                if got is None:
                    continue
                design, params, symmetry = got
                name = f"{recipe}-{bucket}-{made:02d}-{surface}"
                write_target(design, os.path.join(args.out, name + ".obj"))
                design.save(os.path.join(args.out, name + ".curvefold.json"))
                entry = {"name": name, "recipe": recipe, "bucket": bucket, "surface": surface,
                         "parameters": params, "symmetry": symmetry, "folds": folds}
                manifest.write(json.dumps(entry) + "\n")
                manifest.flush()
                print(name, folds, "folds", params or "", symmetry or "", flush=True)
                made += 1


def hausdorff_percent(args, name):
    """`curvefold distance FITTED TARGET`: the two-sided Hausdorff distance, % of the diagonal."""
    fitted = os.path.join(args.out, "fit", name + ".curvefold.json")
    dist = subprocess.run([args.curvefold, "distance", fitted, os.path.join(args.out, name + ".obj")],
                          capture_output=True, text=True)
    m = re.search(r"Hausdorff \(two-sided\): [^(]*\(([0-9.e+-]+)% of", dist.stdout)
    return float(m.group(1)) if m else float("nan")


def run_fit(args, entry):
    target = os.path.join(args.out, entry["name"] + ".obj")
    fitted = os.path.join(args.out, "fit", entry["name"] + ".curvefold.json")
    os.makedirs(os.path.dirname(fitted), exist_ok=True)
    cmd = [args.curvefold, "fit", target, "--from", entry["surface"], "--folds",
           str(max(6, entry["folds"]) if args.folds is None else args.folds), "--time", str(args.time),
           "-o", fitted]
    if args.evaluations:  # clock-free: the same design on any machine, whatever the load
        cmd += ["--evaluations", str(args.evaluations), "--seed", "1"]
    for name, value in ({} if args.kind_only else entry["parameters"]).items():
        cmd += ["--" + name, repr(float(value)) if name != "points" else str(value)]
    if entry["symmetry"]:
        cmd += ["--symmetry", entry["symmetry"]]
    started, cpu = time.monotonic(), resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    run = subprocess.run(cmd, capture_output=True, text=True)
    seconds = time.monotonic() - started
    user = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - cpu
    if run.returncode != 0:
        return {"error": (run.stderr or run.stdout).strip().splitlines()[-1:], "seconds": seconds}
    unfolded = "the target unfolded" in run.stdout
    return {"hausdorff_percent": hausdorff_percent(args, entry["name"]), "seconds": seconds,
            "user_seconds": user,
            "unfolded": unfolded,
            "stop": [l for l in run.stdout.splitlines() if l.startswith("stopped")]}


def command_fit(args):
    entries = [json.loads(l) for l in open(os.path.join(args.out, "manifest.jsonl"))]
    results = os.path.join(args.out, f"results-{args.label}.jsonl")
    done = {}
    if os.path.exists(results):
        for l in open(results):
            r = json.loads(l)
            if "error" not in r and math.isnan(r.get("hausdorff_percent", 0.0)):
                r["hausdorff_percent"] = hausdorff_percent(args, r["name"])
            done[r["name"]] = r
    with open(results, "a") as log:
        for entry in entries:
            if args.only and entry["recipe"] not in args.only.split(","):
                continue
            if args.bucket and entry["bucket"] not in args.bucket.split(","):
                continue
            if entry["name"] in done:
                continue
            r = run_fit(args, entry)
            r["name"] = entry["name"]
            done[r["name"]] = r
            log.write(json.dumps(r) + "\n")
            log.flush()
            print(entry["name"], json.dumps(r), flush=True)
    table(entries, done)


def table(entries, done):
    print("| recipe | folds | targets | Hausdorff <= 1% | <= 3% | unfolded | median time | median user |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    groups = {}
    for e in entries:
        if e["name"] in done:
            groups.setdefault((e["recipe"], e["bucket"]), []).append(done[e["name"]])
    for (recipe, bucket), rs in groups.items():
        h = [r.get("hausdorff_percent", float("inf")) for r in rs]
        times = sorted(r["seconds"] for r in rs)
        users = sorted(r.get("user_seconds", float("nan")) for r in rs)
        print(f"| {recipe} | {bucket} | {len(rs)} | {sum(x <= 1 for x in h)} | "
              f"{sum(x <= 3 for x in h)} | {sum(bool(r.get('unfolded')) for r in rs)} | "
              f"{times[len(times) // 2]:.1f} s | {users[len(users) // 2]:.1f} s |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    make = sub.add_parser("make")
    make.add_argument("out")
    make.add_argument("--per-bucket", type=int, default=4)
    make.add_argument("--seed", default="1")
    make.add_argument("--recipes", default=",".join(RECIPES))
    make.add_argument("--buckets", default="1-2,3-4,5-8")
    make.add_argument("--surfaces", default="", help="only these catalogue surfaces (a,b)")
    fit = sub.add_parser("fit")
    fit.add_argument("out")
    fit.add_argument("--time", type=float, default=20.0)
    fit.add_argument("--folds", type=int, default=None, help="default: 6, or the target's fold count when more")
    fit.add_argument("--curvefold", default="build/app/curvefold")
    fit.add_argument("--only", default="")
    fit.add_argument("--bucket", default="")
    fit.add_argument("--label", default="run")
    fit.add_argument("--evaluations", type=int, default=0,
                     help="fit --evaluations N --seed 1 (with a --time long enough: clock-free)")
    fit.add_argument("--kind-only", action="store_true",
                     help="--from the surface's kind alone, not the target's parameters")
    args = parser.parse_args()
    (command_make if args.command == "make" else command_fit)(args)


if __name__ == "__main__":
    main()
