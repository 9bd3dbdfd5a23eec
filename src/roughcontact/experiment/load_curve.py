"""A measured load-interference curve (paper 002 figure 7's experiment), read from a text table.

Paper 002 compresses its SU-8 island with a flat nanoindenter tip and compares the measured load
against interference with the statistical (KKE) and deterministic (BEM) models. A study sets such
a record beside its curves (``[analysis.compare] measured_curve = "..."``).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from .._text_table import Column, TextTable, column_factors, read_text_table
from ..errors import InputError, UnitError
from ..units import DIMENSIONS, unit_factor

_SUFFIX_UNIT = re.compile(r"^(?P<name>.*[^_])_(?P<unit>[A-Za-zµμ]+)$")
"""A header cell ending in its unit after an underscore: ``interference_m``, ``force_N`` (release 0.1)."""


def read_load_curve(path: str | Path) -> dict[str, np.ndarray]:
    """Read a measured load-interference curve: interference and load, one row per point.

    The first two columns are the interference and the load. A header line gives each its unit,
    ``interference [nm],load [uN]`` (or ``(nm)``, ``/nm``, ``in nm``), or, as release 0.1 wrote
    it, after an underscore, ``interference_m,force_N``. No unit is assumed: a file without a
    header, or a column whose header cell gives no unit, is refused. The interference should
    follow the models' zero (paper 002: zero at 25 uN). Lines starting with ``#`` are comments.

    Parameters
    ----------
    path : str or Path
        The text file (comma, semicolon, tab or whitespace separated).

    Returns
    -------
    dict
        ``"approach"`` (the interference) [m] and ``"force"`` [N] arrays.

    Raises
    ------
    InputError
        A missing file, no header or a column without a unit, fewer than two numeric columns or
        two rows. UnitError for an unknown unit or one of the wrong kind.
    """
    table = read_text_table(path, expected="interference,load rows with their units in a header line")
    name = Path(path).name
    header = "'interference [nm],load [uN]'"
    if table.names is None:
        raise InputError(
            "measured_curve",
            f"{name} has no header, so the units of its interference and load columns are unknown.",
            f"start {name} with a header line naming the columns with their units, e.g. {header}.",
        )
    if table.width < 2:
        raise InputError(
            "measured_curve",
            f"{name} has {table.width} column; it needs interference and load.",
            f"e.g. {header}.",
        )
    units = list(table.units)
    for index in (0, 1):
        suffixed = _SUFFIX_UNIT.match(table.header[index].strip())
        if units[index] is None and suffixed and _length_or_force(suffixed.group("unit")):
            units[index] = suffixed.group("unit")
    if units[0] is None or units[1] is None:
        bare = [repr(table.header[i]) for i in (0, 1) if units[i] is None]
        said = f"cells {' and '.join(bare)} give" if len(bare) > 1 else f"cell {bare[0]} gives"
        raise InputError(
            "measured_curve",
            f"the header {said} no unit in {name}.",
            f"write the unit of each column in its header cell, e.g. {header}.",
        )
    named = TextTable(table.names, units, table.rows, table.delimiter, table.header, table.comments)
    length, newton = column_factors(
        named,
        [Column(0, "measured_curve", None, "length", "nm"), Column(1, "measured_curve", None, "force", "uN")],
        path,
    )
    try:
        data = np.array([[float(row[0]), float(row[1])] for row in table.rows], dtype=float)
    except (ValueError, IndexError):
        data = np.empty((0, 2))
    if data.shape[0] < 2 or not np.all(np.isfinite(data)):
        raise InputError(
            "measured_curve",
            f"{path} has no two numeric columns with at least two rows.",
            f"write interference,load rows below a header line with their units, e.g. {header}.",
        )
    return {"approach": data[:, 0] * length, "force": data[:, 1] * newton}


def _length_or_force(unit: str) -> bool:
    """Whether ``unit`` (the end of a header cell after an underscore) is a unit of length or force."""
    try:
        dimension = unit_factor(unit)[1]
    except UnitError:
        return False
    return dimension in (DIMENSIONS["length"], DIMENSIONS["force"])
