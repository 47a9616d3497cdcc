"""Design.simulate: the bar-and-hinge simulation from Python (issue 39, 5)."""

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import curvefold

CLI = os.environ.get("CURVEFOLD_BINARY", "build/app/curvefold")
SOURCE = Path(os.environ.get("CURVEFOLD_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def test_simulate_folds_a_design_from_flat_to_itself():
    design = curvefold.Design.new("cone", resolution=12)
    flat = design.simulate(percent=0)
    development = np.asarray(design.development)
    # 0%: the flat development exactly, every edge at its length.
    assert np.array_equal(flat["vertices"][:, :2], development)
    assert np.all(flat["vertices"][:, 2] == 0)
    assert np.all(flat["strain"] == 0)
    folded = design.simulate(percent=100, settle=True)
    assert folded["converged"]
    assert np.abs(folded["strain"]).max() < 1e-6
    # 100%: the design itself, up to a rigid motion: every pairwise distance as in the design.
    vertices = np.asarray(design.vertices)
    simulated = folded["vertices"]
    design_distances = np.linalg.norm(vertices[:, None] - vertices[None], axis=2)
    simulated_distances = np.linalg.norm(simulated[:, None] - simulated[None], axis=2)
    assert np.abs(design_distances - simulated_distances).max() < 1e-6
    assert folded["edges"].shape == (folded["strain"].shape[0], 2)


def test_simulate_refuses_a_percent_out_of_range():
    design = curvefold.Design.new("square")
    with pytest.raises(ValueError, match="percent"):
        design.simulate(percent=150)


# curvefold.simulate: crease patterns from other tools (issue 39, 5), made here two ways.

def square_with_crease(angle=90.0, assignment="V"):
    """A FOLD dict as json.load gives it: a 2 x 1 sheet with one crease down its middle."""
    return {
        "file_spec": 1.1,
        "vertices_coords": [[0, 0], [1, 0], [2, 0], [2, 1], [1, 1], [0, 1]],
        "edges_vertices": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]],
        "edges_assignment": ["B", "B", "B", "B", "B", "B", assignment],
        "edges_foldAngle": [0, 0, 0, 0, 0, 0, angle],
    }


def fold_angle_degrees(result):
    """The angle between the normals of the triangles on either side of the one crease edge."""
    vertices, triangles = result["vertices"], result["triangles"]
    crease = [i for i, letter in enumerate(result["assignment"]) if letter in "MV"]
    assert len(crease) == 1
    a, b = result["edges"][crease[0]]
    sides = [t for t in triangles if a in t and b in t]
    assert len(sides) == 2
    normals = []
    for t in sides:
        p, q, r = vertices[t]
        n = np.cross(q - p, r - p)
        normals.append(n / np.linalg.norm(n))
    return np.degrees(np.arccos(np.clip(np.dot(*normals), -1, 1)))


def test_simulate_folds_a_fold_dict_to_the_percent_of_its_crease():
    for percent in (0, 25, 50, 100):
        result = curvefold.simulate(square_with_crease(), percent=percent)
        assert result["converged"]
        n = result["vertices"].shape[0]
        assert result["vertices"].shape == (n, 3) and result["development"].shape == (n, 2)
        assert result["triangles"].shape[1] == 3 and result["triangles"].dtype == np.uint32
        assert result["strain"].shape == (len(result["assignment"]),)
        assert np.abs(result["strain"]).max() < 1e-6
        assert abs(fold_angle_degrees(result) - 0.9 * percent) < 0.5, percent
        assert np.abs(result["crease_angle_error"]).max() < 0.5
    # At 0% the state is the flat pattern itself.
    flat = curvefold.simulate(square_with_crease(), percent=0)
    assert np.array_equal(flat["vertices"][:, :2], flat["development"])
    assert np.all(flat["vertices"][:, 2] == 0)


