import numpy as np
import pytest

from roughcontact.errors import InputError
from roughcontact.topography.process import (
    combine,
    common_spacing,
    crop,
    detrend,
    fill_undefined,
    remove_sphere,
    resample,
)
from roughcontact.topography.surface import Topography

SIZE = 10e-6


def grid(n=(48, 40), size=(SIZE, 0.8 * SIZE)):
    return Topography(np.zeros(n), size).meshgrid()


def periodic_waves(n, size=SIZE, periodic=True):
    """Band-limited periodic surface: three waves with wavelengths >= size / 4."""
    x, y = Topography(np.zeros((n, n)), size).meshgrid()
    heights = sum(
        a * np.cos(2 * np.pi * (k * x + m * y) / size + phase)
        for a, k, m, phase in [(1e-9, 1, 2, 0.3), (5e-10, 3, -1, 1.0), (3e-10, 2, 3, 2.0)]
    )
    return Topography(heights, size, periodic=periodic, info={"name": f"waves{n}"})


# --- detrend -------------------------------------------------------------------------------------


def test_detrend_removes_plane():
    x, y = grid()
    plane = 3e-7 + 2e-2 * x - 5e-2 * y
    result = detrend(Topography(plane, (SIZE, 0.8 * SIZE)), "plane")
    # exact in exact arithmetic; least squares on ~2000 points loses a few ulp of the 1e-6 m range
    assert np.abs(result.heights).max() <= 1e-12 * np.abs(plane).max()
    assert result.info["history"] == ("detrend(mode='plane')",)


def test_detrend_curvature_removes_quadratic_and_keeps_roughness_orthogonal():
    x, y = grid()
    quadratic = 1e-7 + 1e-2 * x + 2e-2 * y + 3e3 * x**2 - 1e3 * x * y + 2e3 * y**2
    result = detrend(Topography(quadratic, (SIZE, 0.8 * SIZE)), "curvature")
    assert np.abs(result.heights).max() <= 1e-12 * np.abs(quadratic).max()  # as above: rounding only


def test_detrend_profile_modes():
    x = np.arange(64) * 1e-7
    line, parabola = 1e-8 + 0.1 * x, 1e-8 + 0.1 * x + 1e4 * x**2
    assert np.abs(detrend(Topography(line, 64e-7), "plane").heights).max() <= 1e-12 * np.abs(line).max()
    assert np.abs(detrend(Topography(parabola, 64e-7), "curvature").heights).max() <= (
        1e-12 * np.abs(parabola).max()
    )
    mean = detrend(Topography(parabola, 64e-7), "mean").heights
    # a least-squares constant is the mean up to rounding: 1e-12 of the range
    assert mean == pytest.approx(parabola - parabola.mean(), abs=1e-12 * np.abs(parabola).max())


@pytest.mark.parametrize("mode", ["mean", "plane", "curvature"])
def test_detrend_is_idempotent(mode):
    rough = Topography(np.random.default_rng(1).normal(size=(32, 24)) * 1e-9 + 1e-9, SIZE)
    once = detrend(rough, mode)
    twice = detrend(once, mode)
    # the second fit only sees rounding noise of the first: 1e-12 of the rms
    assert np.abs(twice.heights - once.heights).max() <= 1e-12 * once.heights.std()


def test_detrend_periodicity():
    waves = periodic_waves(32)
    assert detrend(waves, "mean").periodic
    assert not detrend(waves, "plane").periodic
    with pytest.raises(InputError) as info:
        detrend(waves, "quadratic")
    assert info.value.field == "mode"


# --- remove_sphere -------------------------------------------------------------------------------


@pytest.mark.parametrize("fit", ["paraboloid", "sphere"])
def test_remove_sphere_recovers_radius(fit):
    radius = 5e-3
    x, y = Topography(np.zeros((64, 64)), 1.1e-3).meshgrid()
    r2 = (x - 0.4e-3) ** 2 + (y - 0.7e-3) ** 2
    exact = {"paraboloid": 1e-6 - r2 / (2 * radius), "sphere": 1e-6 + np.sqrt(radius**2 - r2) - radius}[fit]
    flattened, fitted = remove_sphere(Topography(exact, 1.1e-3), fit=fit)
    # noiseless data of the fitted model: recovered to rounding (measured ~1e-15), well below 1e-6
    assert fitted == pytest.approx(radius, rel=1e-6, abs=0)
    # the cap is ~60 um deep; what is left is rounding, below 1 pm
    assert np.abs(flattened.heights).max() < 1e-12
    assert not flattened.periodic


