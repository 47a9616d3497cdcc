#!/usr/bin/env python3
"""Issue 39's checks on bench/make_audit_patterns.py's files, as an independent judge runs them.

    PYTHONPATH=build/python python3 bench/audit_patterns.py build/app/curvefold PATTERN_DIR

good/: `simulate --percent 0:100:5` (dynamic), `--percent 100 --settle` and `--percent 25:100:4
--settle` (residual, energy never rising), `check` of the settled OBJ and FOLD, Python's
`curvefold.simulate` from the path and from the parsed dict (0% exactly the flat sheet); the
single creases' dihedral from the simulated triangles at 25/50/75/100% (within 0.5 degrees); the
Miura-ori's distance to its closed-form rigid motion at 25/50/75% (within 1% of the cell side).
bad/: one line on stderr, a non-zero exit, no output file. Prints one line per run and FAIL lines.
"""

import glob
import json
import math
import os
import re
import subprocess
import sys

import numpy as np

import curvefold


def run(cmd, timeout=300):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return 124, "", "timeout"


def dihedral(v, tris, a, b):
    """Fold angle (degrees, unsigned, 0 when flat) across edge a-b: 180 minus the angle between
    the two triangles' wings (each opposite corner's offset square to the edge)."""
    e = v[b] - v[a]
    e = e / np.linalg.norm(e)
    wings = []
    for t in tris:
        if a in t and b in t:
            o = v[[c for c in t if c not in (a, b)][0]] - v[a]
            w = o - (o @ e) * e
            wings.append(w / np.linalg.norm(w))
    if len(wings) != 2:
        return None
    return 180.0 - math.degrees(math.acos(max(-1.0, min(1.0, float(wings[0] @ wings[1])))))


def placed_distance(P, Q):
    """Largest |P - R Q - t| over the best rotation (reflections too) and translation."""
    pc, qc = P.mean(0), Q.mean(0)
    best = 1e300
    for flip in (1.0, -1.0):
        Qf = (Q - qc) * np.array([1.0, 1.0, flip])
        U, _, Vt = np.linalg.svd(Qf.T @ (P - pc))
        d = np.sign(np.linalg.det(Vt.T @ U.T))
        R = Vt.T @ np.diag([1.0, 1.0, d]) @ U.T
        best = min(best, float(np.max(np.linalg.norm((R @ Qf.T).T - (P - pc), axis=1))))
    return best


def miura_rigid(flat, w, h, d, H, cols, rows, shift=0):
    """The Miura-ori's rigid state at row height H, each flat point mapped affinely in its cell:
    node (i, j) at (i S, j L + V [i odd], H [j odd]), L^2 + H^2 = h^2, L V = h d, S^2 + V^2 =
    w^2 + d^2 (edge lengths and the cell diagonal kept)."""
    L = math.sqrt(h * h - H * H)
    V = h * d / L
    if V * V >= w * w + d * d:
        return None  # past the flat-folded end of the motion
    S = math.sqrt(w * w + d * d - V * V)

    def node(i, j):
        return np.array([i * S, j * L + (V if (i + shift) % 2 else 0.0), H if j % 2 else 0.0])

    out = []
    for x, y in flat:
        i = min(max(int(math.floor(x / w + 1e-9)), 0), cols - 1)
        u = x / w - i
        y0 = d * u if (i + shift) % 2 == 0 else d * (1 - u)
        j = min(max(int(math.floor((y - y0) / h + 1e-9)), 0), rows - 1)
        v = (y - y0) / h - j
        a, b, c = node(i, j), node(i + 1, j), node(i, j + 1)
        out.append(a + u * (b - a) + v * (c - a))
    return np.array(out)


def to_pattern_frame(dev, f):
    """The flat sheet (metres, as read) back in the pattern's own units and place: undo the
    reader's scale, y flip and the group's rotation by fitting the border's long edges."""
    # the reader's scale: the sheet's area against the pattern's (cols w x rows h)
    a = np.ptp(dev[:, 0]) * np.ptp(dev[:, 1])
    pts = dev - dev.mean(0)
    # principal directions of a parallelogram-bounded Miura sheet are not reliable: use the
    # straight column lines, whose direction is the one along which the points' projections
    # cluster; try angles and keep the one whose x projections fall on the fewest distinct values
    best = None
    for deg in np.arange(0.0, 180.0, 0.25):
        t = math.radians(deg)
        x = pts @ np.array([math.cos(t), math.sin(t)])
        k = len(np.unique(np.round(x / (np.ptp(x) + 1e-300) * 2000)))
        if best is None or k < best[0]:
            best = (k, t)
    t = best[1]
    R = np.array([[math.cos(t), math.sin(t)], [-math.sin(t), math.cos(t)]])
    q = pts @ R.T
    s = np.ptp(q[:, 0]) / (f["cols"] * f["w"])
    q = q / s
    q -= q.min(0)
    return q, s, a


