"""Loading programmes: tangential (:func:`solve_tangential`) and combined (:func:`solve_frictional`).

Built here (paper 001's Fig. 6 stroke path, the symmetric Mindlin-Deresiewicz cycles) or read
from a text table (:func:`read_programme_csv`: any user programme, tangential displacement or
force controlled, with an optional normal column; :func:`read_path_csv`: tangential only).
"""

from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

import numpy as np

from .._text_table import read_text_table
from ..errors import InputError
from ..units import DIMENSIONS, unit_factor


def _check_amplitude(name: str, value: float) -> float:
    if not (np.isfinite(value) and value > 0):
        raise InputError(name, f"must be a positive finite number, got {value!r}.", "give it in m (or N).")
    return float(value)


def _check_counts(cycles: int, steps: int) -> None:
    if int(cycles) < 1 or int(steps) < 1:
        raise InputError("cycles", f"cycles={cycles!r}, steps={steps!r}: both must be >= 1.", None)


def _branch(steps: int, spacing: str) -> np.ndarray:
    """Fractions (0, 1] of a branch after each step: uniform, or quadratic (fine after the reversal)."""
    k = np.arange(1, steps + 1) / steps
    if spacing == "uniform":
        return k
    if spacing == "quadratic":
        return k**2
    raise InputError("spacing", f"unknown spacing {spacing!r}.", "use 'uniform' or 'quadratic'.")


def stroke_path(
    stroke: float, *, cycles: int = 4, steps_per_stroke: int = 25, spacing: str = "uniform"
) -> np.ndarray:
    """Paper 001 figure 6: from 0 to ``stroke`` and back to 0, ``cycles`` times.

    Parameters
    ----------
    stroke : float
        d_s, the range of the tangential displacement [m] (Table 1: 2.7-4.3 um).
    cycles : int
        Number of 0 -> stroke -> 0 cycles (the paper uses four; the last loop is compared).
    steps_per_stroke : int
        Steps on each monotonic branch.
    spacing : {"uniform", "quadratic"}
        Equal steps, or steps growing as (k/N)^2 from each reversal, which resolves the
        pre-sliding part of a branch (a rough contact may slide after a few percent of the
        stroke) with the same number of steps.

    Returns
    -------
    ndarray, shape (2 cycles steps_per_stroke,)
        Displacements after each step (the start, 0, is the normal contact and not a step).
    """
    stroke = _check_amplitude("stroke", stroke)
    _check_counts(cycles, steps_per_stroke)
    fractions = _branch(int(steps_per_stroke), spacing)
    cycle = np.concatenate([stroke * fractions, stroke * (1.0 - fractions)])
    return np.tile(cycle, int(cycles))


def symmetric_path(amplitude: float, *, cycles: int = 1, steps_per_stroke: int = 25) -> np.ndarray:
    """0 -> +amplitude, then ``cycles`` full cycles +amplitude -> -amplitude -> +amplitude.

    The Mindlin-Deresiewicz programme (Johnson 1985 sec. 7.4) in displacement or force.
    """
    amplitude = _check_amplitude("amplitude", amplitude)
    _check_counts(cycles, steps_per_stroke)
    first = np.linspace(0.0, amplitude, steps_per_stroke + 1)[1:]
    down = np.linspace(amplitude, -amplitude, 2 * steps_per_stroke + 1)[1:]
    return np.concatenate([first] + [down, down[::-1][1:].tolist() + [amplitude]] * int(cycles))


def reversals(series) -> np.ndarray:
    """Return the indices of the steps after which a path (one component, from 0) changes direction.

    Steps that do not move are skipped: a hold between two strokes is no reversal. "Not moving" is
    a change below 1e-9 of the path's range, so the round-off of a held force (force control meets
    each target to about 1e-16 relative) makes no reversals either.
    """
    x = np.concatenate([[0.0], np.asarray(series, dtype=float)])
    dx = np.diff(x)
    moving = np.flatnonzero(np.abs(dx) > 1e-9 * np.ptp(x))
    turns = [moving[i] for i in range(1, len(moving)) if np.sign(dx[moving[i]]) != np.sign(dx[moving[i - 1]])]
    return np.asarray([t - 1 for t in turns], dtype=int)


