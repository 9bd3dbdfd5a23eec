"""A file's heights as stored (:class:`Scan`, undefined points kept), read once into a converted copy."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..._files import existing_file
from ...errors import InputError
from ...units import format_si
from ..file_cache import ConvertedCopy
from ..native import is_native_file, read_native
from ..process import crop_window, find_specks
from ..surface import LARGEST, Topography, largest_point
from .checks import (
    MAX_FILLED,
    check_height_channel,
    handle_undefined,
    heights_to_metres,
    parsed_size,
    require_metadata,
    select_channel,
    size_agrees,
)
from .metadata import REREAD_FIX, PathLike, SizeLike, length_factor, size_in_metres
from .positions import checked_position_unit, no_positions, size_beside_positions, units_in_file
from .readers import file_info, open_reader, uniform_heights

READER_VERSION = 2
"""Version of what :func:`read_scan` makes of an instrument file: raise it when the same file would
read otherwise (other heights, size, info), so that converted copies of older reads are not used
(:mod:`roughcontact.topography.file_cache`). 2: a text file of positions takes the units of its
header cells (``X_(microns)``, ``x in µm``)."""


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
        heights, filled = handle_undefined(heights, undefined, max_filled, self.path)
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
    path = existing_file(path, empty_fix=REREAD_FIX)
    if is_native_file(path):
        topography = read_native(path, channel=channel)
        if position_unit is not None:
            raise no_positions(path, "a roughcontact height grid with its size")
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
    factor = length_factor(unit)
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
    with open_reader(path) as (reader, positions):
        selected = select_channel(reader, channel, path)
        file_size_unit, file_height_unit = units_in_file(selected, positions)
        check_height_channel(selected, reader, treat_as_height)
        if positions is None and position_unit is not None:
            raise no_positions(path, "a grid of heights, not x (y) z points")
        size_unit = file_size_unit
        if positions is not None:
            size_unit = checked_position_unit(path, positions, position_unit, override_file_values)
            if size is not None:
                raise size_beside_positions(path, selected, positions, size_unit)
        require_metadata(path, reader, selected, (size_unit, file_height_unit), size, height_unit, positions)
        user_size = None if size is None else parsed_size(size, selected.dim)
        height_factor = heights_to_metres(path, file_height_unit, height_unit, override_file_values)
        dummy_size = None if selected.physical_sizes is not None else tuple(map(float, selected.nb_grid_pts))
        measured = reader.topography(channel_index=selected.index, physical_sizes=dummy_size)
        heights, extent, steps = uniform_heights(measured)
        periodic = periodic or bool(measured.is_periodic)
        info = file_info(
            path, reader, selected, measured.info, (file_size_unit, file_height_unit), height_unit
        )
    heights = heights * height_factor
    file_size = size_in_metres(extent, size_unit) if selected.physical_sizes is not None else None
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
            size_agrees(path, file_size, user_size, override_file_values)
            info["size_in_file"] = file_size
        elif selected.physical_sizes is not None:
            info["size_in_file_without_unit"] = tuple(map(float, extent))
    info["history"] = (f"read {path.name} channel {selected.name!r} ({reader.name()})", *steps)
    return Scan(heights, tuple(float(s) for s in np.atleast_1d(physical_size)), periodic, info, path)


def _with_options(
    topography: Topography,
    path: Path,
    size: SizeLike | None,
    height_unit: str | None,
    periodic: bool,
    override: bool,
) -> Topography:
    """Apply read_topography's size, height_unit and periodic to a roughcontact file's topography."""
    factor = heights_to_metres(path, "m", height_unit, override)  # its heights are stored in metres
    changes: dict[str, Any] = {}
    given = None if size is None else parsed_size(size, topography.dim)
    if given is not None and not np.allclose(given, topography.size, rtol=1e-9, atol=0.0):
        size_agrees(path, topography.size, given, override)
        changes["size"] = given
        changes["info"] = {**topography.info, "size_in_file": topography.size}
    if factor != 1.0:
        changes["heights"] = topography.heights * factor
    if periodic:
        changes["periodic"] = True
    if not changes:
        return topography
    return topography.with_heights(changes.pop("heights", topography.heights), **changes)