def test_remove_sphere_keeps_roughness_and_signs_concave():
    x, y = Topography(np.zeros((64, 64)), 1e-3).meshgrid()
    roughness = 1e-8 * np.sin(2 * np.pi * 8 * x / 1e-3) * np.sin(2 * np.pi * 8 * y / 1e-3)
    dimple = Topography((x**2 + y**2) / (2 * 2e-2) + roughness, 1e-3)
    flattened, fitted = remove_sphere(dimple, fit="paraboloid")
    assert fitted == pytest.approx(-2e-2, rel=1e-3, abs=0)  # roughness nearly orthogonal to the quadratic
    assert np.abs(flattened.heights - roughness).max() < 0.05 * np.abs(roughness).max()


def test_remove_sphere_refuses_flat_and_unknown_fit():
    flat = Topography(np.zeros((8, 8)), 1e-6)
    with pytest.raises(InputError) as info:
        remove_sphere(flat)
    assert info.value.field == "topography"
    with pytest.raises(InputError) as info:
        remove_sphere(flat, fit="ellipsoid")
    assert info.value.field == "fit"


# --- crop ----------------------------------------------------------------------------------------


def test_crop_half_open_pixels():
    heights = np.arange(100.0).reshape(10, 10) * 1e-9
    topography = Topography(heights, (1e-6, 2e-6), periodic=True)  # spacing 0.1 um x 0.2 um
    result = crop(topography, x=(0.3e-6, 0.7e-6), y=(0.2e-6, 1.0e-6))
    assert result.shape == (4, 4)  # x 0.3, 0.4, 0.5, 0.6 um; y 0.2 .. 0.8 um (stop excluded)
    assert result.size == pytest.approx((0.4e-6, 0.8e-6), rel=1e-12, abs=0)
    np.testing.assert_array_equal(result.heights, heights[3:7, 1:5])
    assert not result.periodic
    np.testing.assert_array_equal(crop(topography, y=(0.0, 1.0e-6)).heights, heights[:, :5])


def test_crop_errors():
    profile = Topography(np.zeros(10), 1e-6)
    assert crop(profile, x=(0.0, 0.5e-6)).shape == (5,)
    with pytest.raises(InputError) as info:
        crop(profile, y=(0.0, 1e-6))
    assert info.value.field == "y"
    with pytest.raises(InputError) as info:
        crop(profile, x=(0.5e-6, 0.55e-6))  # a single point
    assert info.value.field == "x"
    with pytest.raises(InputError):
        crop(profile, x=(0.6e-6, 0.2e-6))


# --- resample ------------------------------------------------------------------------------------


def test_resample_unchanged_spacing_is_exact():
    rough = Topography(np.random.default_rng(2).normal(size=(30, 20)) * 1e-9, (3e-6, 2e-6))
    same = resample(rough, (1e-7, 1e-7))
    np.testing.assert_array_equal(same.heights, rough.heights)
    assert same.size == rough.size


def test_resample_on_original_points_reproduces_heights():
    rough = Topography(np.random.default_rng(3).normal(size=(21, 21)) * 1e-9, 2.1e-6)
    fine = resample(rough, 0.5e-7)
    assert fine.shape == (41, 41)  # up to the last original point, no extrapolation
    # cubic B-spline interpolation passes through its nodes; rounding of the prefilter only
    np.testing.assert_allclose(fine.heights[::2, ::2], rough.heights, rtol=0, atol=1e-12 * 1e-9)


@pytest.mark.parametrize("factor", [0.5, 0.75, 1.6, 2.0])
def test_resample_preserves_rms_of_band_limited_surface(factor):
    waves = periodic_waves(64)
    result = resample(waves, factor * waves.spacing[0])
    assert result.periodic and result.size == pytest.approx(waves.size, rel=1e-12, abs=0)
    # >= 8 new pixels per wavelength: cubic-spline amplitude error measured <= 1e-4; 1e-3 is the margin
    assert result.heights.std() == pytest.approx(waves.heights.std(), rel=1e-3, abs=0)


def test_resample_spacing_errors():
    with pytest.raises(InputError) as info:
        resample(periodic_waves(16), (1e-7, 1e-7, 1e-7))
    assert info.value.field == "spacing"
    with pytest.raises(InputError):
        resample(periodic_waves(16), -1e-7)


# --- combine -------------------------------------------------------------------------------------


