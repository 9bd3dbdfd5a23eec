"""What an instrument file says of its units and grid; the refusal of a value given beside the file's own."""

from __future__ import annotations

import os

from ...errors import InputError, UnitError
from ...units import length_unit_factor

REREAD_FIX = (
    "copy the file again from the instrument or export it again (e.g. as .x3p, .sur or a "
    "plain-text height matrix); roughcontact reads the formats SurfaceTopography reads."
)
"""The way out of a file that cannot be read."""


PathLike = str | os.PathLike
"""A file's path."""

SizeLike = float | str | tuple[float | str, ...]
"""A size as given: metres, or text with a unit, one value or one per axis."""

CropLike = tuple
"""A crop window as given (see :func:`roughcontact.topography.io.crop_metres`)."""


def channel_units(channel) -> tuple[str | None, str | None]:
    """Return (size unit, height unit) of a SurfaceTopography channel as written in the file.

    Some readers (Bruker .di) give ``unit = (lateral unit, data unit)`` for non-height channels.
    """
    unit, data_unit = channel.unit, channel.data_unit
    size_unit = unit[0] if isinstance(unit, tuple) else unit
    height_unit = data_unit[1] if isinstance(data_unit, tuple) else data_unit
    return size_unit, height_unit


def length_factor(unit: str | None) -> float | None:
    """Factor to metres of a unit from a file, or None when it is absent or not a length."""
    if unit is None:
        return None
    try:
        return length_unit_factor(unit)
    except UnitError:
        return None


def size_in_metres(extent: tuple[float, ...], unit: str | None) -> tuple[float, ...] | None:
    """Return a grid extent in a file's ``unit`` in metres; None when the unit is absent or no length."""
    factor = length_factor(unit)
    return None if factor is None else tuple(float(s) * factor for s in extent)


def grid_extent(channel) -> tuple[float, ...]:
    """Size of the grid in file units: a non-uniform scan of n points spans (n-1) uniform pixels."""
    extent = tuple(float(s) for s in channel.physical_sizes)
    if channel.is_uniform:
        return extent
    return tuple(s * n / (n - 1) for s, n in zip(extent, channel.nb_grid_pts, strict=True))


def clash(field: str, problem: str, use_file: str, use_given: str) -> InputError:
    """Return the refusal of a value given beside the file's own, both ways out in each front end's words."""
    flag = "--" + field.replace("_", "-")
    fixes = {
        "python": f"leave {field} out to use {use_file}, or add override_file_values=True to use "
        f"{use_given}.",
        "study": f"remove {field} to use {use_file}, or add override_file_values = true to use {use_given}.",
        "cli": f"leave {flag} out to use {use_file}, or add --override-file-values to use {use_given}.",
    }
    return InputError(field, problem, fixes["python"], fixes=fixes)
