"""Read measured topographies from instrument files, and save/load roughcontact's own format.

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

roughcontact's own format (:func:`save_topography`, :func:`load_topography`) is a NetCDF-4
file (HDF5, written with the ``h5netcdf`` engine) holding the heights [m] as float64 on
coordinates ``x`` (and ``y``) [m], and as attributes the physical size [m], the periodic
flag, the metadata ``info`` as JSON and a format marker with a version. It round-trips a
:class:`~roughcontact.topography.surface.Topography` exactly.

References
----------
SurfaceTopography (ContactEngineering), https://github.com/ContactEngineering/SurfaceTopography
"""

from __future__ import annotations

import gzip
import io
import json
import os
import shlex
import zlib
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from datetime import date, datetime
from pathlib import Path
from typing import Any

import numpy as np

from .._files import replacing
from ..errors import InputError, UnitError, UnsupportedFormatError
from ..units import length_unit_factor, quantity
from .process import fill_undefined
from .surface import Topography

__all__ = ["ChannelInfo", "list_channels", "load_topography", "read_topography", "save_topography"]

NATIVE_FORMAT = "roughcontact-topography"
NATIVE_VERSION = 1

_GZIP_MAGIC = b"\x1f\x8b"
_HDF5_MAGIC = b"\x89HDF\r\n\x1a\n"
_TUPLE_TAG = "__tuple__"  # JSON has no tuples: {"__tuple__": [...]} keeps info round trips exact
_UNDEFINED_CHOICES = ("refuse", "interpolate")
_REREAD_FIX = (
    "copy the file again from the instrument or export it again (e.g. as .x3p, .sur or a "
    "plain-text height matrix); roughcontact reads the formats SurfaceTopography reads."
)

