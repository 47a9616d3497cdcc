"""curvefold: curved folding by reflection, in Python.

The C++ engine of the `curvefold` command line as a module (no second implementation): make a
design from a catalogue surface or an OBJ, fold it, check it, measure it, export it, render it,
and hand its meshes to numpy, trimesh or polyscope without files.

    import curvefold
    design = curvefold.Design.new("cylinder", radius=0.05, resolution=60)
    design.fold(grab=(0.05, 0.1, 0.0), to=(0.03, 0.07, 0.02))
    assert design.check().passed
    design.export(svg="cylinder.svg", pdf="cylinder.pdf")

Errors are one line each. A bad argument raises ValueError naming its parameter ("size: expected
a number, got NoneType None"); one of the wrong type is curvefold.ArgumentError, both a ValueError
and a TypeError. A file that cannot be read or written (missing, a folder, not a regular file)
raises OSError naming the path. An input over a size limit or malformed is ValueError, with the
command line's message.

A Design may be used from several threads: each takes the design's lock in turn (with the GIL
released), so calls on one design never interleave; `mesh()` gives vertices, triangles and
development of one state while another thread folds.
"""

from ._curvefold import ArgumentError, CheckResult, Design, FoldResult, replay, surfaces

__all__ = ["ArgumentError", "CheckResult", "Design", "FoldResult", "replay", "surfaces"]
