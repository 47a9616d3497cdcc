#!/usr/bin/env python3
"""Three crease patterns unlike the judge's (bench/make_judge_patterns.py) and Origami Simulator's
examples, for settling `curvefold simulate --settle` (issue 39, settle43). Plain Python.

    python3 bench/make_settle_patterns.py OUT_DIR

writes into OUT_DIR:
  fish_base.fold     the kite-based fish base (two kites, two rabbit ears), FOLD with traced faces,
                     M/V letters only (+-180 degrees);
  fan12.svg          a degree-12 flat vertex: twelve rays 30 degrees apart, seven mountains and five
                     valleys (Maekawa), a 200 mm square, SVG lines;
  parabola_pleats.svg  seven nested parabolic curved creases, alternating M/V, as SVG polylines of
                     48 segments, stroke-opacity 0.5 (90 degrees), no facet lines.
Each flat-foldable vertex is checked for Kawasaki's and Maekawa's conditions before writing.
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_judge_patterns import Graph, fold_file, svg_line, svg_open, f  # noqa: E402


def check_flat_foldable(graph):
    """Kawasaki (alternate sectors sum to pi) and Maekawa (|M - V| = 2) at every interior vertex
    whose creases are all M or V; raises on a violation."""
    around = {}
    for (a, b), kind in zip(graph.edges, graph.assignment):
        for u, v in ((a, b), (b, a)):
            around.setdefault(u, []).append((v, kind))
    for u, spokes in around.items():
        if any(k in "BC" for _, k in spokes):
            continue
        p = graph.vertices[u]
        angles = sorted((math.atan2(graph.vertices[v][1] - p[1], graph.vertices[v][0] - p[0]), k)
                        for v, k in spokes)
        sectors = [(angles[(i + 1) % len(angles)][0] - angles[i][0]) % (2 * math.pi)
                   for i in range(len(angles))]
        alt = sum(s if i % 2 == 0 else -s for i, s in enumerate(sectors))
        m = sum(1 for _, k in spokes if k == "M")
        v = sum(1 for _, k in spokes if k == "V")
        if abs(alt) > 1e-9 or abs(m - v) != 2:
            raise SystemExit(f"vertex {u} at {p}: Kawasaki {alt:.3g}, M {m} V {v}")


def fish_base():
    """Unit square A(0,0) B(1,0) C(1,1) D(0,1). Kite folds from A and C meet on the diagonal BD
    at E and F (the incentres of triangles ABC and ACD), the rabbit ears' ridges run E-B and F-D,
    and BD is creased through the centre O."""
    t = math.sqrt(2.0) - 1.0
    A, B, C, D = (0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)
    O = (0.5, 0.5)
    E = (1.0 / (1.0 + t), t / (1.0 + t))
    F = (E[1], E[0])
    g = Graph()
    for p, q in ((A, B), (B, C), (C, D), (D, A)):
        g.add(p, q, "B")
    for p, q, a in ((A, E, "V"), (C, E, "V"), (A, F, "V"), (C, F, "V"), (E, B, "M"), (F, D, "M"),
                    (E, O, "V"), (F, O, "V"), (A, O, "V"), (O, C, "M")):
        g.add(p, q, a)
    g.build()
    check_flat_foldable(g)
    return g


def fan12(size=200.0):
    """Twelve rays 30 degrees apart from the square's centre to its border."""
    h = size / 2.0
    g = Graph(tol=1e-7)
    corners = [(0, 0), (size, 0), (size, size), (0, size)]
    for k in range(4):
        g.add(corners[k], corners[(k + 1) % 4], "B")
    kinds = "MVMVMVMVMVMM"
    ends = []
    for k in range(12):
        a = math.radians(15.0 + 30.0 * k)  # no ray through a corner
        c, s = math.cos(a), math.sin(a)
        r = h / max(abs(c), abs(s))
        ends.append(((h + r * c, h + r * s), kinds[k]))
        g.add((h, h), (h + r * c, h + r * s), kinds[k])
    g.build()
    check_flat_foldable(g)
    return ends


def parabolas(size=200.0, count=7, segments=48):
    """Curves y = y0 + a x^2 over the square's width, spaced evenly, alternating M/V."""
    lines = []
    for k in range(count):
        y0 = size * (0.15 + 0.1 * k)
        a = 0.9 / size
        pts = []
        for i in range(segments + 1):
            x = size * i / segments
            pts.append((x, y0 - a * (x - size / 2) ** 2 + a * (size / 2) ** 2 * 0.5))
        lines.append((pts, "M" if k % 2 == 0 else "V"))
    return lines


def main(out):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "fish_base.fold"), "w") as fp:
        json.dump(fold_file(fish_base(), "fish base", unit="unit"), fp, indent=1)

    size = 200.0
    colour = {"M": "#ff0000", "V": "#0000ff", "B": "#000000"}
    svg = svg_open("200mm", "200mm", "0 0 200 200")
    svg += f'<rect x="0" y="0" width="{f(size)}" height="{f(size)}" fill="none" stroke="#000"/>\n'
    for end, kind in fan12(size):
        svg += svg_line((size / 2, size / 2), end, f'stroke="{colour[kind]}"')
    with open(os.path.join(out, "fan12.svg"), "w") as fp:
        fp.write(svg + "</svg>\n")

    svg = svg_open("200mm", "200mm", "0 0 200 200")
    svg += f'<rect x="0" y="0" width="{f(size)}" height="{f(size)}" fill="none" stroke="#000"/>\n'
    for pts, kind in parabolas(size):
        inside = [p for p in pts if 0.0 <= p[1] <= size]
        text = " ".join(f"{f(x)},{f(y)}" for x, y in inside)
        svg += (f'<polyline points="{text}" fill="none" stroke="{colour[kind]}" '
                'stroke-opacity="0.5"/>\n')
    with open(os.path.join(out, "parabola_pleats.svg"), "w") as fp:
        fp.write(svg + "</svg>\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_settle_patterns.py OUT_DIR")
    main(sys.argv[1])
