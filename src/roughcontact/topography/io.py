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
import warnings
import zlib
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import asdict, dataclass
from datetime import date, datetime
from pathlib import Path
from typing import Any

import numpy as np

from .._files import existing_file, first_line
from .._text_table import split_cells, split_header
from ..checks import flag as boolean
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
from .plausible import PlausibilityWarning, doubts
from .process import check_levelling, crop_window, default_levelling, fill_undefined, find_specks, level
from .process import crop as crop_topography
from .surface import LARGEST, Topography, largest_point
from .text import TextFormatError, TextTable, decode_text, parse_table

__all__ = ["ChannelInfo", "channel_of", "channel_words", "list_channels", "read_topography"]

_GZIP_MAGIC = b"\x1f\x8b"
_UNDEFINED_CHOICES = ("refuse", "interpolate")

READER_VERSION = 2
"""Version of what :func:`read_scan` makes of an instrument file: raise it when the same file would
read otherwise (other heights, size, info), so that converted copies of older reads are not used
(:mod:`roughcontact.topography.file_cache`). 2: a text file of positions takes the units of its
header cells (``X_(microns)``, ``x in µm``)."""

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
    with _open_reader(path) as (reader, positions):
        default = reader.default_channel.index
        channels = [
            _channel_info(channel, channel.index == default, positions) for channel in reader.channels
        ]
    copy.store({"channels": tuple(asdict(channel) for channel in channels)})
    return channels


