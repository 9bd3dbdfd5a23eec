"""Fourier kernels: layer factors against each other and their limits; Love coefficients."""

import numpy as np
import pytest

from roughcontact.elasticity.kernels import (
    film_on_substrate_factor,
    layer_on_rigid_base_factor,
    love_influence_coefficients,
)

QT = np.array([1e-3, 0.01, 0.1, 0.5, 1.0, 3.0, 10.0, 50.0])


def test_film_on_identical_substrate_is_a_half_space():
    # 1e-9: conditioning of the 6 x 6 solve at small q t (the film and substrate modes nearly cancel)
    np.testing.assert_allclose(film_on_substrate_factor(QT, 1e9, 0.3, 1e9, 0.3), 1.0, rtol=1e-9)


def test_film_on_very_stiff_substrate_is_the_bonded_layer():
    """Independent check of the closed form by the 6 x 6 Airy-mode solve (stiffness ratio 1e7)."""
    film = film_on_substrate_factor(QT, 1e9, 0.3, 1e16, 0.3)
    rigid = layer_on_rigid_base_factor(QT, 0.3, base="bonded")
    np.testing.assert_allclose(film, rigid, rtol=1e-3)
    np.testing.assert_allclose(film[2:], rigid[2:], rtol=1e-5)


def test_thin_film_tends_to_the_substrate():
    ratio = (
        2e9 * (1 - 0.2**2) / (1e9 * (1 - 0.3**2))
    )  # c_substrate / c_film = E_f (1 - nu_s^2) / (E_s (1 - nu_f^2))
    assert film_on_substrate_factor(np.array([1e-6]), 2e9, 0.3, 1e9, 0.2)[0] == pytest.approx(
        ratio, rel=1e-5, abs=0
    )


@pytest.mark.parametrize("nu", [0.0, 0.22, 0.3, 0.45])
def test_layer_limits(nu):
    small, large = np.array([1e-5]), np.array([40.0])
    bonded = layer_on_rigid_base_factor(small, nu)[0] / small[0]
    assert bonded == pytest.approx((1 - 2 * nu) / (2 * (1 - nu) ** 2), rel=1e-4, abs=0)
    frictionless = layer_on_rigid_base_factor(small, nu, base="frictionless")[0] / small[0]
    assert frictionless == pytest.approx(0.5, rel=1e-4, abs=0)
    for base in ("bonded", "frictionless"):
        assert layer_on_rigid_base_factor(large, nu, base=base)[0] == pytest.approx(1.0, rel=1e-12, abs=0)
    assert np.isfinite(layer_on_rigid_base_factor(np.array([1e4]), nu)).all()


def test_love_coefficients_far_field_is_a_point_load():
    """Far from the loaded pixel D -> A / (pi E* r) (Boussinesq point load)."""
    spacing = (1e-6, 2e-6)
    d = love_influence_coefficients((256, 256), spacing, 1e9)
    r = np.hypot(60 * spacing[0], 40 * spacing[1])
    point = spacing[0] * spacing[1] / (np.pi * 1e9 * r)
    assert d[60, 40] == pytest.approx(point, rel=1e-3, abs=0)
    assert d[-60, -40] == d[60, 40]  # symmetric in the wrap-around layout
    # Centre of a uniformly loaded square of side s: 4 s asinh(1) / (pi E*)
    square = love_influence_coefficients((8, 8), (1e-6, 1e-6), 1e9)[0, 0]
    assert square == pytest.approx(4 * 1e-6 * np.arcsinh(1.0) / (np.pi * 1e9), rel=1e-12, abs=0)
