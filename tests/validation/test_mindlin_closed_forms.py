"""Cattaneo-Mindlin and Mindlin-Deresiewicz closed forms checked against their definitions."""

import math

import numpy as np
import pytest
from scipy import integrate

from roughcontact.analytic.mindlin import (
    dissipated_energy,
    dissipated_energy_displacement,
    hertz_contact_radius,
    lateral_stiffness,
    masing_displacement,
    masing_force,
    shear_traction,
    sliding_displacement,
    stick_radius,
    tangential_displacement,
    tangential_force,
)
from roughcontact.contact.presliding import effective_shear_modulus_paper001
from roughcontact.errors import InputError
from roughcontact.materials import Material, contact_modulus, johnson_shear_modulus
from roughcontact.papers.paper001 import paper001_mindlin

HDPE = Material(0.98e9, 0.5, "HDPE")
SILICON = Material(130e9, 0.28, "silicon")
MU, P, A, G = 0.153, 25e-3, 40e-6, 0.1e9
ARGS = (MU, P, A, G)


def test_moduli_johnson_and_paper():
    g_star = johnson_shear_modulus(HDPE, SILICON)
    g_s = effective_shear_modulus_paper001(HDPE, SILICON)
    expected = 1.0 / sum((2 - m.poissons_ratio) / m.shear_modulus for m in (HDPE, SILICON))
    assert g_star == pytest.approx(expected, rel=1e-14)
    assert g_s == pytest.approx(4.0 * g_star, rel=1e-14)
    # (2 - nu)(1 + nu)/(2E) form of the paper
    printed = 1.0 / sum(
        (2 - m.poissons_ratio) * (1 + m.poissons_ratio) / (2 * m.youngs_modulus) for m in (HDPE, SILICON)
    )
    assert g_s == pytest.approx(printed, rel=1e-14)
    # rigid counter-body contributes nothing
    assert johnson_shear_modulus(HDPE) == pytest.approx(HDPE.shear_modulus / 1.5, rel=1e-14)


def test_stick_radius_limits():
    assert stick_radius(0.0, *ARGS[:3]) == pytest.approx(A, rel=1e-15)
    assert stick_radius(MU * P, *ARGS[:3]) == pytest.approx(0.0, abs=1e-15)
    assert stick_radius(-0.875 * MU * P, *ARGS[:3]) == pytest.approx(0.5 * A, rel=1e-12)
    with pytest.raises(InputError, match="force"):
        stick_radius(1.01 * MU * P, *ARGS[:3])


@pytest.mark.parametrize("ratio", [0.0, 0.2, 0.5, 0.9, 1.0])
def test_traction_integrates_to_q(ratio):
    q = ratio * MU * P
    c = stick_radius(q, *ARGS[:3])
    total = 0.0
    for lo, hi in ((0.0, c), (c, A)):  # integrate piecewise across the kink at r = c
        if hi > lo:
            value, _ = integrate.quad(
                lambda r: 2 * math.pi * r * shear_traction(r, q, *ARGS[:3]), lo, hi, epsabs=0, epsrel=1e-12
            )
            total += value
    assert total == pytest.approx(q, rel=1e-6, abs=1e-12 * MU * P)
    # the slip annulus carries the limiting traction mu p, the stick zone less
    p0 = 3 * P / (2 * math.pi * A**2)
    r_slip = 0.5 * (c + A)
    assert shear_traction(r_slip, q, *ARGS[:3]) == pytest.approx(MU * p0 * math.sqrt(1 - (r_slip / A) ** 2))
    assert shear_traction(1.1 * A, q, *ARGS[:3]) == 0.0


def test_displacement_and_force_are_inverse_and_saturate():
    delta0 = sliding_displacement(*ARGS)
    assert delta0 == pytest.approx(3 * MU * P / (16 * A * G))
    q = np.linspace(-MU * P, MU * P, 41)
    assert np.allclose(tangential_force(tangential_displacement(q, *ARGS), *ARGS), q, rtol=1e-12, atol=1e-15)
    assert tangential_displacement(MU * P, *ARGS) == pytest.approx(delta0)
    assert tangential_force(3 * delta0, *ARGS) == pytest.approx(MU * P)
    assert tangential_force(-3 * delta0, *ARGS) == pytest.approx(-MU * P)


