"""Unit tests of roughcontact.topography.statistics: definitions, edge cases, errors, invariants."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from roughcontact.errors import InputError
from roughcontact.topography import Topography, generate, statistics


def approx(expected, rel=1e-12, abs=0.0):
    """pytest.approx without its default 1e-12 absolute tolerance, which would swallow SI values like m0."""
    return pytest.approx(expected, rel=rel, abs=abs)


@pytest.fixture(scope="module")
def rough():
    return generate.self_affine(
        (64, 48), (2e-6, 1.5e-6), hurst=0.8, rms_height=4e-9, seed=2, short_cutoff=1e-7
    )


# --- amplitude parameters ------------------------------------------------------------------------


def test_amplitude_parameters_of_a_two_level_profile():
    heights = np.array([1.0, 1.0, 1.0, -3.0]) * 1e-9  # mean 0
    t = Topography(heights, 4e-9)
    assert statistics.ra(t) == approx(1.5e-9, abs=0)  # (1+1+1+3)/4
    assert statistics.rq(t) == approx(math.sqrt(3) * 1e-9, abs=0)  # sqrt((1+1+1+9)/4)
    assert statistics.rsk(t) == approx((3 - 27) / 4 / 3**1.5, abs=0)
    assert statistics.rku(t) == approx((3 + 81) / 4 / 9, abs=0)
    assert statistics.rz(t) == approx(4e-9, abs=0)


def test_amplitude_parameters_are_taken_about_the_mean(rough):
    shifted = rough.with_heights(np.asarray(rough.heights) + 1e-6)
    for function in (statistics.ra, statistics.rq, statistics.rz):
        # the 1e-6 offset is 250 Rq: subtracting it again costs ~1e-13 relative round-off
        assert function(shifted) == approx(function(rough), rel=1e-9, abs=0)


def test_flat_surface_has_no_skewness_and_summary_leaves_it_out():
    flat = Topography(np.full((8, 8), 2e-9), 1e-6, periodic=True)
    with pytest.raises(InputError) as error:
        statistics.rsk(flat)
    assert error.value.field == "topography"
    result = statistics.summary(flat)
    assert not {"Ssk", "Sku", "Rsk", "Rku", "bandwidth"} & set(result)
    assert result["Sq"] == 0 and result["Rq"] == 0 and result["Sdr"] == 0 and result["m2"] == 0


# --- derivatives ---------------------------------------------------------------------------------


def test_unknown_derivative_names_the_field(rough):
    with pytest.raises(InputError) as error:
        statistics.spectral_moments(rough, derivative="backward")
    assert error.value.field == "derivative"


def test_linear_ramp_has_exact_slope_on_non_periodic_grid():
    x = np.arange(10) * 1e-7
    ramp = Topography(np.outer(0.02 * x, np.ones(6)), (1e-6, 6e-7))
    for derivative in statistics.DERIVATIVES:
        moments = statistics.spectral_moments(ramp, derivative=derivative)
        # both stencils are exact for a linear function; edges are excluded so no wrap jump
        assert moments.m2 == approx(0.02**2 / 2, rel=1e-10, abs=0)
        assert moments.m4 == approx(0.0, abs=1e-10)
        assert statistics.rms_slope(ramp, derivative=derivative) == approx(0.02, rel=1e-10, abs=0)


def test_forward_is_default_and_curvature_is_centred(rough):
    assert statistics.rms_slope(rough) == statistics.rms_slope(rough, derivative="forward")
    assert statistics.rms_slope(rough, derivative="central") < statistics.rms_slope(rough)
    central = statistics.spectral_moments(rough, derivative="central")
    assert statistics.spectral_moments(rough).m4 == central.m4


def test_profile_moments_use_only_x(rough):
    profile = Topography(rough.heights[:, 0], rough.size[0], periodic=True)
    moments = statistics.spectral_moments(profile)
    assert statistics.rms_slope(profile) == approx(math.sqrt(moments.m2), abs=0)  # no 1/2 for profiles
    assert statistics.rms_curvature(profile) == approx(math.sqrt(moments.m4), abs=0)


def test_too_small_non_periodic_grid_raises():
    tiny = Topography(np.array([[0.0, 1.0], [1.0, 0.0]]) * 1e-9, 1e-8)
    with pytest.raises(InputError) as error:
        statistics.spectral_moments(tiny)
    assert error.value.field == "topography"


# --- McCool --------------------------------------------------------------------------------------


@pytest.mark.parametrize("field", ["m0", "m2", "m4"])
@pytest.mark.parametrize("value", [0.0, -1.0, math.nan, math.inf])
def test_mccool_rejects_non_positive_moments(field, value):
    moments = {"m0": 1e-15, "m2": 1e-3, "m4": 1e10} | {field: value}
    with pytest.raises(InputError) as error:
        statistics.mccool_parameters(**moments)
    assert error.value.field == field


def test_mccool_rejects_small_bandwidth():
    with pytest.raises(InputError) as error:
        statistics.mccool_parameters(m0=1e-16, m2=1e-3, m4=0.5e10)  # alpha = 0.5
    assert error.value.field == "m2" and "0.8968" in error.value.problem


def test_mccool_is_keyword_only():
    with pytest.raises(TypeError):
        statistics.mccool_parameters(1e-15, 1e-3, 1e10)


def test_mccool_of_topography_matches_moments(rough):
    moments = statistics.spectral_moments(rough)
    direct = statistics.mccool_parameters(m0=moments.m0, m2=moments.m2, m4=moments.m4)
    assert statistics.mccool_parameters_of(rough) == direct


def test_mccool_of_flat_surface_names_topography():
    with pytest.raises(InputError) as error:
        statistics.mccool_parameters_of(Topography(np.zeros((8, 8)), 1e-6, periodic=True))
    assert error.value.field == "topography"


# --- spectra, ACF, summits, summary --------------------------------------------------------------


def test_psd_windows(rough):
    with pytest.raises(InputError) as error:
        statistics.psd_1d(rough, window="blackman")
    assert error.value.field == "window"
    q, plain = statistics.psd_1d(rough, window=None)
    _, default = statistics.psd_1d(rough)
    np.testing.assert_array_equal(plain, default)  # periodic: default is no window
    open_surface = rough.with_heights(rough.heights, periodic=False)
    _, hann = statistics.psd_1d(open_surface)
    assert not np.allclose(hann, plain, rtol=1e-3, atol=0)  # non-periodic: Hann window by default


def test_psd_2d_needs_a_map_and_nbins_is_validated(rough):
    with pytest.raises(InputError):
        statistics.psd_2d(Topography(np.arange(8.0) * 1e-9, 1e-6))
    with pytest.raises(InputError) as error:
        statistics.psd_radial(rough, nbins=0)
    assert error.value.field == "nbins"
    q, c = statistics.psd_radial(rough, nbins=10)
    assert len(q) == 10 and np.all(np.diff(q) > 0) and np.all(c >= 0)


def test_autocorrelation_of_a_sinusoid():
    t = generate.sinusoid((64, 4), (4e-6, 1e-6), amplitude=2e-9, wavelength=1e-6)
    lag, acf = statistics.autocorrelation(t)
    # periodic circular ACF of A cos(kx) is (A^2/2) cos(k r) exactly on whole periods
    np.testing.assert_allclose(acf, 2e-18 * np.cos(2 * math.pi * lag / 1e-6), rtol=0, atol=1e-30)
    assert acf[0] == approx(statistics.rq(t) ** 2, abs=0)


def test_autocorrelation_non_periodic_is_unbiased():
    t = Topography(np.array([1.0, -1.0] * 8) * 1e-9, 1.6e-8)
    lag, acf = statistics.autocorrelation(t)
    expected = 1e-18 * (-1.0) ** np.arange(len(lag))
    np.testing.assert_allclose(acf, expected, rtol=1e-12, atol=0)  # pairs n-k normalisation exact here


def test_summits_of_a_bisinusoid():
    t = generate.bisinusoid((64, 64), 4e-6, amplitude=1e-8, wavelength=1e-6)
    peaks = statistics.summits(t)
    # maxima of cos x cos y: both cosines +1 or both -1: 2 per wavelength cell, 4 x 4 cells
    assert peaks.count == 32
    np.testing.assert_allclose(peaks.heights, 1e-8, rtol=1e-12)
    assert peaks.positions.shape == (32, 2)
    edge = t.with_heights(t.heights, periodic=False)
    assert statistics.summits(edge).count < 32  # summits on the first row / column are dropped


def test_summits_of_a_profile():
    t = Topography(np.array([0.0, 2.0, 1.0, 3.0, 3.0, 0.0, 1.0]) * 1e-9, 7e-9)
    peaks = statistics.summits(t)
    np.testing.assert_array_equal(peaks.indices[:, 0], [1])  # plateau (3, 3) and edge give none


def test_summary_keys_of_a_map_are_every_entry_in_order(rough):
    result = statistics.summary(rough)
    assert list(result) == list(statistics.SUMMARY)
    assert all(isinstance(v, float) and math.isfinite(v) for v in result.values())


def test_summary_of_a_profile_has_profile_names_only():
    profile = Topography(np.random.default_rng(3).standard_normal(64) * 1e-9, 1e-6, periodic=True)
    result = statistics.summary(profile)
    assert not [name for name in result if name.startswith("S")]
    assert {"Ra", "Rq", "Rsk", "Rku", "Rt", "Rdq"} <= set(result)
    assert result["Rq"] == approx(statistics.rq(profile), rel=1e-14)
    assert result["Rt"] == approx(statistics.rz(profile), rel=1e-14)
    assert result["Rdq"] == approx(statistics.rms_slope(profile), rel=1e-14)
    with pytest.raises(InputError, match="areal"):
        statistics.sdr(profile)


# --- areal and profile parameters ----------------------------------------------------------------


@pytest.mark.parametrize("periodic", [False, True])
def test_profile_parameters_see_each_profile_about_its_own_mean(periodic):
    """z = f(x) + g(y): the profiles along x lose g(y) entirely, the areal parameters keep it."""
    x = np.arange(32) / 32
    f = 1e-9 * np.sin(2 * np.pi * 3 * x)
    g = 5e-9 * np.cos(2 * np.pi * x[:16] * 2)
    both = Topography(f[:, None] + g[None, :], (1e-6, 0.5e-6), periodic=periodic)
    alone = Topography(np.tile(f[:, None], (1, 16)), (1e-6, 0.5e-6), periodic=periodic)
    profile, expected = statistics.profile_parameters(both), statistics.profile_parameters(alone)
    assert profile.keys() == expected.keys()
    for name in profile:  # Rsk of a sine is zero: compared to round-off in absolute terms
        assert profile[name] == approx(expected[name], rel=1e-12, abs=1e-14 if name == "Rsk" else 0), name
    assert profile["Rq"] == approx(1e-9 / np.sqrt(2), rel=1e-12)  # whole periods of f
    assert profile["Rt"] == approx(np.ptp(f), rel=1e-12)
    assert statistics.rq(both) == approx(np.sqrt(f.var() + g.var()), rel=1e-12)  # Sq sees g


def test_profile_rq_is_surface_topographys_rq(shared_topographies):
    """Cross-check with SurfaceTopography's Rq (profiles along x, pooled) and Sq on a real scan."""
    import SurfaceTopography

    from roughcontact.topography.io import read_topography
    from roughcontact.topography.process import level

    theirs = SurfaceTopography.read_topography(str(shared_topographies / "top-1.top")).detrend("height")
    ours = level(read_topography(shared_topographies / "top-1.top"), "plane")
    theirs_parameters = SurfaceTopography.Uniform.ScalarParameters  # their heights in nm
    assert statistics.profile_parameters(ours)["Rq"] == approx(theirs_parameters.Rq(theirs) * 1e-9, rel=1e-12)
    assert statistics.rq(ours) == approx(theirs_parameters.Sq(theirs) * 1e-9, rel=1e-12)


