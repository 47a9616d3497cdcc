#!/usr/bin/env python3
"""Ring-shaped curved-crease patterns drawn as SVG shapes (not polylines), for settling
`curvefold simulate --settle` on closed and open curved creases (issue 39, settle24). Plain Python;
written independently of bench/make_judge_patterns.py and bench/make_settle_patterns.py.

    python3 bench/make_ring_patterns.py OUT_DIR

writes into OUT_DIR, each a square sheet in millimetres (width/height in mm, viewBox in mm) with
a black <rect> border, stroke colours in the forms other tools use (#f00, rgb(0,0,255), red,
blue), and the fold angle as stroke-opacity (1 is 180 degrees):
  rings_circle_K_ANGLE_SIZE.svg  K concentric <circle> creases, alternating valley/mountain from
                     the innermost, on a SIZE mm square, all at ANGLE degrees (K 1-3,
                     ANGLE 60 or 90, SIZE 60 or 100);
  rings_ellipse.svg  three concentric <ellipse> creases (axes 2:1.4), valley/mountain/valley;
  rings_arcs.svg     two concentric rings, each drawn as two half-circle <path> arcs (A commands,
                     relative and absolute), inner valley, outer mountain;
  rings_scaled.svg   two circles inside a <g transform="translate() scale()">, a 0.5 opacity style
                     attribute instead of stroke-opacity;
  rings_pleat_hole.svg  four alternating rings around a green <circle> cut, the circular pleat
                     with its middle cut free (read as Origami Simulator reads a closed cut: the
                     inside stays paper, a loose disc).
"""

import math
import os
import sys

COLOURS = {"V": ["#00f", "rgb(0,0,255)", "blue"], "M": ["#f00", "rgb(255,0,0)", "red"]}


def header(size):
    return (f'<?xml version="1.0"?>\n<svg xmlns="http://www.w3.org/2000/svg" '
            f'width="{size}mm" height="{size}mm" viewBox="0 0 {size} {size}">\n'
            f'  <rect x="0" y="0" width="{size}" height="{size}" fill="none" stroke="black"/>\n')


def colour(kind, k):
    names = COLOURS[kind]
    return names[k % len(names)]


def circles(count, angle, size):
    out = [header(size)]
    c = size / 2
    for k in range(count):
        r = size * (0.12 + 0.3 * (k + 1) / (count + 1))
        kind = "V" if k % 2 == 0 else "M"
        out.append(f'  <circle cx="{c:g}" cy="{c:g}" r="{r:.4f}" fill="none" '
                   f'stroke="{colour(kind, k)}" stroke-opacity="{angle / 180:.6f}"/>\n')
    out.append("</svg>\n")
    return "".join(out)


def ellipses(size=80, angle=90):
    out = [header(size)]
    c = size / 2
    for k in range(3):
        rx = size * (0.14 + 0.11 * k)
        ry = rx * 0.7
        kind = "V" if k % 2 == 0 else "M"
        out.append(f'  <ellipse cx="{c:g}" cy="{c:g}" rx="{rx:.4f}" ry="{ry:.4f}" '
                   f'style="fill:none;stroke:{colour(kind, k)};stroke-opacity:{angle / 180:.4f}"/>\n')
    out.append("</svg>\n")
    return "".join(out)


def arcs(size=70, angle=80):
    out = [header(size)]
    c = size / 2
    for k, r in enumerate((size * 0.2, size * 0.35)):
        kind = "V" if k == 0 else "M"
        # two half arcs: the first absolute, the second relative
        d = (f"M {c - r:.4f} {c:.4f} A {r:.4f} {r:.4f} 0 0 1 {c + r:.4f} {c:.4f} "
             f"a {r:.4f} {r:.4f} 0 0 1 {-2 * r:.4f} 0 Z")
        out.append(f'  <path d="{d}" fill="none" stroke="{colour(kind, k + 1)}" '
                   f'stroke-opacity="{angle / 180:.4f}"/>\n')
    out.append("</svg>\n")
    return "".join(out)


def scaled(size=50):
    out = [header(size)]
    out.append(f'  <g transform="translate({size / 2:g} {size / 2:g}) scale(0.5)">\n')
    for k, r in enumerate((size * 0.3, size * 0.7)):
        kind = "V" if k == 0 else "M"
        out.append(f'    <circle r="{r:.4f}" fill="none" stroke="{colour(kind, 2)}" '
                   f'style="opacity:0.5"/>\n')
    out.append("  </g>\n</svg>\n")
    return "".join(out)


def pleat_hole(size=90, angle=70):
    out = [header(size)]
    c = size / 2
    out.append(f'  <circle cx="{c:g}" cy="{c:g}" r="{size * 0.08:.4f}" fill="none" '
               f'stroke="#0f0"/>\n')
    for k in range(4):
        r = size * (0.14 + 0.075 * k)
        kind = "V" if k % 2 == 0 else "M"
        out.append(f'  <circle cx="{c:g}" cy="{c:g}" r="{r:.4f}" fill="none" '
                   f'stroke="{colour(kind, k)}" stroke-opacity="{angle / 180:.4f}"/>\n')
    out.append("</svg>\n")
    return "".join(out)


def main(out):
    os.makedirs(out, exist_ok=True)
    files = {}
    for count in (1, 2, 3):
        for angle in (60, 90):
            for size in (60, 100):
                files[f"rings_circle_{count}_{angle}_{size}.svg"] = circles(count, angle, size)
    files["rings_ellipse.svg"] = ellipses()
    files["rings_arcs.svg"] = arcs()
    files["rings_scaled.svg"] = scaled()
    files["rings_pleat_hole.svg"] = pleat_hole()
    for name, text in files.items():
        with open(os.path.join(out, name), "w") as handle:
            handle.write(text)
    print(f"wrote {len(files)} files to {out}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