def test_combine_same_grid_sums_and_removes_mean():
    rng = np.random.default_rng(4)
    a = Topography(rng.normal(size=(16, 16)) * 1e-9 + 5e-9, SIZE, info={"name": "a"})
    b = Topography(rng.normal(size=(16, 16)) * 2e-9, SIZE, info={"name": "b"})
    result = combine(a, b)
    total = a.heights + b.heights
    np.testing.assert_array_equal(result.heights, total - total.mean())
    assert result.info["sources"] == ({"name": "a"}, {"name": "b"})
    np.testing.assert_array_equal(combine(b, a).heights, result.heights)


def test_combine_refuses_mismatched_grids():
    a = periodic_waves(16)
    with pytest.raises(InputError) as info:
        combine(a, periodic_waves(24))
    assert info.value.field == "b" and "shape" in info.value.problem and "resample=True" in info.value.fix
    with pytest.raises(InputError) as info:
        combine(a, periodic_waves(16, size=2 * SIZE))
    assert "size" in info.value.problem
    with pytest.raises(InputError) as info:
        combine(a, Topography(np.zeros(16), SIZE), resample=True)
    assert "1D" in info.value.problem


def test_combine_resample_periodic_equal_period():
    a, b = periodic_waves(32), periodic_waves(48)
    result = combine(a, b, resample=True)
    assert result.shape == (48, 48) and result.periodic  # finer spacing, same period
    # both are the same band-limited surface: the composite is twice it, to interpolation accuracy
    # (cubic splines at >= 8 pixels per wavelength: below 1e-2 of the amplitude)
    np.testing.assert_allclose(result.heights, 2 * b.heights, atol=1e-2 * np.abs(b.heights).max())
    np.testing.assert_array_equal(combine(b, a, resample=True).heights, result.heights)


def test_combine_resample_overlap_window():
    a = periodic_waves(40, periodic=False)  # 10 um, spacing 0.25 um
    b = crop(periodic_waves(50, periodic=False), x=(0, 6e-6))  # 6 um x 10 um, spacing 0.2 um
    assert common_spacing(a, b) == pytest.approx((0.2e-6, 0.2e-6), rel=1e-12, abs=0)
    result = combine(a, b, resample=True)
    # up to the last point of the smaller extent: x <= 5.8 um -> 30 points; y <= 9.75 um -> 49 points
    assert result.shape == (30, 49) and not result.periodic
    assert result.size == pytest.approx((6e-6, 9.8e-6), rel=1e-12, abs=0)
    np.testing.assert_array_equal(combine(b, a, resample=True).heights, result.heights)


# --- fill_undefined ------------------------------------------------------------------------------


def test_fill_undefined_reproduces_plane_in_hole():
    x, y = grid((30, 30), (3e-6, 3e-6))
    plane = 1e-8 + 2e-3 * x - 3e-3 * y
    holed = plane.copy()
    holed[10:15, 12:20] = np.nan
    holed[22, 5] = np.inf
    filled = fill_undefined(holed)
    # a linear function is discrete-harmonic: the sparse direct solve reproduces it to rounding
    np.testing.assert_allclose(filled, plane, rtol=0, atol=1e-9 * np.abs(plane).max())
    measured = np.isfinite(holed)
    np.testing.assert_array_equal(filled[measured], holed[measured])


def test_fill_undefined_profile_and_all_nan():
    profile = np.array([0.0, 1.0, np.nan, np.nan, 4.0, 5.0])
    np.testing.assert_allclose(fill_undefined(profile), np.arange(6.0), atol=1e-12)
    with pytest.raises(InputError) as info:
        fill_undefined(np.full((4, 4), np.nan), field="channel")
    assert info.value.field == "channel"


def test_scale_to_ra_sets_ra_exactly_and_refuses_a_flat_surface():
    from roughcontact.topography.generate import self_affine
    from roughcontact.topography.process import scale_to_ra
    from roughcontact.topography.statistics import ra, rq

    rough = self_affine((64, 64), 1e-6, hurst=0.8, rms_height=2e-9, seed=4)
    scaled = scale_to_ra(rough, 1.45e-9)
    assert ra(scaled) == pytest.approx(1.45e-9, rel=1e-12)
    assert rq(scaled) / ra(scaled) == pytest.approx(rq(rough) / ra(rough), rel=1e-12)
    flat = rough.with_heights(np.zeros(rough.shape), step="flat")
    with pytest.raises(InputError, match="Ra"):
        scale_to_ra(flat, 1e-9)