def test_sdr_of_a_tilted_plane_is_the_secant_less_one():
    """A plane of slopes (a, b) has true area sqrt(1 + a^2 + b^2) per unit projected area."""
    a, b = 0.3, -0.2
    x, y = np.meshgrid(np.arange(16) * 1e-8, np.arange(12) * 1e-8, indexing="ij")
    plane = Topography(a * x + b * y, (16e-8, 12e-8), periodic=False)
    assert statistics.sdr(plane) == approx(np.sqrt(1 + a**2 + b**2) - 1, rel=1e-12)


def test_sdr_grows_as_half_the_mean_square_gradient(rough):
    """Small slopes: sqrt(1 + s^2) - 1 = s^2/2 - s^4/8 ..., so Sdr ~ Sdq^2 / 2 to a relative Sdq^2."""
    gentle = rough.with_heights(np.asarray(rough.heights) * 1e-3 / statistics.rms_slope(rough))
    assert statistics.sdr(gentle) == approx(statistics.rms_slope(gentle) ** 2 / 2, rel=1e-5)


# --- properties ----------------------------------------------------------------------------------

heights_2d = st.integers(0, 2**32 - 1).map(lambda seed: np.random.default_rng(seed).standard_normal((12, 10)))


@settings(max_examples=30, deadline=None)
@given(heights=heights_2d, scale=st.floats(1e-3, 1e3), offset=st.floats(-1e2, 1e2))
def test_skewness_kurtosis_invariant_under_scale_and_offset(heights, scale, offset):
    base = Topography(heights * 1e-9, 1e-6)
    moved = Topography((heights * scale + offset) * 1e-9, 1e-6)
    # offsets up to 1e5 Rq cost ~1e5 * 1e-16 relative round-off in z about the mean
    assert statistics.rsk(moved) == approx(statistics.rsk(base), rel=1e-8, abs=1e-8)
    assert statistics.rku(moved) == approx(statistics.rku(base), rel=1e-8, abs=0)


@settings(max_examples=30, deadline=None)
@given(heights=heights_2d, offset=st.floats(-1e3, 1e3))
def test_moments_invariant_under_constant_offset(heights, offset):
    base = Topography(heights * 1e-9, 1e-6, periodic=True)
    moved = Topography((heights + offset) * 1e-9, 1e-6, periodic=True)
    a, b = statistics.spectral_moments(base), statistics.spectral_moments(moved)
    # offset up to 1e3 Rq: cancellation leaves ~1e3 * 1e-16 relative error per difference
    assert b.m0 == approx(a.m0, rel=1e-9, abs=0)
    assert b.m2 == approx(a.m2, rel=1e-9, abs=0)
    assert b.m4 == approx(a.m4, rel=1e-9, abs=0)
