"""Files opened with SurfaceTopography: gzip, text tables held to what they hold, failures said."""

from __future__ import annotations

import gzip
import io
import math
import zlib
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from datetime import date, datetime
from pathlib import Path
from typing import Any

import numpy as np

from ..._files import first_line
from ...errors import InputError, UnsupportedFormatError
from ..text import TextFormatError, TextTable, decode_text, parse_table
from .checks import same_name
from .metadata import REREAD_FIX
from .positions import positions_of

_GZIP_MAGIC = b"\x1f\x8b"


@contextmanager
def _reader_errors(path: Path) -> Iterator[None]:
    """Turn any failure inside SurfaceTopography into an UnsupportedFormatError naming ``path``.

    SurfaceTopography's readers raise many exception types (its ReadFileError family, but also
    ValueError, IndexError, struct.error, UnicodeDecodeError, ...), so everything except our
    own errors and MemoryError is translated, with the original chained.
    """
    from SurfaceTopography.Exceptions import CannotDetectFileFormat, CorruptFile

    try:
        yield
    except (InputError, MemoryError):
        raise
    except CannotDetectFileFormat as error:
        raise UnsupportedFormatError(
            str(path),
            "no reader recognises this file (unknown format, or the file is damaged or truncated).",
            REREAD_FIX,
        ) from error
    except CorruptFile as error:
        raise UnsupportedFormatError(
            str(path), f"the file is damaged: {first_line(error)}", REREAD_FIX
        ) from error
    except Exception as error:
        raise UnsupportedFormatError(
            str(path), f"reading failed ({type(error).__name__}: {first_line(error)}).", REREAD_FIX
        ) from error


def _decompressed(path: Path) -> io.BytesIO | str:
    """Return the file itself, or its content in memory when it is gzip-compressed."""
    with path.open("rb") as stream:
        if stream.read(len(_GZIP_MAGIC)) != _GZIP_MAGIC:
            return str(path)
    try:
        content = gzip.decompress(path.read_bytes())
    except (OSError, EOFError, zlib.error) as error:
        raise UnsupportedFormatError(
            str(path), f"the gzip archive is damaged or truncated ({first_line(error)}).", REREAD_FIX
        ) from error
    if not content:
        raise UnsupportedFormatError(str(path), "the gzip archive holds an empty file.", REREAD_FIX)
    return io.BytesIO(content)


_LOOSE_TEXT_READERS = ("asc", "xyz")
"""SurfaceTopography's readers that guess the layout of a text file (checked by :mod:`.text`)."""


_SIZE_ONLY_READERS = ("hgt",)
"""SurfaceTopography's readers that recognise a file by its size alone (NASA SRTM: n x n int16)."""


def _text_content(source: io.BytesIO | str) -> str | None:
    """Return the file as text when it is a text file (see :func:`.text.decode_text`), else None."""
    if isinstance(source, io.BytesIO):
        return decode_text(source.getvalue())
    with open(source, "rb") as stream:
        if decode_text(stream.read(1 << 16)) is None:
            return None
        return decode_text(Path(source).read_bytes())


def _grid_agrees(reader, table: TextTable) -> bool:
    """Whether SurfaceTopography read exactly the table that :func:`.text.parse_table` found."""
    if len(reader.channels) != 1:
        return False
    grid = tuple(int(n) for n in reader.channels[0].nb_grid_pts)
    rows, columns = table.shape
    if reader.format() == "xyz":
        return columns in (2, 3) and math.prod(grid) == rows
    if columns == 1 or rows == 1:
        return grid == (rows * columns,)
    return grid == (columns, rows)


def _checked_text_reader(path: Path, text: str, reader, tried: str):
    """Return a reader of a text file that reads exactly its strict table, or refuse the file.

    ``reader`` is SurfaceTopography's own guess (None when it found none), ``tried`` says what
    it tried. A comma- or semicolon-separated table (or one with decimal commas) is handed to
    SurfaceTopography blank-separated, header unchanged.
    """
    import SurfaceTopography

    try:
        table = parse_table(text)
    except TextFormatError as error:
        if error.line is None:
            fix = (
                "give an instrument file, or heights as a table of numbers (a matrix or x z / x y z columns)."
            )
        else:
            fix = (
                "correct that line in a text editor, or export the file again: plain-text heights are "
                "read only when every data line holds the same number of numbers (nan marks an "
                "undefined point), 4 or more for a height matrix (2 or 3 columns are x z or x y z points)."
            )
        raise UnsupportedFormatError(
            str(path), f"is not a clean table of numbers: {error} {tried}", fix
        ) from error
    if reader is not None and reader.format() not in _SIZE_ONLY_READERS and _grid_agrees(reader, table):
        return reader, table
    if reader is not None:
        reader.close()
    reader = SurfaceTopography.open_topography(io.BytesIO(table.normalised().encode()))
    if not _grid_agrees(reader, table):
        found = " x ".join(map(str, reader.channels[0].nb_grid_pts)) if reader.channels else "nothing"
        reader.close()
        raise UnsupportedFormatError(
            str(path),
            f"holds a {table.shape[0]} x {table.shape[1]} table of numbers ({table.layout}), "
            f"but SurfaceTopography reads {found} from it.",
            "write the heights as a matrix (one line per y, one value per x) or as x z / x y z columns.",
        )
    return reader, table