def test_simulate_reads_fold_and_svg_files_and_numpy_arrays(tmp_path):
    pattern = square_with_crease(angle=-180.0, assignment="M")
    fold_path = tmp_path / "crease.fold"
    fold_path.write_text(json.dumps(pattern))
    # The same sheet drawn as Origami Simulator draws it: black border, red mountain, full opacity
    # (180 degrees); 100 user units to the metre of the FOLD file's 1.
    svg_path = tmp_path / "crease.svg"
    svg_path.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100">'
        '<rect x="0" y="0" width="200" height="100" fill="none" stroke="#000000"/>'
        '<line x1="100" y1="0" x2="100" y2="100" stroke="#ff0000"/></svg>')
    as_arrays = dict(pattern, vertices_coords=np.array(pattern["vertices_coords"], float),
                     edges_vertices=np.array(pattern["edges_vertices"]))
    for source in (fold_path, str(fold_path), svg_path, as_arrays):
        result = curvefold.simulate(source, percent=50, settle=True)
        assert result["converged"], source
        assert abs(fold_angle_degrees(result) - 90.0) < 0.5, source
        assert np.abs(result["strain"]).max() < 1e-6
    # The dynamic solver gets there too, given steps.
    moving = curvefold.simulate(fold_path, percent=50, settle=False, steps=5000)
    assert not moving["converged"]
    assert abs(fold_angle_degrees(moving) - 90.0) < 2.0


def test_simulate_paper_mode_bends_the_facets_freely():
    result = curvefold.simulate(square_with_crease(), percent=50, paper=0.1)
    assert result["converged"]
    assert abs(fold_angle_degrees(result) - 45.0) < 0.5


def one_line(error):
    message = str(error.value)
    assert "\n" not in message, message
    return message


def test_simulate_bad_values_are_value_errors_naming_the_parameter():
    crossing = square_with_crease()
    crossing["edges_vertices"].append([0, 3])  # crosses the crease without a vertex
    crossing["edges_assignment"].append("M")
    crossing["edges_foldAngle"].append(-90)
    not_a_number = square_with_crease()
    not_a_number["vertices_coords"][2] = [float("nan"), 0]
    cases = [
        (lambda: curvefold.simulate(crossing), "pattern: "),
        (lambda: curvefold.simulate(not_a_number), "pattern: holds a NaN"),
        (lambda: curvefold.simulate({"vertices_coords": 5}), "pattern: "),
        (lambda: curvefold.simulate({"vertices_coords": [[0, 0]], "x": object()}), "pattern: "),
        (lambda: curvefold.simulate(square_with_crease(), percent=150), "percent: "),
        (lambda: curvefold.simulate(square_with_crease(), percent=float("nan")), "percent: "),
        (lambda: curvefold.simulate(square_with_crease(), paper=0), "paper: "),
        (lambda: curvefold.simulate(square_with_crease(), paper=0.1, modulus=0), "modulus: "),
        (lambda: curvefold.simulate(square_with_crease(), modulus=4), "modulus: only paper"),
        (lambda: curvefold.simulate(square_with_crease(), contact=False), "contact: only paper"),
        (lambda: curvefold.simulate(square_with_crease(), steps=-1), "steps: "),
    ]
    for call, prefix in cases:
        with pytest.raises(ValueError) as error:
            call()
        assert one_line(error).startswith(prefix), (prefix, str(error.value))
    for call, parameter in [
        (lambda: curvefold.simulate(3), "pattern"),
        (lambda: curvefold.simulate([1, 2]), "pattern"),
        (lambda: curvefold.simulate(square_with_crease(), percent="50"), "percent"),
        (lambda: curvefold.simulate(square_with_crease(), settle="yes"), "settle"),
        (lambda: curvefold.simulate(square_with_crease(), paper=0.1, contact=1), "contact"),
        (lambda: curvefold.simulate(square_with_crease(), steps=2.5), "steps"),
    ]:
        with pytest.raises(curvefold.ArgumentError) as error:
            call()
        assert one_line(error).startswith(parameter + ": "), (parameter, str(error.value))
    with pytest.raises(TypeError, match="^simulate\\(\\): missing or unexpected arguments"):
        curvefold.simulate(square_with_crease(), amount=50)


