"""Numbers for a reader: engineering units, one unit per column (or per quantity), named beside them.

The stored tables (``results.csv``, ``tables/*.csv``) keep SI numbers under headers ``name [unit]``
(:func:`header`), for programs. The report and the commands' printed tables show the same
numbers through this module, by one rule (:mod:`roughcontact.units`): a prefix that puts the
number between 1 and 1000, never a prefix together with an exponent.

* A column (or the values of one quantity across cases) shares one prefix, that of its median
  magnitude (:func:`roughcontact.units.common_scale`), and the prefixed unit goes in the header
  (``Sq (nm)`` over ``1.614``, not ``Sq [m]`` over ``1.614e-09``); values far from the median
  read with more digits in it (``0.0015``, ``20190``).
* A column spanning too many decades for that (a numerical zero, ``8e-22 J``, beside ``29 aJ``)
  has no unit in its header: each cell is written with its own prefix and unit
  (:func:`roughcontact.units.format_si`).
* A single value (a summary line, a cell of a quantity table) takes its own prefix
  (:func:`roughcontact.units.shown`, also a result's display in a notebook).
* A missing value (None, NaN, blank) of a numeric column reads ``none`` (:data:`MISSING`), with
  the reason where the analysis gives one (``none (no jump on loading)``), never a bare unit;
  a text column leaves it empty.

A table whose rows are quantities (a comparison with a paper: columns ``quantity``, ``unit``,
``paper``, ``this_case``, ...) carries each row's unit in its ``unit`` column; the value columns of
such a table (:data:`PER_ROW_UNIT`) are shown in that row's unit, with the unit in each cell.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from ..units import DIGITS, MISSING, blank, common_scale, format_si, number, shown

PER_ROW_UNIT = ("paper", "this_case", "printed_inputs", "ours")
"""Column-name prefixes of a quantity table whose columns take their row's ``unit``."""

SPREAD_COLUMNS = ("mean", "std", "ci95_low", "ci95_high", "min", "max")
"""Columns of a spread table (:func:`roughcontact.study.outputs.spread_rows`), in their row's ``unit``."""


def _per_row(name: str) -> bool:
    return name.startswith(PER_ROW_UNIT) or name in SPREAD_COLUMNS


def header(name: str, unit: str | None) -> str:
    """Return the stored header of a column: ``name [unit]``, or ``name`` for a dimensionless one."""
    return f"{name} [{unit}]" if unit else name


def split_header(text: str) -> tuple[str, str | None]:
    """Inverse of :func:`header`: ``"Sq [m]"`` -> ``("Sq", "m")``, ``"mu"`` -> ``("mu", None)``."""
    if text.endswith("]") and " [" in text:
        name, _, unit = text[:-1].rpartition(" [")
        return name, unit or None
    return text, None


def _text(value: float | int | None, scale: float = 1.0, missing: str = MISSING) -> str:
    """Write the value in units of ``scale`` to :data:`DIGITS` significant digits (20190, not 2.019e+04)."""
    if value is None:
        return missing
    if isinstance(value, int) and scale == 1.0:
        return str(value)
    text = f"{value / scale:.{DIGITS}g}"
    rounded = float(text)
    if "e+" in text and abs(rounded) < 1e6:
        return f"{rounded:.0f}"
    return text


def missing_text(reason: str | None = None) -> str:
    """Return what a value that is not there reads as: ``none``, or ``none (reason)``."""
    return f"{MISSING} ({reason})" if reason else MISSING


