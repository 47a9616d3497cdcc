"""Builds the extension `curvefold._curvefold` with the project's CMake (pyproject.toml)."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent


class CMakeModule(Extension):
    def __init__(self):
        super().__init__("curvefold._curvefold", sources=[])


class CMakeBuild(build_ext):
    """Configures the project for the module alone (no tests, benchmarks) and builds its target."""

    def build_extension(self, ext):
        # One folder below the source, as build/ is, and with build/'s flags (scripts/build.sh:
        # -Werror under CI): ccache rewrites paths relative to the build folder, so every object
        # that scripts/build.sh compiled is a hit here (CI builds both: 331 s -> seconds).
        build = SOURCE / "build-python"
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        werror = ["-DCURVEFOLD_WERROR=ON"] if os.environ.get("CI") == "true" else []
        subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(build), "-G", "Ninja",
                        "-DCMAKE_BUILD_TYPE=Release", "-DCURVEFOLD_BUILD_TESTS=OFF",
                        "-DCURVEFOLD_BUILD_BENCHMARKS=OFF", "-DCURVEFOLD_PYTHON=ON",
                        f"-DPython3_EXECUTABLE={sys.executable}", *werror], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "_curvefold",
                        "-j", os.environ.get("CURVEFOLD_JOBS", "2")], check=True)
        built = next((build / "python" / "curvefold").glob("_curvefold*.so"))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(
    packages=["curvefold"],
    package_dir={"": "python"},
    package_data={"curvefold": ["__init__.pyi", "py.typed"]},
    ext_modules=[CMakeModule()],
    cmdclass={"build_ext": CMakeBuild},
    # Beside, not inside, the CMake build folder build/; CMake's own is build-python/.
    options={"build": {"build_base": "build-python/setuptools"}},
)
