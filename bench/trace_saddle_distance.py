#!/usr/bin/python3
"""Where a fitted sheet lies farthest from a saddle (issue 38, item 2; saddle26): the distance
picture in the target's own frame, as numbers. The target's frame: its centroid, its normal the
axis of least spread (PCA), its in-plane angle measured from the first principal axis. Target
samples are measured to the design (the target's side: what the sheet does not reach) and design
samples to the target (the sheet's side: what stands off), each exactly (judge_distance.py).

Prints, per side: the farthest 1% of samples' mean distance (% of the target's diagonal), and for
the target's side the share of that farthest 1% by radius (fifths of the farthest radius) and by
the sign of the height (above or below the mean plane: a rising or a falling lobe), and the five
farthest points as (r / r_max, angle degrees, h / r_max, distance %).

Usage: bench/trace_saddle_distance.py DESIGN.obj TARGET.obj [--samples N] [--seed S]
"""
import numpy as np

from judge_distance import distances, pair_parser, read_obj, sample


def frame(points):
    centre = points.mean(0)
    _, vectors = np.linalg.eigh(np.cov((points - centre).T))
    return centre, vectors[:, 2], vectors[:, 1], vectors[:, 0]  # first axis, second, normal


def main():
    args = pair_parser().parse_args()
    rng = np.random.default_rng(args.seed)
    va, fa = read_obj(args.a)
    vb, fb = read_obj(args.b)
    diag = np.linalg.norm(vb.max(0) - vb.min(0))
    on_target = sample(vb, fb, args.samples, rng)
    on_sheet = sample(va, fa, args.samples, rng)
    d_target = distances(on_target, va, fa) / diag * 100
    d_sheet = distances(on_sheet, vb, fb) / diag * 100
    centre, e1, e2, normal = frame(on_target)
    rel = on_target - centre
    x, y, h = rel @ e1, rel @ e2, rel @ normal
    r = np.hypot(x, y)
    rmax = r.max()
    angle = np.degrees(np.arctan2(y, x))
    far = np.argsort(d_target)[-max(1, len(d_target) // 100):]
    print(f"target side: farthest 1% mean {d_target[far].mean():.2f}%, max {d_target.max():.2f}%,"
          f" mean {d_target.mean():.2f}%")
    bins = np.minimum((r[far] / rmax * 5).astype(int), 4)
    print("  farthest 1% by radius fifth: " +
          " ".join(f"{k}:{(bins == k).mean():.2f}" for k in range(5)))
    print(f"  farthest 1% above the mean plane: {(h[far] > 0).mean():.2f}"
          f" (all samples above: {(h > 0).mean():.2f})")
    for i in np.argsort(d_target)[-5:][::-1]:
        print(f"  at r {r[i] / rmax:.2f} angle {angle[i]:.0f} h {h[i] / rmax:+.2f}: {d_target[i]:.2f}%")
    far_s = np.argsort(d_sheet)[-max(1, len(d_sheet) // 100):]
    print(f"sheet side: farthest 1% mean {d_sheet[far_s].mean():.2f}%, max {d_sheet.max():.2f}%,"
          f" mean {d_sheet.mean():.2f}%")
    rel_s = on_sheet - centre
    rs = np.hypot(rel_s @ e1, rel_s @ e2)
    print(f"  farthest 1% at r / r_max {np.median(rs[far_s]) / rmax:.2f} (median),"
          f" h / r_max {np.median(rel_s[far_s] @ normal) / rmax:+.2f}")


if __name__ == "__main__":
    main()
