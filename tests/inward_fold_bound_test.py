#!/usr/bin/python3
"""bench/inward_fold_bound.py's bound on two shapes whose answer is known (issue 38, 2).

A straight tube is its own concave envelope: bound about 0. An hourglass of two cones (neck r_n
at half the height H, sides of slope s, ends of radius r_n + s H / 2) keeps a concave envelope
off its neck: the sheet must reach within d of both ends, so at the neck's height it stands at
least at the ends' radius less d, which lies (s H / 2 - d) / sqrt(1 + s^2) from the cones; the
bound is where that equals d: d = (s H / 2) / (1 + sqrt(1 + s^2)). With one free break (--break),
the hourglass is two cones, each its own envelope: about 0, the break at its neck. Usage: inward_fold_bound_test.py
--source DIR (the repository).
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile


def lathe(path, radius_at, height, rows=41, around=24):
    with open(path, "w") as out:
        for i in range(rows):
            h = height * i / (rows - 1)
            for j in range(around):
                a = 2 * math.pi * j / around
                out.write(f"v {radius_at(h) * math.cos(a):.6f} {h:.6f} {radius_at(h) * math.sin(a):.6f}\n")
        for i in range(rows - 1):
            for j in range(around):
                p, q = i * around + j + 1, i * around + (j + 1) % around + 1
                out.write(f"f {p} {q} {q + around}\nf {p} {q + around} {p + around}\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", required=True)
    args = ap.parse_args()
    tool = os.path.join(args.source, "bench", "inward_fold_bound.py")
    height, neck, slope = 2.0, 0.5, 1.0
    with tempfile.TemporaryDirectory() as tmp:
        tube, glass = os.path.join(tmp, "tube.obj"), os.path.join(tmp, "hourglass.obj")
        lathe(tube, lambda h: 1.0, height)
        lathe(glass, lambda h: neck + slope * abs(h - height / 2), height)
        out = subprocess.run([sys.executable, tool, tube, glass], capture_output=True, text=True,
                             check=True).stdout
        split = subprocess.run([sys.executable, tool, glass, "--break"], capture_output=True,
                               text=True, check=True).stdout
    found = [float(x) for x in re.findall(r"stays at least (\S+) ", out)]
    broken = [float(v) for pair in re.findall(r"with one free break \(at height (\S+), radius \S+\): (\S+) ",
                                           split) for v in pair]
    expected = (slope * height / 2) / (1 + math.sqrt(1 + slope ** 2))
    failures = []
    if len(found) != 2:
        failures.append(f"expected two bounds, got: {out!r}")
    else:
        if found[0] > 0.02:
            failures.append(f"a straight tube's bound {found[0]:.4g}, expected about 0")
        # The profile is binned (the ends' points half a bin inside), so a little under.
        if not 0.88 * expected <= found[1] <= 1.02 * expected:
            failures.append(f"the hourglass's bound {found[1]:.4g}, expected {expected:.4g} (0.88-1.02 of it)")
    # With one free break the hourglass is two cones, each its own concave envelope: about 0,
    # the break at the neck (half the height, within a bin).
    if len(broken) != 2:
        failures.append(f"expected one bound with a break, got: {split!r}")
    elif broken[1] > 0.05 or abs(broken[0] - height / 2) > 0.1:
        failures.append(f"the hourglass with a free break: {broken[1]:.4g} at height {broken[0]:.4g}, "
                        f"expected about 0 at {height / 2}")
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print(f"ok: tube {found[0]:.4g}, hourglass {found[1]:.4g} (expected {expected:.4g})")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
