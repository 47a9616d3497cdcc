"""`import curvefold` loads no window toolkit (issue 40, 2): the module links the studio panel's
core for replay (Dear ImGui, static, no window) but not the desktop's side (GLFW, GLib's GDBus)."""

import subprocess
import sys
from pathlib import Path

import pytest

import curvefold

WINDOWING = ("libglfw", "libgio-", "libgobject-", "libglib-", "libgtk", "libimgui")


def test_the_module_needs_no_window_toolkit():
    module = Path(curvefold._curvefold.__file__)
    closure = subprocess.run(["ldd", str(module)], capture_output=True, text=True, check=True).stdout
    assert "libcairo" in closure  # the list is the module's (PDF export needs Cairo)
    assert not [line for line in closure.splitlines() if any(name in line for name in WINDOWING)]


@pytest.mark.skipif(not Path("/proc/self/maps").exists(), reason="needs /proc")
def test_importing_and_replaying_loads_no_window_toolkit():
    source = Path(__file__).resolve().parents[2]
    script = ("import curvefold, sys; curvefold.replay(sys.argv[1]); "
              "print(open('/proc/self/maps').read())")
    maps = subprocess.run([sys.executable, "-c", script,
                           str(source / "examples" / "recordings" / "xr_studio.jsonl")],
                          capture_output=True, text=True, check=True).stdout
    assert "_curvefold" in maps
    assert not [line for line in maps.splitlines() if any(name in line for name in WINDOWING)]
