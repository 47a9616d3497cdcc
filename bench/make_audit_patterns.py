#!/usr/bin/env python3
"""Crease patterns an independent judge would bring to `curvefold simulate` (issue 39, audit39).

Made differently from bench/make_judge_patterns.py and bench/make_settle_patterns.py: random
flat-foldable single vertices (Kawasaki by construction, mountain/valley by crimping the smallest
sector, so Maekawa and big-little-big hold) on random convex paper, written as FOLD with polygon
faces and frame metadata; a generalized Miura-ori (rows of different zigzag slopes, columns of
different widths, quad faces); a Miura-ori of 60-degree-ish parallelograms drawn as an SVG inside
a rotated and scaled group (for the closed-form rigid motion); a Yoshimura pattern of
non-equilateral triangles styled by CSS classes; many concentric curved pleats as SVG circles with
opacity angles; a slanted single crease on a pentagon; a flat sheet in a tilted 3D plane; and
malformed files (crossings without a vertex, an edge with no face, NaN, infinity, counts past
the stated limits, and smaller faults). Plain Python, deterministic (seeded).

    python3 bench/make_audit_patterns.py OUT_DIR

writes OUT_DIR/good/*.{fold,svg}, OUT_DIR/bad/*.{fold,svg} and OUT_DIR/facts.json (what the
runner checks: single-crease angles, the Miura's cell).
"""

import json
import math
import os
import random
import sys


def crimp_assignment(sectors, rng):
    """A valid flat-folding M/V assignment of a flat-foldable vertex: crimp a strict local minimum
    sector (its two creases opposite) until two creases remain (the same)."""
    n = len(sectors)
    ids = list(range(n))  # crease ids[i] starts sector i
    sec = list(sectors)
    out = {}
    while len(sec) > 2:
        k = len(sec)
        cands = [i for i in range(k) if sec[i] < sec[i - 1] - 1e-9 and sec[i] < sec[(i + 1) % k] - 1e-9]
        if not cands:  # equal sectors (not from kawasaki_sectors' random ones): crimp a smallest
            cands = [min(range(k), key=lambda i: sec[i])]
        i = rng.choice(cands)
        a, b = ids[i], ids[(i + 1) % k]
        x = rng.choice("MV")
        out[a], out[b] = x, ("V" if x == "M" else "M")
        merged = sec[i - 1] - sec[i] + sec[(i + 1) % k]
        # remove sector i and i+1, sector i-1 becomes merged; creases a and b go
        j = (i + 1) % k
        keep = [t for t in range(k) if t not in (i, j)]
        new_sec, new_ids = [], []
        for t in keep:
            new_sec.append(merged if t == (i - 1) % k else sec[t])
            new_ids.append(ids[t])
        sec, ids = new_sec, new_ids
    x = rng.choice("MV")
    out[ids[0]] = out[ids[1]] = x
    return [out[i] for i in range(n)]


def kawasaki_sectors(degree, rng):
    """Random sector angles (radians) whose alternate sums are both pi, none under 12 degrees."""
    half = degree // 2
    while True:
        odd = [rng.uniform(0.3, 1.0) for _ in range(half)]
        even = [rng.uniform(0.3, 1.0) for _ in range(half)]
        so, se = sum(odd), sum(even)
        odd = [math.pi * v / so for v in odd]
        even = [math.pi * v / se for v in even]
        sec = [v for pair in zip(odd, even) for v in pair]
        if min(sec) > math.radians(12):
            return sec


def ray_polygon(c, d, poly):
    """First hit of ray c + t d (t > 0) on the polygon's boundary: (t, side index, u on side)."""
    best = None
    for i in range(len(poly)):
        p, q = poly[i], poly[(i + 1) % len(poly)]
        e = (q[0] - p[0], q[1] - p[1])
        den = d[0] * e[1] - d[1] * e[0]
        if abs(den) < 1e-15:
            continue
        w = (p[0] - c[0], p[1] - c[1])
        t = (w[0] * e[1] - w[1] * e[0]) / den
        u = (w[0] * d[1] - w[1] * d[0]) / den
        if t > 1e-12 and -1e-12 <= u <= 1 + 1e-12 and (best is None or t < best[0]):
            best = (t, i, u)
    return best


