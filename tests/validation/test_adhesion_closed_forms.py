"""Closed-form adhesive contacts (roughcontact.analytic.adhesion) against their limits and derivations.

Tolerances are the measured deviations rounded up (the printed values in the comments). No
published table of Maugis-Dugdale pull-off forces or of Johnson's (1995) wavy pull-off was
available to compare with digit by digit; the intermediate values below are therefore checked
against limits, asymptotes and independent derivations, and the table is a regression.
"""

import math

import numpy as np
import pytest

from roughcontact.analytic import (
    WAVY_JKR_SPONTANEOUS_ALPHA,
    dmt_pull_off,
    jkr_pull_off,
    maugis_dugdale,
    maugis_dugdale_curve,
    maugis_dugdale_pull_off,
    maugis_parameter,
    tabor_parameter,
    wavy_adhesion_parameter,
    wavy_jkr,
    wavy_jkr_mean_pressure,
    wavy_jkr_pressure,
    wavy_jkr_pull_off,
    westergaard_contact_half_width,
)
from roughcontact.errors import InputError

# --- sphere -----------------------------------------------------------------------------------


def test_jkr_and_dmt_pull_off():
    assert jkr_pull_off(0.05, 1e-6) == pytest.approx(1.5 * math.pi * 0.05e-6, rel=1e-15)
    assert dmt_pull_off(0.05, 1e-6) == pytest.approx(2.0 * math.pi * 0.05e-6, rel=1e-15)
    with pytest.raises(InputError):
        jkr_pull_off(-1.0, 1e-6)


def test_maugis_parameter_is_1p157_tabor_for_lennard_jones_peak_stress():
    w, r, e, z0 = 0.1, 1e-7, 5e10, 3e-10
    sigma0 = 16.0 * w / (9.0 * math.sqrt(3.0) * z0)  # peak of the LJ 9-3 law, w = its integral
    ratio = maugis_parameter(w, r, e, sigma0) / tabor_parameter(w, r, e, z0)
    assert ratio == pytest.approx(
        16.0 / (9.0 * math.sqrt(3.0)) * (9.0 / (2.0 * math.pi)) ** (1 / 3), rel=1e-12
    )
    assert ratio == pytest.approx(1.16, abs=0.003)  # Johnson & Greenwood (1997): lambda = 1.16 mu


def test_maugis_dugdale_pull_off_limits():
    # measured: |P_c - 1.5| = 1.6e-3 at lambda = 10, 4.1e-4 at 20, 1.6e-5 at 100 (~ lambda^-2)
    assert maugis_dugdale_pull_off(10.0) == pytest.approx(1.5, abs=2e-3)
    assert maugis_dugdale_pull_off(20.0) == pytest.approx(1.5, abs=5e-4)
    assert maugis_dugdale_pull_off(100.0) == pytest.approx(1.5, abs=2e-5)
    # measured: |P_c - 2| = 1.7e-3 at lambda = 0.01, 1.9e-2 at 0.05
    assert maugis_dugdale_pull_off(0.01) == pytest.approx(2.0, abs=2e-3)
    assert maugis_dugdale_pull_off(0.05) == pytest.approx(2.0, abs=2e-2)


def test_maugis_dugdale_pull_off_decreases_with_lambda():
    lams = [0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0, 3.0, 5.0, 10.0, 30.0]
    pc = [maugis_dugdale_pull_off(lam) for lam in lams]
    assert all(p1 > p2 for p1, p2 in zip(pc[:-1], pc[1:], strict=True))
    assert all(1.5 < p < 2.0 for p in pc)


@pytest.mark.parametrize(
    "lam, expected",
    # this module's values (no published table found to compare with; regression only)
    [(0.1, 1.950595), (0.3, 1.815556), (1.0, 1.600735), (3.0, 1.516764)],
)
def test_maugis_dugdale_pull_off_regression(lam, expected):
    assert maugis_dugdale_pull_off(lam) == pytest.approx(expected, abs=2e-6)