@pytest.mark.parametrize("ratio", [0.0, 0.3, 0.6, 0.95])
def test_stiffness_is_derivative_of_displacement(ratio):
    q = ratio * MU * P
    h = 1e-7 * MU * P
    ddelta = (tangential_displacement(q + h, *ARGS) - tangential_displacement(q - h, *ARGS)) / (2 * h)
    assert lateral_stiffness(q, *ARGS) == pytest.approx(1.0 / ddelta, rel=1e-6)
    assert lateral_stiffness(0.0, *ARGS) == pytest.approx(8 * A * G)


def _loop_area_force_control(q_star):
    """Area of the Masing loop by quadrature: integral of (delta_unload - delta_reload) dQ."""

    def width(q):
        return masing_displacement(q, q_star, *ARGS, branch="unloading") - masing_displacement(
            q, q_star, *ARGS, branch="reloading"
        )

    value, _ = integrate.quad(width, -q_star, q_star, epsabs=0, epsrel=1e-11, limit=200)
    return value


@pytest.mark.parametrize("ratio", [0.05, 0.3, 0.7, 1.0])
def test_energy_closed_form_equals_masing_loop_area(ratio):
    q_star = ratio * MU * P
    assert dissipated_energy(q_star, *ARGS) == pytest.approx(_loop_area_force_control(q_star), rel=1e-8)


def test_energy_limits():
    delta0 = sliding_displacement(*ARGS)
    assert dissipated_energy(MU * P, *ARGS) == pytest.approx(0.8 * MU * P * delta0, rel=1e-12)
    q_star = 1e-3 * MU * P  # small amplitude: W ~ Q*^3 / (36 mu P a G*)
    assert dissipated_energy(q_star, *ARGS) == pytest.approx(q_star**3 / (36 * MU * P * A * G), rel=1e-2)


def test_masing_branches_close_the_loop():
    q_star = 0.6 * MU * P
    d_star = tangential_displacement(q_star, *ARGS)
    assert masing_displacement(q_star, q_star, *ARGS) == pytest.approx(d_star)
    assert masing_displacement(-q_star, q_star, *ARGS) == pytest.approx(-d_star)
    assert masing_displacement(-q_star, q_star, *ARGS, branch="reloading") == pytest.approx(-d_star)
    assert masing_displacement(q_star, q_star, *ARGS, branch="reloading") == pytest.approx(d_star)


def _closed_area(delta, force):
    """Closed-path integral of F d(delta) (trapezoids), positive for a clockwise loop in (delta, F)."""
    return abs(float(np.sum(0.5 * (force[1:] + force[:-1]) * np.diff(delta))))


def test_masing_force_symmetric_cycles_match_force_control():
    q_star = 0.7 * MU * P
    d_star = tangential_displacement(q_star, *ARGS)
    up = np.linspace(0, d_star, 400)
    down = np.linspace(d_star, -d_star, 4001)[1:]
    back = np.linspace(-d_star, d_star, 4001)[1:]
    path = np.concatenate([up, down, back, down, back])
    force = masing_force(path, *ARGS)
    assert force[len(up) - 1] == pytest.approx(q_star, rel=1e-12)
    n = len(up) - 1 + len(down)
    assert force[n] == pytest.approx(-q_star, rel=1e-12)
    # the unloading branch is the force-controlled Masing branch
    branch_delta = masing_displacement(force[len(up) : n], q_star, *ARGS)
    assert np.allclose(branch_delta, path[len(up) : n], rtol=0, atol=1e-9 * d_star)
    # steady loop area equals the closed form
    last = slice(len(path) - 2 * len(down) - 1, len(path))
    assert _closed_area(path[last], force[last]) == pytest.approx(dissipated_energy(q_star, *ARGS), rel=1e-5)


def test_masing_force_paper_path_with_gross_sliding():
    delta0 = sliding_displacement(*ARGS)
    stroke = 5 * delta0
    leg = np.linspace(0, stroke, 2001)
    path = np.concatenate([leg] + [leg[::-1][1:], leg[1:]] * 4)
    force = masing_force(path, *ARGS)
    assert np.max(np.abs(force)) == pytest.approx(MU * P, rel=1e-12)
    assert force[len(leg) - 1] == pytest.approx(MU * P)
    # after the first stroke every cycle is the same rhomboid
    n = 2 * (len(leg) - 1)
    last, previous = force[-n - 1 :], force[-2 * n - 1 : -n]
    assert np.allclose(last, previous, rtol=0, atol=1e-12 * MU * P)
    assert _closed_area(path[-n - 1 :], last) == pytest.approx(
        dissipated_energy_displacement(stroke, *ARGS), rel=1e-5
    )
    # reversal branch: Q = mu P - 2 Q_M((stroke - delta)/2)
    down = path[len(leg) : 2 * len(leg) - 1]
    expected = MU * P - 2 * tangential_force((stroke - down) / 2, *ARGS)
    assert np.allclose(force[len(leg) : 2 * len(leg) - 1], expected, rtol=0, atol=1e-12 * MU * P)


