#!/usr/bin/python3
"""Reachable targets made the way issue 38's judge describes them, from the command line alone
(`curvefold new/fold/check/export`; no project code is imported): a random sequence of reflection
folds on a catalogue surface, each fold grabbing a vertex of the folded sheet in the outer third
(distance from the bounding box's centre at least 2/3 of the largest) and dropping it 10-35% of
the bounding box's diagonal away in a direction uniform on the sphere. A fold is kept only when
`check` passes the whole design (no self-intersection allowed); a fold that fails is undone and
drawn again (at most 12 tries, then the target is started over). The target is the folded sheet
from `export --obj` with its `vt` lines removed.

Sets: `default` (each surface at its catalogue defaults) and `random` (each parameter drawn
uniformly between 0.6x and 1.6x its default, angles of cylinder/cone left at 360).
Fold-count bands: 1-2, 3-4 and 5-8, about equal counts, surfaces taken in turn.

Usage: bench/make_judge20_targets.py CURVEFOLD OUTDIR [--set default|random] [--per-band N]
       [--seed S]
Writes OUTDIR/<name>.obj and OUTDIR/manifest.tsv (name, surface, parameters, folds, band).
"""
import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile

SURFACES = ["square", "rectangle", "disk", "star", "cylinder", "half_cylinder", "cone",
            "swept_curve", "helix_tangent"]
# Defaults as `curvefold surfaces` lists them (resolution left alone).
DEFAULTS = {
    "square": {"size": 0.2},
    "rectangle": {"width": 0.297, "height": 0.21},
    "disk": {"radius": 0.1},
    "star": {"outer_radius": 0.1, "inner_radius": 0.045},
    "cylinder": {"radius": 0.045, "height": 0.21},
    "half_cylinder": {"radius": 0.06, "height": 0.21},
    "cone": {"base_radius": 0.08, "height": 0.12},
    "swept_curve": {"amplitude": 0.015, "wavelength": 0.1, "curve_width": 0.2, "length": 0.2},
    "helix_tangent": {"radius": 0.04, "pitch": 0.12, "turns": 0.75, "ruling_width": 0.08},
}
BANDS = [(1, 2), (3, 4), (5, 8)]


def run(args, check=True):
    r = subprocess.run(args, capture_output=True, text=True)
    if check and r.returncode != 0:
        raise RuntimeError(" ".join(args) + ": " + (r.stderr.strip() or r.stdout.strip()))
    return r


def read_vertices(obj):
    out = []
    with open(obj) as f:
        for line in f:
            if line.startswith("v "):
                out.append([float(x) for x in line.split()[1:4]])
    return out


def pick_fold(verts, rng):
    lo = [min(v[i] for v in verts) for i in range(3)]
    hi = [max(v[i] for v in verts) for i in range(3)]
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    diag = sum((b - a) ** 2 for a, b in zip(lo, hi)) ** 0.5
    dist = [sum((v[i] - centre[i]) ** 2 for i in range(3)) ** 0.5 for v in verts]
    far = max(dist)
    outer = [v for v, d in zip(verts, dist) if d >= 2.0 / 3.0 * far]
    grab = rng.choice(outer)
    while True:
        d = [rng.gauss(0, 1) for _ in range(3)]
        n = sum(x * x for x in d) ** 0.5
        if n > 1e-9:
            break
    length = rng.uniform(0.10, 0.35) * diag
    to = [grab[i] + length * d[i] / n for i in range(3)]
    return grab, to


def fmt(p):
    return ",".join("%.9g" % x for x in p)


def make_target(cf, surface, params, folds, rng, work):
    design = os.path.join(work, "d.curvefold.json")
    trial = os.path.join(work, "t.curvefold.json")
    obj = os.path.join(work, "d.obj")
    cmd = [cf, "new", surface, "-o", design]
    for k, v in params.items():
        cmd += ["--" + k, "%.6g" % v]
    run(cmd)
    for _ in range(folds):
        for _try in range(12):
            run([cf, "export", design, "--obj", obj])
            grab, to = pick_fold(read_vertices(obj), rng)
            r = run([cf, "fold", design, "--vertex-near", fmt(grab), "--to", fmt(to), "-o", trial],
                    check=False)
            if r.returncode != 0:
                continue
            if run([cf, "check", trial], check=False).returncode != 0:
                continue
            shutil.copyfile(trial, design)
            break
        else:
            return None
    run([cf, "export", design, "--obj", obj])
    with open(obj) as f:
        return [line for line in f if not line.startswith("vt ")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("curvefold")
    ap.add_argument("outdir")
    ap.add_argument("--set", choices=["default", "random"], default="default")
    ap.add_argument("--per-band", type=int, default=15)
    ap.add_argument("--seed", type=int, default=20)
    a = ap.parse_args()
    rng = random.Random(a.seed * 1000 + (a.set == "random"))
    os.makedirs(a.outdir, exist_ok=True)
    rows = []
    k = 0
    with tempfile.TemporaryDirectory() as work:
        for lo, hi in BANDS:
            for i in range(a.per_band):
                surface = SURFACES[k % len(SURFACES)]
                k += 1
                while True:
                    params = {}
                    if a.set == "random":
                        params = {p: v * rng.uniform(0.6, 1.6)
                                  for p, v in DEFAULTS[surface].items()}
                        if surface == "star":  # notches inside the points
                            params["inner_radius"] = min(params["inner_radius"],
                                                         0.8 * params["outer_radius"])
                    folds = rng.randint(lo, hi)
                    lines = make_target(a.curvefold, surface, params, folds, rng, work)
                    if lines is not None:
                        break
                name = "%s_%d-%d_%02d_%s" % (a.set, lo, hi, i, surface)
                with open(os.path.join(a.outdir, name + ".obj"), "w") as f:
                    f.writelines(lines)
                ps = " ".join("--%s %.6g" % kv for kv in params.items())
                rows.append("\t".join([name, surface, ps, str(folds), "%d-%d" % (lo, hi)]))
                print(rows[-1], flush=True)
    with open(os.path.join(a.outdir, "manifest.tsv"), "w") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    sys.exit(main())
