"""Real contact area on unloading: the single-asperity law and the statistical (KKE) unloading branch.

The single-asperity law A = A_max ((omega - omega_res)/(omega_max - omega_res))^m_A with
m_A = (omega*_max)^-0.12 is recalled, not verified against the papers' text (``docs/asperity.md``);
these tests pin its limits, its agreement with the elastic-unloading stiffness 2 E' a (Sneddon) and
that the statistical branch is the weighted sum of it over the summits.
"""

import math

import numpy as np
import pytest

from roughcontact.asperity import (
    critical_interference,
    gaussian_summits,
    kogut_etsion_area,
    kogut_etsion_load,
    residual_interference_ratio,
    statistical_load_unload,
    unloading_exponent,
    unloading_load,
)
from roughcontact.asperity.elastic_plastic import KOGUT_ETSION_MAX, unloading_area, unloading_area_exponent
from roughcontact.errors import InputError
from roughcontact.papers import paper002
from roughcontact.topography.statistics import mccool_parameters

SU8 = dict(hardness=0.462e9, poissons_ratio=0.22, contact_modulus=7.9727e9, radius=5.08e-6)
OMEGA_C = critical_interference(**SU8)
RADIUS = SU8["radius"]
SUMMITS = gaussian_summits(mccool_parameters(**paper002.MOMENTS))
PAPER_RUN = dict(
    contact_modulus=7.9727e9, hardness=0.462e9, poissons_ratio=0.22, nominal_area=625e-12, max_force=1e-3
)


def _area(omega, w_max):
    """Unloading area [m^2] of an SU-8 summit loaded to w_max omega_c on the Kogut-Etsion area law."""
    max_area = math.pi * RADIUS * OMEGA_C * kogut_etsion_area(w_max)
    return unloading_area(
        omega, max_interference=w_max * OMEGA_C, max_area=max_area, critical_interference=OMEGA_C
    )


# --- single asperity -----------------------------------------------------------------------------


def test_unloading_area_exponent_anchor_points():
    # Hertz (m_A = 1) up to omega_c, then the recalled fit (exact arithmetic: rel 1e-12)
    assert unloading_area_exponent(0.0) == 1.0
    assert unloading_area_exponent(0.5) == 1.0
    assert unloading_area_exponent(1.0) == pytest.approx(1.0, rel=1e-12, abs=0)
    assert unloading_area_exponent(6.0) == pytest.approx(6.0**-0.12, rel=1e-12, abs=0)
    assert unloading_area_exponent(110.0) == pytest.approx(110.0**-0.12, rel=1e-12, abs=0)
    exponents = unloading_area_exponent(np.linspace(1, 110, 300))
    assert np.all(np.diff(exponents) < 0)
    assert exponents.min() > 0.56


def test_unloading_area_exponent_agrees_with_elastic_unloading_stiffness():
    # Elastic unloading has dP/d omega = 2 E' a (Sneddon), so with P ~ x^n the area goes as x^(2(n-1)).
    # From the load exponent n = 1.5 omega*^-0.0331 this is 1 at omega* = 1 and within 3 % of
    # omega*^-0.12 over the whole fit range: an independent check of the recalled coefficient.
    w = np.geomspace(1.0, KOGUT_ETSION_MAX, 500)
    from_stiffness = 2.0 * (unloading_exponent(w) - 1.0)
    assert from_stiffness[0] == pytest.approx(1.0, rel=1e-12, abs=0)
    np.testing.assert_allclose(unloading_area_exponent(w), from_stiffness, rtol=0.03, atol=0)


