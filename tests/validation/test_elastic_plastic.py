"""Elastic-perfectly-plastic load-unload: limits, cap, load balance and the unloading branch."""

import math

import numpy as np
import pytest

from roughcontact.analytic import hertz
from roughcontact.contact import solve_normal
from roughcontact.contact.load_unload import SurfacePlasticity, load_unload
from roughcontact.errors import InputError
from roughcontact.materials import Material
from roughcontact.topography.generate import sphere

MATERIAL = Material(0.91e9, 0.3)  # E* = 1 GPa against a rigid flat
RADIUS, FORCE = 1e-3, 1e-3
HERTZ = hertz(radius=RADIUS, contact_modulus=1e9, force=FORCE)


def _ball(n=64, extent=4):
    return sphere((n, n), (extent * HERTZ.contact_radius,) * 2, radius=RADIUS, kind="paraboloid")


def test_hardness_above_hertz_peak_is_elastic_and_reversible():
    result = load_unload(
        _ball(), MATERIAL, max_force=FORCE, plasticity=SurfacePlasticity(2 * HERTZ.peak_pressure), steps=4
    )
    assert result.residual_interference == 0.0
    assert not result.plastic_deformation.any()
    peak = result.loading[-1]
    assert peak.approach == pytest.approx(HERTZ.approach, rel=1e-3, abs=0)
    curve = result.curve()
    # Unloading retraces loading: the force at each approach equals the elastic solution's.
    for approach, force in zip(curve["approach"][4:], curve["force"][4:], strict=True):
        elastic = solve_normal(_ball(), 1e9, approach=approach, tolerance=1e-10) if approach > 0 else None
        assert force == pytest.approx(0.0 if elastic is None else elastic.force, rel=1e-6, abs=1e-12 * FORCE)


def test_plastic_load_unload_caps_pressure_and_leaves_residual_interference():
    hardness = 0.7 * HERTZ.peak_pressure
    result = load_unload(_ball(), MATERIAL, max_force=FORCE, plasticity=SurfacePlasticity(hardness), steps=6)
    peak = result.loading[-1]
    assert peak.force == pytest.approx(FORCE, rel=1e-6, abs=0)
    for step in result.loading + result.unloading:
        assert step.pressure.max() <= hardness
    # Plastic flow only where the pressure sits at the hardness.
    assert np.all(result.plastic_deformation[~peak.plastic_mask] == 0)
    assert 0 < result.residual_interference < peak.approach
    # The residual interference is the deepest plastic flow of the apex region.
    assert result.residual_interference == pytest.approx(result.plastic_deformation.max(), rel=1e-9, abs=0)
    curve = result.curve()
    unloading = curve["branch"] == "unloading"
    assert curve["force"][unloading][-1] == 0.0
    assert np.all(np.diff(curve["force"][unloading]) < 0)  # unloading is monotonic
    # Loading at a softer (capped) surface needs a deeper approach than Hertz for the same force.
    assert peak.approach > HERTZ.approach
    # Mean pressure over the contact cannot exceed the hardness.
    assert peak.force / peak.contact_area <= hardness


def test_fully_plastic_contact_carries_hardness_times_area():
    hardness = 0.2 * HERTZ.peak_pressure
    ball = _ball(96, extent=8)
    result = load_unload(ball, MATERIAL, max_force=FORCE, plasticity=SurfacePlasticity(hardness), steps=2)
    peak = result.loading[-1]
    plastic_force = hardness * np.count_nonzero(peak.plastic_mask) * ball.pixel_area
    assert plastic_force / peak.force > 0.9  # nearly all the load sits at the cap
    # Rigid-plastic limit: contact area ~ F / H (up to the elastic rim).
    assert peak.contact_area == pytest.approx(FORCE / hardness, rel=0.15, abs=0)
    assert math.isfinite(result.residual_interference)


def test_load_unload_needs_a_hardness():
    with pytest.raises(InputError, match="hardness"):
        load_unload(_ball(16), MATERIAL, max_force=FORCE)


@pytest.mark.parametrize("neighbour_force", [0.3 * FORCE, 1.7 * FORCE])
def test_capped_force_control_warm_started_from_a_neighbour_matches_a_cold_solve(neighbour_force):
    # The root search brackets the approach around the warm start's (from below and from above).
    hardness = 0.7 * HERTZ.peak_pressure
    cold = solve_normal(_ball(), MATERIAL, force=FORCE, hardness=hardness, tolerance=1e-10)
    neighbour = solve_normal(_ball(), MATERIAL, force=neighbour_force, hardness=hardness, tolerance=1e-10)
    warm = solve_normal(_ball(), MATERIAL, force=FORCE, hardness=hardness, tolerance=1e-10, initial=neighbour)
    # Measured: force and approach agree to ~1e-13, pressures to ~2e-9 H (solver tolerance 1e-10).
    assert warm.force == pytest.approx(FORCE, rel=1e-10, abs=0)
    assert warm.approach == pytest.approx(cold.approach, rel=1e-10, abs=0)
    assert np.max(np.abs(warm.pressure - cold.pressure)) <= 1e-8 * hardness
    assert warm.pressure.max() <= hardness


def test_capped_force_control_reports_the_iterations_of_its_whole_root_search(monkeypatch):
    """Under a cap the approach of a force is found by displacement-controlled solves; the result
    counts all of their iterations (it used to report the last solve's alone, often 0)."""
    from roughcontact.contact import _constrained_cg

    engine, counted = _constrained_cg.solve, []

    def counting(*args, **kwargs):
        raw = engine(*args, **kwargs)
        counted.append(raw.iterations)
        return raw

    monkeypatch.setattr(_constrained_cg, "solve", counting)
    result = solve_normal(_ball(), MATERIAL, force=FORCE, hardness=0.7 * HERTZ.peak_pressure, tolerance=1e-10)
    assert len(counted) > 2 and counted[-1] < max(counted)
    assert result.iterations == sum(counted)
