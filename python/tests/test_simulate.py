"""Design.simulate: the bar-and-hinge simulation from Python (issue 39, 5)."""

import numpy as np
import pytest

import curvefold


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