@pytest.mark.parametrize("w_max", [0.3, 1.0, 1.0 + 1e-9, 2.0, 6.0, 30.0, 110.0])
def test_unloading_area_limits(w_max):
    max_area = math.pi * RADIUS * OMEGA_C * kogut_etsion_area(w_max)
    omega_max = w_max * OMEGA_C
    residual = residual_interference_ratio(w_max) * omega_max
    # the loading law's area at the peak: continuous there (rel 1e-12)
    assert _area(omega_max, w_max) == pytest.approx(max_area, rel=1e-12, abs=0)
    # zero exactly at the residual interference and below it, where the load vanishes too
    assert _area(residual, w_max) == 0.0
    assert _area(0.0, w_max) == 0.0
    assert _area(0.5 * residual, w_max) == 0.0
    # the power law in between (rel 1e-12)
    omega = residual + 0.3 * (omega_max - residual)
    assert _area(omega, w_max) == pytest.approx(
        max_area * 0.3 ** unloading_area_exponent(w_max), rel=1e-12, abs=0
    )


@pytest.mark.parametrize("w_max", [0.05, 0.5, 1.0])
def test_elastic_unloading_area_retraces_the_loading_area(w_max):
    # omega_max <= omega_c: omega_res = 0 and m_A = 1, so A = pi R omega, the Hertz (= KE) loading area
    omega = np.linspace(0.0, w_max * OMEGA_C, 41)
    loading = math.pi * RADIUS * OMEGA_C * kogut_etsion_area(omega / OMEGA_C)
    np.testing.assert_allclose(_area(omega, w_max), loading, rtol=1e-12, atol=0)
    np.testing.assert_allclose(_area(omega, w_max), math.pi * RADIUS * omega, rtol=1e-12, atol=0)


def test_unloading_area_is_monotonic_finite_and_vanishes_with_the_load():
    for w_max in [1e-6, 0.5, 1.0, 1.5, 6.0, 6.0 + 1e-9, 50.0, 110.0]:
        omega_max = w_max * OMEGA_C
        residual = residual_interference_ratio(w_max) * omega_max
        omega = np.unique(np.concatenate([np.linspace(0.0, omega_max, 501), [residual]]))
        area = _area(omega, w_max)
        load = unloading_load(
            omega,
            max_interference=omega_max,
            max_force=kogut_etsion_load(w_max),
            critical_interference=OMEGA_C,
        )
        assert np.all(np.isfinite(area))
        assert np.all(np.diff(area) >= 0)  # grows with omega: falls monotonically on unloading
        assert np.all((area > 0) == (load > 0))  # area and load vanish together, at omega_res
        assert area[-1] == pytest.approx(math.pi * RADIUS * OMEGA_C * kogut_etsion_area(w_max), rel=1e-12)


def test_unloading_area_refuses_what_no_fit_covers():
    with pytest.raises(InputError, match="110"):  # beyond omega* = 110: the existing rule, no fit
        unloading_area(1e-7, max_interference=111 * OMEGA_C, max_area=1e-12, critical_interference=OMEGA_C)
    with pytest.raises(InputError, match="max_interference"):  # reloading beyond omega_max
        unloading_area(2e-8, max_interference=1e-8, max_area=1e-12, critical_interference=OMEGA_C)
    with pytest.raises(InputError, match="finite"):
        unloading_area(math.nan, max_interference=1e-8, max_area=1e-12, critical_interference=OMEGA_C)
    with pytest.raises(InputError, match="max_area"):
        unloading_area(1e-9, max_interference=1e-8, max_area=-1.0, critical_interference=OMEGA_C)
    with pytest.raises(InputError, match="max_interference"):
        unloading_area(0.0, max_interference=0.0, max_area=1e-12, critical_interference=OMEGA_C)


# --- statistical unloading branch -----------------------------------------------------------------


def _summed_unloading_area(result, separations):
    """Independent sum of ``unloading_area`` over the Gaussian summits (SI), loaded to the peak."""
    lowest, omega_c = result.separation[result.peak], result.critical_interference
    omega_max = SUMMITS.heights - lowest
    keep = (omega_max > 0) & (omega_max <= KOGUT_ETSION_MAX * omega_c)
    count = SUMMITS.summit_density * PAPER_RUN["nominal_area"]
    total = np.zeros(len(separations))
    for height, weight, peak in zip(
        SUMMITS.heights[keep], SUMMITS.weights[keep], omega_max[keep], strict=True
    ):
        max_area = math.pi * SUMMITS.summit_radius * omega_c * kogut_etsion_area(peak / omega_c)
        omega = np.minimum(height - np.asarray(separations), peak)
        total += weight * unloading_area(
            omega,
            max_interference=peak,
            max_area=max_area,
            critical_interference=omega_c,
        )
    return count * total


