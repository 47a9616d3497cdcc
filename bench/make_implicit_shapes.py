#!/usr/bin/python3
"""Smooth targets for `fit` (issue 38, 2) written from the issue's words alone ("a vase, a bowl, a
lampshade with a bulge, a saddle, a scanned object with noise and holes"), meshed unlike every
other bench/make_*.py: each shape is the zero set of an implicit function F(p) (a surface of
revolution as |p_xz| - r(y), a bowl as a sphere or paraboloid, a saddle as a height field), cut
out of a cube lattice by marching tetrahedra (each cube split into six tetrahedra about its
diagonal, the lattice turned at random and of random spacing, so triangles fall at any size,
shape and direction, slivers included), then clipped exactly by planes (a vase's rim and foot, a
saddle's square) with the cut points shared along each edge. Scans get a smooth random field
added to F (bumps), jitter along the normal and holes cut out by balls. Each is then set at a
random size (4 cm to 1.5 m across, log-uniform, written in metres), a random orientation (vases
stay about y, as the issue has them) and a random offset from the origin (near it or three sizes
away); some OBJ files carry `vn` normals and `f a//a` faces.

    /usr/bin/python3 bench/make_implicit_shapes.py OUTDIR [--seed S] [--mm]

--mm writes the coordinates in millimetres (as many scanners do), so a 20 cm bowl reads as 200 m.

Writes OUTDIR/NAME.obj and OUTDIR/kinds.txt (NAME KIND, the `--from` kind a designer picks).
numpy only; deterministic for one seed.
"""
import argparse
import math
import os

import numpy as np

# Marching tetrahedra: a cube's six tetrahedra about its main diagonal (corner 0 to 6).
CORNERS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                    [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])
TETS = [(0, 5, 1, 6), (0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6)]


def random_rotation(rng):
    q = rng.normal(size=4)
    a, b, c, d = q / np.linalg.norm(q)
    return np.array([[a*a+b*b-c*c-d*d, 2*(b*c-a*d), 2*(b*d+a*c)],
                     [2*(b*c+a*d), a*a-b*b+c*c-d*d, 2*(c*d-a*b)],
                     [2*(b*d-a*c), 2*(c*d+a*b), a*a-b*b-c*c+d*d]])


