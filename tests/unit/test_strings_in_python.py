"""Python functions take SI numbers; a string with units is refused with the fix (issue 15).

The commands and study files read ``"20 MPa"``; in Python, ``solve_normal(..., mean_pressure="20 MPa")``
used to end in NumPy's ``TypeError``. Each refusal names the argument and shows
``quantity('...')`` with the value as typed.
"""

import numpy as np
import pytest

import roughcontact as rc
from roughcontact.errors import InputError
from roughcontact.materials import Material, get_material
from roughcontact.topography.generate import self_affine

SURFACE = self_affine((16, 16), 1e-6, hurst=0.8, rms_height=1e-9, seed=1)
POLYSILICON = get_material("polysilicon")

CALLS = {
    "mean_pressure": lambda: rc.solve_normal(SURFACE, POLYSILICON, mean_pressure="20 MPa"),
    "force": lambda: rc.solve_normal(SURFACE, POLYSILICON, force="10 uN"),
    "approach": lambda: rc.solve_normal(SURFACE, POLYSILICON, approach="2 nm"),
    "hardness": lambda: rc.solve_normal(SURFACE, POLYSILICON, mean_pressure=1e6, hardness="1 GPa"),
    "size": lambda: rc.Topography(np.zeros((4, 4)), "5 um"),
    "size ": lambda: self_affine((16, 16), ("1 um", 1e-6), hurst=0.8, rms_height=1e-9, seed=1),
    "rms_height": lambda: self_affine((16, 16), 1e-6, hurst=0.8, rms_height="1 nm", seed=1),
    "youngs_modulus": lambda: Material(youngs_modulus="70 GPa", poissons_ratio=0.3),
}


@pytest.mark.parametrize("field", list(CALLS))
def test_a_string_is_refused_with_quantity_as_the_fix(field):
    with pytest.raises(InputError) as caught:
        CALLS[field]()
    assert caught.value.field == field.strip()
    assert "quantity('" in caught.value.fix and "SI" in caught.value.problem


def test_a_material_name_points_to_get_material():
    with pytest.raises(InputError, match=r"get_material\('polysilicon'\)"):
        rc.solve_normal(SURFACE, "polysilicon", mean_pressure=1e6)


def test_quantity_gives_what_the_string_meant():
    by_string = rc.solve_normal(SURFACE, POLYSILICON, mean_pressure=rc.quantity("20 MPa", "pressure"))
    assert by_string.mean_pressure == pytest.approx(20e6, rel=1e-9)


# --- the advice works when pasted (issue 32) ---------------------------------------------------------


def _pasted(fix: str, field: str):
    """Evaluate the ``field=...`` expression of a fix as a Python user would paste it."""
    import re

    expression = re.search(rf"\b{field}=((?:quantity|get_material)\('[^']*'(?:, '[^']*')?\))", fix).group(1)
    return eval(expression, {"quantity": rc.quantity, "get_material": rc.get_material})  # noqa: S307


@pytest.mark.parametrize(
    ("keywords", "field"),
    [
        ({"mean_pressure": "20 MPa"}, "mean_pressure"),
        ({"force": "10 nN"}, "force"),
        ({"approach": "0.5 nm"}, "approach"),
        ({"mean_pressure": 2e6, "hardness": "1 GPa"}, "hardness"),
        ({"material": "polysilicon", "mean_pressure": 2e6}, "material"),
        ({"material": "160 GPa", "mean_pressure": 2e6}, "material"),
        ({"counter_body": "SiO2", "mean_pressure": 2e6}, "counter_body"),
    ],
)
def test_the_advice_works_when_pasted(keywords, field):
    arguments = {"material": POLYSILICON} | keywords
    with pytest.raises(InputError) as caught:
        rc.solve_normal(SURFACE, **arguments)
    assert caught.value.field == field  # the parameter as the user named it, never an internal one
    arguments[field] = _pasted(caught.value.fix, field)
    assert rc.solve_normal(SURFACE, **arguments).converged


def test_quantity_needs_no_dimension_but_checks_one_when_given():
    assert rc.quantity("20 MPa") == 2e7 and rc.quantity("72 mJ/m^2") == pytest.approx(0.072)
    with pytest.raises(rc.UnitError, match="expected a length"):
        rc.quantity("20 MPa", "length")


def test_a_misspelt_material_gets_the_nearest_name():
    with pytest.raises(InputError) as caught:
        rc.solve_normal(SURFACE, "polysilicone", mean_pressure=1e6)
    assert "get_material('polysilicon')" in caught.value.fix