def test_maugis_dugdale_pull_off_is_the_curve_minimum():
    a = np.linspace(0.0, 3.0, 601)
    for lam in (0.1, 1.0, 5.0):
        p, _, _ = maugis_dugdale_curve(lam, a)
        assert -maugis_dugdale_pull_off(lam) <= p.min() + 1e-12
        assert -maugis_dugdale_pull_off(lam) == pytest.approx(p.min(), abs=1e-4)
    # the minimum is at a finite radius that shrinks to A = 0 as lambda -> 0 (DMT)
    radii = []
    for lam in (0.01, 0.1, 1.0):
        p, _, _ = maugis_dugdale_curve(lam, a)
        radii.append(a[np.argmin(p)])
        assert p[0] > p.min()
    assert radii[0] < 0.03 < radii[1] < radii[2]


def test_maugis_dugdale_curve_jkr_limit():
    a = np.linspace(0.2, 2.5, 24)
    jkr_p, jkr_d = a**3 - np.sqrt(6.0 * a**3), a**2 - 2.0 / 3.0 * np.sqrt(6.0 * a)
    errors = []
    for lam in (10.0, 20.0, 1000.0):
        p, d, m = maugis_dugdale_curve(lam, a)
        assert np.all(m > 1.0)
        errors.append((np.abs(p - jkr_p).max(), np.abs(d - jkr_d).max()))
    # measured max |P - P_JKR| = 0.061, 0.0155, 6.2e-6 and |Delta - Delta_JKR| = 0.021, 0.0054, 2.2e-6
    assert errors[0][0] < 0.07 and errors[1][0] < 0.02 and errors[2][0] < 1e-5
    assert errors[2][1] < 3e-6
    assert errors[1][0] < errors[0][0] / 3.5  # O(lambda^-2)


def test_maugis_dugdale_curve_dmt_limit_and_small_radius():
    a = np.linspace(0.0, 2.5, 11)
    p, d, _ = maugis_dugdale_curve(1e-4, a)
    # measured: 5.9e-3 in P, 1.5e-2 in Delta at lambda = 1e-4 (the DMT approach is slow in Delta)
    assert np.abs(p - (a**3 - 2.0)).max() < 1e-2 and np.abs(d - a**2).max() < 2e-2
    p0, d0, m0 = maugis_dugdale_curve(1.0, [0.0, 1e-7])
    assert (
        m0[0] == math.inf
        and p0[1] == pytest.approx(p0[0], abs=1e-6)
        and d0[1] == pytest.approx(d0[0], abs=1e-6)
    )
    with pytest.raises(InputError):
        maugis_dugdale_curve(1.0, [-0.1])


def test_maugis_dugdale_dimensional_helper():
    w, r, e, s0 = 0.05, 1e-6, 1e9, 5e7
    lam = maugis_parameter(w, r, e, s0)
    k = 4.0 / 3.0 * e
    a = np.array([0.0, 20e-9, 60e-9])
    md = maugis_dugdale(a, radius=r, contact_modulus=e, work_of_adhesion=w, peak_stress=s0)
    p, d, m = maugis_dugdale_curve(lam, a / (math.pi * w * r**2 / k) ** (1 / 3))
    assert md.maugis_parameter == lam
    np.testing.assert_allclose(md.force, p * math.pi * w * r, rtol=1e-14)
    np.testing.assert_allclose(md.approach, d * (math.pi**2 * w**2 * r / k**2) ** (1 / 3), rtol=1e-14)
    np.testing.assert_allclose(md.cohesive_radius[1:], m[1:] * a[1:], rtol=1e-14)


# --- wavy surface -----------------------------------------------------------------------------

E_STAR, WAVELENGTH, AMPLITUDE = 1e7, 1e-4, 1e-6  # Pa, m, m
P_FULL = math.pi * E_STAR * AMPLITUDE / WAVELENGTH  # p* [Pa]


def _w(alpha: float) -> float:
    """Work of adhesion [J/m^2] giving Johnson's alpha on the test surface."""
    return alpha**2 * math.pi**2 * AMPLITUDE**2 * E_STAR / (2.0 * WAVELENGTH)


def test_wavy_alpha_definition():
    assert wavy_adhesion_parameter(WAVELENGTH, AMPLITUDE, E_STAR, _w(0.3)) == pytest.approx(0.3, rel=1e-14)


