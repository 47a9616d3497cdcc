"""What the bench's saddle generators share (make_saddle_targets.py, make_saddle_scatter.py,
make_saddle_delaunay.py): placing a mesh made in the xy plane (turned about z, tilted about x,
moved), and writing it as an OBJ that names its generator. How each makes its points and
triangles stays its own, so their targets differ."""
import math


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