def test_simulate_files_that_cannot_be_read_are_os_errors_naming_the_path(tmp_path):
    for path in (tmp_path / "missing.fold", tmp_path):
        with pytest.raises(OSError) as error:
            curvefold.simulate(path)
        assert str(path) in one_line(error)
    fifo = tmp_path / "pipe.fold"
    os.mkfifo(fifo)
    with pytest.raises(OSError) as error:
        curvefold.simulate(fifo)  # refused, not read (it would block)
    assert str(fifo) in one_line(error)
    # A file that is there but is no crease pattern: its content is wrong, a ValueError naming it.
    text = tmp_path / "notes.txt"
    text.write_text("hello")
    with pytest.raises(ValueError) as error:
        curvefold.simulate(text)
    assert str(text) in one_line(error)


def test_simulate_reads_a_fold_dicts_frame_unit_as_a_files():
    # The 2 x 1 sheet in mm: 0.002 m wide, as the same FOLD file would be read (docs/formats.md).
    pattern = dict(square_with_crease(), frame_unit="mm")
    result = curvefold.simulate(pattern, percent=50, settle=True)
    assert abs(np.abs(result["development"]).max() - 0.002) < 1e-15


def obj_vertices(path):
    """The `v` lines of an OBJ the command line wrote (shortest round-trip text: exact doubles)."""
    return np.array([[float(x) for x in line.split()[1:4]]
                     for line in path.read_text().splitlines() if line.startswith("v ")])


def test_simulate_paper_mode_is_the_command_lines_bit_for_bit_with_its_contact(tmp_path):
    # A flat-foldable degree-4 vertex (tests/data, SimulateCli's): without self-contact its layers
    # settle through each other, 0.13 m from the state the command line settles with it.
    pattern = SOURCE / "tests" / "data" / "crease_patterns" / "vertex4_s7.fold"
    states = {}
    for contact, extra in ((True, []), (False, ["--no-contact"])):
        obj = tmp_path / f"contact_{contact}.obj"
        subprocess.run([CLI, "simulate", pattern, "--percent", "100", "--settle", "--paper", "0.1",
                        "--modulus", "3", "--obj", obj, *extra], capture_output=True, check=True)
        result = curvefold.simulate(pattern, percent=100, paper=0.1, modulus=3, contact=contact)
        assert np.array_equal(result["vertices"], obj_vertices(obj)), contact
        states[contact] = result["vertices"]
    assert np.abs(states[True] - states[False]).max() > 0.01
    # Design.simulate takes the same paper mode: a folded cylinder (its contact moves the settled
    # state 11 mm) as `simulate DESIGN --paper` settles it.
    design = curvefold.Design.new("cylinder", radius=0.05, resolution=8)
    design.fold(grab=(0.05, 0.1, 0.0), to=(0.03, 0.07, 0.02))
    design.save(tmp_path / "d.curvefold.json")
    subprocess.run([CLI, "simulate", tmp_path / "d.curvefold.json", "--percent", "100", "--settle",
                    "--paper", "0.1", "--obj", tmp_path / "d.obj"], capture_output=True, check=True)
    result = design.simulate(percent=100, paper=0.1)
    assert np.array_equal(result["vertices"], obj_vertices(tmp_path / "d.obj"))


# The command line's other options as keywords (issue 39, 5): each the same state bit for bit as
# `curvefold simulate` with the option, and a state the option moves, so a keyword left unused
# fails. Each case also checks the report the command line prints against the returned numbers.
WATERBOMB = SOURCE / "tests" / "data" / "crease_patterns" / "waterbomb_base.fold"


