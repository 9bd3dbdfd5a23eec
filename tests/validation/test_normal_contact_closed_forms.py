"""Normal contact solver against closed forms, with errors that shrink under mesh refinement.

Tolerances: the discretisation error of a pixel-wise constant pressure is O(h) at the contact
edge (a square-root profile) and smaller for integral quantities; each test states its bound
at its coarsest grid and asserts that the error decreases when the grid is refined.
"""

import math

import numpy as np
import pytest

from roughcontact.analytic import (
    flat_punch_stiffness,
    hertz,
    westergaard_contact_half_width,
    westergaard_pressure,
)
from roughcontact.contact import solve_normal
from roughcontact.elasticity import ElasticLayer
from roughcontact.elasticity.kernels import layer_winkler_compliance
from roughcontact.materials import Material
from roughcontact.topography import Topography
from roughcontact.topography.generate import bisinusoid, flat_punch, sinusoid, sphere

E_STAR = 1e9
RADIUS = 1e-3
FORCE = 1e-3
HERTZ = hertz(radius=RADIUS, contact_modulus=E_STAR, force=FORCE)


def _hertz_errors(n: int) -> dict[str, float]:
    a = HERTZ.contact_radius
    t = sphere((n, n), (4 * a, 4 * a), radius=RADIUS, kind="paraboloid")
    result = solve_normal(t, E_STAR, force=FORCE, tolerance=1e-10)
    x, y = t.meshgrid()
    r = np.hypot(x - 2 * a, y - 2 * a)
    return {
        "peak": abs(result.pressure.max() / HERTZ.peak_pressure - 1),
        "approach": abs(result.approach / HERTZ.approach - 1),
        "area": abs(result.contact_area / (math.pi * a**2) - 1),
        "profile": float(np.sqrt(np.mean((result.pressure - HERTZ.pressure(r))[r < a] ** 2)))
        / HERTZ.peak_pressure,
        "force": abs(result.force / FORCE - 1),
    }


def test_hertz_free_boundary_converges_under_refinement():
    coarse, fine = _hertz_errors(64), _hertz_errors(128)
    # 64^2 over 4a: 16 pixels per contact radius.
    assert coarse["peak"] < 1e-3 and coarse["approach"] < 2e-4 and coarse["area"] < 0.02
    assert coarse["profile"] < 0.01  # rms over the Hertz contact circle
    assert fine["force"] < 1e-12  # load control is exact
    for key in ("peak", "approach", "area", "profile"):
        assert fine[key] < coarse[key], key


def test_hertz_displacement_control_gives_hertz_force():
    a = HERTZ.contact_radius
    t = sphere((128, 128), (4 * a, 4 * a), radius=RADIUS, kind="paraboloid")
    result = solve_normal(t, E_STAR, approach=HERTZ.approach, tolerance=1e-10)
    assert result.force == pytest.approx(FORCE, rel=2e-4, abs=0)
    assert result.approach == HERTZ.approach


@pytest.mark.parametrize("fraction", [0.1, 0.4, 0.8])
def test_westergaard_pressure_and_contact_width(fraction):
    wavelength, amplitude = 1e-4, 1e-6
    full = math.pi * E_STAR * amplitude / wavelength
    mean = fraction * full
    errors = []
    for n in (256, 1024):
        t = sinusoid((n,), (wavelength,), wavelength=wavelength, amplitude=amplitude)
        result = solve_normal(t, E_STAR, mean_pressure=mean, tolerance=1e-12)
        (x,) = t.coordinates()
        exact = westergaard_pressure(
            x, mean, amplitude=amplitude, wavelength=wavelength, contact_modulus=E_STAR
        )
        half = westergaard_contact_half_width(
            mean, amplitude=amplitude, wavelength=wavelength, contact_modulus=E_STAR
        )
        width_error = abs(result.contact_area / 2 - half) / wavelength
        profile_error = np.max(np.abs(result.pressure - exact)) / full
        errors.append((width_error, profile_error))
        assert result.mean_pressure == pytest.approx(mean, rel=1e-12, abs=0)
        assert width_error <= 1.0 / n  # one pixel
    assert errors[0][1] < 0.015 and errors[1][1] < errors[0][1]  # worst pixel, at the contact edge


def test_westergaard_full_contact_is_exact():
    wavelength, amplitude = 1e-4, 1e-6
    full = math.pi * E_STAR * amplitude / wavelength
    t = sinusoid((64,), (wavelength,), wavelength=wavelength, amplitude=amplitude)
    result = solve_normal(t, E_STAR, mean_pressure=1.5 * full, tolerance=1e-12)
    (x,) = t.coordinates()
    exact = westergaard_pressure(
        x, 1.5 * full, amplitude=amplitude, wavelength=wavelength, contact_modulus=E_STAR
    )
    np.testing.assert_allclose(result.pressure, exact, rtol=1e-10, atol=0)


def test_bisinusoid_full_contact_pressure():
    """Johnson, Greenwood and Higginson (1985): full contact needs p* = sqrt(2) pi E* A / lambda."""
    wavelength, amplitude = 1e-4, 1e-6
    full = math.sqrt(2) * math.pi * E_STAR * amplitude / wavelength
    t = bisinusoid((32, 32), (wavelength, wavelength), wavelength=wavelength, amplitude=amplitude)
    result = solve_normal(t, E_STAR, mean_pressure=1.01 * full, tolerance=1e-12)
    x, y = t.meshgrid()
    exact = 1.01 * full + full * np.cos(2 * np.pi * x / wavelength) * np.cos(2 * np.pi * y / wavelength)
    assert result.contact_fraction == 1.0
    np.testing.assert_allclose(result.pressure, exact, rtol=1e-9, atol=0)
    below = solve_normal(t, E_STAR, mean_pressure=0.99 * full, tolerance=1e-10)
    assert below.contact_fraction < 1.0


