"""Combined normal and tangential programmes against closed forms (solve_frictional, issue 20).

* Mindlin and Deresiewicz (1953; Johnson 1985 sec. 7.3) oblique loading of identical spheres
  (beta = 0, nu = 0 so the Cattaneo traction is exact): from a preload P_0, P and Q grow together
  with dQ/dP = k. For k < mu nothing slips and the traction increment is k times the pressure
  increment, so delta = k/(8 G*) int dP/a(P) = (3k/(16 G*)) (4E*/(3R))^(1/3) (P^(2/3) - P_0^(2/3)).
  For k > mu the traction is Cattaneo's at the current (P, Q): c/a = (1 - Q/(mu P))^(1/3) and
  delta = 3 mu P/(16 a G*) (1 - (c/a)^2).
* beta = 0: the frictional normal loading locks in nothing, and a programme started from it is the
  one started from the frictionless normal contact (Goodman's start) to round-off.
* Invariants on a rough ball of dissimilar materials (hypothesis): load balance, |q| <= mu p and
  non-negative dissipation at every step.

Grids: the final contact radius spans 16 pixels (n = 64) and 32 (n = 128).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from roughcontact.analytic import mindlin
from roughcontact.contact import ShearSolver, solve_frictional, solve_normal, solve_tangential
from roughcontact.contact.paths import stroke_path
from roughcontact.errors import InputError
from roughcontact.materials import Material, contact_modulus, get_material, johnson_shear_modulus
from roughcontact.topography import generate

RADIUS, FORCE, MU = 10e-3, 0.5, 0.3
PRELOAD = 0.4 * FORCE


def _spheres(n):
    material = Material(1e9, 0.0, "ball")
    modulus = contact_modulus(material, material)
    a = mindlin.hertz_contact_radius(FORCE, RADIUS, modulus)
    ball = generate.sphere((n, n), (4 * a, 4 * a), radius=RADIUS, kind="paraboloid")
    return ball, material, modulus, johnson_shear_modulus(material, material)


def _oblique(n, ratio, steps):
    """Preload to P_0 in 5 steps, then P: P_0 -> F and Q = k (P - P_0) in ``steps`` steps."""
    ball, material, modulus, g_star = _spheres(n)
    preload = PRELOAD * (np.arange(1, 6) / 5) ** 3
    load = np.linspace(PRELOAD, FORCE, steps + 1)[1:]
    tangential = ratio * MU * (load - PRELOAD)
    result = solve_frictional(
        ball,
        material,
        counter_body=material,
        friction_coefficient=MU,
        normal_force=np.concatenate([preload, load]),
        force=np.concatenate([np.zeros(5), tangential]),
        fields_at="none",
        solver=ShearSolver(tolerance=1e-10),
    )
    radii = np.array([mindlin.hertz_contact_radius(p, RADIUS, modulus) for p in load])
    return result, load, tangential, radii, modulus, g_star


@pytest.mark.parametrize("n", [64, 128])
def test_oblique_loading_steeper_than_mu_follows_cattaneo_at_every_step(n):
    result, load, tangential, radii, _, g_star = _oblique(n, 1.5, 8)
    stick = np.sqrt(result.stick_area[5:] / result.contact_area[5:])
    expected = np.cbrt(1 - tangential / (MU * load))
    delta = [
        mindlin.tangential_displacement(q, MU, p, a, g_star)
        for q, p, a in zip(tangential, load, radii, strict=True)
    ]
    # measured: 64^2 c/a within 0.007, delta within 3e-4; 128^2 within 0.005 and 1e-4
    assert np.abs(stick - expected).max() < {64: 0.015, 128: 0.01}[n]
    np.testing.assert_allclose(result.displacement[5:, 0], delta, rtol={64: 1e-3, 128: 5e-4}[n])
    np.testing.assert_allclose(result.normal_load[5:], load, rtol=1e-9)
    np.testing.assert_allclose(result.force[5:, 0], tangential, rtol=1e-9, atol=1e-12)


def test_oblique_loading_below_mu_never_slips_and_converges_with_the_load_steps():
    """k = mu/2: the whole contact sticks (to the rim pixels) and delta -> the closed form as 1/steps."""
    errors, sticking = [], []
    for steps in (4, 8, 16):
        result, load, _, _, modulus, g_star = _oblique(64, 0.5, steps)
        k = 0.5 * MU
        closed = 3 * k / (16 * g_star) * (4 * modulus / (3 * RADIUS)) ** (1 / 3)
        expected = closed * (FORCE ** (2 / 3) - PRELOAD ** (2 / 3))
        errors.append(abs(result.displacement[-1, 0] / expected - 1))
        sticking.append((result.stick_area[5:] / result.contact_area[5:]).min())
    # measured: 1.85 %, 1.00 %, 0.54 % (first order in the load step)
    assert errors[0] < 0.025 and errors[2] < 0.007
    assert errors[1] < 0.6 * errors[0] and errors[2] < 0.6 * errors[1]
    # the pixels that enter the contact within a step may slip in it: fewer as the steps shrink
    assert sticking[0] < sticking[1] < sticking[2] and sticking[2] > 0.95


def test_beta_zero_frictional_start_equals_goodman_start():
    ball, material, _, _ = _spheres(64)
    normal = solve_normal(ball, material, counter_body=material, force=FORCE, tolerance=1e-13)
    path = stroke_path(0.5e-6, cycles=1, steps_per_stroke=8)
    common = dict(
        counter_body=material, friction_coefficient=MU, displacement=path, solver=ShearSolver(tolerance=1e-12)
    )
    goodman = solve_tangential(normal, material, normal_loading="frictionless", **common)
    frictional = solve_tangential(normal, material, normal_loading="frictional", **common)
    assert frictional.loading is not None and goodman.loading is None
    assert frictional.locked_in()["locked_in_shear_rms"] == 0.0
    scale = MU * FORCE
    np.testing.assert_allclose(frictional.force, goodman.force, rtol=0, atol=1e-10 * scale)
    for step in goodman.states:
        peak = MU * normal.pressure.max()
        np.testing.assert_allclose(
            frictional.states[step].shear_x, goodman.states[step].shear_x, atol=1e-10 * peak
        )


def test_auto_start_is_frictional_for_dissimilar_materials_and_frictionless_for_similar():
    ball, material, _, _ = _spheres(32)
    rigid_flat = None  # nu = 0 body on a rigid flat: beta = 0.5
    for counter, expected in ((material, "frictionless"), (rigid_flat, "frictional")):
        normal = solve_normal(ball, material, counter_body=counter, force=FORCE)
        result = solve_tangential(
            normal, material, counter_body=counter, friction_coefficient=MU, displacement=[1e-7]
        )
        assert result.parameters["normal_loading"] == expected
    assert (
        solve_tangential(
            normal, material, friction_coefficient=MU, displacement=[1e-7], coupling=False
        ).parameters["normal_loading"]
        == "frictionless"
    )  # Goodman's approximation throughout


# --- invariants on a rough ball of dissimilar materials -------------------------------------------


@pytest.fixture(scope="module")
def rough_ball():
    return generate.sphere_with_roughness(
        (32, 32), (32 * 2.148e-6,) * 2, radius=5e-3, rms_height=5e-8, seed=3
    )


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(
    loads=st.lists(st.floats(0.2, 1.0), min_size=2, max_size=5),
    shifts=st.lists(st.floats(-1.0, 1.0), min_size=5, max_size=5),
    force_control=st.booleans(),
)
def test_every_step_balances_loads_respects_coulomb_and_dissipates(rough_ball, loads, shifts, force_control):
    pom, silicon = get_material("POM"), get_material("silicon wafer")
    normal = 2e-3 * np.asarray(loads)
    tangential = np.asarray(shifts[: len(loads)])
    control = (
        {"force": 0.6 * MU * normal * tangential} if force_control else {"displacement": 0.1e-6 * tangential}
    )
    result = solve_frictional(
        rough_ball, pom, counter_body=silicon, friction_coefficient=MU, normal_force=normal, **control
    )
    assert abs(result.parameters["dundurs_beta"]) > 0
    np.testing.assert_allclose(result.normal_load, normal, rtol=1e-8)
    if force_control:
        np.testing.assert_allclose(result.force[:, 0], control["force"], rtol=1e-8, atol=1e-12 * normal.max())
    assert np.all(result.dissipation >= 0)
    for state in result.states.values():
        shear = np.hypot(state.shear_x, state.shear_y)
        assert np.all(shear <= MU * state.pressure * (1 + 1e-9) + 1e-12 * MU * state.pressure.max())


def test_unit_invariance_of_a_combined_programme(rough_ball):
    """The same programme in metres and in micrometres (heights, sizes, moduli scaled) agrees."""
    pom, silicon = get_material("POM"), get_material("silicon wafer")
    normal = 2e-3 * np.array([0.3, 1.0, 0.6])
    shift = 0.05e-6 * np.array([0.0, 1.0, -1.0])
    base = solve_frictional(
        rough_ball,
        pom,
        counter_body=silicon,
        friction_coefficient=MU,
        normal_force=normal,
        displacement=shift,
    )
    scale = 1e6  # lengths in um: heights and sizes x 1e6, forces unchanged if moduli / 1e12
    scaled_ball = generate.sphere_with_roughness(
        (32, 32), (32 * 2.148,) * 2, radius=5e3, rms_height=5e-2, seed=3
    )
    soft = Material(pom.youngs_modulus / scale**2, pom.poissons_ratio, "POM in uN/um^2")
    flat = Material(silicon.youngs_modulus / scale**2, silicon.poissons_ratio, "Si in uN/um^2")
    other = solve_frictional(
        scaled_ball,
        soft,
        counter_body=flat,
        friction_coefficient=MU,
        normal_force=normal,
        displacement=shift * scale,
    )
    np.testing.assert_allclose(other.force, base.force, rtol=1e-6, atol=1e-9 * normal.max())
    np.testing.assert_allclose(other.approach, base.approach * scale, rtol=1e-6)
    np.testing.assert_allclose(other.stick_area, base.stick_area * scale**2, rtol=1e-9)


# --- bad input ------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("arguments", "field", "words"),
    [
        ({"normal_force": [1e-3, 0.0], "displacement": [0, 0]}, "normal_force", "contact is lost"),
        ({"normal_force": [1e-3, np.nan], "displacement": [0, 0]}, "normal_force", "not a finite"),
        ({"normal_force": [1e-3], "approach": [1e-9], "displacement": [0]}, "normal_force", "exactly one"),
        ({"normal_force": [1e-3, 1e-3], "displacement": [0]}, "normal_force", "2 values for 1"),
        ({"normal_force": [1e-3], "displacement": [0], "force": [0]}, "path", "exactly one"),
        ({"normal_force": [1e-3], "force": [0.5 * 1e-3]}, "force", "slid"),
        ({"approach": [-1e-9], "displacement": [0]}, "approach", "contact is lost"),
        (
            {"normal_force": [1e-3], "displacement": [0], "max_stick_change": 2.0},
            "max_stick_change",
            "fraction",
        ),
    ],
)
def test_bad_programmes_are_refused_with_the_field_named(rough_ball, arguments, field, words):
    with pytest.raises(InputError) as error:
        solve_frictional(rough_ball, get_material("POM"), friction_coefficient=MU, **arguments)
    assert error.value.field == field
    assert words in str(error.value)


# --- Spence's frictional normal loading -----------------------------------------------------------


def _spence(mu, steps, n=64):
    """A rigid sphere pressed into a nu = 0 half-space (beta = 0.5) with friction, delta held at 0."""
    material = Material(1e9, 0.0, "nu 0")
    size, radius = 1e-4, 1e-3
    ball = generate.sphere((n, n), (size, size), radius=radius, kind="paraboloid")
    a = 0.35 * size
    force = 4 * material.youngs_modulus * a**3 / (3 * radius)
    loads = force * (np.arange(1, steps + 1) / steps) ** 3  # equal steps of the Hertz radius
    result = solve_frictional(
        ball,
        material,
        friction_coefficient=mu,
        normal_force=loads,
        displacement=np.zeros(steps),
        fields_at="last",
    )
    assert result.parameters["dundurs_beta"] == pytest.approx(0.5)
    return result, np.sqrt(result.stick_area / result.contact_area)


# c/a of the coupled problem at beta = 0.5: mu = 0.2986 gives 0.5 (Spence 1975, as quoted by Kalker 1990
# sec. 5.3.1 and Vollebregt's CONTACT user guide, "Spence compression"); mu = 0.5 gives 0.800-0.815 in an
# independent axisymmetric ring BEM of the coupled problem (200 rings; it reproduces 0.497-0.499 at
# mu = 0.2986 and the centre pressure 1.31 p0_Hertz). docs/frictional_programmes.md has the table.
@pytest.mark.parametrize(("mu", "expected"), [(0.2986, 0.50), (0.5, 0.81)])
def test_frictional_indentation_is_self_similar_with_spences_stick_radius(mu, expected):
    result, ratio = _spence(mu, 32)
    # self-similar: the stick radius is a fixed fraction of the contact radius while the load grows
    assert np.ptp(ratio[-12:]) < 0.04
    assert ratio[-4:].mean() == pytest.approx(expected, abs=0.02)
    state = result.states[result.steps - 1]
    slip = state.contact & ~state.stick
    x, y = result.topography.coordinates()
    rx, ry = np.meshgrid(x - x.mean(), y - y.mean(), indexing="ij")
    radial = (state.shear_x * rx + state.shear_y * ry) / np.hypot(rx, ry)
    # slip annulus: q = mu p, radial and outward on the softer body (its surface is drawn inwards)
    np.testing.assert_allclose(
        np.hypot(state.shear_x, state.shear_y)[slip], mu * state.pressure[slip], rtol=1e-9
    )
    assert np.all(radial[slip] > 0.95 * mu * state.pressure[slip])
    assert abs(result.force[-1, 0]) < 1e-6 * mu * result.normal_load[-1]  # no net shear (symmetry)
    # the shear raises the centre pressure above Hertz's at the same load (Spence 1975: 1.31 p0)
    hertz_radius = (3 * result.normal_load[-1] * 1e-3 / (4 * 1e9)) ** (1 / 3)
    hertz_peak = 3 * result.normal_load[-1] / (2 * np.pi * hertz_radius**2)
    assert state.pressure.max() / hertz_peak == pytest.approx(1.31, abs=0.03)  # measured 1.30 (64^2)


def test_spence_stick_radius_converges_with_the_load_steps():
    """The slip annulus is 0.2 a wide at mu = 0.5: load steps must grow a by much less than that."""
    coarse = _spence(0.5, 8)[1][-1]
    fine = _spence(0.5, 32)[1][-1]
    assert abs(fine - 0.81) < 0.5 * abs(coarse - 0.81)  # measured 0.763 -> 0.805


# --- step control -----------------------------------------------------------------------------------


def test_step_control_puts_ten_steps_between_a_reversal_and_full_slip():
    """Three programme rows per stroke on a smooth sphere: the step control fills the pre-sliding parts."""
    ball, material, modulus, g_star = _spheres(48)
    a = mindlin.hertz_contact_radius(FORCE, RADIUS, modulus)
    full_slip = mindlin.sliding_displacement(MU, FORCE, a, g_star)  # delta at which Cattaneo slides
    rows = 2.5 * full_slip * np.array([0.5, 1.0, 0.5, 0.0, -0.5, -1.0])
    normal = solve_normal(ball, material, counter_body=material, force=FORCE)
    result = solve_tangential(
        normal,
        material,
        counter_body=material,
        friction_coefficient=MU,
        displacement=rows,
        max_stick_change=0.1,
    )
    fraction = result.stick_area / result.contact_area
    assert np.all(
        np.diff(fraction)[np.diff(result.programme_index) == 0] > -0.1 - 1e-12
    )  # never 10 % at once
    reversal = result.step_of(1)
    sliding = reversal + int(np.argmax(fraction[reversal + 1 :] < 0.02)) + 1
    assert sliding - reversal >= 10
    for row, target in enumerate(rows):  # every programme row is solved exactly
        assert result.displacement[result.step_of(row), 0] == pytest.approx(target, rel=1e-12)
    plain = solve_tangential(
        normal, material, counter_body=material, friction_coefficient=MU, displacement=rows
    )
    assert plain.steps == len(rows) and result.steps > len(rows) + 15
    # the rows' forces agree with the unrefined run's where both slide fully
    np.testing.assert_allclose(result.force[result.step_of(1)], plain.force[1], rtol=1e-6)


def test_an_approach_programme_meets_its_approaches(rough_ball):
    pom, silicon = get_material("POM"), get_material("silicon wafer")
    approach = np.array([0.2, 0.4, 0.6, 0.4]) * 1e-6
    result = solve_frictional(
        rough_ball,
        pom,
        counter_body=silicon,
        friction_coefficient=MU,
        approach=approach,
        displacement=np.array([0, 0.05, 0.1, 0.1]) * 1e-6,
    )
    np.testing.assert_allclose(result.approach, approach, rtol=1e-12)
    assert np.all(np.diff(result.normal_load)[:2] > 0) and result.normal_load[3] < result.normal_load[2]
    assert result.parameters["normal_control"] == "approach"


def test_a_periodic_surface_runs_under_tangential_force_control():
    surface = generate.self_affine((48, 48), 5e-6, hurst=0.8, rms_height=5e-9, seed=1)
    pom, silicon = get_material("POM"), get_material("silicon wafer")
    normal, force = np.array([1, 2, 3, 2]) * 1e-4, np.array([0, 1, 2, 1]) * 1e-5
    result = solve_frictional(
        surface, pom, counter_body=silicon, friction_coefficient=MU, normal_force=normal, force=force
    )
    assert result.parameters["boundary"] == "periodic"
    np.testing.assert_allclose(result.normal_load, normal, rtol=1e-8)
    np.testing.assert_allclose(result.force[:, 0], force, rtol=1e-8, atol=1e-12 * normal.max())
    with pytest.raises(InputError, match="periodic"):
        solve_frictional(surface, pom, friction_coefficient=MU, normal_force=normal, displacement=force * 0)
