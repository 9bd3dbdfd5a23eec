"""The normal contact engine on the GPU against the CPU engine and closed forms (skipped without a GPU).

Tolerances: in double precision the GPU runs the CPU's iteration with other round-off (cuFFT
against FFTW or pocketfft, sums combined by atomic additions in a varying order), so the
converged fields agree far below the solver tolerance: pressures within 1e-10 of the peak at
tolerance 1e-10 (the CPU's two FFT backends differ by 4e-15 on the 256^2 self-affine case). The
fused passes are compared one by one with the numba passes on fresh random fields whose outputs
are poisoned first (every element must be written): within 1e-12 relative for the sums, exact
for the masks and counts, and within a few units in the last place for the element-wise fields
(the CUDA compiler fuses multiply-adds, which round once instead of twice). Single precision is
held to its own measured bound.
"""

import numpy as np
import pytest

from roughcontact._backend import RealFFT2
from roughcontact._device import resolve_device
from roughcontact.analytic import hertz
from roughcontact.contact import solve_normal
from roughcontact.elasticity import ElasticLayer
from roughcontact.errors import InputError
from roughcontact.materials import Material
from roughcontact.topography import Topography
from roughcontact.topography.generate import self_affine, sphere


def _gpu_or_skip():
    try:
        resolve_device("gpu")
    except InputError as error:
        pytest.skip(f"no GPU here: {error.problem}")
    import cupy

    return cupy


@pytest.fixture(scope="module")
def cp():
    return _gpu_or_skip()


E_STAR = 1e9
PEAK = 1e-10  # largest pressure difference GPU - CPU, relative to the peak (double precision)


def _both(topography, *args, **kwargs):
    cpu = solve_normal(topography, *args, device="cpu", **kwargs)
    gpu = solve_normal(topography, *args, device="gpu", **kwargs)
    return cpu, gpu


def _agree(cpu, gpu, bound=PEAK):
    difference = np.abs(gpu.pressure - cpu.pressure).max() / cpu.pressure.max()
    assert difference <= bound, difference
    assert gpu.residual <= gpu.tolerance
    assert gpu.approach == pytest.approx(cpu.approach, rel=1e-9, abs=1e-9 * abs(cpu.approach) + 1e-30)
    return difference


def test_periodic_rough_surface_load_control_matches_cpu(cp):
    # 512^2: the coarse-to-fine cascade runs its 256^2 and 128^2 levels on the GPU too.
    surface = self_affine((512, 512), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=512)
    cpu, gpu = _both(surface, E_STAR, mean_pressure=5e6, tolerance=1e-10)
    _agree(cpu, gpu)
    assert gpu.force == pytest.approx(cpu.force, rel=1e-12)
    assert abs(gpu.iterations - cpu.iterations) <= 3


def test_periodic_rough_surface_displacement_control_matches_cpu(cp):
    surface = self_affine((256, 256), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=7)
    approach = 0.5 * float(np.std(surface.heights))
    cpu, gpu = _both(surface, E_STAR, approach=approach, tolerance=1e-10)
    _agree(cpu, gpu)


def test_plain_polonsky_keer_matches_cpu(cp):
    surface = self_affine((128, 128), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=3)
    # Plain Polonsky-Keer converges slowly near the end (116 iterations to 1e-10, 2549 to 1e-12 here):
    # at 1e-10 the two devices' round-off leaves 4.6e-10 of the peak between them (measured, H200).
    cpu, gpu = _both(surface, E_STAR, mean_pressure=5e6, tolerance=1e-12, precondition=False)
    _agree(cpu, gpu)


def test_free_hertz_on_the_gpu_is_hertz(cp):
    contact = hertz(radius=1e-3, contact_modulus=E_STAR, force=1e-3)
    a = contact.contact_radius
    ball = sphere((256, 256), (4 * a, 4 * a), radius=1e-3, kind="paraboloid")
    cpu, gpu = _both(ball, E_STAR, force=1e-3, tolerance=1e-10)
    _agree(cpu, gpu)
    assert gpu.boundary == "free"
    # the CPU's own bounds at this resolution (tests/validation/test_normal_contact_closed_forms.py)
    assert abs(gpu.pressure.max() / contact.peak_pressure - 1) < 1e-3
    assert abs(gpu.approach / contact.approach - 1) < 2e-4


