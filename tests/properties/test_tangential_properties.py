"""Invariants of every partial-slip tangential solution (hypothesis): Coulomb law, force balance, units.

Small free grids (32 x 32) with a smooth or a rough sphere pressed on a flat of the same material
(or a rigid one with coupling), loaded by a force path with a reversal (history) in a random
direction.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from roughcontact.contact import ShearSolver, solve_normal
from roughcontact.contact.tangential import solve_tangential
from roughcontact.materials import Material
from roughcontact.topography import generate

N = 32
SIZE = 40e-6
RADIUS = 1e-3
F0 = 1e-3
TOLERANCE = 1e-8
MATERIAL = Material(1e9, 0.3, "body")
_NORMALS: dict = {}


def _topography(rough: bool, seed: int, scale: float = 1.0):
    if rough:
        return generate.sphere_with_roughness(
            (N, N), (SIZE * scale, SIZE * scale), radius=RADIUS * scale, rms_height=5e-8 * scale, seed=seed
        )
    return generate.sphere((N, N), (SIZE * scale, SIZE * scale), radius=RADIUS * scale, kind="paraboloid")


def _normal(rough: bool, seed: int, counter=MATERIAL, scale: float = 1.0):
    key = (rough, seed if rough else 0, id(counter), scale)
    if key not in _NORMALS:
        topography = _topography(rough, seed, scale)
        _NORMALS[key] = solve_normal(
            topography, MATERIAL, counter_body=counter, force=F0 * scale**2, tolerance=1e-10
        )
    return _NORMALS[key]


def _path(fraction, angle, mu, force):
    direction = np.array([np.cos(angle), np.sin(angle)])
    return np.outer([fraction, 0.4 * fraction, fraction], direction) * mu * force


def _check_coulomb_and_balance(result, path, mu):
    assert np.allclose(result.force, path, rtol=0, atol=1e-10 * np.abs(path).max())
    previous = np.zeros(2)
    for step, state in result.states.items():
        q = np.hypot(state.shear_x, state.shear_y)
        bound = mu * state.pressure
        contact = state.contact
        # |q| <= mu p to round-off everywhere, q = 0 outside the contact
        assert np.all(q <= bound * (1 + 1e-12))
        assert np.all(state.shear_x[~contact] == 0) and np.all(state.shear_y[~contact] == 0)
        # force balance from the fields
        total = np.array([state.shear_x.sum(), state.shear_y.sum()]) * state.pixel_area
        assert np.allclose(total, path[step], rtol=0, atol=1e-10 * np.abs(path[step]).max())
        # stick points do not slip in this step (to the solver's tolerance scale)
        delta = np.asarray(state.displacement)
        step_scale = np.hypot(*(delta - previous)) + 1e-300
        previous = delta
        w = np.hypot(state.slip_increment_x, state.slip_increment_y)
        if state.stick.any():
            assert w[state.stick].max() <= 1e3 * TOLERANCE * step_scale
        # slip points: on the rim, traction opposing the slip increment
        slip = state.slip
        if slip.any():
            assert np.all(np.abs(q[slip] / bound[slip] - 1) <= 1e-10)
            moving = slip & (w > 1e-3 * step_scale)
            dot = state.shear_x * state.slip_increment_x + state.shear_y * state.slip_increment_y
            assert np.all(dot[moving] < 0)
            cosine = np.clip(-dot / np.where(moving, q * w, 1.0), -1.0, 1.0)
            # The solver's criterion is the traction-weighted mean of |w_perp| (pointwise, a weakly
            # loaded point may keep a larger angle): check that mean, relative to the step, and a
            # pointwise bound where the slip is a sizeable part of the step.
            perpendicular = w * np.sqrt(1 - cosine**2)
            weighted = np.sum((bound * perpendicular)[moving]) / np.sum(bound[state.contact])
            assert weighted <= 1e3 * TOLERANCE * step_scale
            large = slip & (w > 0.1 * step_scale)
            assert np.all(np.arccos(cosine[large]) < 1e-3)


@settings(max_examples=15, deadline=None, derandomize=True)
@given(
    rough=st.booleans(),
    seed=st.integers(0, 3),
    mu=st.floats(0.05, 1.0),
    fraction=st.floats(0.05, 0.95),
    angle=st.floats(0.0, 2 * np.pi),
)
def test_force_control_obeys_coulomb_and_balance(rough, seed, mu, fraction, angle):
    """Any direction up to 0.95 mu F0 (the plain method may stall near sliding; "auto" retries)."""
    normal = _normal(rough, seed)
    path = _path(fraction, angle, mu, normal.force)
    result = solve_tangential(
        normal,
        MATERIAL,
        counter_body=MATERIAL,
        friction_coefficient=mu,
        force=path,
        solver=ShearSolver(tolerance=TOLERANCE, max_iterations=3000),
    )
    assert np.all(result.residual <= TOLERANCE)
    _check_coulomb_and_balance(result, path, mu)


@pytest.mark.parametrize(
    "fraction, angle",
    [(0.9054173266933417, 0.9057815605287021), (0.8, 0.3), (0.95, np.pi / 4)],
)
def test_force_control_converges_near_sliding(fraction, angle):
    normal = _normal(False, 0)
    mu = 0.5
    solve_tangential(
        normal,
        MATERIAL,
        counter_body=MATERIAL,
        friction_coefficient=mu,
        force=[fraction * mu * normal.force * np.array([np.cos(angle), np.sin(angle)])],
        solver=ShearSolver(max_iterations=2000),
    )


@settings(max_examples=6, deadline=None, derandomize=True)
@given(
    rough=st.booleans(),
    mu=st.floats(0.05, 1.0),
    fraction=st.floats(0.05, 0.5),
    angle=st.floats(0.0, 2 * np.pi),
    exponent=st.sampled_from([-3, 3, 9]),
)
def test_unit_invariance(rough, mu, fraction, angle, exponent):
    """Lengths x L and forces x L^2 (equal pressures): normalised forces and displacements agree."""
    scale = 10.0**exponent
    out = []
    for factor in (1.0, scale):
        normal = _normal(rough, 1, scale=factor)
        path = _path(fraction, angle, mu, normal.force)
        result = solve_tangential(
            normal,
            MATERIAL,
            counter_body=MATERIAL,
            friction_coefficient=mu,
            force=path,
            solver=ShearSolver(tolerance=TOLERANCE, max_iterations=3000),
        )
        out.append((result, factor))
    (base, _), (scaled, factor) = out
    assert np.allclose(scaled.force / factor**2, base.force, rtol=1e-8, atol=1e-10 * np.abs(base.force).max())
    assert np.allclose(
        scaled.displacement / factor,
        base.displacement,
        rtol=1e-8,
        atol=1e-8 * np.abs(base.displacement).max(),
    )
    assert np.array_equal(scaled.stick_area > 0, base.stick_area > 0)
    assert np.allclose(scaled.stick_area / factor**2, base.stick_area, rtol=1e-8)
    last = max(base.states)
    assert np.allclose(
        scaled.states[last].shear_x,
        base.states[last].shear_x,
        rtol=0,
        atol=1e-7 * mu * base.states[last].pressure.max(),
    )


@settings(max_examples=5, deadline=None, derandomize=True)
@given(
    mu=st.floats(0.05, 1.0),
    fraction=st.floats(0.05, 0.5),
    angle=st.floats(0.0, 2 * np.pi),
)
def test_coupled_dissimilar_pair_keeps_the_normal_force(mu, fraction, angle):
    """Body nu = 0.3 on a rigid flat (beta != 0), coupling on: sum(p) A_px = F0 at every step.

    Smooth sphere here; the rough sphere is covered by test_coupled_rough_sphere_converges.
    """
    normal = _normal(False, 2, counter=None)
    path = _path(fraction, angle, mu, normal.force)
    result = solve_tangential(
        normal,
        MATERIAL,
        friction_coefficient=mu,
        force=path,
        coupling=True,
        solver=ShearSolver(tolerance=TOLERANCE, max_iterations=3000),
    )
    assert result.parameters["coupling"] is True
    assert np.any(result.coupling_iterations > 1)
    for state in result.states.values():
        assert state.pressure.sum() * state.pixel_area == pytest.approx(normal.force, rel=1e-8)
        assert np.all(state.pressure >= 0)
    _check_coulomb_and_balance(result, path, mu)


def test_coupled_rough_sphere_converges():
    normal = _normal(True, 2, counter=None)
    mu = 0.482421875
    solve_tangential(
        normal,
        MATERIAL,
        friction_coefficient=mu,
        force=_path(0.12334696067008269, 1.125, mu, normal.force),
        coupling=True,
        solver=ShearSolver(tolerance=TOLERANCE, max_iterations=3000),
    )
