"""The Python module (issue 30): every call, bad input included, against the command line."""

import json
import os
import re
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import curvefold

CLI = os.environ.get("CURVEFOLD_BINARY", "build/app/curvefold")
SOURCE = Path(os.environ.get("CURVEFOLD_SOURCE_DIR", Path(__file__).resolve().parents[2]))
RECORDINGS = SOURCE / "examples" / "recordings"


def cli(*arguments, cwd=None):
    return subprocess.run([CLI, *map(str, arguments)], cwd=cwd, capture_output=True, text=True,
                          check=True)


def folded_cylinder():
    design = curvefold.Design.new("cylinder", radius=0.05, resolution=60)
    design.fold(grab=(0.05, 0.1, 0.0), to=(0.03, 0.07, 0.02))
    return design


def test_surfaces_lists_the_catalogue_with_ranges_and_symmetries():
    surfaces = curvefold.surfaces()
    assert list(surfaces)[:4] == ["square", "rectangle", "disk", "star"]
    radius = surfaces["cylinder"]["parameters"]["radius"]
    assert radius["min"] < radius["default"] < radius["max"]
    assert surfaces["cylinder"]["parameters"]["resolution"]["integer"] is True
    assert "rotational:12:y" in surfaces["cylinder"]["symmetries"]


def test_a_design_made_in_python_is_byte_identical_to_the_command_lines(tmp_path):
    made = folded_cylinder()
    made.save(tmp_path / "python.curvefold.json")
    cli("new", "cylinder", "--radius", "0.05", "--resolution", "60", "-o", tmp_path / "cli.curvefold.json")
    cli("fold", tmp_path / "cli.curvefold.json", "--vertex-near", "0.05,0.1,0", "--to", "0.03,0.07,0.02",
        "-o", tmp_path / "cli.curvefold.json")
    assert (tmp_path / "python.curvefold.json").read_bytes() == (tmp_path / "cli.curvefold.json").read_bytes()


def test_a_symmetric_fold_brings_its_images_as_the_command_line_does(tmp_path):
    design = curvefold.Design.new("cylinder", symmetry="rotational:4:y")
    assert design.symmetry == "rotational:4:y"
    result = design.fold(grab=(0.045, 0.1, 0.0), to=(0.03, 0.08, 0.0))
    assert result.folded and result.images == 3
    assert "overlap" in result.notes
    assert [fold["group"] for fold in design.folds] == [1, 1, 1, 1]
    design.save(tmp_path / "python.curvefold.json")
    cli("new", "cylinder", "--symmetry", "rotational:4:y", "-o", tmp_path / "cli.curvefold.json")
    cli("fold", tmp_path / "cli.curvefold.json", "--vertex-near", "0.045,0.1,0", "--to", "0.03,0.08,0",
        "-o", tmp_path / "cli.curvefold.json")
    assert (tmp_path / "python.curvefold.json").read_bytes() == (tmp_path / "cli.curvefold.json").read_bytes()
    assert design.undo() and design.folds == []  # the group at once


def test_a_symmetric_fold_the_slit_cuts_short_is_refused_as_the_command_line_refuses_it():
    # Issue 28: its own part ends at the cylinder's slit, its images do not.
    design = curvefold.Design.new("cylinder", symmetry="rotational:4:y")
    with pytest.raises(ValueError, match="not symmetric under rotational:4:y: the fold's part is cut short"):
        design.fold(grab=(-0.011646857029613445, -0.105, -0.04346666218300807),
                    to=(-0.009053855032104785, -0.10085514992637065, -0.033789446984178156))
    assert design.folds == []


def test_fold_undo_redo_and_the_folds():
    design = folded_cylinder()
    (fold,) = design.folds
    assert fold["group"] == 0
    assert np.isclose(np.linalg.norm(fold["plane_normal"]), 1.0)
    assert np.allclose(fold["target"], (0.03, 0.07, 0.02))
    before = design.vertices.copy()
    assert design.undo() is True
    assert design.folds == [] and design.undo() is False
    assert design.redo() is True and design.redo() is False
    assert np.array_equal(design.vertices, before)
    # A drop point on the grabbed point folds nothing.
    result = design.fold(grab=(0.0, 0.0, 0.05), to=(0.0, 0.0, 0.05))
    assert result.folded is False and len(design.folds) == 1


