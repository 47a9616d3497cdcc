"""What the bench's saddle generators share (make_saddle_targets.py, make_saddle_scatter.py,
make_saddle_delaunay.py): placing a mesh made in the xy plane (turned about z, tilted about x,
moved), and writing it as an OBJ that names its generator; and the command line of the numpy
generators that write into one folder from one seed (make_lattice_saddles.py,
make_waist_spline_vases.py). How each makes its points and triangles stays its own, so their
targets differ."""
import argparse
import math
import os


def place(p, yaw, tilt, shift):
    """p turned `yaw` degrees about z, then tilted `tilt` degrees about x, then moved by `shift`."""
    x, y, z = p
    a, b = math.radians(yaw), math.radians(tilt)
    x, y = x * math.cos(a) - y * math.sin(a), x * math.sin(a) + y * math.cos(a)
    y, z = y * math.cos(b) - z * math.sin(b), y * math.sin(b) + z * math.cos(b)
    return (x + shift[0], y + shift[1], z + shift[2])


def write_obj(path, comment, generator, verts, tris, number="%.8f", used_only=True):
    """An OBJ of `verts` and `tris` (0-based triples), headed by `comment` and the generator's
    path. With `used_only`, vertices no triangle uses are left out (holes cut, triangles
    dropped) and the rest renumbered in order; `number` formats each coordinate."""
    used = sorted({v for t in tris for v in t}) if used_only else range(len(verts))
    index = {old: new for new, old in enumerate(used)}
    line = "v " + " ".join([number] * 3) + "\n"
    with open(path, "w") as out:
        out.write("# " + comment + " (" + generator + ")\n")
        for v in used:
            out.write(line % tuple(verts[v]))
        for t in tris:
            out.write("f %d %d %d\n" % tuple(index[v] + 1 for v in t))


def vertex_normals(verts, faces):
    """Each vertex's unit normal: the sum of its triangles' area-weighted normals."""
    acc = [[0.0, 0.0, 0.0] for _ in verts]
    for f in faces:
        a, b, c = (verts[i] for i in f)
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        for i in f:
            for k in range(3):
                acc[i][k] += n[k]
    out = []
    for n in acc:
        length = math.sqrt(sum(c * c for c in n)) or 1.0
        out.append([c / length for c in n])
    return out


def folder_and_seed(description, seed):
    """The command line `OUT [--seed S]` (`seed` unless given): OUT made, and the arguments with a
    numpy random generator seeded by S."""
    import numpy as np

    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=seed)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    return args, np.random.default_rng(args.seed)


def write_kinds(folder, names, kind):
    """OUT/targets.tsv: one line per target, its name and the start kind to fit it from."""
    with open(os.path.join(folder, "targets.tsv"), "w") as out:
        for name in names:
            out.write(f"{name}\t{kind}\n")
