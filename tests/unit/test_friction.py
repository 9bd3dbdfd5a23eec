"""Unit tests of the friction package: readings, E(t), bad input, results, sweeps."""

import math

import numpy as np
import pytest

from roughcontact.errors import InputError
from roughcontact.materials import get_material
from roughcontact.topography import Topography
from roughcontact.topography.generate import self_affine, sphere_with_roughness
from roughcontact.winkler_lj import (
    PRINTED,
    PronySeries,
    Readings,
    WinklerLJOptions,
    material_after_hold,
    solve_winkler_lj,
    standard_linear_solid,
    winkler_lj_model,
    work_of_adhesion,
)
from roughcontact.winkler_lj.readings import CHOICES

POLY, SIO2 = get_material("polysilicon"), get_material("SiO2")


@pytest.fixture(scope="module")
def pair():
    n = 48
    tip = sphere_with_roughness((n, n), n * 20e-9, radius=1e-6, rms_height=0.3e-9, seed=1)
    scan = self_affine((n, n), n * 20e-9, hurst=0.8, rms_height=1.8e-9, seed=2)
    return scan, tip


def model(pair, **options):
    scan, tip = pair
    options = WinklerLJOptions(**{"layer_thickness": 50e-9, "surface_energy": 0.05, **options})
    return winkler_lj_model(scan, POLY, SIO2, options=options, counter_topography=tip)


def test_readings_defaults_choices_and_strings():
    assert Readings().changed() == {}
    for name, allowed in CHOICES.items():
        assert getattr(Readings(), name) == allowed[0]
    parsed = Readings.from_strings(["contact=zero_gap", "adhesive-cutoff=2e-8"])
    assert parsed.contact == "zero_gap" and parsed.adhesive_cutoff == 2e-8
    assert parsed.changed() == {"contact": "zero_gap", "adhesive_cutoff": 2e-8}
    assert PRINTED.winkler_factor == "paper000_eq4_printed" and PRINTED.energy_area == "printed"


@pytest.mark.parametrize(
    "items, field",
    [
        (["contact=glued"], "readings.contact"),
        (["colour=red"], "readings"),
        (["contact"], "readings"),
        (["adhesive_cutoff=far"], "readings"),
    ],
)
def test_readings_refuse_unknown_values(items, field):
    with pytest.raises(InputError) as error:
        Readings.from_strings(items)
    assert error.value.field == field


def test_readings_refuse_non_positive_cutoff():
    with pytest.raises(InputError, match="adhesive_cutoff"):
        Readings(adhesive_cutoff=0.0)


def test_work_of_adhesion_readings():
    assert work_of_adhesion(0.05, 0.072) == pytest.approx(2 * math.sqrt(0.05 * 0.072), rel=1e-15)
    assert work_of_adhesion(0.05, 0.072, reading="printed") == pytest.approx(
        math.sqrt(0.05 * 0.072), rel=1e-15
    )


def test_prony_series_and_standard_linear_solid():
    sls = standard_linear_solid(100e9, 60e9, 2.0)
    assert sls(0.0) == pytest.approx(100e9, rel=1e-15)
    assert sls(2.0) == pytest.approx(60e9 + 40e9 / math.e, rel=1e-15)
    assert sls(1e4) == pytest.approx(60e9, rel=1e-12)
    prony = PronySeries(1e9, (2e9, 3e9), (1.0, 10.0))
    assert prony.instantaneous_modulus == 6e9
    assert material_after_hold(POLY, sls, 2.0).youngs_modulus == sls(2.0)
    with pytest.raises(InputError, match="relaxation_times"):
        PronySeries(1e9, (1e9,), ())
    with pytest.raises(InputError, match="instantaneous_modulus"):
        standard_linear_solid(1e9, 2e9, 1.0)
    with pytest.raises(InputError, match="hold_time"):
        material_after_hold(POLY, sls, -1.0)


def test_result_fields_and_xarray(pair):
    result = model(pair).solve(1e-5)
    assert result.topography.shape == result.stress.shape == result.lateral_force.shape
    assert not np.any(result.mechanical & result.adhesive)
    assert result.friction == pytest.approx(result.adhesive_friction + result.mechanical_friction, rel=1e-15)
    assert result.mu == pytest.approx(result.friction / 1e-5, rel=1e-15)
    assert np.all(result.stress[result.mechanical] >= 0) and np.all(result.stress[result.adhesive] <= 0)
    assert np.all(result.extension[result.adhesive] >= 0)
    dataset = result.to_xarray()
    assert dataset["lateral_force"].attrs["units"] == "N"
    assert dataset.attrs["mu"] == result.mu and dataset.attrs["reading_contact"] == "epsilon"
    assert set(result.scalars()) >= {"mu", "friction", "adhesive_friction", "mechanical_friction", "residual"}


def test_solve_winkler_lj_matches_the_model(pair):
    scan, tip = pair
    direct = solve_winkler_lj(
        scan,
        POLY,
        SIO2,
        normal_force=1e-5,
        options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.05),
        counter_topography=tip,
    )
    assert direct.mu == model(pair).solve(1e-5).mu


def test_sweep_matches_single_solves(pair):
    prepared = model(pair)
    loads = [1e-6, 1e-5, 1e-4]
    sweep = prepared.sweep(loads)
    np.testing.assert_array_equal(sweep.mu, [prepared.solve(load).mu for load in loads])
    assert np.all(np.diff(sweep.mechanical_friction) > 0)
    assert sweep.to_xarray()["mu"].dims == ("normal_force",)