def simulate_cli(source, tmp_path, *options):
    """The OBJ's vertices and the report of `curvefold simulate SOURCE --settle OPTIONS`."""
    obj = tmp_path / "cli.obj"
    run = subprocess.run([CLI, "simulate", source, "--settle", "--obj", obj, *options],
                         capture_output=True, text=True, check=True)
    return obj_vertices(obj), run.stdout


def printed_report(result):
    """The command line's lines for a settled state, from the numbers simulate returns."""
    crossing = result["crossing_pairs"]
    if result["at_rounding_floor"]:
        verdict = (f"settled at the rounding floor (residual {result['residual']:.1e}, floor "
                   f"{result['rounding_floor']:.1e}) in {result['iterations']} iterations")
    else:
        verdict = (f"{'settled' if result['converged'] else 'NOT settled'} in "
                   f"{result['iterations']} iterations, residual {result['residual']:.1e}")
    line = (f"{verdict}, energy {result['energy']:.6g} (rose "
            f"in {result['energy_rises']}), largest strain {result['largest_strain']:.2e}, "
            f"largest crease angle error {result['largest_crease_angle_error']:.2f} degrees "
            f"(mean {result['mean_crease_angle_error']:.2f})")
    for count, what in ((result["wrong_side_creases"], "creases on the wrong side of flat"),
                        (result["past_flat_creases"], "creases past flat-folded")):
        line += f", {count} {what}" if count else ""
    line += f", self-intersection: {f'{crossing} triangle pairs cross' if crossing else 'none'}"
    lines = [line]
    if "motion" in result:
        motion = result["motion"]
        lines.append(f"folding motion: {motion['states']} states, followed to "
                     f"{motion['followed_to']:.1f}%"
                     + (" (the 100% angles)" if motion["reached_full"] else ", then linear"))
    return lines


@pytest.mark.parametrize("options, keywords", [
    (["--pin", "0.5,0.5"], dict(pin=[(0.5, 0.5)])),
    (["--pin", "1,0", "--pin=-1,-1"], dict(pin=["1,0", np.array([-1.0, -1.0])])),
    (["--glue", "-1,-1:1,1"], dict(glue=[((-1, -1), (1, 1))])),
    (["--glue=-1,1:1,-1"], dict(glue=["-1,1:1,-1"])),
    (["--stiffness", "origami-simulator"], dict(stiffness="origami-simulator")),
    (["--motion"], dict(motion=True)),
    (["--size", "50"], dict(size=50)),
], ids=["pin", "pins", "glue", "glue-text", "stiffness", "motion", "size"])
def test_simulate_keywords_are_the_command_lines_options_bit_for_bit(tmp_path, options, keywords):
    # The waterbomb base (9 vertices) at 50% in design mode, where every one of them moves it.
    expected, printed = simulate_cli(WATERBOMB, tmp_path, "--percent", "50", *options)
    result = curvefold.simulate(WATERBOMB, percent=50, **keywords)
    assert np.array_equal(result["vertices"], expected)
    plain = curvefold.simulate(WATERBOMB, percent=50)["vertices"]
    assert np.abs(plain - expected).max() > 0.05  # the option moves the state
    for line in printed_report(result):
        assert line in printed, (line, printed)