def test_wavy_alpha_to_zero_is_westergaard():
    a = np.linspace(0.0, 0.49, 50) * WAVELENGTH
    p = wavy_jkr_mean_pressure(a, WAVELENGTH, AMPLITUDE, E_STAR, 1e-30)
    np.testing.assert_allclose(p, P_FULL * np.sin(np.pi * a / WAVELENGTH) ** 2, rtol=0, atol=1e-8 * P_FULL)
    half = westergaard_contact_half_width(
        p[20], amplitude=AMPLITUDE, wavelength=WAVELENGTH, contact_modulus=E_STAR
    )
    assert half == pytest.approx(a[20], rel=1e-6)


@pytest.mark.parametrize("a_over_lambda", [0.1, 0.3])
def test_wavy_stress_intensity_gives_g_equal_w(a_over_lambda):
    """p ~ -K / sqrt(2 pi r) at the contact edge, and K^2 / (2 E*) = w."""
    w = _w(0.3)
    a = a_over_lambda * WAVELENGTH
    r = a * np.array([1e-6, 1e-7])
    p = wavy_jkr_pressure(a - r, a, WAVELENGTH, AMPLITUDE, E_STAR, w)
    k = -p * np.sqrt(2.0 * np.pi * r)
    assert k[1] ** 2 / (2.0 * E_STAR) == pytest.approx(w, rel=1e-5)
    # the mean of the pressure distribution is the mean pressure (integrable edge singularities)
    n = 2000  # Gauss-Chebyshev in u = sin(pi x / lambda) / sin(psi) takes the 1/sqrt exactly
    s = math.sin(math.pi * a / WAVELENGTH)
    u = np.cos((2 * np.arange(1, n + 1) - 1) * np.pi / (2 * n))
    theta = np.arcsin(s * u)
    x = theta * WAVELENGTH / np.pi
    # p dx = p(theta) (lambda / pi) s du / cos(theta); times sqrt(1 - u^2) to undo the weight
    weight = np.sqrt(1.0 - u**2) * s / np.cos(theta) / np.pi
    mean = np.pi / n * np.sum(wavy_jkr_pressure(x, a, WAVELENGTH, AMPLITUDE, E_STAR, w) * weight)
    assert mean == pytest.approx(float(wavy_jkr_mean_pressure(a, WAVELENGTH, AMPLITUDE, E_STAR, w)), rel=1e-9)


def _punch_series(psi: float, n_terms: int) -> np.ndarray:
    """Fourier cosine coefficients b_n (n = 0..N) of the unit-mean periodic flat-punch pressure
    cos(theta) / sqrt(sin^2 psi - sin^2 theta), theta = pi x / lambda: b_n = (P_n(c) + P_{n-1}(c))/2,
    c = cos(2 psi) (Legendre), checked against Gauss-Chebyshev quadrature in the test."""
    c = math.cos(2.0 * psi)
    leg = np.empty(n_terms + 1)
    leg[0], leg[1] = 1.0, c
    for n in range(1, n_terms):
        leg[n + 1] = ((2 * n + 1) * c * leg[n] - n * leg[n - 1]) / (n + 1)
    b = np.empty(n_terms + 1)
    b[0] = 1.0
    b[1:] = 0.5 * (leg[1:] + leg[:-1])
    return b


