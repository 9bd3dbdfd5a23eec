"""Read measured topographies from instrument files.

Instrument files are read through SurfaceTopography, which recognises the format from the
file's content (AFM: Bruker ``.di``, Asylum ``.ibw``, Nanosurf ``.nid``, WSxM ``.top``;
optical/confocal: Sensofar ``.plu``, Alicona ``.al3d``; Digital Surf ``.sur``; ISO 5436-2
``.x3p``; stylus profilers; plain-text matrices and x-y-z columns; ... ). Gzip-compressed
files are decompressed in memory first, whatever their name.

Everything returned is SI: lengths and heights are converted to metres with the units the
file declares. What a file does not declare (the scan size of a bare height matrix, the
unit of its heights) must be given by the user; it is never guessed. Undefined (missing)
points are refused unless the user asks for them to be interpolated; they are never set to
zero. A file that cannot be read raises :class:`~roughcontact.errors.UnsupportedFormatError`
naming the file, with SurfaceTopography's own exception chained.

roughcontact's own NetCDF files (written by
:func:`~roughcontact.topography.native.save_topography`, see :mod:`roughcontact.topography.native`)
are recognised by their format marker and read here too, with the same options.

References
----------
SurfaceTopography (ContactEngineering), https://github.com/ContactEngineering/SurfaceTopography
"""

from __future__ import annotations

import gzip
import io
import math
import os
import shlex
import zlib
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import asdict, dataclass
from datetime import date, datetime
from pathlib import Path
from typing import Any

import numpy as np

from .._files import existing_file, first_line
from ..checks import positive
from ..errors import (
    InputError,
    MissingMetadataError,
    UndefinedPointsError,
    UnitError,
    UnsupportedFormatError,
)
from ..units import format_si, length_unit_factor, quantity
from .channels import ChannelKind, classify_channel
from .file_cache import ConvertedCopy
from .native import channel_name, is_native_file, read_native
from .process import crop as crop_topography
from .process import crop_window, fill_undefined, find_specks
from .surface import Topography
from .text import TextFormatError, TextTable, decode_text, parse_table

__all__ = ["ChannelInfo", "channel_of", "channel_words", "list_channels", "read_topography"]

_GZIP_MAGIC = b"\x1f\x8b"
_UNDEFINED_CHOICES = ("refuse", "interpolate")

READER_VERSION = 1
"""Version of what :func:`read_scan` makes of an instrument file: raise it when the same file would
read otherwise (other heights, size, info), so that converted copies of older reads are not used
(:mod:`roughcontact.topography.file_cache`)."""

MAX_FILLED = 0.05
"""Largest fraction of a file's points that filling undefined points may invent without being told more."""


def max_filled_allowing(fraction: float) -> float:
    """Return the ``max_filled`` to offer for a file with ``fraction`` undefined (the next whole percent)."""
    return math.ceil(100 * fraction) / 100


_REREAD_FIX = (
    "copy the file again from the instrument or export it again (e.g. as .x3p, .sur or a "
    "plain-text height matrix); roughcontact reads the formats SurfaceTopography reads."
)

PathLike = str | os.PathLike
SizeLike = float | str | tuple[float | str, ...]
CropLike = tuple


@dataclass(frozen=True)
class ChannelInfo:
    """One data channel of a topography file, as listed by :func:`list_channels`.

    Parameters
    ----------
    index : int
        Position of the channel in the file (what ``read_topography(channel=index)`` takes).
    name : str
        Channel name as in the file (what ``read_topography(channel=name)`` takes).
    shape : tuple of int
        Number of grid points along x (and y).
    size : tuple of float or None
        Physical size [m] along each axis; None when the file gives no size with a unit.
    height_unit : str or None
        Unit the values are stored in, as written in the file (``"nm"``, ``"µm"``, ``"m"``; a
        non-length unit such as ``"deg"`` or ``"V"`` marks a channel that holds no heights).
    size_unit : str or None
        Unit of the lateral sizes in the file.
    is_default : bool
        Whether this is the file's default channel (read when ``channel`` is not given).
    is_height : bool
        Whether the channel holds heights (:func:`roughcontact.topography.channels.classify_channel`:
        its name, unit and data kind); a computation refuses the others.
    holds : str
        What a channel that holds no heights holds, and how that was seen (empty for heights).
    """

    index: int
    name: str
    shape: tuple[int, ...]
    size: tuple[float, ...] | None
    height_unit: str | None
    size_unit: str | None
    is_default: bool
    is_height: bool = True
    holds: str = ""


