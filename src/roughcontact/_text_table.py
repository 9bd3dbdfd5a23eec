"""Small text tables: CSV, semicolon, tab or whitespace separated, with an optional header of units.

The tokenising shared by the readers of measured friction loops
(:func:`roughcontact.experiment.friction_loop.read_loop_csv`), of tangential loading programmes
(:func:`roughcontact.contact.paths.read_path_csv`) and of nanoindentation curves
(:func:`roughcontact.experiment.nanoindentation.read_indentation_csv`); each reader gives the
columns their meaning and converts their units (through :mod:`roughcontact.units`).

A header cell gives its unit as ``name [unit]``, ``name (unit)`` or ``name/unit`` (see
:func:`split_header`).
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path

from ._files import read_text
from .errors import InputError
from .origin import DataOrigin, origin_of

HEADER_UNIT = re.compile(r"^\s*(.*?)\s*(?:[\[\(]\s*([^\]\)]*?)\s*[\]\)])?\s*$")
"""A header cell ``name [unit]`` or ``name (unit)``: group 1 the name, group 2 the unit (or None).

The unit is the last bracket of the cell, so ``load (corrected) [mN]`` is ``load (corrected)`` in mN.
"""
_WORDS = re.compile(r"[^\s\[\(]+(?:\s*[\[\(][^\]\)]*[\]\)])?")
"""A cell of a whitespace-separated line: a word with its bracketed unit, ``x [um]``, kept whole."""


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


def _numeric(cell: str) -> bool:
    try:
        float(cell)
    except ValueError:
        return False
    return True


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
    split = (
        (lambda line: next(csv.reader([line], delimiter=delimiter, skipinitialspace=True)))
        if delimiter
        else _WORDS.findall
    )
    rows = [[cell.strip() for cell in split(line)] for line in lines]
    if all(_numeric(cell) for cell in rows[0]):
        return TextTable(None, None, rows, delimiter, comments=comments)
    names, units = zip(*(split_header(cell) for cell in rows[0]), strict=True)
    return TextTable(list(names), list(units), rows[1:], delimiter, rows[0], comments)


def split_header(cell: str) -> tuple[str, str | None]:
    """Split a header cell into its lower-case name and its unit (None where it gives none).

    The unit is written in brackets, ``depth [nm]`` or ``load (mN)`` (the last bracket), or
    after a slash, ``time/s`` (the first slash; a cell starting or ending with one is all name).
    Surrounding double quotes are dropped.

    Examples
    --------
    >>> split_header("Load [mN]"), split_header("time/s"), split_header("step")
    (('load', 'mN'), ('time', 's'), ('step', None))
    """
    text = cell.strip().strip('"').strip()
    match = HEADER_UNIT.match(text)
    if match and match.group(2) is not None:  # a bracket, perhaps empty: "depth ()" has no unit
        return match.group(1).strip().rstrip("/").strip().lower(), match.group(2) or None
    name, slash, unit = text.partition("/")
    if slash and name.strip() and unit.strip():
        return name.strip().lower(), unit.strip()
    return text.lower(), None
