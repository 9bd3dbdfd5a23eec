import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from roughcontact.errors import InputError, UnitError
from roughcontact.units import format_si, length_unit_factor, prefixed_scale, quantity


@pytest.mark.parametrize(
    ("text", "dimension", "expected"),
    [
        ("20 nm", "length", 20e-9),
        ("1.1 mm", "length", 1.1e-3),
        ("70 GPa", "pressure", 70e9),
        ("72 mJ/m^2", "surface_energy", 0.072),
        ("72 mJ/m**2", "surface_energy", 0.072),
        ("72 mN/m", "surface_energy", 0.072),
        ("10 uN", "force", 10e-6),
        ("10 µN", "force", 10e-6),  # micro sign U+00B5
        ("10 μN", "force", 10e-6),  # Greek mu U+03BC
        ("3 µm", "length", 3e-6),
        ("0.1 um/s", "velocity", 0.1e-6),
        ("5 s", "time", 5.0),
        ("50 uN/s", "force_rate", 50e-6),
        ("1e3 nm", "length", 1e-6),
        ("-2.5 nm", "length", -2.5e-9),
        ("35.5 N/m", "stiffness", 35.5),
        ("1 1/um", "inverse_length", 1e6),
        ("0.462 GPa", "pressure", 0.462e9),
        ("5 Å", "length", 5e-10),
        ("2 min", "time", 120.0),
    ],
)
def test_parses_to_si_exactly(text, dimension, expected):
    # Exact decimal prefix arithmetic: the result is the float nearest the true value.
    assert quantity(text, dimension) == expected


def test_bare_numbers_are_si():
    assert quantity(3.0, "length") == 3.0
    assert quantity("3", "length") == 3.0


@pytest.mark.parametrize(
    ("text", "dimension", "fragment"),
    [
        ("20 nN", "length", "is a force, expected a length"),
        ("70 GPa", "force", "is a pressure, expected a force"),
        ("3 furlong", "length", "unknown unit symbol 'furlong'"),
        ("abc", "length", "cannot read 'abc'"),
        ("", "pressure", "cannot read"),
        ("nan nm", "length", "cannot read"),
        ("1e999 nm", "length", "not finite"),
    ],
)
def test_rejections_name_value_and_expectation(text, dimension, fragment):
    with pytest.raises(UnitError) as info:
        quantity(text, dimension, field="youngs_modulus")
    message = str(info.value)
    assert fragment in message
    assert message.startswith("youngs_modulus:")
    assert "Fix:" in message
    assert isinstance(info.value, InputError)  # one except clause catches every input problem


def test_unknown_dimension_is_a_programming_error():
    with pytest.raises(ValueError, match="unknown dimension"):
        quantity("1 m", "lenght")


def test_rejects_non_numbers():
    with pytest.raises(UnitError, match="expected a number"):
        quantity(None, "length")
    with pytest.raises(UnitError):
        quantity(True, "length")


def test_length_unit_factor():
    assert length_unit_factor("µm") == 1e-6
    assert length_unit_factor("nm") == 1e-9
    with pytest.raises(UnitError, match="not a length unit"):
        length_unit_factor("GPa")


def test_format_si():
    assert format_si(2.5e-8, "m") == "25 nm"
    assert format_si(70e9, "Pa") == "70 GPa"
    assert format_si(1e-6, "m") == "1 µm"
    assert format_si(0.0, "m") == "0 m"
    assert format_si(3e-12, "m^2") == "3 µm²"  # the prefix applies to the metre, squared
    assert format_si(4e4, "N/m") == "40 kN/m"


@pytest.mark.parametrize(
    ("value", "unit", "scale", "label", "dimension"),
    [
        (2.5e-8, "m", 1e-9, "nm", "length"),
        (1e-6, "m", 1e-6, "µm", "length"),
        (0.999999999999999e-6, "m", 1e-6, "µm", "length"),  # within 1e-12 of a prefix: that prefix
        (2.0, "m", 1.0, "m", "length"),
        (70e9, "Pa", 1e9, "GPa", "pressure"),
        (3.5e5, "Pa", 1e3, "kPa", "pressure"),
        (3.8e-3, "N", 1e-3, "mN", "force"),
        (-5e-6, "N", 1e-6, "µN", "force"),  # the magnitude decides
        (3e-12, "m^2", 1e-12, "µm²", "area"),
        (1e-9, "m**2", 1e-12, "µm²", "area"),  # a square reads between 1 and 1e6
        (2e-17, "m^3", 1e-18, "µm³", None),  # no named dimension for volumes
        (4e4, "N/m", 1e3, "kN/m", "stiffness"),
        (0.072, "J/m^2", 1e-3, "mJ/m²", "surface_energy"),
        (2e-9, "J", 1e-9, "nJ", "energy"),
        (3e-6, "m/s", 1e-6, "µm/s", "velocity"),
        (2e6, "1/m", 1e6, "1/µm", "inverse_length"),
        (2e6, "m^-1", 1e6, "1/µm", "inverse_length"),
        (3e-3, "N*m", 1e-3, "mN·m", "energy"),
        (1e-20, "m", 1e-12, "pm", "length"),  # below the smallest prefix: the smallest
        (1e20, "Pa", 1e9, "GPa", "pressure"),  # above the largest: the largest
    ],
)
def test_prefixed_scale(value, unit, scale, label, dimension):
    assert prefixed_scale(value, unit) == (scale, label)
    if dimension is not None:  # the label is a unit the parser reads, worth exactly the scale
        assert quantity(f"1 {label}", dimension) == scale


@settings(max_examples=300, deadline=None)
@given(
    st.floats(min_value=1e-12, max_value=1e12, exclude_max=True, allow_nan=False),
    st.sampled_from(["m", "N", "Pa", "J", "N/m", "m/s"]),
)
def test_prefixed_scale_reads_between_1_and_1000(value, unit):
    scale, label = prefixed_scale(value, unit)
    assert 1 - 1e-12 <= value / scale < 1000
    assert label.endswith(unit) and len(label) - len(unit) in (0, 1)  # one prefix letter, or none


@pytest.mark.parametrize(
    ("value", "unit", "label"),
    [
        (0.0, "m", "m"),
        (math.nan, "Pa", "Pa"),
        (math.inf, "N", "N"),
        (0.0, "m^2", "m²"),
        (5.0, "", ""),
        (50, "%", "%"),
    ],
)
def test_prefixed_scale_without_prefix(value, unit, label):
    assert prefixed_scale(value, unit) == (1.0, label)


def test_prefixed_scale_refuses_prefixed_and_unknown_units():
    with pytest.raises(UnitError, match="prefixed symbol 'nm'"):
        prefixed_scale(1e-9, "nm")
    with pytest.raises(UnitError, match="prefixed symbol 'kN'"):
        prefixed_scale(1.0, "kN/m")
    with pytest.raises(UnitError, match="unknown unit symbol"):
        prefixed_scale(1.0, "furlong")
    assert prefixed_scale(3.0, "kg") == (1.0, "kg")  # the SI unit of mass takes no further prefix


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=1e-6, max_value=1e6, allow_nan=False), st.sampled_from(["nm", "um", "mm", "m"]))
def test_prefix_round_trip(value, unit):
    # value in unit -> SI -> back: exact to one rounding of float64 (relative 1e-15).
    si = quantity(f"{value!r} {unit}", "length")
    assert math.isclose(si / length_unit_factor(unit), value, rel_tol=1e-15)