def read_topography(
    path: PathLike,
    *,
    channel: int | str | None = None,
    size: SizeLike | None = None,
    height_unit: str | None = None,
    position_unit: str | None = None,
    crop: CropLike | None = None,
    undefined: str = "refuse",
    max_filled: float = MAX_FILLED,
    remove_specks: bool = False,
    periodic: bool = False,
    treat_as_height: bool = False,
    override_file_values: bool = False,
    detrend: str | None = None,
) -> Topography:
    """Read one channel of a topography file into a :class:`Topography` in SI units, levelled.

    Sizes and heights are converted to metres from the units the file declares:
    ``heights [m] = stored value * factor(unit)`` with factor("nm") = 1e-9 etc. A non-uniform
    line scan (x positions not equally spaced, e.g. a profilometer export with rounded
    positions) is interpolated linearly onto n equally spaced points spanning the same x range,
    so its size is ``n / (n - 1)`` times that range (recorded in ``info['history']``).

    A text file of points (x z or x y z columns) gives its own size: n points at their spacing
    make n times the spacing (not the range, n - 1 spacings). The unit of its positions comes from
    the file (a header cell ``x [um]``, ``X_(microns)``, ``x in µm``, or Gwyddion's ``# Lateral
    units``) or, where the file gives none, from ``position_unit``; a ``size`` beside the
    positions is refused (the positions are the file's own word).

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
        ``override_file_values`` (then ``info['size_in_file']`` keeps the file's). Refused for a
        text file of positions: they give the size (see ``position_unit``).
    height_unit : str, optional
        Unit of the stored heights (``"nm"``, ``"um"``, ...). Required when the file declares
        none; a unit other than the file's is refused unless ``override_file_values``.
    position_unit : str, optional
        Unit of the x (and y) positions of a text file of points (x z or x y z columns), where
        its header gives none (``"um"``); the size is then n times their spacing in that unit. A
        unit other than the file's is refused unless ``override_file_values``; refused for a
        file that holds no positions (a height matrix, an instrument's grid).
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
    detrend : {"none", "mean", "plane", "curvature", "sphere"}, optional
        The background removed after reading (:func:`~roughcontact.topography.process.level`),
        as the commands' ``--detrend`` and a study file's ``detrend``; default, as there,
        ``"plane"`` (``"mean"`` for a surface read as periodic,
        :func:`~roughcontact.topography.process.default_levelling`): the tilt of a measured scan
        is an artefact of mounting, and left in it decides where a flat touches. ``"none"`` keeps
        the heights as the file holds them. Recorded in ``info['detrend']``; the results of the
        solvers show it (``levelling``).

    Returns
    -------
    Topography
        Heights [m] and size [m]. ``info`` (JSON-ready) holds ``source``, ``name``,
        ``file_format``, ``channel``, ``data_source`` (SurfaceTopography's channel id),
        ``height_unit`` and ``size_unit`` as in the file, ``instrument`` and
        ``acquisition_time`` where the file gives them, ``detrend`` and ``history``.

    Raises
    ------
    UnsupportedFormatError
        A missing, empty, unknown, truncated or damaged file.
    InputError
        Unknown channel, a channel that holds no heights, size or height unit missing from
        both the file and the arguments, a height unit that contradicts the file, undefined
        points with ``undefined="refuse"``, a height beyond 1e100 m (its sums overflow; named
        with its point), an unknown ``detrend`` or one that would make a periodic surface
        non-periodic.

    Warns
    -----
    PlausibilityWarning
        (a ``UserWarning``) once for each implausible number of the surface read: a size outside
        1 nm to 1 m, heights spanning more than 1 m or less than 1 pm, a flat surface
        (:mod:`roughcontact.topography.plausible`; the commands print the same sentence as a
        note). The surface is returned all the same; ``warnings.simplefilter("error",
        PlausibilityWarning)`` makes it an error.

    Examples
    --------
    >>> read_topography("afm.txt", size="5 um", height_unit="nm")  # doctest: +SKIP
    >>> read_topography("scan.di", detrend="none")  # the heights as the file holds them  # doctest: +SKIP
    """
    if undefined not in _UNDEFINED_CHOICES:
        raise InputError("undefined", f"unknown choice {undefined!r}.", "choose 'refuse' or 'interpolate'.")
    if positive(max_filled, "max_filled", example="0.3", allow_zero=True) > 1:
        raise InputError(
            "max_filled", f"{max_filled:g} is not a fraction from 0 to 1.", "e.g. max_filled=0.3."
        )
    periodic = boolean(periodic, "periodic")
    if detrend is not None:
        check_levelling(detrend, periodic)
    scan = read_scan(
        path,
        channel=channel,
        size=size,
        height_unit=height_unit,
        position_unit=position_unit,
        periodic=periodic,
        treat_as_height=treat_as_height,
        override_file_values=override_file_values,
    )
    window = None if crop is None else crop_metres(crop, len(scan.size))
    if isinstance(scan, Topography):
        topography = scan if window is None else crop_topography(scan, *window)
    else:
        if window is not None:
            scan = scan.cropped(*window)
        topography = scan.topography(undefined=undefined, max_filled=max_filled, remove_specks=remove_specks)
    topography = level(topography, detrend or default_levelling(topography.periodic))
    name = topography.info.get("name") or Path(path).name
    for doubt in doubts(topography):
        warnings.warn(PlausibilityWarning(f"{name}: {doubt.said('python')}", doubt), stacklevel=2)
    return topography


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
    position_unit: str | None = None,
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
        if position_unit is not None:
            raise _no_positions(path, "a roughcontact height grid with its size")
        return _with_options(topography, path, size, height_unit, periodic, override_file_values)
    options = {
        "channel": channel,
        "size": size,
        "height_unit": height_unit,
        "position_unit": position_unit,
        "periodic": periodic,
        "treat_as_height": treat_as_height,
        "override_file_values": override_file_values,
    }
    copy = ConvertedCopy(path, "scan", options, READER_VERSION)
    found = copy.load("size", "periodic", "info")
    if found is not None:
        record, heights = found
        return _computable(Scan(heights, record["size"], record["periodic"], record["info"], path))
    scan = _computable(_read_instrument_file(path, **options))
    copy.store({"size": scan.size, "periodic": scan.periodic, "info": scan.info}, scan.heights)
    return scan


