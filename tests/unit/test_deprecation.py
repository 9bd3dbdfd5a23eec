"""Release 0.1's names and spellings keep working one release, each with a DeprecationWarning."""

import pytest

from roughcontact.materials import get_material
from roughcontact.papers.paper001 import paper001_mindlin


def test_an_old_keyword_warns_and_gives_the_same_answer():
    new = paper001_mindlin(
        friction_coefficient=0.153, normal_force=0.025, radius=5e-3, material=get_material("HDPE")
    )
    with pytest.warns(DeprecationWarning, match=r"\(mu=\.\.\.\) is now spelled friction_coefficient"):
        old = paper001_mindlin(mu=0.153, normal_force=0.025, radius=5e-3, material=get_material("HDPE"))
    assert old == new


def test_old_and_new_spelling_together_is_an_error():
    with pytest.raises(TypeError, match="both 'counter' and its new name 'counter_body'"):
        paper001_mindlin(
            friction_coefficient=0.153,
            normal_force=0.025,
            radius=5e-3,
            material=get_material("HDPE"),
            counter=None,
            counter_body=None,
        )


@pytest.mark.parametrize(
    ("old", "name", "new"),
    [
        ("roughcontact.analytic.mindlin", "paper001_mindlin", "roughcontact.papers.paper001"),
        ("roughcontact.experiment", "paper000_simulation", "roughcontact.papers.paper000"),
        ("roughcontact.papers.paper001", "presliding", "roughcontact.contact.presliding"),
        ("roughcontact.experiment.compare", "simulate_mu", "roughcontact.papers.paper000"),
        ("roughcontact.plotting.cases", "realisations_of", "roughcontact.cases"),  # study logic, no drawing
        ("roughcontact.plotting.cases", "at_load", "roughcontact.cases"),
    ],
)
def test_a_moved_name_is_found_at_its_old_place_with_a_warning(old, name, new):
    from importlib import import_module

    with pytest.warns(DeprecationWarning, match=f"has moved to {new}.{name}"):
        found = getattr(import_module(old), name)
    assert found is getattr(import_module(new), name)
    with pytest.raises(AttributeError):
        _ = import_module(old).no_such_name


@pytest.mark.parametrize(
    ("old", "new"),
    [
        ("roughcontact.models.paper001", "roughcontact.papers.paper001"),
        ("roughcontact.models.thin_film_island", "roughcontact.papers.paper002"),
        ("roughcontact.papers.thin_film_island", "roughcontact.papers.paper002"),
        ("roughcontact.contact.plastic", "roughcontact.contact.load_unload"),
        ("roughcontact.friction.lennard_jones", "roughcontact.contact.lennard_jones"),
        ("roughcontact.friction.winkler_lj", "roughcontact.winkler_lj"),
        ("roughcontact.friction.readings", "roughcontact.winkler_lj.readings"),
    ],
)
def test_a_moved_module_is_found_at_its_old_place_with_a_warning(old, new):
    import sys
    from importlib import import_module

    sys.modules.pop(old, None)
    with pytest.warns(DeprecationWarning, match=f"{old} has moved to {new}"):
        found = import_module(old)
    assert found is import_module(new)


def test_a_name_of_the_old_friction_package_is_found_with_a_warning():
    import roughcontact.friction as old
    from roughcontact.winkler_lj import winkler_lj_model

    with pytest.warns(DeprecationWarning, match="roughcontact.winkler_lj.winkler_lj_model"):
        assert old.winkler_lj_model is winkler_lj_model


def test_load_unload_takes_release_0_1_keywords_with_a_warning():
    from roughcontact.contact.load_unload import SurfacePlasticity, load_unload
    from roughcontact.topography.generate import sphere

    ball = sphere((16, 16), (4e-6, 4e-6), radius=1e-5, kind="paraboloid")
    material = get_material("SU-8")
    new = load_unload(ball, material, max_force=1e-5, steps=3, plasticity=SurfacePlasticity(2e8))
    with pytest.warns(
        DeprecationWarning, match=r"load_unload\(hardness=\.\.\.\) is now given as plasticity="
    ):
        old = load_unload(ball, material, max_force=1e-5, steps=3, hardness=2e8)
    assert old.scalars() == new.scalars()


