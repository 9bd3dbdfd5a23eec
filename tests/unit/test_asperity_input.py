"""Bad input to the asperity models: clear errors naming the field and the fix."""

import numpy as np
import pytest

from roughcontact.asperity import (
    contact_pressure_factor,
    critical_interference,
    gaussian_summits,
    gw_integral,
    kogut_etsion_area,
    kogut_etsion_load,
    paper002_eq10_load,
    residual_interference_ratio,
    statistical_load_unload,
    unloading_load,
)
from roughcontact.asperity.parameters import asperity_parameters
from roughcontact.errors import InputError
from roughcontact.materials import get_material
from roughcontact.papers import paper002
from roughcontact.topography.statistics import mccool_parameters

SCALES = dict(hardness=0.462e9, contact_modulus=8e9, radius=5e-6)


@pytest.mark.parametrize("nu", [-1.0, 0.5000001, 0.7, float("nan")])
def test_poissons_ratio_outside_the_physical_range_is_refused(nu):
    with pytest.raises(InputError, match="poissons_ratio") as error:
        critical_interference(**SCALES, poissons_ratio=nu)
    assert "(-1, 0.5]" in str(error.value)
    with pytest.raises(InputError, match="poissons_ratio"):
        contact_pressure_factor(nu)


def test_incompressible_limit_is_accepted():
    assert contact_pressure_factor(0.5) == pytest.approx(0.659, rel=1e-12, abs=0)


@pytest.mark.parametrize("field", ["hardness", "contact_modulus", "radius"])
def test_non_positive_scales_are_refused(field):
    with pytest.raises(InputError, match=field):
        critical_interference(**dict(SCALES, **{field: 0.0}), poissons_ratio=0.3)


def test_bandwidth_below_0_8968_is_refused_naming_the_moments():
    # alpha = m0 m4 / m2^2 = 0.5 < 0.8968: sigma_s would be imaginary
    with pytest.raises(InputError, match="m2") as error:
        asperity_parameters(m0=1e-16, m2=1e-2, m4=0.5e12, sample=get_material("SU-8"))
    assert "0.8968" in str(error.value)


@pytest.mark.parametrize("law", [kogut_etsion_load, kogut_etsion_area, residual_interference_ratio])
def test_interference_outside_the_fit_range_is_refused_with_the_range(law):
    with pytest.raises(InputError, match="0 <= omega\\* <= 110"):
        law(110.5)
    with pytest.raises(InputError, match="outside"):
        law(np.array([1.0, -0.1]))


def test_paper002_eq10_unknown_reading_and_range():
    with pytest.raises(InputError, match="reading"):
        paper002_eq10_load(2.0, critical_load=1e-5, reading="typo")
    with pytest.raises(InputError, match="110"):
        paper002_eq10_load(200.0, critical_load=1e-5)


def test_unloading_beyond_the_maximum_is_refused():
    with pytest.raises(InputError, match="interference"):
        unloading_load(2e-8, max_interference=1e-8, max_force=1e-5, critical_interference=5e-9)


def test_gw_integral_negative_order():
    with pytest.raises(InputError, match="order"):
        gw_integral(-1, 0.0)


def test_statistical_model_refuses_loads_beyond_the_fits():
    summits = gaussian_summits(mccool_parameters(**paper002.MOMENTS))
    run = dict(contact_modulus=7.97e9, hardness=0.462e9, poissons_ratio=0.22, nominal_area=625e-12)
    with pytest.raises(InputError, match="max_force") as error:
        statistical_load_unload(summits, **run, max_force=10.0)
    assert "110" in str(error.value)
    with pytest.raises(InputError, match="law"):
        statistical_load_unload(summits, **run, max_force=1e-3, law="greenwood")
    with pytest.raises(InputError, match="yield_strength"):
        statistical_load_unload(summits, **run, max_force=1e-3, law="jackson_green")
    with pytest.raises(InputError, match="reference_force"):
        statistical_load_unload(summits, **run, max_force=1e-3, reference_force=2e-3)


def test_summits_of_names_the_distribution_it_cannot_build():
    from roughcontact.asperity.greenwood_williamson import summits_of

    mccool = mccool_parameters(**paper002.MOMENTS)
    assert summits_of(mccool, "gaussian").kind == "gaussian"
    with pytest.raises(InputError, match="'measured' needs a topography"):
        summits_of(mccool, "measured")
    with pytest.raises(InputError, match="unknown distribution 'normal'"):
        summits_of(mccool, "normal")


def test_the_peak_is_the_last_loading_point():
    curve = paper002.statistical_curve()
    assert curve.peak == int(np.sum(curve.branch == "loading")) - 1
    assert curve.force[curve.peak] == pytest.approx(paper002.PEAK_FORCE, rel=1e-6)
