r"""Analysis of friction hysteresis loops (tangential force vs tangential displacement), paper 001.

A loop is a tangential displacement delta (the capacitive-sensor reading in paper 001) and a
friction force F at constant normal force F0, simulated or measured. The analysis

1. splits the record into monotonic branches at the displacement reversals
   (:func:`split_branches`; a reversal is an extremum followed by a retreat of more than
   ``min_excursion`` times the displacement range, so sensor noise does not create reversals);
2. keeps the last complete loop (the last two complete branches: the converged cycle, paper 001
   sec. 4) and takes the stroke d_s = max - min of its displacement;
3. finds on each branch the gross-sliding plateau and the friction coefficient
   mu = mean ``|F|`` on the plateaus / F0 ("ratio of the sliding friction force to the normal force",
   paper 001 sec. 4);
4. fits paper 001 eq. 9, F = c1 (1 - (1 - c2 delta)^n), to the pre-sliding part of a branch,
   with delta and F counted from the branch's reversal point, and evaluates
   K_L = c1 c2 n (1 - c2 delta)^(n - 1) at points A, B and C;
5. integrates the closed path for the energy dissipated per cycle.

Rules (documented choices; the paper does not define them)
----------------------------------------------------------
Reversal force
    F_r = median of the force over the ``window`` samples that end at the reversal (the end of
    the previous branch, where the contact slides), robust to noise.
Plateau level and start (point D)
    The plateau force change is the median of (F - F_r) over the last ``plateau_tail`` fraction
    of the branch's displacement range. The pre-sliding span is its magnitude, S. Point D
    (start of full sliding) is the first sample at which the running median (``window``
    samples) of ``|F - F_r|`` reaches (1 - ``plateau_tolerance``) S; the plateau is every sample
    from D to the end of the branch. A branch whose force still rises by more than
    5 % of S (linear trend) over that tail has no plateau (mu is then nan).
Eq. 9 fit
    On the samples from the reversal to D, x = ``|delta - delta_r|``, y = ``|F - F_r|`` is fitted with
    y = c1 (1 - (1 - c2 x)^n) (``(1 - c2 x)`` clipped at 0, i.e. saturated at c1 beyond 1/c2),
    by :func:`scipy.optimize.curve_fit` started from the Mindlin-Deresiewicz values
    c1 = S, c2 = 1/x_D, n = 3/2. For the Mindlin contact this form is exact: the Masing branch
    Q = Q_r - 2 Q_M((delta_r - delta)/2) has c1 = 2 mu P, c2 = 1/(2 delta_0), n = 3/2.
Points A, B, C
    Where the fitted force change reaches the fractions (0.25, 0.5, 0.75) (``fractions``) of the
    branch's pre-sliding span S (= 2 mu F0 for a loop that slides in both directions).
    x = (1 - (1 - f S / c1)^(1/n)) / c2 and K_L from eq. 9 there.
Energy
    The area enclosed by the last loop, ``|closed-path integral of F d(delta)|`` (trapezoids; the
    shoelace formula closes the path with a straight segment).

All quantities are SI inside (m, N, J, N/m); :func:`read_loop_csv` converts the file's units once
(from its header, or the units the caller gives; none is assumed).

References
----------
Seed paper 001, "Evaluation of pre-sliding behavior at a rough interface: modeling and experiment",
ASME J. Appl. Mech. (2020), sec. 4 (stroke, mu) and sec. 5, eq. 9 and Fig. 10 (points A-D).
doi:10.1115/1.4045900

R. D. Mindlin and H. Deresiewicz, "Elastic spheres in contact under varying oblique forces",
J. Appl. Mech. 20 (1953) 327-344. doi:10.1115/1.4010702

K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, sec. 7.4.
doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import ClassVar

import numpy as np
from scipy.optimize import OptimizeWarning, curve_fit

from .._text_table import Column, column_factors, read_text_table
from ..display_html import NotebookDisplay
from ..errors import InputError
from ..origin import MEASURED, DataOrigin

__all__ = [
    "BranchAnalysis",
    "Loop",
    "LoopAnalysis",
    "analyse_loop",
    "eq9_force",
    "eq9_stiffness",
    "loop_energy",
    "read_loop_csv",
    "split_branches",
]

MIN_POINTS = 10
"""Fewest samples a loop may have."""


# --- reading --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Loop:
    """A friction loop in SI units.

    Attributes
    ----------
    displacement : ndarray
        Tangential displacement [m].
    force : ndarray
        Friction (tangential) force [N].
    time : ndarray or None
        Time [s], if the file had it.
    source : str
        Where it came from (file path).
    origin : DataOrigin
        What kind of data it is (measured, reconstructed or synthetic), from the file's ``#``
        header (``# origin: synthetic``, ``roughcontact.origin``); measured where the file does
        not say otherwise.
    """

    displacement: np.ndarray
    force: np.ndarray
    time: np.ndarray | None = None
    source: str = ""
    origin: DataOrigin = MEASURED


_DISPLACEMENT_NAMES = ("displacement", "delta", "disp", "x_cs", "x")
_FORCE_NAMES = ("force", "friction", "f_x", "fx", "f")
_TIME_NAMES = ("time", "t")


def _find_column(names: list[str], candidates: tuple[str, ...]) -> int | None:
    for candidate in candidates:
        for index, name in enumerate(names):
            if name == candidate:
                return index
    for candidate in candidates[:2]:
        for index, name in enumerate(names):
            if name.startswith(candidate):
                return index
    return None


def read_loop_csv(
    path: str | Path,
    displacement_unit: str | None = None,
    force_unit: str | None = None,
    *,
    time_unit: str | None = None,
    delimiter: str | None = None,
) -> Loop:
    """Read a friction loop from a CSV (or whitespace-separated) text file.

    Lines starting with ``#`` are comments. The first data line is a header when it holds a
    non-numeric entry; columns are then found by name (``displacement``/``delta``/``x``,
    ``force``/``friction``/``F``, optional ``time``/``t``; case-insensitive). Without a header
    the columns are (displacement, force) or, with three columns, (time, displacement, force).

    No unit is assumed. Each column takes its unit from its header cell (``displacement [um]``,
    ``force (N)``, ``time/s``, ``force in mN``) or, where the header gives none (or the file has
    no header), from the unit argument; a displacement or force column with neither is refused,
    and so is an argument that contradicts the header cell (naming the cell as written). A time
    column without a unit is not read (the analysis does not use the time).

    Parameters
    ----------
    path : str or Path
        The file.
    displacement_unit, force_unit, time_unit : str, optional
        Units of the columns whose header cell gives none (``"um"``, ``"nm"``, ``"m"``; ``"mN"``,
        ``"uN"``, ``"N"``; ``"s"``), converted to SI once, via :mod:`roughcontact.units`.
    delimiter : str, optional
        Column separator; detected (comma, semicolon, tab or whitespace) when not given.

    Returns
    -------
    Loop
        Displacement [m], force [N], time [s] or None, and the origin its ``#`` header declares
        (``# origin: synthetic``; measured where it says nothing else, ``roughcontact.origin``).

    Raises
    ------
    InputError
        Missing file, unknown columns, non-numeric or non-finite values, too few rows, a
        displacement or force column without a unit, or a unit argument that contradicts the
        header. UnitError for an unknown unit, or one of the wrong dimension.

    Examples
    --------
    A file whose header says ``displacement [nm],force [N]`` needs no argument; a file without
    units in its header needs both:

    >>> read_loop_csv("loop.csv", displacement_unit="nm", force_unit="N")  # doctest: +SKIP
    """
    path = Path(path)
    table = read_text_table(path, expected="displacement,force rows", delimiter=delimiter)
    names = table.names
    if names is not None:
        i_d, i_f, i_t = (_find_column(names, c) for c in (_DISPLACEMENT_NAMES, _FORCE_NAMES, _TIME_NAMES))
        if i_d is None or i_f is None or i_d == i_f:
            raise InputError(
                "path",
                f"{path}: cannot find displacement and force columns in header {table.header}.",
                "name the columns 'displacement' and 'force' (optionally 'time'), each with its unit, "
                "e.g. 'displacement [um],force [mN]'.",
            )
    elif table.width == 2:
        i_d, i_f, i_t = 0, 1, None
    elif table.width == 3:
        i_t, i_d, i_f = 0, 1, 2
    else:
        raise InputError(
            "path",
            f"{path} has {table.width} columns and no header.",
            "give a header naming the displacement and force columns with their units, e.g. "
            "'displacement [um],force [mN]'.",
        )
    length, newton, second = column_factors(
        table,
        [
            Column(i_d, "displacement_unit", displacement_unit, "length", "um"),
            Column(i_f, "force_unit", force_unit, "force", "mN"),
            Column(i_t, "time_unit", time_unit, "time", "s", required=False),
        ],
        path,
    )
    try:
        values = np.array([[float(row[i]) for i in (i_d, i_f)] for row in table.rows], dtype=float)
        times = None if second is None else np.array([float(row[i_t]) for row in table.rows]) * second
    except (ValueError, IndexError) as error:
        raise InputError(
            "path", f"{path}: unreadable data row ({error}).", "give numbers in every column."
        ) from None
    if values.size == 0:
        raise InputError("path", f"{path} has a header but no data.", "add displacement,force rows.")
    displacement, force = values[:, 0] * length, values[:, 1] * newton
    _check_signal(displacement, force)
    return Loop(displacement, force, times, str(path), table.origin("path"))


# --- branches -------------------------------------------------------------------------------------


def _check_signal(displacement, force) -> tuple[np.ndarray, np.ndarray]:
    d = np.asarray(displacement, dtype=float)
    f = np.asarray(force, dtype=float)
    if d.ndim != 1 or f.shape != d.shape:
        raise InputError(
            "force",
            f"shape {f.shape} does not match displacement {d.shape}.",
            "give two 1-D arrays of equal length.",
        )
    for name, values in (("displacement", d), ("force", f)):
        bad = ~np.isfinite(values)
        if bad.any():
            raise InputError(
                name,
                f"{int(bad.sum())} NaN or infinite value(s), first at sample {int(np.argmax(bad))}.",
                "remove or interpolate the missing samples.",
            )
    if d.size < MIN_POINTS:
        raise InputError("displacement", f"only {d.size} samples.", f"give at least {MIN_POINTS} samples.")
    return d, f


def split_branches(displacement, *, min_excursion: float = 0.05) -> list[tuple[int, int]]:
    """Split a displacement record into monotonic branches at its reversals.

    A reversal is the extreme sample of a run that is followed by a retreat of more than
    ``min_excursion`` times the total displacement range (a zig-zag filter): noise smaller
    than that threshold never makes a reversal, and the reversal sample is the noisy extreme.

    Parameters
    ----------
    displacement : array_like
        Displacement samples.
    min_excursion : float
        Threshold as a fraction of max - min, in (0, 1).

    Returns
    -------
    list of (start, stop)
        Index ranges (inclusive start, inclusive stop); consecutive branches share their
        reversal sample.

    Raises
    ------
    InputError
        Non-finite samples, a constant record, or a bad ``min_excursion``.
    """
    x = np.asarray(displacement, dtype=float)
    if not np.all(np.isfinite(x)) or x.ndim != 1 or x.size < 2:
        raise InputError("displacement", "needs a 1-D finite record of 2 or more samples.", "clean the data.")
    if not 0.0 < min_excursion < 1.0:
        raise InputError("min_excursion", f"{min_excursion!r} is outside (0, 1).", "use e.g. 0.05.")
    span = float(x.max() - x.min())
    if span == 0.0:
        raise InputError("displacement", "is constant.", "give a record that moves.")
    threshold = min_excursion * span
    turns: list[int] = []
    hi = lo = 0
    direction = 0
    ext = 0
    for k in range(1, x.size):
        v = x[k]
        if direction == 0:
            if v > x[hi]:
                hi = k
            if v < x[lo]:
                lo = k
            if x[hi] - x[lo] > threshold:
                direction = 1 if hi > lo else -1
                ext = hi if direction > 0 else lo
                first = lo if direction > 0 else hi  # where the first real run starts
                if abs(x[first] - x[0]) > threshold:  # the record first moved the other way
                    turns.append(first)
        elif direction > 0:
            if v >= x[ext]:
                ext = k
            elif x[ext] - v > threshold:
                turns.append(ext)
                direction, ext = -1, k
        else:
            if v <= x[ext]:
                ext = k
            elif v - x[ext] > threshold:
                turns.append(ext)
                direction, ext = 1, k
    bounds = [0, *turns, x.size - 1]
    return [(bounds[i], bounds[i + 1]) for i in range(len(bounds) - 1) if bounds[i + 1] > bounds[i]]


def loop_energy(displacement, force) -> float:
    """Area enclosed by a closed loop, ``|closed-path integral of F d(delta)|`` [J] (shoelace form)."""
    d = np.asarray(displacement, dtype=float)
    f = np.asarray(force, dtype=float)
    return abs(0.5 * float(np.sum((f + np.roll(f, -1)) * (np.roll(d, -1) - d))))


# --- eq. 9 ----------------------------------------------------------------------------------------


def eq9_force(x, c1: float, c2: float, n: float):
    """Paper 001 equation 9 force form, c1 (1 - (1 - c2 x)^n), saturated at c1 for c2 x >= 1."""
    base = np.clip(1.0 - c2 * np.asarray(x, dtype=float), 0.0, None)
    return c1 * (1.0 - base**n)


def eq9_stiffness(x, c1: float, c2: float, n: float):
    """Paper 001 equation 9, K_L = c1 c2 n (1 - c2 x)^(n - 1) (0 beyond x = 1/c2) [N/m]."""
    base = np.clip(1.0 - c2 * np.asarray(x, dtype=float), 0.0, None)
    return c1 * c2 * n * base ** (n - 1.0)


@dataclass(frozen=True)
class BranchAnalysis:
    """One monotonic branch of the last loop.

    Attributes
    ----------
    start, stop : int
        Sample range of the branch (inclusive) in the input record.
    direction : int
        +1 for increasing displacement, -1 for decreasing.
    reversal_displacement, reversal_force : float
        delta_r [m] and F_r [N] at the start of the branch.
    span : float
        Pre-sliding force change S = ``|F_plateau - F_r|`` [N] (2 mu F0 for a sliding loop).
    plateau_force : float
        Mean ``|F|`` on the plateau [N] (nan without plateau).
    sliding_start : int or None
        Sample index of point D (start of full sliding), None without plateau.
    sliding_distance : float
        ``|delta_D - delta_r|``, the pre-sliding distance [m] (nan without plateau).
    c1, c2, n : float
        Eq. 9 parameters [N], [1/m], [-] for the force change vs distance from the reversal.
    fractions : tuple of float
        Force fractions of S at the points (A, B, C by default).
    point_displacement, point_force : ndarray
        delta [m] and F [N] of the points in the record's coordinates.
    point_distance : ndarray
        ``|delta - delta_r|`` at the points [m].
    point_stiffness : ndarray
        K_L at the points from eq. 9 [N/m].
    """

    start: int
    stop: int
    direction: int
    reversal_displacement: float
    reversal_force: float
    span: float
    plateau_force: float
    sliding_start: int | None
    sliding_distance: float
    c1: float
    c2: float
    n: float
    fractions: tuple[float, ...]
    point_displacement: np.ndarray
    point_force: np.ndarray
    point_distance: np.ndarray
    point_stiffness: np.ndarray

    def stiffness(self, distance):
        """K_L [N/m] from equation 9 at ``distance`` [m] from the reversal."""
        return eq9_stiffness(distance, self.c1, self.c2, self.n)


_POINT_NAMES = "ABCEFGHIJ"
_PLATEAU_MAX_RISE = 0.05


@dataclass(frozen=True)
class LoopAnalysis(NotebookDisplay):
    """Result of :func:`analyse_loop` (SI units).

    Attributes
    ----------
    stroke : float
        d_s = max - min displacement of the last loop [m].
    mu : float
        Mean ``|F|`` on the gross-sliding plateaus of the last loop / F0 [-] (nan if none slides).
    normal_force : float
        F0 [N].
    energy : float
        Energy dissipated in the last loop [J].
    branches : tuple of BranchAnalysis
        The two branches of the last loop, in record order.
    branch : BranchAnalysis
        The branch chosen for the headline K_L values (``branch`` argument of analyse_loop).
    loop : slice
        Samples of the last loop in the input record.
    reversals : tuple of int
        Reversal samples of the whole record.
    """

    stroke: float
    mu: float
    normal_force: float
    energy: float
    branches: tuple[BranchAnalysis, ...]
    branch: BranchAnalysis
    loop: slice
    reversals: tuple[int, ...] = ()
    displacement: np.ndarray | None = field(default=None, repr=False)
    force: np.ndarray | None = field(default=None, repr=False)

    UNITS: ClassVar[dict[str, str]] = {
        "stroke": "m",
        "normal_force": "N",
        "energy": "J",
        "c1": "N",
        "c2": "1/m",
        "span": "N",
        **{
            f"{kind}_{name}": unit
            for kind, unit in (("K_L", "N/m"), ("delta", "m"), ("distance", "m"))
            for name in _POINT_NAMES
        },
        "distance_D": "m",
    }
    """SI unit of each dimensional scalar of :meth:`scalars`."""

    @property
    def point_names(self) -> tuple[str, ...]:
        """Names of the points: A, B, C for three fractions."""
        return tuple(_POINT_NAMES[i] for i in range(len(self.branch.fractions)))

    @property
    def lateral_stiffness(self) -> dict[str, float]:
        """K_L [N/m] at the points of the chosen branch, keyed A, B, C."""
        return dict(zip(self.point_names, map(float, self.branch.point_stiffness), strict=True))

    def scalars(self) -> dict[str, float]:
        """Return the scalar results as a flat dict (SI; JSON-ready)."""
        b = self.branch
        out = {
            "stroke": self.stroke,
            "mu": self.mu,
            "normal_force": self.normal_force,
            "energy": self.energy,
            "c1": b.c1,
            "c2": b.c2,
            "n": b.n,
            "span": b.span,
            "direction": float(b.direction),
        }
        for name, fraction, k, d, dist in zip(
            self.point_names,
            b.fractions,
            b.point_stiffness,
            b.point_displacement,
            b.point_distance,
            strict=True,
        ):
            out[f"fraction_{name}"] = float(fraction)
            out[f"K_L_{name}"] = float(k)
            out[f"delta_{name}"] = float(d)
            out[f"distance_{name}"] = float(dist)
        out["distance_D"] = b.sliding_distance
        return out

    def to_xarray(self):
        """Return the record, its last loop and its two branches' equation 9 fits as an ``xarray.Dataset``.

        ``displacement`` and ``force`` on ``sample`` (the whole record, with ``in_last_loop``),
        ``fit_displacement`` and ``fit_force`` on ``fit`` (each branch's eq. 9 curve from its
        reversal to point D, ``fit_branch`` 0 or 1 in record order), the points (A, B, C) of the
        chosen branch on ``point``; the scalars as attributes.
        """
        import xarray as xr

        data: dict = {}
        if self.displacement is not None:
            inside = np.zeros(self.displacement.size, dtype=np.int8)
            inside[self.loop] = 1
            data |= {
                "displacement": ("sample", self.displacement, {"units": "m"}),
                "force": ("sample", self.force, {"units": "N"}),
                "in_last_loop": ("sample", inside, {"units": "1"}),
            }
        fits = []
        for number, b in enumerate(self.branches):
            end = b.sliding_distance if math.isfinite(b.sliding_distance) else float(np.max(b.point_distance))
            distance = np.linspace(0.0, end, 60)
            fits.append(
                (
                    b.reversal_displacement + b.direction * distance,
                    b.reversal_force + b.direction * eq9_force(distance, b.c1, b.c2, b.n),
                    np.full(distance.size, number, dtype=np.int8),
                )
            )
        data |= {
            "fit_displacement": ("fit", np.concatenate([f[0] for f in fits]), {"units": "m"}),
            "fit_force": ("fit", np.concatenate([f[1] for f in fits]), {"units": "N"}),
            "fit_branch": ("fit", np.concatenate([f[2] for f in fits])),
            "point_displacement": ("point", np.asarray(self.branch.point_displacement), {"units": "m"}),
            "point_force": ("point", np.asarray(self.branch.point_force), {"units": "N"}),
            "point_stiffness": ("point", np.asarray(self.branch.point_stiffness), {"units": "N/m"}),
        }
        attributes = {k: v for k, v in self.scalars().items() if v is not None and math.isfinite(v)}
        return xr.Dataset(data, coords={"point": ("point", list(self.point_names))}, attrs=attributes)


def _running_median(values: np.ndarray, window: int) -> np.ndarray:
    if window <= 1 or values.size < window:
        return values
    pad = window // 2
    padded = np.pad(values, pad, mode="edge")
    view = np.lib.stride_tricks.sliding_window_view(padded, window)
    return np.median(view, axis=1)[: values.size]


def _analyse_branch(
    d: np.ndarray,
    f: np.ndarray,
    start: int,
    stop: int,
    *,
    fractions: tuple[float, ...],
    window: int,
    plateau_tolerance: float,
    plateau_tail: float,
) -> tuple[BranchAnalysis, np.ndarray]:
    """Analyse one branch; returns the analysis and the plateau ``|F|`` samples."""
    direction = 1 if d[stop] > d[start] else -1
    lo = max(0, start - window + 1)
    f_r = float(np.median(f[lo : start + 1]))
    d_r = float(d[start])
    x = direction * (d[start : stop + 1] - d_r)
    y = direction * (f[start : stop + 1] - f_r)
    x_range = float(x.max())
    tail = x >= (1.0 - plateau_tail) * x_range
    if tail.sum() < 3:
        tail[-3:] = True
    level = float(np.median(y[tail]))
    span = abs(level)
    if span == 0.0:
        raise InputError(
            "force", f"does not change on the branch starting at sample {start}.", "check the force column."
        )
    slope = np.polyfit(x[tail], y[tail], 1)[0] if np.ptp(x[tail]) > 0 else 0.0
    has_plateau = abs(slope) * np.ptp(x[tail]) <= _PLATEAU_MAX_RISE * span
    smooth = _running_median(y, window)
    reached = np.nonzero(smooth >= (1.0 - plateau_tolerance) * span)[0]
    if has_plateau and reached.size:
        i_d = int(reached[0])
    else:
        has_plateau, i_d = False, y.size - 1
    plateau = np.abs(f[start + i_d : stop + 1]) if has_plateau else np.array([])
    fit_x, fit_y = x[: i_d + 1], y[: i_d + 1]
    if fit_x.size < 4:
        raise InputError(
            "displacement",
            f"the pre-sliding part of the branch starting at sample {start} has only {fit_x.size} samples.",
            "record the loop with finer displacement steps (the eq. 9 fit needs at least 4).",
        )
    x_d = max(float(x[i_d]), float(np.max(fit_x)) * 0.5, np.finfo(float).tiny)
    p0 = (span, 1.0 / x_d, 1.5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OptimizeWarning)
        try:
            params, _ = curve_fit(
                eq9_force,
                fit_x,
                fit_y,
                p0=p0,
                bounds=((0.0, 0.0, 1.0), (np.inf, np.inf, 10.0)),
                x_scale=(span, 1.0 / x_d, 1.0),
                max_nfev=2000,
            )
        except RuntimeError as error:
            raise InputError(
                "force",
                f"the eq. 9 fit did not converge on the branch starting at sample {start} ({error}).",
                "check the loop for jumps or give more samples in the pre-sliding part.",
            ) from None
    c1, c2, n = map(float, params)
    fr = np.asarray(fractions, dtype=float)
    target = np.minimum(fr * span / c1, 1.0)
    distance = (1.0 - (1.0 - target) ** (1.0 / n)) / c2
    stiffness = eq9_stiffness(distance, c1, c2, n)
    analysis = BranchAnalysis(
        start=start,
        stop=stop,
        direction=direction,
        reversal_displacement=d_r,
        reversal_force=f_r,
        span=span,
        plateau_force=float(np.mean(plateau)) if plateau.size else math.nan,
        sliding_start=start + i_d if has_plateau else None,
        sliding_distance=float(x[i_d]) if has_plateau else math.nan,
        c1=c1,
        c2=c2,
        n=n,
        fractions=tuple(float(v) for v in fr),
        point_displacement=d_r + direction * distance,
        point_force=f_r + direction * eq9_force(distance, c1, c2, n),
        point_distance=distance,
        point_stiffness=np.asarray(stiffness, dtype=float),
    )
    return analysis, plateau


def analyse_loop(
    displacement,
    force,
    normal_force: float,
    *,
    fractions: tuple[float, ...] = (0.25, 0.5, 0.75),
    branch: str = "increasing",
    min_excursion: float = 0.05,
    window: int = 5,
    plateau_tolerance: float = 0.001,
    plateau_tail: float = 0.2,
) -> LoopAnalysis:
    """Analyse the last loop of a friction record: stroke, mu, equation 9 fit, K_L at A, B, C, energy.

    The rules are in the module docstring.

    Parameters
    ----------
    displacement, force : array_like or Loop
        Tangential displacement [m] and force [N] in record order; or pass a :class:`Loop` as
        ``displacement`` and ``None`` as ``force``.
    normal_force : float
        F0 [N], positive.
    fractions : tuple of float
        Fractions of the branch's pre-sliding force span at which the points (A, B, C) lie,
        each in (0, 1).
    branch : {"increasing", "decreasing"}
        Which branch of the last loop gives the headline points: the one along increasing
        displacement (paper 001 Fig. 10, the branch after the reversal at the minimum) or the
        other. Both are in ``LoopAnalysis.branches``.
    min_excursion : float
        Reversal threshold, fraction of the displacement range (:func:`split_branches`).
    window : int
        Samples of the running median (reversal force, point D), odd, >= 1.
    plateau_tolerance : float
        Relative force deficit below which a branch counts as sliding (point D).
    plateau_tail : float
        Fraction of a branch's displacement range, at its end, that sets the plateau level.

    Returns
    -------
    LoopAnalysis

    Raises
    ------
    InputError
        NaN or infinite samples, fewer than 10 samples, no reversal (a loop needs two complete
        branches), bad options, or a pre-sliding part too short to fit.
    """
    if isinstance(displacement, Loop):
        if force is not None:
            raise InputError("force", "given together with a Loop.", "pass analyse_loop(loop, None, F0).")
        displacement, force = displacement.displacement, displacement.force
    d, f = _check_signal(displacement, force)
    if (
        isinstance(normal_force, bool)
        or not isinstance(normal_force, (int, float))
        or not (math.isfinite(normal_force) and normal_force > 0)
    ):
        raise InputError(
            "normal_force", f"{normal_force!r} is not a positive number.", "give F0 in N, e.g. 0.025."
        )
    fractions = tuple(fractions)
    if not fractions or any(not 0.0 < v < 1.0 for v in fractions) or len(fractions) > len(_POINT_NAMES):
        raise InputError(
            "fractions", f"{fractions!r}: each must lie in (0, 1).", "use e.g. (0.25, 0.5, 0.75)."
        )
    if branch not in ("increasing", "decreasing"):
        raise InputError("branch", f"unknown branch {branch!r}.", "choose 'increasing' or 'decreasing'.")
    if not isinstance(window, int) or window < 1:
        raise InputError("window", f"{window!r} is not a positive integer.", "use e.g. 5.")
    if not 0.0 < plateau_tolerance < 0.5:
        raise InputError(
            "plateau_tolerance", f"{plateau_tolerance!r} is outside (0, 0.5).", "use e.g. 0.001."
        )
    if not 0.0 < plateau_tail < 1.0:
        raise InputError("plateau_tail", f"{plateau_tail!r} is outside (0, 1).", "use e.g. 0.2.")
    ranges = split_branches(d, min_excursion=min_excursion)
    spans = [abs(d[b] - d[a]) for a, b in ranges]
    # drop a trailing incomplete branch (the record stopped mid-stroke)
    if len(ranges) >= 3 and spans[-1] < 0.9 * spans[-2]:
        ranges, spans = ranges[:-1], spans[:-1]
    if len(ranges) < 2:
        raise InputError(
            "displacement",
            "has no displacement reversal, so there is no loop.",
            "give a record with at least one full back-and-forth cycle.",
        )
    last = ranges[-2:]
    results, plateaus = [], []
    for start, stop in last:
        analysis, plateau = _analyse_branch(
            d,
            f,
            start,
            stop,
            fractions=fractions,
            window=window,
            plateau_tolerance=plateau_tolerance,
            plateau_tail=plateau_tail,
        )
        results.append(analysis)
        plateaus.append(plateau)
    loop = slice(last[0][0], last[1][1] + 1)
    sliding = np.concatenate(plateaus)
    mu = float(np.mean(sliding)) / normal_force if sliding.size else math.nan
    wanted = 1 if branch == "increasing" else -1
    chosen = next((i for i, r in enumerate(results) if r.direction == wanted), 0)
    return LoopAnalysis(
        stroke=float(np.ptp(d[loop])),
        mu=mu,
        normal_force=float(normal_force),
        energy=loop_energy(d[loop], f[loop]),
        branches=tuple(results),
        branch=results[chosen],
        loop=loop,
        reversals=tuple(b for _, b in ranges[:-1]),
        displacement=d,
        force=f,
    )