def test_the_tangential_solvers_old_keywords_fold_into_one_options_object():
    """solve_tangential(tolerance=..., method=...) of release 0.1 is solver=ShearSolver(...) now."""
    import numpy as np

    from roughcontact.contact import ShearSolver, solve_normal, solve_tangential
    from roughcontact.topography.generate import sphere

    material = get_material("POM")
    ball = sphere((24, 24), 0.3e-3, radius=5e-3)
    normal = solve_normal(ball, material, force=0.025)
    common = dict(friction_coefficient=0.1, force=[0.001, 0.002])
    new = solve_tangential(normal, material, **common, solver=ShearSolver(tolerance=1e-9, method="cg"))
    with pytest.warns(DeprecationWarning, match=r"is now given as solver=\.\.\."):
        old = solve_tangential(normal, material, **common, tolerance=1e-9, method="cg")
    assert np.array_equal(old.displacement, new.displacement)
    assert old.parameters["method"] == "cg" and old.parameters["tolerance"] == 1e-9


def test_the_winkler_models_old_keywords_fold_into_one_options_object():
    """winkler_lj_model(layer_thickness=..., ...) of release 0.1 is options=WinklerLJOptions(...) now."""
    from roughcontact.papers import paper000
    from roughcontact.topography.generate import self_affine
    from roughcontact.winkler_lj import WinklerLJOptions, solve_winkler_lj, winkler_lj_model

    scan = self_affine((24, 24), 0.48e-6, hurst=0.8, rms_height=1.5e-9, seed=1)
    bodies = (scan, get_material("polysilicon"), get_material("SiO2"))
    new = winkler_lj_model(*bodies, options=WinklerLJOptions(50e-9, surface_energy=0.05, resample=True))
    with pytest.warns(DeprecationWarning, match=r"is now given as options=\.\.\.") as caught:
        old = winkler_lj_model(*bodies, layer_thickness=50e-9, surface_energy=0.05, resample=True)
    assert caught[0].filename == __file__  # the user's line, through both of its decorators
    assert old.solve(1e-6).mu == new.solve(1e-6).mu
    with pytest.warns(
        DeprecationWarning, match=r"solve_winkler_lj\(layer_thickness=\.\.\., surface_energy=\.\.\.\) is now"
    ):
        one = solve_winkler_lj(*bodies, normal_force=1e-6, layer_thickness=50e-9, surface_energy=0.05)
    assert one.mu == new.solve(1e-6).mu
    with pytest.warns(DeprecationWarning, match=r"paper000_options\(\)"):
        keywords = paper000.paper000_model_options()
    assert WinklerLJOptions(**keywords) == paper000.paper000_options()
    scans = {"a": [scan]}
    with pytest.warns(DeprecationWarning, match=r"simulate_mu\(model_options=\.\.\.\)"):
        folded = paper000.simulate_mu(scans, *bodies[1:], normal_force=1e-6, model_options=keywords)
    direct = paper000.simulate_mu(scans, *bodies[1:], normal_force=1e-6, options=paper000.paper000_options())
    assert folded["a"].tolist() == direct["a"].tolist()


@pytest.mark.parametrize(
    ("function", "old", "new"),
    [
        ("roughcontact.analytic.mindlin:sliding_displacement", "mu", "friction_coefficient"),
        ("roughcontact.contact.load_unload:force_targets", "peak_force", "max_force"),
    ],
)
def test_respelled_keywords_keep_working(function, old, new):
    from importlib import import_module

    module, name = function.split(":")
    target = getattr(import_module(module), name)
    arguments = {
        "sliding_displacement": {new: 0.1, "normal_force": 1.0, "contact_radius": 1e-4, "shear_modulus": 1e9},
        "force_targets": {new: 1e-3, "steps": 4},
    }[name]
    expected = target(**arguments)
    arguments[old] = arguments.pop(new)
    with pytest.warns(DeprecationWarning, match=rf"\({old}=\.\.\.\) is now spelled {new}"):
        assert target(**arguments) == pytest.approx(expected)
