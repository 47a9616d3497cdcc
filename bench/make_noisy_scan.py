"""A large noisy "scan" for timing `fit --time` (issue 38, 3): a vase of revolution about y
with radial noise (0.4 mm) and three holes, written as an OBJ with numpy only.

    /usr/bin/python3 bench/make_noisy_scan.py OUT.obj [NU NV]

NU x NV grid (default 350 x 160: 99,674 triangles; 620 272: 301,740), seed 38 (audit38's scan).
"""
import sys

import numpy as np

rng = np.random.default_rng(38)
nu, nv = (int(sys.argv[2]), int(sys.argv[3])) if len(sys.argv) > 3 else (350, 160)
u = np.linspace(0, 2 * np.pi, nu, endpoint=False)
v = np.linspace(0, 0.25, nv)
U, V = np.meshgrid(u, v)
R = 0.06 + 0.025 * np.sin(V / 0.25 * np.pi * 1.5) + rng.normal(0, 0.0004, U.shape)
P = np.stack([R * np.cos(U), V, R * np.sin(U)], -1).reshape(-1, 3)
faces = []
holes = [(1.0, 0.08, 0.15, 0.02), (3.0, 0.15, 0.2, 0.015), (5.0, 0.2, 0.12, 0.01)]
for j in range(nv - 1):
    for i in range(nu):
        a = j * nu + i
        b = j * nu + (i + 1) % nu
        c, d = a + nu, b + nu
        uu, vv = u[i], v[j]
        if any(abs(uu - hu) < hw / 0.08 and abs(vv - hv) < hh / 2 for hu, hv, hw, hh in holes):
            continue
        faces += [(a, b, d), (a, d, c)]
with open(sys.argv[1], "w") as f:
    f.write("".join(f"v {x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in P))
    f.write("".join(f"f {a+1} {b+1} {c+1}\n" for a, b, c in faces))
print(len(faces), "triangles")
