import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from roughcontact.errors import InputError, UnitError
from roughcontact.units import (
    MISSING,
    common_scale,
    format_si,
    length_unit_factor,
    prefixed_scale,
    quantity,
)


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
    assert format_si(4e4, "N/m") == "40 mN/µm"  # paper 001's unit of K_L, equal to kN/m


_SI_LABEL = {"m": "m", "Pa": "Pa", "J": "J", "N/m": "N/m"}


def _read(text: str, unit: str) -> tuple[float, str, str]:
    """Split format_si's text into (its number, the number as written, its unit)."""
    number, _, label = text.partition(" ")
    return float(number), number, label


@pytest.mark.parametrize("unit", ["m", "Pa", "J", "N/m"])
@pytest.mark.parametrize("exponent", range(-12, 13))
@pytest.mark.parametrize("mantissa", [1.0, 2.5, 9.999, -4.2])
def test_a_prefix_never_comes_with_an_exponent(mantissa, exponent, unit):
    """Issue 35: 1e-12..1e12 m, Pa, J, N/m read between 1 and 1000 in a prefixed unit, no exponent."""
    value = mantissa * 10.0**exponent
    number, written_number, label = _read(format_si(value, unit), unit)
    assert "e" not in written_number.lower()
    assert 1 <= abs(number) < 1000
    assert math.isclose(number * quantity(f"1 {label}"), value, rel_tol=1e-3)


@settings(max_examples=300, deadline=None)
@given(
    st.floats(min_value=1e-30, max_value=1e30, allow_nan=False),
    st.sampled_from(["m", "Pa", "J", "N/m", "N", "m^2", "1/m^2", "Pa/m"]),
)
def test_any_value_reads_without_a_prefix_and_an_exponent_together(value, unit):
    text = format_si(value, unit)
    number, written_number, label = _read(text, unit)
    si_label = prefixed_scale(0.0, unit)[1]
    if "e" in written_number:  # beyond every prefix: the unprefixed SI unit
        assert label == si_label
    else:
        assert 1e-3 <= abs(number) < 1e6
    assert math.isclose(number * quantity(f"1 {label}"), value, rel_tol=1e-3)


def test_values_beyond_the_prefixes_are_written_in_si():
    assert format_si(8.164e-22, "J") == "8.164e-22 J"  # was "8.164e-10 pJ"
    assert format_si(2.952e-18, "m") == "2.952 am"  # was "2.952e-06 pm"
    assert format_si(9.787e17, "Pa/m") == "978.7 GPa/µm"  # was "9.787e+08 GPa/m"
    assert format_si(2.778e14, "Pa") == "277.8 TPa"  # was "2.778e+05 GPa"
    assert format_si(2.019e10, "1/m^2") == "20190 1/mm²"  # was "2.019e+04 1/mm²"
    assert format_si(0.999999999e-6, "m") == "1 µm"  # rounded to four digits first


@pytest.mark.parametrize("value", [None, math.nan])
@pytest.mark.parametrize("unit", ["m", "Pa", "J", "N/m", ""])
def test_a_missing_value_reads_as_a_word_not_a_bare_unit(value, unit):
    assert format_si(value, unit) == MISSING == "none"
    assert format_si(value, unit, missing="none (no jump)") == "none (no jump)"


def test_a_column_takes_the_prefix_of_its_median_unless_it_spans_too_many_decades():
    assert common_scale([2.805e-6, 4.1e-7], "m") == (1e-6, "µm")
    assert common_scale([1.566e-16, 1.283e-17, 2.093e-18], "J") == (1e-18, "aJ")  # was pJ: 0.0001566
    assert common_scale([5e-7, 1e-6, 2e-3], "N") == (1e-6, "µN")  # 2000 µN, not 0.0005 mN
    assert common_scale([2.903e-17, 8.707e-22, 8.106e-22], "J") is None  # each value its own prefix
    assert common_scale([0.0, math.nan], "m") == (1.0, "m")


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
        (4e4, "N/m", 1e3, "mN/µm", "stiffness"),  # K_L in paper 001's mN and µm, not kN/m
        (9.787e17, "Pa/m", 1e15, "GPa/µm", None),  # no numerator prefix reads: the denominator's too
        (0.072, "J/m^2", 1e-3, "mJ/m²", "surface_energy"),
        (2e-9, "J", 1e-9, "nJ", "energy"),
        (3e-6, "m/s", 1e-6, "µm/s", "velocity"),
        (2e6, "1/m", 1e6, "1/µm", "inverse_length"),
        (2e6, "m^-1", 1e6, "1/µm", "inverse_length"),
        (3e-3, "N*m", 1e-3, "mN·m", "energy"),
        (1.566e-16, "J", 1e-18, "aJ", "energy"),
        (2.778e14, "Pa", 1e12, "TPa", "pressure"),
        (1e-20, "m", 1e-18, "am", "length"),  # below the smallest prefix: the smallest
        (1e20, "Pa", 1e12, "TPa", "pressure"),  # above the largest: the largest
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
    assert math.isclose(quantity(f"1 {label}"), scale, rel_tol=1e-12)  # a unit the parser reads


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
