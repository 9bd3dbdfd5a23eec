"""Unit tests of roughcontact.topography.generate: shapes, targets, determinism, validation."""

import math

import numpy as np
import pytest

from roughcontact.errors import InputError
from roughcontact.topography import generate, statistics
from roughcontact.topography.process import remove_sphere


def approx(expected, rel=1e-12, abs=0.0):
    """pytest.approx without its default 1e-12 absolute tolerance, which would swallow SI values."""
    return pytest.approx(expected, rel=rel, abs=abs)


# --- self-affine and Gaussian random --------------------------------------------------------------


@pytest.mark.parametrize("shape", [(256,), (64, 48), 33])
def test_self_affine_hits_rms_height_exactly(shape):
    t = generate.self_affine(shape, 1e-5, hurst=0.7, rms_height=2e-8, seed=1)
    assert t.periodic and t.heights.dtype == float
    assert statistics.rq(t) == approx(2e-8, rel=1e-12, abs=0)  # one rescale: round-off only
    assert abs(t.heights.mean()) < 1e-12 * 2e-8  # q = 0 removed


def test_self_affine_hits_rms_slope_exactly():
    t = generate.self_affine((64, 64), 1e-5, hurst=0.5, rms_slope=0.1, seed=1, short_cutoff=1e-6)
    assert statistics.rms_slope(t) == approx(0.1, rel=1e-12, abs=0)


def test_self_affine_is_deterministic_and_seed_dependent():
    kwargs = {"hurst": 0.8, "rms_height": 1e-9, "short_cutoff": 1e-7, "long_cutoff": 1e-6, "rolloff": 0.5}
    a = generate.self_affine((32, 32), 2e-6, seed=5, **kwargs)
    b = generate.self_affine((32, 32), 2e-6, seed=5, **kwargs)
    c = generate.self_affine((32, 32), 2e-6, seed=6, **kwargs)
    np.testing.assert_array_equal(a.heights, b.heights)
    assert not np.allclose(a.heights, c.heights, rtol=0.1, atol=0)


def test_self_affine_band_limits():
    size, n = 1e-5, 128
    t = generate.self_affine(
        (n, n), size, hurst=0.8, rms_height=1e-8, seed=0, short_cutoff=size / 16, long_cutoff=size / 4
    )
    qx, qy, psd = statistics.psd_2d(t)
    q = np.hypot(qx[:, None], qy[None, :])
    # no power outside [q_L, q_s] without roll-off: only FFT round-off (relative 1e-25 in power)
    outside = (q < 2 * math.pi / (size / 4) * (1 - 1e-9)) | (q > 2 * math.pi / (size / 16) * (1 + 1e-9))
    assert psd[outside].max() < 1e-20 * psd.max()
    plateau = generate.self_affine(
        (n, n),
        size,
        hurst=0.8,
        rms_height=1e-8,
        seed=0,
        short_cutoff=size / 16,
        long_cutoff=size / 4,
        rolloff=1.0,
    )
    _, _, psd_plateau = statistics.psd_2d(plateau)
    assert psd_plateau[(q > 0) & (q < 2 * math.pi / (size / 4))].min() > 0


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"hurst": 0.0, "rms_height": 1e-9}, "hurst"),
        ({"hurst": 1.2, "rms_height": 1e-9}, "hurst"),
        ({"hurst": 0.8}, "rms_height"),
        ({"hurst": 0.8, "rms_height": 1e-9, "rms_slope": 0.1}, "rms_height"),
        ({"hurst": 0.8, "rms_height": -1e-9}, "rms_height"),
        ({"hurst": 0.8, "rms_slope": 0.0}, "rms_slope"),
        ({"hurst": 0.8, "rms_height": 1e-9, "short_cutoff": 1e-6, "long_cutoff": 1e-7}, "long_cutoff"),
        ({"hurst": 0.8, "rms_height": 1e-9, "short_cutoff": -1e-6}, "short_cutoff"),
        ({"hurst": 0.8, "rms_height": 1e-9, "rolloff": -0.5}, "rolloff"),
        ({"hurst": 0.8, "rms_height": 1e-9, "long_cutoff": 1e-9}, "short_cutoff"),  # band above Nyquist
    ],
)
def test_self_affine_validation(kwargs, field):
    with pytest.raises(InputError) as error:
        generate.self_affine((16, 16), 1e-6, seed=0, **kwargs)
    assert error.value.field == field


