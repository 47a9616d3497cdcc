#!/usr/bin/python3
"""Vases for `fit` (issue 38, 2), made apart from curvefold and unlike the other generators
(scripts/make-example-targets.sh: awk grids; make_smooth_targets.py: numpy grids;
make_revolution_targets.py: Catmull-Rom rings; make_vase_targets.awk: Bezier rings;
make_gourd_vases.py: elliptic rings and fans; make_spiral_vases.py: one helix): the Python
standard library only, the surface meshed by conforming longest-edge bisection (Rivara) from a
coarse mesh of the (angle, height) domain, each triangle split until its longest edge in space
is under a size that varies over the surface and at random, so the triangles are uneven in size
and shape and no ring of edges follows the axis; the cross-section fluted (the radius varies
with the angle: the target is only nearly of revolution), profiles as piecewise cubic Hermite
curves through (height, radius, slope) keys, axes tilted off every coordinate axis.

Usage: bench/make_fluted_vases.py OUTDIR
Writes fluted_vase_tilted.obj (8 flutes of 5%: a foot of 4.5 cm, a belly of 7 cm, a neck of
3.2 cm and a lip of 4 cm; 25 cm tall, axis tilted 23 degrees off y), and bottle_floor_x.obj (a
bottle lying along x, 24 cm long: a body of 4.5 cm with a flat floor closing its end (a hole of 0.7 cm radius in its middle), a
shoulder into a neck of 1.6 cm; 6 flutes of 3%; two holes).
"""
import math
import os
import random
import sys


def hermite(keys, t):
    """The profile (h, r) at parameter t in [0, 1]: keys are (t, h, r, dr/dt) at increasing t;
    h is linear between keys, r a cubic Hermite curve."""
    for (t0, h0, r0, m0), (t1, h1, r1, m1) in zip(keys, keys[1:]):
        if t <= t1 or (t1, h1, r1, m1) == keys[-1]:
            d = t1 - t0
            s = min(1.0, max(0.0, (t - t0) / d))
            h00, h10 = 2 * s ** 3 - 3 * s ** 2 + 1, s ** 3 - 2 * s ** 2 + s
            h01, h11 = -2 * s ** 3 + 3 * s ** 2, s ** 3 - s ** 2
            return h0 + s * (h1 - h0), h00 * r0 + h10 * d * m0 + h01 * r1 + h11 * d * m1
    raise ValueError(t)


VASE_KEYS = [(0.0, 0.0, 0.045, 0.05), (0.35, 0.0875, 0.07, 0.0), (0.8, 0.2, 0.032, 0.0),
             (1.0, 0.25, 0.04, 0.08)]
BOTTLE_KEYS = [(0.0, 0.0, 0.045, 0.0), (0.55, 0.132, 0.045, 0.0), (0.75, 0.18, 0.018, -0.05),
               (1.0, 0.24, 0.016, 0.02)]


