r"""Oliver-Pharr modulus from a load-displacement curve, with the viscous hold-creep correction.

Paper 001 measures the moduli of its HDPE and POM balls by nanoindentation (Berkovich tip, 10 mN,
20 mN/min loading and unloading, 60 s hold; HDPE 0.98 GPa, POM 1.38 GPa, Table 2) and evaluates
the curves with Oliver and Pharr's method plus the viscous correction of Tang and Ngan, its
eqs. 5-8:

.. math::

    \frac{1}{S_e} = \frac{1}{S} + \frac{\dot d}{|\dot F|}                     \quad (5)

    E_r = \frac{\sqrt{\pi}}{2 \beta} \frac{S_e}{\sqrt{A_c(d_c)}}              \quad (6)

    d_c = d_{max} - \epsilon \frac{F_{max}}{S_e}                              \quad (7)

    \frac{1 - \nu_s^2}{E_s} = \frac{1}{E_r} - \frac{1 - \nu_i^2}{E_i}        \quad (8)

S is the apparent stiffness dF/dd at the onset of unloading, from a power law
F = alpha (d - d_f)^m fitted to the upper part of the unloading curve (Oliver and Pharr 1992);
d_dot is the creep rate at the end of the hold at maximum load and F_dot the unloading rate at
the start of unloading (Tang and Ngan 2003: the creep carries on at its end-of-hold rate into
the unloading, so the measured displacement rate there is F_dot / S_e + d_dot).

Choices where the paper is silent or wrong (see ``docs/nanoindentation.md``):

* ``rate_sign="magnitude"`` (default) uses |F_dot| in eq. 5: creep makes the apparent
  stiffness too high, and the correction must lower it. The paper prints the signed unloading
  rate; with F_dot < 0 that raises the stiffness instead. ``rate_sign="printed"`` keeps that
  literal form for reproducing it.
* The area function is not given: the default is the ideal Berkovich A_c = 24.5 d_c^2; pass
  ``area_function`` for a calibrated tip. beta = 1 as printed.
* The unloading power law is fitted between 20 % and 95 % of F_max (``fit_range``).
* The creep rate at the end of the hold comes from the empirical hold law
  d(t) = d_0 + a (t - t_0)^(1/3) + k (t - t_0) of Feng and Ngan (2002), as used by Tang and Ngan
  (2003), fitted to the whole hold (``creep_fit="tang_ngan"``); ``creep_fit="linear"`` fits a
  straight line to the last ``creep_window`` of the hold instead (biased high while the creep
  is still decaying).
* Without a time column, sample numbers stand in for time (uniform sampling assumed): the
  ratio d_dot / F_dot in eq. 5 is then still right, the rates themselves are per sample.

Everything is SI inside; :func:`read_indentation_csv` converts the file's units once.

References
----------
W. C. Oliver and G. M. Pharr, "An improved technique for determining hardness and elastic modulus
using load and displacement sensing indentation experiments", J. Mater. Res. 7 (1992) 1564-1583.
doi:10.1557/JMR.1992.1564.
B. Tang and A. H. W. Ngan, "Accurate measurement of tip-sample contact size during nanoindentation
of viscoelastic materials", J. Mater. Res. 18 (2003) 1141-1148. doi:10.1557/JMR.2003.0156.
G. Feng and A. H. W. Ngan, "Effects of creep and thermal drift on modulus measurement using
depth-sensing indentation", J. Mater. Res. 17 (2002) 660-668. doi:10.1557/JMR.2002.0094.
Seed paper 001, eqs. 5-8, Fig. 7 and Table 2. doi:10.1115/1.4045900
"""

from __future__ import annotations

import csv
import math
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import optimize

from ..errors import InputError
from ..materials import Material, contact_modulus, get_material, reduced_modulus_to_youngs
from ..units import quantity

EPSILON_BERKOVICH = 0.75
"""Geometric constant epsilon of eq. 7 for a Berkovich (paraboloid-like) tip, as paper 001 uses."""

BERKOVICH_AREA_COEFFICIENT = 24.5
"""Ideal Berkovich area function A_c = 24.5 d_c^2 (paper 001 does not give its calibrated one)."""

RATE_SIGNS = ("magnitude", "printed")
CREEP_FITS = ("tang_ngan", "linear", "none")

MIN_POINTS = 10
MIN_FIT_POINTS = 4

# header names recognised for each column (lower case, units and punctuation stripped)
_COLUMN_NAMES = {
    "depth": (
        "depth", "displacement", "indentation depth", "penetration", "penetration depth", "disp",
        "pd", "h", "d", "z",
    ),
    "load": ("load", "force", "normal load", "normal force", "indentation load", "fn", "pn", "p", "f"),
    "time": ("time", "t", "elapsed time", "time on sample"),
}  # fmt: skip
_DIMENSIONS = {"depth": "length", "load": "force", "time": "time"}


