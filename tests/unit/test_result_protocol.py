"""Every public result speaks one vocabulary (roughcontact.results): scalars, UNITS, to_xarray, and how a
solver ended. Built here on tiny problems; the physics of each is tested elsewhere."""

import json
import math

import numpy as np
import pytest

from roughcontact._json import json_ready
from roughcontact.materials import get_material
from roughcontact.results import SCALAR_NAME, Result, SolverResult, units_of
from roughcontact.units import unit_factor


def _normal():
    from roughcontact.contact import solve_normal
    from roughcontact.topography.generate import self_affine

    surface = self_affine((32, 32), 1e-6, hurst=0.8, rms_height=2e-9, seed=1)
    return solve_normal(surface, get_material("polysilicon"), mean_pressure=50e6)


def _ball():
    from roughcontact.topography.generate import sphere_with_roughness

    return sphere_with_roughness((32, 32), (32 * 2.148e-6,) * 2, radius=5e-3, rms_height=5e-8, seed=3)


def _tangential():
    from roughcontact.contact import solve_normal, solve_tangential
    from roughcontact.contact.paths import stroke_path

    normal = solve_normal(_ball(), get_material("POM"), force=2e-3)
    path = stroke_path(0.2e-6, cycles=1, steps_per_stroke=6)
    return solve_tangential(normal, get_material("POM"), friction_coefficient=0.1, displacement=path)


def _frictional():
    from roughcontact.contact import solve_frictional

    steps = np.linspace(0.2, 1.0, 4)
    return solve_frictional(
        _ball(),
        get_material("POM"),
        counter_body=get_material("silicon wafer"),
        friction_coefficient=0.1,
        normal_force=2e-3 * steps,
        displacement=0.05e-6 * steps,
    )


def _presliding():
    from roughcontact.contact.presliding import presliding

    return presliding(
        _ball(),
        get_material("POM"),
        get_material("silicon wafer"),
        normal_force=2e-3,
        friction_coefficient=0.1,
        stroke=0.3e-6,
        radius=5e-3,
        cycles=2,
        steps_per_stroke=10,
    )


def _load_unload():
    from roughcontact.contact import load_unload
    from roughcontact.topography.generate import self_affine

    surface = self_affine((32, 32), 1e-6, hurst=0.8, rms_height=5e-9, seed=2)
    return load_unload(surface, get_material("SU-8"), max_force=2e-7, steps=3)


def _volume_load_unload():
    from roughcontact.contact import VolumePlasticity, load_unload
    from roughcontact.topography.generate import sphere

    ball = sphere((16, 16), (1e-4, 1e-4), radius=1e-3, kind="paraboloid")
    steel = get_material("SU-8")
    return load_unload(
        ball, steel, max_force=2e-3, steps=2, plasticity=VolumePlasticity(depth=5e-5, layers=6)
    )


def _volume_island():
    from roughcontact.papers.paper002 import compress_island, paper002_island

    return compress_island(paper002_island(16, seed=1), get_material("SU-8"), plasticity="volume", layers=4)


def _island():
    from roughcontact.papers.paper002 import compress_island, paper002_island

    return compress_island(paper002_island(16, seed=1), get_material("SU-8"))


def _winkler():
    from roughcontact.topography.generate import self_affine
    from roughcontact.winkler_lj import WinklerLJOptions, solve_winkler_lj

    surface = self_affine((32, 32), 0.64e-6, hurst=0.8, rms_height=1.5e-9, seed=1)
    return solve_winkler_lj(
        surface,
        get_material("polysilicon"),
        get_material("SiO2"),
        normal_force=1e-6,
        options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.05),
    )


def _winkler_model():
    from roughcontact.topography.generate import self_affine
    from roughcontact.winkler_lj import WinklerLJOptions, winkler_lj_model

    surface = self_affine((32, 32), 0.64e-6, hurst=0.8, rms_height=1.5e-9, seed=1)
    return winkler_lj_model(
        surface,
        get_material("polysilicon"),
        get_material("SiO2"),
        options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.05),
    )


