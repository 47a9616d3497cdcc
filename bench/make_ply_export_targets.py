#!/usr/bin/env python3
"""Smooth targets as a scanner or a modelling tool exports them: PLY, converted to OBJ the way a
mesh viewer saves it (issue 38, 2; lamp25). Python's standard library only; deterministic.

Unlike every other bench/make_*.py (clean OBJ triangles written directly, each `v` used), each
target is written as an ASCII PLY (vertices with colours, faces as quads where the surface is a
grid, triangles elsewhere) and then saved as OBJ by a converter that keeps what the PLY holds:
`v x y z r g b` (colours after the position), quads as `f a b c d`, faces with relative
(negative) indices on some, vertices no face uses (a scanner's stray points, far off the
surface), a seam where the exporter split the vertices (a column of duplicated vertices down a
lathe's meridian, as a texture seam leaves it), duplicated or zero-area faces, a fin (one
triangle hung on an inner edge: a non-manifold edge), and whole meshes wound inside out. Noise
is added along each vertex's normal on scans, and holes cut by removing the faces within a ball
around a few surface points. Units are millimetres, centimetres, inches or metres; the axis a
random direction (a rotation from three random angles), off the origin.

  vase_scan_mm      a vase with noise and three holes, closed foot, open lip, 40 stray points;
  bell_lamp_cm      a bell-shaped lampshade open at top and bottom, quads, a texture seam;
  oval_bowl_scan_m  a bowl whose rim is an oval (a superquadric cap), noise, two holes, a fin;
  lamp_bulge_in     a lampshade with a bulge, open both ends, wound inside out, negative indices;
  dish_strays_m     a shallow dish (a cosine profile) with stray points and duplicated faces;
  hypar_in          a hyperbolic paraboloid z = x y / c over a square, quads, inches;
  tube_lamp_cm      a slightly tapered open tube (a drum lampshade), a few zero-area faces.

Usage: bench/make_ply_export_targets.py OUTDIR [--seed S]
Writes OUTDIR/NAME.ply, OUTDIR/NAME.obj (the export, what `fit` reads) and OUTDIR/NAME.ref.obj
(the same surface without stray points, fins, duplicates and zero-area faces, for
judge_distance.py: a stray point would stretch its bounding-box diagonal), and targets.tsv.
"""
import argparse
import math
import os
import random

UNITS = {"mm": 0.001, "cm": 0.01, "in": 0.0254, "m": 1.0}


def rotation(rng):
    a, b, c = (rng.uniform(0, 2 * math.pi) for _ in range(3))
    ca, sa, cb, sb, cc, sc = math.cos(a), math.sin(a), math.cos(b), math.sin(b), math.cos(c), math.sin(c)
    rz = [[ca, -sa, 0], [sa, ca, 0], [0, 0, 1]]
    rx = [[1, 0, 0], [0, cb, -sb], [0, sb, cb]]
    ry = [[cc, 0, sc], [0, 1, 0], [-sc, 0, cc]]

    def mul(p, q):
        return [[sum(p[i][k] * q[k][j] for k in range(3)) for j in range(3)] for i in range(3)]

    return mul(ry, mul(rx, rz))


def apply(m, p):
    return [sum(m[i][k] * p[k] for k in range(3)) for i in range(3)]


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


class Mesh:
    def __init__(self):
        self.v = []  # positions, metres, local frame
        self.faces = []  # lists of vertex indices (3 or 4), counter-clockwise seen from outside

    def add(self, p):
        self.v.append(list(p))
        return len(self.v) - 1


def grid_surface(point, nu, nv, closed_u, seam=False):
    """Quads over (u, v): u around (closed: wraps) or across, v along. With `seam`, the wrap is
    made with a duplicated column (u = 1 written again), as an exporter's texture seam."""
    mesh = Mesh()
    cols = nu + 1 if (not closed_u or seam) else nu
    ids = [[mesh.add(point(i / nu, j / nv)) for i in range(cols)] for j in range(nv + 1)]
    for j in range(nv):
        for i in range(nu if closed_u else nu):
            i1 = i + 1 if (not closed_u or seam) else (i + 1) % nu
            mesh.faces.append([ids[j][i], ids[j][i1], ids[j + 1][i1], ids[j + 1][i]])
    return mesh, ids


