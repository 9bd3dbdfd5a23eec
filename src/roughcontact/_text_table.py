"""Small text tables: CSV, semicolon, tab or whitespace separated, with an optional header of units.

The tokenising shared by the readers of measured friction loops
(:func:`roughcontact.experiment.friction_loop.read_loop_csv`), of tangential loading programmes
(:func:`roughcontact.contact.paths.read_path_csv`) and of nanoindentation curves
(:func:`roughcontact.experiment.nanoindentation.read_indentation_csv`); each reader gives the
columns their meaning and converts their units (through :mod:`roughcontact.units`).

A header cell gives its unit as ``name [unit]``, ``name (unit)``, ``name/unit`` or ``name in unit``
(see :func:`split_header`). No reader assumes a unit: a column a reader needs takes its unit from
its header cell or from an option the user gave (:func:`column_factors`), and an option that
contradicts the header cell is refused, naming the cell as written.
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

from ._files import read_text
from .errors import InputError, UnitError
from .messages import is_number
from .origin import DataOrigin, origin_of
from .units import DIMENSIONS, unit_factor

HEADER_UNIT = re.compile(r"^\s*(.*?)\s*(?:[\[\(]\s*([^\]\)]*?)\s*[\]\)])?\s*$")
"""A header cell ``name [unit]`` or ``name (unit)``: group 1 the name, group 2 the unit (or None).

The unit is the last bracket of the cell, so ``load (corrected) [mN]`` is ``load (corrected)`` in mN.
"""
_WORDS = re.compile(r"[^\s\[\(]+(?:\s*[\[\(][^\]\)]*[\]\)])?")
"""A cell of a whitespace-separated line: a word with its bracketed unit, ``x [um]``, kept whole."""
_IN_UNIT = re.compile(r"^(.*\S)\s+in\s+(\S+)$")
"""A header cell ``name in unit`` (``x in µm``): group 1 the name, group 2 the unit, if it is one."""


@dataclass(frozen=True)
class TextTable:
    """The cells of a text table.

    Attributes
    ----------
    names : list of str or None
        Lower-case column names from the header (None without a header).
    units : list of (str or None) or None
        The unit of each column from its header cell (:func:`split_header`), None where it gives none.
    rows : list of list of str
        The data rows, cells stripped, not converted.
    delimiter : str or None
        The column separator; None for whitespace.
    header : list of str or None
        The header cells as written, stripped (None without a header), for messages.
    comments : tuple of str
        The ``#`` lines, without their ``#`` (where the file says its origin:
        :func:`roughcontact.origin.origin_of`).
    """

    names: list[str] | None
    units: list[str | None] | None
    rows: list[list[str]]
    delimiter: str | None = None
    header: list[str] | None = None
    comments: tuple[str, ...] = ()

    def origin(self, field: str = "origin") -> DataOrigin:
        """Return the origin the comment lines declare (measured by default; :mod:`roughcontact.origin`)."""
        return origin_of(self.comments, field=field)

    @property
    def width(self) -> int:
        """Number of columns of the first line (header or data)."""
        return len(self.names) if self.names is not None else len(self.rows[0])


def read_text_table(path: str | Path, *, expected: str, delimiter: str | None = None) -> TextTable:
    """Read a text table; lines starting with ``#`` are comments.

    The first line is a header when one of its cells is not a number; its cells are split into
    names and units by :func:`split_header`. The separator is the
    ``delimiter`` given, else the first of comma, semicolon and tab found in the first line, else
    whitespace (a header cell ``x [um]`` then stays one cell).

    Parameters
    ----------
    path : str or Path
        The file.
    expected : str
        What its rows hold, for the messages (e.g. ``"displacement,force rows"``).
    delimiter : str, optional
        Column separator (detected when not given).

    Raises
    ------
    InputError
        The file does not exist or holds no data lines.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("path", f"{path} does not exist.", f"give the path of a CSV with {expected}.")
    text = read_text(path, holds=f"a CSV with {expected}").splitlines()
    lines = [line.strip() for line in text if line.strip() and not line.lstrip().startswith("#")]
    comments = tuple(line.strip()[1:].strip() for line in text if line.lstrip().startswith("#"))
    if not lines:
        raise InputError("path", f"{path} has no data lines.", f"give {expected}.")
    if delimiter is None:
        delimiter = next((d for d in (",", ";", "\t") if d in lines[0]), None)
    rows = [split_cells(line, delimiter) for line in lines]
    if all(is_number(cell) for cell in rows[0]):
        return TextTable(None, None, rows, delimiter, comments=comments)
    names, units = zip(*(split_header(cell) for cell in rows[0]), strict=True)
    return TextTable(list(names), list(units), rows[1:], delimiter, rows[0], comments)