def _friction_sweep():
    return _winkler_model().sweep([1e-6, 3e-6, 1e-5])


def _winkler_normal_curve():
    return _winkler_model().normal_curve([-2e-9, 0.0, 1e-9])


def _volume_field():
    return _volume_load_unload().volume


def _statistical():
    from roughcontact.papers import paper002

    return paper002.statistical_curve()


def _asperity_parameters():
    from roughcontact.papers import paper002

    return paper002.parameters()


def _indentation():
    from roughcontact.experiment.nanoindentation import oliver_pharr, synthetic_indentation_curve

    return oliver_pharr(synthetic_indentation_curve(1e9, creep_rate=1e-9))


def _loop():
    from roughcontact.analytic.mindlin import masing_force
    from roughcontact.experiment.friction_loop import analyse_loop

    path = np.concatenate([np.linspace(0, 2e-6, 80), np.linspace(2e-6, 0, 80)[1:]] * 2)
    force = masing_force(path, 0.15, 0.025, 6e-5, 1e8)
    return analyse_loop(path, force, 0.025)


def _adhesive():
    from roughcontact.contact.adhesive import solve_adhesive
    from roughcontact.contact.interaction import Exponential
    from roughcontact.topography.generate import sphere

    ball = sphere((16, 16), (1.2, 1.2), radius=1.0, kind="paraboloid")
    return solve_adhesive(ball, 1.0, Exponential(1e-3, 0.02), approach=[0.01, -0.02])


def _winkler_beside_bem():
    from dataclasses import replace

    from roughcontact.papers.paper000 import LAYER, winkler_beside_bem
    from roughcontact.topography import Topography

    x = (np.arange(16) - 8) * 10e-9
    heights = -(x[:, None] ** 2 + x[None, :] ** 2) / 2e-6
    surface = Topography(heights, 160e-9, periodic=False)
    return winkler_beside_bem(
        surface,
        get_material("polysilicon"),
        get_material("SiO2"),
        approach=[0.0, -1e-9],
        options=replace(LAYER, surface_energy=0.05, counter_surface_energy=0.072),
    )


def _theories():
    from roughcontact.theory import compare_theories
    from roughcontact.topography.generate import self_affine

    surface = self_affine((32, 32), 1e-6, hurst=0.8, rms_slope=0.1, seed=1)
    return compare_theories(surface, 1e9, reduced_pressures=[0.02, 0.2])


BUILDERS = {
    "normal contact": _normal,
    "tangential path": _tangential,
    "frictional programme": _frictional,
    "pre-sliding (paper 001)": _presliding,
    "load-unload": _load_unload,
    "island compression (paper 002)": _island,
    "volume load-unload": _volume_load_unload,
    "island in the volume (paper 002)": _volume_island,
    "Winkler-Lennard-Jones": _winkler,
    "friction sweep (paper 000)": _friction_sweep,
    "Winkler springs' normal curve (paper 000)": _winkler_normal_curve,
    "plastic volume": _volume_field,
    "statistical load-unload": _statistical,
    "asperity parameters": _asperity_parameters,
    "indentation": _indentation,
    "loop analysis": _loop,
    "adhesive contact": _adhesive,
    "Winkler beside the adhesive BEM (paper 000)": _winkler_beside_bem,
    "theories beside the BEM": _theories,
}
SOLVED = {
    "Winkler-Lennard-Jones",
    "normal contact",
    "tangential path",
    "pre-sliding (paper 001)",
    "load-unload",
    "island compression (paper 002)",
    "volume load-unload",
    "island in the volume (paper 002)",
    "adhesive contact",
    "theories beside the BEM",
}


@pytest.fixture(scope="module", params=list(BUILDERS))
def named_result(request):
    return request.param, BUILDERS[request.param]()


