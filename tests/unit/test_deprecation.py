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
