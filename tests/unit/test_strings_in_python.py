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
