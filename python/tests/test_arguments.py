"""One rule for bad arguments (issue 40, 3): a bad value is ValueError naming its parameter (a
value of the wrong type is curvefold.ArgumentError, a ValueError and a TypeError); a file that
cannot be read or written is OSError naming the path. Each in one line."""

import os
import re
import subprocess
import sys

import numpy as np
import pytest

import curvefold


def one_line(error):
    message = str(error.value)
    assert "\n" not in message, message
    return message


@pytest.mark.parametrize("size", [None, "0.2", [0.2]])
def test_a_parameter_of_the_wrong_type_is_named(size):
    with pytest.raises(ValueError, match=r"^size: expected a number") as error:
        curvefold.Design.new("square", size=size)
    assert isinstance(error.value, TypeError) and isinstance(error.value, curvefold.ArgumentError)
    one_line(error)


def test_a_number_out_of_range_is_a_value_error_naming_it():
    with pytest.raises(ValueError, match=r"^size: .* is out of range") as error:
        curvefold.Design.new("square", size=10**400)
    one_line(error)
    assert not isinstance(error.value, TypeError)


def test_wrong_types_elsewhere_are_one_line_naming_the_parameter(tmp_path):
    design = curvefold.Design.new("square")
    cases = [
        (lambda: curvefold.Design.new(3), "surface"),
        (lambda: curvefold.Design.new("square", symmetry=4), "symmetry"),
        (lambda: curvefold.Design.load(3), "path"),
        (lambda: design.save(None), "path"),
        (lambda: design.fold(grab="abc", to=(0, 0, 0)), "grab"),
        (lambda: design.fold(grab=(0, 0, 0), to={"x": 1}), "to"),
        (lambda: design.check(allow_self_intersection="no"), "allow_self_intersection"),
        (lambda: design.export(svg=3), "svg"),
        (lambda: design.export(pdf=str(tmp_path / "a.pdf"), paper=4), "paper"),
        (lambda: design.export(cut_svg=str(tmp_path / "a.svg"), perforate="3,1"), "perforate"),
        (lambda: design.render(width="800"), "width"),
        (lambda: design.render(view=None), "view"),
        (lambda: curvefold.replay(3.5), "recording"),
    ]
    for call, parameter in cases:
        with pytest.raises(curvefold.ArgumentError) as error:
            call()
        assert one_line(error).startswith(parameter + ": "), (parameter, str(error.value))


def test_a_point_is_three_numbers_not_a_column():
    design = curvefold.Design.new("square")
    with pytest.raises(ValueError, match=r"^grab: expected \(x, y, z\).*shape \(3, 1\)") as error:
        design.fold(grab=np.array([[0.05], [0.05], [0.0]]), to=(0.04, 0.04, 0.02))
    one_line(error)
    with pytest.raises(ValueError, match="^to: expected finite coordinates"):
        design.fold(grab=(0.05, 0.05, 0.0), to=(0.04, float("nan"), 0.02))
    assert design.folds == []
    # A (3,) array and any 3-sequence still are points.
    assert design.fold(grab=np.array([0.05, 0.05, 0.0]), to=[0.04, 0.04, 0.02]).folded


def test_a_missing_file_is_an_os_error_naming_it_everywhere(tmp_path):
    for read, name in [(curvefold.Design.load, "a.curvefold.json"),
                       (curvefold.Design.from_obj, "a.obj"), (curvefold.replay, "a.jsonl")]:
        missing = tmp_path / name
        with pytest.raises(OSError, match="cannot read .*" + name) as error:
            read(missing)
        one_line(error)
        assert not isinstance(error.value, ValueError)


def test_a_file_over_the_limit_is_a_value_error_as_elsewhere(tmp_path):
    huge = tmp_path / "huge.curvefold.json"
    with open(huge, "wb") as f:
        f.truncate(65 << 20)  # sparse: no disk written
    with pytest.raises(ValueError, match="huge.curvefold.json: .*more than a design may hold") as e:
        curvefold.Design.load(huge)
    one_line(e)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
def test_a_fifo_is_refused_at_once_not_read_forever(tmp_path):
    # In a child process: before, each call blocked forever in open() holding the GIL.
    fifo = tmp_path / "f"
    os.mkfifo(fifo)
    script = f"""
import curvefold
for read in (curvefold.Design.from_obj, curvefold.Design.load, curvefold.replay):
    try:
        read({str(fifo)!r})
    except OSError as e:
        assert "not a regular file" in str(e) and {str(fifo)!r} in str(e), e
    else:
        raise SystemExit("read a FIFO")
print("refused")
"""
    try:
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                              timeout=60)
    except subprocess.TimeoutExpired:
        pytest.fail("reading a FIFO blocked")
    assert done.returncode == 0 and done.stdout.strip() == "refused", done.stderr


def test_export_never_writes_over_the_file_the_design_came_from(tmp_path):
    path = tmp_path / "x.curvefold.json"
    curvefold.Design.new("square").save(path)
    before = path.read_bytes()
    loaded = curvefold.Design.load(str(path))
    for parameter in ["fold", "svg", "obj", "gltf", "pdf", "cut_svg"]:
        with pytest.raises(ValueError, match=f"^{parameter}: .*x.curvefold.json is the file this "
                                             "design was read from") as error:
            loaded.export(**{parameter: str(path)})
        one_line(error)
    # Through another spelling of the same path, and a symbolic link to it.
    (tmp_path / "link.json").symlink_to(path)
    with pytest.raises(ValueError, match="read from"):
        loaded.export(svg=str(tmp_path / "." / "link.json"))
    assert path.read_bytes() == before
    loaded.save(path)  # a design may be saved where it was opened, as `curvefold fold D -o D`
    # An OBJ read is not overwritten by saving the design there.
    loaded.export(obj=str(tmp_path / "a.obj"))
    from_obj = curvefold.Design.from_obj(tmp_path / "a.obj")
    with pytest.raises(ValueError, match="^path: .*a.obj is the file this design was read from"):
        from_obj.save(tmp_path / "a.obj")


def test_missing_or_unexpected_arguments_are_one_line_naming_the_call():
    design = curvefold.Design.new("square")
    for call, expected in [
        (lambda: design.fold(grab=(0, 0, 0)), "Design.fold(): .* it takes (*, grab, to)"),
        (lambda: design.fold((0, 0, 0), (0, 0, 0.01)), "Design.fold(): .* it takes (*, grab, to)"),
        (lambda: design.export(svg="a.svg", colour="red"), "Design.export(): .*svg=None"),
        (lambda: curvefold.Design.new(), "Design.new(): .* it takes (surface, *, symmetry=None"),
        (lambda: curvefold.replay(), "replay(): .* it takes (recording)"),
    ]:
        with pytest.raises(TypeError) as error:
            call()
        assert re.match(re.escape(expected).replace(r"\.\*", ".*"), one_line(error)), str(error.value)