# --- public functions ------------------------------------------------------------------------------


def list_channels(path: PathLike) -> list[ChannelInfo]:
    """List the data channels of a topography file without reading the heights.

    Parameters
    ----------
    path : str or path-like
        Instrument file (any format SurfaceTopography reads, optionally gzip-compressed) or a
        roughcontact ``.nc`` file.

    Returns
    -------
    list of ChannelInfo
        One entry per channel, in file order; exactly one has ``is_default=True``.

    Raises
    ------
    UnsupportedFormatError
        A missing, empty, unknown or damaged file.
    """
    path = existing_file(path, empty_fix=_REREAD_FIX)
    if is_native_file(path):
        topography = read_native(path)
        return [
            ChannelInfo(
                0,
                channel_name(topography),
                topography.shape,
                topography.size,
                "m",
                "m",
                True,
            )
        ]
    copy = ConvertedCopy(path, "channels", {}, READER_VERSION)
    found = copy.load("channels")
    if found is not None:
        return [ChannelInfo(**channel) for channel in found[0]["channels"]]
    with _open_reader(path) as reader:
        default = reader.default_channel.index
        channels = [_channel_info(channel, channel.index == default) for channel in reader.channels]
    copy.store({"channels": tuple(asdict(channel) for channel in channels)})
    return channels


