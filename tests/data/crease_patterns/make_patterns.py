#!/usr/bin/env python3
"""Writes the generated crease-pattern fixtures next to this script (run it again after changing it):
the Miura-ori as FOLD (faces given, 2D) and as SVG (one <line> per crease, y down), and a curved
pleat as FOLD (sine creases flattened here into segments, no faces) and as SVG (the same creases as
cubic Bezier paths, which the reader flattens)."""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def miura(columns=4, rows=3, a=1.0, b=1.0, shift=0.4):
    """Vertex (i, j) at (i a + (j odd) shift, j b): straight rows, zigzag columns."""
    index = lambda i, j: j * (columns + 1) + i
    coords = [[i * a + (j % 2) * shift, j * b] for j in range(rows + 1) for i in range(columns + 1)]
    edges, assignment = [], []
    for j in range(rows + 1):  # straight rows: border at the ends, M/V alternating inside
        for i in range(columns):
            edges.append([index(i, j), index(i + 1, j)])
            assignment.append("B" if j in (0, rows) else ("M" if (i + j) % 2 == 0 else "V"))
    for i in range(columns + 1):  # zigzag columns: border at the ends, one assignment per column
        for j in range(rows):
            edges.append([index(i, j), index(i, j + 1)])
            assignment.append("B" if i in (0, columns) else ("M" if i % 2 else "V"))
    faces = [[index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)]
             for j in range(rows) for i in range(columns)]
    return coords, edges, assignment, faces


def write_fold(name, coords, edges, assignment, angles=None, faces=None, comment=""):
    fold = {"file_spec": 1.1, "file_creator": "curvefold tests, make_patterns.py: " + comment,
            "vertices_coords": coords, "edges_vertices": edges, "edges_assignment": assignment}
    if angles is not None:
        fold["edges_foldAngle"] = angles
    if faces is not None:
        fold["faces_vertices"] = faces
    with open(os.path.join(HERE, name), "w") as out:
        json.dump(fold, out)
        out.write("\n")


COLOURS = {"B": "#000000", "M": "#ff0000", "V": "#0000ff", "F": "#ffff00"}


def main():
    coords, edges, assignment, faces = miura()
    write_fold("miura_ori.fold", coords, edges, assignment, faces=faces,
               comment="Miura-ori, 4 x 3 parallelograms")
    # 2 cm to a unit: a sheet of paper's size, as a drawing program states it.
    lines = ['<svg xmlns="http://www.w3.org/2000/svg" width="120mm" height="100mm" '
             'viewBox="-1 -4 6 5">']
    for (u, v), kind in zip(edges, assignment):
        (x1, y1), (x2, y2) = coords[u], coords[v]
        # y negated: the reader negates SVG's downward y, so both files give the same vertices.
        lines.append(f'<line x1="{x1}" y1="{-y1}" x2="{x2}" y2="{-y2}" stroke="{COLOURS[kind]}"/>')
    lines.append("</svg>")
    with open(os.path.join(HERE, "miura_ori.svg"), "w") as out:
        out.write("\n".join(lines) + "\n")

    # Curved pleat: width 4, height 4, three creases y = 1, 2, 3 + 0.3 sin(pi x / 4), M V M.
    width, height, amplitude, samples = 4.0, 4.0, 0.3, 16
    curve = lambda k, x: k + amplitude * math.sin(math.pi * x / width)
    coords = [[0, 0], [width, 0], [width, height], [0, height]]
    left, right = [0], [1]
    edges, assignment, angles = [], [], []
    for k in (1, 2, 3):
        kind, angle = ("M", -90.0) if k % 2 else ("V", 90.0)
        first = len(coords)
        for s in range(samples + 1):
            x = width * s / samples
            coords.append([x, curve(k, x)])
        for s in range(samples):
            edges.append([first + s, first + s + 1])
            assignment.append(kind)
            angles.append(angle)
        left.append(first)
        right.append(first + samples)
    left.append(3)
    right.append(2)
    for chain in (left, right):
        for u, v in zip(chain, chain[1:]):
            edges.append([u, v])
            assignment.append("B")
            angles.append(0.0)
    for u, v in ((0, 1), (2, 3)):
        edges.append([u, v])
        assignment.append("B")
        angles.append(0.0)
    write_fold("curved_pleat.fold", coords, edges, assignment, angles=angles,
               comment="curved pleat, sine creases in 16 segments each")
    # The same creases as one cubic each (a close fit of the half sine), at 50% opacity.
    paths = ['<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 -4 4 4">',
             f'<rect x="0" y="{-height}" width="{width}" height="{height}" stroke="black" fill="none"/>']
    for k in (1, 2, 3):
        colour = "#f00" if k % 2 else "#00f"
        # y = k + 0.3 sin(pi x / 4) with control points at heights k + 0.3 * 4/3 (a common fit).
        c = k + amplitude * 4.0 / 3.0
        paths.append(f'<path d="M0,{-k} C1.2,{-c} 2.8,{-c} 4,{-k}" stroke="{colour}" '
                     f'stroke-opacity="0.5" fill="none"/>')
    paths.append("</svg>")
    with open(os.path.join(HERE, "curved_pleat.svg"), "w") as out:
        out.write("\n".join(paths) + "\n")


if __name__ == "__main__":
    main()
