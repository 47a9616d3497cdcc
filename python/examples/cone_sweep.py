"""A parameter sweep: a grid of cones folded the same way, with a table of their fold angles.

Each cone (base radius by height) is folded once, the front of its base rim pushed in; the table
lists how much crease the fold made and its steepest mountain and valley angles, and that every
design passes the invariants.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/cone_sweep.py
"""

import numpy as np

import curvefold

print(f"{'base r':>7} {'height':>7} {'crease edges':>12} {'mountain':>9} {'valley':>8}  check")
for base_radius in (0.06, 0.08, 0.10):
    for height in (0.08, 0.12, 0.16):
        design = curvefold.Design.new("cone", base_radius=base_radius, height=height,
                                      top_radius=0.02, resolution=48)
        # The same fold on every cone: the front of its base rim pushed 2 cm in.
        base = -height / 2
        design.fold(grab=(0.0, base, base_radius), to=(0.0, base, base_radius - 0.02))
        creases = design.creases()
        angles = creases["angles"]
        mountain = angles[np.array(creases["assignment"]) == "M"]
        valley = angles[np.array(creases["assignment"]) == "V"]
        print(f"{base_radius:7.2f} {height:7.2f} {len(angles):12d} "
              f"{np.abs(mountain).max(initial=0):8.1f}° {np.abs(valley).max(initial=0):7.1f}°  "
              f"{'ok' if design.check() else 'FAIL'}")