def miura_check(path, f, fails):
    for pct in (25, 50, 75):
        s = curvefold.simulate(path, percent=pct, settle=True)
        best = (1e300, None)
        flat0, scale, _ = to_pattern_frame(s["development"], f)
        P = s["vertices"] / scale
        # the column lines are x = const; the sheet may be turned over (then the zigzag's offset
        # is on the even columns): try both
        for shift in (0, 1):
            for my in (False, True):
                flat = flat0.copy()
                if my:
                    flat[:, 1] = flat[:, 1].max() - flat[:, 1]
                def err(H):
                    Q = miura_rigid(flat, f["w"], f["h"], f["d"], H, f["cols"], f["rows"], shift)
                    return 1e300 if Q is None else placed_distance(P, Q)

                grid = np.linspace(0.0, 0.999 * f["h"], 200)
                errs = [err(H) for H in grid]
                k = int(np.argmin(errs))
                lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
                for _ in range(60):  # golden section on the bracket
                    m1, m2 = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
                    if err(m1) < err(m2):
                        hi = m2
                    else:
                        lo = m1
                H = 0.5 * (lo + hi)
                if err(H) < best[0]:
                    best = (err(H), H)
        side = min(f["w"], f["h"])
        frac = best[0] / side
        print(f"  miura {pct}%: {100 * frac:.3f}% of the cell side off the rigid motion (H {best[1]:.2f})")
        if frac > 0.01:
            fails.append(f"{os.path.basename(path)}: Miura {pct}%: {100 * frac:.3f}% of the cell side")


def parse_states(out):
    states = []
    for m in re.finditer(r"^(\d+(?:\.\d+)?)%: (.*)$", out, re.M):
        line = m.group(2)
        st = {"pct": float(m.group(1)), "line": line}
        r = re.search(r"residual ([0-9.e+-]+)", line)
        st["residual"] = float(r.group(1)) if r else None
        r = re.search(r"rose in (\d+)", line)
        st["rose"] = int(r.group(1)) if r else None
        st["settled"] = line.startswith("settled")
        r = re.search(r"largest strain ([0-9.e+-]+)", line)
        st["strain"] = float(r.group(1)) if r else None
        states.append(st)
    return states