def read_topography(
    path: PathLike,
    *,
    channel: int | str | None = None,
    size: SizeLike | None = None,
    height_unit: str | None = None,
    crop: CropLike | None = None,
    undefined: str = "refuse",
    max_filled: float = MAX_FILLED,
    remove_specks: bool = False,
    periodic: bool = False,
    treat_as_height: bool = False,
    override_file_values: bool = False,
) -> Topography:
    """Read one channel of a topography file into a :class:`Topography` in SI units.

    Sizes and heights are converted to metres from the units the file declares:
    ``heights [m] = stored value * factor(unit)`` with factor("nm") = 1e-9 etc. A non-uniform
    line scan (x positions not equally spaced, e.g. a profilometer export with rounded
    positions) is interpolated linearly onto n equally spaced points spanning the same x range,
    so its size is ``n / (n - 1)`` times that range (recorded in ``info['history']``).

    Parameters
    ----------
    path : str or path-like
        Instrument file (any format SurfaceTopography reads, optionally gzip-compressed) or a
        roughcontact ``.nc`` file written by :func:`~roughcontact.topography.native.save_topography`.
    channel : int or str, optional
        Channel index or name (see :func:`list_channels`); default: the file's default channel.
        A name that two channels share is refused (choose by index). Only channels that hold
        heights are read (:mod:`roughcontact.topography.channels`).
    size : float or str or tuple, optional
        Physical scan size: metres as a float, or a string with a unit (``"10 um"``); one value
        (square map or a profile) or one per axis (``("10 um", "20 um")``). Required when the
        file has no size; when the file has one, a different size is refused unless
        ``override_file_values`` (then ``info['size_in_file']`` keeps the file's).
    height_unit : str, optional
        Unit of the stored heights (``"nm"``, ``"um"``, ...). Required when the file declares
        none; a unit other than the file's is refused unless ``override_file_values``.
    crop : tuple, optional
        Read only a window: ``((x0, x1), (y0, y1))`` (``(x0, x1)`` for a profile), metres as
        floats or strings with a unit (``("0 mm", "20 mm")``), half-open as in
        :func:`~roughcontact.topography.process.crop`; cut before undefined points are counted or
        filled, so a window without them needs no filling.
    undefined : {"refuse", "interpolate"}
        What to do with undefined (missing) points: refuse the file, or fill them by harmonic
        interpolation (:func:`roughcontact.topography.process.fill_undefined`), recording the
        count in ``info['undefined_points_filled']``.
    max_filled : float
        Largest fraction of the points that ``undefined="interpolate"`` may fill (default
        :data:`MAX_FILLED`, 5 %). Filling more invents much of the surface (SurfaceTopography's
        ``frt-2.frt`` lacks 27 %), so it must be asked for explicitly: ``max_filled=0.3``.
    remove_specks : bool
        Make the specks (measured points in groups of fewer than ten standing alone amid
        undefined ones, :func:`~roughcontact.topography.process.find_specks`) undefined before
        filling: they are often outliers, and filled around they stand up as spikes. Kept, they
        are marked in ``specks`` (contact results report the load they carry).
    periodic : bool
        Treat the surface as periodic (measured surfaces are not, as a rule). A file that
        declares itself periodic (a roughcontact or SurfaceTopography ``.nc`` file) stays so.
    treat_as_height : bool
        Read a channel whose name or data kind says it holds no heights (phase, amplitude,
        error, ...) as heights anyway, for a file whose channels are misnamed. A channel whose
        values are in a unit that is not a length is refused all the same.
    override_file_values : bool
        Use ``size`` and ``height_unit`` where the file stores other values (a file whose
        metadata are known to be wrong); without it such a clash is refused, showing both.

    Returns
    -------
    Topography
        Heights [m] and size [m]. ``info`` (JSON-ready) holds ``source``, ``name``,
        ``file_format``, ``channel``, ``data_source`` (SurfaceTopography's channel id),
        ``height_unit`` and ``size_unit`` as in the file, ``instrument`` and
        ``acquisition_time`` where the file gives them, and ``history``.

    Raises
    ------
    UnsupportedFormatError
        A missing, empty, unknown, truncated or damaged file.
    InputError
        Unknown channel, a channel that holds no heights, size or height unit missing from
        both the file and the arguments, a height unit that contradicts the file, undefined
        points with ``undefined="refuse"``.

    Examples
    --------
    >>> read_topography("afm.txt", size="5 um", height_unit="nm")  # doctest: +SKIP
    """
    if undefined not in _UNDEFINED_CHOICES:
        raise InputError("undefined", f"unknown choice {undefined!r}.", "choose 'refuse' or 'interpolate'.")
    if positive(max_filled, "max_filled", example="0.3", allow_zero=True) > 1:
        raise InputError(
            "max_filled", f"{max_filled!r} is not a fraction from 0 to 1.", "e.g. max_filled=0.3."
        )
    scan = read_scan(
        path,
        channel=channel,
        size=size,
        height_unit=height_unit,
        periodic=periodic,
        treat_as_height=treat_as_height,
        override_file_values=override_file_values,
    )
    window = None if crop is None else crop_metres(crop, len(scan.size))
    if isinstance(scan, Topography):
        return scan if window is None else crop_topography(scan, *window)
    if window is not None:
        scan = scan.cropped(*window)
    return scan.topography(undefined=undefined, max_filled=max_filled, remove_specks=remove_specks)


@dataclass(frozen=True)
class Scan:
    """A file's heights as stored (undefined points kept as NaN) with its size and metadata, SI.

    What :func:`read_scan` returns for a file with undefined points, so that the file can be
    described (``roughcontact inspect``) before anything that needs every point is asked of it.

    Attributes
    ----------
    heights : ndarray
        Heights [m]; NaN where the instrument recorded no value.
    size : tuple of float
        Physical size [m] per axis.
    periodic : bool
    info : dict
        As :func:`read_topography`'s ``info``.
    path : Path
        The file.
    """

    heights: np.ndarray
    size: tuple[float, ...]
    periodic: bool
    info: dict[str, Any]
    path: Path

    @property
    def undefined(self) -> np.ndarray:
        """True where the file holds no height."""
        return ~np.isfinite(self.heights)

    def cropped(self, x: tuple[float, float] | None, y: tuple[float, float] | None = None) -> Scan:
        """Return the window ``x`` x ``y`` [m] of the scan (as :func:`~.process.crop` does)."""
        spacing = tuple(s / n for s, n in zip(self.size, self.heights.shape, strict=True))
        window = crop_window(self.heights.shape, spacing, x, y)
        heights = self.heights[window]
        size = tuple(n * h for n, h in zip(heights.shape, spacing, strict=True))
        info = dict(self.info)
        info["history"] = (*info.get("history", ()), f"crop(x={x}, y={y})")
        info["cropped_from"] = tuple(self.heights.shape)
        return Scan(heights, size, False, info, self.path)

    def topography(
        self, *, undefined: str = "refuse", max_filled: float = MAX_FILLED, remove_specks: bool = False
    ) -> Topography:
        """Return the scan as a :class:`Topography`, its undefined points refused or filled.

        See :func:`read_topography` for ``undefined``, ``max_filled`` and ``remove_specks``. The
        filled points and the specks are marked on the topography (``filled``, ``specks``).
        """
        info = dict(self.info)
        steps = list(info.pop("history", ()))
        heights = self.heights
        specks = find_specks(self.undefined)
        if remove_specks and specks.any():
            heights = np.where(specks, np.nan, heights)
            count = int(np.count_nonzero(specks))
            steps.append(
                f"remove_specks: {count} measured points standing alone amid undefined ones set undefined"
            )
            info["specks_removed"] = count
            specks = None
        missing = ~np.isfinite(heights)
        heights, filled = _handle_undefined(heights, undefined, max_filled, self.path)
        if filled:
            info["undefined_points_filled"] = filled
            steps.append(f"fill_undefined: {filled} undefined points interpolated (harmonic)")
        info["history"] = tuple(steps)
        return Topography(
            heights, self.size, periodic=self.periodic, info=info, filled=missing, specks=specks
        )