def as_path(values, name: str) -> np.ndarray:
    """Return a path as an (n, 2) float array (a 1D path is along x); refuses NaN and empty paths."""
    path = np.asarray(values, dtype=float)
    if path.ndim == 1:
        path = np.stack([path, np.zeros_like(path)], axis=1)
    if path.ndim != 2 or path.shape[1] != 2 or len(path) == 0:
        raise InputError(name, f"shape {np.shape(values)}: need (n,) or (n, 2) with n >= 1.", None)
    if not np.all(np.isfinite(path)):
        bad = int(np.flatnonzero(~np.all(np.isfinite(path), axis=1))[0])
        raise InputError(
            name, f"step {bad} is not a finite number ({path[bad].tolist()}).", "remove or fill it."
        )
    return path


CONTROLS = {DIMENSIONS["length"]: "displacement", DIMENSIONS["force"]: "force"}
"""The control a path column's unit selects: a length prescribes the rigid displacement, a force the force."""
NORMAL_NAMES = ("f_n", "fn", "n", "p", "f_z", "fz", "normal", "z", "approach", "delta_z")
"""Column names (any case) of the normal programme: a force (``F_n [mN]``) or an approach (``z [um]``)."""
NORMAL_CONTROLS = {DIMENSIONS["length"]: "approach", DIMENSIONS["force"]: "force"}
_PATH_FIX = (
    "start the file with a header naming each column with its unit: 'x [um]' or 'x [um],y [um]' "
    "(rigid tangential displacement), 'Q_x [mN]' or 'Q_x [mN],Q_y [mN]' (tangential force), and "
    "optionally one normal column, 'F_n [mN]' (normal force) or 'z [um]' (normal approach)."
)


class Programme(NamedTuple):
    """A loading programme read from a table (SI).

    ``tangential``: (n, 2) displacement [m] or force [N] as ``control`` says; ``normal``: (n,)
    normal force [N] or approach [m] as ``normal_control`` says, or None (a constant normal force
    given elsewhere).
    """

    tangential: np.ndarray
    control: str
    normal: np.ndarray | None
    normal_control: str | None


