"""Paper 002's Fig. 6 said in full: each quantity against the grid, its changes, its order or why none.

``roughcontact.asperity.convergence`` (the study logic, below plotting), the ``mesh_convergence``
table of the ``load_unload`` kind and the figure drawn from it: per grid the mean over the
realisations with its 95 % interval (never below zero), the change per refinement of the mean and
of each draw, the observed order where the changes shrink monotonically and "not monotone" where
they change sign, for the peak interference, the interference back at the reference load and the
peak contact area.
"""

import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from roughcontact.asperity.convergence import QUANTITIES, mesh_convergence, trend
from roughcontact.spread import convergence_order, spread
from roughcontact.study.kinds.load_unload import _mesh_convergence
from roughcontact.study.store import notes_of

SIZES = {64**2: 0.4, 128**2: 0.2, 256**2: 0.1}  # grid points -> pixel size


@pytest.mark.parametrize("order", [1.0, 1.5, 2.0])
@pytest.mark.parametrize("sizes", [(1.0, 0.5, 0.25), (0.9, 0.6, 0.25)])  # constant and varying refinement
def test_observed_order_and_richardson_of_a_known_sequence(order, sizes):
    values = [3.0 + 0.7 * h**order for h in sizes]
    p, extrapolated = convergence_order(list(sizes), values)
    assert p == pytest.approx(order, rel=1e-8)
    assert extrapolated == pytest.approx(3.0, rel=1e-10)


def test_no_order_without_an_asymptotic_range():
    assert convergence_order([1.0, 0.5], [1.0, 2.0]) is None  # two grids
    assert convergence_order([1.0, 0.5, 0.25], [1.0, 2.0, 1.0]) is None  # oscillating


def test_trend_says_why_there_is_no_order():
    assert trend([0.4, 0.2, 0.1], [5.32, 5.08, 5.02])[1] == "observed order 2"
    assert trend([0.4, 0.2, 0.1], [5.0, 5.1, 5.05]) == (None, "not monotone")
    assert trend([0.4, 0.2, 0.1], [5.0, 5.01, 5.05]) == (None, "changes do not shrink")
    assert trend([0.2, 0.1], [5.0, 5.01]) == (None, "2 grids: no order")
    # changes that hardly shrink fit an "order" of 0.16: not asymptotic, no extrapolation given
    values = [1.8e-9 + 2e-9 * h**0.16 for h in (0.4, 0.2, 0.1)]
    assert convergence_order([0.4, 0.2, 0.1], values)[0] == pytest.approx(0.16, rel=1e-6)
    assert trend([0.4, 0.2, 0.1], values) == (None, "order 0.16, too low: not asymptotic")


def _record(points, replicate, **scalars):
    return SimpleNamespace(
        scalars={"grid_points": points, "pixel_size": SIZES[points], **scalars},
        parameters={"replicate": replicate},
    )


def _smooth_study(draw_offsets=(-1e-3, 1e-3)):
    """Second-order convergence in every quantity; two draws a fixed offset apart on every grid."""
    return [
        _record(
            n,
            r,
            peak_interference=(5.0 + 2.0 * h**2 + d) * 1e-8,
            interference_at_return_force=(1.0 + 0.5 * h**2 + d) * 1e-8,
            peak_contact_area=(8.0 - 3.0 * h**2 + d) * 1e-12,
        )
        for n, h in SIZES.items()
        for r, d in enumerate(draw_offsets)
    ]


def test_table_reports_every_quantity_per_grid_with_its_interval_change_and_order():
    table = _mesh_convergence(_smooth_study(), None)
    assert [row["quantity"] for row in table] == [q for q in QUANTITIES for _ in SIZES]
    by = {(row["quantity"], row["grid_points"]): row for row in table}
    for quantity, unit in QUANTITIES.items():
        rows = [by[quantity, n] for n in sorted(SIZES)]
        assert all(row["unit"] == unit and row["n"] == 2 for row in rows)
        values = [
            [c.scalars[quantity] for c in _smooth_study() if c.scalars["grid_points"] == n] for n in SIZES
        ]
        for row, draws in zip(rows, values, strict=True):
            summary = spread(draws, bounds=(0.0, np.inf))
            assert (row["mean"], row["ci95_low"], row["ci95_high"]) == pytest.approx(
                (summary.mean, summary.ci95_low, summary.ci95_high), rel=1e-12
            )
        assert rows[0]["change_from_coarser (%)"] is None
        assert rows[1]["change_from_coarser (%)"] == pytest.approx(
            100 * (rows[1]["mean"] / rows[0]["mean"] - 1), rel=1e-12
        )
        assert rows[-1]["observed_order"] == pytest.approx(2.0, rel=1e-8)
        assert rows[-1]["trend"] == "observed order 2"
        assert "observed_order" not in rows[0]
    # each draw's change per refinement, signed, in %
    change = by["peak_interference", 256**2]["change_per_draw (%)"].split(", ")
    assert len(change) == 2 and all(c.startswith("-") for c in change)
    notes = notes_of(table)
    assert len(notes) == 3 and notes[0].startswith("peak interference: the mean changes")
    assert (
        "Richardson extrapolation 50 nm" in notes[0] and "per draw: observed order 2 (draws 0, 1)" in notes[0]
    )
    assert _mesh_convergence(_smooth_study()[:2], None) is None  # one grid


