"""Figure of a nanoindentation analysis: data segments, unloading fit, tangent at d_max."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from roughcontact.experiment.nanoindentation import oliver_pharr, synthetic_indentation_curve  # noqa: E402
from roughcontact.plotting.indentation import plot_indentation  # noqa: E402


def test_figure_has_fit_tangent_and_labels(tmp_path):
    result = oliver_pharr(synthetic_indentation_curve(0.98e9, creep_rate=1e-9, sampling_rate=2.0))
    fig, ax = plot_indentation(result)
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert {"loading", "hold", "unloading", "power-law fit", "tangent S at d_max", "corrected S_e"} <= set(
        lines
    )
    assert {"d_max, F_max", "contact depth d_c"} <= set(lines)
    assert ax.get_xlabel() == "depth d (nm)" and ax.get_ylabel() == "load F (mN)"
    assert "GPa" in ax.get_title()
    tangent = lines["tangent S at d_max"]
    x, y = tangent.get_xdata(), tangent.get_ydata()
    slope = (y[1] - y[0]) / (x[1] - x[0]) * 1e-3 / 1e-9  # mN/nm -> N/m
    assert slope == pytest.approx(result.stiffness, rel=1e-9)
    assert y[-1] == pytest.approx(result.max_load * 1e3) and x[-1] == pytest.approx(result.max_depth * 1e9)
    fit = lines["power-law fit"].get_ydata() / 1e3
    assert fit.min() >= 0.2 * result.max_load * (1 - 1e-9) and fit.max() <= 0.95 * result.max_load * (
        1 + 1e-9
    )
    assert np.isfinite(lines["loading"].get_ydata()).all()
    fig.savefig(tmp_path / "fig.png")
    assert (tmp_path / "fig.png").stat().st_size > 0


def test_title_gives_the_modulus_and_the_hardness():
    from roughcontact.plotting.indentation import plot_indentation_record

    result = oliver_pharr(synthetic_indentation_curve(0.98e9, hardness=60e6, sampling_rate=2.0))
    _, ax = plot_indentation(result)
    assert "E = 980 MPa, H = 60 MPa (E_r = " in ax.get_title()
    older = {k: v for k, v in result.scalars().items() if k != "hardness"}  # a record stored before H
    _, ax = plot_indentation_record(result.to_xarray(), older)
    assert ax.get_title().startswith("E = 980 MPa (E_r = ")
