"""The theories of rough contact and the BEM's contact area against published values (docs/theories.md).

* Persson's small-load slope sqrt(8/pi) = 1.596 and his full-contact limit (Persson 2001, 2006);
* Bush-Gibson-Thomas's small-load slope sqrt(2 pi) = 2.507 (Bush, Gibson and Thomas 1975);
* Persson's (2007) mean separation beside the BEM's mean gap on a self-affine surface: within a
  few per cent, as Almqvist et al. (2011) found;
* the perimeter-corrected area (Yastrebov et al. 2017): exact on a Hertz contact to a fraction of
  a per cent where the raw count is a per cent high, and converging faster than the raw count under
  refinement of one self-affine surface (modes shared across the grids);
* the BEM's small-load kappa on well-resolved self-affine surfaces (16 pixels per shortest
  wavelength) at three Hurst exponents: slightly above 2 and barely dependent on H (Hyun et al.
  2004: about 2; Prodanov et al. 2014; Yastrebov et al. 2017), between Persson's and BGT's.
"""

import math

import numpy as np
import pytest

from roughcontact.analytic import hertz
from roughcontact.contact import solve_normal
from roughcontact.theory import (
    bgt_contact_fraction,
    compare_theories,
    persson_contact_fraction,
    surface_spectrum,
)
from roughcontact.theory.bgt import KAPPA as BGT_KAPPA
from roughcontact.theory.persson import KAPPA as PERSSON_KAPPA
from roughcontact.topography.generate import self_affine, sphere

E_STAR = 1e9
SIDE = 1e-6


def test_persson_small_load_slope_is_1_596_and_full_contact_is_reached():
    assert PERSSON_KAPPA == pytest.approx(1.5958, abs=1e-4)
    g = 0.1
    x = np.array([1e-5, 1e-3])
    slope = persson_contact_fraction(x * E_STAR * g, contact_modulus=E_STAR, rms_gradient=g) / x
    assert slope == pytest.approx(np.full(2, math.sqrt(8 / math.pi)), rel=1e-5)
    # full contact: 1 - A/A0 = erfc(sqrt 2 x) ~ exp(-2 x^2) / (sqrt(2 pi) x) as x grows
    x = np.array([2.5, 3.0, 3.5])  # 1 - erf keeps 4 digits up to 3.5
    gap = 1 - persson_contact_fraction(x * E_STAR * g, contact_modulus=E_STAR, rms_gradient=g)
    asymptote = np.exp(-2 * x**2) / (math.sqrt(2 * math.pi) * x)
    assert gap / asymptote == pytest.approx(np.ones(3), rel=0.04)
    assert np.all(np.diff(gap / asymptote) > 0)  # the asymptotic series: relative error ~ 1/(4 x^2)


def test_bgt_small_load_slope_is_2_507():
    assert BGT_KAPPA == pytest.approx(2.5066, abs=1e-4)
    assert bgt_contact_fraction(0.01 * E_STAR * 0.2, contact_modulus=E_STAR, rms_gradient=0.2)[0] / 0.01 == (
        pytest.approx(math.sqrt(2 * math.pi))
    )


def test_persson_mean_separation_beside_the_bem():
    """Almqvist et al. (2011): Persson's mean separation follows the BEM's mean gap over the loads."""
    surface = self_affine(
        (256, 256),
        SIDE,
        hurst=0.8,
        rms_slope=0.1,
        short_cutoff=SIDE / 32,
        long_cutoff=SIDE / 4,
        rolloff=1.0,
        seed=3,
    )
    result = compare_theories(surface, E_STAR, reduced_pressures=[0.01, 0.03, 0.1, 0.3])
    ratio = result.persson_mean_gap / result.mean_gap
    assert ratio == pytest.approx(np.ones(4), abs=0.1)


def _hertz_area_errors(n: int) -> tuple[float, float]:
    contact = hertz(radius=1e-3, contact_modulus=E_STAR, force=1e-3)
    a = contact.contact_radius
    ball = sphere((n, n), (4 * a, 4 * a), radius=1e-3, kind="paraboloid")
    result = solve_normal(ball, E_STAR, force=1e-3, tolerance=1e-10)
    exact = math.pi * a**2
    return result.contact_area / exact - 1, result.contact_area_corrected / exact - 1


def test_corrected_area_of_a_hertz_contact_converges_faster_than_the_pixel_count():
    errors = {n: _hertz_area_errors(n) for n in (32, 64, 128)}
    for n, (raw, corrected) in errors.items():
        assert raw > 0, n  # the pixel count over-estimates
        assert abs(corrected) < raw, n
    assert abs(errors[128][1]) < 2e-3 < errors[128][0]  # 32 pixels per radius: 0.04 % against 1 %


def test_corrected_area_of_one_rough_surface_converges_under_refinement():
    """One surface on 64^2 to 1024^2 (modes kept); reference: the raw count extrapolated at first order."""
    fractions = {}
    for n in (64, 128, 256, 512, 1024):
        surface = self_affine(  # per wavevector: the same modes on every grid
            (n, n),
            SIDE,
            hurst=0.8,
            rms_slope=0.1,
            short_cutoff=SIDE / 16,
            long_cutoff=SIDE / 4,
            rolloff=1.0,
            seed=1,
            modes="wavevector",
        )
        g = surface_spectrum(surface).rms_gradient
        result = solve_normal(surface, E_STAR, mean_pressure=0.05 * E_STAR * g, tolerance=1e-10)
        fractions[n] = (result.contact_fraction, result.contact_fraction_corrected)
    reference = 2 * fractions[1024][0] - fractions[512][0]  # raw(h) = A + c h
    raw = {n: f[0] / reference - 1 for n, f in fractions.items()}
    corrected = {n: f[1] / reference - 1 for n, f in fractions.items()}
    for n in fractions:
        assert abs(corrected[n]) < abs(raw[n]) or n == 1024, (n, raw[n], corrected[n])
    assert raw[128] > 0.05 and abs(corrected[128]) < 0.015  # 8 pixels per shortest wavelength
    assert abs(corrected[1024]) < 3e-3  # the two estimates of the area agree
    assert all(raw[a] > raw[b] for a, b in zip((64, 128, 256), (128, 256, 512), strict=True))


@pytest.mark.parametrize("hurst", [0.3, 0.5, 0.8])
def test_bem_kappa_on_well_resolved_self_affine_surfaces_is_slightly_above_2(hurst):
    kappas = []
    for seed in range(3):
        surface = self_affine(
            (512, 512),
            SIDE,
            hurst=hurst,
            rms_slope=0.1,
            short_cutoff=SIDE / 32,
            long_cutoff=SIDE / 4,
            rolloff=1.0,
            seed=seed,
            modes="wavevector",
        )
        result = compare_theories(surface, E_STAR, reduced_pressures=[0.0025, 0.005, 0.01, 0.02, 0.04])
        kappa, loads = result.kappa
        assert loads == 5
        kappas.append(kappa)
    mean = float(np.mean(kappas))
    assert 1.9 <= mean <= 2.4, kappas
    assert PERSSON_KAPPA < min(kappas) and max(kappas) < BGT_KAPPA