def single_vertex(degree, seed):
    """A flat-foldable vertex off centre on a random convex heptagon: FOLD with polygon faces,
    frame metadata and a (ignored) folded frame in file_frames."""
    rng = random.Random(seed)
    m = 7
    poly = []
    for k in range(m):
        a = 2 * math.pi * (k + rng.uniform(-0.3, 0.3)) / m
        r = rng.uniform(0.09, 0.12)  # metres
        poly.append((r * math.cos(a), r * math.sin(a)))
    c = (rng.uniform(-0.015, 0.015), rng.uniform(-0.015, 0.015))
    sec = kawasaki_sectors(degree, rng)
    mv = crimp_assignment(sec, rng)
    start = rng.uniform(0, 2 * math.pi)
    dirs, a = [], start
    for s in sec:
        dirs.append((math.cos(a), math.sin(a)))
        a += s
    # boundary points: polygon corners and ray hits, walked counter-clockwise
    hits = []
    for r, d in enumerate(dirs):
        t, side, u = ray_polygon(c, d, poly)
        hits.append((side, u, r, (c[0] + t * d[0], c[1] + t * d[1])))
    verts = [list(c)]
    ring = []  # (vertex index, ray index or None)
    for side in range(m):
        verts.append(list(poly[side]))
        ring.append((len(verts) - 1, None))
        for h in sorted([h for h in hits if h[0] == side], key=lambda h: h[1]):
            verts.append(list(h[3]))
            ring.append((len(verts) - 1, h[2]))
    edges, assign, angle = [], [], []
    for k in range(len(ring)):
        edges.append([ring[k][0], ring[(k + 1) % len(ring)][0]])
        assign.append("B")
        angle.append(0)
    for k, (v, r) in enumerate(ring):
        if r is not None:
            edges.append([0, v])
            assign.append(mv[r])
            angle.append(-180 if mv[r] == "M" else 180)
    # faces: the centre, then the ring from one ray's end to the next (polygons, not triangles)
    ray_pos = [k for k, (v, r) in enumerate(ring) if r is not None]
    faces = []
    for n in range(len(ray_pos)):
        a0, a1 = ray_pos[n], ray_pos[(n + 1) % len(ray_pos)]
        f = [0]
        k = a0
        while True:
            f.append(ring[k][0])
            if k == a1:
                break
            k = (k + 1) % len(ring)
        faces.append(f)
    # every other crease's angle left null: Origami Simulator's default
    angle = [None if (i % 3 == 2 and assign[i] in "MV") else angle[i] for i in range(len(angle))]
    folded = [[x, y, 0.01 * (i % 2)] for i, (x, y) in enumerate(verts)]
    return {
        "file_spec": 1.1,
        "file_creator": "audit39 make_audit_patterns.py",
        "file_classes": ["singleModel"],
        "frame_title": f"flat-foldable degree {degree}",
        "frame_classes": ["creasePattern"],
        "frame_attributes": ["2D"],
        "frame_unit": "m",
        "vertices_coords": verts,
        "edges_vertices": edges,
        "edges_assignment": assign,
        "edges_foldAngle": angle,
        "faces_vertices": faces,
        "file_frames": [{"frame_classes": ["foldedForm"], "frame_inherit": True,
                         "frame_parent": 0, "vertices_coords": folded}],
    }