def test_the_meshes_are_read_only_arrays_shared_without_copies():
    design = folded_cylinder()
    vertices, triangles, development = design.vertices, design.triangles, design.development
    assert vertices.dtype == np.float64 and vertices.shape[1] == 3
    assert triangles.dtype == np.uint32 and triangles.shape[1] == 3
    assert development.shape == (vertices.shape[0], 2)
    assert triangles.max() < vertices.shape[0]
    assert not vertices.flags.writeable
    with pytest.raises(ValueError):
        vertices[0, 0] = 1.0
    assert np.shares_memory(vertices, design.vertices)  # no copy per access
    kept = vertices.copy()
    design.fold(grab=(-0.05, -0.1, 0.0), to=(-0.03, -0.07, 0.02))
    assert np.array_equal(vertices, kept)  # an array handed out stays valid and unchanged
    assert design.vertices.shape[0] > vertices.shape[0]
    # Isometric: every edge as long folded as flat.
    a, b = triangles[:, 0], triangles[:, 1]
    lengths3 = np.linalg.norm(vertices[a] - vertices[b], axis=1)
    lengths2 = np.linalg.norm(development[a] - development[b], axis=1)
    assert np.max(np.abs(lengths3 - lengths2)) < 1e-9


def test_creases_carry_assignments_and_angles():
    creases = folded_cylinder().creases()
    count = len(creases["assignment"])
    assert count > 10
    assert creases["edges"].shape == (count, 2) and creases["angles"].shape == (count,)
    assert set(creases["assignment"]) <= {"M", "V"}
    assert np.all(np.abs(creases["angles"]) > 0)


def test_creases_tell_mountains_from_valleys():
    # A corner of the square (its front faces +z) folded up toward the front makes a valley, the
    # opposite corner folded down a mountain: FOLD's signs (valley positive), and the same
    # assignment as the FOLD file has for each edge.
    design = curvefold.Design.new("square")
    design.fold(grab=(0.09, 0.09, 0.0), to=(0.05, 0.05, 0.03))
    design.fold(grab=(-0.09, -0.09, 0.0), to=(-0.05, -0.05, -0.03))
    creases = design.creases()
    assignment = np.array(creases["assignment"])
    flat = design.development
    side = np.sign(flat[creases["edges"][:, 0], 0] + flat[creases["edges"][:, 1], 0])
    assert np.all(assignment[side > 0] == "V") and np.sum(side > 0) > 0
    assert np.all(assignment[side < 0] == "M") and np.sum(side < 0) > 0
    assert np.all((creases["angles"] > 0) == (assignment == "V"))
    fold = design.to_fold()
    by_edge = {tuple(sorted(edge)): kind
               for edge, kind in zip(fold["edges_vertices"], fold["edges_assignment"])}
    assert [by_edge[tuple(sorted(edge))] for edge in creases["edges"].tolist()] == list(assignment)


def test_check_returns_the_command_lines_invariants(tmp_path):
    design = folded_cylinder()
    result = design.check()
    assert result.passed and result.failures == []
    assert result.self_intersections == 0
    assert result.max_edge_length_error <= result.length_tolerance
    design.save(tmp_path / "a.curvefold.json")
    printed = cli("check", tmp_path / "a.curvefold.json").stdout.splitlines()
    assert [("  ok    " if ok else "  FAIL  ") + text for ok, text in result.lines] == printed[1:]
    # A fold that passes the paper through itself fails, unless allowed.
    through_itself = curvefold.Design.new("cylinder")
    through_itself.fold(grab=(0.05, 0.1, 0.0), to=(0.02, 0.06, 0.05))
    crossing = through_itself.check()
    assert bool(result) and not crossing  # true when every invariant holds
    assert not crossing.passed and crossing.self_intersections > 0
    assert crossing.failures[0].startswith("self-intersection")
    assert through_itself.check(allow_self_intersection=True).passed


def test_to_fold_is_the_fold_files_content(tmp_path):
    design = folded_cylinder()
    design.save(tmp_path / "a.curvefold.json")
    cli("export", tmp_path / "a.curvefold.json", "--fold", tmp_path / "a.fold")
    assert design.to_fold() == json.loads((tmp_path / "a.fold").read_text())
    assert design.to_fold()["edges_assignment"].count("M") > 0


