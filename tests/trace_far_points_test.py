#!/usr/bin/python3
"""bench/trace_far_points.py names where a sheet stands farthest from its target (issue 38, 2).

The target is a tube of radius 1 and height 2 about +y; the sheet is the same tube with one bump
pushed out by 0.3 about the height 1.5 and the angle 90 degrees (a corner left standing, as a
narrowed vase's neck corners are). The farthest sheet sample must be named there: height 1.5
(from the tube's lower end, not its upper), radius 1.3, 0.3 from the target, whose mean radius
there is 1; the band holding it must show the sheet's largest radius 1.3 against the target's 1.
Usage: trace_far_points_test.py --source DIR (the repository).
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile


def lathe(path, radius_at, height=2.0, rows=81, around=72):
    with open(path, "w") as out:
        for i in range(rows):
            h = height * i / (rows - 1)
            for j in range(around):
                a = 2 * math.pi * j / around
                r = radius_at(h, a)
                out.write(f"v {r * math.cos(a):.6f} {h:.6f} {r * math.sin(a):.6f}\n")
        for i in range(rows - 1):
            for j in range(around):
                p, q = i * around + j + 1, i * around + (j + 1) % around + 1
                out.write(f"f {p} {q} {q + around}\nf {p} {q + around} {p + around}\n")


def bump(h, a):
    # A smooth bump of height 0.3 about (h 1.5, angle 90 degrees), 0 past 0.25 and 25 degrees.
    d = math.hypot((h - 1.5) / 0.25, (a - math.pi / 2) / math.radians(25))
    return 1.0 + (0.3 * math.cos(0.5 * math.pi * d) ** 2 if d < 1 else 0.0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", required=True)
    args = ap.parse_args()
    tool = os.path.join(args.source, "bench", "trace_far_points.py")
    with tempfile.TemporaryDirectory() as tmp:
        sheet, target = os.path.join(tmp, "sheet.obj"), os.path.join(tmp, "target.obj")
        lathe(sheet, bump)
        lathe(target, lambda h, a: 1.0)
        out = subprocess.run([sys.executable, tool, sheet, target, "--samples", "20000", "--far", "1",
                              "--bands", "8"], capture_output=True, text=True, check=True).stdout
    failures = []
    lines = out.splitlines()
    far = lines[lines.index(next(l for l in lines if l.startswith("farthest sheet"))) + 1].split()
    height, radius, distance, there = float(far[0]), float(far[1]), float(far[3]), float(far[5])
    if abs(height - 1.5) > 0.06:
        failures.append(f"the farthest sheet sample at height {height:.4g}, expected 1.5")
    if abs(radius - 1.3) > 0.02 or abs(distance - 0.3) > 0.02:
        failures.append(f"the farthest sheet sample at radius {radius:.4g}, {distance:.4g} away; "
                        "expected 1.3, 0.3")
    if abs(there - 1.0) > 0.01:
        failures.append(f"the target's mean radius there {there:.4g}, expected 1")
    # The band of heights 1.5-1.75 (the seventh of eight): the sheet's largest radius 1.3.
    bands = [l.split() for l in lines[lines.index(next(l for l in lines if l.startswith("band"))) + 1:]]
    band = next((b for b in bands if abs(float(b[0]) - 1.625) < 1e-3), None)
    if band is None or abs(float(band[4]) - 1.3) > 0.02 or abs(float(band[1]) - 1.0) > 0.01:
        failures.append(f"the band about 1.625: {band}, expected the target's 1 and the sheet's largest 1.3")
    if not re.search(r"hausdorff (\S+)%", out):
        failures.append(f"no distance line: {out!r}")
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print(f"ok: the farthest sheet sample at height {height:.4g}, radius {radius:.4g}, "
              f"{distance:.4g} away")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