def generalized_miura(seed, cols=7, rows=5):
    """Straight columns of random widths, zigzag rows of random slopes (each vertex's slopes equal
    and opposite, so Kawasaki holds), rows alternating M/V; quad faces; mm."""
    rng = random.Random(seed)
    widths = [rng.uniform(18, 30) for _ in range(cols)]
    xs = [0.0]
    for w in widths:
        xs.append(xs[-1] + w)
    height = 40.0
    zig = []
    for j in range(1, rows):
        s = rng.uniform(0.25, 0.6) * (1 if j % 2 else 0.8)
        y = [j * height]
        for i in range(cols):
            y.append(y[-1] + (s if i % 2 == 0 else -s) * widths[i])
        zig.append(y)
    top = rows * height + 15
    lines = [[(x, -15.0) for x in xs]] + [[(xs[i], y[i]) for i in range(cols + 1)] for y in zig] + \
        [[(x, top) for x in xs]]
    verts, index = [], {}
    for r, line in enumerate(lines):
        for i, p in enumerate(line):
            index[(r, i)] = len(verts)
            verts.append([round(p[0], 9), round(p[1], 9)])
    edges, assign, angle = [], [], []

    def edge(a, b, x, ang):
        edges.append([a, b])
        assign.append(x)
        angle.append(ang)

    nl = len(lines)
    for r in range(nl):
        for i in range(cols):
            border = r in (0, nl - 1)
            x = "B" if border else ("M" if r % 2 else "V")
            edge(index[(r, i)], index[(r, i + 1)], x, 0 if border else (-180 if x == "M" else 180))
    for r in range(nl - 1):
        for i in range(cols + 1):
            if i in (0, cols):
                edge(index[(r, i)], index[(r + 1, i)], "B", 0)
                continue
            # the vertical crease between row line r and r+1: below a local minimum of row r+1
            # it is the one that differs from the row (checked by Maekawa below)
            lower_is_min = (i % 2 == 0)  # row slopes go up then down from x0: x_i even is a min
            row_above = r + 1
            if row_above < nl - 1:
                xrow = "M" if row_above % 2 else "V"
                x = ("V" if xrow == "M" else "M") if not lower_is_min else xrow
            else:
                xrow = "M" if r % 2 else "V"
                x = ("V" if xrow == "M" else "M") if lower_is_min else xrow
            edge(index[(r, i)], index[(r + 1, i)], x, -180 if x == "M" else 180)
    faces = []
    for r in range(nl - 1):
        for i in range(cols):
            faces.append([index[(r, i)], index[(r, i + 1)], index[(r + 1, i + 1)], index[(r + 1, i)]])
    check_maekawa(verts, edges, assign)
    return {"file_spec": 1.2, "file_creator": "audit39", "frame_unit": "mm",
            "frame_title": "generalized Miura", "vertices_coords": verts, "edges_vertices": edges,
            "edges_assignment": assign, "edges_foldAngle": angle, "faces_vertices": faces}


def check_maekawa(verts, edges, assign):
    """Every interior vertex: |M - V| == 2 and Kawasaki's alternate sums equal."""
    around = {}
    for (a, b), x in zip(edges, assign):
        around.setdefault(a, []).append((b, x))
        around.setdefault(b, []).append((a, x))
    for v, nb in around.items():
        if any(x == "B" for _, x in nb):
            continue
        m = sum(1 for _, x in nb if x == "M")
        vv = sum(1 for _, x in nb if x == "V")
        assert abs(m - vv) == 2, (v, m, vv)
        ang = sorted(math.atan2(verts[b][1] - verts[v][1], verts[b][0] - verts[v][0]) for b, _ in nb)
        sec = [(ang[(k + 1) % len(ang)] - ang[k]) % (2 * math.pi) for k in range(len(ang))]
        assert abs(sum(sec[0::2]) - math.pi) < 1e-9, (v, sec)


def miura_svg(cols=8, rows=5, w=10.0, h=15.0, d=6.0):
    """A plain Miura-ori (column lines straight, rows zigzag by d) drawn in a group rotated 30
    degrees and scaled 2, creases as path elements with relative commands, mountains as
    #F00 and valleys as rgb(0, 0, 255)."""
    def p(i, j):
        return (i * w, j * h + (d if i % 2 else 0.0))

    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="400mm" height="400mm" viewBox="-200 -200 400 400">',
           '<g transform="rotate(30) scale(2) translate(-40,-40)">']
    border = [p(i, 0) for i in range(cols + 1)] + [p(cols, j) for j in range(1, rows + 1)] + \
        [p(i, rows) for i in range(cols - 1, -1, -1)] + [p(0, j) for j in range(rows - 1, 0, -1)]
    out.append('<polygon fill="none" stroke="black" points="' +
               " ".join(f"{x:.6f},{y:.6f}" for x, y in border) + '"/>')
    # zigzag rows: one path each, relative lines; rows alternate M/V
    for j in range(1, rows):
        col = "#F00" if j % 2 else "rgb(0, 0, 255)"
        x0, y0 = p(0, j)
        seg = " ".join(f"l{w:.6f},{(d if i % 2 == 0 else -d):.6f}" for i in range(cols))
        out.append(f'<path fill="none" stroke="{col}" d="M{x0:.6f},{y0:.6f} {seg}"/>')
    # column segments: at a zigzag minimum (even i) the segment above differs from the row above
    for i in range(1, cols):
        for j in range(rows):
            row_above = j + 1
            if row_above < rows:
                xrow = "M" if row_above % 2 else "V"
                x = xrow if i % 2 == 0 else ("V" if xrow == "M" else "M")
            else:
                xrow = "M" if j % 2 else "V"
                x = xrow if i % 2 == 1 else ("V" if xrow == "M" else "M")
            # SVG's y points down: i even is then a maximum seen from +z; the mirror flips M/V
            # consistently, so the pattern stays flat-foldable
            col = "#F00" if x == "M" else "rgb(0, 0, 255)"
            (ax, ay), (bx, by) = p(i, j), p(i, j + 1)
            out.append(f'<path fill="none" stroke="{col}" d="M {ax:.6f} {ay:.6f} v {by - ay:.6f}"/>')
    out.append("</g></svg>")
    return "\n".join(out)


