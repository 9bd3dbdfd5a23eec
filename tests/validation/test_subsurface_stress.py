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