def read_scan(
    path: PathLike,
    *,
    channel: int | str | None = None,
    size: SizeLike | None = None,
    height_unit: str | None = None,
    periodic: bool = False,
    treat_as_height: bool = False,
    override_file_values: bool = False,
) -> Scan | Topography:
    """Read one channel of a file as stored: a :class:`Scan` (NaN where undefined), SI units.

    As :func:`read_topography` without deciding about undefined points; a roughcontact ``.nc``
    file (never holding undefined points) is returned as the :class:`Topography` it is. An
    instrument file read before with the same options is served from its converted copy,
    without loading the readers (:mod:`roughcontact.topography.file_cache`).
    """
    path = existing_file(path, empty_fix=_REREAD_FIX)
    if is_native_file(path):
        topography = read_native(path, channel=channel)
        return _with_options(topography, path, size, height_unit, periodic, override_file_values)
    options = {
        "channel": channel,
        "size": size,
        "height_unit": height_unit,
        "periodic": periodic,
        "treat_as_height": treat_as_height,
        "override_file_values": override_file_values,
    }
    copy = ConvertedCopy(path, "scan", options, READER_VERSION)
    found = copy.load("size", "periodic", "info")
    if found is not None:
        record, heights = found
        return Scan(heights, record["size"], record["periodic"], record["info"], path)
    scan = _read_instrument_file(path, **options)
    copy.store({"size": scan.size, "periodic": scan.periodic, "info": scan.info}, scan.heights)
    return scan


def _read_instrument_file(
    path: Path,
    *,
    channel: int | str | None,
    size: SizeLike | None,
    height_unit: str | None,
    periodic: bool,
    treat_as_height: bool,
    override_file_values: bool,
) -> Scan:
    """Read one channel of an instrument file with SurfaceTopography (:func:`read_scan`'s options)."""
    with _open_reader(path) as reader:
        selected = _select_channel(reader, channel, path)
        file_size_unit, file_height_unit = _file_units(selected)
        _check_height_channel(selected, reader, treat_as_height)
        _require_metadata(path, reader, selected, (file_size_unit, file_height_unit), size, height_unit)
        user_size = None if size is None else _user_size(size, selected.dim)
        height_factor = _height_factor(path, file_height_unit, height_unit, override_file_values)
        dummy_size = None if selected.physical_sizes is not None else tuple(map(float, selected.nb_grid_pts))
        measured = reader.topography(channel_index=selected.index, physical_sizes=dummy_size)
        heights, extent, steps = _uniform_heights(measured)
        periodic = periodic or bool(measured.is_periodic)
        info = _file_info(
            path, reader, selected, measured.info, (file_size_unit, file_height_unit), height_unit
        )
    heights = heights * height_factor
    file_size = _size_in_metres(extent, file_size_unit) if selected.physical_sizes is not None else None
    info["size_from"] = "file" if user_size is None else "user"
    if user_size is None:
        physical_size = file_size
    else:
        physical_size = user_size
        if file_size is not None:
            _size_agrees(path, file_size, user_size, override_file_values)
            info["size_in_file"] = file_size
        elif selected.physical_sizes is not None:
            info["size_in_file_without_unit"] = tuple(map(float, extent))
    info["history"] = (f"read {path.name} channel {selected.name!r} ({reader.name()})", *steps)
    return Scan(heights, tuple(float(s) for s in np.atleast_1d(physical_size)), periodic, info, path)


