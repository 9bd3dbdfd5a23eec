"""Adhesive BEM contact (roughcontact.contact.solve_adhesive) against closed forms and invariants.

Sphere: the Maugis-Dugdale pull-off (Maugis 1992, roughcontact.analytic.adhesion) on a free
window. The Dugdale law's step in traction makes the error first order in pixel / cohesive zone
(measured: +14 % at 4 pixels, +6.8 % at 8 pixels across the zone at lambda = 1.63), so the test
checks that error halves with the pixel and that the Richardson extrapolation of the two grids
lands on Maugis' value.
"""

import numpy as np
import pytest

from roughcontact.analytic.adhesion import maugis_dugdale_pull_off, maugis_parameter
from roughcontact.contact import solve_normal
from roughcontact.contact.adhesive import solve_adhesive
from roughcontact.contact.interaction import Exponential, LennardJones, MaugisDugdale, cohesive_zone_length
from roughcontact.errors import InputError
from roughcontact.topography.generate import sphere

RADIUS, MODULUS, WORK, WINDOW = 1.0, 1.0, 1e-3, 1.2
"""A sphere in units where R = E* = 1: w = 1e-3 gives a JKR contact radius of 0.24 in a window of 1.2."""

SCALE = (np.pi**2 * WORK**2 * RADIUS / MODULUS**2) ** (1 / 3)
"""Maugis' approach scale (pi^2 w^2 R / E*^2)^(1/3)."""


def _unload(n: int, law, *, boundary="free", start=1.0):
    ball = sphere((n, n), (WINDOW, WINDOW), radius=RADIUS, kind="paraboloid", periodic=boundary == "periodic")
    programme = SCALE * np.linspace(start, -0.5, int(round((start + 0.5) / 0.1)) + 1)
    return solve_adhesive(ball, MODULUS, law, approach=programme, boundary=boundary)


def test_maugis_dugdale_pull_off_converges_to_maugis_with_the_grid():
    law = MaugisDugdale(WORK, 6.9e-3)
    lam = maugis_parameter(WORK, RADIUS, MODULUS, law.peak_tension)
    exact = maugis_dugdale_pull_off(lam) * np.pi * WORK * RADIUS
    coarse, fine = (_unload(n, law).pull_off_force for n in (128, 256))
    assert lam == pytest.approx(1.634, abs=1e-3)
    assert cohesive_zone_length(law, MODULUS) / (WINDOW / 128) == pytest.approx(3.99, abs=0.01)
    assert 0 < fine - exact < 0.6 * (coarse - exact)  # first order: the error halves with the pixel
    assert 2 * fine - coarse == pytest.approx(exact, rel=0.02)  # measured 0.1 %


def test_dmt_side_pull_off_matches_maugis_on_one_grid():
    law = MaugisDugdale(WORK, 0.0376)  # lambda = 0.30: a wide cohesive zone, 21 pixels
    lam = maugis_parameter(WORK, RADIUS, MODULUS, law.peak_tension)
    result = _unload(128, law)
    assert lam == pytest.approx(0.300, abs=1e-3)
    exact = maugis_dugdale_pull_off(lam)
    assert result.pull_off_force / (np.pi * WORK * RADIUS) == pytest.approx(exact, rel=0.01)
    assert result.range_warnings() == []


def test_jump_in_and_out_are_bracketed_and_the_cycle_dissipates():
    law = Exponential(WORK, 6.9e-3)
    ball = sphere((64, 64), (WINDOW, WINDOW), radius=RADIUS, kind="paraboloid")
    programme = SCALE * np.concatenate([np.linspace(-1.0, 1.0, 11), np.linspace(1.0, -1.0, 11)[1:]])
    result = solve_adhesive(ball, MODULUS, law, approach=programme, jump_resolution=0.25 * law.length)
    scalars = result.scalars()
    assert result.contact_area[0] == 0 and result.contact_area[-1] == 0
    assert np.isfinite(scalars["jump_in_approach"]) and np.isfinite(scalars["jump_out_approach"])
    # hysteresis: the body snaps in later on loading than it lets go on unloading, after the pull-off
    assert scalars["jump_out_approach"] < scalars["jump_in_approach"]
    assert scalars["jump_out_approach"] < scalars["pull_off_approach"]
    jumps = np.flatnonzero(result.jump)
    assert all(abs(result.delta[i] - result.delta[i - 1]) <= 0.25 * law.length + 1e-15 for i in jumps)
    assert scalars["dissipated_energy"] > 0
    assert (~result.requested).sum() == scalars["inserted_steps"] > 0