def test_rough_ball_capped_at_a_force_matches_cpu(cp):
    # free boundary, box around the contact, hardness: the approach found by Brent's method
    roughness = self_affine((256, 256), (40e-6, 40e-6), hurst=0.8, rms_slope=0.05, seed=11)
    ball = sphere((256, 256), (40e-6, 40e-6), radius=1e-3, kind="paraboloid")
    surface = Topography(ball.heights + roughness.heights, ball.size)
    cpu, gpu = _both(surface, E_STAR, force=1e-3, hardness=5e7, tolerance=1e-10)
    _agree(cpu, gpu, bound=1e-9)
    assert gpu.pressure.max() <= 5e7 * (1 + 1e-12)
    assert np.count_nonzero(gpu.pressure >= 5e7 * (1 - 1e-9)) > 10  # the cap is reached


def test_layer_and_line_contact_match_cpu(cp):
    film = Material(youngs_modulus=2e9, poissons_ratio=0.3)
    surface = self_affine((128, 128), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=5)
    layer = ElasticLayer(2e-6, film, base="bonded")
    cpu, gpu = _both(surface, None, layer=layer, mean_pressure=5e6, tolerance=1e-10)
    _agree(cpu, gpu)
    profile = self_affine((1024,), (1e-4,), hurst=0.8, rms_slope=0.1, seed=9)
    cpu, gpu = _both(profile, E_STAR, mean_pressure=5e6, tolerance=1e-10)
    _agree(cpu, gpu)


def test_single_precision_is_within_its_bound(cp):
    surface = self_affine((512, 512), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=512)
    double = solve_normal(surface, E_STAR, mean_pressure=5e6, tolerance=1e-10, device="cpu")
    single = solve_normal(
        surface, E_STAR, mean_pressure=5e6, tolerance=1e-5, device="gpu", precision="single"
    )
    difference = np.abs(single.pressure - double.pressure).max() / double.pressure.max()
    assert difference < 1e-3, difference
    assert single.force == pytest.approx(double.force, rel=1e-6)


def test_device_transform_matches_cpu_transform(cp):
    from roughcontact._gpu import DeviceFFT2

    rng = np.random.default_rng()
    for shape, padded in (((96, 64), (96, 64)), ((48, 40), (96, 80))):
        field = rng.standard_normal(shape)
        q = np.hypot(np.fft.fftfreq(padded[0])[:, None], np.fft.rfftfreq(padded[1])[None, :])
        kernel = 1.0 / (0.01 + q) * (1.0 + rng.random())  # real and even in q, as the operators' are
        cpu = RealFFT2(padded, input_shape=shape, backend="scipy")
        gpu = DeviceFFT2(padded, input_shape=shape)
        with gpu.staged() as stage:
            stage[...] = cp.asarray(field)
            got = gpu.apply_staged(gpu.prepared(kernel)).get()
            power = gpu.power_staged(gpu.quadratic_form_weights(kernel))
        expected = cpu.convolve(field, kernel)
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12 * np.abs(expected).max())
        assert power == pytest.approx(float(np.sum(field * expected)), rel=1e-12)


def _fields(rng, shape, cap):
    """Random engine fields: pressures with zeros and points at the cap, gaps of both signs."""
    p = rng.random(shape) * cap * 1.2
    p[rng.random(shape) < 0.3] = 0.0
    p = np.minimum(p, cap)
    return {
        "p": p,
        "u": rng.standard_normal(shape),
        "h0": rng.random(shape),
        "t": rng.standard_normal(shape),
        "z": rng.standard_normal(shape).astype(np.float32),
        "g_previous": rng.standard_normal(shape).astype(np.float32),
    }


