"""Volume plasticity (roughcontact.contact.volume_plastic) against closed forms and FEM fits.

A smooth elastic-perfectly-plastic paraboloid (E = 200 GPa, nu = 0.3, Y = 1 GPa, R = 1 mm) is
pressed on a rigid flat, force-controlled, on a free 48^2 window 10 a_c wide with 24 layers down
to 4 a_c (a_c = sqrt(R omega_c), about 4.8 pixels). omega_c, P_c and A_c are those of Kogut and
Etsion (2002) (H = 2.8 Y, K = 0.454 + 0.41 nu).

Tolerances and what sets them:

- Below yield the solver is the elastic solver: pressure to 1e-8 of the peak (one contact solve).
- Onset of yield (Hertz, Johnson 1985 sec. 6.2): max von Mises 0.620 p0 at z = 0.48 a for
  nu = 0.3; on this grid to 1 % in stress and within one cell in depth.
- Kogut-Etsion load and area for omega/omega_c up to 5.8: measured -5.2 % (load) and +7 %
  (area, pixel-quantised at a_c = 4.8 px) at worst; asserted within 6 % and 8 %. These are model
  differences (small strains, a half-space for the sphere, the fits' own scatter), not mesh error:
  the 48^2 and 96^2 grids agree to 0.3 % on the residual interference.
- Residual interference against the Etsion-Kligerman-Kadin fit: 0.291 omega_max against 0.254 at
  omega_max = 5.8 omega_c (+15 %; the fit is recalled, see docs/asperity.md); asserted within 20 %.
- Plastic work >= 0 at every step; unloading is elastic (a reload to the peak retraces the
  unloading branch to 1e-6 of the peak interference and dissipates < 1e-4 of the loading's work).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from roughcontact.asperity.elastic_plastic import (
    critical_interference,
    critical_load,
    kogut_etsion_area,
    kogut_etsion_load,
    residual_interference_ratio,
)
from roughcontact.contact import solve_normal
from roughcontact.contact.volume_plastic import solve_elastic_plastic
from roughcontact.errors import InputError
from roughcontact.materials import Material
from roughcontact.topography.generate import sphere

E, NU, Y, R = 200e9, 0.3, 1e9, 1e-3
STEEL = Material(youngs_modulus=E, poissons_ratio=NU, yield_strength=Y)
E_STAR = E / (1 - NU**2)
OMEGA_C = critical_interference(hardness=2.8 * Y, poissons_ratio=NU, contact_modulus=E_STAR, radius=R)
P_C = critical_load(hardness=2.8 * Y, poissons_ratio=NU, contact_modulus=E_STAR, radius=R)
A_C = np.pi * R * OMEGA_C
RADIUS_C = np.sqrt(R * OMEGA_C)
LOADING = [0.5, 1, 2, 4, 8, 12]
UNLOADING = [8, 4, 2, 1, 0]
RELOADING = [4, 8, 12]


def _ball(n=48):
    return sphere((n, n), (10 * RADIUS_C, 10 * RADIUS_C), radius=R, kind="paraboloid")


def _path(n=48, forces=tuple(LOADING + UNLOADING), **options):
    return solve_elastic_plastic(
        _ball(n), STEEL, forces=P_C * np.asarray(forces), depth=4 * RADIUS_C, layers=n // 2, **options
    )


@pytest.fixture(scope="module")
def cycle():
    forces = LOADING + UNLOADING + RELOADING
    branch = ["loading"] * len(LOADING) + ["unloading"] * len(UNLOADING) + ["reloading"] * len(RELOADING)
    return _path(forces=forces, branch=branch)


def test_below_yield_the_solver_is_the_elastic_solver():
    result = _path(forces=[0.5])
    elastic = solve_normal(_ball(), STEEL, force=0.5 * P_C, tolerance=1e-10)
    assert np.abs(result.pressure[0] - elastic.pressure).max() < 1e-8 * elastic.pressure.max()
    assert not result.plastic_strain.any()
    assert result.iterations == 1


def test_onset_of_yield_is_hertz():
    """Half the critical load: max von Mises 0.620 p0 at z = 0.48 a (nu = 0.3, Johnson 1985 sec. 6.2)."""
    result = _path(forces=[0.5])
    p0 = (6 * 0.5 * P_C * E_STAR**2 / (np.pi**3 * R**2)) ** (1 / 3)
    radius = (3 * 0.5 * P_C * R / (4 * E_STAR)) ** (1 / 3)  # Hertz contact radius
    field = result.von_mises[0]
    assert field.max() == pytest.approx(0.620 * p0, rel=0.01)
    depth = result.depths[np.unravel_index(np.argmax(field), field.shape)[0]]
    cell = result.depths[1] - result.depths[0]
    assert abs(depth - 0.48 * radius) <= cell


def test_yield_starts_at_the_critical_load(cycle):
    assert cycle.dissipation[0] == 0.0
    assert cycle.von_mises[0].max() < Y
    assert cycle.von_mises[1].max() == pytest.approx(Y, rel=1e-3)  # P_c: just at yield


def test_loading_follows_kogut_etsion(cycle):
    for step in range(2, len(LOADING)):
        w_star = cycle.approach[step] / OMEGA_C
        assert cycle.force[step] / P_C == pytest.approx(kogut_etsion_load(w_star), rel=0.06)
        assert cycle.contact_area[step] / A_C == pytest.approx(kogut_etsion_area(w_star), rel=0.08)


def test_residual_interference_against_etsion_kligerman_kadin(cycle):
    peak = len(LOADING) - 1
    last = len(LOADING) + len(UNLOADING) - 1
    assert cycle.force[last] == 0.0
    lift = cycle.residual_displacement[last]
    heights = cycle.topography.heights
    residual = np.min(heights.max() - heights + lift)
    ratio = residual / cycle.approach[peak]
    assert ratio == pytest.approx(residual_interference_ratio(cycle.approach[peak] / OMEGA_C), rel=0.2)
    assert cycle.approach[last] == pytest.approx(residual)


def test_plastic_work_is_never_negative_and_unloading_is_elastic(cycle):
    assert np.all(cycle.dissipation >= 0)
    loading_work = cycle.dissipation[: len(LOADING)].sum()
    assert loading_work > 0
    unloading = slice(len(LOADING), len(LOADING) + len(UNLOADING))
    assert cycle.dissipation[unloading].sum() == 0.0
    assert cycle.dissipation[-len(RELOADING) :].sum() < 1e-4 * loading_work


def test_reloading_retraces_the_unloading_branch(cycle):
    peak_interference = cycle.approach[len(LOADING) - 1]
    for force, approach in zip(
        cycle.force[-len(RELOADING) :], cycle.approach[-len(RELOADING) :], strict=True
    ):
        index = [i for i in range(len(LOADING), len(cycle.force)) if cycle.force[i] == pytest.approx(force)][
            0
        ]
        assert approach == pytest.approx(cycle.approach[index], abs=1e-6 * peak_interference)


def test_residual_stress_remains_at_zero_load(cycle):
    last = len(LOADING) + len(UNLOADING) - 1
    assert cycle.pressure[last].max() == 0.0
    assert cycle.von_mises[last].max() > 0.3 * Y
    assert cycle.scalars()["max_residual_von_mises"] > 0


def test_mesh_refinement_leaves_the_residual_interference():
    coarse, fine = (_path(n, forces=[1, 8, 0]) for n in (32, 48))
    assert coarse.residual_interference == pytest.approx(fine.residual_interference, rel=0.01)


@pytest.mark.parametrize(
    ("options", "field"),
    [
        (dict(yield_strength=-1.0), "yield_strength"),
        (dict(yield_strength=300e9), "yield_strength"),
        (dict(hardening_modulus=-1.0), "hardening_modulus"),
    ],
)
def test_bad_plastic_constants_name_the_field(options, field):
    with pytest.raises(InputError) as raised:
        _path(n=16, forces=[1.0], **options)
    assert raised.value.field == field


def test_a_plastic_zone_reaching_the_bottom_says_how_deep_to_go():
    with pytest.raises(InputError, match="deeper volume") as raised:
        solve_elastic_plastic(_ball(32), STEEL, forces=[8 * P_C], depth=0.5 * RADIUS_C, layers=4)
    assert raised.value.field == "depth"


def test_one_programme_only():
    with pytest.raises(InputError):
        solve_elastic_plastic(_ball(16), STEEL, forces=[1.0], approaches=[1e-9], depth=RADIUS_C)
    with pytest.raises(InputError):
        solve_elastic_plastic(_ball(16), STEEL, forces=[np.nan], depth=RADIUS_C)


def test_a_thick_film_on_a_substrate_is_the_half_space():
    """Film 40 volumes deep on a soft substrate: the same pressures, plastic strain and residual (1e-3)."""
    glass = Material(youngs_modulus=70e9, poissons_ratio=0.2)
    forces = P_C * np.array([4.0, 8.0, 0.0])
    half = _path(32, forces=[4, 8, 0])
    film = solve_elastic_plastic(
        _ball(32), STEEL, forces=forces, depth=4 * RADIUS_C, layers=16,
        substrate=glass, film_thickness=160 * RADIUS_C,
    )  # fmt: skip
    # pressures, plastic strain and residual interference; the loaded approach differs by the layered
    # surface kernel's mean mode on a free window (a uniform shift, SurfaceCompliance notes)
    assert np.abs(film.pressure - half.pressure).max() < 1e-3 * half.pressure.max()
    assert np.abs(film.plastic_strain - half.plastic_strain).max() < 1e-3 * np.abs(half.plastic_strain).max()
    assert film.residual_interference == pytest.approx(half.residual_interference, rel=1e-3)


def test_a_stiff_substrate_under_a_thin_film_shrinks_the_interference():
    """Film 4 a_c thick: on diamond-like stiffness the peak interference falls below the half-space's."""
    stiff = Material(youngs_modulus=2000e9, poissons_ratio=0.2)
    half = _path(32, forces=[8])
    film = solve_elastic_plastic(
        _ball(32), STEEL, forces=P_C * np.array([8.0]), depth=4 * RADIUS_C, layers=16,
        substrate=stiff, film_thickness=4 * RADIUS_C,
    )  # fmt: skip
    assert film.approach[0] < 0.9 * half.approach[0]
    assert film.dissipation[0] > 0


def test_range_warnings_name_large_plastic_strain_and_a_deep_plastic_zone(cycle):
    """A run within the model's range says nothing; a large strain or a zone near the bottom is said."""
    assert _path(n=32, forces=(2, 0)).range_warnings() == []
    # the validation cycle itself: at 12 P_c the zone reaches 43.3 of the 46.2 um (4 a_c) volume
    (deep,) = cycle.range_warnings()
    assert "plastic zone reaches" in deep and "deeper" in deep
    strained = dataclasses.replace(
        cycle, plastic_strain_equivalent=np.full_like(cycle.plastic_strain_equivalent, 0.2)
    )
    notes = strained.range_warnings()
    assert len(notes) == 2
    assert "0.2" in notes[0] and "small-strain" in notes[0]
    assert "deeper" in notes[1] and "depth = '" in notes[1]
