"""What a reading checks: the channel chosen, the metadata the file lacks, values given beside the file's own.

Each refusal names the option and says the way out in each front end's words (Python, a study
file, the command line).
"""

from __future__ import annotations

import math
import shlex
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...errors import InputError, MissingMetadataError, UndefinedPointsError
from ...units import format_si, length_unit_factor, quantity
from ..channels import ChannelKind, classify_channel
from ..process import fill_undefined
from .metadata import SizeLike, channel_units, clash, grid_extent, length_factor, size_in_metres
from .positions import Positions, grid_words, units_in_file

MAX_FILLED = 0.05
"""Largest fraction of a file's points that filling undefined points may invent without being told more."""


def max_filled_allowing(fraction: float) -> float:
    """Return the ``max_filled`` to offer for a file with ``fraction`` undefined (the next whole percent)."""
    return math.ceil(100 * fraction) / 100


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


def _kind(channel) -> ChannelKind:
    """Whether a SurfaceTopography channel holds heights (:func:`.channels.classify_channel`)."""
    unit = channel_units(channel)[1]
    data_kind = getattr(channel, "data_kind", None)
    return classify_channel(
        str(channel.name),
        unit,
        None if unit is None else length_factor(unit) is not None,
        None if data_kind is None else getattr(data_kind, "name", str(data_kind)),
    )


def channel_info(channel, is_default: bool, positions: Positions | None = None) -> ChannelInfo:
    """Return the :class:`ChannelInfo` of a SurfaceTopography channel (units as the file writes them)."""
    size_unit, height_unit = units_in_file(channel, positions)
    size = None if channel.physical_sizes is None else size_in_metres(grid_extent(channel), size_unit)
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


def select_channel(reader, channel: int | str | None, path: Path):
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


def same_name(reader, channel) -> list[int]:
    """Return the indices of the other channels named like ``channel``."""
    return [int(c.index) for c in reader.channels if c.name == channel.name and c.index != channel.index]


def _channel_list(reader) -> str:
    """Every channel as ``0: 'ZSensor' (heights), 2: 'Phase' (not heights)``."""
    return ", ".join(
        f"{c.index}: {c.name!r} ({'heights' if _kind(c).is_height else 'not heights'})"
        for c in reader.channels
    )


def check_height_channel(channel, reader, treat_as_height: bool) -> None:
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


def require_metadata(
    path: Path,
    reader,
    channel,
    file_units: tuple[str | None, str | None],
    size: SizeLike | None,
    height_unit: str | None,
    positions: Positions | None = None,
) -> None:
    """Raise one InputError listing everything the file lacks and the user did not give.

    ``file_units`` are the units to read the file in (a file of points: its positions' unit, the
    file's or the one given); its size hint is the size the file implies, n points at their spacing.
    """
    file_size_unit, file_height_unit = file_units
    size_known = channel.physical_sizes is not None and length_factor(file_size_unit) is not None
    missing, notes = [], []
    if positions is not None and not size_known:
        grid, _ = grid_words(channel, None)
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
        notes.append(f"positions in um make a size of {grid_words(channel, 'um')[1]}")
    elif size is None and not size_known:
        in_file = (
            ""
            if channel.physical_sizes is None
            else (f" (it gives {' x '.join(f'{float(s):.4g}' for s in grid_extent(channel))} without a unit)")
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


def size_agrees(path: Path, file_size, user_size, override: bool) -> None:
    """Refuse a given size that differs from the file's, unless ``override``."""
    if override or np.allclose(file_size, user_size, rtol=1e-9, atol=0.0):
        return
    stored, given = (" x ".join(format_si(s, "m") for s in sides) for sides in (file_size, user_size))
    raise clash(
        "size",
        f"{path.name} stores its scan size, {stored}, but size {given} was given.",
        f"the file's {stored}",
        f"{given} (the file's value is kept as size_in_file)",
    )


def heights_to_metres(
    path: Path, file_unit: str | None, user_unit: str | None, override: bool = False
) -> float:
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
    raise clash(
        "height_unit",
        f"{path.name} stores heights in {file_unit!r}, but height unit {user_unit!r} was given.",
        f"the file's {file_unit!r}",
        f"{user_unit!r}",
    )


def handle_undefined(
    heights: np.ndarray, undefined: str, max_filled: float, path: Path
) -> tuple[np.ndarray, int]:
    """Return the heights with their undefined points refused or filled, and how many were filled.

    ``undefined`` and ``max_filled`` as :func:`~roughcontact.topography.io.read_topography` takes them.
    """
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


def parsed_size(size: SizeLike, dim: int) -> tuple[float, ...]:
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
