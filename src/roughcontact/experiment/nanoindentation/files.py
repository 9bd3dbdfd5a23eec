"""Load-displacement curves as text files: reading any instrument's CSV export, writing one.

:func:`read_indentation_csv` tokenises the file with the shared text-table reader
(:func:`roughcontact._text_table.read_text_table`: comma, semicolon, tab or whitespace
separated, ``#`` comment lines), finds the depth, load and optional time columns by their
header names and converts their units to SI once, through :mod:`roughcontact.units`.
The header gives the units as ``depth (nm)``, ``load [mN]``, ``time/s`` or ``depth in nm``; the
``*_unit`` arguments give the unit of a column whose header cell has none (one that contradicts
the header is refused, naming the cell: no unit is assumed, none overridden), the ``*_column``
arguments name columns the auto-detection misses. A curve whose deepest point or largest load no
indentation reaches (:data:`DEPTH_RANGE`, :data:`LOAD_RANGE`: a depth in nm read as metres is
kilometres deep) is refused, naming the column and its unit.

:func:`write_indentation_csv` writes a curve back with ``time (s)``, ``depth (nm)``,
``load (mN)`` columns (units to choose) and ``#`` comment lines, in a form
:func:`read_indentation_csv` reads.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from ..._text_table import Column, column_factors, read_text_table
from ...errors import InputError
from ...units import format_si, quantity
from .curve import IndentationCurve

DEPTH_RANGE = (1e-10, 1e-3)
"""Largest depth [m] an indentation curve may reach: from an atom's size (0.1 nm) to 1 mm.

Nanoindentation reaches nanometres to tens of micrometres; outside this range the unit of the
depth column is wrong (a depth in nm labelled m reads as kilometres), not the indentation."""
LOAD_RANGE = (1e-12, 100.0)
"""Largest load [N] an indentation curve may reach: from 1 pN (an AFM tip) to 100 N (micro-hardness)."""

# header names recognised for each column (lower case, units stripped, "_" and "-" read as spaces)
_COLUMN_NAMES = {
    "depth": (
        "depth", "displacement", "indentation depth", "penetration", "penetration depth", "disp",
        "pd", "h", "d", "z",
    ),
    "load": ("load", "force", "normal load", "normal force", "indentation load", "fn", "pn", "p", "f"),
    "time": ("time", "t", "elapsed time", "time on sample"),
}  # fmt: skip
_DIMENSIONS = {"depth": "length", "load": "force", "time": "time"}
_EXAMPLE_UNITS = {"depth": "nm", "load": "mN", "time": "s"}


def _clean_name(name: str) -> str:
    """Return a column name lower case, with runs of spaces, ``_`` and ``-`` as one space."""
    return " ".join(name.lower().replace("_", " ").replace("-", " ").split())


def read_indentation_csv(
    path: str | Path,
    *,
    depth_column: str | None = None,
    load_column: str | None = None,
    time_column: str | None = None,
    depth_unit: str | None = None,
    load_unit: str | None = None,
    time_unit: str | None = None,
) -> IndentationCurve:
    """Read a load-displacement CSV into SI units.

    Lines starting with ``#`` are comments. The first other line is the header; columns are
    found by their names (depth/displacement/h, load/force/P, time/t; case, spaces, ``_`` and
    ``-`` ignored) unless named explicitly. Units come from the header, as in ``depth (nm)``,
    ``load [mN]``, ``time/s`` or ``depth in nm``; a ``*_unit`` argument gives the unit of a column
    whose header cell has none, and one that contradicts the header cell is refused (no unit is
    assumed). Comma, semicolon and tab delimiters are recognised, else whitespace (then no spaces
    inside a column name). A deepest point or a largest load outside 0.1 nm to 1 mm or 1 pN to
    100 N (``DEPTH_RANGE``, ``LOAD_RANGE`` of ``roughcontact.experiment.nanoindentation.files``) is
    refused: the unit of that column is wrong.

    Parameters
    ----------
    path : str or Path
        The file.
    depth_column, load_column, time_column : str, optional
        Header of the column (without its unit) where auto-detection does not find it.
    depth_unit, load_unit, time_unit : str, optional
        Unit strings (``"nm"``, ``"mN"``, ``"s"``) of columns whose header cell gives none.

    Returns
    -------
    IndentationCurve
        Depth [m], load [N], time [s] or None.

    Raises
    ------
    InputError
        Missing file, no header, a depth or load column that cannot be found, a column without
        a unit, a unit argument that contradicts the header, a cell that is not a number, a
        depth or load no indentation reaches.
    UnitError
        An unknown unit, or one of the wrong dimension.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(str(path), "file not found.", "check the path.")
    no_rows = InputError(
        str(path), "has no header and data rows.", "give a header line, then one row per point."
    )
    try:
        table = read_text_table(path, expected="a header line, then one row per point")
    except InputError:  # only comments and blank lines
        raise no_rows from None
    if table.names is None:
        raise InputError(
            str(path),
            "has no header line: its first line holds only numbers.",
            "give a header line naming the columns with their units, e.g. 'depth (nm),load (mN)'.",
        )
    if not table.rows:
        raise no_rows
    if table.width < 2:
        raise InputError(
            str(path), "has a single column.", "separate the columns by commas, semicolons or tabs."
        )
    header = table.header
    if table.delimiter is None and len(table.rows[0]) != table.width:
        raise InputError(
            str(path),
            f"the space-separated header {header} has {table.width} columns but the first data row "
            f"has {len(table.rows[0])}.",
            "join the words of each column name (e.g. 'indentation_depth (nm)'), or separate the "
            "columns by commas, semicolons or tabs.",
        )
    names = [_clean_name(name) for name in table.names]
    wanted = {"depth": depth_column, "load": load_column, "time": time_column}
    units = {"depth": depth_unit, "load": load_unit, "time": time_unit}
    indices: dict[str, int | None] = {}
    for quantity_name, explicit in wanted.items():
        option = f"{quantity_name}_column"
        if explicit is not None:
            key = _clean_name(explicit)
            if key not in names:
                raise InputError(
                    option, f"no column {explicit!r} in {path.name} (columns: {names}).", "name one of them."
                )
            indices[quantity_name] = names.index(key)
            continue
        found = [i for i, name in enumerate(names) if name in _COLUMN_NAMES[quantity_name]]
        if not found and quantity_name != "time":
            raise InputError(
                option,
                f"no {quantity_name} column recognised in {path.name} (columns: {names}).",
                f"name it with {option}= (CLI: --{quantity_name}-column).",
            )
        indices[quantity_name] = found[0] if found else None
    factors = column_factors(
        table,
        [
            Column(indices[q], f"{q}_unit", units[q], _DIMENSIONS[q], _EXAMPLE_UNITS[q])
            for q in ("depth", "load", "time")
        ],
        path,
    )
    columns: dict[str, np.ndarray | None] = {}
    for quantity_name, factor in zip(("depth", "load", "time"), factors, strict=True):
        index = indices[quantity_name]
        if index is None:
            columns[quantity_name] = None
            continue
        values = []
        for number, row in enumerate(table.rows, start=1):
            try:
                values.append(float(row[index]))
            except (ValueError, IndexError):
                raise InputError(
                    str(path),
                    f"data row {number}, column {header[index]!r}: {row[index : index + 1]} is not a number.",
                    "remove text rows below the header, or mark them as comments with '#'.",
                ) from None
        columns[quantity_name] = np.asarray(values) * factor
    for quantity_name, (low, high) in (("depth", DEPTH_RANGE), ("load", LOAD_RANGE)):
        _plausible(
            columns[quantity_name], quantity_name, low, high, header[indices[quantity_name]], units, path
        )
    return IndentationCurve(columns["depth"], columns["load"], columns["time"], source=path.name)