def test_boussinesq_flat_punch_stiffness_converges():
    radius = 1e-5
    errors = []
    for n in (64, 128, 256):
        t = flat_punch((n, n), (4 * radius, 4 * radius), radius=radius, depth=1e-6)
        result = solve_normal(t, E_STAR, approach=1e-9, tolerance=1e-10)
        stiffness = result.force / 1e-9
        # The discrete face has the area of the pixels inside r <= a: compare with its equivalent radius.
        face = np.count_nonzero(t.heights == 0) * t.pixel_area
        exact = flat_punch_stiffness(radius=math.sqrt(face / math.pi), contact_modulus=E_STAR)
        errors.append(abs(stiffness / exact - 1))
    assert errors[0] < 0.02  # 16 pixels per radius
    assert errors[2] < errors[0]


def test_thick_layer_tends_to_half_space():
    wavelength, amplitude = 1e-4, 1e-7
    t = bisinusoid((32, 32), (wavelength, wavelength), wavelength=wavelength, amplitude=amplitude)
    material = Material(1e9, 0.3)
    half_space = solve_normal(t, material, mean_pressure=1e5, tolerance=1e-12)
    layer = ElasticLayer(thickness=10 * wavelength, material=material, base="bonded")
    thick = solve_normal(t, layer=layer, mean_pressure=1e5, tolerance=1e-12)
    np.testing.assert_allclose(thick.pressure, half_space.pressure, rtol=1e-9, atol=1e-9 * 1e5)


@pytest.mark.parametrize("base", ["bonded", "frictionless"])
def test_thin_layer_on_rigid_base_tends_to_winkler(base):
    """Full contact of a thin layer: p - mean(p) = (h - mean(h)) / c with c the Winkler compliance."""
    wavelength, amplitude, thickness = 1e-4, 1e-9, 1e-7  # q t = 0.0063
    material = Material(1e9, 0.3)
    t = bisinusoid((32, 32), (wavelength, wavelength), wavelength=wavelength, amplitude=amplitude)
    layer = ElasticLayer(thickness=thickness, material=material, base=base)
    compliance = layer_winkler_compliance(thickness, 1e9, 0.3, base=base)
    mean = 2 * amplitude / compliance  # full contact
    result = solve_normal(t, layer=layer, mean_pressure=mean, tolerance=1e-12)
    expected = mean + (t.heights - t.heights.mean()) / compliance
    np.testing.assert_allclose(result.pressure, expected, rtol=1e-3, atol=0)  # O((q t)^2) correction
    # Against a rigid base the approach is absolute: mean displacement = c * mean pressure.
    assert result.displacement.mean() == pytest.approx(compliance * mean, rel=1e-9, abs=0)


def test_unit_invariance_nm_and_m():
    rng = np.random.default_rng(3)
    heights = rng.normal(size=(32, 32)) * 1e-9
    in_m = Topography(heights, (1e-6, 1e-6))
    in_nm = Topography(heights * 1e9, (1e3, 1e3))  # same numbers, lengths in nm
    a = solve_normal(in_m, E_STAR, mean_pressure=1e7, tolerance=1e-10)
    b = solve_normal(in_nm, E_STAR, mean_pressure=1e7, tolerance=1e-10)
    np.testing.assert_allclose(a.pressure, b.pressure, rtol=1e-9, atol=1e-9 * 1e7)
    assert a.iterations == b.iterations
    assert b.approach == pytest.approx(a.approach * 1e9, rel=1e-9, abs=0)


@pytest.mark.parametrize("boundary", ["periodic", "free"])
def test_preconditioning_changes_iterations_not_the_answer(boundary):
    from roughcontact.topography.generate import self_affine

    # The gain grows with the grid: 2x at 128^2, 3-4x at 256^2 (measured 154 -> 41 periodic,
    # 134 -> 42 free), 4-5x at 512^2.
    surface = self_affine((256, 256), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=7)
    common = dict(mean_pressure=5e6, tolerance=1e-10, boundary=boundary)
    plain = solve_normal(surface, E_STAR, precondition=False, **common)
    fast = solve_normal(surface, E_STAR, **common)
    np.testing.assert_allclose(fast.pressure, plain.pressure, rtol=0, atol=1e-6 * plain.pressure.max())
    assert fast.iterations < plain.iterations / 3


@pytest.mark.parametrize("control", ["mean_pressure", "approach"])
def test_polak_ribiere_directions_reach_the_published_iterations_answer(control):
    """The preconditioned engine keeps its Polak-Ribiere+ conjugacy across changes of the contact set.

    Its answer must be Polonsky and Keer's (plain, Fletcher-Reeves reset whenever points enter)
    to 1e-8 of the peak pressure at tolerance 1e-10, under load and displacement control, cold
    and warm-started from the solution of a 20 times larger load (a contact set far too large
    that must shrink); measured 1e-9 to 3e-9 at 256^2 to 4096^2.
    """
    from roughcontact.topography.generate import self_affine

    surface = self_affine((256, 256), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=11)
    load = solve_normal(surface, E_STAR, mean_pressure=5e6, tolerance=1e-10)
    common = {"tolerance": 1e-10, control: 5e6 if control == "mean_pressure" else load.approach}
    plain = solve_normal(surface, E_STAR, precondition=False, **common)
    heavy = solve_normal(surface, E_STAR, mean_pressure=1e8, tolerance=1e-8)
    for initial in (None, heavy):
        fast = solve_normal(surface, E_STAR, initial=initial, **common)
        np.testing.assert_allclose(fast.pressure, plain.pressure, rtol=0, atol=1e-8 * plain.pressure.max())
        assert fast.iterations < plain.iterations / 2
