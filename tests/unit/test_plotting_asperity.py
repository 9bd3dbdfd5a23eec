"""Figures of paper 002: Fig. 7 curves, contact area, von Mises maps."""

import numpy as np
import pytest

from roughcontact.materials import get_material
from roughcontact.papers.paper002 import compress_island, paper002_island
from roughcontact.plotting import plot_area_load, plot_load_interference, plot_von_mises_maps

CURVE = {
    "branch": np.array(["loading"] * 3 + ["unloading"] * 2),
    "approach": np.array([0.0, 1e-8, 2e-8, 1.5e-8, 1e-8]),
    "force": np.array([25e-6, 4e-4, 1e-3, 5e-4, 25e-6]),
    "contact_area": np.array([1e-12, 5e-12, 9e-12, 7e-12, 2e-12]),
}


def test_fig7_scales_interference_by_omega_c_and_load_to_micronewtons():
    measured = {"approach": np.array([0.0, 2e-8]), "force": np.array([25e-6, 1e-3])}
    fig, ax = plot_load_interference({"KKE": CURVE}, 1e-8, measured=measured)
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert set(lines) == {"KKE, loading", "KKE, unloading", "measured"}
    np.testing.assert_allclose(lines["KKE, loading"].get_xdata(), [0, 1, 2], rtol=1e-12, atol=0)
    np.testing.assert_allclose(lines["KKE, loading"].get_ydata(), [25, 400, 1000], rtol=1e-12, atol=0)
    assert lines["KKE, unloading"].get_linestyle() == "--"
    # the unloading branch starts at the peak, so the two branches meet there
    np.testing.assert_allclose(lines["KKE, unloading"].get_xdata(), [2, 1.5, 1], rtol=1e-12, atol=0)


def test_area_plot_draws_loading_solid_and_unloading_dashed_in_one_colour():
    fig, ax = plot_area_load({"KKE": CURVE})
    loading, unloading = ax.get_lines()
    np.testing.assert_allclose(loading.get_ydata(), [1, 5, 9], rtol=1e-12, atol=0)
    branch = np.asarray(CURVE["branch"])
    expected = np.asarray(CURVE["contact_area"])[branch != "loading"] / 1e-12
    expected = np.concatenate([[9.0], expected])  # the dashed branch starts at the peak
    np.testing.assert_allclose(unloading.get_ydata(), expected, rtol=1e-12, atol=0)
    assert unloading.get_linestyle() == "--" and unloading.get_color() == loading.get_color()


def test_von_mises_maps_one_panel_per_step():
    run = compress_island(
        paper002_island(24),
        get_material("SU-8"),
        loading_forces=[0, 25e-6, 1e-3],
        unloading_forces=[5e-4, 0.0],
    )
    fig, axes = plot_von_mises_maps(run, [1, 2, 3, 4])
    visible = [ax for ax in axes if ax.get_visible()]
    assert len(visible) == 4
    assert visible[1].get_title() == "loading, W = 1000 µN"
    assert visible[3].get_title() == "unloading, W = 0 µN"
    assert pytest.approx(run.steps[2].force, rel=1e-6, abs=0) == 1e-3
