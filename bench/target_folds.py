"""What the bench's target generators share (make_drag_targets.py, make_symmetric_targets.py,
reach_targets.py, make_rim_targets.py, make_plane_targets.py, make_tangent_targets.py): a fold
kept only when it moved the sheet and `check` passes whole, the target written as `export --obj` less its vt lines, the
fold-count buckets and each case's own random stream, and the small geometry they choose folds
with (the bounding diagonal, the rim, a uniform direction). How each generator chooses its folds
stays its own, so their targets differ. make_rim_targets.py and make_plane_targets.py drive the
binary, not the module: they use what does not fold (read_obj, strip_vt and the rest).
make_area_normal_targets.py and make_symmetric_plane_targets.py share seeded_generator_main (their
command line, manifest and files). distance_truth.py reads OBJ files with read_obj."""
import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys

BUCKETS = {"1-2": (1, 2), "3-4": (3, 4), "5-8": (5, 8)}


def cases(seed, recipes, buckets, surfaces):
    """(recipe, bucket, (fewest, most) folds, surface, its random stream) for every recipe, then
    bucket, then surface; each stream seeded by all four, so a case does not depend on others."""
    for recipe in recipes:
        for bucket in buckets:
            for surface in surfaces:
                yield (recipe, bucket, BUCKETS[bucket], surface,
                       random.Random(f"{seed}/{recipe}/{bucket}/{surface}"))


def record_case(manifest, name, recipe, bucket, surface, folds, parameters=None):
    """One manifest.jsonl line for a target made (as reach_targets.py reads it), flushed, and
    the target named on stdout. `parameters`: the sheet's, where not its defaults."""
    entry = {"name": name, "recipe": recipe, "bucket": bucket, "surface": surface,
             "parameters": parameters or {}, "symmetry": None, "folds": folds}
    manifest.write(json.dumps(entry) + "\n")
    manifest.flush()
    print(name, folds, "folds", flush=True)


def diagonal(vertices):
    """The bounding box's diagonal."""
    lo = [min(v[i] for v in vertices) for i in range(3)]
    hi = [max(v[i] for v in vertices) for i in range(3)]
    return math.dist(lo, hi)


def unit_vector(rng, dimensions=3):
    """A direction uniform on the sphere (a normalised Gaussian)."""
    while True:
        v = [rng.gauss(0.0, 1.0) for _ in range(dimensions)]
        n = math.sqrt(sum(x * x for x in v))
        if n > 1e-9:
            return [x / n for x in v]


def boundary_vertices(triangles):
    """The vertices on the rim (an edge of one triangle), sorted."""
    count = {}
    for t in triangles:
        for i in range(3):
            a, b = int(t[i]), int(t[(i + 1) % 3])
            key = (min(a, b), max(a, b))
            count[key] = count.get(key, 0) + 1
    return sorted({v for key, c in count.items() if c == 1 for v in key})


def read_obj(path):
    """An OBJ's positions and triangles (0-based; a polygon as a fan, negative indices counted
    back from the last position), as lists."""
    positions, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                positions.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                ids = [int(p.split("/")[0]) for p in parts[1:]]
                ids = [i - 1 if i > 0 else len(positions) + i for i in ids]
                for k in range(1, len(ids) - 1):
                    faces.append([ids[0], ids[k], ids[k + 1]])
    return positions, faces


def strip_vt(full, path):
    """`full` (an `export --obj`) written to `path` less its vt lines, faces keeping only their
    vertex indices; `full` removed."""
    with open(full) as f, open(path, "w") as out:
        for line in f:
            if line.startswith("vt "):
                continue
            if line.startswith("f "):
                line = "f " + " ".join(p.split("/")[0] for p in line.split()[1:]) + "\n"
            out.write(line)
    os.remove(full)


def fold_if_whole(design, grab, drop):
    """Folds grab onto drop; keeps the fold when it moved the sheet and the design passes
    `check` whole (undone otherwise). True when kept."""
    before = design.vertices
    try:
        result = design.fold(grab=grab, to=drop)
    except ValueError:
        return False
    if not result.folded:
        return False
    after = design.vertices
    moved = before.shape != after.shape or bool((abs(after[: len(before)] - before) > 1e-9).any())
    if not moved or not design.check().passed:
        design.undo()
        return False
    return True


