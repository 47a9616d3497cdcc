"""Several Python threads on one Design (issue 40, 2), run by test_threads.py in a child process
(a crash or a hang there fails the test instead of killing pytest):

    python thread_scenarios.py SCENARIO ROUNDS

Each round makes a fresh Design and runs the scenario's threads on it. Prints "ok" when every
round ended with a valid design; any exception in a thread is printed and exits 1."""

import os
import random
import sys
import tempfile
import threading

import curvefold  # no numpy before it: the first array is made by the module (the deadlock's case)


def fold_point(rng):
    x, y = rng.uniform(-0.09, 0.09), rng.uniform(-0.09, 0.09)
    return {"grab": (x, y, 0.0), "to": (0.8 * x, 0.8 * y, 0.03)}


def run_threads(*bodies):
    errors = []

    def guarded(body):
        try:
            body()
        except Exception as e:  # noqa: BLE001: reported below, with its type
            errors.append(f"{type(e).__name__}: {e}")

    threads = [threading.Thread(target=guarded, args=(body,)) for body in bodies]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    if errors:
        print("\n".join(errors))
        sys.exit(1)


def assert_valid(design):
    """The arrays agree with each other and the design passes its invariants but the paper's
    self-crossings (random folds may pass it through itself)."""
    vertices, triangles = design.vertices, design.triangles
    assert triangles.max() < len(vertices), "a triangle indexes past the vertices"
    assert len(design.development) == len(vertices)
    failures = [line for line in design.check(allow_self_intersection=True).failures]
    assert not failures, failures


def folder(design, seed, folds):
    rng = random.Random(seed)
    return lambda: [design.fold(**fold_point(rng)) for _ in range(folds)]


def two_folders(design, round_):
    """Two threads each make 20 folds on one design."""
    run_threads(folder(design, 2 * round_, 20), folder(design, 2 * round_ + 1, 20))
    assert len(design.folds) == 40, len(design.folds)


def fold_undo_vertices(design, round_):
    """Two threads fold, undo and read `vertices` (40 operations in all)."""
    def body(seed):
        rng = random.Random(seed)
        def run():
            for i in range(20):
                operation = i % 3
                if operation == 0:
                    design.fold(**fold_point(rng))
                elif operation == 1:
                    design.undo()
                else:
                    vertices, triangles = design.vertices, design.triangles
                    assert vertices.shape[1] == 3 and triangles.shape[1] == 3
        return run
    run_threads(body(2 * round_), body(2 * round_ + 1))


def fold_while_reading(design, round_):
    """One thread folds, the other reads the arrays meanwhile: the arrays of one mesh() agree."""
    done = threading.Event()
    def reader():
        while not done.is_set():
            vertices, triangles, development = design.mesh()
            assert triangles.max() < len(vertices), "a triangle indexes past the vertices"
            assert len(development) == len(vertices)
            assert design.vertices.shape[1] == 3
    def fold_then_stop():
        try:
            folder(design, round_, 15)()
        finally:
            done.set()
    run_threads(fold_then_stop, reader)


def fold_while_checking(design, round_):
    """One thread folds while the other checks the design."""
    done = threading.Event()
    def checker():
        while not done.is_set():
            design.check(allow_self_intersection=True)
    def fold_then_stop():
        try:
            folder(design, round_, 15)()
        finally:
            done.set()
    run_threads(fold_then_stop, checker)


def fold_while_exporting(design, round_):
    """One thread folds while the other exports the design."""
    done = threading.Event()
    folder_out = tempfile.mkdtemp()
    def exporter():
        while not done.is_set():
            design.export(obj=os.path.join(folder_out, "a.obj"),
                          svg=os.path.join(folder_out, "a.svg"))
    def fold_then_stop():
        try:
            folder(design, round_, 15)()
        finally:
            done.set()
    run_threads(fold_then_stop, exporter)


def replays(design, round_):
    """Four threads replay the studio recording at once: each gets the recording's design."""
    source = os.environ.get("CURVEFOLD_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    recording = os.path.join(source, "examples", "recordings", "xr_studio.jsonl")
    expected = curvefold.replay(recording).folds
    def replay():
        for _ in range(2):
            assert curvefold.replay(recording).folds == expected, "another design"
    run_threads(*[replay] * 4)


# check and export take long on the full sheet; a coarse one calls them often enough to race.
SHEETS = {"fold_while_checking": {"resolution": 6}, "fold_while_exporting": {"resolution": 6}}

SCENARIOS = {f.__name__: f for f in
             [two_folders, fold_undo_vertices, fold_while_reading, fold_while_checking,
              fold_while_exporting, replays]}

if __name__ == "__main__":
    scenario, rounds = SCENARIOS[sys.argv[1]], int(sys.argv[2])
    sys.setswitchinterval(1e-5)  # switch threads often, so a race shows in few rounds
    for round_ in range(rounds):
        design = curvefold.Design.new("square", **SHEETS.get(scenario.__name__, {}))
        scenario(design, round_)
        assert_valid(design)
    print("ok")