def frame(axis):
    n = math.sqrt(sum(c * c for c in axis))
    a = [c / n for c in axis]
    helper = (1.0, 0.0, 0.0) if abs(a[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = [helper[1] * a[2] - helper[2] * a[1], helper[2] * a[0] - helper[0] * a[2],
         helper[0] * a[1] - helper[1] * a[0]]
    n = math.sqrt(sum(c * c for c in u))
    u = [c / n for c in u]
    v = [a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2], a[0] * u[1] - a[1] * u[0]]
    return u, v, a


def bisect_mesh(domain, faces, embed, size, rnd):
    """Conforming longest-edge bisection: `domain` holds (angle, t) points, `embed` maps one to
    space, `size(p)` is the longest edge allowed near p (space). A triangle whose longest edge (in
    space) is too long is split at its midpoint together with the triangle across that edge,
    which is first split along its own longest edge until that edge is the shared one."""
    points = [embed(p) for p in domain]
    midpoint = {}

    def length(i, j):
        return math.dist(points[i], points[j])

    def longest(f):
        edges = [(f[0], f[1]), (f[1], f[2]), (f[2], f[0])]
        return max(edges, key=lambda e: (length(*e), min(e), max(e)))

    def middle(i, j):
        key = (min(i, j), max(i, j))
        if key not in midpoint:
            a, b = domain[i], domain[j]
            # Angles wrap: the midpoint of 5 pi / 3 and 0 is 11 pi / 6.
            a0, b0 = a[0], b[0]
            if abs(a0 - b0) > math.pi:
                a0, b0 = (a0 + 2 * math.pi, b0) if a0 < b0 else (a0, b0 + 2 * math.pi)
            domain.append((((a0 + b0) / 2) % (2 * math.pi), (a[1] + b[1]) / 2))
            points.append(embed(domain[-1]))
            midpoint[key] = len(domain) - 1
        return midpoint[key]

    alive = {k: tuple(f) for k, f in enumerate(faces)}
    by_edge = {}
    next_id = len(faces)

    def index(k, f):
        for e in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            by_edge.setdefault((min(e), max(e)), set()).add(k)

    def unindex(k, f):
        for e in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            by_edge[(min(e), max(e))].discard(k)

    for k, f in alive.items():
        index(k, f)

    def split(k):
        nonlocal next_id
        f = alive[k]
        i, j = longest(f)
        key = (min(i, j), max(i, j))
        others = [o for o in by_edge[key] if o != k]
        for o in others:  # the neighbour first, until it shares this longest edge
            while True:
                g = alive[o]
                gi, gj = longest(g)
                if (min(gi, gj), max(gi, gj)) == key:
                    break
                o = split(o)
                others = [x for x in by_edge[key] if x != k]
                o = others[0]
        m = middle(i, j)
        result = None
        for o in list(by_edge[key]):
            g = alive.pop(o)
            unindex(o, g)
            a = g.index(i)
            b = g.index(j)
            # Keep the orientation: replace j by m in one half, i by m in the other.
            h1 = list(g)
            h1[b] = m
            h2 = list(g)
            h2[a] = m
            for h in (h1, h2):
                alive[next_id] = tuple(h)
                index(next_id, alive[next_id])
                if o == k and result is None:
                    result = next_id
                next_id += 1
        return result

    changed = True
    while changed:
        changed = False
        for k in list(alive):
            if k not in alive:
                continue
            f = alive[k]
            i, j = longest(f)
            centre = [sum(points[v][c] for v in f) / 3 for c in range(3)]
            if length(i, j) > size(centre) * (0.75 + 0.5 * rnd.random()):
                split(k)
                changed = True
    return points, list(alive.values())


def vase_of_revolution(keys, flutes, depth, axis, offset, coarse_size, fine_size, fine_at, seed,
                       floor=False, holes=0):
    rnd = random.Random(seed)
    u, v, a = frame(axis)
    twist = rnd.uniform(0, 2 * math.pi)
    height = keys[-1][1]

    def embed(p):
        angle, t = p
        h, r = hermite(keys, t)
        r *= 1.0 + depth * math.cos(flutes * angle + twist)
        if floor and t < 0.0:  # the floor: the domain below t = 0 maps onto the disk at h = 0
            h, r = 0.0, hermite(keys, 0.0)[1] * (1.0 + depth * math.cos(flutes * angle + twist)) * (1.0 + 0.85 * t / 0.1)
        c, s = r * math.cos(angle), r * math.sin(angle)
        return tuple(c * u[i] + s * v[i] + h * a[i] + offset[i] for i in range(3))

    # The coarse domain: 6 sectors by 4 bands (plus a band of floor), sector 5 joined to sector 0.
    sectors, bands = 6, 4
    low = -0.1 if floor else 0.0
    ts = [low] + [k / bands for k in range(bands + 1)] if floor else [k / bands for k in range(bands + 1)]
    domain, index = [], {}
    for b, t in enumerate(ts):
        for s in range(sectors):
            index[(s, b)] = len(domain)
            domain.append((2 * math.pi * s / sectors, t))
    faces = []
    for b in range(len(ts) - 1):
        for s in range(sectors):
            p00, p10 = index[(s, b)], index[((s + 1) % sectors, b)]
            p01, p11 = index[(s, b + 1)], index[((s + 1) % sectors, b + 1)]
            if (s + b) % 2:
                faces += [(p00, p10, p11), (p00, p11, p01)]
            else:
                faces += [(p00, p10, p01), (p10, p11, p01)]
    centre = [h * a[i] + offset[i] for i, h in enumerate([fine_at * height] * 3)]

    def size(p):
        w = math.exp(-(math.dist(p, centre) / (0.35 * height)) ** 2)
        return coarse_size + (fine_size - coarse_size) * w

    points, tris = bisect_mesh(domain, faces, embed, size, rnd)
    unique = points
    for _ in range(holes):
        c = unique[rnd.choice(rnd.choice(tris))]
        tris = [t for t in tris if min(math.dist(unique[i], c) for i in t) > 0.012]
    return unique, tris


def write(path, verts, faces, comment):
    used = sorted({i for f in faces for i in f})
    new = {old: k for k, old in enumerate(used)}
    with open(path, "w") as out:
        out.write(f"# {comment} (bench/make_fluted_vases.py)\n")
        for i in used:
            p = verts[i]
            out.write(f"v {p[0]:.9g} {p[1]:.9g} {p[2]:.9g}\n")
        for f in faces:
            out.write(f"f {new[f[0]] + 1} {new[f[1]] + 1} {new[f[2]] + 1}\n")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_fluted_vases.py OUTDIR")
    os.makedirs(sys.argv[1], exist_ok=True)
    v, f = vase_of_revolution(VASE_KEYS, 8, 0.05, (0.35, 1.0, -0.25), (0.03, -0.12, 0.02),
                              0.022, 0.009, 0.8, seed=11)
    write(os.path.join(sys.argv[1], "fluted_vase_tilted.obj"), v, f,
          "a fluted vase, 8 flutes, axis tilted 23 degrees, uneven triangles")
    v, f = vase_of_revolution(BOTTLE_KEYS, 6, 0.03, (1.0, 0.08, 0.05), (-0.12, 0.01, 0.0),
                              0.02, 0.007, 0.75, seed=5, floor=True, holes=2)
    write(os.path.join(sys.argv[1], "bottle_floor_x.obj"), v, f,
          "a bottle lying along x with a floor, 6 flutes, two holes, uneven triangles")


if __name__ == "__main__":
    main()