def test_statistical_unloading_area_is_the_summed_single_asperity_law():
    result = statistical_load_unload(SUMMITS, **PAPER_RUN, reference_force=25e-6, steps=12)
    unloading = result.branch == "unloading"
    assert np.all(np.isfinite(result.contact_area))
    expected = _summed_unloading_area(result, result.separation[unloading])
    np.testing.assert_allclose(result.contact_area[unloading], expected, rtol=1e-12, atol=0)
    # at the peak separation the unloading sum is the loading branch's area (rel 1e-12)
    at_peak = _summed_unloading_area(result, [result.separation[result.peak]])[0]
    assert at_peak == pytest.approx(result.contact_area[result.peak], rel=1e-12, abs=0)


def test_statistical_unloading_area_falls_to_zero_with_the_load():
    # No reference force: the unloading branch runs down to 1e-6 of the peak load.
    result = statistical_load_unload(SUMMITS, **PAPER_RUN, steps=30)
    curve = result.curve()
    unloading = curve["branch"] == "unloading"
    area, force = curve["contact_area"][unloading], curve["force"][unloading]
    peak_area = result.contact_area[result.peak]
    assert np.all(np.isfinite(curve["contact_area"]))
    assert np.all(np.diff(area) < 0)  # falls monotonically with the load
    assert area[0] < peak_area
    assert force[-1] == pytest.approx(1e-6 * 1e-3, rel=1e-6, abs=0)
    assert area[-1] < 1e-4 * peak_area  # a millionth of the load leaves < 1e-4 of the area
    assert result.scalars()["peak_contact_area"] == peak_area


def test_statistical_unloading_keeps_more_area_than_loading_at_the_same_load():
    # Plastically flattened summits carry a given load on a larger real area (KKE 2006).
    result = statistical_load_unload(SUMMITS, **PAPER_RUN, reference_force=25e-6, steps=30)
    curve = result.curve()
    loading = curve["branch"] == "loading"
    f_load, a_load = curve["force"][loading], curve["contact_area"][loading]
    f_un, a_un = curve["force"][~loading], curve["contact_area"][~loading]
    assert np.all(a_un > np.interp(f_un, f_load, a_load))


def test_elastic_population_unloads_along_its_loading_area():
    # Hardness so large that no summit reaches omega_c: the unloading area retraces the loading area.
    run = dict(PAPER_RUN, hardness=50e9)
    result = statistical_load_unload(SUMMITS, **run, steps=30)
    curve = result.curve()
    loading = curve["branch"] == "loading"
    a_load, area_load = curve["approach"][loading], curve["contact_area"][loading]
    a_un, area_un = curve["approach"][~loading], curve["contact_area"][~loading]
    # both branches sample the same separations here (the unloading floor is the loading start, to the
    # root finder's 1e-12 sigma_s), so the interpolation adds nothing: rel 1e-9
    np.testing.assert_allclose(area_un, np.interp(a_un, a_load, area_load), rtol=1e-9, atol=0)
    # and for law="hertz" it is exactly the GW area pi R sum (z - d)_+ at every point (rel 1e-12)
    hertz = statistical_load_unload(SUMMITS, **run, law="hertz", steps=30)
    count = SUMMITS.summit_density * run["nominal_area"]
    gw = [
        count * math.pi * SUMMITS.summit_radius * (SUMMITS.weights @ np.maximum(SUMMITS.heights - d, 0.0))
        for d in hertz.separation
    ]
    np.testing.assert_allclose(hertz.contact_area, gw, rtol=1e-12, atol=0)
