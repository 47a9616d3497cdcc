#!/usr/bin/env python3
"""Smooth targets as a designer's CAD or print tool hands them over: STL, converted to OBJ by a
plain facet-by-facet converter (issue 38, 2; lamp25). numpy only; deterministic per seed.

Unlike every other bench/make_*.py (which write OBJ with shared vertices, consistently wound,
in metres or millimetres), each target here is first written as an STL (binary or ASCII, the
format drawn), its coordinates rounded to 32-bit floats as STL stores them, then turned into an
OBJ the way a naive converter does it: every facet its own three `v` lines (a triangle soup: no
vertex shared, every edge a boundary edge of the file), `vn` lines from the facet normals and
faces `f a//n b//n c//n`. On some targets a share of the facets is wound the other way (an STL
whose normals disagree with its winding, as a repaired or merged model has), and units are
inches, centimetres or millimetres (set per target, not metres). Shapes are closed formulas:
the tubes lathed as rings whose vertex count doubles past 0.55 of the widest radius (2:1 bands,
no T-junction), the dishes, the bowl and the saddle as rings about a centre whose count grows
with the radius, merged by angle; the axis a uniform random direction, moved off the origin:

  lamp_bulge      a lampshade with a bulge: r(t) = r0 + (r1 - r0) t + b sin(pi t)^2, open at top
                  and bottom;
  bell            a bell: a closed crown, a waist and a flaring lip (r(t) from a tanh flare);
  dish            a shallow dish: z = d (rho / R)^2.4, 10-20x wider than deep, closed;
  oval_bowl       a bowl with an oval rim: a cap of an ellipsoid (semi-axes a > b, depth c);
  open_vase       a vase open at top and bottom: a belly and a neck (a sum of Gaussians);
  saddle          z = k (x^2 - q y^2) over a disk, as a tile a designer draws.

Usage: bench/make_stl_soup_targets.py OUTDIR [--seed S]
Writes OUTDIR/NAME.stl and OUTDIR/NAME.obj per target and OUTDIR/targets.tsv (name, kind a
designer would name, unit, scale to metres, flipped share, description).
"""
import argparse
import math
import os
import struct

import numpy as np

UNITS = {"in": 0.0254, "cm": 0.01, "mm": 0.001}


def random_axis_frame(rng):
    """A rotation taking +z (the lathe's axis) to a uniform random direction."""
    a = rng.normal(size=3)
    a /= np.linalg.norm(a)
    helper = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(a, helper)
    u /= np.linalg.norm(u)
    v = np.cross(a, u)
    spin = rng.uniform(0, 2 * math.pi)
    u, v = math.cos(spin) * u + math.sin(spin) * v, -math.sin(spin) * u + math.cos(spin) * v
    return np.stack([u, v, a], axis=1)  # columns: local x, y, z in world


def lathe(profile, rows, base_count, close_bottom=False):
    """Rings of (radius, height) along t in [0, 1]; ring vertex counts double where the ring's
    circumference passes twice the base spacing (and halve back), joined without T-junctions."""
    ts = np.linspace(0.0, 1.0, rows)
    prof = [profile(t) for t in ts]
    rmax = max(r for r, _ in prof)
    rings = []  # list of (count, array of points)
    for r, z in prof:
        count = base_count if r < 0.55 * rmax else 2 * base_count
        phi = np.arange(count) * 2 * math.pi / count
        rings.append(np.stack([r * np.cos(phi), r * np.sin(phi), np.full(count, z)], axis=1))
    tris = []
    for lower, upper in zip(rings[:-1], rings[1:]):
        n0, n1 = len(lower), len(upper)
        if n0 == n1:
            for i in range(n0):
                j = (i + 1) % n0
                tris.append((lower[i], lower[j], upper[j]))
                tris.append((lower[i], upper[j], upper[i]))
        elif n1 == 2 * n0:
            for i in range(n0):
                j = (i + 1) % n0
                a, m, b = upper[2 * i], upper[2 * i + 1], upper[(2 * i + 2) % n1]
                tris.append((lower[i], m, a))
                tris.append((lower[i], lower[j], m))
                tris.append((lower[j], b, m))
        elif n0 == 2 * n1:
            for i in range(n1):
                j = (i + 1) % n1
                a, m, b = lower[2 * i], lower[2 * i + 1], lower[(2 * i + 2) % n0]
                tris.append((a, m, upper[i]))
                tris.append((m, upper[j], upper[i]))
                tris.append((m, b, upper[j]))
        else:
            raise ValueError("rings must keep or double their count")
    if close_bottom:
        centre = np.array([0.0, 0.0, prof[0][1]])
        ring = rings[0]
        for i in range(len(ring)):
            tris.append((centre, ring[(i + 1) % len(ring)], ring[i]))
    return np.array(tris)  # (n, 3, 3)