def _computable(scan: Scan) -> Scan:
    """Return ``scan`` after refusing a height beyond :data:`~.surface.LARGEST` (its sums overflow).

    Said with the file, the point (index and position) and the value as the file holds it, so that
    the user can find it; such a value is a typo or an instrument's marker of a missing point.
    """
    huge = largest_point(scan.heights)
    if huge is None:
        return scan
    index, value = huge
    spacing = [side / n for side, n in zip(scan.size, scan.heights.shape, strict=True)]
    where = ", ".join(
        f"{axis} = {format_si(i * step, 'm')}" for axis, i, step in zip("xy", index, spacing, strict=False)
    )
    unit = scan.info.get("height_unit")
    factor = _length_factor(unit)
    stored = f"{value / factor:.3g} {unit} in the file, " if factor else ""
    point = ", ".join(str(i) for i in index)
    problem = (
        f"the height at {where} (grid point {point}) is {stored}{value:.3g} m, beyond "
        f"{LARGEST:.0e} m: no surface is that high, and the sums of squares of such heights overflow."
    )
    said = "correct that value in the file (a typo, or the instrument's marker of a missing point: "
    fixes = {
        "python": said + "write it as NaN and read with undefined='interpolate'), or crop it away.",
        "study": said + "write it as NaN and add fill_undefined = true), or crop it away.",
        "cli": said + "write it as NaN and add --fill-undefined), or crop it away with --crop.",
    }
    raise InputError(str(scan.path), problem, fixes["python"], fixes=fixes)


def _read_instrument_file(
    path: Path,
    *,
    channel: int | str | None,
    size: SizeLike | None,
    height_unit: str | None,
    position_unit: str | None,
    periodic: bool,
    treat_as_height: bool,
    override_file_values: bool,
) -> Scan:
    """Read one channel of an instrument file with SurfaceTopography (:func:`read_scan`'s options)."""
    with _open_reader(path) as (reader, positions):
        selected = _select_channel(reader, channel, path)
        file_size_unit, file_height_unit = _file_units(selected, positions)
        _check_height_channel(selected, reader, treat_as_height)
        if positions is None and position_unit is not None:
            raise _no_positions(path, "a grid of heights, not x (y) z points")
        size_unit = file_size_unit
        if positions is not None:
            size_unit = _position_unit(path, positions, position_unit, override_file_values)
            if size is not None:
                raise _size_beside_positions(path, selected, positions, size_unit)
        _require_metadata(path, reader, selected, (size_unit, file_height_unit), size, height_unit, positions)
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
    file_size = _size_in_metres(extent, size_unit) if selected.physical_sizes is not None else None
    info["size_from"] = "file" if user_size is None else "user"
    if positions is not None:
        info["size_from"] = "positions"
        info["position_unit"] = size_unit
        info["position_unit_from"] = (
            "file" if positions.unit is not None and not override_file_values else "user"
        )
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
            _REREAD_FIX,
        )
    return reader, None


@contextmanager
def _open_reader(path: Path):
    """Open ``path`` (decompressing gzip) with SurfaceTopography; close the reader afterwards.

    Yields the reader and, for a text file of points, its position columns (:func:`_positions`;
    None otherwise). Failures inside the ``with`` block that uses the reader are reported as in
    :func:`_reader_errors`, since any access to the reader may parse more of the file.
    """
    source = _decompressed(path)
    with _reader_errors(path):
        reader, table = _opened(path, source)
        try:
            yield reader, _positions(path, reader, table)
        finally:
            reader.close()


@dataclass(frozen=True)
class _Positions:
    """The position columns of a text file of points (x z or x y z), as its header names them.

    Attributes
    ----------
    cells : tuple of str
        The header cells of the x (and y) columns as written (empty without a header line).
    unit : str or None
        Their length unit as the file gives it: SurfaceTopography's (``# Lateral units``), else
        the header cells' (``x [um]``, ``X_(microns)``, ``x in µm``); None where it gives none.
    height_unit : str or None
        The unit of the heights as the file gives it (the same way; None where it gives none).
    """

    cells: tuple[str, ...]
    unit: str | None
    height_unit: str | None

    @property
    def written(self) -> str:
        """Where the file says the positions' unit, for the messages."""
        cells = " and ".join(repr(cell) for cell in self.cells)
        return f"its header cell{'s' if len(self.cells) > 1 else ''} {cells}" if cells else "its header"


