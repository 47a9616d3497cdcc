"""What the bench's target generators share (make_drag_targets.py, make_symmetric_targets.py,
reach_targets.py): a fold kept only when it moved the sheet and `check` passes whole, and the
target written as `export --obj` less its vt lines. How each generator chooses its folds stays
its own, so their targets differ."""
import os


def fold_if_whole(design, grab, drop):
    """Folds grab onto drop; keeps the fold when it moved the sheet and the design passes
    `check` whole (undone otherwise). True when kept."""
    before = design.vertices
    try:
        result = design.fold(grab=grab, to=drop)
    except ValueError:
        return False
    if not result.folded:
        return False
    after = design.vertices
    moved = before.shape != after.shape or bool((abs(after[: len(before)] - before) > 1e-9).any())
    if not moved or not design.check().passed:
        design.undo()
        return False
    return True


def write_target(design, path):
    """`export --obj` less its vt lines; faces keep only their vertex indices."""
    tmp = path + ".full.obj"
    design.export(obj=tmp)
    with open(tmp) as f, open(path, "w") as out:
        for line in f:
            if line.startswith("vt "):
                continue
            if line.startswith("f "):
                line = "f " + " ".join(p.split("/")[0] for p in line.split()[1:]) + "\n"
            out.write(line)
    os.remove(tmp)