@pytest.mark.parametrize("surface, options, keywords", [
    ("cylinder", ["--pin", "PIN"], dict(pin=["PIN"])),
    ("cylinder", ["--glue", "GLUE"], dict(glue=["GLUE"])),
    ("cylinder", ["--stiffness", "origami-simulator"], dict(stiffness="origami-simulator")),
    ("cone", ["--glue", "slits", "--paper", "0.1"], dict(glue="slits", paper=0.1)),
], ids=["pin", "glue", "stiffness", "glue-slits"])
def test_design_simulate_keywords_are_the_command_lines_options_bit_for_bit(tmp_path, surface,
                                                                             options, keywords):
    # A folded cylinder at 50% (its creases and bending disagree there: the stiffnesses matter;
    # --motion finds no other motion for it, so the waterbomb above alone covers motion); a cone
    # with its slit glued in paper mode.
    design = curvefold.Design.new(surface, resolution=8)
    if surface == "cylinder":
        design = curvefold.Design.new(surface, radius=0.05, resolution=8)
        design.fold(grab=(0.05, 0.1, 0.0), to=(0.03, 0.07, 0.02))
    design.save(tmp_path / "d.curvefold.json")
    # Points of the flat sheet as the command line takes them (shortest round-trip text: exact).
    development = np.asarray(design.development)
    corner, far = development[0], development[np.argmax(np.linalg.norm(development - development[0],
                                                                       axis=1))]
    point = lambda p: f"{p[0]!r},{p[1]!r}"
    texts = {"PIN": point(corner), "GLUE": point(corner) + ":" + point(far)}
    options = [texts.get(option, option) for option in options]
    keywords = {key: [texts.get(v, v) for v in value] if isinstance(value, list) else value
                for key, value in keywords.items()}
    percent = 100 if "paper" in keywords else 50
    expected, printed = simulate_cli(tmp_path / "d.curvefold.json", tmp_path, "--percent",
                                     str(percent), *options)
    result = design.simulate(percent=percent, **keywords)
    assert np.array_equal(result["vertices"], expected)
    plain = design.simulate(percent=percent, paper=keywords.get("paper"))["vertices"]
    assert np.abs(plain - expected).max() > 1e-3  # the option moves the state
    for line in printed_report(result):
        assert line in printed, (line, printed)


def test_simulate_keywords_refuse_what_the_command_line_refuses_with_its_message(tmp_path):
    # Each bad value as an option and as a keyword: the command line's one line, less its "--",
    # is the ValueError's (one function checks both: engine/simulation/simulate_options.hpp).
    cases = [
        (["--pin", "40,40"], dict(pin=[(40, 40)])),
        (["--pin", "x"], dict(pin=["x"])),
        (["--pin", "nan,0"], dict(pin=["nan,0"])),
        (["--glue", "0,0:0.01,0"], dict(glue=[((0, 0), (0.01, 0))])),
        (["--glue", "0,0"], dict(glue="0,0")),
        (["--glue", "slits"], dict(glue="slits")),
        (["--stiffness", "soft"], dict(stiffness="soft")),
        (["--stiffness", "curvefold", "--paper", "0.1"], dict(stiffness="curvefold", paper=0.1)),
        (["--size", "0"], dict(size=0)),
        (["--size", "2e6"], dict(size=2e6)),
    ]
    for options, keywords in cases:
        run = subprocess.run([CLI, "simulate", WATERBOMB, "--percent", "50", "--obj",
                              tmp_path / "x.obj", *options], capture_output=True, text=True)
        assert run.returncode == 1 and not (tmp_path / "x.obj").exists(), options
        message = run.stderr.splitlines()[-1].removeprefix("curvefold: error: --")
        with pytest.raises(ValueError) as error:
            curvefold.simulate(WATERBOMB, percent=50, **keywords)
        assert not isinstance(error.value, TypeError), options
        assert one_line(error) == message, options
    # Only a crease pattern takes a size (a design is in metres): Design.simulate has no size.
    with pytest.raises(TypeError):
        curvefold.Design.new("square").simulate(size=50)
    for keywords in (dict(pin=(0.5, 0.5)), dict(pin="0.5,0.5"), dict(pin=[(0.5, 0.5, 0)]),
                     dict(glue=[(0, 0)]), dict(glue=5), dict(stiffness=3), dict(motion="yes"),
                     dict(size="50")):
        with pytest.raises(curvefold.ArgumentError) as error:
            curvefold.simulate(WATERBOMB, percent=50, **keywords)
        assert one_line(error).startswith(next(iter(keywords)) + ": "), keywords