def _positions(path: Path, reader, table: TextTable | None) -> _Positions | None:
    """Return the position columns of a text file of points read by SurfaceTopography's x-y-z reader.

    None for any other file. The header cells are those of the last header line (not a comment)
    when it has one cell per column; with three columns of which SurfaceTopography took the first
    for an index (a line scan), the positions are the second.

    Raises
    ------
    InputError
        A header cell of the positions whose unit is not a length, or x and y cells of two units.
    """
    if reader.format() != "xyz" or not reader.channels:
        return None
    channel = reader.channels[0]
    width = None if table is None else table.shape[1]
    lines = [] if table is None else [line for line in table.header if line.strip()]
    last = lines[-1] if lines and not lines[-1].lstrip().startswith(("#", "%", "//", "\\", "!")) else None
    cells = [] if last is None else split_cells(last, table.separator)
    if len(cells) != width:
        cells = []
    roles = {2: ((0,), 1), 3: ((1,), 2) if channel.dim == 1 else ((0, 1), 2)}.get(width, ((), None))
    x_cells = tuple(cells[i] for i in roles[0]) if cells else ()
    units = [split_header(cell)[1] for cell in x_cells]
    for cell, unit in zip(x_cells, units, strict=True):
        if unit is not None and _length_factor(unit) is None:
            raise InputError(
                "position_unit",
                f"the header cell {cell!r} of {path.name} gives [{unit}], not a length (positions are).",
                f"correct the header cell to the unit of the positions, e.g. '{split_header(cell)[0]} [um]'.",
            )
    if len(set(units)) > 1:
        given = " and ".join(f"[{unit}]" if unit else "no unit" for unit in units)
        raise InputError(
            "position_unit",
            f"the header cells {x_cells[0]!r} and {x_cells[1]!r} of {path.name} give {given}: a grid of "
            "points has one unit.",
            "write the x and y positions in one unit.",
        )
    file_size_unit, file_height_unit = _file_units(channel)
    height_cell = cells[roles[1]] if cells and roles[1] is not None else None
    return _Positions(
        x_cells,
        file_size_unit or (units[0] if units else None),
        file_height_unit or (None if height_cell is None else split_header(height_cell)[1]),
    )


def _grid_words(channel, unit: str | None) -> tuple[str, str]:
    """Say the grid of a file's positions and the size they make, in their unit: (words, size).

    ``("8 points 38.61 nm apart: a size of 8 x 38.61 nm = 308.9 nm", "308.9 nm")``. The size is
    the number of points times their spacing, n spacings (not the range, n - 1). Without a unit
    the numbers are said as the file holds them.
    """
    counts = [int(n) for n in channel.nb_grid_pts]
    extent = _grid_extent(channel)
    factor = _length_factor(unit)

    def said(values) -> str:
        if factor is None:
            return " x ".join(f"{v:.4g}" for v in values)
        return " x ".join(format_si(v * factor, "m") for v in values)

    spacing = [e / n for e, n in zip(extent, counts, strict=True)]
    size = said(extent)
    product = f"{counts[0]} x {said(spacing)} = {size}" if len(counts) == 1 else size
    unnamed = "" if factor is not None else " in a unit the file does not name"
    points = " x ".join(map(str, counts))
    return f"{points} points {said(spacing)} apart: a size of {product}{unnamed}", size


def _position_unit(path: Path, positions: _Positions, given: str | None, override: bool) -> str | None:
    """Return the unit of a file's positions: the file's, or ``given`` where the file has none.

    A ``given`` unit other than the file's is refused (naming the header cell) unless ``override``.
    """
    if given is not None:
        given_factor = length_unit_factor(given, field="position_unit")
    if given is None or positions.unit is None:
        return given if positions.unit is None else positions.unit
    if math.isclose(given_factor, _length_factor(positions.unit) or math.nan, rel_tol=1e-12):
        return positions.unit
    if override:
        return given
    raise _clash(
        "position_unit",
        f"{path.name} gives its positions in {positions.unit!r} ({positions.written}), but position unit "
        f"{given!r} was given.",
        f"the file's {positions.unit!r}",
        f"{given!r}",
    )


