"""Invariants of study sweeps: every combination once, in order; ranges keep their ends and count."""

import itertools
import math

from hypothesis import given
from hypothesis import strategies as st

from roughcontact.study.config import expand
from roughcontact.units import quantity

axis_values = st.lists(st.integers(-5, 5), min_size=1, max_size=4, unique=True)


@given(
    axes=st.lists(axis_values, min_size=0, max_size=3),
    zip_length=st.integers(0, 3),
)
def test_the_cases_are_the_product_of_the_axes_times_the_zip(axes, zip_length):
    sweep = {f"a{i}": values for i, values in enumerate(axes)}
    zipped = {"z": list(range(zip_length)), "w": [f"s{k}" for k in range(zip_length)]} if zip_length else {}
    rows = expand(sweep, zipped, "analysis")
    expected = math.prod(len(v) for v in axes) * (zip_length or 1)
    assert len(rows) == expected
    keys = [tuple(row.values()) for row in rows]
    assert len(set(keys)) == expected  # every combination once
    product = list(
        itertools.product(*axes, *([list(zip(zipped["z"], zipped["w"], strict=True))] if zipped else []))
    )
    flattened = [
        tuple(v for item in combo for v in (item if isinstance(item, tuple) else (item,)))
        for combo in product
    ]
    assert keys == flattened  # first axis slowest, the zip axis last
    assert all(row["z"] == int(row["w"][1:]) for row in rows if zipped)  # zipped values stay together


@given(
    start=st.floats(1e-3, 1e3),
    ratio=st.floats(1.0, 1e3),
    num=st.integers(1, 12),
    spacing=st.sampled_from(["linear", "log"]),
    unit=st.sampled_from(["nm", "um", "mN", "GPa"]),
)
def test_a_range_has_num_values_from_start_to_stop_in_its_unit(start, ratio, num, spacing, unit):
    stop = start * ratio
    rows = expand(
        {"x": {"start": f"{start!r} {unit}", "stop": f"{stop!r} {unit}", "num": num, "spacing": spacing}},
        {},
        "a",
    )
    values = [row["x"] for row in rows]
    assert len(values) == num
    assert all(v.endswith(f" {unit}") for v in values)
    dimension = {"nm": "length", "um": "length", "mN": "force", "GPa": "pressure"}[unit]
    si = [quantity(v, dimension) for v in values]
    assert math.isclose(si[0], quantity(f"{start!r} {unit}", dimension), rel_tol=1e-11)
    if num > 1:
        assert math.isclose(si[-1], quantity(f"{stop!r} {unit}", dimension), rel_tol=1e-11)
    assert all(b >= a * (1 - 1e-11) for a, b in itertools.pairwise(si))  # non-decreasing


@given(start=st.integers(-20, 20), count=st.integers(0, 20), step=st.integers(1, 5))
def test_an_integer_step_range_includes_its_stop(start, count, step):
    stop = start + count * step
    values = [row["i"] for row in expand({"i": {"start": start, "stop": stop, "step": step}}, {}, "a")]
    assert values == list(range(start, stop + 1, step))
