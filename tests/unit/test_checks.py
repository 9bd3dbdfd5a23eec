"""Unit tests of roughcontact.checks: the shared argument checkers and their messages."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest

from roughcontact.checks import finite_array, positive
from roughcontact.errors import InputError

# --- positive ------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "value", [5e-3, 3, np.float64(2.5), np.float32(0.5), np.int64(7), np.array(1.5), Fraction(1, 4)]
)
def test_positive_accepts_real_numbers_and_returns_a_float(value):
    result = positive(value, "radius")
    assert type(result) is float
    assert result == float(value)


@pytest.mark.parametrize("value", [True, False, np.bool_(True)])
def test_positive_refuses_bools(value):
    with pytest.raises(InputError) as info:
        positive(value, "radius", example="5e-3", unit="m")
    assert info.value.field == "radius"
    assert "bool" in info.value.problem


@pytest.mark.parametrize("value", [None, [1.0], np.array([1.0, 2.0]), 1j])
def test_positive_refuses_non_numbers(value):
    with pytest.raises(InputError) as info:
        positive(value, "youngs_modulus", example="70e9", unit="Pa")
    assert info.value.field == "youngs_modulus"
    assert "must be a real number" in info.value.problem
    assert "e.g. 70e9 Pa" in info.value.fix


@pytest.mark.parametrize("value", ["5e-3", "70 GPa"])
def test_a_string_is_told_to_convert(value):
    with pytest.raises(InputError) as info:
        positive(value, "youngs_modulus", example="70e9", unit="Pa")
    assert info.value.field == "youngs_modulus"
    assert repr(value) in info.value.problem and "SI units" in info.value.problem
    assert f"youngs_modulus=quantity({value!r})" in info.value.fix


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf, np.float64("nan")])
@pytest.mark.parametrize("allow_zero", [False, True])
def test_positive_refuses_nan_and_infinities(value, allow_zero):
    with pytest.raises(InputError) as info:
        positive(value, "epsilon", example="2e-9", unit="m", allow_zero=allow_zero)
    assert info.value.field == "epsilon"
    assert repr(float(value)) in info.value.problem
    assert "finite" in info.value.problem


@pytest.mark.parametrize("value", [0, 0.0, -0.0, -1e-9, -5])
def test_positive_refuses_zero_and_negative(value):
    with pytest.raises(InputError) as info:
        positive(value, "layer_thickness", example="50e-9", unit="m")
    assert info.value.field == "layer_thickness"
    assert info.value.problem == f"must be positive and finite, got {float(value)!r} m."
    assert info.value.fix == "give a positive number in m, e.g. 50e-9 m."


def test_allow_zero_accepts_zero_and_refuses_negative():
    assert positive(0.0, "hold_time", allow_zero=True) == 0.0
    assert positive(0, "hold_time", allow_zero=True) == 0.0
    with pytest.raises(InputError) as info:
        positive(-1.0, "hold_time", example="30", unit="s", allow_zero=True)
    assert info.value.field == "hold_time"
    assert info.value.problem == "must be non-negative and finite, got -1.0 s."
    assert info.value.fix == "give a non-negative number in s, e.g. 30 s."


def test_message_names_field_value_and_fix():
    with pytest.raises(InputError) as info:
        positive(-2.0, "radius", example="5e-3", unit="m")
    assert str(info.value) == (
        "radius: must be positive and finite, got -2.0 m. Fix: give a positive number in m, e.g. 5e-3 m."
    )


@pytest.mark.parametrize(
    ("example", "unit", "fix"),
    [
        (None, "", "give a positive number."),
        (None, "Pa", "give a positive number in Pa."),
        ("0.15", "", "give a positive number, e.g. 0.15."),
        (2.5, "N", "give a positive number in N, e.g. 2.5 N."),
    ],
)
def test_fix_without_example_or_unit(example, unit, fix):
    with pytest.raises(InputError) as info:
        positive(0.0, "x", example=example, unit=unit)
    assert info.value.fix == fix


# --- finite_array --------------------------------------------------------------------------------


def test_finite_array_returns_float_arrays():
    result = finite_array([0, 1, 2], "displacement")
    assert result.dtype == float and result.tolist() == [0.0, 1.0, 2.0]
    scalar = finite_array(3, "force")
    assert scalar.shape == () and scalar.dtype == float
    assert finite_array(np.zeros((2, 3)), "heights").shape == (2, 3)
    assert finite_array([], "path").size == 0


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_finite_array_refuses_nan_and_infinities(bad):
    with pytest.raises(InputError) as info:
        finite_array([0.0, bad, 1.0, 2.0], "displacement_path")
    assert info.value.field == "displacement_path"
    assert info.value.problem == "1 of 4 values are NaN or infinite."
    assert info.value.fix == "remove or interpolate the missing samples."


def test_finite_array_counts_every_bad_value():
    with pytest.raises(InputError) as info:
        finite_array(np.array([[np.nan, 1.0], [np.inf, np.nan]]), "force")
    assert "3 of 4" in info.value.problem


@pytest.mark.parametrize("values", [["a", "b"], "text", [[1.0, 2.0], [3.0]], {"x": 1}])
def test_finite_array_refuses_non_numbers(values):
    with pytest.raises(InputError) as info:
        finite_array(values, "force")
    assert info.value.field == "force"
    assert info.value.fix