def _size_beside_positions(path: Path, channel, positions: _Positions, unit: str | None) -> InputError:
    """Return the refusal of a size given beside a file's own positions (they give the size)."""
    grid, size = _grid_words(channel, unit)
    if unit is not None:
        problem = (
            f"{path.name} gives its own positions in {unit} ({positions.written}), {grid}; a size beside "
            "them is refused."
        )
        then = f"the positions give the size, {size}."
        fixes = {
            "python": f"leave size out: {then}",
            "study": f"remove size: {then}",
            "cli": f"leave --size out: {then}",
        }
    else:
        problem = (
            f"{path.name} gives its own positions without a unit, {grid}; a size beside them is refused "
            "(they need a unit, not a size)."
        )
        then = f"(if they are micrometres, the size is then {_grid_words(channel, 'um')[1]})."
        fixes = {
            "python": f'leave size out and give the positions\' unit: position_unit="um" {then}',
            "study": f'remove size and give the positions\' unit: position_unit = "um" {then}',
            "cli": f"leave --size out and give the positions' unit: --position-unit um {then}",
        }
    return InputError("size", problem, fixes["python"], fixes=fixes)


def _no_positions(path: Path, holds: str) -> InputError:
    """Return the refusal of a position unit for a file that holds no positions."""
    then = "its size comes from the file, or from {} where the file gives none."
    return InputError(
        "position_unit",
        f"{path.name} holds {holds}: a position unit is the unit of a text file's x (y) position columns.",
        f"leave position_unit out: {then.format('size')}",
        fixes={
            "study": f"remove position_unit: {then.format('size')}",
            "cli": f"leave --position-unit out: {then.format('--size')}",
        },
    )


def _file_units(channel, positions: _Positions | None = None) -> tuple[str | None, str | None]:
    """Return (size unit, height unit) of a SurfaceTopography channel as written in the file.

    Some readers (Bruker .di) give ``unit = (lateral unit, data unit)`` for non-height channels.
    For a text file of points, the units its header cells give where SurfaceTopography found none
    (:func:`_positions`).
    """
    unit, data_unit = channel.unit, channel.data_unit
    size_unit = unit[0] if isinstance(unit, tuple) else unit
    height_unit = data_unit[1] if isinstance(data_unit, tuple) else data_unit
    if positions is not None:
        return size_unit or positions.unit, height_unit or positions.height_unit
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


def _channel_info(channel, is_default: bool, positions: _Positions | None = None) -> ChannelInfo:
    size_unit, height_unit = _file_units(channel, positions)
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
    positions: _Positions | None = None,
) -> None:
    """Raise one InputError listing everything the file lacks and the user did not give.

    ``file_units`` are the units to read the file in (a file of points: its positions' unit, the
    file's or the one given); its size hint is the size the file implies, n points at their spacing.
    """
    file_size_unit, file_height_unit = file_units
    size_known = channel.physical_sizes is not None and _length_factor(file_size_unit) is not None
    missing, notes = [], []
    if positions is not None and not size_known:
        grid, _ = _grid_words(channel, None)
        axes = "x and y" if channel.dim == 2 else "x"
        missing.append(
            (
                "position_unit",
                f"{axes} positions without a unit ({grid})",
                'position_unit="um"',
                "--position-unit um",
                "um",
            )
        )
        notes.append(f"positions in um make a size of {_grid_words(channel, 'um')[1]}")
    elif size is None and not size_known:
        in_file = (
            ""
            if channel.physical_sizes is None
            else (
                f" (it gives {' x '.join(f'{float(s):.4g}' for s in _grid_extent(channel))} without a unit)"
            )
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
            "pass «undefined=interpolate» to fill them by harmonic interpolation from their "
            "neighbours, or crop them away.",
            count,
        )  # a study file and a command line fill them with fill_undefined (UndefinedPointsError's fixes)
    if fraction > max_filled:
        allowing = max_filled_allowing(fraction)
        raise UndefinedPointsError(
            "max_filled",
            f"{path.name}: {100 * fraction:.3g} % of the points are undefined, more than the "
            f"{100 * max_filled:.3g} % that are filled without asking; filling invents that much surface.",
            f"if that is acceptable, allow it: «max_filled={allowing:g}»; or crop the undefined region away.",
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