@pytest.mark.parametrize(
    ("shape", "size", "field"),
    [
        ((1, 8), 1e-6, "shape"),
        ((8, 8, 8), 1e-6, "shape"),
        ((8, 8), -1e-6, "size"),
        ((8, 8), (1e-6, 0), "size"),
        ((8.0, 8), 1e-6, "shape"),
        ((8, 8), (1, 2, 3), "size"),
    ],
)
def test_grid_validation(shape, size, field):
    with pytest.raises(InputError) as error:
        generate.gaussian_random(shape, size, rms_height=1e-9, correlation_length=1e-7)
    assert error.value.field == field


def test_gaussian_random_rms_and_correlation_length():
    xi, size = 2e-7, 1e-5
    acfs = []
    for seed in range(4):
        t = generate.gaussian_random((256, 256), size, rms_height=3e-9, correlation_length=xi, seed=seed)
        assert statistics.rq(t) == approx(3e-9, rel=1e-12, abs=0)
        lag, acf = statistics.autocorrelation(t)
        acfs.append(acf / acf[0])
    acf = np.mean(acfs, axis=0)
    # ACF at r = xi should be 1/e; xi/L = 0.02 leaves ~2500 correlation areas per map, i.e. ~2 %
    # statistical scatter per map, 1 % on 4 maps: 0.03 absolute on 0.368 is ~3 sigma
    at_xi = np.interp(xi, lag, acf)
    assert at_xi == approx(math.exp(-1), abs=0.03, rel=0)


# --- deterministic shapes ------------------------------------------------------------------------


def test_sphere_and_paraboloid():
    radius = 1e-5
    cap = generate.sphere((65, 64), (4e-6, 4e-6), radius=radius)
    parabola = generate.sphere((65, 64), (4e-6, 4e-6), radius=radius, kind="paraboloid")
    apex = (32, 32)
    assert cap.heights[apex] == 0 and parabola.heights[apex] == 0
    assert cap.heights.max() == 0 and not cap.periodic
    x, y = (c - c[32] for c in (cap.coordinates()[0], cap.coordinates()[1]))
    r2 = x[:, None] ** 2 + y[None, :] ** 2
    np.testing.assert_allclose(cap.heights, np.sqrt(radius**2 - r2) - radius, rtol=1e-12, atol=1e-22)
    np.testing.assert_allclose(parabola.heights, -r2 / (2 * radius), rtol=1e-12, atol=0)
    # the cap lies below the paraboloid by ~r^4 / (8 R^3) (next term of the expansion), < 1 % of it here
    assert np.all(cap.heights <= parabola.heights)


def test_sphere_validation():
    with pytest.raises(InputError) as error:
        generate.sphere((16, 16), 3e-6, radius=1e-6)
    assert error.value.field == "radius"
    with pytest.raises(InputError) as error:
        generate.sphere((16, 16), 3e-6, radius=1e-6, kind="cone")
    assert error.value.field == "kind"
    with pytest.raises(InputError) as error:
        generate.sphere((16, 16), 3e-6, radius=1e-5, centre=(1e-6,))
    assert error.value.field == "centre"
    # a grid that fits: apex off centre, periodic minimum image keeps every point within R
    wrapped = generate.sphere((16, 16), 3e-6, radius=2.2e-6, centre=(0.0, 0.0), periodic=True)
    assert wrapped.periodic and wrapped.heights[0, 0] == 0


