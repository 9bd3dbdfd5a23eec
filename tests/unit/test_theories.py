"""The theories of rough contact (roughcontact.theory) against their own closed forms and limits.

Persson's area, pressure distribution and mean separation, BGT's small-load law, GW at a pressure,
the spectrum of a surface and the comparison with the BEM over realisations; each on small inputs.
The published values they are checked against are in tests/validation/test_theories_limits.py.
"""

import math

import numpy as np
import pytest
from scipy import integrate, special

from roughcontact.asperity.greenwood_williamson import gaussian_summits, greenwood_williamson
from roughcontact.errors import InputError
from roughcontact.theory import (
    Spectrum,
    against_bem,
    bgt_contact_fraction,
    gw_at_pressure,
    kappa_fit,
    persson_contact_fraction,
    persson_contact_fraction_magnified,
    persson_mean_separation,
    persson_pressure_distribution,
    surface_spectrum,
)
from roughcontact.topography.generate import self_affine
from roughcontact.topography.statistics import SpectralMoments, mccool_parameters, rms_slope, rq

E_STAR = 1e9


@pytest.fixture(scope="module")
def surface():
    return self_affine(
        (128, 128), 1e-6, hurst=0.8, rms_slope=0.1, short_cutoff=1e-6 / 16, seed=4, modes="wavevector"
    )


def test_spectrum_keeps_parseval_and_the_continuum_gradient(surface):
    spectrum = surface_spectrum(surface)
    assert spectrum.window is None  # periodic: no window
    assert spectrum.m0 == pytest.approx(rq(surface) ** 2, rel=1e-10)
    assert spectrum.m2 == pytest.approx(spectrum.rms_gradient**2 / 2, rel=1e-12)
    # 8 pixels per shortest wavelength: forward differences low by (sin(qh/2)/(qh/2)) ~ 1 - (qh)^2/24
    assert rms_slope(surface) == pytest.approx(spectrum.rms_gradient, rel=0.03)
    assert rms_slope(surface) < spectrum.rms_gradient
    assert spectrum.lowest == pytest.approx(2 * math.pi / 1e-6)
    assert spectrum.highest == pytest.approx(16 * 2 * math.pi / 1e-6, rel=0.07)  # the ring at q_s
    assert spectrum.cumulative_gradient(np.inf)[0] == pytest.approx(spectrum.rms_gradient)
    assert spectrum.cumulative_gradient(0.0)[0] == 0.0


def test_a_window_of_a_larger_surface_is_taken_with_a_hann_window(surface):
    from roughcontact.topography import Topography

    window = Topography(surface.heights, surface.size, periodic=False)
    assert surface_spectrum(window).window == "hann"
    with pytest.raises(InputError, match="profile"):
        surface_spectrum(Topography(surface.heights[:, 0], 1e-6, periodic=True))


def test_persson_area_is_erf_and_its_small_load_slope_is_sqrt_8_over_pi():
    g = 0.1
    x = np.array([1e-6, 0.1, 0.5, 2.0])
    area = persson_contact_fraction(x * E_STAR * g, contact_modulus=E_STAR, rms_gradient=g)
    assert area == pytest.approx(special.erf(math.sqrt(2) * x), rel=1e-14)
    assert area[0] / x[0] == pytest.approx(math.sqrt(8 / math.pi), rel=1e-9)
    assert persson_contact_fraction(0.0, contact_modulus=E_STAR, rms_gradient=g)[0] == 0.0


def test_persson_pressure_distribution_holds_the_area_and_the_load():
    g, p0 = 0.1, 0.05 * E_STAR * 0.1

    def density(s):
        return persson_pressure_distribution(s, mean_pressure=p0, contact_modulus=E_STAR, rms_gradient=g)[0]

    top = p0 + 10 * E_STAR * g
    area, _ = integrate.quad(density, 0, top, points=[p0], limit=200)
    load, _ = integrate.quad(lambda s: s * density(s), 0, top, points=[p0], limit=200)
    assert area == pytest.approx(
        persson_contact_fraction(p0, contact_modulus=E_STAR, rms_gradient=g)[0], rel=1e-8
    )
    assert load == pytest.approx(p0, rel=1e-8)  # P(0) = 0 keeps the load
    assert density(0.0) == 0.0 and density(-1.0) == 0.0


def test_persson_area_at_magnification_falls_to_the_full_band(surface):
    spectrum = surface_spectrum(surface)
    p0 = 0.05 * E_STAR * spectrum.rms_gradient
    zeta = np.array([1.0, 2.0, 4.0, 8.0, 16.0, 1e3])
    area = persson_contact_fraction_magnified(
        p0, contact_modulus=E_STAR, spectrum=spectrum, magnification=zeta
    )[0]
    assert np.all(np.diff(area) <= 0)
    full = persson_contact_fraction(p0, contact_modulus=E_STAR, rms_gradient=spectrum.rms_gradient)[0]
    assert area[-1] == pytest.approx(full, rel=1e-12)
    with pytest.raises(InputError, match="magnification"):
        persson_contact_fraction_magnified(p0, contact_modulus=E_STAR, spectrum=spectrum, magnification=0.5)


def _one_ring(q=1e7, v=1e-18):
    return Spectrum(q=np.array([q]), variance=np.array([v]), m4=0.375 * q**4 * v)


