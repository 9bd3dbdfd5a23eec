"""Numbers for a reader (roughcontact.study.display) and what the figures promise (captions, legends,
colour scales)."""

import math

import numpy as np
import pytest
from matplotlib.figure import Figure

from roughcontact.plotting.layout import colour_scale, legend
from roughcontact.study import display
from roughcontact.study.kind import figure_caption
from roughcontact.study.kinds import get_kind, kind_names


def test_a_column_shares_the_prefix_of_its_largest_value_and_names_it_in_the_header():
    rows = [
        {"Rq [m]": 2.805e-6, "mu": 0.25, "iterations": 12},
        {"Rq [m]": 4.1e-7, "mu": 0.3, "iterations": 7},
    ]
    titles, cells = display.columns(rows)
    assert titles == ["Rq (µm)", "mu", "iterations"]
    assert cells == [["2.805", "0.25", "12"], ["0.41", "0.3", "7"]]


def test_units_of_plain_names_come_from_the_kind_and_blank_columns_are_left_out():
    rows = [{"force": 5e-3, "note": None, "case": "ab12"}, {"force": 2.5e-2, "note": "", "case": "ab12"}]
    titles, cells = display.columns(rows, {"force": "N"})
    assert titles == ["force (mN)"] and cells == [["5"], ["25"]]  # one case id says nothing


def test_numbers_up_to_a_million_are_written_out():
    assert display.scaled([2.019e10], "1/m^2") == ("1/mm²", ["20190"])
    assert display.scaled([3.2e12], "") == ("", ["3.2e+12"])


def test_a_quantity_table_shows_each_row_in_its_own_unit():
    rows = [
        {"quantity": "summit_radius", "unit": "m", "paper": 5.08e-6, "this_case": 5.0823e-6},
        {"quantity": "bandwidth", "unit": "", "paper": None, "this_case": 6.894},
    ]
    titles, cells = display.columns(rows)
    assert titles == ["quantity", "paper", "this_case"]  # the unit is in each cell
    assert cells[0][1:] == ["5.08 µm", "5.082 µm"] and cells[1][1:] == ["", "6.894"]


def test_text_and_nan_cells():
    assert display.scaled(["Ra 1.45 nm", 3.0], "m") is None  # a label column stays text
    assert display.scaled([math.nan, 1e-9], "m") == ("nm", ["", "1"])
    assert display.shown(None, "m") == "-" and display.shown(math.nan, "m") == "-"
    assert display.shown(2.5e-8, "m") == "25 nm" and display.shown(7, None) == "7"
    assert display.split_header(display.header("K_L_A", "N/m")) == ("K_L_A", "N/m")


def test_every_figure_of_every_kind_has_a_caption():
    kinds = [get_kind(name) for name in kind_names()]
    missing = [f"{k.name}/{n}" for k in kinds for n, f in k.figures.items() if len(figure_caption(f)) < 40]
    assert not missing


def test_a_legend_lists_only_what_is_drawn():
    ax = Figure().add_subplot()
    ax.plot([1, 2], [1, 2], label="drawn")
    ax.plot([1, 2], [math.nan, math.nan], label="undefined everywhere")
    ax.set_yscale("log")
    ax.plot([1, 2], [-1.0, 0.0], label="not positive on a log axis")
    legend(ax)
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["drawn"]
    empty = Figure().add_subplot()
    empty.plot([1], [math.nan], label="nothing")
    legend(empty)
    assert empty.get_legend() is None


def test_one_spike_does_not_set_the_colour_scale():
    field = np.zeros((100, 100))
    field[:40, :25] = np.linspace(1e6, 2e6, 1000).reshape(40, 25)  # 10 % of the map loaded
    field[5, 5] = 1e9  # one spike
    pressure = colour_scale(field, from_zero=True)
    assert pressure.low == 0 and pressure.high < 2.1e6 and pressure.extend == "max" and pressure.words
    heights = colour_scale(np.r_[np.linspace(-1, 1, 999), 50.0])
    assert heights.high < 1.01 and "clipped" in heights.words
    full = colour_scale(np.linspace(0, 1, 10), percentiles=(0, 100))
    assert (full.low, full.high, full.words) == (0, 1, "")


@pytest.mark.parametrize("fields", [(np.ones((4, 4)), 3 * np.ones((4, 4)))])
def test_panels_share_one_scale(fields):
    shared = colour_scale(*fields, from_zero=True, percentiles=(0, 100))
    assert (shared.low, shared.high) == (0, 3)


def test_specks_amid_undefined_points_do_not_set_a_height_scale():
    """A few stray pixels inside a lost region (frt-2.frt: 0.75 % of its points) keep the map readable."""
    from roughcontact.plotting.topography import plot_heights
    from roughcontact.topography import Topography

    rng = np.random.default_rng(1)
    heights = rng.normal(0.0, 1e-9, (60, 60))
    undefined = np.zeros(heights.shape, dtype=bool)
    undefined[:, :20] = True
    undefined[::6, 2:18:6] = False  # 30 isolated pixels (0.7 % of the defined ones), far off
    heights[::6, 2:18:6] = -70e-6
    fig, ax = plot_heights(Topography(heights, 1e-6), undefined=undefined)
    low, high = ax.collections[0].get_clim()
    assert -5 < low < 0 < high < 5  # nm: set by the real surface, not by the -70 um specks
    assert "30 specks" in ax.get_title()