def vertex_normals(mesh):
    n = [[0.0, 0.0, 0.0] for _ in mesh.v]
    for f in mesh.faces:
        for k in range(1, len(f) - 1):
            c = cross(sub(mesh.v[f[k]], mesh.v[f[0]]), sub(mesh.v[f[k + 1]], mesh.v[f[0]]))
            for i in (f[0], f[k], f[k + 1]):
                n[i] = [n[i][0] + c[0], n[i][1] + c[1], n[i][2] + c[2]]
    return [[x / (norm(a) or 1.0) for x in a] for a in n]


def add_noise(mesh, rng, sigma):
    normals = vertex_normals(mesh)
    for p, n in zip(mesh.v, normals):
        e = rng.gauss(0.0, sigma)
        p[0] += e * n[0]
        p[1] += e * n[1]
        p[2] += e * n[2]


def cut_holes(mesh, rng, count, radius):
    used = sorted({i for f in mesh.faces for i in f})
    centres = [mesh.v[rng.choice(used)] for _ in range(count)]
    keep = []
    for f in mesh.faces:
        c = [sum(mesh.v[i][k] for i in f) / len(f) for k in range(3)]
        if all(norm(sub(c, q)) > radius for q in centres):
            keep.append(f)
    mesh.faces = keep


def lathe(profile, nu, nv, seam=False):
    def point(u, v):
        r, z = profile(v)
        return [r * math.cos(2 * math.pi * u), r * math.sin(2 * math.pi * u), z]

    return grid_surface(point, nu, nv, True, seam)


def write_ply(path, positions, colours, faces):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment lamp25 make_ply_export_targets.py\n")
        f.write(f"element vertex {len(positions)}\nproperty float x\nproperty float y\n"
                "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n")
        f.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        for p, c in zip(positions, colours):
            f.write(f"{p[0]:.6g} {p[1]:.6g} {p[2]:.6g} {c[0]} {c[1]} {c[2]}\n")
        for face in faces:
            f.write(f"{len(face)} " + " ".join(str(i) for i in face) + "\n")


def read_ply(path):
    lines = open(path).read().splitlines()
    end = lines.index("end_header")
    nv = int(next(l.split()[2] for l in lines if l.startswith("element vertex")))
    nf = int(next(l.split()[2] for l in lines if l.startswith("element face")))
    verts = [l.split() for l in lines[end + 1:end + 1 + nv]]
    faces = [list(map(int, l.split()[1:])) for l in lines[end + 1 + nv:end + 1 + nv + nf]]
    return verts, faces


def ply_to_obj(ply, obj, negative):
    """Saves the PLY as OBJ keeping colours on `v` lines and polygons as they are."""
    verts, faces = read_ply(ply)
    with open(obj, "w") as f:
        f.write(f"# exported from {os.path.basename(ply)}\n# vertices {len(verts)}, faces {len(faces)}\n")
        f.write("o scan\n")
        if not negative:
            for v in verts:
                f.write("v " + " ".join(v[:3]) + " " +
                        " ".join(f"{int(c) / 255:.4f}" for c in v[3:6]) + "\n")
            f.write("g surface\ns 1\n")
            for face in faces:
                f.write("f " + " ".join(str(i + 1) for i in face) + "\n")
        else:
            # Each face written right after its own new vertices would need duplicates; instead
            # all vertices first and faces by relative index from the end, as some tools do.
            for v in verts:
                f.write("v " + " ".join(v[:3]) + "\n")
            for face in faces:
                f.write("f " + " ".join(str(i - len(verts)) for i in face) + "\n")