def channel_of(info: Mapping[str, Any]) -> dict[str, Any] | None:
    """Return the channel a topography was read from: ``{"name", "index", "shares_name_with"}``.

    None for a topography that was not read from a file channel (generated, combined).
    """
    if "channel" not in info:
        return None
    return {
        "name": info["channel"],
        "index": info.get("channel_index"),
        "shares_name_with": list(info.get("channel_shares_name_with", ())),
    }


def channel_words(channel: Mapping[str, Any]) -> str:
    """Return a channel in words: ``'Height' (index 0; index 1 has the same name)``."""
    words = f"{channel['name']!r}"
    if channel.get("index") is not None:
        words += f" (index {channel['index']}"
        others = channel.get("shares_name_with") or []
        if others:
            one = len(others) == 1
            indices = ", ".join(map(str, others))
            words += f"; {'index' if one else 'indices'} {indices} {'has' if one else 'have'} the same name"
        words += ")"
    return words


# --- files and SurfaceTopography -----------------------------------------------------------------


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
            _REREAD_FIX,
        ) from error
    except CorruptFile as error:
        raise UnsupportedFormatError(
            str(path), f"the file is damaged: {first_line(error)}", _REREAD_FIX
        ) from error
    except Exception as error:
        raise UnsupportedFormatError(
            str(path), f"reading failed ({type(error).__name__}: {first_line(error)}).", _REREAD_FIX
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
            str(path), f"the gzip archive is damaged or truncated ({first_line(error)}).", _REREAD_FIX
        ) from error
    if not content:
        raise UnsupportedFormatError(str(path), "the gzip archive holds an empty file.", _REREAD_FIX)
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
        return reader
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
    return reader