def test_sinusoid_and_bisinusoid_forms():
    t = generate.sinusoid((40, 3), (2e-6, 1e-6), amplitude=1e-9, wavelength=0.5e-6)
    x = t.coordinates()[0]
    # atol 1e-22 (1e-13 of A): round-off of x = i * size / n against i * spacing in the phase
    np.testing.assert_allclose(t.heights[:, 1], 1e-9 * np.cos(2 * math.pi * x / 0.5e-6), rtol=0, atol=1e-22)
    assert t.periodic
    assert not generate.sinusoid((40,), 2.1e-6, amplitude=1e-9, wavelength=0.5e-6).periodic
    b = generate.bisinusoid((40, 20), (2e-6, 1e-6), amplitude=1e-9, wavelength=(0.5e-6, 1e-6))
    x, y = b.coordinates()
    expected = 1e-9 * np.outer(np.cos(2 * math.pi * x / 0.5e-6), np.cos(2 * math.pi * y / 1e-6))
    np.testing.assert_allclose(b.heights, expected, rtol=0, atol=1e-22)
    assert b.periodic
    with pytest.raises(InputError) as error:
        generate.sinusoid((8,), 1e-6, amplitude=1e-9, wavelength=1e-7, axis=1)
    assert error.value.field == "axis"
    with pytest.raises(InputError) as error:
        generate.bisinusoid((8, 8), 1e-6, amplitude=1e-9, wavelength=(1e-7, 1e-7, 1e-7))
    assert error.value.field == "wavelength"


def test_flat_punch():
    t = generate.flat_punch((41, 41), 4e-6, radius=1e-6, depth=5e-7)
    assert set(np.unique(t.heights)) == {0.0, -5e-7}
    face = np.count_nonzero(t.heights == 0) * t.pixel_area
    # pixel count approximates pi a^2 within ~2 h / a = 20 % worst case; observed 0.9 %: 5 %
    assert face == approx(math.pi * 1e-12, rel=0.05, abs=0)
    with pytest.raises(InputError) as error:
        generate.flat_punch((41, 41), 4e-6, radius=1e-6, depth=0)
    assert error.value.field == "depth"


def test_raised_island():
    size, island, thickness = 60e-6, 25e-6, 6.3e-6
    t = generate.raised_island(
        (120, 120), size, island_size=island, thickness=thickness, rms_height=40e-9, seed=3
    )
    on_island = t.heights > thickness / 2
    # island pixels: |x - 30 um| <= 12.5 um at 0.5 um pixels -> 51 points per side
    assert on_island.sum() == 51 * 51
    assert not t.periodic
    top = t.heights[on_island]
    assert top.mean() == approx(thickness, rel=1e-12, abs=0)
    assert np.sqrt(np.mean((top - thickness) ** 2)) == approx(40e-9, rel=1e-9, abs=0)
    assert np.all(t.heights[~on_island] == 0)
    smooth = generate.raised_island((120,), size, island_size=island, thickness=thickness)
    assert set(np.unique(smooth.heights)) == {0.0, thickness}
    with pytest.raises(InputError) as error:
        generate.raised_island((120, 120), size, island_size=70e-6, thickness=thickness)
    assert error.value.field == "island_size"


def test_sphere_with_roughness_flattens_back_to_its_roughness():
    radius, rms = 5e-6, 2e-9  # AFM-tip-like (paper 000 uses 20 nm pixels); 128^2 keeps the test fast
    t = generate.sphere_with_roughness(
        (128, 128), 2e-6, radius=radius, rms_height=rms, seed=1, short_cutoff=1e-7
    )
    flattened, fitted = remove_sphere(t, fit="paraboloid")
    # the fit also absorbs the roughness' own longest waves: seeds 0-3 give R within 0.8 % and the
    # flattened Rq 4-9 % low, hence 2 % on R and 15 % on Rq
    assert fitted == approx(radius, rel=0.02, abs=0)
    assert statistics.rq(flattened) == approx(rms, rel=0.15, abs=0)