def yoshimura_svg(cols=6, rows=4, w=30.0, hh=14.0):
    """Yoshimura: horizontal valleys, diagonal mountains, triangles of base w and height hh (not
    equilateral); colours from a CSS <style>, lines as polylines."""
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{cols * w}mm" height="{rows * hh}mm" '
           f'viewBox="0 0 {cols * w} {rows * hh}">',
           "<style>.m{stroke:#ff0000} .v{stroke:#0000ff;stroke-opacity:0.8} polygon{stroke:#000}</style>"]
    W, H = cols * w, rows * hh
    out.append(f'<polygon fill="none" points="0,0 {W},0 {W},{H} 0,{H}"/>')
    for j in range(1, rows):
        out.append(f'<polyline class="v" fill="none" points="0,{j * hh} {W},{j * hh}"/>')
    for j in range(rows):
        off = 0.0 if j % 2 == 0 else w / 2
        y0, y1 = j * hh, (j + 1) * hh
        # zigzag between row lines j and j+1, clipped to the sheet at the ends
        pts = []
        x = -off
        up = True
        while x <= W + 1e-9:
            pts.append((x, y0 if up else y1))
            x += w / 2
            up = not up
        # clip first and last segments to [0, W]
        clipped = []
        for (ax, ay), (bx, by) in zip(pts, pts[1:]):
            if bx <= 0 or ax >= W:
                continue
            if ax < 0:
                ay = ay + (by - ay) * (0 - ax) / (bx - ax)
                ax = 0.0
            if bx > W:
                by = ay + (by - ay) * (W - ax) / (bx - ax)
                bx = W
            clipped.append((ax, ay, bx, by))
        line = [(clipped[0][0], clipped[0][1])] + [(c[2], c[3]) for c in clipped]
        out.append('<polyline class="m" fill="none" points="' +
                   " ".join(f"{x:.6f},{y:.6f}" for x, y in line) + '"/>')
    out.append("</svg>")
    return "\n".join(out)


def ring_pleats_svg(rings=18, size=200.0):
    """Concentric circular pleats (circle elements, alternating M/V at opacity 0.35: 63 degrees)
    around a cut hole (green circle), on a square sheet; SVG with no size: user units as px."""
    c = size / 2
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {size} {size}">',
           f'<rect x="0" y="0" width="{size}" height="{size}" fill="none" stroke="#000000"/>',
           f'<circle cx="{c}" cy="{c}" r="8" fill="none" stroke="#00ff00"/>']
    for k in range(rings):
        r = 12 + k * (c - 16) / rings
        col = "red" if k % 2 else "blue"
        out.append(f'<circle cx="{c}" cy="{c}" r="{r:.4f}" fill="none" stroke="{col}" opacity="0.35"/>')
    out.append("</svg>")
    return "\n".join(out)


