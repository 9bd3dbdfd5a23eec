r"""The three fits of an indentation analysis: unloading power law, hold creep rate, unloading rate.

Each turns one segment of the curve (plain arrays, SI) into one input of eq. 5 of seed
paper 001 (see :mod:`.oliver_pharr`):

* :func:`fit_unloading`: the power law of Oliver and Pharr (1992)

  .. math:: F = \alpha (d - d_f)^m

  fitted to the upper part of the unloading curve, between ``fit_range[0]`` and
  ``fit_range[1]`` of F_max (default 20-95 %); its slope at d_max is the apparent stiffness S.
* :func:`fit_creep`: the creep rate :math:`\dot d` at the end of the hold at maximum load. The
  default ``"tang_ngan"`` fits the empirical hold law of Feng and Ngan (2002), as used by Tang
  and Ngan (2003),

  .. math:: d(t) = d_0 + a (t - t_0)^{1/3} + k (t - t_0),

  to the whole hold and returns its slope at the end,
  :math:`\dot d = a/3\,(t_{end} - t_0)^{-2/3} + k`; ``"linear"`` fits a straight line to the
  last ``window`` of the hold instead (biased high while the creep is still decaying);
  ``"none"`` returns 0 (no viscous correction).
* :func:`unloading_rate`: the signed :math:`\dot F` at the onset of unloading, the slope of
  F(t) over the unloading points above (1 - window) F_max.

Without a time column the sample number stands in for time (uniform sampling assumed): the
rates are then per sample, and their ratio in eq. 5 is still right.

References
----------
W. C. Oliver and G. M. Pharr, "An improved technique for determining hardness and elastic modulus
using load and displacement sensing indentation experiments", J. Mater. Res. 7 (1992) 1564-1583.
doi:10.1557/JMR.1992.1564.
G. Feng and A. H. W. Ngan, "Effects of creep and thermal drift on modulus measurement using
depth-sensing indentation", J. Mater. Res. 17 (2002) 660-668. doi:10.1557/JMR.2002.0094.
B. Tang and A. H. W. Ngan, "Accurate measurement of tip-sample contact size during nanoindentation
of viscoelastic materials", J. Mater. Res. 18 (2003) 1141-1148. doi:10.1557/JMR.2003.0156.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize

from ...errors import InputError

CREEP_FITS = ("tang_ngan", "linear", "none")
"""Methods of :func:`fit_creep` (and ``creep_fit`` of :func:`.oliver_pharr.oliver_pharr`)."""

MIN_FIT_POINTS = 4
"""Fewest points a fitted segment (the unloading in the fit range, the hold) may have."""


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
    """Creep rate at the end of the hold (the d_dot of paper 001 equation 5).

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