def test_adhesive_cutoff_removes_far_springs(pair):
    full, cut = model(pair).solve(1e-5), model(pair, readings=Readings(adhesive_cutoff=10e-9)).solve(1e-5)
    assert cut.adhesive.sum() < full.adhesive.sum()
    assert np.all(cut.gap[cut.adhesive] <= 10e-9 * (1 + 1e-12))
    assert cut.adhesive_friction < full.adhesive_friction


def test_only_springs_bonded_within_the_dugdale_zone_add_adhesive_friction(pair):
    prepared = model(pair)
    result = prepared.solve(1e-5)
    assert prepared.adhesive_range == pytest.approx((1 + 9 * math.sqrt(3) / 16) * 2e-9, rel=1e-15)
    bond = result.gap - result.extension  # l_ia of eq. 14
    np.testing.assert_array_equal(result.bonded, result.adhesive & (bond <= prepared.adhesive_range))
    assert 0 < result.bonded.sum() < result.adhesive.sum()
    assert np.all(result.lateral_force[result.adhesive & ~result.bonded] == 0)
    assert np.all(result.lateral_force[result.bonded] > 0)
    assert result.adhesive_friction == pytest.approx(result.lateral_force[result.bonded].sum(), rel=1e-12)
    assert result.scalars()["bonded_springs"] == result.bonded.sum()
    assert prepared.sweep([1e-5]).bonded_springs[0] == result.bonded.sum()
    everywhere = model(pair, readings=Readings(adhesive_range="all_springs"))
    every = everywhere.solve(1e-5)
    assert everywhere.adhesive_range == math.inf
    np.testing.assert_array_equal(every.bonded, every.adhesive)
    assert every.separation == result.separation  # eq. 2 is the same under both ranges
    assert every.mechanical_friction == result.mechanical_friction
    assert every.adhesive_friction > result.adhesive_friction
    assert Readings.from_strings(["adhesive_range=all_springs"]) == Readings(adhesive_range="all_springs")
    assert PRINTED.adhesive_range == "all_springs"


def test_rigid_counter_needs_a_surface_energy(pair):
    scan, _ = pair
    with pytest.raises(InputError) as error:
        winkler_lj_model(
            scan, POLY, None, options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.05)
        )
    assert error.value.field == "counter_surface_energy"
    rigid = winkler_lj_model(
        scan, POLY, None, options=WinklerLJOptions(50e-9, surface_energy=0.05, counter_surface_energy=0.07)
    )
    assert rigid.contact_modulus == pytest.approx(110e9 / (1 - 0.22**2), rel=1e-14)


@pytest.mark.parametrize(
    "options, field",
    [
        ({"surface_energy": -0.05}, "surface_energy"),
        ({"surface_energy": 0.0}, "surface_energy"),
        ({"epsilon": 0.0}, "epsilon"),
        ({"epsilon": -2e-9}, "epsilon"),
        ({"layer_thickness": math.nan}, "layer_thickness"),
    ],
)
def test_bad_parameters_name_their_field(pair, options, field):
    with pytest.raises(InputError) as error:
        model(pair, **options)
    assert error.value.field == field


@pytest.mark.parametrize("load", [0.0, -1e-6, math.inf, math.nan])
def test_bad_loads_are_refused(pair, load):
    with pytest.raises(InputError) as error:
        model(pair).solve(load)
    assert error.value.field == "normal_force"


def test_different_pixel_sizes_refused_or_resampled(pair):
    scan, _ = pair
    coarse_tip = sphere_with_roughness((24, 24), scan.size, radius=1e-6, rms_height=0.3e-9, seed=1)
    with pytest.raises(InputError) as error:
        winkler_lj_model(
            scan,
            POLY,
            SIO2,
            options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.05),
            counter_topography=coarse_tip,
        )
    assert error.value.field == "counter_topography" and "resample=True" in error.value.fix
    resampled = winkler_lj_model(
        scan,
        POLY,
        SIO2,
        options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.05, resample=True),
        counter_topography=coarse_tip,
    )
    assert resampled.topography.spacing == pytest.approx(scan.spacing, rel=1e-12)
    assert np.isfinite(resampled.solve(1e-5).mu)


def test_a_surface_that_never_reaches_the_flat_is_refused(pair):
    """With the printed sign adhesion carries load; a tiny load then needs the flat metres away."""
    with pytest.raises(InputError, match="never reaches the flat") as error:
        model(pair, readings=Readings(adhesion_sign="printed")).solve(1e-20)
    assert error.value.field == "normal_force"


def test_profiles_are_refused():
    with pytest.raises(InputError, match="topography"):
        winkler_lj_model(
            Topography(np.zeros(8), 1e-6), POLY, SIO2, options=WinklerLJOptions(5e-8, surface_energy=0.05)
        )


def test_incompressible_pair_is_refused(pair):
    scan, _ = pair
    rubber = type(POLY)(1e6, 0.5, "rubber", surface_energy=0.03)
    with pytest.raises(InputError, match="poissons_ratio"):
        winkler_lj_model(scan, rubber, rubber, options=WinklerLJOptions(layer_thickness=5e-8))


def test_every_reading_gives_finite_totals(pair):
    for name, allowed in CHOICES.items():
        for value in allowed:
            result = model(pair, readings=Readings(**{name: value})).solve(1e-5)
            totals = [result.mu, result.friction, result.adhesive_friction, result.mechanical_friction]
            assert np.all(np.isfinite(totals)), (name, value)


def test_eq16_signed_counts_springs_with_negative_energy(pair):
    result = model(pair, readings=Readings(mechanical_energy="eq16_signed")).solve(3e-4)
    assert result.negative_energy_springs > 0
    assert np.all(np.isfinite(result.lateral_force))
