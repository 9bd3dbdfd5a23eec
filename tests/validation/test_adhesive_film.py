"""Adhesive contact of a film: the layer kernels of the normal solver under an interaction law.

* a film much thicker than the interaction zone is the half-space (same pull-off);
* a film on the same material as substrate is the half-space whatever its thickness;
* a thin film on a rigid base is stiffer (more force at the same approach) and deforms locally
  (contact over the geometric intersection, the Winkler limit); its pull-off is above the
  half-space's (Maugis-Dugdale at lambda = 0.3, 1.816 pi w R) and within 10 % of DMT's 2 pi w R
  (measured +3.3 %: the film stretches towards the flat where it is pulled).

Maugis-Dugdale law, lambda = 0.3 (w = 50 mJ/m^2, rho = 1.9 nm, E* = 4.4 GPa, R = 1 um), 32^2
pixels of 6.25 nm over 200 nm: the cohesive zone spans ~40 pixels.
"""

import math

import numpy as np
import pytest

from roughcontact.analytic.adhesion import maugis_dugdale_pull_off, maugis_parameter
from roughcontact.contact import MaugisDugdale, solve_adhesive
from roughcontact.elasticity.halfspace import ElasticLayer
from roughcontact.materials import Material
from roughcontact.topography.generate import sphere

FILM = Material(4e9, 0.3, name="film")
BALL = sphere((32, 32), 200e-9, radius=1e-6)
LAW = MaugisDugdale(0.05, 1.9e-9)
PROGRAMME = np.r_[np.linspace(-4e-9, 1.5e-9, 12), np.linspace(1.5e-9, -4e-9, 12)[1:]]


def _cycle(layer=None):
    material = None if layer is not None else FILM
    return solve_adhesive(BALL, material, LAW, approach=PROGRAMME, layer=layer, boundary="free")


@pytest.fixture(scope="module")
def halfspace():
    return _cycle()


def test_a_thick_film_is_the_half_space():
    """Periodic: a film 50 windows thick (10 um) has the half-space's pull-off within 0.2 % (0.025 %).

    The film's mean mode has its own compliance, t / E (the approach is counted from its base), a
    soft machine for the thickest films (100 um: +1.3 %, the programme samples the minimum
    differently). The free window approximates a layer only when it is thin compared with the
    window (:class:`~roughcontact.elasticity.halfspace.SurfaceCompliance`), so it is not used here.
    """
    halfspace = solve_adhesive(BALL, FILM, LAW, approach=PROGRAMME, boundary="periodic")
    thick = solve_adhesive(
        BALL, None, LAW, approach=PROGRAMME, boundary="periodic", layer=ElasticLayer(10e-6, FILM)
    )
    assert thick.pull_off_force == pytest.approx(halfspace.pull_off_force, rel=2e-3)


def test_a_film_on_its_own_material_is_the_half_space(halfspace):
    same = _cycle(ElasticLayer(20e-9, FILM, base=FILM))
    assert same.pull_off_force == pytest.approx(halfspace.pull_off_force, rel=2e-3)


def test_a_thin_film_on_a_rigid_base_is_stiffer_and_keeps_the_dmt_pull_off(halfspace):
    thin = _cycle(ElasticLayer(20e-9, FILM, base="bonded"))
    peak = int(np.argmax(thin.approach))
    assert thin.force[peak] > 1.5 * halfspace.force[peak]
    # a thin film deforms locally (Winkler): contact over the geometric intersection, pi 2 R delta,
    # twice Hertz' pi R delta, which the half-space (with its adhesion) exceeds
    delta = thin.approach[peak]
    assert thin.contact_area[peak] == pytest.approx(2 * math.pi * 1e-6 * delta, rel=0.1)
    assert math.pi * 1e-6 * delta < halfspace.contact_area[peak] < thin.contact_area[peak]
    w, radius = LAW.work_of_adhesion, 1e-6
    lam = maugis_parameter(w, radius, FILM.youngs_modulus / (1 - FILM.poissons_ratio**2), LAW.peak_tension)
    assert halfspace.pull_off_force == pytest.approx(
        maugis_dugdale_pull_off(lam) * math.pi * w * radius, rel=0.02
    )
    # the film's springs stretch towards the flat under the tension (measured +3.3 % over DMT)
    assert halfspace.pull_off_force < thin.pull_off_force
    assert thin.pull_off_force == pytest.approx(2 * math.pi * w * radius, rel=0.1)
