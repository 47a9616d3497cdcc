#!/usr/bin/python3
"""Bowls unlike the other generators' for `fit --from disk` (issue 38, 2), as OBJ.

Unlike bench/make_bowl_targets.py (hexagonal disks, closed-form profiles), make_smooth_targets.py
(numpy grids) and make_revolution_targets.py (spline profiles): Python's standard library only,
each mesh a polar grid whose rings are spaced by arc length along the profile (not by radius), the
profile a piecewise-linear table interpolated by a cosine ease (not a formula), and one shape not
of revolution. Shapes: a rice bowl on a flat foot ring (a raised step under a flat bottom), a
cereal bowl with a rolled rim turning down outside, an elliptic bowl (1.4 : 1 across: no axis of
revolution), a tilted salad bowl scanned with noise and holes, a steep tumbler-like cup.
Usage: bench/make_footed_bowls.py OUTDIR
"""
import math
import os
import random
import sys

rand = random.Random(38_2_3)


def eased(table):
    """A profile (r, z) from a table of points, eased between them, with its arc length."""
    def at(u):
        u = min(max(u, 0.0), 1.0) * (len(table) - 1)
        i = min(int(u), len(table) - 2)
        f = u - i
        f = 0.5 - 0.5 * math.cos(math.pi * f)
        (r0, z0), (r1, z1) = table[i], table[i + 1]
        return r0 + f * (r1 - r0), z0 + f * (z1 - z0)
    return at


def by_arc_length(profile, rings):
    """Parameters u of `rings` + 1 points evenly spaced along the profile's arc."""
    fine = [profile(i / 2000) for i in range(2001)]
    arcs = [0.0]
    for a, b in zip(fine, fine[1:]):
        arcs.append(arcs[-1] + math.dist(a, b))
    out, j = [], 0
    for k in range(rings + 1):
        want = arcs[-1] * k / rings
        while j < 2000 and arcs[j + 1] < want:
            j += 1
        out.append(j / 2000)
    return out


def polar(profile, rings, around, squash=1.0):
    """A polar grid about z: the centre, then `rings` rings of `around` vertices (x scaled)."""
    v = [(0.0, 0.0, profile(0.0)[1])]
    for k, u in enumerate(by_arc_length(profile, rings)[1:]):
        r, z = profile(u)
        for i in range(around):
            a = 2 * math.pi * (i + 0.5 * (k % 2)) / around  # rings staggered by half a step
            v.append((squash * r * math.cos(a), r * math.sin(a), z))
    tr = []
    for i in range(around):
        tr.append((0, 1 + i, 1 + (i + 1) % around))
    for j in range(rings - 1):
        for i in range(around):
            a, b = 1 + j * around + i, 1 + j * around + (i + 1) % around
            c, d = a + around, b + around
            tr += [(a, c, d), (a, d, b)]
    return v, tr


def rotate(p, axis, degrees):
    n = math.sqrt(sum(c * c for c in axis))
    k = [c / n for c in axis]
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    dot = sum(k[i] * p[i] for i in range(3))
    cross = (k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0])
    return tuple(p[i] * c + cross[i] * s + k[i] * dot * (1 - c) for i in range(3))


def scanned(v, tr, noise, holes):
    """Noise along each vertex's position and `holes` round holes cut out."""
    size = max(max(p[i] for p in v) - min(p[i] for p in v) for i in range(3))
    v = [tuple(c + rand.gauss(0.0, noise * size) for c in p) for p in v]
    for _ in range(holes):
        centre = v[rand.randrange(len(v))]
        radius = rand.uniform(0.05, 0.09) * size
        tr = [t for t in tr if all(math.dist(v[i], centre) > radius for i in t)]
    return v, tr


def write(path, comment, v, tr):
    used = sorted({i for t in tr for i in t})
    index = {old: new + 1 for new, old in enumerate(used)}
    with open(path + ".tmp", "w") as f:
        f.write(f"# {comment} (bench/make_footed_bowls.py)\n")
        for i in used:
            f.write("v %.7f %.7f %.7f\n" % v[i])
        for t in tr:
            f.write("f %d %d %d\n" % tuple(index[i] for i in t))
    os.replace(path + ".tmp", path)
    print("wrote", path, len(used), "vertices", len(tr), "triangles")


def main(out):
    os.makedirs(out, exist_ok=True)
    # a rice bowl 12 cm on a foot ring: flat bottom, the foot's 6 mm step, a round wall
    rice = eased([(0.0, 0.0), (0.02, 0.0), (0.022, -0.006), (0.03, -0.004), (0.045, 0.012),
                  (0.055, 0.032), (0.06, 0.05)])
    write(os.path.join(out, "rice_bowl_foot.obj"), "a rice bowl on a foot ring, 12 cm",
          *polar(rice, 22, 40))
    # a cereal bowl 16 cm whose rim rolls over and down outside
    cereal = eased([(0.0, 0.0), (0.03, 0.004), (0.055, 0.02), (0.07, 0.042), (0.078, 0.052),
                    (0.082, 0.05)])
    write(os.path.join(out, "rolled_rim_bowl.obj"), "a bowl with a rolled rim, 16 cm",
          *polar(cereal, 20, 48))
    # an elliptic bowl 21 x 15 cm, 5 cm deep: no axis of revolution
    elliptic = eased([(0.0, 0.0), (0.035, 0.006), (0.06, 0.025), (0.075, 0.05)])
    write(os.path.join(out, "elliptic_bowl.obj"), "an elliptic bowl 21 x 15 cm", *polar(
        elliptic, 18, 48, squash=1.4))
    # a salad bowl 26 cm tilted 25 degrees about (1, -2, 0), noise 0.25% of its size, 4 holes
    salad = eased([(0.0, 0.0), (0.05, 0.008), (0.1, 0.045), (0.13, 0.085)])
    v, tr = polar(salad, 24, 56)
    v = [tuple(c + s for c, s in zip(rotate(p, (1, -2, 0), 25), (-0.3, 0.05, 0.4))) for p in v]
    write(os.path.join(out, "salad_scan.obj"), "a tilted salad bowl 26 cm, scanned: noise, holes",
          *scanned(v, tr, 0.0025, 4))
    # a steep cup 8 cm across, 7 cm deep, slightly flared
    cup = eased([(0.0, 0.0), (0.025, 0.002), (0.033, 0.02), (0.036, 0.045), (0.04, 0.07)])
    write(os.path.join(out, "steep_tumbler.obj"), "a steep cup 8 cm, 7 cm deep",
          *polar(cup, 20, 40))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: bench/make_footed_bowls.py OUTDIR")
    main(sys.argv[1])
