#!/usr/bin/env python3
# Writes examples/meshes/elliptic_tube.obj, the showcase's OBJ surface (an elliptic cylinder):
#   python3 scripts/make-elliptic-tube-obj.py > examples/meshes/elliptic_tube.obj
import math
a, b = 0.07, 0.035           # semi-axes of the ellipse, metres
t0, t1, n, m, h = math.radians(-110), math.radians(110), 44, 24, 0.2
ts = [t0 + (t1 - t0) * i / n for i in range(n + 1)]
pts = [(a * math.sin(t), b * math.cos(t)) for t in ts]
u = [0.0]
for i in range(n):
    u.append(u[-1] + math.dist(pts[i], pts[i + 1]))
mid = u[-1] / 2
out = ["# curvefold example: an elliptic cylinder (semi-axes 7 cm and 3.5 cm, 220 degrees around, 20 cm",
       "# long), a developable surface none of curvefold's generators makes. v = position in metres,",
       "# vt = development in metres (chord lengths around, so every triangle keeps its shape).",
       "# Made by scripts/make-elliptic-tube-obj.py."]
for j in range(m + 1):
    y = -h / 2 + h * j / m
    for i in range(n + 1):
        out.append(f"v {pts[i][0]!r} {y!r} {pts[i][1]!r}")
for j in range(m + 1):
    y = -h / 2 + h * j / m
    for i in range(n + 1):
        out.append(f"vt {u[i] - mid!r} {y!r}")
idx = lambda i, j: j * (n + 1) + i + 1
for j in range(m):
    for i in range(n):
        a_, b_, c_, d_ = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
        out.append(f"f {a_}/{a_} {d_}/{d_} {c_}/{c_}")
        out.append(f"f {a_}/{a_} {c_}/{c_} {b_}/{b_}")
print("\n".join(out))
