"""Paper 002's Fig. 6 as a table: a quantity against the grid, its observed order and extrapolation."""

from types import SimpleNamespace

import numpy as np
import pytest

from roughcontact.spread import convergence_order
from roughcontact.study.kinds.load_unload import _mesh_convergence


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


def test_table_over_grids_and_realisations():
    def record(points, size, peak):
        return SimpleNamespace(scalars={"grid_points": points, "pixel_size": size, "peak_interference": peak})

    sizes = {64**2: 0.4, 128**2: 0.2, 256**2: 0.1}
    records = [record(n, h, 5.0 + 2.0 * h**2 + noise) for n, h in sizes.items() for noise in (-1e-3, 1e-3)]
    rows = _mesh_convergence(records, None)
    assert [row["grid_points"] for row in rows] == sorted(sizes) and all(row["n"] == 2 for row in rows)
    assert rows[-1]["observed_order"] == pytest.approx(2.0, rel=1e-8)
    assert rows[-1]["extrapolated_peak_interference [m]"] == pytest.approx(5.0, rel=1e-10)
    assert _mesh_convergence(records[:2], None) is None  # one grid


def test_fig6_from_python_cases():
    from roughcontact.plotting.asperity import mesh_convergence_figure
    from roughcontact.plotting.cases import ResultCase

    def case(n, peak):
        return ResultCase(
            f"{n}", {"grid_points": n, "pixel_size": 1e-6 / np.sqrt(n), "peak_interference": peak}
        )

    cases = [case(n * n, 40e-9 + 8e-9 / n**2 + d) for n in (32, 64, 128) for d in (-1e-10, 1e-10)]
    ax = mesh_convergence_figure(cases).axes[0]
    assert ax.get_xlabel() == "grid points (elements)" and ax.get_ylabel() == "peak interference ω_max (nm)"
    labels = [text.get_text() for text in ax.get_legend().get_texts()]
    assert any("observed order 2.00" in label for label in labels)
    assert mesh_convergence_figure(cases[:2]) is None
