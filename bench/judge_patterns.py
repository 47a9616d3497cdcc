#!/usr/bin/env python3
"""Runs issue 39's checks on the patterns of bench/make_judge_patterns.py, as a stranger would.

    PYTHONPATH=build/python python3 bench/judge_patterns.py build/app/curvefold PATTERN_DIR

For every pattern: `simulate --percent 0:100:21` (timed), `simulate --percent 100 --settle`,
`check` of the settled OBJ, and Python's `curvefold.simulate`; then the issue's numeric checks
where a pattern allows them: 0% flat exactly, a single straight crease at P% of its angle (from
the simulated triangles, not from the simulator's own error report), the Miura-ori within 1% of
its cell side of the closed-form rigid motion (best rigid placement) at 25/50/75%. Prints a
Markdown table and a line per failed check.
"""

import glob
import json
import math
import os
import re
import subprocess
import sys
import time

import numpy as np

import curvefold


def run(cmd, timeout=300):
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr, time.monotonic() - t0
    except subprocess.TimeoutExpired:
        return 124, "", "timeout", time.monotonic() - t0


def dihedral(verts, tris, a, b):
    """Unsigned fold angle (degrees) across edge a-b of a triangle mesh."""
    faces = [t for t in tris if a in t and b in t]
    if len(faces) != 2:
        return None
    n = []
    for t in faces:
        p = verts[list(t)]
        v = np.cross(p[1] - p[0], p[2] - p[0])
        n.append(v / np.linalg.norm(v))
    return math.degrees(math.acos(max(-1.0, min(1.0, float(np.dot(n[0], n[1]))))))


def kabsch_max(P, Q):
    """Largest distance between P and Q after the best rigid placement of Q onto P."""
    pc, qc = P.mean(0), Q.mean(0)
    H = (Q - qc).T @ (P - pc)
    U, S, Vt = np.linalg.svd(H)
    d = np.sign(np.linalg.det(Vt.T @ U.T))
    D = np.diag([1, 1, d])
    R = Vt.T @ D @ U.T
    Qr = (R @ (Q - qc).T).T + pc
    return float(np.max(np.linalg.norm(Qr - P, axis=1)))


def miura_closed_form(dev, w, h, d, H, offset=(0.0, 0.0)):
    """Each flat point's place in the rigid state at height H: the parallelogram cell it lies in,
    mapped affinely (each cell stays a plane parallelogram)."""
    L = math.sqrt(h * h - H * H)
    V = h * d / L
    S = math.sqrt(w * w + d * d - V * V)

    def state(i, j):
        return np.array([i * S, j * L + (V if i % 2 else 0.0), H if j % 2 else 0.0])

    out = []
    for x, y in dev:
        x -= offset[0]
        y -= offset[1]
        i = min(max(int(math.floor(x / w + 1e-9)), 0), 5)
        u = x / w - i
        y0 = (d * u) if i % 2 == 0 else d * (1 - u)  # zigzag row offset at this x
        j = min(max(int(math.floor((y - y0) / h + 1e-9)), 0), 3)
        v = (y - y0) / h - j
        p00, p10, p01 = state(i, j), state(i + 1, j), state(i, j + 1)
        out.append(p00 + u * (p10 - p00) + v * (p01 - p00))
    return np.array(out)


def miura_check(path, params):
    """Largest distance (fraction of cell side) to the nearest rigid state, at 25/50/75%."""
    res = {}
    for pct in (25, 50, 75):
        s = curvefold.simulate(path, percent=pct, settle=True)
        dev = s["development"].copy()
        # the sheet's size as the reader states it: back to the pattern's own units
        k = (dev[:, 0].max() - dev[:, 0].min()) / (6 * params["w"])
        dev = (dev - dev.min(0)) / k
        P = s["vertices"] / k
        best = (1e9, None)
        # an SVG's y axis points down: the reader may have turned the sheet over
        flipped = dev.copy()
        flipped[:, 1] = flipped[:, 1].max() - flipped[:, 1]
        for H in np.linspace(0.0, 0.89 * params["h"], 200):
            for D in (dev, flipped):
                Q = miura_closed_form(D, params["w"], params["h"], params["d"], H)
                for Qm in (Q, Q * np.array([1.0, 1.0, -1.0])):
                    e = kabsch_max(P, Qm)
                    if e < best[0]:
                        best = (e, H)
        side = min(params["w"], params["h"])
        res[pct] = (best[0] / side, best[1])
    return res


