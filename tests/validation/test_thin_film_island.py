"""BEM flat-punch compression of the paper 002 island: load balance, hardness cap, plastic memory."""

import numpy as np
import pytest

from roughcontact.errors import InputError
from roughcontact.materials import get_material
from roughcontact.papers import paper002
from roughcontact.papers.paper002 import compress_island, paper002_island

SU8, SILICON = get_material("SU-8"), get_material("silicon wafer")
ISLAND = paper002_island(40, seed=3)
RUN = compress_island(ISLAND, SU8, substrate=SILICON, tolerance=1e-9)


def test_gaussian_stand_in_has_the_papers_rms_height_on_its_top():
    island = paper002_island(40, seed=3, roughness="gaussian")
    top = island.heights[island.heights > paper002.FILM_THICKNESS / 2]
    assert np.sqrt(np.mean((top - top.mean()) ** 2)) == pytest.approx(
        np.sqrt(paper002.MOMENTS["m0"]), rel=1e-12, abs=0
    )
    assert island.size[0] == pytest.approx(30e-6, rel=1e-12, abs=0)
    # Gaussian ACF: m2 = 2 m0 / xi^2 gives the paper's m2 for xi = 1.36 um
    assert island.info["correlation_length"] == pytest.approx(1.3618e-6, rel=1e-4, abs=0)


def test_moments_stand_in_is_one_island_on_every_grid_with_the_papers_moments():
    """The default stand-in: paper 002's three moments in expectation, the same field on every grid."""
    coarse, fine = paper002_island(96, seed=3), paper002_island(384, seed=3)
    assert coarse.info["roughness"] == "moments" and not coarse.info["resolved"]
    # 96 px over the 30 um window hold every mode of the band (q_s: 1.07 um): the fine island at
    # every 4th point is the coarse one
    np.testing.assert_allclose(fine.heights[::4, ::4], coarse.heights, rtol=0, atol=1e-9 * np.sqrt(2.13e-15))
    # the tops' moments, averaged over realisations (one draw scatters 12 % in m0, 5 % in m2)
    tops = [paper002.island_top_moments(paper002_island(384, seed=seed)) for seed in range(24)]
    # measured: m0 -1.6 %, m2 -1.6 %, m4 -3.0 % (78 nm pixels: the second difference reads m4 low);
    # tolerance ~3 standard errors of the 24-draw mean (m0 2.3 %, m2 0.7 %, m4 0.6 %) plus that bias
    for name, tolerance in (("m0", 0.08), ("m2", 0.03), ("m4", 0.05)):
        mean = np.mean([top[f"top_{name}"] for top in tops])
        assert mean == pytest.approx(paper002.MOMENTS[name], rel=tolerance), name
        assert tops[0][f"paper_{name}"] == paper002.MOMENTS[name]


def test_every_step_carries_its_target_load_and_never_exceeds_the_hardness():
    curve = RUN.curve()
    loading = np.unique(np.r_[np.linspace(0, 1e-3, 11), 25e-6])
    targets = np.concatenate([loading, loading[::-1][1:]])
    np.testing.assert_allclose(curve["force"], targets, rtol=1e-6, atol=1e-12 * 1e-3)
    for step in RUN.steps:
        assert step.pressure.max() <= SU8.hardness
        assert step.converged


def test_zero_interference_at_25_uN_and_unloading_ends_at_the_residual():
    curve = RUN.curve()
    loading = curve["branch"] == "loading"
    at_reference = np.isclose(curve["force"][loading], 25e-6, rtol=1e-6, atol=0)
    assert curve["approach"][loading][at_reference][0] == 0.0
    assert curve["approach"][-1] == RUN.residual_interference
    assert curve["force"][-1] == 0.0
    # interference grows with load on loading and falls on unloading
    assert np.all(np.diff(curve["approach"][loading]) > 0)
    assert np.all(np.diff(curve["approach"][~loading]) < 0)


def test_plastic_flattening_sits_where_the_peak_pressure_is_capped():
    peak = RUN.steps[int(np.sum(RUN.branch == "loading")) - 1]
    assert np.all(RUN.plastic_deformation[~peak.plastic_mask] == 0)
    assert RUN.residual_interference >= RUN.curve()["approach"][0]  # at or beyond the first touch


