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

The reading is in this package's modules: :mod:`.scan` (a file's heights as stored, and its
converted copy), :mod:`.readers` (SurfaceTopography, gzip, text tables held to what they hold),
:mod:`.positions` (text tables of points), :mod:`.checks` (the channel, the metadata a file lacks,
values given beside the file's own) and :mod:`.metadata` (a file's units and grid). Import from here.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import asdict
from pathlib import Path
from typing import Any

from ..._files import existing_file
from ...checks import flag as boolean
from ...checks import positive
from ...errors import InputError
from ...units import quantity
from ..file_cache import ConvertedCopy
from ..native import channel_name, is_native_file, read_native
from ..plausible import PlausibilityWarning, doubts
from ..process import check_levelling, default_levelling, level
from ..process import crop as crop_topography
from ..surface import Topography
from .checks import MAX_FILLED, ChannelInfo, channel_info
from .checks import max_filled_allowing as max_filled_allowing  # the commands offer it
from .metadata import REREAD_FIX, CropLike, PathLike, SizeLike
from .readers import open_reader
from .scan import READER_VERSION, read_scan
from .scan import Scan as Scan  # what read_scan returns

__all__ = ["ChannelInfo", "channel_of", "channel_words", "list_channels", "read_topography"]

_UNDEFINED_CHOICES = ("refuse", "interpolate")


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
    path = existing_file(path, empty_fix=REREAD_FIX)
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
    with open_reader(path) as (reader, positions):
        default = reader.default_channel.index
        channels = [channel_info(channel, channel.index == default, positions) for channel in reader.channels]
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