def test_export_writes_every_format_or_none(tmp_path):
    design = folded_cylinder()
    names = {key: tmp_path / f"a.{suffix}" for key, suffix in
             [("fold", "fold"), ("svg", "svg"), ("obj", "obj"), ("gltf", "glb"), ("pdf", "pdf"),
              ("cut_svg", "cut.svg")]}
    design.export(**{key: str(path) for key, path in names.items()}, perforate=(3, 1.5), paper="letter")
    for path in names.values():
        assert path.stat().st_size > 100, path
    assert (tmp_path / "a.pdf").read_bytes().startswith(b"%PDF")
    # One output that cannot be written: nothing is replaced.
    (tmp_path / "dir.obj").mkdir()
    before = names["svg"].read_bytes()
    design.undo()
    with pytest.raises(OSError):
        design.export(svg=str(names["svg"]), obj=str(tmp_path / "dir.obj"))
    assert names["svg"].read_bytes() == before
    with pytest.raises(ValueError, match="name at least one"):
        design.export()
    with pytest.raises(ValueError, match="paper"):
        design.export(pdf=str(tmp_path / "b.pdf"), paper="a9")
    with pytest.raises(ValueError, match="perforate"):
        design.export(cut_svg=str(tmp_path / "b.svg"), perforate=(0, 1))
    assert not (tmp_path / "b.pdf").exists() and not (tmp_path / "b.svg").exists()


def undated(pdf):
    """A PDF's bytes without the creation time Cairo writes into it."""
    return re.sub(rb"/CreationDate \(D:[0-9Z+'-]*\)", b"", pdf.read_bytes())


def test_the_pdf_is_the_command_lines_with_the_folded_form_and_the_date(tmp_path):
    """Issue 41, 3: Design.export(pdf=...) prints the cover `curvefold export --pdf` prints: the
    picture of the folded form and the facts with the date (the same bytes, but for the time)."""
    folded_cylinder().save(tmp_path / "a.curvefold.json")
    cli("export", tmp_path / "a.curvefold.json", "--pdf", tmp_path / "cli.pdf", "--paper", "fit")
    curvefold.Design.load(tmp_path / "a.curvefold.json").export(pdf=str(tmp_path / "python.pdf"),
                                                                paper="fit")
    python = undated(tmp_path / "python.pdf")
    assert b"/Subtype /Image" in python  # the folded form
    assert python == undated(tmp_path / "cli.pdf")


def test_render_is_an_rgba_image_of_the_design():
    image = folded_cylinder().render(160, 120, view="front")
    assert image.shape == (120, 160, 4) and image.dtype == np.uint8
    background = image[0, 0, :3].astype(int)
    differs = np.abs(image[:, :, :3].astype(int) - background).sum(axis=2) > 30
    assert differs.mean() > 0.05  # the sheet covers a good part of it
    with pytest.raises(ValueError, match="unknown view"):
        folded_cylinder().render(10, 10, view="sideways")


def test_replay_makes_the_recordings_design(tmp_path):
    design = curvefold.replay(str(RECORDINGS / "star.jsonl"))
    cli("replay", RECORDINGS / "star.jsonl", "--out", tmp_path / "star")
    design.save(tmp_path / "python.curvefold.json")
    assert (tmp_path / "python.curvefold.json").read_bytes() == \
        (tmp_path / "star" / "star.curvefold.json").read_bytes()


def test_load_and_from_obj(tmp_path):
    design = folded_cylinder()
    design.save(tmp_path / "a.curvefold.json")
    loaded = curvefold.Design.load(str(tmp_path / "a.curvefold.json"))
    assert loaded.folds == design.folds and loaded.surface == "cylinder"
    assert loaded.undo()  # the loaded folds can be undone
    design.export(obj=str(tmp_path / "a.obj"))
    from_path = curvefold.Design.from_obj(tmp_path / "a.obj")
    assert from_path.surface == "embedded mesh"
    assert from_path.vertices.shape[0] > 0
    # Arrays: a flat square of two triangles, with and without its development.
    vertices = np.array([[0, 0, 0], [0.1, 0, 0], [0.1, 0.1, 0], [0, 0.1, 0]], dtype=float)
    triangles = np.array([[0, 1, 2], [0, 2, 3]])
    square = curvefold.Design.from_obj(vertices, triangles=triangles)
    assert square.triangles.shape == (2, 3)
    assert curvefold.Design.from_obj(vertices, triangles=triangles,
                                     development=vertices[:, :2]).check().passed