def test_scalars_have_plain_names_and_json_values(named_result):
    name, result = named_result
    assert isinstance(result, Result), name
    scalars = result.scalars()
    assert scalars, name
    bad = [key for key in scalars if not SCALAR_NAME.match(key)]
    assert not bad, f"{name}: names with units or spaces: {bad}"
    json.dumps(json_ready(scalars))  # JSON-ready as they are


def test_units_are_readable_si_units(named_result):
    name, result = named_result
    for key, unit in units_of(result).items():
        assert SCALAR_NAME.match(key), (name, key)
        if unit:
            factor, _ = unit_factor(unit)
            assert float(factor) == 1.0, f"{name}: {key} in {unit!r} is not an SI unit"


def test_dimensional_scalars_are_in_units(named_result):
    """A float scalar that is not a count, ratio, exponent or label has its unit in UNITS."""
    name, result = named_result
    units = units_of(result)
    dimensionless = (
        "mu",
        "fraction",
        "share",
        "ratio",
        "coefficient",
        "factor",
        "index",
        "exponent",
        "_n",
        "over_",
    )
    dimensionless += ("m2", "bandwidth", "residual", "iterations", "epsilon", "beta", "poissons_ratio")
    dimensionless += (
        "range_",
        "direction",
        "steps",
        "loops",
        "patches",
        "points",
        "springs",
        "strain",
        "alpha",
        "pixels",
    )
    exact = {"n"}  # eq. 9 exponent
    fitted = {
        "fit_alpha",
        "creep_fit_a",
    }  # units with fitted powers (N/m^m, m/s^(1/3)): documented, not in UNITS
    for key, value in result.scalars().items():
        if isinstance(value, bool) or not isinstance(value, float | np.floating):
            continue
        if any(word in key for word in dimensionless) or key in units or key in exact | fitted:
            continue
        pytest.fail(f"{name}: scalar {key!r} = {value!r} has no unit in UNITS and looks dimensional")


def test_to_xarray_gives_units(named_result):
    import xarray as xr

    name, result = named_result
    data = result.to_xarray()
    assert isinstance(data, xr.Dataset), name
    for variable in data.data_vars.values():
        if variable.dtype.kind in "fc":
            assert "units" in variable.attrs, f"{name}: {variable.name} has no units"


def test_solvers_say_how_they_ended(named_result):
    name, result = named_result
    if name not in SOLVED:
        return
    assert isinstance(result, SolverResult), name
    assert result.converged is True
    assert int(np.sum(result.iterations)) >= 0
    assert math.isfinite(float(np.max(result.residual)))


def _result_classes() -> set[type]:
    """Every public class of the package with ``scalars`` and ``to_xarray``: a result, found by itself."""
    import importlib
    import importlib.util
    import inspect
    import pkgutil
    from pathlib import Path

    import roughcontact

    found = set()
    for module in pkgutil.walk_packages(roughcontact.__path__, "roughcontact."):
        parts = module.name.split(".")
        if any(p.startswith("_") for p in parts[1:]) or parts[1] in ("cli", "study", "plotting"):
            continue  # private modules and the edges
        if "moved_module(" in Path(importlib.util.find_spec(module.name).origin).read_text():
            continue  # a kept old place of a moved module
        loaded = importlib.import_module(module.name)
        for name, cls in inspect.getmembers(loaded, inspect.isclass):
            if (
                cls.__module__ == module.name
                and not name.startswith("_")
                and cls.__name__ not in ("Result", "SolverResult")
            ):
                if callable(getattr(cls, "to_xarray", None)) and callable(getattr(cls, "scalars", None)):
                    found.add(cls)
    return found


def test_every_result_class_is_built_and_checked_here():
    """A new result class is found without being listed: it must get a builder above."""
    built = {type(build()) for build in BUILDERS.values()}
    missing = sorted(cls.__qualname__ for cls in _result_classes() - built)
    assert not missing, f"result classes no test builds: {missing}"