def slanted_crease_fold(angle_deg):
    """One straight crease across a pentagon at a slant, target angle given, in cm."""
    pent = [(10 * math.cos(2 * math.pi * k / 5 + 0.3), 10 * math.sin(2 * math.pi * k / 5 + 0.3)) for k in range(5)]
    # crease from the middle of side 0 to the middle of side 2
    a = ((pent[0][0] + pent[1][0]) / 2, (pent[0][1] + pent[1][1]) / 2)
    b = ((pent[2][0] + pent[3][0]) / 2, (pent[2][1] + pent[3][1]) / 2)
    verts = [list(pent[0]), list(a), list(pent[1]), list(pent[2]), list(b), list(pent[3]), list(pent[4])]
    edges = [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 6], [6, 0], [1, 4]]
    assign = ["B"] * 7 + ["M" if angle_deg < 0 else "V"]
    return {"file_spec": 1.1, "frame_unit": "cm", "vertices_coords": verts, "edges_vertices": edges,
            "edges_assignment": assign, "edges_foldAngle": [0] * 7 + [angle_deg]}


def slanted_crease_svg(opacity):
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="150mm" height="100mm" viewBox="0 0 150 100">'
            '<polygon points="0,0 150,0 150,100 0,100" fill="none" stroke="black"/>'
            f'<line x1="20" y1="0" x2="110" y2="100" style="stroke:#0000ff;stroke-opacity:{opacity}"/></svg>')


def tilted_plane_fold():
    """A unit square with a diagonal valley, its vertices in a plane tilted about x (flat, but no
    coordinate constant)."""
    t = math.radians(35)
    sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    verts = [[x, y * math.cos(t), y * math.sin(t)] for x, y in sq]
    return {"vertices_coords": verts, "edges_vertices": [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]],
            "edges_assignment": ["B", "B", "B", "B", "V"], "edges_foldAngle": [0, 0, 0, 0, 90]}