def _plausible(
    values, quantity_name: str, low: float, high: float, cell: str, units: dict, path: Path
) -> None:
    """Refuse a depth or load column whose largest value no indentation reaches: its unit is wrong."""
    finite = np.abs(values[np.isfinite(values)])
    if finite.size == 0:
        return
    largest = float(finite.max())
    if low <= largest <= high:
        return
    si = "m" if quantity_name == "depth" else "N"
    option = f"{quantity_name}_unit"
    given = units[quantity_name]
    read = f"read in {given!r}" if given else f"read in the unit of its header cell {cell!r}"
    side = "above" if largest > high else "below"
    problem = (
        f"the {quantity_name} column of {path.name}, {read}, reaches {format_si(largest, si)}, {side} "
        f"what an indentation reaches ({format_si(low, si)} to {format_si(high, si)})."
    )
    example = _EXAMPLE_UNITS[quantity_name]
    check = f"check the unit of the {quantity_name} column"
    if given:
        fixes = {
            "python": f'{check}: give the unit its values are in, e.g. {option}="{example}".',
            "study": f'{check}: give the unit its values are in, e.g. {option} = "{example}".',
            "cli": f"{check}: give the unit its values are in, e.g. --{quantity_name}-unit {example}.",
        }
    else:
        own = f"{check}: correct its header cell {cell!r} to the unit its values are in, e.g. "
        own += f"'{quantity_name} ({example})'."
        fixes = {"python": own}
    raise InputError(option if given else str(path), problem, fixes["python"], fixes=fixes)


def write_indentation_csv(
    path: str | Path, curve: IndentationCurve, *, comments: Sequence[str] = (), depth_unit: str = "nm",
    load_unit: str = "mN", time_unit: str = "s", digits: int = 8,
) -> Path:  # fmt: skip
    """Write a curve as CSV with ``time (s)``, ``depth (nm)``, ``load (mN)`` columns and ``#`` comments.

    Parameters
    ----------
    path : str or Path
        The file (overwritten).
    curve : IndentationCurve
        The record (SI); its time column is written when it has one.
    comments : sequence of str
        Lines written first, each after ``#`` and a space.
    depth_unit, load_unit, time_unit : str
        Units of the columns, written in the header.
    digits : int
        Significant digits of the values.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    UnitError
        An unknown unit, or one of the wrong dimension.
    """
    path = Path(path)
    scale = {
        "depth": 1.0 / quantity(f"1 {depth_unit}", "length", field="depth_unit"),
        "load": 1.0 / quantity(f"1 {load_unit}", "force", field="load_unit"),
        "time": 1.0 / quantity(f"1 {time_unit}", "time", field="time_unit"),
    }
    lines = [f"# {c}" for c in comments]
    header = [f"depth ({depth_unit})", f"load ({load_unit})"]
    columns = [curve.depth * scale["depth"], curve.load * scale["load"]]
    if curve.time is not None:
        header.insert(0, f"time ({time_unit})")
        columns.insert(0, curve.time * scale["time"])
    lines.append(",".join(header))
    for row in zip(*columns, strict=True):
        lines.append(",".join(f"{v:.{digits}g}" for v in row))
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path
