# Type stubs for curvefold (the C++ module _curvefold and this package).
from os import PathLike
from typing import Any, Literal, Sequence

import numpy as np
import numpy.typing as npt

# A point is three numbers: a 3-sequence or a (3,) array (not (3, 1)), finite.
Point = Sequence[float] | npt.NDArray[np.floating[Any]]
# A point of the flat sheet in metres, (x, y) (simulate's pin and glue; "X,Y" as a str too).
SheetPoint = Sequence[float] | npt.NDArray[np.floating[Any]]

# The rule for every call: a bad value raises ValueError naming its parameter; a value of the wrong
# type raises ArgumentError (a ValueError and a TypeError) naming it; a file that cannot be read or
# written (missing, a folder, a FIFO, no permission) raises OSError naming the path.
class ArgumentError(ValueError, TypeError): ...

class FoldResult:
    @property
    def folded(self) -> bool: ...
    @property
    def grabbed(self) -> list[float]: ...
    @property
    def plane_point(self) -> list[float]: ...
    @property
    def plane_normal(self) -> list[float]: ...
    @property
    def triangles(self) -> int: ...
    @property
    def images(self) -> int: ...
    @property
    def notes(self) -> str: ...

class CheckResult:
    @property
    def passed(self) -> bool: ...
    @property
    def summary(self) -> str: ...
    @property
    def lines(self) -> list[tuple[bool, str]]: ...
    @property
    def failures(self) -> list[str]: ...
    @property
    def self_intersections(self) -> int: ...
    @property
    def contacts(self) -> int: ...
    @property
    def max_edge_length_error(self) -> float: ...
    @property
    def length_tolerance(self) -> float: ...
    @property
    def crease_curves(self) -> int: ...
    @property
    def mountain_edges(self) -> int: ...
    @property
    def valley_edges(self) -> int: ...
    def __bool__(self) -> bool: ...

class Design:
    @staticmethod
    def new(surface: str, *, symmetry: str | None = None, **parameters: float) -> Design: ...
    @staticmethod
    def from_obj(
        source: str | PathLike[str] | npt.ArrayLike,
        triangles: npt.ArrayLike | None = None,
        development: npt.ArrayLike | None = None,
    ) -> Design: ...
    @staticmethod
    def load(path: str | PathLike[str]) -> Design: ...
    def save(self, path: str | PathLike[str]) -> None: ...
    def simulate(
        self, *, percent: float = 100.0, settle: bool = True, paper: float | None = None,
        modulus: float | None = None, contact: bool = True, steps: int = 2000,
        stiffness: str | None = None, motion: bool = False,
        pin: Sequence[SheetPoint | str] | None = None,
        glue: str | Sequence[tuple[SheetPoint, SheetPoint] | str] | None = None,
    ) -> dict[str, Any]: ...
    def fold(self, *, grab: Point, to: Point) -> FoldResult: ...
    def undo(self) -> bool: ...
    def redo(self) -> bool: ...
    @property
    def folds(self) -> list[dict[str, Any]]: ...
    @property
    def symmetry(self) -> str: ...
    @property
    def surface(self) -> str: ...
    def check(self, allow_self_intersection: bool = False) -> CheckResult: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def development(self) -> npt.NDArray[np.float64]: ...
    @property
    def triangles(self) -> npt.NDArray[np.uint32]: ...
    def mesh(
        self,
    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32], npt.NDArray[np.float64]]: ...
    def creases(self) -> dict[str, Any]: ...
    def to_fold(self) -> dict[str, Any]: ...
    def export(
        self,
        *,
        fold: str | PathLike[str] | None = None,
        svg: str | PathLike[str] | None = None,
        obj: str | PathLike[str] | None = None,
        gltf: str | PathLike[str] | None = None,
        pdf: str | PathLike[str] | None = None,
        cut_svg: str | PathLike[str] | None = None,
        perforate: tuple[float, float] | None = None,
        paper: Literal["a4", "letter", "a3", "fit"] = "a4",
        angles: bool = False,
    ) -> None: ...
    def fit(
        self,
        target: str | PathLike[str] | Design,
        *,
        folds: int = 6,
        time: float | None = None,
        seed: int = 1,
        evaluations: int | None = None,
        allow_self_intersection: bool = False,
    ) -> dict[str, Any]: ...
    def render(
        self,
        width: int = 800,
        height: int = 600,
        *,
        view: Literal["iso", "front", "back", "top", "left", "right"] = "iso",
        crease_pattern: bool = False,
    ) -> npt.NDArray[np.uint8]: ...

def distance(
    a: str | PathLike[str] | Design,
    b: str | PathLike[str] | Design,
    *,
    samples: int = 20000,
    seed: int = 1,
    png: str | PathLike[str] | None = None,
) -> dict[str, float]: ...
def fit(
    target: str | PathLike[str] | Design,
    *,
    folds: int = 6,
    time: float | None = None,
    seed: int = 1,
    evaluations: int | None = None,
    start: str | None = None,
    allow_self_intersection: bool = False,
) -> tuple[Design, dict[str, Any]]: ...
def surfaces() -> dict[str, dict[str, Any]]: ...

# What Design.simulate and simulate return: vertices (n, 3) float64, development (n, 2) float64,
# triangles (m, 3) uint32, edges (e, 2) uint32, assignment (str, one FOLD letter per edge), strain
# (e,) float64, crease_angle_error (e,) float64 degrees; what `curvefold simulate` prints of the
# state: largest_strain, largest_crease_angle_error and mean_crease_angle_error (float, degrees),
# wrong_side_creases, past_flat_creases, crossing_pairs (int), converged (bool), iterations and
# energy_rises (int, 0 without settle), residual (float), energy (float, with settle), motion
# (with motion=True: {states, followed_to, reached_full}); notes (list[str]).
def simulate(
    pattern: dict[str, Any] | str | PathLike[str],
    *,
    percent: float = 100.0,
    settle: bool = True,
    paper: float | None = None,
    modulus: float | None = None,
    contact: bool = True,
    steps: int = 2000,
    stiffness: str | None = None,
    motion: bool = False,
    pin: Sequence[SheetPoint | str] | None = None,
    glue: str | Sequence[tuple[SheetPoint, SheetPoint] | str] | None = None,
    size: float | None = None,
) -> dict[str, Any]: ...
def replay(recording: str | PathLike[str]) -> Design: ...
