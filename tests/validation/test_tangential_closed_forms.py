"""Partial-slip tangential contact against Cattaneo-Mindlin and Mindlin-Deresiewicz (paper 001).

Reference: a smooth sphere on a flat of the same material (Dundurs beta = 0, so normal and
tangential problems are uncoupled), free boundary. With nu = 0 the Cattaneo-Mindlin traction is
exact (the x-displacement of the Hertzian shear traction is axisymmetric only for nu = 0;
Johnson 1985 sec. 7.2), so the tolerances below measure discretisation error alone and shrink
under refinement. Grids: the contact radius spans 10 (n = 64) to 20 (n = 128) pixels.

Both increment solvers (``method="cg"``, Polonsky-Keer conjugate gradients on the discs, and
``method="apg"``, accelerated projected gradients) are held to the same tolerances.
"""

from __future__ import annotations

import numpy as np
import pytest

from roughcontact.analytic import mindlin
from roughcontact.contact import ShearSolver, solve_normal
from roughcontact.contact.paths import stroke_path, symmetric_path
from roughcontact.contact.tangential import solve_tangential
from roughcontact.materials import Material, contact_modulus, johnson_shear_modulus
from roughcontact.topography import generate

RADIUS = 10e-3
FORCE = 0.5
MU = 0.3


def _case(n, nu=0.0, window=4.0):
    material = Material(1e9, nu, "ball")
    modulus = contact_modulus(material, material)
    a = mindlin.hertz_contact_radius(FORCE, RADIUS, modulus)
    size = window * a
    topography = generate.sphere((n, n), (size, size), radius=RADIUS, kind="paraboloid")
    normal = solve_normal(topography, material, counter_body=material, force=FORCE, tolerance=1e-10)
    g_star = johnson_shear_modulus(material, material)
    return material, normal, a, g_star


METHODS = ["cg", "apg"]


@pytest.fixture(scope="module", params=METHODS)
def mindlin_force_control(request):
    out = {}
    for n in (64, 128):
        material, normal, a, g_star = _case(n)
        fractions = np.array([0.25, 0.5, 0.75, 0.9])
        result = solve_tangential(
            normal,
            material,
            counter_body=material,
            friction_coefficient=MU,
            force=fractions * MU * FORCE,
            solver=ShearSolver(tolerance=1e-10, method=request.param),
        )
        assert result.parameters["method"] == request.param
        out[n] = (result, a, g_star, fractions)
    return out


def test_tangential_displacement_follows_mindlin(mindlin_force_control):
    """delta(Q) = 3 mu P/(16 a G*) [1 - (1 - Q/mu P)^(2/3)]: within 0.3 % at 64^2, 0.1 % at 128^2."""
    errors = {}
    for n, (result, a, g_star, fractions) in mindlin_force_control.items():
        expected = mindlin.tangential_displacement(fractions * MU * FORCE, MU, FORCE, a, g_star)
        errors[n] = np.max(np.abs(result.displacement[:, 0] / expected - 1))
    assert errors[64] < 3e-3
    assert errors[128] < 1e-3
    assert errors[128] < errors[64]


def test_stick_radius_follows_cattaneo(mindlin_force_control):
    """c/a = (1 - Q/mu P)^(1/3), c from the stick area: within 0.04 a at 64^2, 0.025 a at 128^2."""
    errors = {}
    for n, (result, a, _, fractions) in mindlin_force_control.items():
        c = np.sqrt(result.stick_area / np.pi)
        errors[n] = np.max(np.abs(c / a - (1 - fractions) ** (1 / 3)))
    assert errors[64] < 0.04
    assert errors[128] < 0.025


def test_traction_profile_follows_cattaneo(mindlin_force_control):
    """q vs Johnson eqs. 7.36-7.39 over the whole contact, relative to mu p0.

    The exact traction has square-root cusps at r = c and r = a, so the pointwise maximum error
    falls like h^(1/2) (measured 6.2 % -> 4.3 %) and the rms error faster (2.2 % -> 1.1 %).
    """
    worst, rms = {}, {}
    for n, (result, a, _, fractions) in mindlin_force_control.items():
        topography = result.normal.topography
        x, y = topography.meshgrid()
        r = np.hypot(x - topography.size[0] / 2, y - topography.size[1] / 2)
        p0 = 3 * FORCE / (2 * np.pi * a**2)
        worst[n] = rms[n] = 0.0
        for step, fraction in enumerate(fractions):
            expected = mindlin.shear_traction(r, fraction * MU * FORCE, MU, FORCE, a)
            state = result.states[step]
            error = np.abs(state.shear_x - expected)[state.contact | (expected > 0)] / (MU * p0)
            worst[n] = max(worst[n], error.max())
            rms[n] = max(rms[n], np.sqrt(np.mean(error**2)))
            assert np.max(np.abs(state.shear_y)) < 1e-10 * MU * p0  # nu = 0: no transverse traction
    print(worst, rms)
    assert worst[64] < 0.07 and worst[128] < 0.05
    assert rms[128] < 0.6 * rms[64]


