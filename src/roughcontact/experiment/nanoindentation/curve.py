"""One load-displacement record and its segments: loading, hold at maximum load, unloading.

:class:`IndentationCurve` holds a record in SI units (depth into the sample [m], load [N],
time [s] or none) and refuses what no analysis can use: arrays of different lengths, NaN or
infinite values, a time that does not increase, fewer than :data:`MIN_POINTS` points. Without
a time column, :attr:`IndentationCurve.clock` gives the sample number in its place (uniform
sampling assumed).

:func:`detect_segments` splits a load-hold-unload cycle (seed paper 001: 10 mN at 20 mN/min,
a 60 s hold, unloading at 20 mN/min) into the index ranges of :class:`Segments` from the load
alone; :meth:`Segments.from_indices` and :meth:`Segments.from_times` give them explicitly.
The onset of unloading, where d_max and F_max are read, is the last point of the hold and the
first of the unloading.

References
----------
Seed paper 001: the nanoindentation protocol of its moduli (Table 2) and its curve, Fig. 7.
doi:10.1115/1.4045900
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import InputError
from .fits import MIN_FIT_POINTS

MIN_POINTS = 10
"""Fewest points an :class:`IndentationCurve` may have."""


@dataclass(frozen=True)
class IndentationCurve:
    """One load-displacement record in SI units.

    Attributes
    ----------
    depth : ndarray
        Displacement into the sample [m].
    load : ndarray
        Load [N].
    time : ndarray or None
        Time [s]; None where the file has none (sample numbers then stand in for time).
    source : str
        Where the data came from (file name), for messages.
    """

    depth: np.ndarray
    load: np.ndarray
    time: np.ndarray | None = None
    source: str = ""

    def __post_init__(self):
        depth = _checked_array(self.depth, "depth")
        load = _checked_array(self.load, "load")
        if depth.shape != load.shape:
            raise InputError(
                "load", f"has {load.size} values but depth has {depth.size}.", "give one load per depth."
            )
        time = None
        if self.time is not None:
            time = _checked_array(self.time, "time")
            if time.shape != depth.shape:
                raise InputError(
                    "time", f"has {time.size} values but depth has {depth.size}.", "give one time per depth."
                )
            if np.any(np.diff(time) <= 0):
                raise InputError(
                    "time",
                    "is not strictly increasing.",
                    "give the rows in the order they were recorded, one cycle per file, no repeated times.",
                )
        if depth.size < MIN_POINTS:
            raise InputError(
                "depth",
                f"only {depth.size} points; an indentation curve needs at least {MIN_POINTS}.",
                "give the whole load-hold-unload record.",
            )
        object.__setattr__(self, "depth", depth)
        object.__setattr__(self, "load", load)
        object.__setattr__(self, "time", time)

    @property
    def clock(self) -> np.ndarray:
        """Time [s], or the sample number where there is no time column."""
        return self.time if self.time is not None else np.arange(self.depth.size, dtype=float)


def _checked_array(values, name: str) -> np.ndarray:
    try:
        array = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise InputError(
            name, "is not a sequence of numbers.", f"give {name} as numbers in SI units."
        ) from None
    if array.ndim != 1:
        raise InputError(name, f"has shape {array.shape}, expected one dimension.", "give a flat sequence.")
    bad = ~np.isfinite(array)
    if bad.any():
        rows = np.flatnonzero(bad)
        raise InputError(
            name,
            f"has {rows.size} NaN or infinite values (first at row {rows[0]}).",
            "remove those rows or fill them from the neighbouring points before the analysis.",
        )
    return array


@dataclass(frozen=True)
class Segments:
    """Index ranges of the loading, hold and unloading segments (Python slices, stop exclusive).

    The hold ends at the first unloading point: ``hold.stop - 1 == unloading.start``, the onset
    of unloading where d_max and F_max are read.
    """

    loading: slice
    hold: slice
    unloading: slice

    @classmethod
    def from_indices(
        cls, hold_start: int, unloading_start: int, unloading_stop: int | None = None
    ) -> Segments:
        """Segments from the index where the hold begins and the index of the onset of unloading."""
        if not 0 <= hold_start <= unloading_start:
            raise InputError(
                "segments", f"hold_start {hold_start} is after unloading_start {unloading_start}.",
                "give 0 <= hold_start <= unloading_start.",
            )  # fmt: skip
        return cls(
            slice(0, hold_start + 1),
            slice(hold_start, unloading_start + 1),
            slice(unloading_start, unloading_stop),
        )

    @classmethod
    def from_times(
        cls, time: np.ndarray, hold_start: float, unloading_start: float, unloading_stop: float | None = None
    ) -> Segments:
        """Segments from times [s]: the nearest samples to the given instants."""
        time = np.asarray(time, dtype=float)

        def index(t):
            return int(np.argmin(np.abs(time - t)))

        stop = None if unloading_stop is None else index(unloading_stop) + 1
        return cls.from_indices(index(hold_start), index(unloading_start), stop)


def detect_segments(curve: IndentationCurve, *, hold_tolerance: float = 0.01) -> Segments:
    """Find loading, hold at maximum load and unloading from the load alone.

    The hold is the contiguous run of points around the maximum load whose load stays within
    ``hold_tolerance * F_max`` of it; loading is everything before, unloading everything after
    (starting at the last hold point, the onset of unloading).

    Parameters
    ----------
    curve : IndentationCurve
        The record.
    hold_tolerance : float
        Relative band around F_max that counts as holding (default 1 %).

    Returns
    -------
    Segments

    Raises
    ------
    InputError
        No unloading after the maximum load, or a load that is never positive.
    """
    load = curve.load
    peak = int(np.argmax(load))
    f_max = load[peak]
    if f_max <= 0:
        raise InputError("load", "is never positive.", "check the sign and the column of the load.")
    band = load >= (1.0 - hold_tolerance) * f_max
    # the band's ends still hold the last loading and the first unloading points: keep only the
    # points within 4 sigma of the load noise below the median level of the band; sigma from the
    # second differences of the whole record (zero on constant-rate ramps and flat holds)
    level = float(np.median(load[band]))
    sigma = 1.4826 * float(np.median(np.abs(np.diff(load, 2)))) / math.sqrt(6.0)
    near = band & (load >= level - max(4.0 * sigma, 1e-9 * f_max))
    peak = int(np.flatnonzero(near)[np.argmin(np.abs(np.flatnonzero(near) - peak))])
    start = peak
    while start > 0 and near[start - 1]:
        start -= 1
    stop = peak
    while stop < load.size - 1 and near[stop + 1]:
        stop += 1
    if load.size - stop < MIN_FIT_POINTS:
        raise InputError(
            "unloading",
            f"no unloading segment: only {load.size - stop - 1} points follow the hold at maximum load.",
            "give the whole record including the unloading, or the segments explicitly.",
        )
    return Segments.from_indices(start, stop)