def test_bad_input_is_a_value_error_with_the_one_line_message(tmp_path):
    with pytest.raises(ValueError, match="parameter 'radius'"):
        curvefold.Design.new("cylinder", radius=-1)
    with pytest.raises(ValueError, match='unknown surface "teapot"'):
        curvefold.Design.new("teapot")
    with pytest.raises(ValueError, match='no parameter "points"'):
        curvefold.Design.new("cylinder", points=5)
    with pytest.raises(ValueError, match="rotational:7"):
        curvefold.Design.new("cylinder", symmetry="rotational:7:x")
    with pytest.raises(ValueError, match="grab"):
        folded_cylinder().fold(grab=(0, 0), to=(0, 0, 0))
    with pytest.raises(OSError, match="cannot read"):
        curvefold.Design.load(str(tmp_path / "missing.curvefold.json"))
    (tmp_path / "bad.curvefold.json").write_text("{not json")
    with pytest.raises(ValueError, match="bad.curvefold.json"):
        curvefold.Design.load(str(tmp_path / "bad.curvefold.json"))
    (tmp_path / "bad.obj").write_text("v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(ValueError, match="bad.obj"):
        curvefold.Design.from_obj(str(tmp_path / "bad.obj"))
    with pytest.raises(ValueError, match="names a vertex"):
        curvefold.Design.from_obj(np.zeros((3, 3)), triangles=np.array([[0, 1, 7]]))
    with pytest.raises(ValueError, match="bad.jsonl"):
        (tmp_path / "bad.jsonl").write_text("nothing\n")
        curvefold.replay(str(tmp_path / "bad.jsonl"))
    with pytest.raises(OSError):
        folded_cylinder().save(str(tmp_path / "no" / "such" / "folder" / "a.curvefold.json"))


def test_a_long_fold_lets_other_python_threads_run():
    design = curvefold.Design.new("cylinder", resolution=600)  # about 700k triangles
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    start = time.perf_counter()
    design.fold(grab=(0.045, 0.1, 0.0), to=(0.03, 0.07, 0.02))
    end = time.perf_counter()
    stop.set()
    ticker.join()
    during = [t for t in ticks if start < t < end]
    assert end - start > 0.05
    assert len(during) > 5  # the GIL was released while the engine folded


EXAMPLES = SOURCE / "python" / "examples"


def run_example(name, tmp_path, *arguments, without=()):
    """Runs an example; `without` names modules it must find missing (stubs that raise ImportError)."""
    environment = dict(os.environ, MPLBACKEND="Agg")
    if without:
        stubs = tmp_path / "missing-modules"
        stubs.mkdir(exist_ok=True)
        for module in without:
            (stubs / f"{module}.py").write_text(f"raise ImportError('{module} hidden by the test')\n")
        environment["PYTHONPATH"] = os.pathsep.join(
            [str(stubs)] + [p for p in [environment.get("PYTHONPATH")] if p])
    return subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, arguments)], cwd=tmp_path,
                          env=environment, capture_output=True, text=True, check=True).stdout


def test_the_examples_run(tmp_path):
    table = run_example("cone_sweep.py", tmp_path).splitlines()
    assert len(table) == 10 and all(row.endswith("ok") for row in table[1:])
    run_example("symmetric_pdf.py", tmp_path, tmp_path / "crown.pdf")
    assert (tmp_path / "crown.pdf").read_bytes().startswith(b"%PDF")
    # Without polyscope and matplotlib the example renders the PNG itself: it must be written.
    shown = run_example("show_design.py", tmp_path, RECORDINGS / "star.jsonl",
                        without=("polyscope", "matplotlib"))
    assert "wrote design.png" in shown
    assert (tmp_path / "design.png").read_bytes().startswith(b"\x89PNG")


TARGETS = SOURCE / "examples" / "targets"


def cli_distance(a, b, *arguments):
    """The four lines of `curvefold distance`, as {A -> B max, ..., hausdorff, chamfer} in mm."""
    out = cli("distance", a, b, *arguments).stdout.splitlines()
    def mm(text):
        return float(text.split(" mm")[0].split()[-1])
    return {
        "a_to_b_max": mm(out[0].split("max ")[1]), "a_to_b_mean": mm(out[0].split("mean ")[1]),
        "b_to_a_max": mm(out[1].split("max ")[1]), "b_to_a_mean": mm(out[1].split("mean ")[1]),
        "hausdorff": mm(out[2].split(": ")[1]), "chamfer": mm(out[3].split(": ")[1]),
    }