def disk_height(height, radius, rings, base_count):
    """A disk z = height(x, y) meshed as lathe rings from the centre (the first ring a fan)."""
    tris = []
    prev = None
    for k in range(1, rings + 1):
        rho = radius * k / rings
        count = base_count * k
        phi = np.arange(count) * 2 * math.pi / count
        x, y = rho * np.cos(phi), rho * np.sin(phi)
        ring = np.stack([x, y, height(x, y)], axis=1)
        if prev is None:
            c = np.array([0.0, 0.0, height(np.array(0.0), np.array(0.0))])
            for i in range(count):
                tris.append((c, ring[i], ring[(i + 1) % count]))
        else:
            # Ring k - 1 has base * (k - 1) vertices, ring k base * k: merge by angle.
            i = j = 0
            n0, n1 = len(prev), count
            while i < n0 or j < n1:
                a0 = (i + 0.5) / n0 if i < n0 else 2.0
                a1 = (j + 0.5) / n1 if j < n1 else 2.0
                if a1 <= a0:
                    tris.append((prev[i % n0], ring[j % n1], ring[(j + 1) % n1]))
                    j += 1
                else:
                    tris.append((prev[i % n0], ring[(j) % n1], prev[(i + 1) % n0]))
                    i += 1
        prev = ring
    return np.array(tris)


def place(tris, rng, scale_m, unit):
    """Rotate to a random axis, move off the origin, and write in `unit` as float32."""
    frame = random_axis_frame(rng)
    offset = rng.uniform(-3, 3, size=3) * scale_m
    world = tris.reshape(-1, 3) @ frame.T + offset
    return (world / UNITS[unit]).reshape(-1, 3, 3).astype(np.float32)


def flip_some(tris, rng, share):
    if share <= 0:
        return tris
    flip = rng.random(len(tris)) < share
    out = tris.copy()
    out[flip] = out[flip][:, ::-1, :]
    return out


def facet_normals(tris):
    n = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]).astype(np.float64)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return n / np.where(length > 0, length, 1.0)


def write_stl(path, tris, binary, name):
    normals = facet_normals(tris)
    if binary:
        with open(path, "wb") as f:
            f.write(name.encode()[:80].ljust(80, b" "))
            f.write(struct.pack("<I", len(tris)))
            for n, t in zip(normals, tris):
                f.write(struct.pack("<12fH", *n, *t.reshape(-1), 0))
    else:
        with open(path, "w") as f:
            f.write(f"solid {name}\n")
            for n, t in zip(normals, tris):
                f.write(f"  facet normal {n[0]:e} {n[1]:e} {n[2]:e}\n    outer loop\n")
                for p in t:
                    f.write(f"      vertex {p[0]:e} {p[1]:e} {p[2]:e}\n")
                f.write("    endloop\n  endfacet\n")
            f.write(f"endsolid {name}\n")


def read_stl(path):
    """Reads back what write_stl wrote, as a converter would (binary when the size says so)."""
    data = open(path, "rb").read()
    if len(data) >= 84:
        count = struct.unpack("<I", data[80:84])[0]
        if 84 + 50 * count == len(data):
            tris = np.zeros((count, 3, 3), np.float32)
            for k in range(count):
                vals = struct.unpack("<12fH", data[84 + 50 * k:84 + 50 * (k + 1)])
                tris[k] = np.array(vals[3:12], np.float32).reshape(3, 3)
            return tris
    pts = [list(map(float, line.split()[1:4])) for line in data.decode().splitlines()
           if line.strip().startswith("vertex")]
    return np.array(pts, np.float32).reshape(-1, 3, 3)


