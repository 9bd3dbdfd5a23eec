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
from roughcontact.units import quantity


def test_a_column_shares_the_prefix_of_its_median_value_and_names_it_in_the_header():
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
    assert cells[0][1:] == ["5.08 µm", "5.082 µm"] and cells[1][1:] == ["none", "6.894"]


def test_text_and_nan_cells():
    assert display.scaled(["Ra 1.45 nm", 3.0], "m") is None  # a label column stays text
    assert display.scaled([math.nan, 1e-9], "m") == ("nm", ["none", "1"])  # a word, not a blank
    assert display.shown(None, "m") == "none" and display.shown(math.nan, "m") == "none"
    assert display.shown(2.5e-8, "m") == "25 nm" and display.shown(7, None) == "7"
    assert display.split_header(display.header("K_L_A", "N/m")) == ("K_L_A", "N/m")


def test_a_column_spanning_many_decades_writes_each_cell_in_its_own_prefix():
    """Issue 35: a numerical zero beside real values was "8.707e-10 pJ" under one prefix."""
    label, cells = display.scaled([2.903e-17, 8.707e-22, None], "J", "none (no jump)")
    assert label == "" and cells == ["29.03 aJ", "8.707e-22 J", "none (no jump)"]
    label, cells = display.scaled([1.566e-16, 1.283e-17, 2.093e-18], "J")  # was 0.0001566 pJ, ...
    assert (label, cells) == ("aJ", ["156.6", "12.83", "2.093"])


def test_a_quantity_without_any_value_has_no_unit_but_a_word():
    """Issue 35: a jump_in_approach row read "m" and nothing."""
    assert display.column_cells([None, math.nan], "m", "none (no jump on loading)") == (
        "",
        ["none (no jump on loading)"] * 2,
    )
    rows = [{"case": "a", "jump_in_approach [m]": -5.4e-10}, {"case": "b", "jump_in_approach [m]": None}]
    titles, cells = display.columns(rows, missing={"jump_in_approach": "no jump on loading"})
    assert titles == ["case", "jump_in_approach (pm)"]
    assert [row[1] for row in cells] == ["-540", "none (no jump on loading)"]


@pytest.mark.parametrize("unit", ["m", "Pa", "J", "N/m"])
def test_no_cell_has_a_prefix_and_an_exponent(unit):
    """Columns of values from 1e-12 to 1e12: a prefixed header over plain numbers, or units per cell."""
    for low in range(-12, 12):
        for span in (0, 1, 3, 6, 9, 12):
            values = [10.0 ** (low + k * span / 2) * m for k, m in enumerate((1.0, 3.7, 5.5))]
            label, cells = display.scaled(values, unit)
            for cell in cells:
                number, _, cell_unit = cell.partition(" ")
                prefixed = bool(label) or cell_unit not in ("", unit)
                assert not (prefixed and "e" in number.lower()), (values, label, cell)
            if label:  # one prefix for the column: the median reads between 1 and 1000
                assert 1 <= sorted(values)[1] / quantity(f"1 {label}") < 1000


def test_lateral_stiffness_has_one_unit_in_the_figure_and_the_table():
    """Issue 35: K_L was mN/µm in the figures and kN/m in the tables."""
    from roughcontact.plotting.presliding import plot_lateral_stiffness

    loads = [25e-3, 50e-3]
    k_l = {"A": [40.68e3, 48.0e3], "B": [32.93e3, 41.9e3], "C": [22.95e3, 33.3e3]}
    rows = [
        {"normal_force [N]": f} | {f"K_L_{p} [N/m]": v[i] for p, v in k_l.items()}
        for i, f in enumerate(loads)
    ]
    titles, _ = display.columns(rows)
    assert [t for t in titles if t.startswith("K_L")] == ["K_L_A (mN/µm)", "K_L_B (mN/µm)", "K_L_C (mN/µm)"]
    assert display.shown(65.87e3, "N/m") == "65.87 mN/µm"  # a summary line of loop-analysis
    figure = plot_lateral_stiffness(loads, k_l)
    assert figure.axes[0].get_ylabel().endswith("(mN/µm)")


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


def test_a_height_map_is_drawn_about_its_mean_also_far_from_zero():
    """An unlevelled scan (120 nm above zero, as top-1.top reads) gets the colour scale of its relief."""
    from roughcontact.plotting.topography import plot_heights
    from roughcontact.topography import Topography

    rng = np.random.default_rng(2)
    relief = rng.normal(0.0, 1e-9, (40, 40))
    limits = []
    for offset in (0.0, 120e-9):
        fig, ax = plot_heights(Topography(relief + offset, 1e-6))
        limits.append(ax.collections[0].get_clim())
    np.testing.assert_allclose(limits[1], limits[0], rtol=1e-6)
    assert limits[0][0] < 0 < limits[0][1]