def split_cells(line: str, delimiter: str | None) -> list[str]:
    """Split a line into its cells, stripped: at ``delimiter`` (CSV quoting), or at white space.

    Split at white space, a word keeps its bracketed unit: ``x [um] z [nm]`` is two cells.
    """
    if delimiter:
        return [cell.strip() for cell in next(csv.reader([line], delimiter=delimiter, skipinitialspace=True))]
    return [cell.strip() for cell in _WORDS.findall(line)]


def split_header(cell: str) -> tuple[str, str | None]:
    """Split a header cell into its lower-case name and its unit (None where it gives none).

    The unit is written in brackets, ``depth [nm]`` or ``load (mN)`` (the last bracket), after
    a slash, ``time/s`` (the first slash; a cell starting or ending with one is all name), or
    after the word ``in``, ``x in µm`` (only where the last word is a unit: ``time in contact``
    is a name). Surrounding double quotes are dropped.

    Examples
    --------
    >>> split_header("Load [mN]"), split_header("time/s"), split_header("x in µm"), split_header("step")
    (('load', 'mN'), ('time', 's'), ('x', 'µm'), ('step', None))
    """
    text = cell.strip().strip('"').strip()
    match = HEADER_UNIT.match(text)
    if match and match.group(2) is not None:  # a bracket, perhaps empty: "depth ()" has no unit
        return match.group(1).strip().rstrip("/").strip().lower(), match.group(2) or None
    name, slash, unit = text.partition("/")
    if slash and name.strip() and unit.strip():
        return name.strip().lower(), unit.strip()
    worded = _IN_UNIT.match(text)
    if worded and _is_unit(worded.group(2)):
        return worded.group(1).strip().lower(), worded.group(2)
    return text.lower(), None


def _is_unit(text: str) -> bool:
    """Whether ``text`` is a unit :mod:`roughcontact.units` reads (and not a bare number)."""
    if is_number(text):
        return False
    try:
        unit_factor(text)
    except UnitError:
        return False
    return True


@dataclass(frozen=True)
class Column:
    """A column a reader needs, and the option through which the user may give its unit.

    Attributes
    ----------
    index : int or None
        Its position in the table (None: the file has no such column).
    option : str
        The keyword (study key) that gives its unit, e.g. ``"displacement_unit"``; the command
        line spells it ``--displacement-unit``.
    given : str or None
        The unit the user gave through ``option`` (None: none given; never a default).
    dimension : str
        Its dimension (``"length"``, ``"force"``, ``"time"``).
    example : str
        A unit of that dimension for the messages (``"um"``).
    required : bool
        Whether a column without a unit is refused (else it is left unread: factor None).
    """

    index: int | None
    option: str
    given: str | None
    dimension: str
    example: str
    required: bool = True

    @property
    def flag(self) -> str:
        """The option as the command line spells it."""
        return "--" + self.option.replace("_", "-")


def _factor(unit: str, column: Column, where: str | None = None, cell: str | None = None) -> float:
    """Return the factor to SI of ``unit``, refusing one of another dimension than the column's.

    ``where`` says where the unit was written (None: the column's option); ``cell`` is the header
    cell when it was written there.
    """
    fix = (
        f"give the unit of the {column.dimension}s the column holds, e.g. {column.example}."
        if cell is None
        else f"correct the header cell to the unit of the {column.dimension}s the column holds, e.g. "
        f"'{split_header(cell)[0]} [{column.example}]'."
    )
    said = "" if where is None else f"{where}: "
    try:
        factor, dimension = unit_factor(unit)
    except UnitError as error:
        raise UnitError(column.option, f"{said}{error.problem}", fix) from None
    if dimension != DIMENSIONS[column.dimension]:
        raise UnitError(column.option, f"{said}{unit!r} is not a {column.dimension} unit.", fix)
    return float(factor)