PathLike = str | os.PathLike
SizeLike = float | str | tuple[float | str, ...]


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
    """

    index: int
    name: str
    shape: tuple[int, ...]
    size: tuple[float, ...] | None
    height_unit: str | None
    size_unit: str | None
    is_default: bool


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
    path = _existing_file(path)
    if _is_native(path):
        topography = load_topography(path)
        return [
            ChannelInfo(
                0,
                str(topography.info.get("channel", "heights")),
                topography.shape,
                topography.size,
                "m",
                "m",
                True,
            )
        ]
    with _open_reader(path) as reader:
        default = reader.default_channel.index
        return [_channel_info(channel, channel.index == default) for channel in reader.channels]


def read_topography(
    path: PathLike,
    *,
    channel: int | str | None = None,
    size: SizeLike | None = None,
    height_unit: str | None = None,
    undefined: str = "refuse",
    periodic: bool = False,
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
        roughcontact ``.nc`` file written by :func:`save_topography`.
    channel : int or str, optional
        Channel index or name (see :func:`list_channels`); default: the file's default channel.
    size : float or str or tuple, optional
        Physical scan size: metres as a float, or a string with a unit (``"10 um"``); one value
        (square map or a profile) or one per axis (``("10 um", "20 um")``). Required when the
        file has no size; when the file has one, this value wins and ``info['size_in_file']``
        keeps the file's.
    height_unit : str, optional
        Unit of the stored heights (``"nm"``, ``"um"``, ...). Required when the file declares
        none; must agree with the file's unit when it declares one.
    undefined : {"refuse", "interpolate"}
        What to do with undefined (missing) points: refuse the file, or fill them by harmonic
        interpolation (:func:`roughcontact.topography.process.fill_undefined`), recording the
        count in ``info['undefined_points_filled']``.
    periodic : bool
        Treat the surface as periodic (measured surfaces are not, as a rule). A file that
        declares itself periodic (a roughcontact or SurfaceTopography ``.nc`` file) stays so.

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
    path = _existing_file(path)
    if _is_native(path):
        return _read_native(path, channel, size, height_unit, periodic)
    with _open_reader(path) as reader:
        selected = _select_channel(reader, channel, path)
        file_size_unit, file_height_unit = _file_units(selected)
        _check_height_channel(selected, file_height_unit, reader)
        _require_metadata(path, reader, selected, (file_size_unit, file_height_unit), size, height_unit)
        user_size = None if size is None else _user_size(size, selected.dim)
        height_factor = _height_factor(path, file_height_unit, height_unit)
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
            info["size_in_file"] = file_size
        elif selected.physical_sizes is not None:
            info["size_in_file_without_unit"] = tuple(map(float, extent))
    heights, filled = _handle_undefined(heights, undefined, path)
    if filled:
        info["undefined_points_filled"] = filled
        steps.append(f"fill_undefined: {filled} undefined points interpolated (harmonic)")
    info["history"] = (f"read {path.name} channel {selected.name!r} ({reader.name()})", *steps)
    return Topography(heights, physical_size, periodic=periodic, info=info)


def save_topography(topography: Topography, path: PathLike) -> None:
    """Write a topography to roughcontact's own NetCDF format, atomically.

    The file holds ``heights`` [m] (float64) on coordinates ``x`` (and ``y``) [m] at the grid
    points ``i * spacing``, and attributes ``format = "roughcontact-topography"``,
    ``format_version = 1``, ``size`` [m], ``periodic`` (0 or 1) and ``info`` (JSON; tuples are
    written as ``{"__tuple__": [...]}`` so that they come back as tuples). The file is written
    under a temporary name in the target folder and renamed into place, so a failed write
    leaves no partial file and an existing file intact.

    Parameters
    ----------
    topography : Topography
        Surface to save; its ``info`` must hold only str, numbers, None, lists, tuples and dicts
        with str keys.
    path : str or path-like
        Output file, conventionally ending in ``.nc``.

    Raises
    ------
    InputError
        Not a Topography, info that JSON cannot hold exactly, a missing or unwritable folder.
    """
    import xarray as xr

    if not isinstance(topography, Topography):
        raise InputError(
            "topography",
            f"expected a Topography, got {type(topography).__name__}.",
            "read or generate a Topography first.",
        )
    path = Path(path)
    dims = ("x", "y")[: topography.dim]
    coordinates = {d: (d, c, {"units": "m"}) for d, c in zip(dims, topography.coordinates(), strict=True)}
    heights = (dims, np.asarray(topography.heights, dtype=np.float64), {"units": "m", "long_name": "height"})
    dataset = xr.Dataset(
        {"heights": heights},
        coords=coordinates,
        attrs={
            "format": NATIVE_FORMAT,
            "format_version": NATIVE_VERSION,
            "size": list(topography.size),
            "size_units": "m",
            "periodic": int(topography.periodic),
            "info": _encode_info(topography.info),
        },
    )
    encoding = {name: {"_FillValue": None} for name in (*dims, "heights")}
    _write_atomically(dataset, path, encoding)


def load_topography(path: PathLike) -> Topography:
    """Load a topography written by :func:`save_topography`, exactly as it was saved.

    Parameters
    ----------
    path : str or path-like
        A roughcontact ``.nc`` file.

    Returns
    -------
    Topography
        Heights [m], size [m], periodic flag and info as saved.

    Raises
    ------
    UnsupportedFormatError
        A missing file, a file that is not NetCDF, a NetCDF file without the roughcontact format
        marker, or one written by a newer format version.
    """
    import xarray as xr

    path = _existing_file(path)
    try:
        with xr.open_dataset(path, engine="h5netcdf") as dataset:
            dataset.load()
    except Exception as error:  # any failure of the HDF5 stack means the same to the user
        raise UnsupportedFormatError(
            str(path),
            f"cannot be opened as a NetCDF file ({_first_line(error)}).",
            "load .nc files written by save_topography(); read instrument files with read_topography().",
        ) from error
    attrs = dataset.attrs
    if attrs.get("format") != NATIVE_FORMAT or "heights" not in dataset:
        raise UnsupportedFormatError(
            str(path),
            f"is NetCDF but not a roughcontact topography (no format marker {NATIVE_FORMAT!r}).",
            "read instrument files with read_topography(); write this format with save_topography().",
        )
    version = attrs.get("format_version")
    if version != NATIVE_VERSION:
        raise UnsupportedFormatError(
            str(path),
            f"has format version {version}; this roughcontact reads version {NATIVE_VERSION}.",
            "open it with the roughcontact version that wrote it.",
        )
    size = tuple(float(s) for s in np.atleast_1d(attrs["size"]))
    return Topography(
        dataset["heights"].values, size, periodic=bool(attrs["periodic"]), info=_decode_info(attrs["info"])
    )


# --- files and SurfaceTopography -----------------------------------------------------------------


def _existing_file(path: PathLike) -> Path:
    """Return ``path`` as a Path, refusing what is not a readable non-empty file."""
    path = Path(path)
    if not path.exists():
        raise UnsupportedFormatError(str(path), "no such file.", "check the path and the file name.")
    if path.is_dir():
        raise UnsupportedFormatError(
            str(path), "is a folder, not a file.", "give the path of one topography file inside it."
        )
    if path.stat().st_size == 0:
        raise UnsupportedFormatError(str(path), "the file is empty (0 bytes).", _REREAD_FIX)
    return path


def _is_native(path: Path) -> bool:
    """Whether ``path`` is an HDF5 file carrying roughcontact's format marker."""
    import h5netcdf

    with path.open("rb") as stream:
        if stream.read(len(_HDF5_MAGIC)) != _HDF5_MAGIC:
            return False
    try:
        with h5netcdf.File(path, "r") as handle:
            return handle.attrs.get("format") == NATIVE_FORMAT
    except Exception:  # a damaged HDF5 file is left to SurfaceTopography, which reports it
        return False