def berkovich_area(contact_depth: float) -> float:
    """Projected contact area of an ideal Berkovich tip, A_c = 24.5 d_c^2 [m^2].

    Parameters
    ----------
    contact_depth : float
        Contact depth d_c [m].

    Returns
    -------
    float
        A_c [m^2].
    """
    return BERKOVICH_AREA_COEFFICIENT * contact_depth**2


# --- data ---------------------------------------------------------------------------------------


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


# --- CSV ----------------------------------------------------------------------------------------


def _header_name_and_unit(header: str) -> tuple[str, str | None]:
    """Split 'depth (nm)', 'Load [mN]' or 'time/s' into a lower-case name and a unit."""
    text = header.strip().strip('"').strip()
    match = re.match(r"^(.*?)\s*[\(\[]\s*([^\)\]]*)\s*[\)\]]\s*$", text)
    if match:
        return _clean_name(match.group(1)), match.group(2).strip() or None
    if "/" in text and not text.startswith("/"):
        name, unit = text.split("/", 1)
        return _clean_name(name), unit.strip() or None
    return _clean_name(text), None


def _clean_name(name: str) -> str:
    return re.sub(r"[\s_\-]+", " ", name.strip().lower()).strip()


def read_indentation_csv(
    path: str | Path,
    *,
    depth_column: str | None = None,
    load_column: str | None = None,
    time_column: str | None = None,
    depth_unit: str | None = None,
    load_unit: str | None = None,
    time_unit: str | None = None,
) -> IndentationCurve:
    """Read a load-displacement CSV into SI units.

    Lines starting with ``#`` are comments. The first other line is the header; columns are
    found by their names (depth/displacement/h, load/force/P, time/t; case and spaces ignored)
    unless named explicitly. Units come from the header, as in ``depth (nm)``, ``load [mN]`` or
    ``time/s``, and a ``*_unit`` argument overrides them. Comma, semicolon and tab delimiters are
    recognised.

    Parameters
    ----------
    path : str or Path
        The file.
    depth_column, load_column, time_column : str, optional
        Header of the column (without its unit) where auto-detection does not find it.
    depth_unit, load_unit, time_unit : str, optional
        Unit strings (``"nm"``, ``"mN"``, ``"s"``), overriding the header's.

    Returns
    -------
    IndentationCurve
        Depth [m], load [N], time [s] or None.

    Raises
    ------
    InputError
        Missing file, no header, a depth or load column that cannot be found, a column without
        a unit, a unit of the wrong dimension, a cell that is not a number.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(str(path), "file not found.", "check the path.")
    lines = [line for line in path.read_text(encoding="utf-8-sig").splitlines() if line.strip()]
    lines = [line for line in lines if not line.lstrip().startswith("#")]
    if len(lines) < 2:
        raise InputError(
            str(path), "has no header and data rows.", "give a header line, then one row per point."
        )
    delimiter = max((",", ";", "\t"), key=lines[0].count)
    if lines[0].count(delimiter) == 0:
        raise InputError(
            str(path), "has a single column.", "separate the columns by commas, semicolons or tabs."
        )
    rows = list(csv.reader(lines, delimiter=delimiter))
    headers = [_header_name_and_unit(h) for h in rows[0]]
    names = [name for name, _ in headers]
    wanted = {"depth": depth_column, "load": load_column, "time": time_column}
    overrides = {"depth": depth_unit, "load": load_unit, "time": time_unit}
    columns: dict[str, np.ndarray | None] = {}
    for quantity_name, explicit in wanted.items():
        option = f"{quantity_name}_column"
        if explicit is not None:
            key = _clean_name(explicit)
            if key not in names:
                raise InputError(
                    option, f"no column {explicit!r} in {path.name} (columns: {names}).", "name one of them."
                )
            index = names.index(key)
        else:
            found = [i for i, name in enumerate(names) if name in _COLUMN_NAMES[quantity_name]]
            if not found:
                if quantity_name == "time":
                    columns["time"] = None
                    continue
                raise InputError(
                    option,
                    f"no {quantity_name} column recognised in {path.name} (columns: {names}).",
                    f"name it with {option}= (CLI: --{quantity_name}-column).",
                )
            index = found[0]
        unit = overrides[quantity_name] or headers[index][1]
        if not unit:
            raise InputError(
                f"{quantity_name}_unit",
                f"column {rows[0][index].strip()!r} of {path.name} has no unit.",
                f"give it in the header, e.g. '{quantity_name} ({_EXAMPLE_UNITS[quantity_name]})', or pass "
                f"{quantity_name}_unit= (CLI: --{quantity_name}-unit).",
            )
        factor = quantity(f"1 {unit}", _DIMENSIONS[quantity_name], field=f"{quantity_name}_unit")
        values = []
        for number, row in enumerate(rows[1:], start=2):
            try:
                values.append(float(row[index]))
            except (ValueError, IndexError):
                raise InputError(
                    str(path),
                    f"data row {number - 1}, column {rows[0][index].strip()!r}: "
                    f"{row[index : index + 1]} is not a number.",
                    "remove text rows below the header, or mark them as comments with '#'.",
                ) from None
        columns[quantity_name] = np.asarray(values) * factor
    return IndentationCurve(columns["depth"], columns["load"], columns["time"], source=path.name)


_EXAMPLE_UNITS = {"depth": "nm", "load": "mN", "time": "s"}


# --- fits ---------------------------------------------------------------------------------------


@dataclass(frozen=True)
class UnloadingFit:
    """Power law F = alpha (d - d_f)^m fitted to the upper unloading curve (Oliver-Pharr 1992).

    Attributes
    ----------
    alpha : float
        Prefactor [N/m^m].
    final_depth : float
        d_f [m], the residual depth of the fit.
    exponent : float
        m [-] (1 for a flat punch, 1.5 for a paraboloid; Berkovich tips give 1.2-1.6).
    fit_range : tuple of float
        Fraction of F_max between which the points were fitted.
    points : int
        Points in the fit.
    rms_residual : float
        Root mean square load residual [N].
    """

    alpha: float
    final_depth: float
    exponent: float
    fit_range: tuple[float, float]
    points: int
    rms_residual: float

    def load(self, depth):
        """Fitted load [N] at ``depth`` [m] (zero below d_f)."""
        return (
            self.alpha
            * np.clip(np.asarray(depth, dtype=float) - self.final_depth, 0.0, None) ** self.exponent
        )

    def stiffness(self, depth: float) -> float:
        """dF/dd of the fit at ``depth`` [N/m]."""
        return float(self.exponent * self.alpha * max(depth - self.final_depth, 0.0) ** (self.exponent - 1.0))


def fit_unloading(
    depth: np.ndarray, load: np.ndarray, f_max: float, fit_range: tuple[float, float] = (0.2, 0.95)
) -> UnloadingFit:
    """Fit F = alpha (d - d_f)^m to the unloading points with fit_range[0] F_max <= F <= fit_range[1] F_max.

    Least squares in the load, in units scaled by the fitted data, bounds 1 <= m <= 10 and
    d_f below the smallest fitted depth.

    Raises
    ------
    InputError
        Too few points in the range, or depth that does not fall with the load.
    """
    low, high = fit_range
    if not 0.0 <= low < high <= 1.0:
        raise InputError("fit_range", f"{fit_range} is not 0 <= low < high <= 1.", "e.g. (0.2, 0.95).")
    keep = (load >= low * f_max) & (load <= high * f_max)
    d, f = depth[keep], load[keep]
    if d.size < MIN_FIT_POINTS:
        raise InputError(
            "unloading",
            f"only {d.size} unloading points between {low:.0%} and {high:.0%} of F_max "
            f"(at least {MIN_FIT_POINTS} needed).",
            "record the unloading more densely, or widen fit_range.",
        )
    if np.ptp(d) <= 0 or np.corrcoef(d, f)[0, 1] < 0.9:
        raise InputError(
            "unloading",
            "the depth does not fall with the load on the unloading curve "
            f"(correlation {np.corrcoef(d, f)[0, 1]:.2f} between {low:.0%} and {high:.0%} of F_max).",
            "check that depth and load are the right columns with the right signs, that the file holds one "
            "load-hold-unload cycle, and that creep at the onset of unloading (a 'nose') is outside "
            "fit_range.",
        )
    # scaled variables: x = (d - d_lo) / span, y = F / F_max
    d_lo, span = d.min(), np.ptp(d)
    x, y = (d - d_lo) / span, f / f_max

    def residual(p):
        alpha, x_f, m = p
        return alpha * np.clip(x - x_f, 0.0, None) ** m - y

    # start: scan d_f = d_lo - span * exp(u); for each, log F = log alpha + m log(d - d_f) is linear
    log_y = np.log(np.clip(y, 1e-300, None))
    best_start, best_cost = None, np.inf
    for u in np.linspace(-8.0, 5.0, 53):
        x_f = -math.exp(u)
        m, log_alpha = np.polyfit(np.log(x - x_f), log_y, 1)
        m = min(max(m, 1.0), 10.0)
        start = (math.exp(log_alpha), x_f, m)
        cost = float(np.sum(residual(start) ** 2))
        if cost < best_cost:
            best_start, best_cost = start, cost
    best = optimize.least_squares(
        residual, best_start, bounds=([0.0, -np.inf, 1.0], [np.inf, -1e-12, 10.0]), x_scale="jac"
    )
    alpha_s, x_f, m = best.x
    final_depth = d_lo + x_f * span
    alpha = alpha_s * f_max / span**m
    rms = float(np.sqrt(np.mean((alpha * (d - final_depth) ** m - f) ** 2)))
    return UnloadingFit(
        float(alpha), float(final_depth), float(m), (float(low), float(high)), int(d.size), rms
    )


@dataclass(frozen=True)
class CreepFit:
    """Fit of the hold at maximum load that gives the creep rate at its end.

    Attributes
    ----------
    method : str
        ``"tang_ngan"``: d = d_0 + a (t - t_0)^(1/3) + k (t - t_0) over the whole hold;
        ``"linear"``: d = d_0 + k t over the last ``window`` of the hold; ``"none"``: no correction.
    parameters : dict
        The fitted coefficients (SI).
    rate : float
        dd/dt at the end of the hold [m/s, or m per sample without a time column].
    window : float
        Fraction of the hold used.
    """

    method: str
    parameters: dict = field(default_factory=dict)
    rate: float = 0.0
    window: float = 1.0


def fit_creep(
    time: np.ndarray, depth: np.ndarray, method: str = "tang_ngan", *, window: float = 0.2
) -> CreepFit:
    """Creep rate at the end of the hold (the d_dot of paper 001 eq. 5).

    Parameters
    ----------
    time, depth : ndarray
        The hold segment [s, m].
    method : {"tang_ngan", "linear", "none"}
        ``"tang_ngan"`` (default) fits d = d_0 + a tau^(1/3) + k tau, tau = t - t_0, to the whole
        hold (Feng and Ngan 2002; Tang and Ngan 2003) and returns a/3 tau_end^(-2/3) + k.
        ``"linear"`` fits a straight line to the last ``window`` of the hold.
    window : float
        Fraction of the hold (by time) for ``"linear"``.

    Raises
    ------
    InputError
        An unknown method, or too few hold points.
    """
    if method not in CREEP_FITS:
        raise InputError("creep_fit", f"unknown method {method!r}.", f"choose one of {CREEP_FITS}.")
    if method == "none":
        return CreepFit("none", {}, 0.0, 0.0)
    if time.size < MIN_FIT_POINTS:
        raise InputError(
            "hold",
            f"only {time.size} points at maximum load; the creep rate needs at least {MIN_FIT_POINTS}.",
            "record a hold at maximum load, widen hold_tolerance, give the segments, or pass "
            "creep_fit='none' (no viscous correction).",
        )
    tau = time - time[0]
    if method == "linear":
        if not 0 < window <= 1:
            raise InputError(
                "creep_window", f"{window} is not in (0, 1].", "e.g. 0.2 (the last 20 % of the hold)."
            )
        keep = tau >= (1.0 - window) * tau[-1]
        if keep.sum() < 2:
            keep[-2:] = True
        slope, intercept = np.polyfit(tau[keep], depth[keep], 1)
        return CreepFit("linear", {"d0": float(intercept), "k": float(slope)}, float(slope), float(window))
    basis = np.column_stack([np.ones_like(tau), np.cbrt(tau), tau])
    (d0, a, k), *_ = np.linalg.lstsq(basis, depth, rcond=None)
    rate = a / 3.0 * tau[-1] ** (-2.0 / 3.0) + k
    return CreepFit("tang_ngan", {"d0": float(d0), "a": float(a), "k": float(k)}, float(rate), 1.0)


def unloading_rate(time: np.ndarray, load: np.ndarray, f_max: float, window: float = 0.2) -> float:
    """Return the signed dF/dt at the onset of unloading [N/s].

    The slope of a line through the unloading points above (1 - window) F_max.
    """
    keep = load >= (1.0 - window) * f_max
    keep[:2] = True
    slope = np.polyfit(time[keep] - time[0], load[keep], 1)[0]
    if not slope < 0:
        raise InputError(
            "unloading",
            f"the load does not fall at the onset of unloading (dF/dt = {slope:.3g}).",
            "check the segments and that the time column is in recording order.",
        )
    return float(slope)


# --- the analysis -------------------------------------------------------------------------------


@dataclass(frozen=True)
class IndentationResult:
    """Oliver-Pharr analysis with the viscous correction (paper 001 eqs. 5-8), SI units.

    Attributes
    ----------
    stiffness : float
        Apparent unloading stiffness S = dF/dd at d_max from the power-law fit [N/m].
    corrected_stiffness : float
        S_e of eq. 5 [N/m] (equal to S without creep correction).
    max_depth, max_load : float
        d_max [m] and F_max [N] at the onset of unloading.
    contact_depth : float
        d_c of eq. 7 [m].
    contact_area : float
        A_c(d_c) [m^2].
    reduced_modulus : float
        E_r of eq. 6 [Pa].
    youngs_modulus : float
        Sample modulus E_s of eq. 8 [Pa].
    uncorrected_reduced_modulus, uncorrected_youngs_modulus : float
        The same with S in place of S_e (plain Oliver-Pharr) [Pa].
    creep_rate : float
        d_dot at the end of the hold [m/s].
    unloading_rate : float
        Signed F_dot at the onset of unloading [N/s] (negative).
    time_basis : str
        ``"time"`` or ``"sample"`` (no time column: rates are per sample).
    unloading_fit : UnloadingFit
    creep_fit : CreepFit
    segments : Segments
    curve : IndentationCurve
    options : dict
        rate_sign, epsilon, beta, poissons_ratio, indenter name and its modulus and ratio.
    """

    stiffness: float
    corrected_stiffness: float
    max_depth: float
    max_load: float
    contact_depth: float
    contact_area: float
    reduced_modulus: float
    youngs_modulus: float
    uncorrected_reduced_modulus: float
    uncorrected_youngs_modulus: float
    creep_rate: float
    unloading_rate: float
    time_basis: str
    unloading_fit: UnloadingFit
    creep_fit: CreepFit
    segments: Segments
    curve: IndentationCurve
    options: dict

    def scalars(self) -> dict:
        """Return the scalar results and options as a flat dict (SI; JSON-ready)."""
        fit = self.unloading_fit
        return {
            "stiffness": self.stiffness,
            "corrected_stiffness": self.corrected_stiffness,
            "max_depth": self.max_depth,
            "max_load": self.max_load,
            "contact_depth": self.contact_depth,
            "contact_area": self.contact_area,
            "reduced_modulus": self.reduced_modulus,
            "youngs_modulus": self.youngs_modulus,
            "uncorrected_reduced_modulus": self.uncorrected_reduced_modulus,
            "uncorrected_youngs_modulus": self.uncorrected_youngs_modulus,
            "creep_rate": self.creep_rate,
            "unloading_rate": self.unloading_rate,
            "time_basis": self.time_basis,
            "fit_alpha": fit.alpha,
            "fit_final_depth": fit.final_depth,
            "fit_exponent": fit.exponent,
            "fit_range_low": fit.fit_range[0],
            "fit_range_high": fit.fit_range[1],
            "fit_points": fit.points,
            "fit_rms_residual": fit.rms_residual,
            "creep_fit": self.creep_fit.method,
            **{f"creep_fit_{k}": v for k, v in self.creep_fit.parameters.items()},
            **self.options,
        }


def _modulus(stiffness, max_depth, max_load, epsilon, beta, area_function, field_name):
    contact_depth = max_depth - epsilon * max_load / stiffness  # eq. 7
    if not contact_depth > 0:
        raise InputError(
            field_name,
            f"gives a contact depth d_c = d_max - eps F_max / S = {contact_depth:.4g} m <= 0 "
            f"(d_max = {max_depth:.4g} m, F_max = {max_load:.4g} N, S = {stiffness:.4g} N/m).",
            "check the depth and load units and the zero of the depth, and epsilon.",
        )
    area = float(area_function(contact_depth))
    if not (math.isfinite(area) and area > 0):
        raise InputError(
            "area_function",
            f"returned {area!r} m^2 at d_c = {contact_depth:.4g} m.",
            "return a positive area in m^2.",
        )
    reduced = math.sqrt(math.pi) / (2.0 * beta) * stiffness / math.sqrt(area)  # eq. 6
    return contact_depth, area, reduced


def _youngs(reduced: float, indenter: Material, poissons_ratio: float) -> float:
    try:
        return reduced_modulus_to_youngs(reduced, indenter, poissons_ratio)  # eq. 8
    except InputError as error:
        if error.field != "reduced_modulus":
            raise
        raise InputError(
            "reduced_modulus",
            f"E_r = {reduced:.4g} Pa from the data is not below the indenter's own "
            f"E_i/(1-nu_i^2) = {contact_modulus(indenter):.4g} Pa: the sample would need a negative "
            "compliance.",
            "check the depth and load units (a depth in nm read as um makes E_r 1000x too high), the "
            "indenter, the area function and the frame compliance.",
        ) from None


def oliver_pharr(
    curve: IndentationCurve,
    *,
    indenter: Material | str = "diamond berkovich",
    poissons_ratio: float = 0.5,
    epsilon: float = EPSILON_BERKOVICH,
    beta: float = 1.0,
    area_function: Callable[[float], float] = berkovich_area,
    fit_range: tuple[float, float] = (0.2, 0.95),
    rate_sign: str = "magnitude",
    creep_fit: str = "tang_ngan",
    creep_window: float = 0.2,
    rate_window: float = 0.2,
    hold_tolerance: float = 0.01,
    segments: Segments | None = None,
) -> IndentationResult:
    """Sample modulus from a load-hold-unload curve: Oliver-Pharr with Tang-Ngan's correction.

    Implements seed paper 001 eqs. 5-8 (see the module docstring for the equations and choices).

    Parameters
    ----------
    curve : IndentationCurve
        The record in SI (:func:`read_indentation_csv` or ``IndentationCurve(depth, load, time)``).
    indenter : Material or str
        Indenter (default ``"diamond berkovich"``: 1141 GPa, 0.07, as paper 001).
    poissons_ratio : float
        Sample nu_s of eq. 8 (paper 001: 0.5 for the polymers).
    epsilon : float
        eq. 7's geometric constant (0.75).
    beta : float
        Tip-shape factor dividing eq. 6 (1, as printed; 1.034 is often used for Berkovich tips).
    area_function : callable
        A_c [m^2] of d_c [m]; default the ideal Berkovich 24.5 d_c^2 (paper 001 gives none).
    fit_range : (float, float)
        Fractions of F_max between which the unloading power law is fitted (default 20-95 %).
    rate_sign : {"magnitude", "printed"}
        ``"magnitude"`` (default): 1/S_e = 1/S + d_dot/|F_dot|, the correct reading that lowers
        the stiffness when the sample creeps. ``"printed"``: the paper's literal d_dot/F_dot with
        the signed (negative) unloading rate, which raises it instead; for reproduction only.
    creep_fit : {"tang_ngan", "linear", "none"}
        How the end-of-hold creep rate is found (:func:`fit_creep`); ``"none"``: no correction.
    creep_window : float
        Fraction of the hold for ``creep_fit="linear"``.
    rate_window : float
        The unloading rate is the slope of F(t) over the unloading points above (1 - rate_window) F_max.
    hold_tolerance : float
        Band around F_max that counts as the hold when the segments are detected.
    segments : Segments, optional
        Loading / hold / unloading index ranges; detected from the load when not given.

    Returns
    -------
    IndentationResult

    Raises
    ------
    InputError
        Bad options; too few points, no unloading, depth not falling with the load, no hold with
        creep correction on; a corrected compliance that is not positive; a contact depth that is
        not positive; a reduced modulus the indenter cannot give (negative sample compliance).
    """
    if rate_sign not in RATE_SIGNS:
        raise InputError("rate_sign", f"unknown value {rate_sign!r}.", f"choose one of {RATE_SIGNS}.")
    for name, value in (("epsilon", epsilon), ("beta", beta)):
        if not (isinstance(value, int | float) and math.isfinite(value) and value > 0):
            raise InputError(
                name, f"{value!r} is not a positive number.", f"e.g. {name}=1.0 (epsilon: 0.75)."
            )
    if isinstance(indenter, str):
        indenter = get_material(indenter)
    if not isinstance(curve, IndentationCurve):
        raise InputError(
            "curve",
            f"expected an IndentationCurve, got {type(curve).__name__}.",
            "wrap the arrays: IndentationCurve(depth, load, time).",
        )
    segments = segments or detect_segments(curve, hold_tolerance=hold_tolerance)
    depth, load, clock = curve.depth, curve.load, curve.clock
    loading = slice(segments.loading.start, segments.loading.stop)
    if (
        np.ptp(depth[loading]) > 0
        and depth[loading].size > 2
        and np.corrcoef(depth[loading], load[loading])[0, 1] < 0
    ):
        raise InputError(
            "depth",
            "decreases while the load increases on loading.",
            "give the depth positive into the sample (multiply it by -1), or check the columns.",
        )
    onset = segments.unloading.start
    d_max, f_max = float(depth[onset]), float(load[onset])
    if not f_max > 0:
        raise InputError(
            "load",
            f"is {f_max:.4g} N at the onset of unloading.",
            "check the sign and the column of the load.",
        )
    un = segments.unloading
    d_un, f_un, t_un = depth[un], load[un], clock[un]
    if d_un.size < MIN_FIT_POINTS or f_un.min() > fit_range[0] * f_max:
        raise InputError(
            "unloading",
            f"no unloading segment down to {fit_range[0]:.0%} of F_max after the maximum load.",
            "give the whole record including the unloading (or the segments), or raise fit_range's "
            "lower end.",
        )
    fit = fit_unloading(d_un, f_un, f_max, fit_range)
    stiffness = fit.stiffness(d_max)
    if not stiffness > 0:
        raise InputError(
            "unloading",
            f"the fitted stiffness at d_max is {stiffness:.4g} N/m.",
            "check the unloading data and fit_range.",
        )
    hold = segments.hold
    creep = fit_creep(clock[hold], depth[hold], creep_fit, window=creep_window)
    f_dot = unloading_rate(t_un, f_un, f_max, rate_window)
    denominator = abs(f_dot) if rate_sign == "magnitude" else f_dot
    compliance = 1.0 / stiffness + creep.rate / denominator  # eq. 5
    if not compliance > 0:
        raise InputError(
            "rate_sign",
            f"eq. 5 gives a corrected compliance 1/S_e = {compliance:.4g} m/N <= 0 "
            f"(S = {stiffness:.4g} N/m, d_dot = {creep.rate:.4g}, F_dot = {f_dot:.4g}).",
            "use rate_sign='magnitude' (the printed signed form over-corrects), or check the hold segment.",
        )
    corrected = 1.0 / compliance
    d_c, area, reduced = _modulus(
        corrected, d_max, f_max, epsilon, beta, area_function, "corrected_stiffness"
    )
    youngs = _youngs(reduced, indenter, poissons_ratio)
    _, _, reduced_plain = _modulus(stiffness, d_max, f_max, epsilon, beta, area_function, "stiffness")
    youngs_plain = _youngs(reduced_plain, indenter, poissons_ratio)
    return IndentationResult(
        stiffness=stiffness,
        corrected_stiffness=corrected,
        max_depth=d_max,
        max_load=f_max,
        contact_depth=d_c,
        contact_area=area,
        reduced_modulus=reduced,
        youngs_modulus=youngs,
        uncorrected_reduced_modulus=reduced_plain,
        uncorrected_youngs_modulus=youngs_plain,
        creep_rate=creep.rate,
        unloading_rate=f_dot,
        time_basis="time" if curve.time is not None else "sample",
        unloading_fit=fit,
        creep_fit=creep,
        segments=segments,
        curve=curve,
        options={
            "rate_sign": rate_sign,
            "epsilon": float(epsilon),
            "beta": float(beta),
            "poissons_ratio": float(poissons_ratio),
            "indenter": indenter.name,
            "indenter_youngs_modulus": indenter.youngs_modulus,
            "indenter_poissons_ratio": indenter.poissons_ratio,
        },
    )


# --- synthetic curves ---------------------------------------------------------------------------


def synthetic_indentation_curve(
    youngs_modulus: float,
    *,
    poissons_ratio: float = 0.5,
    indenter: Material | str = "diamond berkovich",
    hardness: float = 60e6,
    max_load: float = 10e-3,
    loading_rate: float = 20e-3 / 60.0,
    unloading_rate: float | None = None,
    hold_time: float = 60.0,
    creep_rate: float = 0.0,
    unloading_exponent: float = 1.5,
    epsilon: float = EPSILON_BERKOVICH,
    beta: float = 1.0,
    area_function: Callable[[float], float] = berkovich_area,
    sampling_rate: float = 10.0,
    depth_noise: float = 0.0,
    load_noise: float = 0.0,
    seed: int | None = 0,
) -> IndentationCurve:
    """Make a load-hold-unload curve whose Oliver-Pharr modulus with the viscous correction is known.

    * Loading at ``loading_rate``: F = C d^2 (a self-similar pyramid) up to ``max_load``.
    * Hold of ``hold_time`` at F_max: creep d = d_0 + a tau^(1/3), the hold law of Feng and Ngan
      (2002) with k = 0, with a chosen so that the rate at the end of the hold is ``creep_rate``.
    * Unloading at ``unloading_rate`` (default: the loading rate): the elastic part follows
      F = alpha (d_e - d_f)^m whose slope at F_max is the S_e that eqs. 6-8 turn into
      ``youngs_modulus``; the creep carries on, at the hold law's rate scaled by F / F_max (a
      viscous flow driven by the load), so its rate at the onset of unloading is the end-of-hold
      rate: Tang and Ngan's assumption, under which eq. 5 with |F_dot| recovers S_e.

    The contact depth comes from the hardness, A_c(d_c) = F_max / H; d_max = d_c + eps F_max / S_e.

    Parameters
    ----------
    youngs_modulus : float
        Sample modulus E_s [Pa] to be recovered.
    poissons_ratio, indenter, epsilon, beta, area_function
        As in :func:`oliver_pharr` (eq. 8 and eqs. 6-7 run backwards).
    hardness : float
        Mean contact pressure F_max / A_c [Pa] (sets the depth; 60 MPa is HDPE-like).
    max_load : float
        F_max [N].
    loading_rate, unloading_rate : float
        |dF/dt| [N/s] (paper 001: 20 mN/min).
    hold_time : float
        [s] (paper 001: 60 s).
    creep_rate : float
        Creep rate at the end of the hold [m/s] (>= 0).
    unloading_exponent : float
        m of the elastic unloading power law (1.5: paraboloid of revolution, Sneddon).
    sampling_rate : float
        Samples per second.
    depth_noise, load_noise : float
        Standard deviation of Gaussian noise added to depth [m] and load [N].
    seed : int, optional
        Seed of the noise.

    Returns
    -------
    IndentationCurve
        Depth [m], load [N], time [s].
    """
    if isinstance(indenter, str):
        indenter = get_material(indenter)
    if creep_rate < 0:
        raise InputError(
            "creep_rate", f"{creep_rate!r} is negative.", "give the creep rate into the sample, >= 0."
        )
    unloading_rate = loading_rate if unloading_rate is None else unloading_rate
    reduced = 1.0 / (
        (1.0 - poissons_ratio**2) / youngs_modulus
        + (1.0 - indenter.poissons_ratio**2) / indenter.youngs_modulus
    )
    # contact depth from the hardness: solve A_c(d_c) = F_max / H
    target = max_load / hardness
    d_c = optimize.brentq(lambda x: area_function(x) - target, 1e-12, 1.0)
    s_e = 2.0 * beta / math.sqrt(math.pi) * reduced * math.sqrt(target)  # eq. 6 backwards
    d_max = d_c + epsilon * max_load / s_e  # eq. 7
    m = unloading_exponent
    d_f = d_max - m * max_load / s_e  # S_e = m F_max / (d_max - d_f)
    alpha = max_load / (d_max - d_f) ** m
    # creep law d = d0 + a tau^(1/3): rate a/3 tau^(-2/3) = creep_rate at tau = hold_time
    a = 3.0 * creep_rate * hold_time ** (2.0 / 3.0)
    d_load_end = d_max - a * hold_time ** (1.0 / 3.0)
    if d_load_end <= 0:
        raise InputError(
            "creep_rate",
            f"{creep_rate!r} m/s creeps deeper than the whole indent.",
            "give a smaller creep rate.",
        )
    dt = 1.0 / sampling_rate
    t_load = max_load / loading_rate
    t1 = np.arange(0.0, t_load, dt)
    f1 = loading_rate * t1
    d1 = d_load_end * np.sqrt(f1 / max_load)
    tau_hold = np.arange(0.0, hold_time, dt)
    t2 = t_load + tau_hold
    f2 = np.full_like(t2, max_load)
    d2 = d_load_end + a * np.cbrt(tau_hold)
    t_unload = max_load / unloading_rate
    tau_un = np.arange(0.0, t_unload + 0.5 * dt, dt)
    t3 = t_load + hold_time + tau_un
    f3 = np.clip(max_load - unloading_rate * tau_un, 0.0, None)

    # creep during unloading: rate a/3 (hold_time + tau)^(-2/3) * F/F_max, integrated exactly
    # (F/F_max = 1 - tau/t_unload is linear in tau)
    def creep_integral(tau):
        u = hold_time + tau
        # integral of (1 - (u - T)/t_u) * a/3 u^(-2/3) du from T to T + tau
        c = 1.0 + hold_time / t_unload
        return a * (
            c * (np.cbrt(u) - np.cbrt(hold_time))
            - (u ** (4.0 / 3.0) - hold_time ** (4.0 / 3.0)) / (4.0 * t_unload)
        )

    d3 = d_f + (f3 / alpha) ** (1.0 / m) + creep_integral(tau_un)
    time = np.concatenate([t1, t2, t3])
    depth = np.concatenate([d1, d2, d3])
    load = np.concatenate([f1, f2, f3])
    rng = np.random.default_rng(seed)
    if depth_noise > 0:
        depth = depth + rng.normal(0.0, depth_noise, depth.size)
    if load_noise > 0:
        load = load + rng.normal(0.0, load_noise, load.size)
    return IndentationCurve(depth, load, time, source="synthetic")


def write_indentation_csv(
    path: str | Path, curve: IndentationCurve, *, comments: Sequence[str] = (), depth_unit: str = "nm",
    load_unit: str = "mN", time_unit: str = "s", digits: int = 8,
) -> Path:  # fmt: skip
    """Write a curve as CSV with ``time (s)``, ``depth (nm)``, ``load (mN)`` columns and ``#`` comments."""
    path = Path(path)
    scale = {
        "depth": 1.0 / quantity(f"1 {depth_unit}", "length", field="depth_unit"),
        "load": 1.0 / quantity(f"1 {load_unit}", "force", field="load_unit"),
        "time": 1.0 / quantity(f"1 {time_unit}", "time", field="time_unit"),
    }
    lines = [f"# {c}" for c in comments]
    header = [f"depth ({depth_unit})", f"load ({load_unit})"]
    columns = [curve.depth * scale["depth"], curve.load * scale["load"]]
    if curve.time is not None:
        header.insert(0, f"time ({time_unit})")
        columns.insert(0, curve.time * scale["time"])
    lines.append(",".join(header))
    for row in zip(*columns, strict=True):
        lines.append(",".join(f"{v:.{digits}g}" for v in row))
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path