def _opened(path: Path, source: io.BytesIO | str):
    """Open ``source`` with SurfaceTopography, holding its guesses to what the content is.

    A text file read by a reader that guesses its layout (plain-text matrices, x-y-z columns) must
    be the clean table :func:`.text.parse_table` finds; a file recognised by its size alone (NASA
    SRTM) is taken only when it is binary and named ``.hgt``. Returns the reader and that table
    (None for a file read otherwise).
    """
    import SurfaceTopography
    from SurfaceTopography.Exceptions import CannotDetectFileFormat

    text = _text_content(source)
    try:
        reader = SurfaceTopography.open_topography(source)
    except CannotDetectFileFormat:
        if text is None:
            raise
        reader = None
    guessed = None if reader is None else reader.format()
    tried = (
        "No instrument format matches it either."
        if reader is None
        else f"(SurfaceTopography's {reader.name()!r} reader would accept it without this check.)"
    )
    if text is not None and (reader is None or guessed in _LOOSE_TEXT_READERS + _SIZE_ONLY_READERS):
        return _checked_text_reader(path, text, reader, tried)
    if guessed in _SIZE_ONLY_READERS and path.suffix.lower() != ".hgt":
        reader.close()
        raise UnsupportedFormatError(
            str(path),
            "no reader recognises this file by its content; only the NASA SRTM elevation reader "
            "would take it, by its size alone (2 bytes per point of a square grid), and it is not "
            "named .hgt.",
            REREAD_FIX,
        )
    return reader, None


@contextmanager
def open_reader(path: Path):
    """Open ``path`` (decompressing gzip) with SurfaceTopography; close the reader afterwards.

    Yields the reader and, for a text file of points, its position columns (:func:`positions_of`;
    None otherwise). Failures inside the ``with`` block that uses the reader are reported as in
    :func:`_reader_errors`, since any access to the reader may parse more of the file.
    """
    source = _decompressed(path)
    with _reader_errors(path):
        reader, table = _opened(path, source)
        try:
            yield reader, positions_of(path, reader, table)
        finally:
            reader.close()


def uniform_heights(measured) -> tuple[np.ndarray, tuple[float, ...], list[str]]:
    """Return heights (undefined points as NaN), the grid extent in file units and history steps.

    A non-uniform line scan is interpolated linearly onto equally spaced points over the same
    x range.
    """
    if measured.is_uniform:
        heights = np.ma.filled(np.ma.asarray(measured.heights(), dtype=float), np.nan)
        return heights, tuple(float(s) for s in measured.physical_sizes), []
    positions, heights = measured.positions_and_heights()
    heights = np.ma.filled(np.ma.asarray(heights, dtype=float), np.nan)
    if np.any(np.diff(positions) <= 0):
        raise ValueError("the x positions of the line scan are not increasing")
    n = len(positions)
    grid = np.linspace(positions[0], positions[-1], n)
    spacing = (positions[-1] - positions[0]) / (n - 1)
    step = (
        f"interpolated {n} non-uniformly spaced points linearly onto a uniform grid "
        f"(largest shift {np.max(np.abs(positions - grid)) / spacing:.2g} pixel)"
    )
    return np.interp(grid, positions, heights), (n * spacing,), [step]


def file_info(
    path: Path,
    reader,
    channel,
    measured_info: Mapping[str, Any],
    file_units: tuple[str | None, str | None],
    user_height_unit: str | None,
) -> dict[str, Any]:
    """Return the ``info`` of a topography read from ``channel`` of a file (format, channel, units, ...)."""
    file_size_unit, file_height_unit = file_units
    info: dict[str, Any] = {
        "name": path.name,
        "source": str(path),
        "file_format": reader.name(),
        "channel": str(channel.name),
        "channel_index": int(channel.index),
        "channel_shares_name_with": tuple(same_name(reader, channel)),
        "data_source": str(getattr(channel, "channel_id", channel.name)),
        "height_unit": file_height_unit if file_height_unit is not None else user_height_unit,
        "height_unit_from": "file" if file_height_unit is not None else "user",
        "size_unit": file_size_unit,
    }
    for key in ("instrument", "acquisition_time"):
        if key in measured_info:
            info[key] = _info_value(measured_info[key])
    return info


def _info_value(value: Any) -> Any:
    """Convert reader metadata to values the native format stores exactly (dicts with str keys, tuples, ...).

    Not :func:`roughcontact._json.json_ready`, which serves ``json.dumps`` output: that one turns
    tuples into lists and NaN into None and passes arrays, dates and other objects through, while
    ``info`` keeps tuples and NaN, and needs arrays as tuples and dates and objects as text.
    """
    if isinstance(value, Mapping):
        return {str(k): _info_value(v) for k, v in value.items()}
    if isinstance(value, list | tuple | np.ndarray):
        return tuple(_info_value(v) for v in value)
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, datetime | date):
        return value.isoformat()
    if value is None or isinstance(value, str | bool | int | float):
        return value
    return str(value)