def _first_line(error: BaseException, limit: int = 160) -> str:
    text = str(error).strip().splitlines()
    line = text[0].strip() if text else type(error).__name__
    return line if len(line) <= limit else line[: limit - 3] + "..."


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
            str(path), f"the file is damaged: {_first_line(error)}", _REREAD_FIX
        ) from error
    except Exception as error:
        raise UnsupportedFormatError(
            str(path), f"reading failed ({type(error).__name__}: {_first_line(error)}).", _REREAD_FIX
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
            str(path), f"the gzip archive is damaged or truncated ({_first_line(error)}).", _REREAD_FIX
        ) from error
    if not content:
        raise UnsupportedFormatError(str(path), "the gzip archive holds an empty file.", _REREAD_FIX)
    return io.BytesIO(content)


@contextmanager
def _open_reader(path: Path):
    """Open ``path`` (decompressing gzip) with SurfaceTopography; close the reader afterwards.

    Failures inside the ``with`` block that uses the reader are reported as in
    :func:`_reader_errors`, since any access to the reader may parse more of the file.
    """
    import SurfaceTopography

    source = _decompressed(path)
    with _reader_errors(path):
        reader = SurfaceTopography.open_topography(source)
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


def _channel_info(channel, is_default: bool) -> ChannelInfo:
    size_unit, height_unit = _file_units(channel)
    size = None if channel.physical_sizes is None else _size_in_metres(_grid_extent(channel), size_unit)
    return ChannelInfo(
        index=int(channel.index),
        name=str(channel.name),
        shape=tuple(int(n) for n in channel.nb_grid_pts),
        size=size,
        height_unit=height_unit,
        size_unit=size_unit,
        is_default=is_default,
    )


def _channel_names(reader) -> str:
    return ", ".join(f"{c.index}: {c.name!r}" for c in reader.channels)


def _select_channel(reader, channel: int | str | None, path: Path):
    """Return the SurfaceTopography channel chosen by index or name (default: the file's)."""
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
            f"choose one of {_channel_names(reader)}.",
        )
    if not matches:
        raise InputError(
            "channel",
            f"{path.name} has no channel {channel!r}.",
            f"choose one of {_channel_names(reader)} (by index or name).",
        )
    return matches[0]


def _height_channel_names(reader) -> list[str]:
    """Names of the channels whose values the file declares in a length unit."""
    return [c.name for c in reader.channels if _length_factor(_file_units(c)[1]) is not None]


def _check_height_channel(channel, file_height_unit: str | None, reader) -> None:
    """Refuse a channel whose values are not lengths (phase in deg, potential in V, ...)."""
    if file_height_unit is None or _length_factor(file_height_unit) is not None:
        return
    names = ", ".join(map(repr, _height_channel_names(reader))) or "none in this file"
    raise InputError(
        "channel",
        f"channel {channel.name!r} holds values in {file_height_unit!r}, not heights.",
        f"choose a height channel: {names}.",
    )


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
        missing.append(("size", f"no physical scan size{in_file}", 'size="5 um"', '--size "5 um"'))
        if channel.dim == 2:
            notes.append('a non-square scan takes size=("5 um", "10 um") or --size "5 um x 10 um"')
    if height_unit is None and file_height_unit is None:
        missing.append(("height_unit", "no height unit", 'height_unit="nm"', "--height-unit nm"))
        others = [name for name in _height_channel_names(reader) if name != channel.name]
        if others:
            names = ", ".join(map(repr, others))
            notes.append(f"channel {channel.name!r} may hold no heights; these do: {names}")
    if not missing:
        return
    what = " and ".join(m[1] for m in missing)
    python = ", ".join(m[2] for m in missing)
    cli = " ".join(m[3] for m in missing)
    raise InputError(
        missing[0][0],
        f"{path} has {what}.",
        f"give the real values, e.g. read_topography({str(path)!r}, {python}) in Python, or "
        f"roughcontact inspect {shlex.quote(str(path))} {cli} at the command line"
        + "".join(f"; {note}" for note in notes)
        + ".",
    )


def _height_factor(path: Path, file_unit: str | None, user_unit: str | None) -> float:
    """Factor from stored heights to metres: the file's unit, or the user's when the file has none."""
    user_factor = None if user_unit is None else length_unit_factor(user_unit, field="height_unit")
    if file_unit is None:
        return user_factor
    file_factor = length_unit_factor(file_unit, field=str(path))
    if user_factor is not None and not np.isclose(user_factor, file_factor, rtol=1e-12, atol=0.0):
        raise InputError(
            "height_unit",
            f"{path.name} stores heights in {file_unit!r}, but height_unit={user_unit!r} was given.",
            "leave height_unit out (the file's unit is used); rescale the heights afterwards "
            "if the file's unit is wrong.",
        )
    return file_factor


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


