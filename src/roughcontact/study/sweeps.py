"""Sweeps of a study's analysis: the ``[analysis.sweep]`` axes and the ``[analysis.zip]`` axis into cases.

A sweep axis is a list or a range table: ``{start = "1 uN", stop = "100 uN", num = 5, spacing =
"log"}`` (``num`` points from start to stop, ``"linear"`` by default) or ``{start = 0, stop = 6,
step = 1}`` (start, start + step, ... up to and including stop). The cases are the Cartesian
product of the sweep axes (the first varying slowest) times the zip axis: equally long lists
taken together. Values stay as written (``"10 uN"``); the schemas convert them to SI.
"""

from __future__ import annotations

import itertools
import math
from typing import Any

import numpy as np

from ..errors import InputError
from ..units import split_quantity, unit_factor


def _split_quantity(value: Any, where: str) -> tuple[float, str]:
    if isinstance(value, bool):
        raise InputError(where, f"expected a number or a quantity, got {value!r}.", "e.g. '1 uN' or 3.")
    if isinstance(value, int | float):
        return float(value), ""
    number, unit = split_quantity(str(value), field=where)
    return float(number), unit


def _range_values(spec: dict, where: str) -> list:
    """Expand a range table into a list of values written in the unit of ``start``."""
    known = {"start", "stop", "num", "step", "spacing"}
    if not known >= set(spec) or not {"start", "stop"} <= set(spec) or ("num" in spec) == ("step" in spec):
        raise InputError(
            where,
            f"a range is start, stop and one of num or step, got {sorted(spec)}.",
            "e.g. {start = '1 uN', stop = '100 uN', num = 5, spacing = 'log'} "
            "or {start = 0, stop = 6, step = 1}.",
        )
    start, unit = _split_quantity(spec["start"], f"{where}.start")
    stop, stop_unit = _split_quantity(spec["stop"], f"{where}.stop")
    if stop_unit != unit:
        factor, dimension = unit_factor(stop_unit)
        own_factor, own_dimension = unit_factor(unit)
        if dimension != own_dimension:
            raise InputError(
                f"{where}.stop",
                f"{spec['stop']!r} is not the same kind of quantity as start = {spec['start']!r}.",
                f"write start and stop in units of one kind, e.g. stop = '{stop:g} {unit}'."
                if unit
                else "give start a unit too, or neither a unit.",
            )
        stop *= float(factor / own_factor)
    integers = all(isinstance(spec[k], int) and not isinstance(spec[k], bool) for k in ("start", "stop"))
    if "step" in spec:
        step, step_unit = _split_quantity(spec["step"], f"{where}.step")
        if step_unit not in ("", unit) or not step > 0 or stop < start:
            raise InputError(
                f"{where}.step", f"need step > 0 and stop >= start, got {spec}.", "e.g. step = 1."
            )
        count = int(math.floor((stop - start) / step * (1 + 1e-12))) + 1
        numbers = [start + k * step for k in range(count)]
        integers = integers and isinstance(spec["step"], int)
    else:
        num = spec["num"]
        if not isinstance(num, int) or num < 1:
            raise InputError(f"{where}.num", f"need a whole number >= 1, got {num!r}.", "e.g. num = 5.")
        spacing = spec.get("spacing", "linear")
        if spacing == "log":
            if not (start > 0 and stop > 0):
                raise InputError(f"{where}.spacing", "log spacing needs start and stop > 0.", "use linear.")
            numbers = list(np.geomspace(start, stop, num))
        elif spacing == "linear":
            numbers = list(np.linspace(start, stop, num))
        else:
            raise InputError(f"{where}.spacing", f"unknown spacing {spacing!r}.", "use 'linear' or 'log'.")
        integers = integers and all(float(n).is_integer() for n in numbers)
    if integers and not unit:
        return [int(round(n)) for n in numbers]
    return [f"{float(n):.12g} {unit}".strip() if unit else float(n) for n in numbers]


def _axis_values(value: Any, where: str) -> list:
    if isinstance(value, dict):
        return _range_values(value, where)
    if isinstance(value, list) and value:
        return value
    raise InputError(
        where, f"an axis is a non-empty list or a range table, got {value!r}.", "e.g. [1, 2, 3]."
    )


def expand(sweep: dict, zipped: dict | list[dict], where: str) -> list[dict[str, Any]]:
    """Return one ``{axis: value}`` dictionary per case: the product of the sweep axes and the zip axes.

    Parameters
    ----------
    sweep : dict
        Axis -> list or range table; the cases are their Cartesian product, the first axis
        varying slowest.
    zipped : dict or list of dict
        Axis -> list, all of one length; taken together as one more (last) axis. A list of such
        tables (``[[analysis.zip]]`` in a study file) is one axis per table, crossed with each
        other in their order: the samples of one table against the model readings of another.
    where : str
        The analysis' field name for error messages.

    Returns
    -------
    list of dict
        One dictionary of raw (as written) values per case; ``[{}]`` without axes.
    """
    axes = {name: _axis_values(value, f"{where}.sweep.{name}") for name, value in sweep.items()}
    groups = zipped if isinstance(zipped, list) else [zipped] if zipped else []
    seen: set[str] = set(axes)
    rows: list[dict] = [{}]
    for number, group in enumerate(groups):
        field = f"{where}.zip" if len(groups) == 1 else f"{where}.zip[{number}]"
        overlap = seen & set(group)
        if overlap:
            raise InputError(field, f"{sorted(overlap)} is both swept and zipped.", "keep it in one place.")
        seen |= set(group)
        lists = {name: _axis_values(value, f"{field}.{name}") for name, value in group.items()}
        lengths = {name: len(values) for name, values in lists.items()}
        if len(set(lengths.values())) > 1:
            raise InputError(field, f"zipped lists differ in length: {lengths}.", "make them equal.")
        zipped_rows = [dict(zip(lists, values, strict=True)) for values in zip(*lists.values(), strict=True)]
        rows = [row | other for row in rows for other in zipped_rows]
    names = list(axes)
    return [
        dict(zip(names, values, strict=True)) | row
        for values in itertools.product(*axes.values())
        for row in rows
    ]