def rotation_about_y(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def march(field, lo, hi, spacing, turn):
    """Triangles of field = 0 inside the box [lo, hi] (unit-free, the shape's own frame), on a
    lattice of `spacing` turned by `turn`. Returns (vertices, triangles) with shared vertices."""
    centre = 0.5 * (lo + hi)
    half = 0.5 * np.linalg.norm(hi - lo) + 2 * spacing
    n = int(math.ceil(2 * half / spacing)) + 1
    ax = np.arange(n) * spacing - half
    g = np.stack(np.meshgrid(ax, ax, ax, indexing="ij"), -1).reshape(-1, 3)
    world = g @ turn.T + centre
    values = field(world)
    # No lattice value exactly zero (a surface through a lattice point makes a zero-area triangle).
    tiny = 0.02 * spacing
    values = np.where(np.abs(values) < tiny, np.where(values < 0, -tiny, tiny), values)
    values = values.reshape(n, n, n)
    world = world.reshape(n, n, n, 3)
    keyed = {}
    verts = []
    tris = []

    def vertex(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in keyed:
            va, vb = values[a], values[b]
            t = va / (va - vb)
            keyed[key] = len(verts)
            verts.append(world[a] + t * (world[b] - world[a]))
        return keyed[key]

    inside = np.abs(values) < 1.8 * spacing  # cubes the surface may cross
    cells = np.argwhere(inside[:-1, :-1, :-1] | inside[1:, 1:, 1:])
    for i, j, k in cells:
        corner = [tuple(c) for c in np.array([i, j, k]) + CORNERS]
        for tet in TETS:
            p = [corner[t] for t in tet]
            s = [values[q] < 0 for q in p]
            neg = [q for q, m in zip(p, s) if m]
            pos = [q for q, m in zip(p, s) if not m]
            if len(neg) in (0, 4):
                continue
            if len(neg) == 1 or len(neg) == 3:
                one = neg[0] if len(neg) == 1 else pos[0]
                rest = pos if len(neg) == 1 else neg
                tri = [vertex(one, r) for r in rest]
                tris.append((tri, one, len(neg) == 1))
            else:
                a, b = neg
                c, d = pos
                quad = [vertex(a, c), vertex(a, d), vertex(b, d), vertex(b, c)]
                tris.append(([quad[0], quad[1], quad[2]], a, True))
                tris.append(([quad[0], quad[2], quad[3]], a, True))
    verts = np.array(verts)
    out = []
    for tri, ref, negative in tris:
        # Orient every triangle with the gradient (normal toward positive F).
        p = verts[tri]
        n_ = np.cross(p[1] - p[0], p[2] - p[0])
        towards = p.mean(0) - world[ref]  # from the reference lattice point to the triangle
        if (np.dot(n_, towards) > 0) != negative:
            tri = [tri[0], tri[2], tri[1]]
        out.append(tri)
    return verts, np.array(out)


def clip(verts, tris, planes):
    """Keeps the part of the mesh where every plane's n.p <= d, cutting triangles exactly; the cut
    point on an edge is shared by the triangles on both sides."""
    verts = [v for v in verts]
    for normal, d in planes:
        normal = np.asarray(normal, float)
        side = np.array([np.dot(normal, v) - d for v in verts])
        side = np.where(np.abs(side) < 1e-9, 1e-9, side)
        cut = {}

        def cutpoint(a, b):
            key = (a, b) if a < b else (b, a)
            if key not in cut:
                t = side[a] / (side[a] - side[b])
                cut[key] = len(verts)
                verts.append(verts[a] + t * (verts[b] - verts[a]))
            return cut[key]

        kept = []
        for tri in tris:
            poly = []
            for e in range(3):
                a, b = tri[e], tri[(e + 1) % 3]
                if side[a] <= 0:
                    poly.append(a)
                if (side[a] <= 0) != (side[b] <= 0):
                    poly.append(cutpoint(a, b))
            for e in range(1, len(poly) - 1):
                kept.append((poly[0], poly[e], poly[e + 1]))
        tris = kept
    return tidy(np.array(verts), np.array(tris))


def tidy(verts, tris):
    """Drops unused vertices and triangles thinner than a sliver a scanner's software keeps."""
    p = verts[tris]
    area2 = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    longest = np.max([np.linalg.norm(p[:, a] - p[:, b], axis=1) for a, b in ((0, 1), (1, 2), (2, 0))], 0)
    tris = tris[area2 > 1e-4 * longest ** 2]
    used = np.unique(tris)
    remap = -np.ones(len(verts), int)
    remap[used] = np.arange(len(used))
    return verts[used], remap[tris]


def normals_of(verts, tris):
    n = np.zeros_like(verts)
    p = verts[tris]
    fn = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    for k in range(3):
        np.add.at(n, tris[:, k], fn)
    return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)


def bumps(rng, amplitude, wavelength):
    """A smooth random field: a sum of plane waves of random direction and phase."""
    dirs = rng.normal(size=(12, 3))
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    k = 2 * math.pi / wavelength * rng.uniform(0.6, 1.6, 12)
    phase = rng.uniform(0, 2 * math.pi, 12)
    return lambda p: amplitude / math.sqrt(6) * np.sin((p @ dirs.T) * k + phase).sum(1)


def revolution(radius):
    return lambda p: np.hypot(p[:, 0], p[:, 2]) - radius(p[:, 1])


def shapes(rng):
    """(name, kind, field, box lo, box hi, clip planes, about-y, noise, holes, normals)."""
    out = []
    # A vase about y: a round belly, a waist and a flared lip, 1 unit tall.
    vase = lambda y: 0.22 + 0.12 * np.sin(math.pi * np.clip(y, 0, 1) * 1.1) \
        - 0.06 * np.exp(-((y - 0.78) / 0.1) ** 2) + 0.05 * np.clip(y - 0.85, 0, None) / 0.15
    out.append(("vase_march", "cylinder", revolution(vase), [-0.45, -0.05, -0.45], [0.45, 1.05, 0.45],
                [((0, -1, 0), 0.0), ((0, 1, 0), 1.0)], True, 0, 0, True))
    # A lampshade with a bulge two fifths down: a cone 0.35 -> 0.2 with a Gaussian bulge.
    lamp = lambda y: 0.35 - 0.15 * y + 0.07 * np.exp(-((y - 0.6) / 0.15) ** 2)
    out.append(("lampshade_march", "cone", revolution(lamp), [-0.5, -0.05, -0.5], [0.5, 1.05, 0.5],
                [((0, -1, 0), 0.0), ((0, 1, 0), 0.8)], False, 0, 0, False))
    # A bowl: a sphere's cap below a plane (a hemisphere's lower 60%).
    sphere = lambda p: np.linalg.norm(p, axis=1) - 0.5
    out.append(("bowl_cap", "disk", sphere, [-0.55, -0.55, -0.55], [0.55, 0.55, 0.0],
                [((0, 0, 1), -0.12)], False, 0, 0, True))
    # A shallow dish: a paraboloid z = 0.6 r^2 up to r = 0.5.
    dish = lambda p: p[:, 2] - 0.6 * (p[:, 0] ** 2 + p[:, 1] ** 2)
    out.append(("dish_paraboloid", "disk", dish, [-0.55, -0.55, -0.02], [0.55, 0.55, 0.2],
                [((0, 0, 1), 0.15)], False, 0, 0, False))
    # A saddle z = (x^2 - y^2) / 1.2 over a square of side 1 (its edges along the axes).
    saddle = lambda p: p[:, 2] - (p[:, 0] ** 2 - p[:, 1] ** 2) / 1.2
    out.append(("saddle_march", "square", saddle, [-0.5, -0.5, -0.25], [0.5, 0.5, 0.25],
                [((1, 0, 0), 0.5), ((-1, 0, 0), 0.5), ((0, 1, 0), 0.5), ((0, -1, 0), 0.5)],
                False, 0, 0, True))
    # A hypar z = x y / 0.7 over a square turned 45 degrees to its rulings.
    hypar = lambda p: p[:, 2] - p[:, 0] * p[:, 1] / 0.7
    s = 1 / math.sqrt(2)
    out.append(("hypar_diamond", "square", hypar, [-0.55, -0.55, -0.3], [0.55, 0.55, 0.3],
                [((s, s, 0), 0.5), ((-s, -s, 0), 0.5), ((s, -s, 0), 0.5), ((-s, s, 0), 0.5)],
                False, 0, 0, False))
    # A scanned bowl: a deep paraboloid with bumps, jitter and three holes.
    deep = lambda p: p[:, 2] - 1.1 * (p[:, 0] ** 2 + p[:, 1] ** 2)
    out.append(("bowl_scan_holes", "disk", deep, [-0.5, -0.5, -0.02], [0.5, 0.5, 0.3],
                [((0, 0, 1), 0.25)], False, 0.006, 3, False))
    # A scanned vase about y with bumps, jitter and two holes (normals written).
    jar = lambda y: 0.25 + 0.08 * np.sin(2.2 * y + 0.4)
    out.append(("vase_scan_holes", "cylinder", revolution(jar), [-0.4, -0.05, -0.4], [0.4, 1.05, 0.4],
                [((0, -1, 0), 0.0), ((0, 1, 0), 1.0)], True, 0.005, 2, True))
    return out


def write_obj(path, verts, tris, with_normals):
    with open(path + ".tmp", "w") as f:
        f.write("# made by bench/make_implicit_shapes.py (marching tetrahedra of a formula)\n")
        for v in verts:
            f.write("v %.9g %.9g %.9g\n" % tuple(v))
        if with_normals:
            for n in normals_of(verts, tris):
                f.write("vn %.6f %.6f %.6f\n" % tuple(n))
            for t in tris + 1:
                f.write("f %d//%d %d//%d %d//%d\n" % (t[0], t[0], t[1], t[1], t[2], t[2]))
        else:
            for t in tris + 1:
                f.write("f %d %d %d\n" % tuple(t))
    os.replace(path + ".tmp", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("--seed", type=int, default=16)
    parser.add_argument("--mm", action="store_true", help="write coordinates in millimetres")
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    rng = np.random.default_rng(args.seed)
    kinds = []
    for name, kind, field, lo, hi, planes, about_y, noise, holes, with_normals in shapes(rng):
        if noise:
            field = (lambda f, b: (lambda p: f(p) + b(p)))(field, bumps(rng, noise, 0.2))
        spacing = rng.uniform(0.025, 0.05)
        verts, tris = march(field, np.array(lo, float), np.array(hi, float), spacing,
                            random_rotation(rng))
        verts, tris = clip(verts, tris, planes)
        if noise:
            verts = verts + normals_of(verts, tris) * rng.normal(0, 0.4 * noise, (len(verts), 1))
        for _ in range(holes):
            centre = verts[rng.integers(len(verts))]
            radius = rng.uniform(0.04, 0.08)
            far = np.linalg.norm(verts[tris].mean(1) - centre, axis=1) > radius
            tris = tris[far]
        verts, tris = tidy(verts, tris)
        scale = 10 ** rng.uniform(math.log10(0.04), math.log10(1.5))  # 4 cm to 1.5 m across
        turn = rotation_about_y(rng.uniform(0, 2 * math.pi)) if about_y else random_rotation(rng)
        offset = rng.normal(0, 1, 3) * scale * rng.choice([0.1, 3.0])
        verts = (verts * scale) @ turn.T + offset
        if args.mm:
            verts = verts * 1000
        write_obj(os.path.join(args.outdir, name + ".obj"), verts, tris, with_normals)
        kinds.append("%s %s" % (name, kind))
        print("%-18s %-8s %6d triangles, %.3g m across" % (name, kind, len(tris), scale))
    with open(os.path.join(args.outdir, "kinds.txt"), "w") as f:
        f.write("\n".join(kinds) + "\n")


if __name__ == "__main__":
    main()
