"""Small text tables: CSV, semicolon, tab or whitespace separated, with an optional ``name [unit]`` header.

The tokenising shared by the readers of measured friction loops
(:func:`roughcontact.experiment.friction_loop.read_loop_csv`) and of tangential loading
programmes (:func:`roughcontact.contact.paths.read_path_csv`); each reader gives the columns
their meaning and converts their units (through :mod:`roughcontact.units`).
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path

from .errors import InputError

HEADER_UNIT = re.compile(r"^\s*([^\[\(]*?)\s*(?:[\[\(]\s*([^\]\)]*?)\s*[\]\)])?\s*$")
"""A header cell ``name [unit]`` or ``name (unit)``: group 1 the name, group 2 the unit (or None)."""
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
        The unit written in brackets after each name, None where there is none.
    rows : list of list of str
        The data rows, cells stripped, not converted.
    """

    names: list[str] | None
    units: list[str | None] | None
    rows: list[list[str]]

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

    The first line is a header when one of its cells is not a number. The separator is the
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
    lines = [
        line.strip()
        for line in path.read_text(encoding="utf-8-sig").splitlines()
        if line.strip() and not line.lstrip().startswith("#")
    ]
    if not lines:
        raise InputError("path", f"{path} has no data lines.", f"give {expected}.")
    if delimiter is None:
        delimiter = next((d for d in (",", ";", "\t") if d in lines[0]), None)
    split = (lambda line: next(csv.reader([line], delimiter=delimiter))) if delimiter else _WORDS.findall
    rows = [[cell.strip() for cell in split(line)] for line in lines]
    if all(_numeric(cell) for cell in rows[0]):
        return TextTable(None, None, rows)
    names, units = [], []
    for cell in rows[0]:
        match = HEADER_UNIT.match(cell)
        names.append((match.group(1) if match else cell).strip().lower())
        units.append(match.group(2) if match and match.group(2) else None)
    return TextTable(names, units, rows[1:])
