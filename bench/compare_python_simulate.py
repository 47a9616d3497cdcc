#!/usr/bin/env python3
"""Python's simulate against the command line's, per option (issue 39, 5; pysim21).

For every crease pattern given: `CLI simulate P --percent 50 --settle OPTIONS --obj` against
`curvefold.simulate(P, percent=50, KEYWORDS)`, the vertices bit for bit (the OBJ's `v` lines are
shortest round-trip text), for --pin, --glue (the pattern's first vertex and the one farthest from
it), --stiffness origami-simulator, --motion, --size 150 and --paper 0.1 with a pin and glue; also
whether the printed report holds the returned largest strain and crossing verdict, and whether
the option moved the state at all. A run of the command line past 60 s is skipped.

    PYTHONPATH=build/python python3 bench/compare_python_simulate.py build/app/curvefold P...
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

import curvefold

CLI = sys.argv[1]
OBJ = os.path.join(tempfile.mkdtemp(), "cli.obj")


def obj(path):
    return np.array([[float(x) for x in l.split()[1:4]] for l in open(path).read().splitlines() if l.startswith('v ')])


tot = {}
for P in sys.argv[2:]:
    try:
        plain = curvefold.simulate(P, percent=50)
    except Exception as e:
        print(P, "plain fails:", e); continue
    dev = plain["development"]
    p0 = dev[0]; far = dev[np.argmax(np.linalg.norm(dev - p0, axis=1))]
    t = lambda p: f"{p[0]!r},{p[1]!r}"
    cases = {
        "pin": (["--pin", t(p0)], dict(pin=[tuple(p0)])),
        "glue": (["--glue", t(p0) + ":" + t(far)], dict(glue=[(p0, far)])),
        "stiffness": (["--stiffness", "origami-simulator"], dict(stiffness="origami-simulator")),
        "motion": (["--motion"], dict(motion=True)),
        "size": (["--size", "150"], dict(size=150)),
        "paper+pin+glue": (["--paper", "0.1", "--pin", t(far), "--glue", t(p0) + ":" + t(far)],
                           dict(paper=0.1, pin=[t(far)], glue=[t(p0) + ":" + t(far)])),
    }
    row = []
    for name, (options, keywords) in cases.items():
        try:
            run = subprocess.run([CLI, "simulate", P, "--percent", "50", "--settle", "--obj", OBJ, *options],
                                 capture_output=True, text=True, timeout=60)
        except subprocess.TimeoutExpired:
            row.append(f"{name}:CLI-over-60s(skipped)"); tot.setdefault(name, [0, 0, 0, 0])[3] += 1; continue
        try:
            r = curvefold.simulate(P, percent=50, **keywords)
        except ValueError as e:
            ok = run.returncode == 1 and run.stderr.splitlines()[-1].endswith(str(e))
            row.append(f"{name}:refused{'=' if ok else '!='}"); tot.setdefault(name, [0, 0, 0, 0])[0 if ok else 1] += 1
            continue
        if run.returncode != 0:
            row.append(f"{name}:CLI-failed"); tot.setdefault(name, [0, 0, 0, 0])[1] += 1; continue
        eq = np.array_equal(obj(OBJ), r["vertices"])
        moved = not np.array_equal(r["vertices"], plain["vertices"])
        rep = f"largest strain {r['largest_strain']:.2e}" in run.stdout and ("self-intersection: none" in run.stdout) == (r["crossing_pairs"] == 0)
        row.append(f"{name}:{'eq' if eq else 'NE'}{'' if moved else '(unmoved)'}{'' if rep else '(report!)'}")
        tot.setdefault(name, [0, 0, 0, 0])[0 if eq and rep else 1] += 1
        tot[name][2] += moved
    print(P.split('/')[-1], " ".join(row), flush=True)
print("per keyword [equal (or refused alike), not, moved, skipped]:", tot)