# --- modes: the grid's noise (unchanged) or one draw per wavevector (the same on every grid) ------


def test_grid_mode_keeps_the_surfaces_of_earlier_releases():
    # values drawn by the generator before modes existed; any change of the grid draw moves them
    t = generate.self_affine((64, 48), 1e-5, hurst=0.7, rms_height=2e-8, seed=1)
    assert t.info["modes"] == "grid"
    assert [t.heights[0, 0], t.heights[10, 20], t.heights[63, 47]] == approx(
        [-7.2922217230948864e-09, -2.0561702117615895e-08, 6.770681256666297e-11], rel=1e-12
    )
    g = generate.gaussian_random((32, 32), 1e-5, rms_height=3e-9, correlation_length=2e-7, seed=2)
    assert [g.heights[0, 0], g.heights[5, 7]] == approx(
        [6.589485880247349e-10, 2.2627282702311553e-09], rel=1e-12
    )
    explicit = generate.self_affine((64, 48), 1e-5, hurst=0.7, rms_height=2e-8, seed=1, modes="grid")
    np.testing.assert_array_equal(explicit.heights, t.heights)


def _coefficients(t):
    """Fourier coefficients c_k of heights = sum_k c_k exp(i q_k.r), keyed by integer wavevector."""
    c = np.fft.fftn(t.heights) / t.heights.size  # numpy's forward FFT is unnormalised: divide by n
    ks = np.meshgrid(*(np.rint(np.fft.fftfreq(n, 1 / n)).astype(int) for n in t.shape), indexing="ij")
    return {tuple(int(k[i]) for k in ks): c[i] for i in np.ndindex(c.shape)}


