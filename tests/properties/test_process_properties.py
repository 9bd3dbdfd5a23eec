import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from roughcontact.topography.process import combine, crop, detrend, fill_undefined, resample
from roughcontact.topography.surface import Topography

shapes = st.tuples(st.integers(4, 24), st.integers(4, 24))
sizes = st.tuples(st.floats(1e-7, 1e-3), st.floats(1e-7, 1e-3))
seeds = st.integers(0, 2**32 - 1)


def rough(shape, size, seed, periodic=False):
    heights = np.random.default_rng(seed).normal(size=shape) * 1e-9
    return Topography(heights, size, periodic=periodic)


@settings(max_examples=25, deadline=None)
@given(
    shapes,
    sizes,
    seeds,
    st.sampled_from(["mean", "plane", "curvature"]),
    st.tuples(*[st.floats(-1e-2, 1e-2)] * 6),
)
def test_detrend_removes_polynomial_and_is_idempotent(shape, size, seed, mode, coefficients):
    surface = rough(shape, size, seed)
    x, y = (c / s for c, s in zip(surface.meshgrid(), size, strict=True))
    c0, c1, c2, c3, c4, c5 = coefficients
    polynomial = {
        "mean": c0 * np.ones(shape),
        "plane": c0 + c1 * x + c2 * y,
        "curvature": c0 + c1 * x + c2 * y + c3 * x**2 + c4 * x * y + c5 * y**2,
    }[mode] * 1e-6
    once = detrend(surface.with_heights(surface.heights + polynomial), mode)
    reference = detrend(surface, mode)
    # adding a polynomial of the fitted family changes nothing but rounding: the background is
    # up to 1e-8 m, the roughness 1e-9 m; 1e-12 of the background is ulp level
    assert np.abs(once.heights - reference.heights).max() <= 1e-12 * max(np.abs(polynomial).max(), 1e-9)
    # idempotent: a second fit sees only that rounding; 1e-20 m is 1e-11 of the 1e-9 m roughness
    assert np.abs(detrend(once, mode).heights - once.heights).max() <= 1e-20


@settings(max_examples=20, deadline=None)
@given(shapes, sizes, seeds, seeds)
def test_combine_is_symmetric(shape, size, seed_a, seed_b):
    a, b = rough(shape, size, seed_a), rough(shape, size, seed_b)
    np.testing.assert_array_equal(combine(a, b).heights, combine(b, a).heights)


@settings(max_examples=15, deadline=None)
@given(shapes, shapes, sizes, seeds, seeds)
def test_combine_resampled_is_symmetric_and_inside_both(shape_a, shape_b, size, seed_a, seed_b):
    a, b = rough(shape_a, size, seed_a), rough(shape_b, (size[0] * 0.7, size[1]), seed_b)
    ab, ba = combine(a, b, resample=True), combine(b, a, resample=True)
    np.testing.assert_array_equal(ab.heights, ba.heights)
    for surface in (a, b):  # no extrapolation: the common grid ends within the last point of both
        for k in range(2):
            last_point = (surface.shape[k] - 1) * surface.spacing[k]
            assert (ab.shape[k] - 1) * ab.spacing[k] <= last_point * (1 + 1e-9)


@settings(max_examples=20, deadline=None)
@given(st.integers(16, 64), st.floats(0.5, 2.0), seeds)
def test_resample_preserves_rms_of_band_limited_periodic_surface(n, factor, seed):
    rng = np.random.default_rng(seed)
    surface = Topography(np.zeros((n, n)), 1e-6)
    x, y = surface.meshgrid()
    kmax = max(1, n // 16)  # wavelengths >= n / (kmax sqrt 2): 11 original, 5.6 resampled pixels
    wavenumbers = zip(rng.integers(1, kmax + 1, 3), rng.integers(-kmax, kmax + 1, 3), strict=True)
    heights = sum(
        rng.uniform(0.1, 1) * np.cos(2 * np.pi * (k * x + m * y) / 1e-6 + rng.uniform(0, 6.3))
        for k, m in wavenumbers
    )
    surface = surface.with_heights(heights * 1e-9, periodic=True)
    result = resample(surface, factor * surface.spacing[0])
    # measured worst case over 300 random draws: 6e-5; 1e-3 leaves an order of magnitude of margin
    assert result.heights.std() == pytest.approx(surface.heights.std(), rel=1e-3, abs=0)


@settings(max_examples=20, deadline=None)
@given(shapes, seeds, st.floats(0, 1), st.floats(0, 1))
def test_crop_keeps_the_half_open_window(shape, seed, start_fraction, width_fraction):
    surface = rough(shape, (1e-6, 1e-6), seed)
    spacing = surface.spacing[0]
    start = start_fraction * (shape[0] - 2) * spacing
    stop = start + 2 * spacing + width_fraction * (shape[0] * spacing - start - 2 * spacing)
    result = crop(surface, x=(start, stop))
    xs = surface.coordinates()[0]
    kept = (xs >= start - 1e-9 * spacing) & (xs < stop - 1e-9 * spacing)
    np.testing.assert_array_equal(result.heights, surface.heights[kept])


@settings(max_examples=20, deadline=None)
@given(shapes, seeds, st.floats(0.05, 0.6))
def test_fill_undefined_keeps_measured_points_and_adds_no_extrema(shape, seed, fraction):
    rng = np.random.default_rng(seed)
    heights = rng.normal(size=shape) * 1e-9
    holed = heights.copy()
    holed[rng.random(shape) < fraction] = np.nan
    keep = rng.integers(heights.size)
    holed.flat[keep] = heights.flat[keep]  # at least one measured point
    filled = fill_undefined(holed)
    measured = np.isfinite(holed)
    np.testing.assert_array_equal(filled[measured], holed[measured])
    # discrete maximum principle of harmonic interpolation; 1e-12 of the range for the direct solve
    low, high = holed[measured].min(), holed[measured].max()
    slack = 1e-12 * max(high - low, 1e-9)
    assert filled.min() >= low - slack and filled.max() <= high + slack
