"""Text tables of points (x z or x y z columns): their position columns, their unit and the size they make."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from ..._text_table import split_cells, split_header
from ...errors import InputError
from ...units import format_si, length_unit_factor
from ..text import TextTable
from .metadata import channel_units, clash, grid_extent, length_factor


@dataclass(frozen=True)
class Positions:
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


def positions_of(path: Path, reader, table: TextTable | None) -> Positions | None:
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
        if unit is not None and length_factor(unit) is None:
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
    file_size_unit, file_height_unit = channel_units(channel)
    height_cell = cells[roles[1]] if cells and roles[1] is not None else None
    return Positions(
        x_cells,
        file_size_unit or (units[0] if units else None),
        file_height_unit or (None if height_cell is None else split_header(height_cell)[1]),
    )


def units_in_file(channel, positions: Positions | None = None) -> tuple[str | None, str | None]:
    """Return (size unit, height unit) of a SurfaceTopography channel as written in the file.

    Some readers (Bruker .di) give ``unit = (lateral unit, data unit)`` for non-height channels.
    For a text file of points, the units its header cells give where SurfaceTopography found none
    (:func:`positions_of`).
    """
    size_unit, height_unit = channel_units(channel)
    if positions is not None:
        return size_unit or positions.unit, height_unit or positions.height_unit
    return size_unit, height_unit


def grid_words(channel, unit: str | None) -> tuple[str, str]:
    """Say the grid of a file's positions and the size they make, in their unit: (words, size).

    ``("8 points 38.61 nm apart: a size of 8 x 38.61 nm = 308.9 nm", "308.9 nm")``. The size is
    the number of points times their spacing, n spacings (not the range, n - 1). Without a unit
    the numbers are said as the file holds them.
    """
    counts = [int(n) for n in channel.nb_grid_pts]
    extent = grid_extent(channel)
    factor = length_factor(unit)

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


def checked_position_unit(path: Path, positions: Positions, given: str | None, override: bool) -> str | None:
    """Return the unit of a file's positions: the file's, or ``given`` where the file has none.

    A ``given`` unit other than the file's is refused (naming the header cell) unless ``override``.
    """
    if given is not None:
        given_factor = length_unit_factor(given, field="position_unit")
    if given is None or positions.unit is None:
        return given if positions.unit is None else positions.unit
    if math.isclose(given_factor, length_factor(positions.unit) or math.nan, rel_tol=1e-12):
        return positions.unit
    if override:
        return given
    raise clash(
        "position_unit",
        f"{path.name} gives its positions in {positions.unit!r} ({positions.written}), but position unit "
        f"{given!r} was given.",
        f"the file's {positions.unit!r}",
        f"{given!r}",
    )


def size_beside_positions(path: Path, channel, positions: Positions, unit: str | None) -> InputError:
    """Return the refusal of a size given beside a file's own positions (they give the size)."""
    grid, size = grid_words(channel, unit)
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
        then = f"(if they are micrometres, the size is then {grid_words(channel, 'um')[1]})."
        fixes = {
            "python": f'leave size out and give the positions\' unit: position_unit="um" {then}',
            "study": f'remove size and give the positions\' unit: position_unit = "um" {then}',
            "cli": f"leave --size out and give the positions' unit: --position-unit um {then}",
        }
    return InputError("size", problem, fixes["python"], fixes=fixes)


def no_positions(path: Path, holds: str) -> InputError:
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
