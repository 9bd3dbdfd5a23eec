"""A measured load-interference curve (paper 002 Fig. 7's experiment), read from a text table.

Paper 002 compresses its SU-8 island with a flat nanoindenter tip and compares the measured load
against interference with the statistical (KKE) and deterministic (BEM) models. A study sets such
a record beside its curves (``[analysis.compare] measured_curve = "..."``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .._text_table import read_text_table
from ..errors import InputError
from ..units import quantity


def read_load_curve(path: str | Path) -> dict[str, np.ndarray]:
    """Read a measured load-interference curve: interference and load, one row per point.

    The first two columns are the interference and the load. A header is optional; a unit in it
    (``interference [nm], load [uN]``) is converted, else the values are SI (m and N), as in
    ``interference_m,force_N``. The interference should follow the models' zero (paper 002: zero
    at 25 uN). Lines starting with ``#`` are comments.

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
        A missing file, fewer than two numeric columns or two rows, a unit of the wrong kind.
    """
    table = read_text_table(path, expected="interference,load rows")
    factors = [1.0, 1.0]
    if table.units is not None:
        for column, dimension in ((0, "length"), (1, "force")):
            unit = table.units[column] if column < len(table.units) else None
            if unit:
                factors[column] = quantity(f"1 {unit}", dimension, field="measured_curve")
    try:
        data = np.array([[float(row[0]), float(row[1])] for row in table.rows], dtype=float)
    except (ValueError, IndexError):
        data = np.empty((0, 2))
    if data.shape[0] < 2 or not np.all(np.isfinite(data)):
        raise InputError(
            "measured_curve",
            f"{path} has no two numeric columns with at least two rows.",
            "write 'interference_m,force_N' rows in SI units (or give units in the header).",
        )
    return {"approach": data[:, 0] * factors[0], "force": data[:, 1] * factors[1]}
