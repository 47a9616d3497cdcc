"""What the bench's target generators share (make_drag_targets.py, make_symmetric_targets.py,
reach_targets.py, make_rim_targets.py, make_plane_targets.py): a fold kept only when it moved
the sheet and `check` passes whole, the target written as `export --obj` less its vt lines, the
fold-count buckets and each case's own random stream, and the small geometry they choose folds
with (the bounding diagonal, the rim, a uniform direction). How each generator chooses its folds
stays its own, so their targets differ. make_rim_targets.py and make_plane_targets.py drive the
binary, not the module: they use what does not fold (read_obj, strip_vt and the rest).
distance_truth.py reads OBJ files with read_obj."""
import json
import math
import os
import random
import subprocess

BUCKETS = {"1-2": (1, 2), "3-4": (3, 4), "5-8": (5, 8)}


def cases(seed, recipes, buckets, surfaces):
    """(recipe, bucket, (fewest, most) folds, surface, its random stream) for every recipe, then
    bucket, then surface; each stream seeded by all four, so a case does not depend on others."""
    for recipe in recipes:
        for bucket in buckets:
            for surface in surfaces:
                yield (recipe, bucket, BUCKETS[bucket], surface,
                       random.Random(f"{seed}/{recipe}/{bucket}/{surface}"))


def record_case(manifest, name, recipe, bucket, surface, folds):
    """One manifest.jsonl line for a target made (as reach_targets.py reads it), flushed, and
    the target named on stdout."""
    entry = {"name": name, "recipe": recipe, "bucket": bucket, "surface": surface,
             "parameters": {}, "symmetry": None, "folds": folds}
    manifest.write(json.dumps(entry) + "\n")
    manifest.flush()
    print(name, folds, "folds", flush=True)


def diagonal(vertices):
    """The bounding box's diagonal."""
    lo = [min(v[i] for v in vertices) for i in range(3)]
    hi = [max(v[i] for v in vertices) for i in range(3)]
    return math.dist(lo, hi)


def unit_vector(rng):
    """A direction uniform on the sphere (a normalised Gaussian)."""
    while True:
        v = [rng.gauss(0.0, 1.0) for _ in range(3)]
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
