"""Contact figures draw from real results and label their axes with units."""

import numpy as np
import pytest

from roughcontact.contact import solve_normal
from roughcontact.contact.load_unload import load_unload
from roughcontact.elasticity.stress import subsurface_stress
from roughcontact.materials import Material
from roughcontact.plotting import (
    plot_contact_area,
    plot_contact_overview,
    plot_load_approach,
    plot_von_mises,
)
from roughcontact.topography.generate import sphere


def _ball():
    return sphere((32, 32), (40e-6, 40e-6), radius=1e-3, kind="paraboloid")


def test_contact_maps_and_curves_are_labelled(tmp_path):
    result = solve_normal(_ball(), 1e9, force=1e-3)
    fig = plot_contact_overview(result)
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert any("pressure (MPa)" in label for label in labels)
    assert any("gap" in label for label in labels)
    fig.savefig(tmp_path / "maps.png")

    path = load_unload(_ball(), Material(0.91e9, 0.3, hardness=4e6), max_force=1e-3, steps=3)
    fig, ax = plot_load_approach(path.curve())
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["loading", "unloading"]
    assert ax.get_xlabel().startswith("approach (")
    fig, ax = plot_contact_area(path.curve())
    assert ax.get_ylabel() == "real contact area (m²)"

    stress = subsurface_stress(
        result.pressure, result.topography.size, [5e-6], poissons_ratio=0.3, boundary="free"
    )
    fig, ax = plot_von_mises(stress, 0)
    assert "von Mises" in ax.get_title()
    assert np.isfinite(stress.von_mises()).all()


def test_a_single_spike_does_not_set_the_pressure_colour_scale():
    from roughcontact.plotting import plot_pressure
    from roughcontact.plotting.layout import colour_scale

    surface = _ball()
    spiky = surface.heights.copy()
    spiky[5, 5] = spiky.max() + 20e-9  # one point 20 nm above the apex, away from it
    result = solve_normal(type(surface)(spiky, surface.size), 1e9, force=1e-3)
    fig, ax = plot_pressure(result)
    mesh = ax.collections[0]
    scale = colour_scale(result.pressure, from_zero=True)
    factor, _ = scale.prefixed("Pa")
    assert result.pressure[5, 5] == result.pressure.max() > 2 * scale.high  # the spike's load
    # the top: the 99.5th percentile of nonzero (divided by the prefix and multiplied back: rounding)
    assert mesh.get_clim()[1] * factor == pytest.approx(scale.high, rel=1e-12)
    assert "99.5th pct." in fig.axes[-1].get_ylabel()
    assert np.ma.is_masked(mesh.get_array())  # no contact: masked, drawn grey


def test_the_unloading_branch_starts_at_the_peak():
    curve = {
        "approach": np.array([0.0, 1e-9, 2e-9, 1.5e-9, 1e-9]),
        "force": np.array([0.0, 1e-3, 3e-3, 1e-3, 0.0]),
        "branch": np.array(["loading", "loading", "loading", "unloading", "unloading"]),
    }
    fig, ax = plot_load_approach(curve)
    loading, unloading = ax.get_lines()
    assert tuple(unloading.get_xydata()[0]) == tuple(loading.get_xydata()[-1])  # they meet at the peak


def test_one_result_is_one_case():
    from roughcontact.plotting import as_cases

    result = solve_normal(_ball(), 1e9, force=1e-3)
    assert len(as_cases(result)) == 1 and len(as_cases([result, result])) == 2