def test_masing_force_memory_inner_loop_wiped():
    delta0 = sliding_displacement(*ARGS)
    path = (
        np.concatenate(
            [np.linspace(0, 0.6, 61), np.linspace(0.6, 0.3, 31)[1:], np.linspace(0.3, 0.8, 51)[1:]]
        )
        * delta0
    )
    force = masing_force(path, *ARGS)
    # beyond the first reversal (0.6 delta0) the force is back on the virgin curve
    beyond = path > 0.6 * delta0 + 1e-15
    assert np.allclose(force[beyond], tangential_force(path[beyond], *ARGS), rtol=1e-12)


def test_displacement_energy_partial_slip_equals_force_form():
    delta0 = sliding_displacement(*ARGS)
    half = 0.4 * delta0
    amplitude = tangential_force(half, *ARGS)
    assert dissipated_energy_displacement(2 * half, *ARGS) == pytest.approx(
        dissipated_energy(amplitude, *ARGS)
    )


def test_paper001_printed_is_four_times_johnson():
    kw = dict(
        friction_coefficient=0.153, normal_force=25e-3, radius=5e-3, material=HDPE, counter_body=SILICON
    )
    johnson = paper001_mindlin(**kw)
    printed = paper001_mindlin(**kw, normalisation="printed")
    assert johnson.normalisation == "johnson"
    assert printed.contact_radius == johnson.contact_radius
    a = (3 * 25e-3 * 5e-3 / (4 * contact_modulus(HDPE, SILICON))) ** (1 / 3)
    assert johnson.contact_radius == pytest.approx(a, rel=1e-14)
    assert hertz_contact_radius(25e-3, 5e-3, contact_modulus(HDPE, SILICON)) == pytest.approx(a, rel=1e-14)
    for f in (0.0, 0.25, 0.5, 0.75):
        fx = f * 0.153 * 25e-3
        assert printed.lateral_stiffness(fx) / johnson.lateral_stiffness(fx) == pytest.approx(4.0, rel=1e-14)
    assert printed.sliding_distance / johnson.sliding_distance == pytest.approx(0.25, rel=1e-14)
    # eq. 12, both forms of the printed equation agree
    d = 0.3 * johnson.sliding_distance
    assert johnson.lateral_stiffness_at_displacement(d) == pytest.approx(
        johnson.lateral_stiffness(johnson.force(d)), rel=1e-12
    )
    with pytest.raises(InputError, match="normalisation"):
        paper001_mindlin(**kw, normalisation="paper")


def test_unit_invariance():
    """Scaling lengths by s and forces by f scales delta by s, K by f/s and W by f s."""
    s, f = 1e6, 1e3  # m -> um, N -> mN
    g = G * f / s**2
    kw = (MU, P * f, A * s, g)
    assert sliding_displacement(*kw) == pytest.approx(sliding_displacement(*ARGS) * s, rel=1e-13)
    assert lateral_stiffness(0.3 * MU * P * f, *kw) == pytest.approx(
        lateral_stiffness(0.3 * MU * P, *ARGS) * f / s, rel=1e-13
    )
    assert dissipated_energy(0.5 * MU * P * f, *kw) == pytest.approx(
        dissipated_energy(0.5 * MU * P, *ARGS) * f * s, rel=1e-13
    )
    path = np.linspace(0, 3 * sliding_displacement(*ARGS), 50)
    assert np.allclose(masing_force(path * s, *kw), masing_force(path, *ARGS) * f, rtol=1e-12)


@pytest.mark.parametrize(
    "call, field",
    [
        (lambda: sliding_displacement(-0.1, P, A, G), "friction_coefficient"),
        (lambda: sliding_displacement(MU, P, 0.0, G), "contact_radius"),
        (lambda: masing_force([0.0, np.nan], *ARGS), "displacement_path"),
        (lambda: dissipated_energy(2 * MU * P, *ARGS), "force_amplitude"),
        (lambda: masing_displacement(0.0, 0.5 * MU * P, *ARGS, branch="up"), "branch"),
    ],
)
def test_bad_input_names_field(call, field):
    with pytest.raises(InputError) as info:
        call()
    assert info.value.field == field
