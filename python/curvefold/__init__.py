"""curvefold: curved folding by reflection, in Python.

The C++ engine of the `curvefold` command line as a module (no second implementation): make a
design from a catalogue surface or an OBJ, fold it, check it, measure it, export it, render it,
and hand its meshes to numpy, trimesh or polyscope without files.

    import curvefold
    design = curvefold.Design.new("cylinder", radius=0.05, resolution=60)
    design.fold(grab=(0.05, 0.1, 0.0), to=(0.03, 0.07, 0.02))
    assert design.check().passed
    design.export(svg="cylinder.svg", pdf="cylinder.pdf")
    report = curvefold.Design.new("cylinder").fit("target.obj", folds=4, evaluations=20000)
    curvefold.distance(design, "target.obj")["hausdorff"]   # metres, as `curvefold distance`

Bad input raises ValueError, a file that cannot be read or written OSError, each with the
command line's one-line message.
"""

from ._curvefold import CheckResult, Design, FoldResult, distance, replay, surfaces

__all__ = ["CheckResult", "Design", "FoldResult", "distance", "replay", "surfaces"]