def test_force_balance_and_coulomb_bound_to_round_off(mindlin_force_control):
    for result, _, _, fractions in mindlin_force_control.values():
        assert np.allclose(result.force[:, 0], fractions * MU * FORCE, rtol=1e-12, atol=0)
        for state in result.states.values():
            assert np.all(np.hypot(state.shear_x, state.shear_y) <= MU * state.pressure * (1 + 1e-12))
            assert np.all(state.shear_x[~state.contact] == 0) and np.all(state.shear_y[~state.contact] == 0)


@pytest.fixture(scope="module", params=METHODS)
def masing_loop(request):
    material, normal, a, g_star = _case(96)
    delta0 = mindlin.sliding_displacement(MU, FORCE, a, g_star)
    path = symmetric_path(0.8 * delta0, cycles=2, steps_per_stroke=12)
    result = solve_tangential(
        normal,
        material,
        counter_body=material,
        friction_coefficient=MU,
        displacement=path,
        fields_at="none",
        solver=ShearSolver(tolerance=1e-10, method=request.param),
    )
    return result, a, g_star, path


def test_loop_follows_mindlin_deresiewicz(masing_loop):
    """Displacement-controlled +-0.8 delta_0 cycles: F within 0.3 % of mu P of the Masing branches."""
    result, a, g_star, path = masing_loop
    expected = mindlin.masing_force(np.concatenate([[0.0], path]), MU, FORCE, a, g_star)[1:]
    assert np.max(np.abs(result.force[:, 0] - expected)) < 3e-3 * MU * FORCE


def test_dissipated_energy_per_cycle(masing_loop):
    """Loop area vs Mindlin-Deresiewicz (trapezoidal over 24 steps per branch): within 1.5 %."""
    result, a, g_star, path = masing_loop
    expected = mindlin.dissipated_energy_displacement(2 * path.max(), MU, FORCE, a, g_star)
    energies = result.dissipated_energy()
    assert len(energies) == 2
    assert np.allclose(energies, expected, rtol=0.015)


def test_uncoupled_loop_closes_after_the_first_cycle():
    """Paper 001 path (0 -> stroke -> 0, three cycles), beta = 0: every loop after the first is identical."""
    material, normal, a, g_star = _case(48)
    stroke = 1.5 * mindlin.sliding_displacement(MU, FORCE, a, g_star)
    result = solve_tangential(
        normal,
        material,
        counter_body=material,
        friction_coefficient=MU,
        displacement=stroke_path(stroke, cycles=3, steps_per_stroke=8),
        fields_at="none",
        solver=ShearSolver(tolerance=1e-11),
    )
    (s1, e1), (s2, e2) = result.loops()
    assert np.allclose(result.force[s1 : e1 + 1], result.force[s2 : e2 + 1], atol=1e-8 * MU * FORCE)
    # beyond delta_0 the contact slides: the force is mu F0 at the end of each stroke
    assert np.isclose(result.force[e1, 0], MU * FORCE, rtol=1e-9)


def test_both_tangential_directions_give_the_same_answer():
    """A sphere loaded along y gives the x answer rotated (nu = 0.3, so slip directions turn)."""
    material, normal, a, g_star = _case(48, nu=0.3)
    along_x = solve_tangential(
        normal,
        material,
        counter_body=material,
        friction_coefficient=MU,
        force=[[0.6 * MU * FORCE, 0.0]],
        solver=ShearSolver(tolerance=1e-10),
    )
    along_y = solve_tangential(
        normal,
        material,
        counter_body=material,
        friction_coefficient=MU,
        force=[[0.0, 0.6 * MU * FORCE]],
        solver=ShearSolver(tolerance=1e-10),
    )
    assert np.isclose(along_x.displacement[0, 0], along_y.displacement[0, 1], rtol=1e-7)
    assert np.allclose(along_x.states[0].shear_x, along_y.states[0].shear_y.T, atol=1e-7 * MU * 1e6)


def test_nu_03_stays_close_to_mindlin():
    """nu = 0.3: Mindlin is approximate (slip not exactly parallel); delta within 2 %, c/a within 0.05."""
    material, normal, a, g_star = _case(64, nu=0.3)
    result = solve_tangential(
        normal,
        material,
        counter_body=material,
        friction_coefficient=MU,
        force=[0.5 * MU * FORCE],
        solver=ShearSolver(tolerance=1e-10),
    )
    expected = mindlin.tangential_displacement(0.5 * MU * FORCE, MU, FORCE, a, g_star)
    assert abs(result.displacement[0, 0] / expected - 1) < 0.02
    assert abs(np.sqrt(result.stick_area[0] / np.pi) / a - 0.5 ** (1 / 3)) < 0.05