def test_elastic_island_unloads_along_its_loading_curve():
    elastic = compress_island(ISLAND, SU8, substrate=SILICON, hardness=1e12, tolerance=1e-10)
    assert not elastic.plastic_deformation.any()
    curve = elastic.curve()
    loading = curve["branch"] == "loading"
    # Each unloading point against the loading point of the same target force; the root finder
    # hits a target to about 1e-8 relative, so the points are paired by the nearest force.
    loading_force, loading_approach = curve["force"][loading], curve["approach"][loading]
    for force, approach in zip(curve["force"][~loading], curve["approach"][~loading], strict=True):
        nearest = np.argmin(np.abs(loading_force - force))
        assert loading_force[nearest] == pytest.approx(force, rel=1e-7, abs=1e-12)
        assert approach == pytest.approx(loading_approach[nearest], rel=1e-6, abs=1e-6 * 1e-8)


def test_von_mises_maps_at_the_papers_loads():
    curve = RUN.curve()
    for index in (2, 6, 11):
        stress = RUN.stress(index, depths=[0.0, 0.5e-6])
        vm = stress.von_mises()
        assert vm.shape == (2, *ISLAND.shape)
        assert vm.max() > 0
    # no load, no stress: the surface-plasticity model keeps no residual stress
    assert RUN.stress(len(RUN.steps) - 1).von_mises().max() == 0.0
    assert curve["force"][-1] == 0.0


def test_bad_targets_are_refused():
    with pytest.raises(InputError, match="loading_forces"):
        compress_island(ISLAND, SU8, loading_forces=[0, 5e-4, 2e-4, 1e-3])
    with pytest.raises(InputError, match="reference_force"):
        compress_island(ISLAND, SU8, loading_forces=[0, 5e-4, 1e-3])
    with pytest.raises(InputError, match="hardness"):
        compress_island(ISLAND, get_material("silicon wafer"))


def test_two_interferences_after_the_peak_under_two_names():
    """residual_interference is at zero load; interference_at_return_force back at 25 uN (KKE's end point)."""
    curve = RUN.curve()
    unloading = np.flatnonzero(curve["branch"] == "unloading")
    at_25 = unloading[np.isclose(curve["force"][unloading], 25e-6, rtol=1e-6, atol=0)][0]
    assert RUN.return_force == 25e-6
    assert RUN.interference_at_return_force == curve["approach"][at_25]
    assert RUN.residual_interference == curve["approach"][-1] and curve["force"][-1] == 0.0
    # the film springs back between 25 uN and zero load: the two are different numbers
    assert RUN.residual_interference < RUN.interference_at_return_force
    scalars = RUN.scalars()
    assert scalars["interference_at_return_force"] == RUN.interference_at_return_force
    assert scalars["residual_interference"] == RUN.residual_interference
    assert scalars["return_force"] == 25e-6
    for name in ("interference_at_return_force", "residual_interference", "return_force"):
        assert name in RUN.UNITS


def test_return_point_between_targets_is_interpolated_in_the_force():
    run = compress_island(
        ISLAND, SU8, substrate=SILICON, loading_forces=[0, 25e-6, 5e-4, 1e-3], unloading_forces=[5e-4, 0.0]
    )
    curve = run.curve()
    (w_half, w_zero), (f_half, f_zero) = curve["approach"][-2:], curve["force"][-2:]
    expected = w_half + (f_half - 25e-6) / (f_half - f_zero) * (w_zero - w_half)
    assert run.interference_at_return_force == pytest.approx(expected, rel=1e-12)
    assert w_zero < run.interference_at_return_force < w_half


def test_statistical_model_names_its_end_point_for_what_it_is():
    kke = paper002.statistical_curve()
    scalars = kke.scalars()
    assert "residual_interference" not in scalars
    assert scalars["return_force"] == 25e-6
    # the unloading branch ends at the return force, at this interference
    assert kke.force[-1] == pytest.approx(25e-6, rel=1e-9)
    assert scalars["interference_at_return_force"] == kke.approach[-1]
    with pytest.warns(DeprecationWarning, match="interference_at_return_force"):
        assert kke.residual_interference == kke.interference_at_return_force
