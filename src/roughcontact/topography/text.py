"""Strict reading of plain-text height data: height matrices and x-z / x-y-z columns.

SurfaceTopography's plain-text reader takes every line that does not parse as numbers for a
header line, wherever it stands: a matrix with one corrupt token loses that row without a word
(50 x 50 read as 50 x 49, the later rows shifted), and a comma- or semicolon-separated matrix is
not recognised at all. So a text file is first parsed here, strictly, and handed to
SurfaceTopography (for its header conventions: Gwyddion, SPIP, Wyko, Nova, Dektak) only as the
table found here; :mod:`roughcontact.topography.io` then checks that SurfaceTopography read
exactly that table.

The rules (:func:`parse_table`)
-------------------------------
* The file is text: UTF-8 (with or without a byte-order mark), UTF-16 with a byte-order mark,
  or Latin-1; a NUL byte elsewhere marks a binary file.
* Values are separated by white space (blanks or tabs), commas or semicolons, one separator
  for the whole file; with semicolons or white space a decimal comma (``1,5``) is accepted.
  Separators at the end of a line are ignored (spreadsheet exports write them).
* ``nan``, ``bad``, ``inf`` (any case, any sign) mark an undefined point (NaN).
* The *data* are the lines from the first line of numbers to the last. Lines before them are
  the header (any text, e.g. Gwyddion's ``# Width: 10 µm``, ``# Height: 5 µm``,
  ``# Value units: nm``); lines after them may only be comments (``#``) or empty.
* Every data line holds the same number of numbers. A data line with a token that is not a
  number, a line with more or fewer values, text between data lines, or a header line that
  is mostly numbers of the data's width (a corrupt first row) is refused, naming the line and
  the value.

References
----------
Gwyddion's plain-text export (asciiexport), http://gwyddion.net/documentation/user-guide-en/
"""

from __future__ import annotations

import codecs
import re
from dataclasses import dataclass

import numpy as np

__all__ = ["TextFormatError", "TextTable", "decode_text", "parse_table"]

_UNDEFINED_WORDS = {"nan", "+nan", "-nan", "bad", "inf", "+inf", "-inf", "infinite", "-infinite"}
_COMMENT_STARTS = ("#", "%", "//", "\\", "!")
_SAMPLE_LINES = 64
"""Data lines looked at to choose the separator and decimal mark."""

_DECIMAL_COMMA = re.compile(r"^[+-]?\d*,\d+(?:[eE][+-]?\d+)?$")

# (separator, decimal mark), in order of preference when several read the sample alike
_LAYOUTS: tuple[tuple[str | None, str], ...] = (
    (None, "."),
    (",", "."),
    (";", "."),
    (";", ","),
    (None, ","),
)


class TextFormatError(ValueError):
    """A text file that is not a clean table of numbers.

    Attributes
    ----------
    line : int or None
        1-based line of the file where the problem is (None for the file as a whole).
    problem : str
        What is wrong there, with the value as written.
    """

    def __init__(self, problem: str, line: int | None = None):
        self.line = line
        self.problem = problem
        super().__init__(problem if line is None else f"line {line}: {problem}")


@dataclass(frozen=True)
class TextTable:
    """The numbers of a text file, as :func:`parse_table` found them.

    Attributes
    ----------
    values : ndarray, shape (rows, columns)
        The data lines, NaN where a value is marked undefined.
    header : tuple of str
        The lines before the data, as written.
    first_line : int
        1-based line number of the first data line.
    separator : str or None
        ``","``, ``";"`` or None (white space).
    decimal : str
        ``"."`` or ``","``.
    """

    values: np.ndarray
    header: tuple[str, ...]
    first_line: int
    separator: str | None
    decimal: str

    @property
    def shape(self) -> tuple[int, int]:
        """(rows, columns) of the data."""
        return self.values.shape

    @property
    def layout(self) -> str:
        """The separator and decimal mark in words, e.g. ``"comma-separated"``."""
        words = {None: "whitespace-separated", ",": "comma-separated", ";": "semicolon-separated"}
        return words[self.separator] + (", decimal comma" if self.decimal == "," else "")

    def normalised(self) -> str:
        """Return the file as SurfaceTopography's plain-text readers take it: header, blank-separated data."""
        rows = "\n".join(" ".join(repr(float(v)) for v in row) for row in self.values)
        return "\n".join(self.header) + ("\n" if self.header else "") + rows + "\n"


def decode_text(content: bytes) -> str | None:
    """Return ``content`` as text, or None when it is binary.

    UTF-16 needs its byte-order mark; otherwise a NUL byte means binary. UTF-8 is tried before
    Latin-1 (which decodes any byte, e.g. a ``µ`` written by an old Windows program).
    """
    for mark, encoding in ((codecs.BOM_UTF16_LE, "utf-16"), (codecs.BOM_UTF16_BE, "utf-16")):
        if content.startswith(mark):
            try:
                return content.decode(encoding)
            except UnicodeDecodeError:
                return None
    if b"\x00" in content:
        return None
    try:
        text = content.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = content.decode("latin-1")
    printable = sum(ch.isprintable() or ch in "\t\r\n\f" for ch in text[:4096])
    return text if printable >= 0.95 * min(len(text), 4096) else None