def test_wavy_energy_release_rate_from_flat_punch_compliance():
    """Independent of K: G = -(lambda p1^2 / 4) dC/da from the periodic flat-punch compliance.

    A cosine pressure 2 b_n p1 cos(q x) on the half-plane gives the approach 4 b_n p1 cos(q x) / (E* q)
    (p* = pi E* Delta / lambda flattens amplitude Delta), so the punch's approach relative to the mean
    surface is C p1 with C = (2 lambda / (pi E*)) sum b_n / n. At fixed mean load p1 (two contact edges
    per period) the energy release rate is G = -(lambda p1^2 / 4) dC/da, which must equal w with
    p1 = p* sin^2 psi - p_bar.
    """
    psi = 0.7
    # the Legendre form of b_n against Gauss-Chebyshev quadrature (exact for these degrees)
    m = 200
    theta = np.arcsin(math.sin(psi) * np.cos((2 * np.arange(1, m + 1) - 1) * np.pi / (2 * m)))
    quad = np.cos(2.0 * np.outer(np.arange(41), theta)).mean(axis=1)
    np.testing.assert_allclose(_punch_series(psi, 40), quad, atol=1e-13)

    n_terms = 60000
    n = np.arange(1, n_terms + 1)

    def compliance(p):
        return 2.0 * WAVELENGTH / (np.pi * E_STAR) * np.sum(_punch_series(p, n_terms)[1:] / n)

    # C = -(2 lambda / (pi E*)) ln sin psi, and the punch is flat inside the contact
    assert compliance(psi) == pytest.approx(
        -2.0 * WAVELENGTH / (np.pi * E_STAR) * math.log(math.sin(psi)), rel=1e-6
    )
    b = _punch_series(psi, n_terms)[1:]
    for t in (0.3 * psi, 0.8 * psi):
        assert abs(np.sum(b * (np.cos(2 * n * t) - 1.0) / n)) < 1e-5 * np.sum(b / n)

    h = 1e-3
    da = 2.0 * h * WAVELENGTH / np.pi
    dc_da = (compliance(psi + h) - compliance(psi - h)) / da
    for alpha in (0.1, 0.4):
        w = _w(alpha)
        a = psi * WAVELENGTH / np.pi
        p1 = P_FULL * math.sin(psi) ** 2 - float(wavy_jkr_mean_pressure(a, WAVELENGTH, AMPLITUDE, E_STAR, w))
        g = -WAVELENGTH * p1**2 / 4.0 * dc_da
        assert g == pytest.approx(w, rel=1e-4)


def test_wavy_pull_off_small_alpha_asymptote_and_extrema():
    # p_bar_c -> -3 (alpha/4)^(4/3) p*: measured relative deviation 1.1e-4 at alpha = 0.01, 2.5e-3 at 0.1
    for alpha, tol in ((0.01, 2e-4), (0.1, 3e-3)):
        pull = wavy_jkr_pull_off(WAVELENGTH, AMPLITUDE, E_STAR, _w(alpha))
        assert pull == pytest.approx(3.0 * (alpha / 4.0) ** (4.0 / 3.0) * P_FULL, rel=tol)
    w = _w(0.3)
    state = wavy_jkr(WAVELENGTH, AMPLITUDE, E_STAR, w)
    assert not state.spontaneous and state.pull_off_half_width < state.jump_in_half_width
    for a, value in (
        (state.pull_off_half_width, -state.pull_off_pressure),
        (state.jump_in_half_width, state.jump_in_pressure),
    ):
        a3 = a + np.array([-1e-4, 0.0, 1e-4]) * WAVELENGTH
        p = wavy_jkr_mean_pressure(a3, WAVELENGTH, AMPLITUDE, E_STAR, w)
        assert p[1] == pytest.approx(value, rel=1e-12)
        assert abs(p[2] - p[0]) < 1e-6 * P_FULL  # stationary
    grid = np.linspace(1e-6, state.jump_in_half_width, 4001)
    assert wavy_jkr_mean_pressure(grid, WAVELENGTH, AMPLITUDE, E_STAR, w).min() >= -state.pull_off_pressure


def test_wavy_spontaneous_jump_into_full_contact():
    # Johnson (1995) quotes alpha > 0.57; derived: max p_bar = 0 at psi = pi/3, alpha = 3^(3/4)/4
    assert WAVY_JKR_SPONTANEOUS_ALPHA == pytest.approx(0.5699, abs=1e-4)
    below = wavy_jkr(WAVELENGTH, AMPLITUDE, E_STAR, _w(WAVY_JKR_SPONTANEOUS_ALPHA * (1 - 1e-9)))
    assert not below.spontaneous and 0.0 < below.jump_in_pressure < 1e-8 * P_FULL
    assert below.jump_in_half_width == pytest.approx(WAVELENGTH / 3.0, rel=1e-3)
    above = wavy_jkr(WAVELENGTH, AMPLITUDE, E_STAR, _w(WAVY_JKR_SPONTANEOUS_ALPHA * (1 + 1e-9)))
    assert above.spontaneous and above.pull_off_pressure == math.inf and above.jump_in_pressure == 0.0
    with pytest.raises(InputError):
        wavy_jkr_mean_pressure(WAVELENGTH / 2.0, WAVELENGTH, AMPLITUDE, E_STAR, _w(0.1))