@pytest.mark.parametrize(
    ("coarse", "fine", "size"),
    [
        ((64, 64), (256, 256), 1e-5),  # the band (|k| <= 48) beyond the coarse grid's Nyquist (32)
        ((40, 45), (160, 135), (1e-5, 7e-6)),  # rectangular, an odd side (no Nyquist mode)
        ((50,), (200,), 1e-5),  # a profile
    ],
)
def test_wavevector_mode_is_one_surface_on_every_grid(coarse, fine, size):
    kwargs = {"hurst": 0.8, "rms_height": 1e-8, "short_cutoff": 1e-5 / 48, "seed": 7, "modes": "wavevector"}
    a = generate.self_affine(coarse, size, **kwargs)
    b = generate.self_affine(fine, size, **kwargs)
    assert a.info["modes"] == "wavevector" and a.periodic
    ca, cb = _coefficients(a), _coefficients(b)
    scale = max(abs(c) for c in cb.values())
    # modes the coarse grid holds whole (its Nyquist modes are zero by construction)
    shared = [k for k in ca if all(2 * abs(ki) < n for ki, n in zip(k, coarse, strict=True))]
    assert len(shared) > 0.9 * a.heights.size
    # measured 1.8e-16 of the largest coefficient (FFT round-off)
    assert max(abs(ca[k] - cb[k]) for k in shared) < 1e-13 * scale
    assert max(abs(ca[k]) for k in ca if k not in shared) < 1e-13 * scale  # Nyquist modes left out
    # the coarse surface is the fine one low-passed to the coarse grid's modes, sampled: measured 4.5e-16
    kept = np.ones(fine, dtype=bool)
    for axis, (n_coarse, n_fine) in enumerate(zip(coarse, fine, strict=True)):
        k = np.abs(np.rint(np.fft.fftfreq(n_fine, 1 / n_fine)))
        kept &= np.expand_dims(2 * k < n_coarse, tuple(a for a in range(len(fine)) if a != axis))
    low_passed = np.fft.ifftn(np.fft.fftn(b.heights) * kept).real
    sampled = low_passed[tuple(slice(None, None, nf // nc) for nc, nf in zip(coarse, fine, strict=True))]
    np.testing.assert_allclose(sampled, a.heights, rtol=0, atol=1e-13 * np.abs(a.heights).max())


def test_wavevector_mode_normalises_the_psd_on_the_lattice():
    size = 1e-5
    band = {"short_cutoff": size / 32, "long_cutoff": size / 4, "rolloff": 1.0, "modes": "wavevector"}
    # rms height: 40 seeds, one realisation's Rq^2 scatters 10 % about the target (measured mean 1.0006)
    rq2 = [
        statistics.rq(generate.self_affine((256, 256), size, hurst=0.8, rms_height=1e-9, seed=s, **band)) ** 2
        for s in range(40)
    ]
    assert np.mean(rq2) == approx(1e-18, rel=0.05)

    def mean_square_gradient(t):  # continuum (spectral) derivative, as the normalisation
        c = np.fft.fftn(t.heights) / t.heights.size
        q = [2 * math.pi * np.fft.fftfreq(n, s / n) for n, s in zip(t.shape, t.size, strict=True)]
        return float(np.sum((q[0][:, None] ** 2 + q[1][None, :] ** 2) * np.abs(c) ** 2))

    # rms gradient: scatter 3 % per realisation, mean of 40 measured 0.992 of the target
    slope2 = [
        mean_square_gradient(generate.self_affine((256, 256), size, hurst=0.8, rms_slope=0.1, seed=s, **band))
        for s in range(40)
    ]
    assert np.mean(slope2) == approx(0.01, rel=0.03)
    # Gaussian ACF: the lattice sum runs to q xi = 12.9, so 128^2 and 256^2 draw the same field
    # (xi = 2.5 pixels of 128^2); scatter 2.6 % per realisation, mean of 20 measured 0.985
    for n in (128, 256):
        rq2 = [
            statistics.rq(
                generate.gaussian_random(
                    (n, n), size, rms_height=1e-9, correlation_length=size / 50, seed=s, modes="wavevector"
                )
            )
            ** 2
            for s in range(20)
        ]
        assert np.mean(rq2) == approx(1e-18, rel=0.03)


def test_wavevector_mode_is_deterministic_and_seed_dependent():
    kwargs = {"hurst": 0.8, "rms_height": 1e-9, "short_cutoff": 1e-7, "modes": "wavevector"}
    a = generate.self_affine((32, 32), 2e-6, seed=5, **kwargs)
    np.testing.assert_array_equal(a.heights, generate.self_affine((32, 32), 2e-6, seed=5, **kwargs).heights)
    other = generate.self_affine((32, 32), 2e-6, seed=6, **kwargs)
    assert not np.allclose(a.heights, other.heights, rtol=0.1, atol=0)
    assert abs(a.heights.mean()) < 1e-12 * 1e-9


@pytest.mark.parametrize(
    ("make", "field"),
    [
        (
            lambda: generate.self_affine((16, 16), 1e-6, hurst=0.8, rms_height=1e-9, modes="wavevector"),
            "short_cutoff",
        ),
        (lambda: generate.self_affine((16, 16), 1e-6, hurst=0.8, rms_height=1e-9, modes="wave"), "modes"),
        (
            lambda: generate.self_affine(
                (16, 16), 1e-6, hurst=0.8, rms_height=1e-9, short_cutoff=1e-7, seed=-1, modes="wavevector"
            ),
            "seed",
        ),
        (
            lambda: generate.sphere_with_roughness(
                (16, 16), 1e-6, radius=1e-5, rms_height=1e-9, modes="wavevector"
            ),
            "short_cutoff",
        ),
        (
            lambda: generate.raised_island(
                (16, 16), 1e-6, island_size=5e-7, thickness=1e-7, rms_height=1e-9, modes="wavevector"
            ),
            "short_cutoff",
        ),
        (
            lambda: generate.gaussian_random(
                (16, 16), 1e-6, rms_height=1e-9, correlation_length=1e-7, modes="x"
            ),
            "modes",
        ),
    ],
)
def test_wavevector_mode_validation(make, field):
    with pytest.raises(InputError) as error:
        make()
    assert error.value.field == field


def test_check_arguments_knows_modes():
    generate.check_arguments(
        "self_affine",
        (16, 16),
        1e-6,
        {"hurst": 0.8, "rms_height": 1e-9, "short_cutoff": 1e-7, "modes": "wavevector"},
    )
    cases = [
        ("self_affine", {"hurst": 0.8, "rms_height": 1e-9, "modes": "wavevector"}, "short_cutoff"),
        ("gaussian_random", {"rms_height": 1e-9, "correlation_length": 1e-7, "modes": "x"}, "modes"),
        (
            "sphere_with_roughness",
            {"radius": 1e-5, "rms_height": 1e-9, "modes": "wavevector"},
            "short_cutoff",
        ),
        ("raised_island", {"island_size": 5e-7, "thickness": 1e-7, "modes": "wavevector"}, "short_cutoff"),
    ]
    for generator, options, field in cases:
        with pytest.raises(InputError) as error:
            generate.check_arguments(generator, (16, 16), 1e-6, options)
        assert error.value.field == field


def test_wavevector_mode_through_the_composite_generators():
    island = generate.raised_island(
        (120, 120),
        60e-6,
        island_size=25e-6,
        thickness=6.3e-6,
        rms_height=40e-9,
        seed=3,
        short_cutoff=2e-6,
        modes="wavevector",
    )
    top = island.heights[island.heights > 3e-6]
    assert np.sqrt(np.mean((top - top.mean()) ** 2)) == approx(40e-9, rel=1e-9)  # exact on the island
    assert island.info["modes"] == "wavevector"
    ball = generate.sphere_with_roughness(
        (64, 64), 2e-6, radius=5e-6, rms_height=2e-9, seed=1, short_cutoff=1e-7, modes="wavevector"
    )
    roughness = generate.self_affine(
        (64, 64), 2e-6, hurst=0.8, rms_height=2e-9, seed=1, short_cutoff=1e-7, modes="wavevector"
    )
    body = generate.sphere((64, 64), 2e-6, radius=5e-6, kind="paraboloid")
    np.testing.assert_allclose(ball.heights - body.heights, roughness.heights, rtol=0, atol=1e-12 * 2e-9)
    assert ball.info["modes"] == "wavevector"


# --- matched_moments -------------------------------------------------------------------------------

PAPER002 = {"m0": 0.00213279e-12, "m2": 0.00230023, "m4": 0.0171036e12}  # papers.paper002.MOMENTS


def test_matched_moments_records_its_band():
    from roughcontact.papers.paper002 import MOMENTS

    assert MOMENTS == PAPER002
    t = generate.matched_moments((448, 448), 25e-6, **MOMENTS, seed=0)
    info = t.info
    assert info["generator"] == "matched_moments" and info["modes"] == "wavevector" and t.periodic
    assert (info["m0"], info["m2"], info["m4"], info["hurst"], info["rolloff"]) == (
        *MOMENTS.values(),
        0.8,
        1.0,
    )
    assert info["short_cutoff"] == approx(2 * math.pi / info["q_short"]) and info["q_long"] < info["q_short"]
    # expected moments of the lattice: m0 and m2 exact, m4 within one shell of modes (measured 3.4e-4)
    assert info["expected_m4"] == approx(MOMENTS["m4"], rel=2e-3)
    assert info["short_cutoff"] / (25e-6 / 448) >= generate.MIN_PIXELS_PER_SHORT_WAVELENGTH
    # the grid only samples the band: 512^2 holds the same field (shared modes to round-off)
    fine = generate.matched_moments((512, 512), 25e-6, **MOMENTS, seed=0)
    assert fine.info["q_short"] == info["q_short"]
    ca, cb = _coefficients(t), _coefficients(fine)
    assert max(abs(ca[k] - cb[k]) for k in ca if max(map(abs, k)) < 224) < 1e-13 * max(map(abs, cb.values()))


def test_min_pixels_per_short_wavelength_bounds_the_second_difference():
    # mean square curvature seen by the centred second difference: (sin(x)/x)^4, x = pi / pixels
    def seen(pixels):
        return (math.sin(math.pi / pixels) / (math.pi / pixels)) ** 4

    assert (
        seen(generate.MIN_PIXELS_PER_SHORT_WAVELENGTH)
        >= 0.98
        > seen(generate.MIN_PIXELS_PER_SHORT_WAVELENGTH - 1)
    )


@pytest.mark.parametrize(
    ("shape", "size", "changes", "field"),
    [
        ((512, 512), 25e-6, {"hurst": 0.1}, "hurst"),  # roll-off below the lowest wavevector of 25 um
        ((512, 512), 25e-6, {"m4": PAPER002["m4"] / 4}, "m4"),  # alpha = 1.72 < 2: no plateau + power law
        ((512, 512), 25e-6, {"m4": PAPER002["m4"] / 5}, "m4"),  # alpha = 1.38 < 1.5: no isotropic surface
        ((256, 256), 25e-6, {}, "shape"),  # 10.9 pixels per shortest wavelength
        ((512,), 25e-6, {}, "shape"),  # a profile
        ((512, 512), 5e-6, {}, "hurst"),  # the roll-off below 2 pi / size: a larger hurst or size
        ((512, 512), 8e-6, {"m4": 0.3 * PAPER002["m4"]}, "size"),  # shells 5 % apart in bandwidth
        ((512, 512), 25e-6, {"m2": -1.0}, "m2"),
    ],
)
def test_matched_moments_refuses_what_it_cannot_match(shape, size, changes, field):
    arguments = {**PAPER002, **changes}
    with pytest.raises(InputError) as error:
        generate.matched_moments(shape, size, **arguments, seed=0)
    assert error.value.field == field
    with pytest.raises(InputError) as error:
        generate.check_arguments("matched_moments", shape, size, {**arguments, "seed": 0})
    assert error.value.field == field
    if field == "hurst":
        assert "larger hurst" in error.value.fix


def test_matched_psd_reproduces_a_scans_psd_over_an_ensemble():
    """Each ring of the template's radial PSD is met on average; the mean square height too."""
    from roughcontact.topography.generate import matched_psd

    template = generate.self_affine((128, 128), 2e-6, hurst=0.8, rms_height=2e-9, seed=1)
    q, target = statistics.psd_radial(template, ring_ratio=1.1)
    draws = [matched_psd(template, seed=seed) for seed in range(100)]
    mean = np.mean([statistics.psd_radial(draw, ring_ratio=1.1)[1] for draw in draws], axis=0)
    # measured: median ring ratio 1.003, rings 0.85-1.13 (the few modes of a ring scatter); mean Rq^2 -0.6 %
    assert np.median(mean / target) == pytest.approx(1.0, abs=0.02)
    assert np.all(np.abs(mean / target - 1) < 0.25)
    rq2 = np.mean([statistics.rq(draw) ** 2 for draw in draws])
    assert rq2 == pytest.approx(statistics.rq(template) ** 2, rel=0.05)
    assert draws[0].info["generator"] == "matched_psd" and draws[0].periodic


def test_matched_psd_on_another_grid_and_refusals():
    from roughcontact.topography.generate import matched_psd

    template = generate.self_affine((64, 64), 1e-6, hurst=0.8, rms_height=1e-9, seed=2)
    larger = matched_psd(template, shape=128, size=2e-6, seed=1)
    assert larger.shape == (128, 128) and larger.size == pytest.approx((2e-6, 2e-6))
    profile = generate.self_affine(64, 1e-6, hurst=0.8, rms_height=1e-9, seed=2)
    with pytest.raises(InputError) as error:
        matched_psd(profile)
    assert error.value.field == "template"
    with pytest.raises(InputError) as error:
        matched_psd(template, ring_ratio=1.0)
    assert error.value.field == "ring_ratio"
