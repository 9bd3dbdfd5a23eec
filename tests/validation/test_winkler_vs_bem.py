"""Paper 000's Winkler-Lennard-Jones model beside the adhesive BEM (docs/winkler_lj.md).

Smooth sphere (R = 1 um, paper 000's materials and epsilon = 2 nm) on small free windows; every
case below takes well under a second.
"""

import math

import numpy as np
import pytest

from roughcontact.contact.interaction import LennardJones
from roughcontact.errors import InputError
from roughcontact.friction import Readings, winkler_lj_model
from roughcontact.materials import get_material
from roughcontact.models.paper000 import winkler_beside_bem
from roughcontact.topography import Topography

RADIUS, EPS, W = 1e-6, 2e-9, 2.0 * math.sqrt(0.05 * 0.072)  # dgamma = 2 sqrt(g1 g2) = 0.12 J/m^2
ENERGIES = {"surface_energy": 0.05, "counter_surface_energy": 0.072}


def sphere(n: int = 32, pixel: float = 10e-9) -> Topography:
    x = (np.arange(n) - n // 2) * pixel
    xx, yy = np.meshgrid(x, x, indexing="ij")
    return Topography(-(xx**2 + yy**2) / (2 * RADIUS), n * pixel, periodic=False)


def model(topography, **options):
    return winkler_lj_model(
        topography,
        get_material("polysilicon"),
        get_material("SiO2"),
        epsilon=EPS,
        **({"layer_thickness": 50e-9} | ENERGIES | options),
    )


def rigid_sum(topography: Topography) -> float:
    """Derjaguin's rigid-sphere force at first touch over the same pixels: sum f(eps + z_max - z) S."""
    depth = topography.heights.max() - topography.heights
    return float(-LennardJones(W, EPS).traction(depth).sum() * topography.pixel_area)


def test_winkler_pull_off_is_the_rigid_sphere_limit_whatever_the_springs():
    # eq. 2 takes the attraction at the undeformed gap and no spring is compressed at first touch,
    # so the most tensile force is Derjaguin's rigid sum 2 pi R w (Bradley), independent of E and h
    surface = sphere(64, 5e-9)
    expected = rigid_sum(surface)
    pulls = [
        model(surface, layer_thickness=h).pull_off_force() for h in (20e-9, 50e-9, 500e-9)
    ]  # measured: the three agree to 1e-12 and exceed the sum at a = 0 by 5e-6 (the discrete minimum)
    assert pulls == pytest.approx([expected] * 3, rel=1e-4)
    # the window (radius 160 nm) cuts the tail: (4/3)(eps / l_edge)^2 ~ 1.8 %; measured 0.982
    assert expected / (2 * math.pi * RADIUS * W) == pytest.approx(1.0, abs=0.02)


def test_stiff_bem_reaches_the_rigid_limit_and_the_curves_share_the_approach():
    surface = sphere()
    programme = np.concatenate([np.linspace(-4e-9, 2e-9, 7), np.linspace(2e-9, -4e-9, 7)[1:]])
    result = winkler_beside_bem(
        surface, get_material("polysilicon"), get_material("SiO2"), approach=programme, **ENERGIES
    )
    scalars = result.scalars()
    assert result.bem.converged
    assert np.array_equal(result.winkler.approach, result.bem.approach)
    # paper 000's materials: lambda ~ 0.11 (DMT side). Measured: BEM 8.09e-7 N (2.146 pi w R),
    # Winkler 7.41e-7 N (the rigid sum), ratio 0.915; the Winkler contact is larger (1.36x at 2 nm)
    assert scalars["winkler_pull_off_force"] == pytest.approx(rigid_sum(surface), rel=1e-3)
    assert 0.85 < scalars["pull_off_ratio"] < 0.97
    assert scalars["contact_area_ratio"] > 1.0
    dataset = result.to_xarray()
    assert dataset["bem_force"].attrs["units"] == "N"
    assert set(result.UNITS) <= set(scalars)


def test_bem_gap_model_refuses_the_readings_of_eq_2():
    with pytest.raises(InputError) as error:
        model(sphere(8), gap_model="bem", readings=Readings(contact="zero_gap"))
    assert error.value.field == "gap_model"
    with pytest.raises(InputError):
        model(sphere(8), gap_model="elastic")