def write_target(design, path):
    """`export --obj` less its vt lines; faces keep only their vertex indices."""
    tmp = path + ".full.obj"
    design.export(obj=tmp)
    strip_vt(tmp, path)


def run(cmd):
    """A command line's result, its output captured (the generators that drive the binary)."""
    return subprocess.run(cmd, capture_output=True, text=True)


def export_obj(cf, design, path):
    """`export --obj`, its vt lines and face texture indices dropped."""
    full = path + ".full.obj"
    got = run([cf, "export", design, "--obj", full])
    if got.returncode != 0:
        raise RuntimeError(got.stderr)
    strip_vt(full, path)


def fmt(p):
    """A point as the command line's x,y,z."""
    return ",".join("%.9g" % x for x in p)


def fold_through_cli(cf, work, surface, folds, choose, rng, parameters=None):
    """`folds` folds of the catalogue's `surface` (at its defaults, or with `parameters`) through
    the binary, each (grab, drop) from `choose(vertices, faces, diagonal, rng)` (None: try
    again), kept when it moves the sheet and `check` passes whole; the design's path, or None
    after 30 tries a fold (or when `new` refuses the parameters)."""
    design = os.path.join(work, "d.curvefold.json")
    trial = os.path.join(work, "t.curvefold.json")
    obj = os.path.join(work, "form.obj")
    options = [x for name, value in (parameters or {}).items() for x in ("--" + name, str(value))]
    if run([cf, "new", surface, *options, "-o", design]).returncode != 0:
        return None
    export_obj(cf, design, obj)
    vertices, faces = read_obj(obj)
    diag = diagonal(vertices)
    made, tries = 0, 0
    while made < folds and tries < 30 * folds:
        tries += 1
        chosen = choose(vertices, faces, diag, rng)
        if chosen is None:
            continue
        grab, drop = chosen
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


def cli_generator_main(description, recipes, buckets, choose,
                       parameters=lambda recipe, surface, rng: {}):
    """The command line of a generator that drives the binary: for every recipe, bucket and
    catalogue surface (`curvefold surfaces`), `--per-surface` targets folded by
    fold_through_cli with `choose(recipe, vertices, faces, diagonal, rng)` from the sheet of
    `parameters(recipe, surface, rng)` (drawn per try; {}: the defaults), written with their
    designs and manifest.jsonl into `out`."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("out")
    parser.add_argument("--per-surface", type=int, default=1)
    parser.add_argument("--seed", default="1")
    parser.add_argument("--buckets", default=buckets)
    parser.add_argument("--recipes", default=",".join(recipes))
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
                params = parameters(recipe, surface, rng)
                folds = rng.randint(lo, hi)
                design = fold_through_cli(
                    cf, work, surface, folds,
                    lambda v, f, d, r, recipe=recipe: choose(recipe, v, f, d, r), rng, params)
                if design is None:
                    continue
                name = f"{recipe}-{bucket}-{made:02d}-{surface}"
                export_obj(cf, design, os.path.join(args.out, name + ".obj"))
                shutil.copyfile(design, os.path.join(args.out, name + ".curvefold.json"))
                record_case(manifest, name, recipe, bucket, surface, folds, params)
                made += 1
    shutil.rmtree(work)


def module_generator_main(description, recipe, make_one, tries_per_target,
                          fold_count=lambda rng, lo, hi: rng.randint(lo, hi)):
    """The command line of a generator that folds through the Python module: for every bucket
    and catalogue surface, `--per-surface` targets made by `make_one(cf, surface, folds, rng)`
    (None when it could not), with `fold_count(rng, lo, hi)` folds, at most `tries_per_target`
    tries each, written with their designs and manifest.jsonl into `out`."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("out")
    parser.add_argument("--per-surface", type=int, default=1)
    parser.add_argument("--seed", default="1")
    parser.add_argument("--buckets", default="1-2,3-4,5-8")
    parser.add_argument("--surfaces", default="", help="only these catalogue surfaces (a,b)")
    args = parser.parse_args()
    import curvefold as cf

    os.makedirs(args.out, exist_ok=True)
    surfaces = [s for s in cf.surfaces() if not args.surfaces or s in args.surfaces.split(",")]
    with open(os.path.join(args.out, "manifest.jsonl"), "w") as manifest:
        for recipe_, bucket, (lo, hi), surface, rng in cases(args.seed, [recipe],
                                                             args.buckets.split(","), surfaces):
            made = 0
            for _ in range(tries_per_target * args.per_surface):
                if made == args.per_surface:
                    break
                folds = fold_count(rng, lo, hi)
                design = make_one(cf, surface, folds, rng)
                if design is None:
                    continue
                name = f"{recipe_}-{bucket}-{made:02d}-{surface}"
                write_target(design, os.path.join(args.out, name + ".obj"))
                design.save(os.path.join(args.out, name + ".curvefold.json"))
                record_case(manifest, name, recipe_, bucket, surface, folds)
                made += 1


