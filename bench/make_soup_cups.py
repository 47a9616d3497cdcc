#!/usr/bin/python3
"""Steep cups written as triangle soup, for `curvefold fit` (issue 38, 2), plain Python.
Usage: bench/make_soup_cups.py OUTDIR [--seed N] (deterministic for a seed).

Unlike the other cup generators (shared vertices: profiles of revolution in rings or lattices,
marched solids, subdivided cages), every triangle here is written with three vertices of its own
(no vertex is shared: an OBJ from a CAD export or an STL converted as it is), and the cups are not
surfaces of revolution: the cross-section morphs along the height (a circle at the floor to an
oval at the mouth), the floor is domed or stands on a foot ring, and each ring of the wall is cut
at its own random count of points (so the triangles between rings are slivers and fans, not a
grid).
- soup_oval_mouth (metres): a flat floor 3 cm in radius, the mouth an oval 4.2 x 3.4 cm, 8 cm
  deep; tilted 25 degrees.
- soup_domed_tumbler_mm (mm): a tumbler 28 -> 32 mm in radius, 90 mm deep, its floor domed 6 mm
  into the cup at the centre (a bottle's punt); tilted 60 degrees.
- soup_footed_cup (metres): a cup 3.5 -> 4.5 cm in radius, 7 cm deep, whose wall goes on 8 mm
  past the floor as a foot ring (the floor inside it, a level annulus at the foot's rim missing:
  the foot is open); tilted 110 degrees (upside down and leaning).
"""
import math
import os
import random
import sys


def section(radius_x, radius_y, count, turn):
    """`count` points round an oval, at angles drawn unevenly (a scan's or export's spacing)."""
    return [(radius_x * math.cos(turn + 2.0 * math.pi * (i + 0.35 * math.sin(3.1 * i)) / count),
             radius_y * math.sin(turn + 2.0 * math.pi * (i + 0.35 * math.sin(3.1 * i)) / count))
            for i in range(count)]


def stitch(lower, upper):
    """Triangles between two closed rings of points of any counts (advancing along both by
    angle), as (a, b, c) point triples."""
    def angle(p):
        return math.atan2(p[1], p[0]) % (2.0 * math.pi)
    a = sorted(lower, key=angle)
    b = sorted(upper, key=angle)
    i = j = 0
    out = []
    while i < len(a) or j < len(b):
        ai, bj = a[i % len(a)], b[j % len(b)]
        na, nb = a[(i + 1) % len(a)], b[(j + 1) % len(b)]
        # Advance along the ring whose next point comes first by angle.
        ta = angle(na) + (2.0 * math.pi if i + 1 >= len(a) else 0.0)
        tb = angle(nb) + (2.0 * math.pi if j + 1 >= len(b) else 0.0)
        if j >= len(b) or (i < len(a) and ta <= tb):
            out.append((ai, na, bj))
            i += 1
        else:
            out.append((ai, nb, bj))
            j += 1
    return out


def cup(rng, floor_r, mouth_rx, mouth_ry, depth, dome, foot, rings):
    """Triangle soup of a cup whose floor lies at z = 0 and mouth at z = depth (3D triples)."""
    tris = []
    # The wall, ring by ring: radius and oval blend by height, each ring its own point count.
    levels = []
    for k in range(rings + 1):
        s = k / rings
        z = -foot + (depth + foot) * s
        h = max(0.0, z) / depth
        rx = floor_r + (mouth_rx - floor_r) * h
        ry = floor_r + (mouth_ry - floor_r) * h
        count = rng.randint(40, 64)
        levels.append([(x, y, z) for x, y in section(rx, ry, count, rng.uniform(0.0, 0.2))])
    for lower, upper in zip(levels, levels[1:]):
        z0, z1 = lower[0][2], upper[0][2]
        for p, q, r in stitch([(x, y) for x, y, _ in lower], [(x, y) for x, y, _ in upper]):
            tris.append(((p[0], p[1], z0), (q[0], q[1], z0 if q in [(x, y) for x, y, _ in lower]
                                                           else z1), (r[0], r[1], z1)))
    # The floor: rings from the heel in to the centre, domed by `dome` into the cup.
    heel = [(x, y) for x, y, z in levels[0]] if foot == 0.0 else None
    floor_rings = 7
    previous = heel if heel is not None else section(floor_r, floor_r, 56, 0.1)
    previous_z = 0.0
    for k in range(1, floor_rings + 1):
        f = 1.0 - k / floor_rings
        z = dome * (1.0 - f * f)
        if k == floor_rings:
            centre = (0.0, 0.0)
            for i in range(len(previous)):
                a, b = previous[i], previous[(i + 1) % len(previous)]
                tris.append(((a[0], a[1], previous_z), (centre[0], centre[1], z),
                             (b[0], b[1], previous_z)))
            break
        ring = section(floor_r * f, floor_r * f, max(8, int(56 * f) + rng.randint(-3, 3)),
                       rng.uniform(0.0, 0.3))
        for p, q, r in stitch(previous, ring):
            zq = previous_z if q in previous else z
            tris.append(((p[0], p[1], previous_z), (q[0], q[1], zq), (r[0], r[1], z)))
        previous, previous_z = ring, z
    return tris


def placed(tris, tilt_degrees, offset, scale):
    """Turned by the tilt about x, then moved."""
    c, s = math.cos(math.radians(tilt_degrees)), math.sin(math.radians(tilt_degrees))
    out = []
    for t in tris:
        out.append(tuple(((x * scale + offset[0]),
                          (c * y - s * z) * scale + offset[1],
                          (s * y + c * z) * scale + offset[2]) for x, y, z in t))
    return out


def write(path, comment, tris):
    """Every triangle with three vertices of its own; written atomically."""
    temporary = path + ".tmp"
    with open(temporary, "w") as f:
        f.write("# %s (triangle soup: no vertex shared)\n" % comment)
        for t in tris:
            for x, y, z in t:
                f.write("v %.8g %.8g %.8g\n" % (x, y, z))
        for i in range(len(tris)):
            f.write("f %d %d %d\n" % (3 * i + 1, 3 * i + 2, 3 * i + 3))
    os.replace(temporary, path)


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--seed")]
    seed = 25
    for i, a in enumerate(argv):
        if a == "--seed":
            if i + 1 >= len(argv):
                sys.exit("make_soup_cups.py: --seed needs a number")
            seed = int(argv[i + 1])
            args = [x for x in args if x != argv[i + 1]]
    if len(args) != 1:
        sys.exit("usage: bench/make_soup_cups.py OUTDIR [--seed N]")
    out = args[0]
    os.makedirs(out, exist_ok=True)
    rng = random.Random(seed)
    write(os.path.join(out, "soup_oval_mouth.obj"), "oval mouth, flat floor, metres",
          placed(cup(rng, 0.03, 0.042, 0.034, 0.08, 0.0, 0.0, 14), 25.0, (0.01, 0.0, -0.02), 1.0))
    write(os.path.join(out, "soup_domed_tumbler_mm.obj"), "domed floor, millimetres",
          placed(cup(rng, 28.0, 32.0, 32.0, 90.0, 6.0, 0.0, 16), 60.0, (0.0, 0.0, 0.0), 1.0))
    write(os.path.join(out, "soup_footed_cup.obj"), "foot ring, metres",
          placed(cup(rng, 0.035, 0.045, 0.045, 0.07, 0.0, 0.008, 14), 110.0, (0.0, 0.02, 0.0),
                 1.0))


if __name__ == "__main__":
    main(sys.argv)