def _opened(path: Path, source: io.BytesIO | str):
    """Open ``source`` with SurfaceTopography, holding its guesses to what the content is.

    A text file read by a reader that guesses its layout (plain-text matrices, x-y-z columns) must
    be the clean table :func:`.text.parse_table` finds; a file recognised by its size alone (NASA
    SRTM) is taken only when it is binary and named ``.hgt``.
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
            _REREAD_FIX,
        )
    return reader


@contextmanager
def _open_reader(path: Path):
    """Open ``path`` (decompressing gzip) with SurfaceTopography; close the reader afterwards.

    Failures inside the ``with`` block that uses the reader are reported as in
    :func:`_reader_errors`, since any access to the reader may parse more of the file.
    """
    source = _decompressed(path)
    with _reader_errors(path):
        reader = _opened(path, source)
        try:
            yield reader
        finally:
            reader.close()


def _file_units(channel) -> tuple[str | None, str | None]:
    """Return (size unit, height unit) of a SurfaceTopography channel as written in the file.

    Some readers (Bruker .di) give ``unit = (lateral unit, data unit)`` for non-height channels.
    """
    unit, data_unit = channel.unit, channel.data_unit
    size_unit = unit[0] if isinstance(unit, tuple) else unit
    height_unit = data_unit[1] if isinstance(data_unit, tuple) else data_unit
    return size_unit, height_unit


def _length_factor(unit: str | None) -> float | None:
    """Factor to metres of a unit from a file, or None when it is absent or not a length."""
    if unit is None:
        return None
    try:
        return length_unit_factor(unit)
    except UnitError:
        return None


def _size_in_metres(extent: tuple[float, ...], unit: str | None) -> tuple[float, ...] | None:
    factor = _length_factor(unit)
    return None if factor is None else tuple(float(s) * factor for s in extent)


def _grid_extent(channel) -> tuple[float, ...]:
    """Size of the grid in file units: a non-uniform scan of n points spans (n-1) uniform pixels."""
    extent = tuple(float(s) for s in channel.physical_sizes)
    if channel.is_uniform:
        return extent
    return tuple(s * n / (n - 1) for s, n in zip(extent, channel.nb_grid_pts, strict=True))


def _kind(channel) -> ChannelKind:
    """Whether a SurfaceTopography channel holds heights (:func:`.channels.classify_channel`)."""
    unit = _file_units(channel)[1]
    data_kind = getattr(channel, "data_kind", None)
    return classify_channel(
        str(channel.name),
        unit,
        None if unit is None else _length_factor(unit) is not None,
        None if data_kind is None else getattr(data_kind, "name", str(data_kind)),
    )


def _channel_info(channel, is_default: bool) -> ChannelInfo:
    size_unit, height_unit = _file_units(channel)
    size = None if channel.physical_sizes is None else _size_in_metres(_grid_extent(channel), size_unit)
    kind = _kind(channel)
    return ChannelInfo(
        index=int(channel.index),
        name=str(channel.name),
        shape=tuple(int(n) for n in channel.nb_grid_pts),
        size=size,
        height_unit=height_unit,
        size_unit=size_unit,
        is_default=is_default,
        is_height=kind.is_height,
        holds=kind.reason,
    )


def _select_channel(reader, channel: int | str | None, path: Path):
    """Return the SurfaceTopography channel chosen by index or name (default: the file's).

    A name that several channels share is refused, naming their indices.
    """
    channels = reader.channels
    if channel is None:
        return reader.default_channel
    if isinstance(channel, str):
        matches = [c for c in channels if c.name == channel]
    elif isinstance(channel, int | np.integer) and not isinstance(channel, bool):
        matches = [c for c in channels if c.index == channel]
    else:
        raise InputError(
            "channel",
            f"expected a channel index or name, got {type(channel).__name__}.",
            f"give an index or a name: {_channel_list(reader)}.",
        )
    if not matches:
        raise _channel_error(
            f"{path.name} has no channel {channel!r}.",
            [int(c.index) for c in channels if _kind(c).is_height],
            False,
            reader,
        )
    if len(matches) > 1:
        indices = " and ".join(str(c.index) for c in matches)
        raise _channel_error(
            f"{path.name} has {len(matches)} channels named {channel!r}: indices {indices}.",
            [int(c.index) for c in matches],
            False,
            reader,
        )
    return matches[0]


def _same_name(reader, channel) -> list[int]:
    """Return the indices of the other channels named like ``channel``."""
    return [int(c.index) for c in reader.channels if c.name == channel.name and c.index != channel.index]


def _channel_list(reader) -> str:
    """Every channel as ``0: 'ZSensor' (heights), 2: 'Phase' (not heights)``."""
    return ", ".join(
        f"{c.index}: {c.name!r} ({'heights' if _kind(c).is_height else 'not heights'})"
        for c in reader.channels
    )


def _check_height_channel(channel, reader, treat_as_height: bool) -> None:
    """Refuse a channel that holds no heights (phase, amplitude, error, a unit that is no length)."""
    kind = _kind(channel)
    if kind.is_height or (treat_as_height and kind.unit_is_length is not False):
        return
    raise _channel_error(
        f"channel {channel.index} ({channel.name!r}) holds {kind.reason}, not heights.",
        [int(c.index) for c in reader.channels if _kind(c).is_height],
        kind.unit_is_length is not False,
        reader,
    )


def _channel_error(problem: str, choices: list[int], override: bool, reader) -> InputError:
    """Return the refusal of a channel, offering ``choices`` (and ``treat_as_height`` with ``override``)."""
    fixes = {}
    for style, choose, flag in (
        ("python", "channel={}", "treat_as_height=True"),
        ("study", "channel = {}", "treat_as_height = true"),
        ("cli", "--channel {}", "--treat-as-height"),
    ):
        if choices:
            options = " or ".join(choose.format(index) for index in choices[:3])
            fix = f"choose a channel by its index, {options} ({_channel_list(reader)})"
        else:
            fix = f"this file has no height channel ({_channel_list(reader)})"
        if override:
            fix += f"; if this channel does hold heights (a misnamed channel), add {flag}"
        fixes[style] = fix + "."
    return InputError("channel", problem, fixes["python"], fixes=fixes)


def _require_metadata(
    path: Path,
    reader,
    channel,
    file_units: tuple[str | None, str | None],
    size: SizeLike | None,
    height_unit: str | None,
) -> None:
    """Raise one InputError listing everything the file lacks and the user did not give."""
    file_size_unit, file_height_unit = file_units
    size_known = channel.physical_sizes is not None and _length_factor(file_size_unit) is not None
    missing, notes = [], []
    if size is None and not size_known:
        in_file = (
            ""
            if channel.physical_sizes is None
            else (f" (it gives {' x '.join(f'{float(s):g}' for s in channel.physical_sizes)} without a unit)")
        )
        missing.append(("size", f"no physical scan size{in_file}", 'size="5 um"', '--size "5 um"', "5 um"))
        if channel.dim == 2:
            notes.append('a non-square scan takes size=("5 um", "10 um") or --size "5 um x 10 um"')
    if height_unit is None and file_height_unit is None:
        missing.append(("height_unit", "no height unit", 'height_unit="nm"', "--height-unit nm", "nm"))
    if not missing:
        return
    what = " and ".join(m[1] for m in missing)
    python = ", ".join(m[2] for m in missing)
    cli = " ".join(m[3] for m in missing)
    noted = "".join(f"; {note}" for note in notes) + "."
    error = MissingMetadataError(
        missing[0][0],
        f"{path} has {what}.",
        f"give the real values, e.g. read_topography({str(path)!r}, {python}) in Python, or "
        f"roughcontact inspect {shlex.quote(str(path))} {cli} at the command line" + noted,
        {m[0]: m[4] for m in missing},
        [note for note in notes if note.startswith("channel")],
    )
    error.fixes["cli"] = f"give the real values, e.g. {cli}" + noted.replace('size=("5 um", "10 um") or ', "")
    raise error


def _clash(field: str, problem: str, use_file: str, use_given: str) -> InputError:
    """Return the refusal of a value given beside the file's own, both ways out in each front end's words."""
    flag = "--" + field.replace("_", "-")
    fixes = {
        "python": f"leave {field} out to use {use_file}, or add override_file_values=True to use "
        f"{use_given}.",
        "study": f"remove {field} to use {use_file}, or add override_file_values = true to use {use_given}.",
        "cli": f"leave {flag} out to use {use_file}, or add --override-file-values to use {use_given}.",
    }
    return InputError(field, problem, fixes["python"], fixes=fixes)


def _size_agrees(path: Path, file_size, user_size, override: bool) -> None:
    """Refuse a given size that differs from the file's, unless ``override``."""
    if override or np.allclose(file_size, user_size, rtol=1e-9, atol=0.0):
        return
    stored, given = (" x ".join(format_si(s, "m") for s in sides) for sides in (file_size, user_size))
    raise _clash(
        "size",
        f"{path.name} stores its scan size, {stored}, but size {given} was given.",
        f"the file's {stored}",
        f"{given} (the file's value is kept as size_in_file)",
    )


def _height_factor(path: Path, file_unit: str | None, user_unit: str | None, override: bool = False) -> float:
    """Factor from stored heights to metres: the file's unit, or the user's when the file has none.

    A user's unit other than the file's is refused unless ``override``.
    """
    user_factor = None if user_unit is None else length_unit_factor(user_unit, field="height_unit")
    if file_unit is None:
        return user_factor
    file_factor = length_unit_factor(file_unit, field=str(path))
    if user_factor is None or np.isclose(user_factor, file_factor, rtol=1e-12, atol=0.0):
        return file_factor
    if override:
        return user_factor
    raise _clash(
        "height_unit",
        f"{path.name} stores heights in {file_unit!r}, but height unit {user_unit!r} was given.",
        f"the file's {file_unit!r}",
        f"{user_unit!r}",
    )


def _uniform_heights(measured) -> tuple[np.ndarray, tuple[float, ...], list[str]]:
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


def _handle_undefined(
    heights: np.ndarray, undefined: str, max_filled: float, path: Path
) -> tuple[np.ndarray, int]:
    count = int(np.count_nonzero(~np.isfinite(heights)))
    if count == 0:
        return heights, 0
    fraction = count / heights.size
    if undefined == "refuse":
        raise UndefinedPointsError(
            str(path),
            f"{count} of {heights.size} points ({100 * fraction:.3g} %) are undefined (missing in the "
            "measurement).",
            "pass undefined='interpolate' (command line: --fill-undefined) to fill them by "
            "harmonic interpolation from their neighbours, or crop them away.",
            count,
        )
    if fraction > max_filled:
        allowing = max_filled_allowing(fraction)
        raise UndefinedPointsError(
            "max_filled",
            f"{path.name}: {100 * fraction:.3g} % of the points are undefined, more than the "
            f"{100 * max_filled:.3g} % that are filled without asking; filling invents that much surface.",
            f"if that is acceptable, allow it: max_filled={allowing:g} (command line: --max-filled "
            f"{allowing:g}); or crop the undefined region away.",
            count,
            allowing,
        )
    return fill_undefined(heights, field=str(path)), count


def _file_info(
    path: Path,
    reader,
    channel,
    measured_info: Mapping[str, Any],
    file_units: tuple[str | None, str | None],
    user_height_unit: str | None,
) -> dict[str, Any]:
    file_size_unit, file_height_unit = file_units
    info: dict[str, Any] = {
        "name": path.name,
        "source": str(path),
        "file_format": reader.name(),
        "channel": str(channel.name),
        "channel_index": int(channel.index),
        "channel_shares_name_with": tuple(_same_name(reader, channel)),
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


def crop_metres(crop: CropLike, dim: int) -> tuple[tuple[float, float], ...]:
    """Return a crop window as (start, stop) pairs in metres per axis.

    ``crop`` is ``((x0, x1), (y0, y1))``, ``(x0, x1)`` for a profile, or the flat
    ``(x0, x1, y0, y1)`` the command line gives; each value metres or a string with a unit.
    """
    if isinstance(crop, str):
        raise InputError(
            "crop",
            f"got the string {crop!r}.",
            "give the window as pairs, ((x0, x1), (y0, y1)), e.g. crop=(('0 um', '5 um'), ('0 um', '5 um')).",
        )
    values = list(crop)
    if values and all(isinstance(v, tuple | list) for v in values):
        values = [v for pair in values for v in pair]
    if len(values) != 2 * dim:
        raise InputError(
            "crop",
            f"got {len(values)} values for a {dim}D topography.",
            "give x0 x1"
            + (" y0 y1" if dim == 2 else "")
            + ", e.g. '0 um' '5 um'"
            + (" '0 um' '5 um'." if dim == 2 else "."),
        )
    metres = [quantity(v, "length", field="crop") for v in values]
    return tuple((metres[2 * k], metres[2 * k + 1]) for k in range(dim))


def _user_size(size: SizeLike, dim: int) -> tuple[float, ...]:
    """Parse a user-given size (metres or strings with units) into one length [m] per axis."""
    if (
        isinstance(size, str) and " x " in size
    ):  # '5 um x 10 um', as the command line and study files write it
        size = tuple(part.strip() for part in size.split(" x "))
    values = tuple(size) if isinstance(size, tuple | list) else (size,)
    metres = tuple(quantity(v, "length", field="size") for v in values)
    if len(metres) == 1:
        metres = metres * dim
    if len(metres) != dim:
        raise InputError(
            "size",
            f"got {len(metres)} values for a {'profile (a line scan)' if dim == 1 else 'map'}.",
            "give its length, e.g. '5 um'." if dim == 1 else "give one value or two, e.g. '5 um x 10 um'.",
        )
    return metres


def _with_options(
    topography: Topography,
    path: Path,
    size: SizeLike | None,
    height_unit: str | None,
    periodic: bool,
    override: bool,
) -> Topography:
    """Apply read_topography's size, height_unit and periodic to a roughcontact file's topography."""
    factor = _height_factor(path, "m", height_unit, override)  # its heights are stored in metres
    changes: dict[str, Any] = {}
    given = None if size is None else _user_size(size, topography.dim)
    if given is not None and not np.allclose(given, topography.size, rtol=1e-9, atol=0.0):
        _size_agrees(path, topography.size, given, override)
        changes["size"] = given
        changes["info"] = {**topography.info, "size_in_file": topography.size}
    if factor != 1.0:
        changes["heights"] = topography.heights * factor
    if periodic:
        changes["periodic"] = True
    if not changes:
        return topography
    return topography.with_heights(changes.pop("heights", topography.heights), **changes)