def square(extra_v=(), extra_e=(), extra_a=()):
    v = [[0, 0], [1, 0], [1, 1], [0, 1]] + [list(p) for p in extra_v]
    e = [[0, 1], [1, 2], [2, 3], [3, 0]] + [list(p) for p in extra_e]
    a = ["B"] * 4 + list(extra_a)
    return {"vertices_coords": v, "edges_vertices": e, "edges_assignment": a}


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def main(out):
    good, bad = os.path.join(out, "good"), os.path.join(out, "bad")
    os.makedirs(good, exist_ok=True)
    os.makedirs(bad, exist_ok=True)
    facts = {"single": {}, "miura": {}}
    for degree, seed in ((4, 1), (4, 7), (6, 2), (6, 11), (8, 3), (10, 5)):
        write(os.path.join(good, f"vertex{degree}_s{seed}.fold"), json.dumps(single_vertex(degree, seed)))
    write(os.path.join(good, "gen_miura.fold"), json.dumps(generalized_miura(4)))
    write(os.path.join(good, "miura60.svg"), miura_svg())
    facts["miura"]["miura60.svg"] = {"cols": 8, "rows": 5, "w": 10.0, "h": 15.0, "d": 6.0}
    write(os.path.join(good, "yoshimura.svg"), yoshimura_svg())
    write(os.path.join(good, "ring_pleats.svg"), ring_pleats_svg())
    write(os.path.join(good, "crease73.fold"), json.dumps(slanted_crease_fold(73.0)))
    facts["single"]["crease73.fold"] = 73.0
    write(os.path.join(good, "crease_m131.fold"), json.dumps(slanted_crease_fold(-131.0)))
    facts["single"]["crease_m131.fold"] = 131.0
    write(os.path.join(good, "crease_svg037.svg"), slanted_crease_svg(0.37))
    facts["single"]["crease_svg037.svg"] = 0.37 * 180
    write(os.path.join(good, "tilted_plane.fold"), json.dumps(tilted_plane_fold()))

    # malformed
    write(os.path.join(bad, "crossing.fold"), json.dumps(square(extra_e=[[0, 2], [1, 3]], extra_a=["M", "V"])))
    write(os.path.join(bad, "dangling.fold"),
          json.dumps(square(extra_v=[[1.5, 0.5]], extra_e=[[1, 4]], extra_a=["M"])))
    write(os.path.join(bad, "outside_edge.fold"),
          json.dumps(square(extra_v=[[2, 0], [2, 1]], extra_e=[[4, 5]], extra_a=["V"])))
    write(os.path.join(bad, "nan.fold"), json.dumps(square(extra_v=[[float("nan"), 0.5]])))
    write(os.path.join(bad, "inf.fold"), json.dumps(square()).replace("[1, 1]", "[1e400, 1]"))
    write(os.path.join(bad, "nan.svg"),
          '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="10" height="10" '
          'fill="none" stroke="black"/><line x1="NaN" y1="0" x2="10" y2="10" stroke="red"/></svg>')
    write(os.path.join(bad, "nan_opacity.svg"),
          '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="10" height="10" '
          'fill="none" stroke="black"/><line x1="0" y1="0" x2="10" y2="10" stroke="red" opacity="nan"/></svg>')
    write(os.path.join(bad, "crossing.svg"),  # an SVG crossing is split, as Origami Simulator does: good
          '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="10" height="10" '
          'fill="none" stroke="black"/><line x1="0" y1="0" x2="10" y2="10" stroke="red"/>'
          '<line x1="10" y1="0" x2="0" y2="10" stroke="blue"/></svg>')
    n = 1_000_001
    with open(os.path.join(bad, "huge_vertices.fold"), "w") as f:
        f.write('{"vertices_coords": [' + ",".join(["[0,0]"] * n) +
                '], "edges_vertices": [[0,1]], "edges_assignment": ["B"]}')
    with open(os.path.join(bad, "huge_segments.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="10" height="10" '
                'fill="none" stroke="black"/><path stroke="red" d="M0 0 ' + "l0 0 " * 3_100_000 + '"/></svg>')
    sq = square()
    sq["faces_vertices"] = [[0, 1, 2, 7]]
    write(os.path.join(bad, "face_out_of_range.fold"), json.dumps(sq))
    write(os.path.join(bad, "self_loop.fold"), json.dumps(square(extra_e=[[2, 2]], extra_a=["M"])))
    write(os.path.join(bad, "short_assignment.fold"),
          json.dumps({"vertices_coords": [[0, 0], [1, 0], [1, 1]], "edges_vertices": [[0, 1], [1, 2], [2, 0]],
                      "edges_assignment": ["B", "B"]}))
    write(os.path.join(bad, "empty.fold"), "")
    write(os.path.join(bad, "truncated.fold"), json.dumps(square())[:-7])
    write(os.path.join(bad, "no_creases.svg"),
          '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><text>hi</text></svg>')
    write(os.path.join(bad, "bent.fold"), json.dumps({
        "vertices_coords": [[0, 0, 0], [1, 0, 0], [1, 1, 0.3], [0, 1, 0]],
        "edges_vertices": [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]],
        "edges_assignment": ["B", "B", "B", "B", "V"]}))
    write(os.path.join(bad, "through_vertex.fold"),
          json.dumps(square(extra_v=[[0.5, 0.5]], extra_e=[[0, 2]], extra_a=["V"])))
    write(os.path.join(bad, "duplicate_edge.fold"),
          json.dumps(square(extra_e=[[0, 2], [2, 0]], extra_a=["V", "M"])))
    write(os.path.join(bad, "zero_length.fold"),
          json.dumps(square(extra_v=[[0, 0]], extra_e=[[0, 4]], extra_a=["V"])))
    write(os.path.join(bad, "tjunction.fold"), json.dumps({
        "vertices_coords": [[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]],
        "edges_vertices": [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2], [4, 1]],
        "edges_assignment": ["B", "B", "B", "B", "V", "M"]}))
    # 32 paths of 500 kB: each attribute under libxml2's 10 MB, 16 MB in all
    with open(os.path.join(bad, "huge_paths.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="10" '
                'height="10" fill="none" stroke="black"/>')
        for _ in range(32):
            f.write('<path stroke="red" d="M0 0 ' + "l0 0 " * 100_000 + '"/>')
        f.write("</svg>")
    # not malformed: 12 MB of short lines, past libxml2's 10 MB read-ahead but in small pieces
    with open(os.path.join(bad, "big_lines.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">\n<rect width="10" '
                'height="10" fill="none" stroke="black"/>\n')
        while f.tell() < 12_000_000:
            f.write('<line x1="1" y1="1" x2="1.000001" y2="1" stroke="#ff0000" stroke-width="0.1"/>\n')
        f.write("</svg>\n")
    with open(os.path.join(out, "facts.json"), "w") as f:
        json.dump(facts, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1])