def main(cf, pdir):
    motion = json.load(open(os.path.join(pdir, "miura_motion.json")))
    rows, fails = [], []
    outdir = os.path.join(pdir, "out")
    os.makedirs(outdir, exist_ok=True)
    for path in sorted(glob.glob(os.path.join(pdir, "*.fold")) + glob.glob(os.path.join(pdir, "*.svg"))):
        name = os.path.basename(path)
        obj = os.path.join(outdir, name + ".obj")
        rc, out, err, t = run([cf, "simulate", path, "--percent", "0:100:21", "--obj", obj])
        if rc != 0:
            line = (err.strip().splitlines() or ["(no message)"])[-1]
            rows.append((name, "no: " + line, "", "", "", f"{t:.2f}"))
            continue
        strains = [float(m) for m in re.findall(r"largest strain ([0-9.e+-]+)", out)]
        errs = [float(m) for m in re.findall(r"largest crease angle error ([0-9.]+)", out)]
        first = re.search(r"^0%: .*largest strain ([0-9.e+-]+)", out, re.M)
        if first and float(first.group(1)) != 0.0:
            fails.append(f"{name}: 0% not flat (strain {first.group(1)})")
        sobj = os.path.join(outdir, name + ".settled.obj")
        src, sout, serr, st = run([cf, "simulate", path, "--percent", "100", "--settle", "--obj", sobj])
        settled = "no"
        if src == 0:
            m = re.search(r"residual ([0-9.e+-]+)", sout)
            settled = "yes" if "not converged" not in sout else "not converged"
            if m:
                settled += f" ({m.group(1)})"
            crc, cout, cerr, _ = run([cf, "check", sobj])
            if crc != 0:
                settled += "; check: " + ((cout + cerr).strip().splitlines() or [""])[-1]
        else:
            settled = "no: " + ((serr.strip().splitlines()) or [""])[-1]
        try:
            p = curvefold.simulate(path, percent=50)
            pyok = "ok" if p["converged"] else "not converged"
            if np.max(np.abs(curvefold.simulate(path, percent=0)["vertices"][:, 2])) != 0.0:
                fails.append(f"{name}: python 0% has z != 0")
        except Exception as e:  # noqa: BLE001 (a stranger reports whatever it raises)
            pyok = f"{type(e).__name__}: {e}"
        rows.append((name, "yes", f"{max(strains):.2e}" if strains else "?",
                     f"{errs[-1]:.2f}" if errs else "?", settled + "; py " + pyok, f"{t:.2f}"))
        if "single" in name:
            for pct in (25, 50, 75, 100):
                s = curvefold.simulate(path, percent=pct, settle=True)
                e = s["edges"]
                crease = [k for k, a in enumerate(s["assignment"]) if a in "MV"]
                for k in crease:
                    ang = dihedral(s["vertices"], s["triangles"].tolist(), int(e[k][0]), int(e[k][1]))
                    target = {"fold": 90.0 if "quads" in name else 120.0,
                              "svg": 90.0}[name.split("_")[0]]
                    want = target * pct / 100
                    if ang is None or abs(ang - want) > 0.5:
                        fails.append(f"{name}: {pct}%: crease at {ang} degrees, wants {want}")
        if name in motion:
            r = miura_check(path, motion[name])
            for pct, (e, H) in r.items():
                msg = f"{name}: Miura {pct}%: {100 * e:.3f}% of the cell side off the rigid motion (H {H:.3f})"
                print(msg)
                if e > 0.01:
                    fails.append(msg)
    print("| pattern | loads? | max strain (0-100%) | crease error at 100% (deg) | settles at 100%? | time 21 states (s) |")
    print("| --- | --- | --- | --- | --- | --- |")
    for r in rows:
        print("| " + " | ".join(r) + " |")
    for f in fails:
        print("FAIL", f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