def scaled(values: Sequence[Any], unit: str | None, missing: str = MISSING) -> tuple[str, list[str]] | None:
    """Return cells of values of one quantity in one prefix; None unless all are numbers.

    The prefix is that of the median magnitude (:func:`roughcontact.units.common_scale`); where
    the values span too many decades for one prefix, the label is ``""`` and each cell carries its
    own prefix and unit (:func:`roughcontact.units.format_si`). Blanks (None, "", NaN) are allowed
    and read ``missing``.

    Returns
    -------
    (label, cells) or None
        The prefixed unit ("" for a dimensionless quantity, for one without any value, and for
        cells that carry their units) and each value as text.
    """
    numbers = [number(v) for v in values]
    if any(n is None and not blank(v) for n, v in zip(numbers, values, strict=True)):
        return None
    present = [n for n in numbers if n is not None]
    if not unit or not present:
        return "", [_text(n, missing=missing) for n in numbers]
    common = common_scale(present, unit, digits=DIGITS)
    if common is None:
        return "", [format_si(n, unit, digits=DIGITS, missing=missing) for n in numbers]
    scale, label = common
    return label, [_text(n, scale, missing) for n in numbers]


def column_cells(values: Sequence[Any], unit: str | None, missing: str = MISSING) -> tuple[str, list[str]]:
    """Return the values of one quantity as (prefixed unit, cells); a quantity with any text stays text.

    Numbers share one prefix (:func:`scaled`) and blanks read ``missing``; otherwise every value
    is shown as written (label "") and blanks are empty.
    """
    return scaled(values, unit, missing) or ("", ["" if blank(v) else str(v) for v in values])


def columns(
    rows: Sequence[Mapping[str, Any]],
    units: Mapping[str, str] | None = None,
    missing: Mapping[str, str] | None = None,
) -> tuple[list[str], list[list[str]]]:
    """Return the titles and cells of a table of rows, each numeric column in one engineering unit.

    Parameters
    ----------
    rows : sequence of mapping
        One mapping per row; keys are stored headers (``name [unit]``) or plain names, whose
        unit, if any, comes from ``units``.
    units : mapping, optional
        SI unit of plain-named columns.
    missing : mapping, optional
        Column name (without its unit) -> why a row may have no value there (``"no jump on
        loading"``); such a cell reads ``none (no jump on loading)``, others ``none``.

    Columns with no value in any row are left out, and so is a ``case`` column that holds one
    case id in every row, and the ``unit`` column of a quantity table (its cells carry the unit).

    Returns
    -------
    titles : list of str
        ``name (prefixed unit)`` for a column with a unit, else the name.
    cells : list of list of str
        One list per row.
    """
    names = list(dict.fromkeys(key for row in rows for key in row))
    names = [n for n in names if not all(blank(row.get(n)) for row in rows)]
    if "unit" in names and any(_per_row(n) for n in names):
        names.remove("unit")  # every value cell of such a table carries its row's unit
    if len(rows) > 1 and len({str(row.get("case")) for row in rows}) == 1:
        names = [n for n in names if n != "case"]  # rows of one case: its id says nothing
    titles, by_column = [], []
    for key in names:
        name, unit = split_header(key)
        unit = unit or (units or {}).get(key)
        values = [row.get(key) for row in rows]
        if _per_row(key) and any("unit" in row for row in rows):
            titles.append(name)
            row_units = [row.get("unit") or None for row in rows]
            by_column.append([shown(v, u) for v, u in zip(values, row_units, strict=True)])
            continue
        label, column = column_cells(values, unit, missing_text((missing or {}).get(name)))
        titles.append(f"{name} ({label})" if label else name)
        by_column.append(column)
    return titles, [list(row) for row in zip(*by_column, strict=True)] if by_column else []


def text_table(titles: Sequence[str], cells: Sequence[Sequence[str]], indent: str = "") -> list[str]:
    """Titles and cells as aligned text lines (right-aligned columns)."""
    widths = [max(len(t), *(len(row[i]) for row in cells)) for i, t in enumerate(titles)]
    lines = ["  ".join(f"{t:>{w}}" for t, w in zip(titles, widths, strict=True))]
    lines += ["  ".join(f"{c:>{w}}" for c, w in zip(row, widths, strict=True)) for row in cells]
    return [indent + line for line in lines]
