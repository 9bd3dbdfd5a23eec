"""Subsurface stress by FFT against Hertz (free patch) and a periodic sinusoidal pressure."""

import numpy as np
import pytest

from roughcontact.analytic import hertz
from roughcontact.elasticity.stress import subsurface_stress

NU = 0.3


def _hertz_axis_errors(n: int, padding: int) -> tuple[float, float, float, float]:
    h = hertz(radius=1e-3, contact_modulus=1e9, force=1e-3)
    a, p0 = h.contact_radius, h.peak_pressure
    length = 4 * a
    x = np.arange(n) * length / n
    xx, yy = np.meshgrid(x, x, indexing="ij")
    pressure = h.pressure(np.hypot(xx - length / 2, yy - length / 2))
    z = np.linspace(0.05, 2.0, 40) * a
    stress = subsurface_stress(
        pressure, (length, length), z, poissons_ratio=NU, boundary="free", padding=padding
    )
    centre = n // 2
    sz, sr = stress.component("zz")[:, centre, centre], stress.component("xx")[:, centre, centre]
    zeta = z / a
    exact_z = -1 / (1 + zeta**2)  # Johnson (1985) eq. 3.45
    exact_r = -(1 + NU) * (1 - zeta * np.arctan(1 / zeta)) + 0.5 / (1 + zeta**2)
    vm_max, (_, _, depth) = stress.max_von_mises()
    return (
        float(np.max(np.abs(sz / p0 - exact_z))),
        float(np.max(np.abs(sr / p0 - exact_r))),
        vm_max / p0,
        depth / a,
    )


def test_hertz_axis_stresses_and_von_mises_maximum():
    coarse = _hertz_axis_errors(64, 4)
    fine = _hertz_axis_errors(128, 8)
    assert coarse[0] < 2e-3 and coarse[1] < 1e-2  # in units of p0
    assert fine[0] < 2e-4 and fine[1] < 2.5e-3
    assert fine[1] < coarse[1]
    # Largest von Mises stress 0.62 p0 on the axis at z = 0.48 a for nu = 0.3 (Johnson fig. 3.9).
    assert fine[2] == pytest.approx(0.62, abs=0.01)
    assert fine[3] == pytest.approx(0.48, abs=0.05)


def test_periodic_sinusoidal_pressure_is_exact():
    n, length, amplitude, mean = 64, 1e-4, 1e6, 2e6
    k = 2 * np.pi / length
    x = np.arange(n) * length / n
    pressure = np.repeat((mean + amplitude * np.cos(k * x))[:, None], 8, axis=1)
    z = np.array([0.0, 0.1, 0.5, 2.0]) * length
    stress = subsurface_stress(pressure, (length, length / 8), z, poissons_ratio=NU)
    for i, depth in enumerate(z):
        decay = np.exp(-k * depth)
        wave = amplitude * np.cos(k * x)
        np.testing.assert_allclose(
            stress.component("zz")[i, :, 0], -mean - (1 + k * depth) * decay * wave, rtol=0, atol=1e-9 * mean
        )
        lateral = -NU / (1 - NU) * mean - (1 - k * depth) * decay * wave
        np.testing.assert_allclose(stress.component("xx")[i, :, 0], lateral, rtol=0, atol=1e-9 * mean)
        shear = -amplitude * k * depth * decay * np.sin(k * x)
        np.testing.assert_allclose(stress.component("xz")[i, :, 0], shear, rtol=0, atol=1e-9 * mean)
        np.testing.assert_allclose(stress.component("yz")[i], 0.0, atol=1e-9 * mean)


def _smooth_field(rng, n):
    """Random periodic field with only long wavelengths (so z-differences are accurate)."""
    spectrum = np.fft.rfft2(rng.normal(size=(n, n)))
    kx = np.fft.fftfreq(n)[:, None] * n
    ky = np.fft.rfftfreq(n)[None, :] * n
    spectrum[np.hypot(kx, ky) > 6] = 0
    return np.fft.irfft2(spectrum, s=(n, n))


def test_tractions_satisfy_surface_conditions_and_equilibrium():
    rng = np.random.default_rng(5)
    n, length = 64, 1e-5
    p = 1e8 + 1e7 * _smooth_field(rng, n)
    qx, qy = 1e7 * _smooth_field(rng, n), 1e7 * _smooth_field(rng, n)
    h = 1e-4 * length
    z0 = 0.05 * length
    stress = subsurface_stress(
        p, (length, length), [0.0, z0 - h, z0, z0 + h], poissons_ratio=NU, traction=(qx, qy)
    )
    scale = 1e8
    np.testing.assert_allclose(stress.component("zz")[0], -p, atol=1e-9 * scale)
    np.testing.assert_allclose(stress.component("xz")[0], -qx, atol=1e-9 * scale)
    np.testing.assert_allclose(stress.component("yz")[0], -qy, atol=1e-9 * scale)

    k = 2 * np.pi * np.fft.fftfreq(n, d=length / n)

    def d(field, axis):
        return np.real(
            np.fft.ifft(1j * np.expand_dims(k, 1 - axis) * np.fft.fft(field, axis=axis), axis=axis)
        )

    def dz(name):
        return (stress.component(name)[3] - stress.component(name)[1]) / (2 * h)

    def at(name):
        return stress.component(name)[2]

    for row in (("xx", "xy", "xz"), ("xy", "yy", "yz"), ("xz", "yz", "zz")):
        residual = d(at(row[0]), 0) + d(at(row[1]), 1) + dz(row[2])
        assert np.max(np.abs(residual)) * length < 1e-5 * scale, row