@pytest.mark.parametrize("admit", [True, False])
def test_fused_passes_match_numba(cp, admit):
    from roughcontact.contact import _cg_kernels as cpu
    from roughcontact.contact import _cg_kernels_gpu as gpu

    rng = np.random.default_rng()
    shape, cap, scale, delta = (67, 45), 1.0, 1.1, 0.4  # odd sides: no accidental alignment
    f = _fields(rng, shape, cap)
    d = {name: cp.asarray(value) for name, value in f.items()}

    def close(a, b):
        np.testing.assert_allclose(
            np.asarray(a, dtype=float), np.asarray(b, dtype=float), rtol=1e-12, atol=1e-12
        )

    # a strided displacement, as a free boundary's padded transform leaves it
    u_wide = cp.full((shape[0], 2 * shape[1]), np.nan)
    u_wide[:, : shape[1]] = d["u"]
    close(
        gpu.displacement_statistics(d["p"], u_wide[:, : shape[1]], d["h0"], cap, scale),
        cpu.displacement_statistics(f["p"], f["u"], f["h0"], cap, scale),
    )
    g_c, stage_c, free_c = (
        np.full(shape, np.nan),
        np.full(shape, np.nan, np.float32),
        np.full(shape, 7, np.uint8),
    )
    g_d, free_d = cp.full(shape, np.nan), cp.full(shape, 7, dtype=np.uint8)
    stage_wide = cp.full((shape[0], 2 * shape[1]), np.nan, dtype=np.float32)
    stage_d = stage_wide[:, : shape[1]]
    sums_c = cpu.gap_and_residual(
        f["p"], f["u"], f["h0"], delta, cap, scale, f["t"], g_c, stage_c, free_c, admit
    )
    sums_d = gpu.gap_and_residual(
        d["p"], d["u"], d["h0"], delta, cap, scale, d["t"], g_d, stage_d, free_d, admit
    )
    close(sums_d, sums_c)
    np.testing.assert_array_equal(free_d.get(), free_c)
    np.testing.assert_allclose(g_d.get(), g_c, rtol=0, atol=1e-14)
    np.testing.assert_allclose(stage_d.get(), stage_c, rtol=1e-6, atol=1e-6)
    assert np.all(np.isnan(stage_wide[:, shape[1] :].get()))  # nothing written beside the view

    previous_c, previous_d = f["g_previous"].copy(), d["g_previous"].copy()
    sums_d = gpu.restricted_sums(d["z"], g_d, free_d, previous_d)
    sums_c = cpu.restricted_sums(f["z"], g_c, free_c, previous_c)
    close(np.take(sums_d, [0, 1, 3]), np.take(sums_c, [0, 1, 3]))
    # sum g_previous z: numba keeps float() of a float32 as float32, so the CPU rounds each product to
    # float32 (it only steers the Polak-Ribiere coefficient); the GPU multiplies in float64. Measured on
    # an H200: 2.5e-8 relative on a sum of about 1500 products.
    scale = float(np.sum(np.abs(f["g_previous"] * f["z"])[free_c == 1]))
    assert abs(sums_d[2] - sums_c[2]) <= 1e-6 * scale
    np.testing.assert_allclose(previous_d.get(), previous_c, rtol=1e-6, atol=1e-6)

    t_c, t_d = f["t"].copy(), d["t"].copy()
    t_stage_c, t_stage_d = np.full(shape, np.nan, np.float32), cp.full(shape, np.nan, dtype=np.float32)
    close(
        gpu.update_direction(t_d, d["z"], 0.1, 0.7, free_d, g_d, t_stage_d),
        cpu.update_direction(t_c, f["z"], 0.1, 0.7, free_c, g_c, t_stage_c),
    )
    np.testing.assert_allclose(t_d.get(), t_c, rtol=0, atol=1e-14)
    np.testing.assert_allclose(t_stage_d.get(), t_stage_c, rtol=1e-6, atol=1e-6)
    # plain Polonsky-Keer builds the direction from the gap itself (float64), not from M g (float32)
    t_plain_c, t_plain_d = f["t"].copy(), d["t"].copy()
    close(
        gpu.update_direction(t_plain_d, g_d, 0.1, 0.7, free_d, g_d, t_stage_d),
        cpu.update_direction(t_plain_c, g_c, 0.1, 0.7, free_c, g_c, t_stage_c),
    )
    np.testing.assert_allclose(t_plain_d.get(), t_plain_c, rtol=0, atol=1e-14)

    p_c, p_d = f["p"].copy(), d["p"].copy()
    p_stage_c, p_stage_d = np.full(shape, np.nan), cp.full(shape, np.nan)
    entered_c = cpu.update_pressure(p_c, t_c, g_c, 0.3, 2.0, cap, admit, scale, p_stage_c)
    entered_d = gpu.update_pressure(p_d, t_d, g_d, 0.3, 2.0, cap, admit, scale, p_stage_d)
    assert entered_d[0] == entered_c[0]
    close(entered_d[1], entered_c[1])
    np.testing.assert_allclose(p_d.get(), p_c, rtol=0, atol=1e-14)
    np.testing.assert_allclose(p_stage_d.get(), p_stage_c, rtol=0, atol=1e-14)
    assert not np.isnan(p_stage_d.get()).any() and not np.isnan(t_stage_d.get()).any()