def seeded_generator_main(description, prefix, recipe, seed, buckets, surfaces, draw_symmetry,
                          make_target, add_options=lambda parser: None):
    """The command line of a generator that folds through the Python module and names each target
    by its seed (make_area_normal_targets.py, make_symmetric_plane_targets.py): for every surface
    (`surfaces(catalogue)`, or --surfaces), bucket and --per-surface, the target
    `{prefix}{seed}-{surface}-{bucket}-{k}` from its own random stream, which draws the fold count,
    then `draw_symmetry(args, rng, catalogue, surface)` (None: none), then `make_target(rng,
    surface, folds, symmetry, defaults)` -> (design, parameters, steps) (design None: skipped; a
    ValueError: a symmetry the sheet lacks, refused). Written into `out` with its design
    (designs/) and a manifest.jsonl line (appended); `add_options(parser)` adds a generator's own."""
    import curvefold as cf

    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=seed)
    parser.add_argument("--per-surface", type=int, default=1)
    parser.add_argument("--buckets", default=buckets)
    parser.add_argument("--surfaces", default="")
    add_options(parser)
    args = parser.parse_args()
    os.makedirs(os.path.join(args.out, "designs"), exist_ok=True)
    catalogue = cf.surfaces()
    chosen = args.surfaces.split(",") if args.surfaces else surfaces(catalogue)
    with open(os.path.join(args.out, "manifest.jsonl"), "a") as manifest:
        for surface in chosen:
            spec = catalogue[surface]["parameters"]
            defaults = {k: int(s["default"]) if s["integer"] else s["default"]
                        for k, s in spec.items()}
            for bucket in args.buckets.split(","):
                lo, hi = (int(x) for x in bucket.split("-"))
                for k in range(args.per_surface):
                    name = f"{prefix}{args.seed}-{surface}-{bucket}-{k}"
                    rng = random.Random(f"{args.seed}/{name}")
                    folds = rng.randint(lo, hi)
                    symmetry = draw_symmetry(args, rng, catalogue, surface)
                    try:
                        design, params, steps = make_target(rng, surface, folds, symmetry, defaults)
                    except ValueError as e:  # a symmetry the sheet lacks
                        print(name, symmetry, "refused:", e, file=sys.stderr, flush=True)
                        continue
                    if design is None:
                        print(name, "no fold passed check; skipped", file=sys.stderr, flush=True)
                        continue
                    write_target(design, os.path.join(args.out, name + ".obj"))
                    design.save(os.path.join(args.out, "designs", name + ".curvefold.json"))
                    entry = {"name": name, "recipe": recipe, "bucket": bucket, "surface": surface,
                             "parameters": params, "symmetry": symmetry, "folds": folds,
                             "steps": steps}
                    manifest.write(json.dumps(entry) + "\n")
                    manifest.flush()
                    print(name, folds, symmetry or "", steps, flush=True)
