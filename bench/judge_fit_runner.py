#!/usr/bin/env python3
"""Runs issue 38's goal on a folder of reachable targets, as the judge measures it (judge17):
`curvefold fit TARGET --from SURFACE --folds 8 --time 60` (the defaults and `--symmetry` added
for a symmetric target), at most two fits at a time, then the fitted design exported as OBJ and
measured apart from the project (bench/judge_distance.py, 40,000 area-uniform samples);
with `--evaluations N` instead of `--time` for a clock-free run; each fit's user CPU seconds
recorded (under load, the judge's 60 s on 2 free cores is about 120 CPU seconds); results
bucketed by fold count against the goal (1-2 folds within 1% of the diagonal, 3-4
within 1%, 5-8 within 3%; Hausdorff).

    /usr/bin/python3 bench/judge_fit_runner.py DIR [--curvefold BIN] [--label L] [--time 60]
        [--evaluations N] [--jobs 2] [--only NAME,NAME] [--literal]

`--literal` runs the issue's command word for word (no `--symmetry`, no parameters: the judge
does not say a target is symmetric). Reads DIR/manifest.jsonl (as bench/make_area_normal_targets.py and reach_targets.py write it);
writes DIR/fit-L/*.curvefold.json, *.obj and DIR/results-L.jsonl (one line per target: the
Hausdorff and Chamfer in % of the target's diagonal, the seconds, the fit's own closing lines).
"""

import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
GOAL = {"1-2": 1.0, "3-4": 1.0, "5-8": 3.0}


def bucket_of(folds):
    return "1-2" if folds <= 2 else "3-4" if folds <= 4 else "5-8"


def run_one(args, entry):
    target = os.path.join(args.dir, entry["name"] + ".obj")
    out = os.path.join(args.dir, "fit-" + args.label)
    design = os.path.join(out, entry["name"] + ".curvefold.json")
    fitted = os.path.join(out, entry["name"] + ".obj")
    cmd = ["/usr/bin/time", "-f", "cpu %U", args.curvefold, "fit", target, "--from", entry["surface"], "--folds", "8", "-o", design]
    cmd += ["--evaluations", str(args.evaluations)] if args.evaluations else ["--time", str(args.time)]
    for name, value in ({} if args.literal else entry.get("parameters") or {}).items():
        cmd += ["--" + name, str(value)]
    if entry.get("symmetry") and not args.literal:
        cmd += ["--symmetry", entry["symmetry"]]
    started = time.monotonic()
    run = subprocess.run(cmd, capture_output=True, text=True)
    seconds = time.monotonic() - started
    result = {"name": entry["name"], "surface": entry["surface"], "folds": entry["folds"],
              "symmetry": entry.get("symmetry"), "seconds": round(seconds, 1),
              "tail": run.stdout.strip().splitlines()[-4:],
              "unfolded": "the target unfolded" in run.stdout}
    cpu = [l for l in run.stderr.splitlines() if l.startswith("cpu ")]
    if cpu:
        result["cpu_seconds"] = float(cpu[-1].split()[1])
    if run.returncode != 0:
        result["error"] = [l for l in (run.stderr + run.stdout).strip().splitlines()
                           if not l.startswith("cpu ")][-1:]
        return result
    subprocess.run([args.curvefold, "export", design, "--obj", fitted], check=True,
                   capture_output=True)
    measured = subprocess.run([sys.executable, os.path.join(HERE, "judge_distance.py"), fitted,
                               target], capture_output=True, text=True, check=True)
    h, c, diag, hp, cp = (float(x) for x in measured.stdout.split())
    result.update({"hausdorff_percent": round(hp, 3), "chamfer_percent": round(cp, 3)})
    return result


def table(entries, results):
    rows = {}
    for e in entries:
        r = results.get(e["name"])
        if r is None:
            continue
        b = bucket_of(e["folds"])
        ok = "hausdorff_percent" in r and r["hausdorff_percent"] <= GOAL[b]
        n, k = rows.get(b, (0, 0))
        rows[b] = (n + 1, k + ok)
    for b in ("1-2", "3-4", "5-8"):
        if b in rows:
            n, k = rows[b]
            print(f"{b} folds: {k}/{n} within {GOAL[b]:g}% ({100.0 * k / n:.0f}%)")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("dir")
    p.add_argument("--curvefold", default="build/app/curvefold")
    p.add_argument("--label", default="run")
    p.add_argument("--time", type=float, default=60.0)
    p.add_argument("--evaluations", type=int, default=0)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--only", default="")
    p.add_argument("--literal", action="store_true",
                   help="the issue's command word for word: no --symmetry, no parameters")
    args = p.parse_args()
    os.makedirs(os.path.join(args.dir, "fit-" + args.label), exist_ok=True)
    entries = [json.loads(l) for l in open(os.path.join(args.dir, "manifest.jsonl"))]
    if args.only:
        entries = [e for e in entries if e["name"] in args.only.split(",")]
    path = os.path.join(args.dir, f"results-{args.label}.jsonl")
    results = {}
    if os.path.exists(path):
        for l in open(path):
            r = json.loads(l)
            results[r["name"]] = r
    todo = [e for e in entries if e["name"] not in results]
    with open(path, "a") as log, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for r in pool.map(lambda e: run_one(args, e), todo):
            results[r["name"]] = r
            log.write(json.dumps(r) + "\n")
            log.flush()
            print(r["name"], r.get("hausdorff_percent", r.get("error")), r["seconds"],
                  r.get("cpu_seconds"), flush=True)
    table(entries, results)


if __name__ == "__main__":
    main()
