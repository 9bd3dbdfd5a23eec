"""Figures of paper 001's pre-sliding analysis: loops, stick/slip maps, lateral stiffness."""

import numpy as np
import pytest
from matplotlib.figure import Figure

from roughcontact.errors import InputError
from roughcontact.plotting.presliding import (
    plot_hysteresis_loops,
    plot_lateral_stiffness,
    plot_stick_slip_maps,
)


def test_hysteresis_loops_in_um_and_mN():
    delta = np.array([0.0, 1e-6, 2e-6, 1e-6, 0.0])
    force = np.array([0.0, 3e-3, 3.8e-3, -3e-3, -3.8e-3])
    fig = plot_hysteresis_loops([(delta, force, "simulation")], [(delta, 1.1 * force, "spot 1")])
    assert isinstance(fig, Figure)
    (ax,) = fig.axes
    lines = {line.get_label(): line for line in ax.get_lines() if not line.get_label().startswith("_")}
    assert set(lines) == {"simulation", "spot 1"}
    np.testing.assert_allclose(lines["simulation"].get_xdata(), [0, 1, 2, 1, 0])
    np.testing.assert_allclose(lines["simulation"].get_ydata(), [0, 3, 3.8, -3, -3.8])
    assert lines["spot 1"].get_linestyle() == "--"
    assert "µm" in ax.get_xlabel() and "mN" in ax.get_ylabel()
    with pytest.raises(InputError):
        plot_hysteresis_loops([(delta, force[:3], "bad")])


def test_stick_slip_maps_fixed_scale_and_slip_fraction():
    y, x = np.mgrid[-1:1:41j, -1:1:41j]
    r = np.hypot(x, y)
    shear = np.where(r < 0.5, 0.6, 1.0)
    shear[r > 1] = np.nan
    maps = {"25 mN, A": shear, "25 mN, C": np.where(r > 1, np.nan, 1.0)}
    fig = plot_stick_slip_maps(maps, (-50e-6, 50e-6, -50e-6, 50e-6), zoom=(-20e-6, 20e-6, -20e-6, 20e-6))
    panels = [ax for ax in fig.axes if ax.get_images()]
    assert len(panels) == 2
    image = panels[0].get_images()[0]
    assert image.get_clim() == (0.0, 1.0)
    assert panels[0].get_xlim() == pytest.approx((-20, 20))
    assert "µm" in panels[0].get_xlabel()
    assert panels[0].get_title().startswith("25 mN, A (slip ")
    assert panels[1].get_title() == "25 mN, C (slip 100 %)"
    colourbar = [ax for ax in fig.axes if "slip" in ax.get_ylabel()]
    assert colourbar, "colour bar labelled with the slip level"
    with pytest.raises(InputError):
        plot_stick_slip_maps({}, (0, 1, 0, 1))
    with pytest.raises(InputError, match="extent"):
        plot_stick_slip_maps(maps, (0, 1))


def test_lateral_stiffness_markers_lines_and_both_mindlin_forms():
    loads = np.array([25e-3, 50e-3, 75e-3])
    sim = {"A": [4e4, 5e4, 6e4], "B": [3e4, 4e4, 5e4], "C": [2e4, 3e4, 4e4]}
    johnson = {p: np.asarray(v) * 1.5 for p, v in sim.items()}
    mindlin = {"johnson": johnson, "printed": {p: 4 * v for p, v in johnson.items()}}
    fig = plot_lateral_stiffness(loads, simulated=sim, measured=sim, mindlin=mindlin)
    (ax,) = fig.axes
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert lines["A simulated"].get_marker() == "o" and lines["A simulated"].get_linestyle() == "None"
    assert lines["A measured"].get_linestyle() == "-"
    assert lines["A Mindlin (Johnson)"].get_linestyle() == "--"
    assert lines["A Mindlin (paper 001 as printed, 4x)"].get_linestyle() == "-."
    assert lines["A simulated"].get_color() == "tab:red" and lines["C measured"].get_color() == "black"
    np.testing.assert_allclose(lines["A simulated"].get_xdata(), [25, 50, 75])
    np.testing.assert_allclose(lines["A simulated"].get_ydata(), [40, 50, 60])  # mN/um
    ratio = (
        lines["B Mindlin (paper 001 as printed, 4x)"].get_ydata() / lines["B Mindlin (Johnson)"].get_ydata()
    )
    np.testing.assert_allclose(ratio, 4.0)
    assert "mN/µm" in ax.get_ylabel()
    with pytest.raises(InputError):
        plot_lateral_stiffness(loads, simulated={"A": [1.0, 2.0]})
    with pytest.raises(InputError, match="normalisation"):
        plot_lateral_stiffness(loads, mindlin={"textbook": johnson})


def test_no_lateral_stiffness_figure_without_an_analysed_loop():
    from roughcontact.plotting.cases import ResultCase
    from roughcontact.plotting.presliding import lateral_stiffness_figure

    scalars = {"normal_force": 0.025} | {f"K_L_{p}": None for p in "ABC"}
    cases = [ResultCase("no loop", scalars, None, {"material": "HDPE", "radius": 5e-3})]
    assert lateral_stiffness_figure(cases) is None  # Mindlin's curves alone would compare with nothing


def test_the_path_figure_names_points_by_the_axis_it_draws():
    from roughcontact.plotting.presliding import plot_displacement_path

    delta = np.array([0.0, 1.0, 2.0, 1.0, 0.0]) * 1e-6
    by_step = plot_displacement_path({"programme": delta}, points={"A": 2})
    labels = (
        [t.get_text() for t in by_step.axes[0].get_legend().get_texts()]
        if by_step.axes[0].get_legend()
        else []
    )
    assert labels == ["programme", "point A (step 2)"]
    by_row = plot_displacement_path(
        {"programme": delta}, points={"A": 2}, positions={"programme": np.array([0, 0.5, 1, 2, 3.0])}
    )
    assert by_row.axes[0].get_xlabel().startswith("programme row")
    assert [t.get_text() for t in by_row.axes[0].get_legend().get_texts()] == ["programme", "point A (row 1)"]