def stl_to_obj_soup(stl_path, obj_path):
    """A facet-by-facet STL -> OBJ conversion: three `v` per facet, one `vn`, no welding."""
    tris = read_stl(stl_path)
    normals = facet_normals(tris)
    with open(obj_path, "w") as f:
        f.write(f"# converted from {os.path.basename(stl_path)}: {len(tris)} facets\n")
        for k, (n, t) in enumerate(zip(normals, tris)):
            for p in t:
                f.write(f"v {p[0]:.7g} {p[1]:.7g} {p[2]:.7g}\n")
            f.write(f"vn {n[0]:.5f} {n[1]:.5f} {n[2]:.5f}\n")
        for k in range(len(tris)):
            a = 3 * k + 1
            f.write(f"f {a}//{k + 1} {a + 1}//{k + 1} {a + 2}//{k + 1}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir")
    parser.add_argument("--seed", type=int, default=2501)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    os.makedirs(args.outdir, exist_ok=True)
    rows = []

    def emit(name, kind, unit, tris, scale_m, flip_share, binary, description):
        tris = flip_some(tris, rng, flip_share)
        placed = place(tris, rng, scale_m, unit)
        stl = os.path.join(args.outdir, name + ".stl")
        write_stl(stl, placed, binary, name)
        stl_to_obj_soup(stl, os.path.join(args.outdir, name + ".obj"))
        rows.append((name, kind, unit, UNITS[unit], flip_share, description))

    # A lampshade with a bulge, inches, open both ends.
    h = rng.uniform(0.22, 0.30)
    r0, r1 = h * rng.uniform(0.45, 0.6), h * rng.uniform(0.2, 0.3)
    bulge = h * rng.uniform(0.08, 0.14)
    tris = lathe(lambda t: (r0 + (r1 - r0) * t + bulge * math.sin(math.pi * t) ** 2, h * t), 28, 40)
    emit("lamp_bulge_in", "cone", "in", tris, h, 0.0, True,
         f"lampshade {h:.3f} m tall, radii {r0:.3f} -> {r1:.3f} m, bulge {bulge:.3f} m, open ends")

    # A bell: closed crown, waist, flaring lip; cm; a third of the facets wound the other way.
    h = rng.uniform(0.12, 0.2)
    crown, lip = h * 0.35, h * 0.62

    def bell(t):
        flare = 0.5 * (1 + math.tanh((t - 0.8) / 0.08))
        return (crown * (1 - 0.25 * t) + (lip - crown * 0.75) * flare, h * (1 - t))

    tris = lathe(bell, 30, 36, close_bottom=True)
    emit("bell_cm", "cone", "cm", tris, h, 0.33, False,
         f"bell {h:.3f} m tall, crown radius {crown:.3f} m closed, lip {lip:.3f} m, "
         "a third of the facets flipped")

    # A shallow dish, mm, binary.
    radius = rng.uniform(0.12, 0.18)
    depth = radius / rng.uniform(5, 10)
    tris = disk_height(lambda x, y: depth * (np.sqrt(x * x + y * y) / radius) ** 2.4, radius, 16, 7)
    emit("dish_mm", "disk", "mm", tris, radius, 0.0, True,
         f"shallow dish {2 * radius:.3f} m across, {depth:.3f} m deep")

    # A bowl with an oval rim (ellipsoid cap), inches, every facet flipped (inside out).
    a = rng.uniform(0.08, 0.12)
    b = a * rng.uniform(0.6, 0.75)
    c = a * rng.uniform(0.5, 0.7)
    tris = disk_height(lambda x, y: c * (1 - np.sqrt(np.maximum(0.0, 1 - (x / 1.0) ** 2 / a ** 2
                                                                    - (y / 1.0) ** 2 / b ** 2))),
                       1.0, 14, 8)
    # The unit disk stretched to the oval rim (the cap lies over the ellipse x^2/a^2+y^2/b^2 <= 0.97).
    flat = tris.reshape(-1, 3)
    flat[:, 0] *= a * 0.985
    flat[:, 1] *= b * 0.985
    flat[:, 2] = c * (1 - np.sqrt(np.maximum(0.0, 1 - flat[:, 0] ** 2 / a ** 2 - flat[:, 1] ** 2 / b ** 2)))
    tris = flat.reshape(-1, 3, 3)
    emit("oval_bowl_in", "disk", "in", tris, a, 1.0, False,
         f"bowl over an oval rim {2 * a:.3f} x {2 * b:.3f} m, {c:.3f} m deep, wound inside out")

    # A vase open at both ends: a belly and a neck; mm; a tenth flipped.
    h = rng.uniform(0.25, 0.35)
    rb, rn = h * rng.uniform(0.28, 0.36), h * rng.uniform(0.09, 0.13)
    tris = lathe(lambda t: (rn + (rb - rn) * math.exp(-((t - 0.35) / 0.28) ** 2)
                            + 0.5 * rn * math.exp(-((t - 1.0) / 0.08) ** 2), h * t), 36, 24)
    emit("open_vase_mm", "cylinder", "mm", tris, h, 0.1, True,
         f"vase {h:.3f} m tall, belly {rb:.3f} m, neck {rn:.3f} m, open ends, a tenth flipped")

    # A saddle tile over a disk, cm, ASCII.
    radius = rng.uniform(0.1, 0.15)
    k = rng.uniform(1.2, 2.5)
    q = rng.uniform(0.7, 1.4)
    tris = disk_height(lambda x, y: k * (x * x - q * y * y), radius, 14, 7)
    emit("saddle_cm", "square", "cm", tris, radius, 0.0, False,
         f"saddle z = {k:.2f} (x^2 - {q:.2f} y^2) over a disk of radius {radius:.3f} m")

    with open(os.path.join(args.outdir, "targets.tsv"), "w") as f:
        f.write("name\tkind\tunit\tmetres_per_unit\tflipped_share\tdescription\n")
        for r in rows:
            f.write("\t".join(str(x) for x in r) + "\n")


if __name__ == "__main__":
    main()