def column_factors(table: TextTable, columns: list[Column], path: str | Path) -> list[float | None]:
    """Return the factor to SI of each column: its header cell's unit, or the unit its option gives.

    No unit is assumed. A needed column whose header cell gives no unit (or a file without a
    header) takes the unit its option gives; where neither does, the file is refused naming every
    such column and both ways to give its unit. An option that contradicts the header cell (a
    unit of another size) is refused, naming the cell as written: the header is the file's own
    word, and a wrong header is corrected in the file.

    Parameters
    ----------
    table : TextTable
        The file's table (:func:`read_text_table`).
    columns : list of Column
        The columns the reader needs.
    path : str or Path
        The file, for the messages.

    Returns
    -------
    list of (float or None)
        One factor per column; None for a column the file lacks, or an optional one without a unit.

    Raises
    ------
    InputError
        A needed column without a unit from the header or its option; an option that contradicts
        the header cell. UnitError for an unknown unit, or one of the wrong dimension.
    """
    name = Path(path).name
    factors: list[float | None] = []
    missing: list[Column] = []
    for column in columns:
        if column.index is None:
            factors.append(None)
            continue
        cell = None if table.header is None else table.header[column.index]
        stated = None if table.units is None else table.units[column.index]
        where = (
            f"column {column.index + 1} of {name}" if cell is None else f"the header cell {cell!r} of {name}"
        )
        given = None if column.given is None else _factor(column.given, column)
        if stated is None:
            if given is None and column.required:
                missing.append(column)
            factors.append(given)
            continue
        written = _factor(stated, column, where, cell)
        if given is not None and not math.isclose(given, written, rel_tol=1e-12):
            raise _contradiction(column, cell, stated, name)
        factors.append(written)
    if missing:
        raise _missing_units(missing, columns, table, name)
    return factors


def _contradiction(column: Column, cell: str, stated: str, name: str) -> InputError:
    """Return the refusal of a unit option that contradicts the header cell ``cell``."""
    problem = f"{column.given!r} contradicts the header cell {cell!r} of {name}, which gives [{stated}]."
    then = (
        f"the column is read in {stated}, as its header says; if the header is wrong, correct it in {name}."
    )
    return InputError(
        column.option,
        problem,
        f"leave {column.option} out: {then}",
        fixes={"study": f"remove {column.option}: {then}", "cli": f"leave {column.flag} out: {then}"},
    )


def _missing_units(missing: list[Column], columns: list[Column], table: TextTable, name: str) -> InputError:
    """Return the refusal of needed columns without a unit, with both ways to give them."""
    plural = "s" if len(missing) > 1 else ""
    if table.header is None:
        what = " and ".join(column.option.removesuffix("_unit") for column in missing)
        problem = (
            f"{name} has no header, so the unit{plural} of its {what} column{plural} {_are(missing)} unknown."
        )
        present = sorted((c for c in columns if c.index is not None), key=lambda c: c.index)
        header = ",".join(f"{c.option.removesuffix('_unit')} [{c.given or c.example}]" for c in present)
        own = f"start {name} with a header line naming the columns with their units, e.g. {header!r}"
    else:
        cells = " and ".join(repr(table.header[column.index]) for column in missing)
        problem = (
            f"the header cell{plural} {cells} of {name} {'has' if len(missing) == 1 else 'have'} no unit."
        )
        written = ", ".join(repr(f"{table.header[column.index]} [{column.example}]") for column in missing)
        own = f"write the unit{plural} in the header, e.g. {written}"
    options = {
        "python": ", ".join(f'{column.option}="{column.example}"' for column in missing),
        "study": ", ".join(f'{column.option} = "{column.example}"' for column in missing),
        "cli": " ".join(f"{column.flag} {column.example}" for column in missing),
    }
    said = {
        style: f"{own}; or give the unit{plural} the values are in, e.g. {given}."
        for style, given in options.items()
    }
    return InputError(missing[0].option, problem, said["python"], fixes=said)


def _are(columns: list[Column]) -> str:
    return "is" if len(columns) == 1 else "are"