def read_programme_csv(path: str | Path, *, delimiter: str | None = None) -> Programme:
    """Read a loading programme: one row per step, tangential x (and y), optionally a normal column.

    The header must give every column a unit, and the units choose the control: lengths
    (``x [um], y [um]``) prescribe the rigid tangential displacement of the counter-body, forces
    (``Q_x [mN], Q_y [mN]``) the tangential force (see :func:`solve_tangential`). A column named
    for the normal direction (:data:`NORMAL_NAMES`: ``F_n [mN]``, ``N [mN]``, ``P [mN]`` for the
    normal force, ``z [um]`` or ``approach [um]`` for the normal approach) makes it a combined
    programme (:func:`~roughcontact.contact.frictional.solve_frictional`). A column named
    ``step`` and columns in units of time (``t [s]``) are ignored. The start is the unloaded
    state (combined) or the normal contact (tangential only) and is not a row. Units are converted
    once, through :mod:`roughcontact.units`.

    Parameters
    ----------
    path : str or Path
        CSV, semicolon, tab or whitespace separated text file; ``#`` starts a comment line.
    delimiter : str, optional
        Column separator (detected when not given).

    Returns
    -------
    Programme

    Raises
    ------
    InputError
        No header, a column without a unit, tangential units of another or of mixed dimensions
        (a displacement and a force column), more than two tangential or more than one normal
        column, a cell that is not a number, a NaN or infinite step, no rows, a normal force or
        approach <= 0 (contact lost at that row).
    UnitError
        An unknown unit.
    """
    table = read_text_table(path, expected="one row per step, x then y", delimiter=delimiter)
    if table.names is None:
        raise InputError("path", f"{path} has no header, so its units are unknown.", _PATH_FIX)
    columns, factors, controls, normal = [], [], set(), []
    for index, (name, unit) in enumerate(zip(table.names, table.units, strict=True)):
        if name == "step" and unit is None:
            continue
        cell = table.header[index]  # as written, for the messages
        if unit is None:
            raise InputError("path", f"{path}: the header cell {cell!r} has no unit.", _PATH_FIX)
        factor, dimension = unit_factor(unit)
        if dimension == DIMENSIONS["time"]:
            continue
        if dimension not in CONTROLS:
            raise InputError(
                "path",
                f"{path}: the header cell {cell!r} is in [{unit}], neither a length nor a force.",
                _PATH_FIX,
            )
        if name.strip().lower() in NORMAL_NAMES:
            normal.append((index, float(factor), NORMAL_CONTROLS[dimension], name))
            continue
        columns.append(index)
        factors.append(float(factor))
        controls.add(CONTROLS[dimension])
    if not 1 <= len(columns) <= 2 or len(controls) != 1:
        raise InputError(
            "path",
            f"{path}: {len(columns)} tangential displacement or force column(s) ({sorted(controls)}); need "
            "one or two of the same kind (mixed controls in one direction are not a programme).",
            _PATH_FIX,
        )
    if len(normal) > 1:
        raise InputError(
            "path",
            f"{path}: {len(normal)} normal columns ({', '.join(n[3] for n in normal)}); need at most one.",
            "give the normal force or the normal approach, not both.",
        )
    every = columns + [n[0] for n in normal]
    values = np.array([_numbers(row, every, number, path) for number, row in enumerate(table.rows, 1)])
    if len(values) == 0:
        raise InputError("path", f"{path} has a header but no steps.", "add one row per step.")
    tangential = values[:, : len(columns)] * np.array(factors)
    tangential = as_path(tangential[:, 0] if len(columns) == 1 else tangential, "path")
    if not normal:
        return Programme(tangential, controls.pop(), None, None)
    _, factor, normal_control, name = normal[0]
    load = as_path(values[:, -1] * factor, "path")[:, 0]
    low = np.flatnonzero(load <= 0)
    if low.size:
        raise InputError(
            "path",
            f"{path}: data row {int(low[0]) + 1} has {name} = {values[low[0], -1]:g} <= 0: contact is "
            "lost there.",
            "keep the normal force (or approach) above zero; end the programme before the bodies separate.",
        )
    return Programme(tangential, controls.pop(), load, normal_control)


def read_path_csv(path: str | Path, *, delimiter: str | None = None) -> tuple[np.ndarray, str]:
    """Read a tangential programme (:func:`read_programme_csv` without a normal column).

    Returns
    -------
    programme : ndarray, shape (n, 2)
        The programme in SI (m or N), x and y (0 when only x is given).
    control : {"displacement", "force"}

    Raises
    ------
    InputError
        As :func:`read_programme_csv`, and a normal column (the programme is then a combined one).
    """
    programme = read_programme_csv(path, delimiter=delimiter)
    if programme.normal is not None:
        raise InputError(
            "path",
            f"{path} has a normal column: it is a combined normal and tangential programme.",
            "solve it with solve_frictional (read_programme_csv), or drop the normal column.",
        )
    return programme.tangential, programme.control


def _numbers(row: list[str], columns: list[int], number: int, path) -> list[float]:
    """Return the cells ``columns`` of data row ``number`` as floats, or say which row is not numbers."""
    try:
        return [float(row[i]) for i in columns]
    except (IndexError, ValueError):
        raise InputError(
            "path", f"{path}: data row {number} {row} is not numbers.", "give a number in every column."
        ) from None
