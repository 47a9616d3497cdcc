#!/usr/bin/env python3
"""Tessellated crease patterns as FOLD files, for the static solver's settle sweeps (issue 39).

Unlike the other generators (SVG lines and circles, single bases, one Miura or Yoshimura sheet),
these repeat a unit cell over a sheet at several sizes, so a pattern has many vertices of the
same kind folding at once, and they are written the way other tools write FOLD: polygon faces in
faces_vertices (quads and hexagons where a cell's region is one), signed edges_foldAngle in
degrees (valley +, mountain -, FOLD's convention) next to edges_assignment, a frame_unit of
"mm" or "in", and vertex coordinates as [x, y, 0] in some files and [x, y] in others:

  waterbomb_tess_N_A   N x N waterbomb bases (diagonals valley, midlines mountain), every other
                       row shifted by half a cell (the "magic ball"), cut to the sheet's square;
                       cell edges flat; fold angles A and -A.
  kresling_N_M_A       a Kresling tower's development: N parallelograms around, M storeys, each
                       split by its valley diagonal; the storeys' edges mountains; left and right
                       sides boundaries (not glued); triangles.
  pleat_quads_N_A      an accordion of N strips, alternately valley and mountain at +-A, each strip
                       a quad face, with a hexagonal face where a strip's end is chamfered.

Usage: make_tessellation_patterns.py OUTPUT_DIR
"""
import json
import math
import os
import sys


class Pattern:
    def __init__(self):
        self.vertices = []
        self.index = {}
        self.edges = {}

    def vertex(self, x, y):
        key = (round(x, 9), round(y, 9))
        if key not in self.index:
            self.index[key] = len(self.vertices)
            self.vertices.append((x, y))
        return self.index[key]

    def edge(self, a, b, assignment, angle):
        if a == b:
            return
        key = (min(a, b), max(a, b))
        old = self.edges.get(key)
        # A crease wins over a flat edge drawn along it by a neighbouring cell.
        if old is None or old[0] in ("F", "B"):
            self.edges[key] = (assignment, angle)

    def write(self, path, unit, faces=None, three_d=True):
        edges = sorted(self.edges.items())
        xs = [v[0] for v in self.vertices]
        ys = [v[1] for v in self.vertices]
        doc = {
            "file_spec": 1.1,
            "file_creator": "make_tessellation_patterns.py",
            "frame_classes": ["creasePattern"],
            "frame_unit": unit,
            "vertices_coords": [[x, y, 0.0] if three_d else [x, y] for x, y in self.vertices],
            "edges_vertices": [list(k) for k, _ in edges],
            "edges_assignment": [a for _, (a, _) in edges],
            "edges_foldAngle": [g for _, (_, g) in edges],
        }
        if faces:
            doc["faces_vertices"] = faces
        with open(path, "w") as f:
            json.dump(doc, f)
        return len(self.vertices), len(edges), (max(xs) - min(xs), max(ys) - min(ys))


def boundary_of_square(p, side):
    """Marks edges along the square's sides as boundaries."""
    for (a, b), (kind, angle) in list(p.edges.items()):
        (xa, ya), (xb, yb) = p.vertices[a], p.vertices[b]
        on = any(abs(u) < 1e-9 and abs(v) < 1e-9 for u, v in ((xa, xb), (ya, yb))) or any(
            abs(u - side) < 1e-9 and abs(v - side) < 1e-9 for u, v in ((xa, xb), (ya, yb)))
        if on:
            p.edges[(a, b)] = ("B", 0)


def waterbomb_tess(n, angle, cell=20.0):
    """n x n cells of side `cell`, odd rows shifted by half a cell, clipped to [0, n cell]^2."""
    p = Pattern()
    side = n * cell
    h = cell / 2.0

    def clip(x):
        return min(max(x, 0.0), side)

    for j in range(n):
        shift = h if j % 2 else 0.0
        for i in range(-1, n + 1):
            x0, y0 = i * cell + shift, j * cell
            if x0 + cell <= 0 or x0 >= side:
                continue
            cx, cy = x0 + h, y0 + h
            # Half cells at the sheet's sides: the square [x0, x0 + cell] cut at 0 or side.
            lo, hi = clip(x0), clip(x0 + cell)
            if hi - lo < 1e-9:
                continue
            if lo == x0 and hi == x0 + cell:
                c = p.vertex(cx, cy)
                corners = [(x0, y0), (x0 + cell, y0), (x0 + cell, y0 + cell), (x0, y0 + cell)]
                mids = [(cx, y0), (x0 + cell, cy), (cx, y0 + cell), (x0, cy)]
                for k in range(4):
                    a = p.vertex(*corners[k])
                    b = p.vertex(*corners[(k + 1) % 4])
                    m = p.vertex(*mids[k])
                    p.edge(c, a, "V", angle)
                    p.edge(c, m, "M", -angle)
                    p.edge(a, m, "F", 0)
                    p.edge(m, b, "F", 0)
            else:
                # A half cell: its centre lies on the sheet's side; its half of the base.
                c = p.vertex(clip(cx), cy)
                xin = lo if hi == side else hi
                a, b = p.vertex(xin, y0), p.vertex(xin, y0 + cell)
                ca, cb = p.vertex(clip(cx), y0), p.vertex(clip(cx), y0 + cell)
                m = p.vertex(xin, cy)
                p.edge(c, a, "V", angle)
                p.edge(c, b, "V", angle)
                p.edge(c, m, "M", -angle)
                for u, v in ((a, ca), (b, cb), (a, m), (m, b), (c, ca), (c, cb)):
                    p.edge(u, v, "F", 0)
    boundary_of_square(p, side)
    return p


