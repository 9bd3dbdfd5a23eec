"""Load paths (warm starts) and two rough bodies through their composite surface."""

import numpy as np
import pytest

from roughcontact.contact import load_path, solve_normal
from roughcontact.materials import Material
from roughcontact.topography.generate import self_affine
from roughcontact.topography.process import combine


def _surface(seed=3, n=64):
    return self_affine((n, n), (1e-5, 1e-5), hurst=0.8, rms_slope=0.1, seed=seed)


def test_warm_started_path_matches_cold_solves_with_fewer_iterations():
    surface = _surface()
    loads = [1e6, 2e6, 4e6, 8e6]
    path = list(load_path(surface, 1e9, mean_pressures=loads, tolerance=1e-10))
    cold = [solve_normal(surface, 1e9, mean_pressure=p, tolerance=1e-10) for p in loads]
    for warm, reference in zip(path, cold, strict=True):
        np.testing.assert_allclose(
            warm.pressure, reference.pressure, rtol=0, atol=1e-6 * reference.pressure.max()
        )
    assert sum(r.iterations for r in path[1:]) < sum(r.iterations for r in cold[1:])
    areas = [r.contact_fraction for r in path]
    assert areas == sorted(areas)  # contact area grows with load


def test_two_rough_bodies_are_symmetric():
    a, b = _surface(1), _surface(2)
    soft, stiff = Material(2e9, 0.4), Material(150e9, 0.2)
    one = solve_normal(combine(a, b), soft, counter_body=stiff, mean_pressure=5e6, tolerance=1e-10)
    other = solve_normal(combine(b, a), stiff, counter_body=soft, mean_pressure=5e6, tolerance=1e-10)
    np.testing.assert_allclose(one.pressure, other.pressure, rtol=0, atol=1e-9 * one.pressure.max())
    assert one.contact_modulus == pytest.approx(1 / ((1 - 0.16) / 2e9 + (1 - 0.04) / 150e9), rel=1e-12, abs=0)