def write_ref_obj(path, positions, faces):
    used = sorted({i for f in faces for i in f})
    index = {i: k + 1 for k, i in enumerate(used)}
    with open(path, "w") as f:
        for i in used:
            p = positions[i]
            f.write(f"v {p[0]:.6g} {p[1]:.6g} {p[2]:.6g}\n")
        for face in faces:
            f.write("f " + " ".join(str(index[i]) for i in face) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir")
    parser.add_argument("--seed", type=int, default=2502)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    os.makedirs(args.outdir, exist_ok=True)
    rows = []

    def emit(name, kind, unit, mesh, size, description, strays=0, fin=False, duplicates=0,
             zero_area=0, inside_out=False, negative=False):
        m = rotation(rng)
        offset = [rng.uniform(-2, 2) * size for _ in range(3)]
        positions = [[x / UNITS[unit] for x in (lambda q: [q[0] + offset[0], q[1] + offset[1],
                                                            q[2] + offset[2]])(apply(m, p))]
                     for p in mesh.v]
        faces = [list(reversed(f)) if inside_out else list(f) for f in mesh.faces]
        ref_faces = [list(f) for f in faces]
        extra = []
        if fin:
            # A triangle hung on an inner edge of a face near the middle: that edge now has three faces.
            f = faces[len(faces) // 2]
            a, b = f[0], f[1]
            mid = [(positions[a][k] + positions[b][k]) / 2 for k in range(3)]
            n = cross(sub(positions[b], positions[a]), sub(positions[f[2]], positions[a]))
            tip = [mid[k] + 0.5 * n[k] / (norm(n) or 1.0) * norm(sub(positions[b], positions[a]))
                   for k in range(3)]
            positions.append(tip)
            extra.append([a, b, len(positions) - 1])
        for _ in range(duplicates):
            extra.append(list(rng.choice(faces)))
        for _ in range(zero_area):
            f = rng.choice(faces)
            extra.append([f[0], f[1], f[0]] if rng.random() < 0.5 else [f[0], f[1], f[1]])
        faces = faces + extra
        centre = [sum(p[k] for p in positions) / len(positions) for k in range(3)]
        for _ in range(strays):
            # A scanner's stray point: up to twice the size off the surface, in no face.
            positions.append([centre[k] + rng.uniform(-2, 2) * size / UNITS[unit] for k in range(3)])
        colours = [(rng.randrange(90, 200),) * 3 for _ in positions]
        ply = os.path.join(args.outdir, name + ".ply")
        write_ply(ply, positions, colours, faces)
        ply_to_obj(ply, os.path.join(args.outdir, name + ".obj"), negative)
        write_ref_obj(os.path.join(args.outdir, name + ".ref.obj"), positions, ref_faces)
        rows.append((name, kind, unit, UNITS[unit], description))

    # A vase scan: closed foot (a fan), belly, neck, open lip; noise, holes, stray points.
    h = rng.uniform(0.22, 0.3)
    rb, rn, rf = h * 0.3, h * 0.12, h * 0.18

    def vase(v):
        r = rf + (rb - rf) * math.sin(math.pi * min(1.0, v / 0.45) / 2) ** 2
        if v > 0.45:
            s = (v - 0.45) / 0.55
            r = rn + (rb - rn) * (1 - s) ** 2 * (1 + 2 * s) + 0.6 * rn * s ** 4
        return r, h * v

    mesh, ids = lathe(vase, 48, 40)
    centre = mesh.add([0.0, 0.0, 0.0])
    ring = ids[0]
    for i in range(48):
        mesh.faces.append([centre, ring[(i + 1) % 48], ring[i]])
    add_noise(mesh, rng, 0.002 * h)
    cut_holes(mesh, rng, 3, 0.07 * h)
    emit("vase_scan_mm", "cylinder", "mm", mesh, h,
         f"vase scan {h:.3f} m tall, foot {rf:.3f}, belly {rb:.3f}, neck {rn:.3f} m, noise 0.2%, "
         "3 holes, 40 stray points", strays=40)

    # A bell lampshade open at both ends: quads, a texture seam.
    h = rng.uniform(0.15, 0.22)
    top, lip = h * 0.22, h * 0.6

    def bell(v):
        return top + (lip - top) * (v ** 2.2) * (0.6 + 0.4 * v), h * (1 - v)

    mesh, _ = lathe(bell, 40, 24, seam=True)
    emit("bell_lamp_cm", "cone", "cm", mesh, h,
         f"bell lampshade {h:.3f} m tall, top {top:.3f}, lip {lip:.3f} m, open, quads, a seam")

    # An oval bowl scan: a superquadric cap over an oval rim, noise, two holes, a fin.
    a = rng.uniform(0.09, 0.13)
    b = a * rng.uniform(0.6, 0.75)
    depth = a * rng.uniform(0.45, 0.6)

    def oval(u, v):
        # v: 0 at the bottom, 1 at the rim; the depth falls as (1 - v^2)^0.8.
        phi = 2 * math.pi * u
        return [a * v * math.cos(phi), b * v * math.sin(phi), -depth * (1 - v * v) ** 0.8]

    mesh, ids = grid_surface(oval, 44, 18, True)
    # v = 0 is a ring of coincident points: weld it into one centre vertex.
    pole = ids[0][0]
    mesh.faces = [[pole if i in ids[0] else i for i in f] for f in mesh.faces]
    mesh.faces = [[i for k, i in enumerate(f) if i != f[k - 1]] for f in mesh.faces]
    add_noise(mesh, rng, 0.0015 * a)
    cut_holes(mesh, rng, 2, 0.12 * a)
    emit("oval_bowl_scan_m", "disk", "m", mesh, a,
         f"bowl over an oval rim {2 * a:.3f} x {2 * b:.3f} m, {depth:.3f} m deep, noise, 2 holes, a fin",
         fin=True)

    # A lampshade with a bulge, inches, inside out, negative indices.
    h = rng.uniform(0.2, 0.28)
    r0, r1, bulge = h * 0.5, h * 0.26, h * 0.12
    mesh, _ = lathe(lambda v: (r0 + (r1 - r0) * v + bulge * math.sin(math.pi * v) ** 1.5, h * v),
                    36, 22)
    emit("lamp_bulge_in", "cone", "in", mesh, h,
         f"lampshade {h:.3f} m tall, radii {r0:.3f} -> {r1:.3f}, bulge {bulge:.3f} m, open, "
         "inside out, relative indices", inside_out=True, negative=True)

    # A shallow dish: cosine profile, stray points, duplicated faces.
    radius = rng.uniform(0.13, 0.17)
    depth = radius * rng.uniform(0.08, 0.14)

    def dish(u, v):
        phi = 2 * math.pi * u
        return [radius * v * math.cos(phi), radius * v * math.sin(phi),
                -depth * 0.5 * (1 + math.cos(math.pi * v))]

    mesh, ids = grid_surface(dish, 40, 14, True)
    pole = ids[0][0]
    mesh.faces = [[pole if i in ids[0] else i for i in f] for f in mesh.faces]
    mesh.faces = [[i for k, i in enumerate(f) if i != f[k - 1]] for f in mesh.faces]
    emit("dish_strays_m", "disk", "m", mesh, radius,
         f"shallow dish {2 * radius:.3f} m across, {depth:.3f} m deep, 25 stray points, "
         "6 duplicated faces", strays=25, duplicates=6)

    # A hyperbolic paraboloid over a square, inches, quads.
    side = rng.uniform(0.18, 0.26)
    c = side * rng.uniform(0.35, 0.6)
    mesh, _ = grid_surface(lambda u, v: [side * (u - 0.5), side * (v - 0.5),
                                         side * (u - 0.5) * side * (v - 0.5) / c], 26, 26, False)
    emit("hypar_in", "square", "in", mesh, side,
         f"hyperbolic paraboloid z = x y / {c:.3f} over a {side:.3f} m square, quads")

    # A drum lampshade: an open, slightly tapered tube, a few zero-area faces.
    h = rng.uniform(0.18, 0.25)
    rb, rt = h * 0.55, h * 0.47
    mesh, _ = lathe(lambda v: (rb + (rt - rb) * v, h * v), 56, 16)
    emit("tube_lamp_cm", "cylinder", "cm", mesh, h,
         f"drum lampshade {h:.3f} m tall, radii {rb:.3f} -> {rt:.3f} m, open, 4 zero-area faces",
         zero_area=4)

    with open(os.path.join(args.outdir, "targets.tsv"), "w") as f:
        f.write("name\tkind\tunit\tmetres_per_unit\tdescription\n")
        for r in rows:
            f.write("\t".join(str(x) for x in r) + "\n")


if __name__ == "__main__":
    main()
