"""Several Python threads on one Design (issue 40, 2). Each scenario (thread_scenarios.py) runs in a
child process, so a crash or a hang fails its test instead of killing pytest."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

SCENARIOS = Path(__file__).with_name("thread_scenarios.py")


def run_scenario(name, rounds, timeout=120):
    try:
        done = subprocess.run([sys.executable, str(SCENARIOS), name, str(rounds)],
                              capture_output=True, text=True, timeout=timeout, env=dict(os.environ))
    except subprocess.TimeoutExpired:
        pytest.fail(f"{name} did not finish in {timeout} s (deadlock)")
    assert done.returncode == 0, f"{name} exited {done.returncode}: {done.stdout[-2000:]}{done.stderr[-2000:]}"
    assert done.stdout.strip().endswith("ok")


def test_two_threads_folding_one_design_make_every_fold():
    # Before the design lock: SIGSEGV, or made-up errors ("not manifold"), in 5 of 5 runs.
    run_scenario("two_folders", 3)


def test_threads_folding_undoing_and_reading_one_design_finish():
    # The first numpy array made in two threads at once deadlocked (pybind11's npy_api guard):
    # only a fresh process makes its first array, so several of them.
    for _ in range(4):
        run_scenario("fold_undo_vertices", 1, timeout=60)


def test_reading_the_arrays_while_another_thread_folds_gives_one_mesh():
    run_scenario("fold_while_reading", 3)


def test_checking_or_exporting_while_another_thread_folds():
    run_scenario("fold_while_checking", 3)
    run_scenario("fold_while_exporting", 3)


def test_threads_replaying_studio_recordings_at_once():
    # Before replays took turns: ImGui assertions or SIGSEGV (its one current context).
    run_scenario("replays", 1)
