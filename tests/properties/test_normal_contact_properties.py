"""Invariants of every normal contact solution (hypothesis): load balance, signs, complementarity."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from roughcontact.contact import solve_normal
from roughcontact.errors import InputError
from roughcontact.topography import Topography

TOLERANCE = 1e-10


def _surface(seed: int, n: int, periodic: bool) -> Topography:
    rng = np.random.default_rng(seed)
    heights = rng.normal(size=(n, n)) * 1e-8
    return Topography(heights, (1e-6, 1e-6), periodic=periodic)


@settings(max_examples=25, deadline=None)
@given(
    seed=st.integers(0, 10_000),
    n=st.sampled_from([8, 16, 24]),
    periodic=st.booleans(),
    load=st.floats(1e5, 1e9),
)
def test_solution_satisfies_the_contact_conditions(seed, n, periodic, load):
    t = _surface(seed, n, periodic)
    result = solve_normal(t, 1e10, mean_pressure=load, tolerance=TOLERANCE)
    p, g = result.pressure, result.gap
    height_scale = t.heights.std() + result.displacement.std()
    assert result.mean_pressure == pytest.approx(load, rel=1e-12, abs=0)  # load balance
    assert np.all(p >= 0)
    assert np.all(g[p == 0] >= -TOLERANCE * height_scale)  # no overlap outside the contact
    assert np.sum(p * np.abs(g)) / p.sum() <= TOLERANCE * height_scale  # zero gap where p > 0
    assert result.residual <= TOLERANCE


@settings(max_examples=15, deadline=None)
@given(seed=st.integers(0, 10_000), hardness_ratio=st.floats(1.2, 5.0))
def test_capped_pressure_never_exceeds_hardness_and_balances(seed, hardness_ratio):
    t = _surface(seed, 16, True)
    load = 1e8
    result = solve_normal(t, 1e10, mean_pressure=load, hardness=hardness_ratio * load, tolerance=1e-9)
    assert np.all(result.pressure <= hardness_ratio * load)
    assert result.mean_pressure == pytest.approx(load, rel=1e-6, abs=0)
    assert np.all(result.gap[result.plastic_mask] <= 1e-9 * t.heights.std())


def test_load_above_capacity_is_refused():
    t = _surface(1, 8, True)
    with pytest.raises(InputError, match="hardness"):
        solve_normal(t, 1e10, mean_pressure=2e9, hardness=1e9)


def test_bad_input_names_the_field():
    t = _surface(1, 8, True)
    with pytest.raises(InputError, match="exactly one"):
        solve_normal(t, 1e10, mean_pressure=1e6, approach=1e-9)
    with pytest.raises(InputError, match="mean_pressure"):
        solve_normal(t, 1e10, mean_pressure=-1.0)
    with pytest.raises(InputError, match="heights"):  # undefined heights never reach the solver
        t.with_heights(np.where(np.eye(8, dtype=bool), np.nan, t.heights))
    with pytest.raises(InputError, match="contact_modulus"):
        solve_normal(t, -1.0, mean_pressure=1e6)
    with pytest.raises(InputError, match="material: no material given"):
        solve_normal(t, mean_pressure=1e6)


def test_non_convergence_raises_with_residual_and_iterations():
    from roughcontact.errors import ConvergenceError

    t = _surface(2, 32, True)
    with pytest.raises(ConvergenceError) as error:
        solve_normal(t, 1e10, mean_pressure=1e7, tolerance=1e-14, max_iterations=3)
    assert error.value.iterations == 3 and error.value.residual > 1e-14


def test_a_tolerance_below_the_round_off_floor_stops_early_and_names_the_floor():
    """Below the floor the preconditioned residual stops falling: the solve says so at once, not after
    max_iterations, and the tolerance it suggests (twice the floor, rounded up) is met."""
    from roughcontact.contact._constrained_cg import STALL_ITERATIONS
    from roughcontact.errors import ConvergenceError
    from roughcontact.topography.generate import self_affine

    surface = self_affine((256, 256), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=256)
    load = {"mean_pressure": 5e6, "max_iterations": 10_000}
    with pytest.raises(ConvergenceError, match="stalled at") as error:
        solve_normal(surface, 1e9, tolerance=1e-16, **load)
    floor = error.value.stalled_at
    assert 1e-16 < floor < 1e-11  # measured 1.1e-13 on this surface
    assert error.value.iterations < 100 + STALL_ITERATIONS  # converged to the floor in ~60
    suggested = error.value.suggested_tolerance
    assert 2 * floor <= suggested <= 5 * floor and f"ask for {suggested:g}" in str(error.value)
    result = solve_normal(surface, 1e9, tolerance=suggested, **load)
    assert result.residual <= suggested


def test_a_stall_far_above_round_off_offers_no_looser_tolerance():
    """A solve stalled at a residual of order 1 failed: no tolerance is suggested that would accept it."""
    from roughcontact.errors import ConvergenceError

    failed = ConvergenceError("solve_normal", 0.697, 223, 1e-8, stalled_at=0.416)
    assert failed.suggested_tolerance is None
    assert "far above round-off" in str(failed) and "ask for" not in str(failed)
    floor = ConvergenceError("solve_normal", 2e-7, 80, 1e-8, stalled_at=1.6e-7)
    assert floor.suggested_tolerance == 4e-7 and "ask for 4e-07" in str(floor)