def test_sliding_line_contact_surface_stress():
    """Johnson (1985) eq. 7.21 (q = mu p on a Hertz line contact): sigma_x(x, 0) = -p - 2 mu p0 x / a.

    Periodic array of contacts 64 a apart: the mean pressure adds (1 - nu/(1 - nu)) mean(p) (the
    q = 0 mode under uniaxial strain); the images' remaining effect is O((a/L)^2).
    """
    a, p0, mu, n = 1e-5, 1e8, 0.3, 8192
    length = 64 * a
    x = (np.arange(n) - n // 2) * length / n
    p = p0 * np.sqrt(np.clip(1 - (x / a) ** 2, 0, None))
    stress = subsurface_stress(
        p[:, None],
        (length, length / n),
        [0.0],
        poissons_ratio=NU,
        traction=(mu * p[:, None], np.zeros((n, 1))),
    )
    inside = np.abs(x) < 0.95 * a
    exact = -p - 2 * mu * p0 * x / a + (1 - NU / (1 - NU)) * p.mean()
    error = np.abs(stress.component("xx")[0, :, 0] - exact)[inside]
    assert np.max(error) < 2.5e-3 * p0
    assert stress.component("xx")[0, np.argmin(np.abs(x + 0.999 * a)), 0] > 0  # tension at the trailing edge


def test_shear_in_y_is_shear_in_x_transposed():
    rng = np.random.default_rng(1)
    p, q = rng.random((32, 32)), rng.random((32, 32))
    a = subsurface_stress(p, (1.0, 1.0), [0.1], poissons_ratio=NU, traction=(q, np.zeros_like(q)))
    b = subsurface_stress(p.T, (1.0, 1.0), [0.1], poissons_ratio=NU, traction=(np.zeros_like(q), q.T))
    # Equal up to the Nyquist modes, where rfft2 treats the two axes differently.
    for ca, cb in (("xx", "yy"), ("zz", "zz"), ("xz", "yz"), ("xy", "xy")):
        np.testing.assert_allclose(a.component(ca)[0], b.component(cb)[0].T, atol=1e-4)


def test_film_stress_of_the_same_material_as_its_substrate_is_the_half_space():
    from roughcontact.elasticity.halfspace import ElasticLayer
    from roughcontact.materials import Material

    steel = Material(youngs_modulus=200e9, poissons_ratio=0.3)
    n, size = 32, 1e-6
    x = np.arange(n) * size / n
    xx, yy = np.meshgrid(x, x, indexing="ij")
    pressure = 1e9 * np.exp(-((xx - size / 2) ** 2 + (yy - size / 2) ** 2) / (0.1 * size) ** 2)
    depths = [0.0, 0.1e-6, 0.3e-6]  # in the film and below it
    layer = ElasticLayer(0.2e-6, steel, base=steel)
    film = subsurface_stress(pressure, (size, size), depths, poissons_ratio=0.3, layer=layer)
    half = subsurface_stress(pressure, (size, size), depths, poissons_ratio=0.3)
    assert np.abs(film.components - half.components).max() < 1e-12 * pressure.max()


def test_film_stress_meets_the_surface_conditions_and_a_stiff_substrate_concentrates_it():
    from roughcontact.elasticity.halfspace import ElasticLayer
    from roughcontact.materials import Material

    su8, silicon = Material(7.64e9, 0.22), Material(130e9, 0.28)
    n, size = 64, 30e-6
    x = np.arange(n) * size / n
    xx, yy = np.meshgrid(x, x, indexing="ij")
    pressure = 1e8 * np.exp(-((xx - size / 2) ** 2 + (yy - size / 2) ** 2) / (3e-6) ** 2)
    on_silicon = subsurface_stress(
        pressure, (size, size), [0.0, 3e-6], poissons_ratio=0.22, layer=ElasticLayer(3e-6, su8, base=silicon)
    )
    assert np.abs(on_silicon.component("zz")[0] + pressure).max() < 1e-9 * pressure.max()
    assert np.abs(on_silicon.component("xz")[0]).max() < 1e-9 * pressure.max()
    half = subsurface_stress(pressure, (size, size), [3e-6], poissons_ratio=0.22)
    assert -on_silicon.component("zz")[1].min() > -half.component("zz")[0].min()  # the wafer carries more