def test_persson_mean_separation_of_one_mode_is_the_double_integral():
    r"""One mode: u = q v w J(w p / E*) / (2 sqrt(pi)), J the inner integral, by adaptive quadrature."""
    q, v, gamma = 1e7, 1e-18, 0.4
    w = math.sqrt(2) / (q * math.sqrt(v))
    for p in (1e2, 1e4, 1e6):
        x0 = w * p / E_STAR
        inner, _ = integrate.quad(
            lambda x: (gamma + 3 * (1 - gamma) * special.erf(x) ** 2) * math.exp(-(x**2)) / x,
            x0,
            np.inf,
            limit=400,
        )
        expected = q * v * w * inner / (2 * math.sqrt(math.pi))
        found = persson_mean_separation(p, contact_modulus=E_STAR, spectrum=_one_ring(q, v), gamma=gamma)[0]
        assert found == pytest.approx(expected, rel=1e-6)


def test_persson_mean_separation_falls_logarithmically_at_small_load(surface):
    """Persson (2007): p ~ exp(-u / u0) at small load, u0 = gamma sum(q v w) / (2 sqrt(pi))."""
    spectrum = surface_spectrum(surface)
    gamma = 0.4
    q, v = spectrum.q, spectrum.variance
    carried = v > 0
    w = math.sqrt(2) / spectrum.cumulative_gradient(q[carried])
    u0 = gamma * float(np.sum(q[carried] * v[carried] * w)) / (2 * math.sqrt(math.pi))
    p = np.array([1e-9, 1e-8]) * E_STAR * spectrum.rms_gradient
    u = persson_mean_separation(p, contact_modulus=E_STAR, spectrum=spectrum, gamma=gamma)
    assert (u[0] - u[1]) / math.log(10) == pytest.approx(u0, rel=1e-3)
    loads = np.geomspace(1e-3, 3.0, 12) * E_STAR * spectrum.rms_gradient
    gaps = persson_mean_separation(loads, contact_modulus=E_STAR, spectrum=spectrum)
    assert np.all(np.diff(gaps) < 0) and np.all(gaps > 0)
    assert gaps[-1] < 1e-3 * gaps[0]  # full contact closes the gap
    with pytest.raises(InputError, match="diverges"):
        persson_mean_separation(0.0, contact_modulus=E_STAR, spectrum=spectrum)
    with pytest.raises(InputError, match="gamma"):
        persson_mean_separation(1e6, contact_modulus=E_STAR, spectrum=spectrum, gamma=1.5)


def test_bgt_is_linear_with_slope_sqrt_2_pi():
    x = np.array([0.0, 0.01, 0.1])
    area = bgt_contact_fraction(x * E_STAR * 0.2, contact_modulus=E_STAR, rms_gradient=0.2)
    assert area == pytest.approx(math.sqrt(2 * math.pi) * x, rel=1e-14)
    with pytest.raises(InputError, match="mean_pressure"):
        bgt_contact_fraction(-1.0, contact_modulus=E_STAR, rms_gradient=0.2)


def test_gw_at_a_pressure_carries_that_pressure():
    moments = SpectralMoments(m0=1e-18, m2=5e-3, m4=1e14)
    pressures = np.array([1e5, 1e6, 1e7])
    found = gw_at_pressure(pressures, contact_modulus=E_STAR, moments=moments)
    summits = gaussian_summits(mccool_parameters(m0=moments.m0, m2=moments.m2, m4=moments.m4))
    again = greenwood_williamson(found.summit_separation, summits, contact_modulus=E_STAR)
    assert again.force == pytest.approx(pressures, rel=1e-9)
    assert again.contact_area == pytest.approx(found.contact_fraction, rel=1e-12)
    offset = mccool_parameters(m0=moments.m0, m2=moments.m2, m4=moments.m4).summit_mean_offset
    assert found.mean_separation - found.summit_separation == pytest.approx(np.full(3, offset))
    slope = found.contact_fraction / (pressures / (E_STAR * math.sqrt(2 * moments.m2)))
    assert np.all(np.diff(slope) < 0)  # GW's kappa grows as the load falls: no linear law


def test_kappa_fit_uses_the_small_loads_only():
    x = np.array([0.01, 0.02, 0.05, 0.1, 0.2])
    area = 2.0 * x * (1 - x)  # 1.98 x at the smallest load, a falling slope above
    kappa, loads = kappa_fit(x, area, max_fraction=0.1)
    assert loads == 3
    assert kappa == pytest.approx(np.sum(area[:3] * x[:3]) / np.sum(x[:3] ** 2))
    assert kappa_fit(x, area, max_fraction=1e-3) == (pytest.approx(math.nan, nan_ok=True), 0)
    raw, used = kappa_fit(x, 1.1 * area, max_fraction=0.1, select=area)
    assert used == 3 and raw == pytest.approx(1.1 * kappa)


def test_against_bem_pairs_each_theory_with_the_bem_on_the_same_realisation():
    rng = np.random.default_rng(0)
    bem = 0.1 * (1 + 0.2 * rng.standard_normal((6, 2)))  # realisations x loads
    found = against_bem(
        {"over": 1.1 * bem, "same": bem.copy(), "under": 0.8 * bem},
        bem,
        quantity="contact_fraction",
        reduced_pressure=np.full(bem.shape, 0.05),
        mean_pressure=np.full(bem.shape, 5e6),
    )
    assert len(found) == 6 and all(d.reduced_pressure == pytest.approx(0.05) for d in found)
    words = {d.theory: {e.words for e in found if e.theory == d.theory} for d in found}
    assert words == {"over": {"over-predicts"}, "under": {"under-predicts"}, "same": {"not established"}}
    over = next(d for d in found if d.theory == "over")
    assert over.deviation.mean == pytest.approx(0.1) and over.deviation.std == pytest.approx(0.0, abs=1e-12)
    row = over.row()
    assert row["bem_ci95_low"] < row["bem_mean"] < row["bem_ci95_high"] and row["n"] == 6
    one = against_bem({"persson": bem[:1]}, bem[:1], quantity="kappa")
    assert one[0].words == "one realisation: no interval"