def good(cf, path, facts, outdir, fails):
    name = os.path.basename(path)
    obj = os.path.join(outdir, name + ".obj")
    rc, out, err = run([cf, "simulate", path, "--percent", "0:100:5", "--obj", obj], 300)
    dyn = parse_states(out)
    if rc != 0 or not dyn:
        fails.append(f"{name}: dynamic run rc {rc}: {err.strip()[-200:]}")
    elif dyn[0]["strain"] != 0.0:
        fails.append(f"{name}: 0% strain {dyn[0]['strain']}")
    summary = [f"dyn max strain {max(s['strain'] for s in dyn):.2e}" if dyn else "dyn -"]
    for pcts in ("100", "25:100:4"):
        sobj = os.path.join(outdir, name + ".settled.obj")
        sfold = os.path.join(outdir, name + ".settled.fold")
        rc, out, err = run([cf, "simulate", path, "--percent", pcts, "--settle", "--obj", sobj, "--fold", sfold], 300)
        st = parse_states(out)
        if rc != 0 or not st:
            fails.append(f"{name}: settle {pcts} rc {rc}: {err.strip()[-200:]}")
            summary.append(f"settle {pcts}: rc {rc}")
            continue
        for s in st:
            if not s["settled"]:
                fails.append(f"{name}: {s['pct']}% (of {pcts}) NOT settled: {s['line'][:120]}")
            if s["rose"]:
                fails.append(f"{name}: {s['pct']}% (of {pcts}) energy rose in {s['rose']} iterations")
        summary.append(f"settle {pcts}: " + "/".join(
            (re.search(r"in (\d+)", s["line"]).group(1) if s["settled"] else "NOT") for s in st) +
            f" it, max residual {max(s['residual'] or 0 for s in st):.1e}, strain@100 {st[-1]['strain']:.2e}")
        for f in (sobj, sfold):
            crc, cout, cerr = run([cf, "check", "--allow-self-intersection", f])
            if crc != 0:
                fails.append(f"{name}: check {os.path.basename(f)} rc {crc}: {(cout + cerr).strip()[-200:]}")
    # Python, from the path and (FOLD) from the parsed dict
    flat = curvefold.simulate(path, percent=0)
    v, dev = flat["vertices"], flat["development"]
    if not (np.all(v[:, 2] == 0.0) and np.array_equal(v[:, :2], dev)):
        fails.append(f"{name}: python 0% is not the flat sheet exactly (max |z| {np.max(np.abs(v[:, 2]))}, "
                     f"max |xy - dev| {np.max(np.abs(v[:, :2] - dev))})")
    if path.endswith(".fold"):
        d = curvefold.simulate(json.load(open(path)), percent=60, settle=True)
        p = curvefold.simulate(path, percent=60, settle=True)
        if not np.array_equal(d["vertices"], p["vertices"]):
            fails.append(f"{name}: python dict and path differ at 60%")
    if name in facts["single"]:
        want = facts["single"][name]
        s = None
        for pct in (25, 50, 75, 100):
            s = curvefold.simulate(path, percent=pct, settle=True)
            tris = s["triangles"].tolist()
            for k, a in enumerate(s["assignment"]):
                if a in "MV":
                    e = s["edges"][k]
                    ang = dihedral(s["vertices"], tris, int(e[0]), int(e[1]))
                    if ang is None or abs(ang - want * pct / 100) > 0.5:
                        fails.append(f"{name}: {pct}%: crease at {ang} degrees, wants {want * pct / 100}")
        summary.append("single crease checked")
    if name in facts["miura"]:
        miura_check(path, facts["miura"][name], fails)
    print(f"{name}: " + "; ".join(summary))


def bad(cf, path, outdir, fails):
    name = os.path.basename(path)
    outs = [os.path.join(outdir, "bad." + e) for e in ("obj", "fold", "glb")]
    for o in outs:
        if os.path.exists(o):
            os.remove(o)
    rc, out, err = run([cf, "simulate", path, "--percent", "50", "--obj", outs[0], "--fold", outs[1],
                        "--gltf", outs[2]], 120)
    lines = [l for l in err.splitlines() if l.strip()]
    errs = [l for l in lines if "error" in l]
    written = [os.path.basename(o) for o in outs if os.path.exists(o)]
    verdict = "refused" if rc != 0 else "read"
    print(f"{name}: rc {rc} ({verdict}), {len(lines)} stderr lines, written {written or 'none'}: "
          f"{(errs or lines or [''])[-1][:160]}")
    if rc != 0 and (len(errs) != 1 or written):
        fails.append(f"{name}: refused but {len(errs)} error lines, files {written}")
    if rc >= 128 or rc == 124:
        fails.append(f"{name}: crashed or hung (rc {rc})")
    try:
        curvefold.simulate(path, percent=50)
        if rc != 0:
            fails.append(f"{name}: the CLI refuses it but Python reads it")
    except Exception as e:  # noqa: BLE001 (any exception type a stranger would see)
        if rc == 0:
            fails.append(f"{name}: the CLI reads it but Python raises {type(e).__name__}: {e}")


def main(cf, pdir):
    facts = json.load(open(os.path.join(pdir, "facts.json")))
    outdir = os.path.join(pdir, "out")
    os.makedirs(outdir, exist_ok=True)
    fails = []
    only = sys.argv[3:]
    for path in sorted(glob.glob(os.path.join(pdir, "good", "*"))):
        if not only or os.path.basename(path) in only:
            try:
                good(cf, path, facts, outdir, fails)
            except Exception as e:  # noqa: BLE001 (a judge notes whatever it raises, and goes on)
                fails.append(f"{os.path.basename(path)}: python raised {type(e).__name__}: {e}")
    for path in sorted(glob.glob(os.path.join(pdir, "bad", "*"))):
        if not only or os.path.basename(path) in only:
            bad(cf, path, outdir, fails)
    for f in fails:
        print("FAIL", f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