def _handle_undefined(heights: np.ndarray, undefined: str, path: Path) -> tuple[np.ndarray, int]:
    count = int(np.count_nonzero(~np.isfinite(heights)))
    if count == 0:
        return heights, 0
    if undefined == "refuse":
        raise InputError(
            str(path),
            f"{count} of {heights.size} points are undefined (missing in the measurement).",
            "pass undefined='interpolate' (command line: --fill-undefined) to fill them by "
            "harmonic interpolation from their neighbours, or crop them away.",
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
        "data_source": str(getattr(channel, "channel_id", channel.name)),
        "height_unit": file_height_unit if file_height_unit is not None else user_height_unit,
        "height_unit_from": "file" if file_height_unit is not None else "user",
        "size_unit": file_size_unit,
    }
    for key in ("instrument", "acquisition_time"):
        if key in measured_info:
            info[key] = _json_ready(measured_info[key])
    return info


def _json_ready(value: Any) -> Any:
    """Convert reader metadata to JSON-ready values (dicts with str keys, tuples, str, numbers)."""
    if isinstance(value, Mapping):
        return {str(k): _json_ready(v) for k, v in value.items()}
    if isinstance(value, list | tuple | np.ndarray):
        return tuple(_json_ready(v) for v in value)
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, datetime | date):
        return value.isoformat()
    if value is None or isinstance(value, str | bool | int | float):
        return value
    return str(value)


def _user_size(size: SizeLike, dim: int) -> tuple[float, ...]:
    """Parse a user-given size (metres or strings with units) into one length [m] per axis."""
    values = tuple(size) if isinstance(size, tuple | list) else (size,)
    metres = tuple(quantity(v, "length", field="size") for v in values)
    if len(metres) == 1:
        metres = metres * dim
    if len(metres) != dim:
        raise InputError(
            "size",
            f"got {len(metres)} values for a {dim}D topography.",
            f"give one value or {dim} values, e.g. '5 um'.",
        )
    return metres


def _read_native(
    path: Path, channel: int | str | None, size: SizeLike | None, height_unit: str | None, periodic: bool
) -> Topography:
    """Apply read_topography's options to a roughcontact .nc file (one channel, heights in m)."""
    topography = load_topography(path)
    if channel not in (None, 0, topography.info.get("channel", "heights")):
        raise InputError(
            "channel", f"{path.name} is a roughcontact file with a single channel.", "leave channel out."
        )
    _height_factor(path, "m", height_unit)
    changes: dict[str, Any] = {}
    if size is not None:
        changes["size"] = _user_size(size, topography.dim)
        changes["info"] = {**topography.info, "size_in_file": topography.size}
    if periodic:
        changes["periodic"] = True
    return topography.with_heights(topography.heights, **changes) if changes else topography


# --- native format helpers -----------------------------------------------------------------------


def _encode_info(info: Mapping[str, Any]) -> str:
    """Return ``info`` as JSON, tuples tagged so that they are restored as tuples."""

    def encode(value: Any, where: str) -> Any:
        if isinstance(value, Mapping):
            for key in value:
                if not isinstance(key, str):
                    raise InputError(
                        "topography.info", f"key {key!r} in {where} is not a string.", "use str keys in info."
                    )
            return {k: encode(v, f"{where}[{k!r}]") for k, v in value.items()}
        if isinstance(value, tuple):
            return {_TUPLE_TAG: [encode(v, where) for v in value]}
        if isinstance(value, list):
            return [encode(v, where) for v in value]
        if isinstance(value, np.generic):
            return value.item()
        if value is None or isinstance(value, str | bool | int | float):
            return value
        raise InputError(
            "topography.info",
            f"{where} holds a {type(value).__name__}, which the .nc format cannot store.",
            "keep info to str, numbers, None, lists, tuples and dicts with str keys.",
        )

    return json.dumps(encode(dict(info), "info"))


def _decode_info(text: str) -> dict[str, Any]:
    def restore(mapping: dict) -> Any:
        return tuple(mapping[_TUPLE_TAG]) if mapping.keys() == {_TUPLE_TAG} else mapping

    return json.loads(text, object_hook=restore)


def _write_atomically(dataset, path: Path, encoding: dict) -> None:
    """Write ``dataset`` through a temporary file beside ``path`` (:func:`roughcontact._files.replacing`).

    The folder must exist (it is not created); a failed write is an :class:`InputError` naming the path.
    """
    if not path.parent.is_dir():
        raise InputError(
            "path", f"folder {path.parent} does not exist.", "create it first or choose another path."
        )
    try:
        with replacing(path) as temporary:
            dataset.to_netcdf(temporary, engine="h5netcdf", encoding=encoding)
    except OSError as error:
        raise InputError(
            "path", f"cannot write {path}: {_first_line(error)}", "choose a writable folder with free space."
        ) from error