def test_vanishing_adhesion_is_the_elastic_solver():
    ball = sphere((64, 64), (WINDOW, WINDOW), radius=RADIUS, kind="paraboloid")
    law = MaugisDugdale(1e-12, 1e-6)
    result = solve_adhesive(ball, MODULUS, law, approach=[0.02], until_detached=False)
    normal = solve_normal(ball, MODULUS, approach=0.02)
    pressure = result.maps["end"][0]
    assert np.abs(pressure - normal.pressure).max() < 1e-5 * normal.pressure.max()
    assert result.force[0] == pytest.approx(normal.pressure.sum() * ball.pixel_area, rel=1e-5)


def test_periodic_and_free_agree_for_a_small_contact_and_units_do_not_matter():
    law = Exponential(WORK, 0.02)
    free = _unload(64, law)
    periodic = _unload(64, law, boundary="periodic")
    assert periodic.pull_off_force == pytest.approx(free.pull_off_force, rel=0.02)
    nano = 1e-9  # the same problem with lengths in nm, moduli in GPa-like units: forces scale by L^2 E
    ball = sphere((64, 64), (WINDOW * nano,) * 2, radius=RADIUS * nano, kind="paraboloid")
    law_nm = Exponential(WORK * nano, 0.02 * nano)
    programme = SCALE * nano * np.linspace(1.0, -0.5, 16)
    scaled = solve_adhesive(ball, MODULUS, law_nm, approach=programme)
    assert scaled.pull_off_force / nano**2 == pytest.approx(free.pull_off_force, rel=1e-6)


def test_lennard_jones_law_is_paper_000_eq_7_with_the_gap_from_eps():
    law = LennardJones(0.05, 2e-9)
    assert law.energy(np.array([0.0]))[0] == pytest.approx(-0.05)
    assert law.traction(np.array([0.0]))[0] == pytest.approx(0.0, abs=1e-6)
    peak = law.traction(np.array([(3 ** (1 / 6) - 1) * 2e-9]))[0]
    assert -peak == pytest.approx(law.peak_tension)


@pytest.mark.parametrize(
    ("make", "field"),
    [
        (lambda: MaugisDugdale(-0.1, 1e-9), "work_of_adhesion"),
        (lambda: Exponential(0.1, 0.0), "length"),
    ],
)
def test_bad_laws_are_refused_naming_the_field(make, field):
    with pytest.raises(InputError) as error:
        make()
    assert error.value.field == field


def test_bad_programmes_are_refused():
    ball = sphere((16, 16), (WINDOW, WINDOW), radius=RADIUS, kind="paraboloid")
    with pytest.raises(InputError, match="approach"):
        solve_adhesive(ball, MODULUS, Exponential(WORK, 0.01), approach="5 nm")
    with pytest.raises(InputError, match="interaction"):
        solve_adhesive(ball, MODULUS, 0.1, approach=[0.0])


def test_an_unresolved_cohesive_zone_is_reported_with_the_pixel_needed():
    law = MaugisDugdale(WORK, 1e-3)  # zone 0.0008: a tenth of a pixel at 128^2
    ball = sphere((32, 32), (WINDOW, WINDOW), radius=RADIUS, kind="paraboloid")
    result = solve_adhesive(ball, MODULUS, law, approach=[0.0], until_detached=False)
    (warning,) = [w for w in result.range_warnings() if "cohesive zone" in w]
    assert "pixel of at most" in warning
    # at the first touch the contact is a pixel or two: said too
    assert any("not resolved by the grid" in w for w in result.range_warnings())