def test_non_monotone_mean_and_draws_are_said_so():
    """The paper002_mesh.toml case: omega_max changes ~1 % per refinement with no order, per draw too."""
    peaks = {  # draw -> peak interference [nm] on 64, 128, 256 points
        0: (40.0, 40.4, 40.1),
        1: (30.0, 29.7, 29.9),
        2: (50.0, 50.5, 50.3),
    }
    records = [
        _record(n, r, peak_interference=values[i] * 1e-9, peak_contact_area=(9.0 + 0.1 * i) * 1e-12)
        for r, values in peaks.items()
        for i, n in enumerate(sorted(SIZES))
    ]
    (peak, area) = mesh_convergence(records)
    assert peak.order is None and peak.trend == "not monotone"
    assert peak.draw_trends == {0: "not monotone", 1: "not monotone", 2: "not monotone"}
    assert "per draw: not monotone (draws 0, 1, 2)" in peak.summary()
    assert peak.finest.draw_changes[0] == pytest.approx(40.1 / 40.4 - 1, rel=1e-12)
    # one draw scatters far more than the grid changes it: the summary says both
    assert "One draw differs from another by" in peak.summary()
    # the area is linear in the grid index: its changes do not shrink, and the table says so
    assert area.trend == "changes do not shrink" and area.order is None
    rows = _mesh_convergence(records, None)
    assert [r["trend"] for r in rows if "trend" in r] == ["not monotone", "changes do not shrink"]
    assert all(r["observed_order"] is None for r in rows if "observed_order" in r)
    # no interference at the return force stored: that quantity is left out, not invented
    assert {r["quantity"] for r in rows} == {"peak_interference", "peak_contact_area"}


def test_a_draw_missing_on_one_grid_is_left_out_of_the_means():
    """A failed (or pending) case must not move the mean by the scatter between draws."""
    records = [
        c
        for c in _smooth_study(draw_offsets=(-1.0, 1.0))
        if (c.scalars["grid_points"], c.parameters["replicate"]) != (256**2, 1)
    ]
    peak = mesh_convergence(records)[0]
    assert peak.left_out == (1,)
    assert [g.spread.n for g in peak.grids] == [1, 1, 1]
    assert peak.order == pytest.approx((2.0, 4.0e-8), rel=1e-8)  # draw 0 alone: 5 + 2 h^2 - 1 (x 1e-8)
    assert peak.finest.draw_changes == {0: pytest.approx((4.0 + 2 * 0.01) / (4.0 + 2 * 0.04) - 1, rel=1e-12)}
    assert "Draw 1 left out of the means: not on every grid" in peak.summary()


def test_intervals_of_positive_quantities_stop_at_zero():
    records = [
        _record(n, r, peak_interference=v * 1e-9, peak_contact_area=v * 1e-12)
        for n in SIZES
        for r, v in enumerate((1.0, 30.0))  # two draws far apart: Student's interval reaches below 0
    ]
    for quantity in mesh_convergence(records):
        for grid in quantity.grids:
            assert grid.spread.ci95_low == 0.0 and grid.spread.note


def test_fig6_one_panel_per_quantity_from_python_cases():
    from roughcontact.plotting.asperity import mesh_convergence_figure
    from roughcontact.plotting.cases import ResultCase

    def case(n, peak, area):
        scalars = {"grid_points": n, "pixel_size": 1e-6 / np.sqrt(n)}
        return ResultCase(f"{n}", scalars | {"peak_interference": peak, "peak_contact_area": area})

    cases = [
        case(n * n, 40e-9 + 8e-9 / n**2 + d, 9e-12 + 1e-12 / n**2)
        for n in (32, 64, 128)
        for d in (-1e-10, 1e-10)
    ]
    figure = mesh_convergence_figure(cases)
    interference, area = figure.axes
    assert interference.get_xlabel() == "grid points (elements)"
    assert interference.get_ylabel() == "peak interference ω_max (nm)"
    assert area.get_ylabel() == "real contact area at the peak (µm²)"
    labels = [text.get_text() for text in interference.get_legend().get_texts()]
    assert any("observed order 2.00" in label for label in labels)
    assert "observed order 2" in interference.get_title()
    assert mesh_convergence_figure(cases[:2]) is None


def test_the_old_place_of_the_table_logic_still_answers_with_a_warning():
    import roughcontact.plotting.asperity as plotting_asperity

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        moved = plotting_asperity.mesh_convergence
    assert moved is mesh_convergence
    assert any(issubclass(w.category, DeprecationWarning) for w in caught)