def assert_same_to_three_digits(python_metres, cli_millimetres, what):
    # The command prints three significant digits.
    assert python_metres * 1000 == pytest.approx(cli_millimetres, rel=5e-3, abs=1e-9), what


def test_distance_is_the_command_lines(tmp_path):
    design = folded_cylinder()
    design.save(tmp_path / "d.curvefold.json")
    target = TARGETS / "tube_tucked.obj"
    for a, b in [(design, target), (tmp_path / "d.curvefold.json", str(target)), (target, design)]:
        ours = curvefold.distance(a, b, samples=5000, seed=3)
        theirs = cli_distance(tmp_path / "d.curvefold.json" if isinstance(a, curvefold.Design) else a,
                              tmp_path / "d.curvefold.json" if isinstance(b, curvefold.Design) else b,
                              "--samples", "5000", "--seed", "3")
        for key, millimetres in theirs.items():
            assert_same_to_three_digits(ours[key], millimetres, key)
        assert ours["hausdorff"] == max(ours["a_to_b_max"], ours["b_to_a_max"])
    with pytest.raises((OSError, ValueError), match="missing.obj"):  # as from_obj says it
        curvefold.distance(design, tmp_path / "missing.obj")
    with pytest.raises(ValueError):
        curvefold.distance(design, 3)


def test_distance_png_is_the_command_lines_picture(tmp_path):
    """png= draws a coloured by its distance to b as `curvefold distance A B --png` does: the same
    bytes for the same shapes; a picture over an input is refused and nothing is written."""
    design = folded_cylinder()
    design.save(tmp_path / "d.curvefold.json")
    target = TARGETS / "tube_tucked.obj"
    ours = curvefold.distance(target, design, samples=2000, png=tmp_path / "python.png")
    assert ours["hausdorff"] > 0
    cli("distance", target, tmp_path / "d.curvefold.json", "--samples", "2000",
        "--png", tmp_path / "cli.png")
    picture = (tmp_path / "python.png").read_bytes()
    assert picture[:8] == b"\x89PNG\r\n\x1a\n"
    assert picture == (tmp_path / "cli.png").read_bytes()
    with pytest.raises((OSError, ValueError), match="d.curvefold.json"):
        curvefold.distance(design, tmp_path / "d.curvefold.json", png=tmp_path / "d.curvefold.json")
    with pytest.raises(TypeError):
        curvefold.distance(design, target, png=3)


def test_fit_is_the_command_lines_fit(tmp_path):
    """With evaluations (no clock) Design.fit keeps the same folds as `curvefold fit`, byte for
    byte in the saved design, and reports the same distances; another seed searches otherwise."""
    target = TARGETS / "saddle.obj"
    design = curvefold.Design.new("square", resolution=12)
    report = design.fit(target, folds=2, evaluations=30, seed=5)
    # A step may be a pleat (two folds of one group): the report counts steps.
    assert report["folds"] >= 1 and len({f["group"] for f in design.folds}) == report["folds"]
    assert report["out_of_evaluations"] and not report["timed_out"]
    assert report["evaluations"] >= 30
    assert report["dropped_samples"] == 0
    design.save(tmp_path / "python.curvefold.json")
    out = cli("fit", target, "--from", "square", "--resolution", "12", "--folds", "2",
              "--evaluations", "30", "--seed", "5", "-o", tmp_path / "cli.curvefold.json",
              "--log", tmp_path / "cli.jsonl").stdout
    assert (tmp_path / "python.curvefold.json").read_bytes() == (tmp_path / "cli.curvefold.json").read_bytes()
    # The same numbers, not only the same three digits: each step's distances as the log writes
    # them, and the candidates scored.
    log = [json.loads(line) for line in (tmp_path / "cli.jsonl").read_text().splitlines()]
    end = log.pop()
    steps = {}  # per step (a pleat logs each of its folds): the distance after it
    for entry in log:
        steps[entry["fold"]] = (entry["hausdorff"], entry["chamfer"])
    assert [(s["hausdorff"], s["chamfer"]) for s in report["steps"][1:]] == list(steps.values())
    assert report["evaluations"] == end["evaluations"] and report["stop"] == end["stop"]
    wrote = [line for line in out.splitlines() if line.startswith("wrote ")][0]
    hausdorff_mm = float(wrote.split("Hausdorff ")[1].split(" mm")[0])
    chamfer_mm = float(wrote.split("Chamfer ")[1].split(" mm")[0])
    assert_same_to_three_digits(report["hausdorff"], hausdorff_mm, "hausdorff")
    assert_same_to_three_digits(report["chamfer"], chamfer_mm, "chamfer")
    assert report["steps"][0]["folds"] == 0 and len(report["steps"]) == report["folds"] + 1
    other = curvefold.Design.new("square", resolution=12)
    other.fit(target, folds=2, evaluations=200, seed=6)
    assert other.folds != design.folds
    assert design.check().passed