def kresling(n, m, angle, width=15.0, height=12.0, lean=0.6):
    """A Kresling development: parallelograms `width` wide and `height` high, each storey shifted
    by lean x width; diagonals valley at `angle`, storeys' edges mountain at -angle / 2."""
    p = Pattern()
    ids = [[p.vertex(i * width + j * lean * width, j * height) for i in range(n + 1)]
           for j in range(m + 1)]
    faces = []
    for j in range(m + 1):
        for i in range(n):
            kind = "B" if j in (0, m) else "M"
            p.edge(ids[j][i], ids[j][i + 1], kind, 0 if kind == "B" else -angle / 2.0)
    for j in range(m):
        for i in range(n + 1):
            kind = "B" if i in (0, n) else "M"
            p.edge(ids[j][i], ids[j + 1][i], kind, 0 if kind == "B" else -angle / 3.0)
        for i in range(n):
            p.edge(ids[j][i], ids[j + 1][i + 1], "V", angle)
            faces.append([ids[j][i], ids[j][i + 1], ids[j + 1][i + 1]])
            faces.append([ids[j][i], ids[j + 1][i + 1], ids[j + 1][i]])
    return p, faces


def pleat_quads(n, angle, width=1.0, length=4.0, chamfer=0.3):
    """An accordion of n strips across a `length` long sheet (inches), its last strip's far
    corners chamfered (a hexagon face)."""
    p = Pattern()
    faces = []
    lines = []
    for k in range(n + 1):
        lines.append((p.vertex(k * width, 0.0), p.vertex(k * width, length)))
    for k in range(n):
        (a0, a1), (b0, b1) = lines[k], lines[k + 1]
        p.edge(a0, b0, "B", 0)
        if k == n - 1:
            c0 = p.vertex((k + 1) * width, chamfer)
            c1 = p.vertex((k + 1) * width, length - chamfer)
            d0 = p.vertex((k + 1) * width - chamfer, 0.0)
            d1 = p.vertex((k + 1) * width - chamfer, length)
            p.edges.pop((min(a0, b0), max(a0, b0)), None)
            for u, v in ((a0, d0), (d0, c0), (c0, c1), (c1, d1), (d1, a1)):
                p.edge(u, v, "B", 0)
            faces.append([a0, d0, c0, c1, d1, a1])
        else:
            p.edge(a1, b1, "B", 0)
            faces.append([a0, b0, b1, a1])
    for k in range(n):
        a0, a1 = lines[k]
        if k == 0:
            p.edge(a0, a1, "B", 0)
        else:
            valley = k % 2 == 1
            p.edge(a0, a1, "V" if valley else "M", angle if valley else -angle)
    return p, faces


def main(out):
    os.makedirs(out, exist_ok=True)
    made = []
    for n in (2, 3, 4):
        for angle in (90, 150):
            name = f"waterbomb_tess_{n}_{angle}.fold"
            info = waterbomb_tess(n, angle).write(os.path.join(out, name), "mm",
                                                  three_d=n % 2 == 0)
            made.append((name, info))
    for n, m in ((6, 2), (8, 3)):
        for angle in (60, 120):
            p, faces = kresling(n, m, angle)
            name = f"kresling_{n}_{m}_{angle}.fold"
            made.append((name, p.write(os.path.join(out, name), "mm", faces)))
    for n in (4, 7):
        for angle in (120, 170):
            p, faces = pleat_quads(n, angle)
            name = f"pleat_quads_{n}_{angle}.fold"
            made.append((name, p.write(os.path.join(out, name), "in", faces, three_d=False)))
    for name, (vertices, edges, (w, h)) in made:
        print(f"{name}: {vertices} vertices, {edges} edges, {w:g} x {h:g}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_tessellation_patterns.py OUTPUT_DIR")
    main(sys.argv[1])
