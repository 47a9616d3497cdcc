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
    design, report = curvefold.fit("target.obj", folds=16, evaluations=1500)  # as `curvefold fit`
    curvefold.distance(design, "target.obj")["hausdorff"]   # metres, as `curvefold distance`
    state = curvefold.simulate("pattern.fold", percent=50)   # any crease pattern, folded halfway
    state["vertices"], state["triangles"], state["strain"]

Errors are one line each. A bad argument raises ValueError naming its parameter ("size: expected
a number, got NoneType None"); one of the wrong type is curvefold.ArgumentError, both a ValueError
and a TypeError. A file that cannot be read or written (missing, a folder, not a regular file)
raises OSError naming the path. An input over a size limit or malformed is ValueError, with the
command line's message. Missing or unexpected arguments are a one-line TypeError.

A Design may be used from several threads: each takes the design's lock in turn (with the GIL
released), so calls on one design never interleave; `mesh()` gives vertices, triangles and
development of one state while another thread folds.
"""

import functools as _functools
import re as _re

from . import _curvefold
from ._curvefold import (ArgumentError, CheckResult, Design, FoldResult, distance, fit, replay,
                         simulate, surfaces)

__all__ = [
    "ArgumentError", "CheckResult", "Design", "FoldResult", "distance", "fit", "replay", "simulate",
    "surfaces"
]


def _one_line_call_errors(function, name):
    """Missing or unexpected arguments in one line, as Python's own functions say them, instead
    of pybind11's list of signatures (the arguments' values are checked by the module)."""

    @_functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as error:
            lines = str(error).splitlines()
            if len(lines) < 2 or "incompatible function arguments" not in lines[0]:
                raise
            signature = lines[1].split(". ", 1)[-1].split(" -> ")[0]
            signature = _re.sub(r"self: [\w.]+(, )?", "", signature)
            signature = _re.sub(r": [\w.\[\], ]+?(?=(, |\)| =))", "", signature)
            signature = signature.replace(" = ", "=")
            raise TypeError(f"{name}(): missing or unexpected arguments; it takes "
                            f"{signature}") from None

    return call


for _name, _member in list(vars(_curvefold.Design).items()):
    if _name.startswith("_"):
        continue
    if isinstance(_member, staticmethod):
        setattr(Design, _name,
                staticmethod(_one_line_call_errors(_member.__func__, f"Design.{_name}")))
    elif type(_member).__name__ == "instancemethod":
        setattr(Design, _name, _one_line_call_errors(_member.__func__, f"Design.{_name}"))
for _name in ("distance", "fit", "replay", "simulate", "surfaces"):
    globals()[_name] = _one_line_call_errors(getattr(_curvefold, _name), _name)
distance, replay, surfaces = globals()["distance"], globals()["replay"], globals()["surfaces"]
fit = globals()["fit"]
simulate = globals()["simulate"]