def test_module_fit_is_the_command_lines_fit_without_from(tmp_path):
    """curvefold.fit chooses the start as `curvefold fit` without --from (here the folded tube's
    own cylinder: the target has its creases) and keeps the same folds: the same design file, byte
    for byte, and the same distances as the log's."""
    target = TARGETS / "tube_tucked.obj"
    design, report = curvefold.fit(target, folds=2, evaluations=30, seed=1)
    assert isinstance(design, curvefold.Design) and design.surface == "cylinder"
    design.save(tmp_path / "python.curvefold.json")
    out = cli("fit", target, "--folds", "2", "--evaluations", "30", "--seed", "1", "-o",
              tmp_path / "cli.curvefold.json", "--log", tmp_path / "cli.jsonl").stdout
    assert out.startswith("from: cylinder")
    assert (tmp_path / "python.curvefold.json").read_bytes() == (tmp_path / "cli.curvefold.json").read_bytes()
    log = [json.loads(line) for line in (tmp_path / "cli.jsonl").read_text().splitlines()]
    end = log.pop()
    assert [(s["hausdorff"], s["chamfer"]) for s in report["steps"][1:]] == [
        (entry["hausdorff"], entry["chamfer"]) for entry in log]
    assert report["evaluations"] == end["evaluations"] and report["stop"] == end["stop"]
    # No runner-up here: the one start folded, kept.
    assert report["starts"] == [{"surface": "cylinder", "placed": False,
                                 "hausdorff": report["hausdorff"], "chamfer": report["chamfer"],
                                 "kept": True}]
    assert design.check().passed
    with pytest.raises(ValueError, match="start"):
        curvefold.fit(target, start="nonesuch")
    with pytest.raises(ValueError, match="folds"):
        curvefold.fit(target, folds=0)
    with pytest.raises(TypeError):
        curvefold.fit(target, start=3)


def test_fit_refuses_bad_values_and_keeps_the_design(tmp_path):
    design = folded_cylinder()
    before = design.folds
    with pytest.raises(ValueError, match="folds"):
        design.fit(TARGETS / "tube_tucked.obj", folds=0)
    with pytest.raises(ValueError, match="time"):
        design.fit(TARGETS / "tube_tucked.obj", time=float("nan"))
    with pytest.raises((OSError, ValueError), match="missing.obj"):
        design.fit(tmp_path / "missing.obj")
    far = tmp_path / "far.obj"
    far.write_text("v 100 0 0\nv 101 0 0\nv 100 1 0\nf 1 2 3\n")
    with pytest.raises(ValueError, match="far.obj"):
        design.fit(far)
    assert design.folds == before


def test_module_fit_refuses_bad_values_before_fitting(tmp_path):
    target = TARGETS / "tube_tucked.obj"
    with pytest.raises(ValueError, match="folds"):
        curvefold.fit(target, folds=0)
    with pytest.raises(ValueError, match="evaluations"):
        curvefold.fit(target, evaluations=0)
    with pytest.raises(ValueError, match="time"):
        curvefold.fit(target, time=float("nan"))
    with pytest.raises(ValueError, match="start"):
        curvefold.fit(target, start="teapot")
    with pytest.raises((OSError, ValueError), match="missing.obj"):
        curvefold.fit(tmp_path / "missing.obj")


def test_a_long_fit_lets_other_python_threads_run():
    design = curvefold.Design.new("square", resolution=12)
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    thread = threading.Thread(target=tick)
    thread.start()
    start = time.monotonic()
    design.fit(TARGETS / "saddle.obj", folds=2, time=1.0)
    elapsed = time.monotonic() - start
    done.set()
    thread.join()
    assert elapsed < 1.0 * 1.05 + 0.5
    assert sum(1 for t in ticks if start < t < start + elapsed) >= 10