def _tokens(line: str, separator: str | None) -> list[str]:
    stripped = line.strip()
    if separator is not None:
        stripped = stripped.rstrip(separator + " \t")
        return [token.strip() for token in stripped.split(separator)]
    return stripped.split()


def _number(token: str, decimal: str) -> float | None:
    """Return the value of ``token`` (NaN for an undefined marker), or None when it is no number."""
    if token.lower() in _UNDEFINED_WORDS:
        return float("nan")
    if decimal == ",":
        if "." in token or not _DECIMAL_COMMA.match(token) and "," in token:
            return None
        token = token.replace(",", ".")
    try:
        return float(token)
    except ValueError:
        return None


def _row(line: str, layout: tuple[str | None, str]) -> list[float] | None:
    """Return the numbers of a line laid out as ``layout``, or None when a token is not a number."""
    tokens = _tokens(line, layout[0])
    if not tokens or tokens == [""]:
        return None
    values = [_number(token, layout[1]) for token in tokens]
    return None if any(v is None for v in values) else values


def _is_comment(line: str) -> bool:
    return line.lstrip().startswith(_COMMENT_STARTS)


def _choose_layout(lines: list[str]) -> tuple[tuple[str | None, str], int]:
    """Return the (separator, decimal) reading most of the first data-looking lines, and the data width."""
    candidates = [line for line in lines if line.strip() and not _is_comment(line)][: 4 * _SAMPLE_LINES]

    def score(layout):
        rows = [_row(line, layout) for line in candidates]
        widths = [len(r) for r in rows if r is not None][:_SAMPLE_LINES]
        if not widths:
            return (0, 0)
        common = max(widths, key=widths.count)  # on a tie, the width of the first line
        return (widths.count(common), common)

    best = max(_LAYOUTS, key=score)  # max keeps the first of equals: the order of preference
    return best, score(best)[1]


def _first_bad_token(line: str, layout: tuple[str | None, str]) -> tuple[int, str]:
    """(1-based position, token) of the first token of ``line`` that is not a number."""
    for position, token in enumerate(_tokens(line, layout[0]), start=1):
        if _number(token, layout[1]) is None:
            return position, token
    return 0, ""


def _looks_like_data(line: str, layout: tuple[str | None, str], width: int) -> bool:
    """Whether a line that is not all numbers is a damaged data line: the data's width, mostly numbers.

    For a matrix (4 or more columns) half the values being numbers is enough; for columns (x z or
    x y z) all but one, and not the first (a header names its columns: ``Height 5`` is a label).
    """
    tokens = _tokens(line, layout[0])
    numbers = [_number(token, layout[1]) is not None for token in tokens]
    if len(tokens) != width or width < 2:
        return False
    if width >= 4:
        return sum(numbers) >= width // 2
    return sum(numbers) == width - 1 and numbers[0]


def parse_table(text: str) -> TextTable:
    """Read the numbers of a plain-text file strictly (see the module's rules).

    Parameters
    ----------
    text : str
        The file's content.

    Returns
    -------
    TextTable

    Raises
    ------
    TextFormatError
        No line of numbers, a ragged or corrupt data line, text between or after the data, or a
        corrupt first row; the message names the line, the value and what was expected.
    """
    lines = text.splitlines()
    layout, width = _choose_layout(lines)
    parsed = [None if _is_comment(line) else _row(line, layout) for line in lines]
    starts = [i for i, row in enumerate(parsed) if row is not None and len(row) == width]
    if not starts:
        raise TextFormatError("no line holds only numbers: this is not a table of heights.")
    first, last = starts[0], max(i for i, row in enumerate(parsed) if row is not None)
    before = [i for i in range(first) if lines[i].strip() and not _is_comment(lines[i])]
    for index in before:  # numbers before the data: a count or grid line (1-3 values) is header
        row = parsed[index]
        if row is not None and not len(row) < min(width, 4):
            raise TextFormatError(
                f"{len(row)} values, where the data from line {first + 1} on have {width}.", index + 1
            )
    if before and parsed[before[-1]] is None and _looks_like_data(lines[before[-1]], layout, width):
        position, token = _first_bad_token(lines[before[-1]], layout)
        raise TextFormatError(
            f"value {position}, {token!r}, is not a number (the line has the data's width, {width} "
            f"values, and stands right before the data at line {first + 1}).",
            before[-1] + 1,
        )
    rows = []
    for index in range(first, last + 1):
        line = lines[index]
        if not line.strip():
            continue
        row = parsed[index]
        if row is None:
            if _is_comment(line):
                raise TextFormatError(
                    f"a comment between data lines ({line.strip()[:40]!r}); a file holds one table.",
                    index + 1,
                )
            position, token = _first_bad_token(line, layout)
            raise TextFormatError(f"value {position}, {token!r}, is not a number.", index + 1)
        if len(row) != width:
            raise TextFormatError(
                f"{len(row)} values, where the data from line {first + 1} on have {width}.", index + 1
            )
        rows.append(row)
    for index in range(last + 1, len(lines)):
        if lines[index].strip() and not _is_comment(lines[index]):
            raise TextFormatError(
                f"text after the data ({lines[index].strip()[:40]!r}); only comments (#) may follow it.",
                index + 1,
            )
    return TextTable(
        values=np.array(rows, dtype=float),
        header=tuple(lines[:first]),
        first_line=first + 1,
        separator=layout[0],
        decimal=layout[1],
    )
