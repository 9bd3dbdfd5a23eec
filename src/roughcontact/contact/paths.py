"""Tangential loading programmes: displacement (or force) paths for :func:`solve_tangential`."""

from __future__ import annotations

import numpy as np

from ..errors import InputError


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
    """Paper 001 Fig. 6: from 0 to ``stroke`` and back to 0, ``cycles`` times.

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
