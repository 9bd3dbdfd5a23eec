r"""The spread of a quantity over independent realisations: mean, scatter and the interval of the mean.

A prediction that rests on a generated surface depends on the draw. Run on N independent
realisations (seeds derived from the study's seed, or measured spots of one sample), each
quantity is summarised by

.. math::

    \bar x = \frac1N \sum_i x_i, \qquad
    s = \sqrt{\frac{1}{N-1}\sum_i (x_i - \bar x)^2}, \qquad
    \bar x \pm t_{0.975,\,N-1}\, \frac{s}{\sqrt N}

(the sample mean, the sample standard deviation and Student's 95 % confidence interval of the
mean), with the smallest and largest value. The other uncertainty of a computed number, that of
its grid, is estimated by :func:`convergence_order` (observed order and Richardson extrapolation
over three grids). The interval is that of the *mean* over realisations:
it shrinks as 1/sqrt(N); the scatter of one realisation is ``std``. Values that are not finite
(a failed or undefined case) are left out and ``n`` counts the others.

References
----------
Student (W. S. Gosset), "The probable error of a mean", Biometrika 6 (1908) 1-25.
doi:10.1093/biomet/6.1.1
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Iterable
from dataclasses import asdict, dataclass

import numpy as np

CONFIDENCE = 0.95
"""Level of the confidence interval of the mean."""


def realisation_seed(base: int, *keys: str | int) -> int:
    """Return the seed of one realisation: a hash of the base seed and what names the draw.

    A study derives the seed of a generated topography from (study seed, topography name,
    sample, replicate); Python routes to the same scenario (paper 000's scans) call this with the
    same keys and draw the same surfaces. 32 bits of SHA-256 of the JSON list ``[base, *keys]``.
    """
    text = json.dumps([base, *keys])
    return int(hashlib.sha256(text.encode()).hexdigest()[:8], 16)


@dataclass(frozen=True)
class Spread:
    """Summary of one quantity over realisations (its unit is the values').

    Attributes
    ----------
    n : int
        Number of finite values.
    mean, std : float
        Sample mean and standard deviation (ddof = 1; NaN for n < 2).
    ci95_low, ci95_high : float
        Student's 95 % confidence interval of the mean (NaN for n < 2), within the quantity's
        bounds where it has any (see ``note``).
    min, max : float
        Smallest and largest value.
    note : str
        Why an interval was cut at a bound of the quantity ('' when none was).
    bounds : tuple of float
        The range the quantity can take (``(-inf, inf)`` unless given to :func:`spread`).
    """

    n: int
    mean: float
    std: float
    ci95_low: float
    ci95_high: float
    min: float
    max: float
    note: str = ""
    bounds: tuple[float, float] = (-math.inf, math.inf)

    @property
    def half_width(self) -> float:
        """Half the width of the confidence interval of the mean."""
        return 0.5 * (self.ci95_high - self.ci95_low)

    def prediction(self) -> tuple[float, float]:
        r"""Return the 95 % prediction interval of one more realisation (NaN for n < 2).

        :math:`\bar x \pm t_{0.975, N-1}\, s \sqrt{1 + 1/N}`, cut at the quantity's bounds: where a
        single new draw (one ball, one island, or one measurement of a spot, if the model holds)
        falls 95 % of the time. Judge a claim about one specimen with this, not with the interval
        of the mean.
        """
        if self.n < 2:
            return math.nan, math.nan
        from scipy import stats

        half = float(stats.t.ppf(0.5 + CONFIDENCE / 2, self.n - 1)) * self.std * math.sqrt(1 + 1 / self.n)
        return _within(self.mean - half, self.mean + half, self.bounds)

    def verdict(self, reference: float, *, of: str = "mean") -> Verdict:
        """Judge where ``reference`` lies against this spread, at the level of the claim.

        Parameters
        ----------
        reference : float
            The value the claim compares with (Mindlin's K_L, the statistical model's peak, 1 for
            a ratio).
        of : {"mean", "one"}
            ``"mean"``: a claim about the mean over realisations, judged with the 95 % confidence
            interval of the mean. ``"one"``: a claim about one specimen (one ball, one island),
            judged with the 95 % prediction interval of one realisation.

        Returns
        -------
        Verdict
            ``below`` where the whole interval lies below ``reference``, ``above`` where it lies
            above, ``not established`` where it holds ``reference``, ``one realisation`` without
            an interval (n < 2).
        """
        if of not in ("mean", "one"):
            raise ValueError(f"of must be 'mean' or 'one', not {of!r}")
        interval = self.prediction() if of == "one" else (self.ci95_low, self.ci95_high)
        low, high = interval
        if self.n < 2 or not (math.isfinite(low) and math.isfinite(high)):
            word = "one realisation"
        elif high < reference:
            word = "below"
        elif low > reference:
            word = "above"
        else:
            word = "not established"
        return Verdict(word, float(reference), of, (low, high), (self.ci95_low, self.ci95_high), self.n)

    def within(self, low: float, high: float, *, of: str = "one") -> str:
        """Say whether the interval of the claim lies inside the band [``low``, ``high``].

        For a printed value read with a tolerance ("roughly 40": a band around 40). ``of`` as in
        :meth:`verdict`. Returns ``inside`` where the whole interval lies in the band,
        ``outside`` where it lies wholly outside it, ``not established`` where it straddles an
        edge, ``one realisation`` without an interval.
        """
        interval = self.prediction() if of == "one" else (self.ci95_low, self.ci95_high)
        if self.n < 2 or not all(math.isfinite(x) for x in interval):
            return "one realisation"
        if low <= interval[0] and interval[1] <= high:
            return "inside"
        if interval[1] < low or interval[0] > high:
            return "outside"
        return "not established"

    def row(self) -> dict[str, float | int | str]:
        """Return the summary as a table row (its keys are the attribute names, bounds left out)."""
        row = asdict(self)
        del row["bounds"]
        return row


INTERVAL_NAMES = {
    "mean": "95 % confidence interval of the mean",
    "one": "95 % prediction interval of one realisation",
}
"""What each interval of a :class:`Verdict` is called in tables and sentences."""


@dataclass(frozen=True)
class Verdict:
    """Where a reference value lies against a quantity's spread, judged at the level of the claim.

    Attributes
    ----------
    word : str
        ``below``, ``above``, ``not established`` or ``one realisation``.
    reference : float
        The value compared with.
    of : str
        ``"one"`` (a claim about one specimen: the prediction interval) or ``"mean"`` (a claim
        about the mean: its confidence interval).
    interval : tuple of float
        The interval the verdict rests on.
    mean_interval : tuple of float
        The 95 % confidence interval of the mean, shown beside a prediction interval.
    n : int
        Number of realisations.
    """

    word: str
    reference: float
    of: str
    interval: tuple[float, float]
    mean_interval: tuple[float, float]
    n: int

    @property
    def established(self) -> bool:
        """True when the interval lies wholly on one side of the reference."""
        return self.word in ("below", "above")

    @property
    def interval_name(self) -> str:
        """The name of the interval the verdict rests on."""
        return INTERVAL_NAMES[self.of]

    def describe(self, number=None) -> str:
        """Say the verdict with its interval, e.g. ``below 1 (95 % prediction interval ..., n = 5)``.

        ``number`` formats the values (default ``'{:.3g}'``).
        """
        number = number or "{:.3g}".format
        low, high = self.interval
        if self.word == "one realisation":
            return f"one realisation: no interval to judge against {number(self.reference)}"
        place = "holds" if self.word == "not established" else f"lies {self.word}"
        return (
            f"{self.word}: the {self.interval_name} [{number(low)}, {number(high)}] (n = {self.n}) "
            f"{place} {number(self.reference)}"
        )


def _within(low: float, high: float, bounds: tuple[float, float]) -> tuple[float, float]:
    return max(low, bounds[0]), min(high, bounds[1])


def spread(values: Iterable[float], *, bounds: tuple[float, float] | None = None) -> Spread:
    """Summarise ``values`` (one per realisation) by mean, std, 95 % interval of the mean, min and max.

    Parameters
    ----------
    values : iterable of float
        One value per realisation; NaN and infinite values are left out.
    bounds : (float, float), optional
        The range the quantity can take (``(0, inf)`` for a stiffness or a load, ``(0, 1)`` for
        a fraction; :func:`natural_bounds`). Student's interval assumes a normal scatter and
        reaches past such a bound when the scatter is wide against the mean (n = 2, a fraction
        near 1): it is then cut at the bound and ``note`` says so.

    Returns
    -------
    Spread
        With ``n = 0`` and NaN everywhere when no value is finite.
    """
    from scipy import stats

    limits = (-math.inf, math.inf) if bounds is None else (float(bounds[0]), float(bounds[1]))
    array = np.asarray([float(v) for v in values], dtype=float)
    array = array[np.isfinite(array)]
    n = int(array.size)
    if n == 0:
        return Spread(0, *(math.nan,) * 6, bounds=limits)
    mean = float(array.mean())
    if n == 1:
        return Spread(1, mean, math.nan, math.nan, math.nan, mean, mean, bounds=limits)
    std = float(array.std(ddof=1))
    half = float(stats.t.ppf(0.5 + CONFIDENCE / 2, n - 1)) * std / math.sqrt(n)
    low, high = _within(mean - half, mean + half, limits)
    cut = [
        f"{bound:g}"
        for bound, raw, kept in ((limits[0], mean - half, low), (limits[1], mean + half, high))
        if raw != kept
    ]
    note = (
        f"95 % interval cut at {' and '.join(cut)}: the quantity lies in [{limits[0]:g}, {limits[1]:g}], "
        f"and Student's interval of {n} values reaches past it"
        if cut
        else ""
    )
    return Spread(n, mean, std, low, high, float(array.min()), float(array.max()), note, limits)


NON_NEGATIVE_UNITS = frozenset({"m^2", "N/m", "J", "s"})
"""Units of quantities that cannot be negative whatever their name (areas, stiffnesses, energies, times)."""


ROOT_MEAN_SQUARE = frozenset(
    {"ra", "rq", "sa", "sq", "m0", "m2", "m4", "rms_height", "rms_slope", "rms_curvature"}
)
"""Roughness statistics and spectral moments: non-negative whatever their unit."""


def natural_bounds(name: str, unit: str | None = None) -> tuple[float, float] | None:
    """Return the range a result's scalar can take from its name and unit, or None if unbounded.

    Fractions and shares lie in [0, 1]; counts (``number_of_*``, ``*_springs``, ``iterations``),
    residuals, gaps, areas, stiffnesses (``K_L_*``), energies, times, friction coefficients
    (``mu*``), roughness statistics and spectral moments, largest pressures and von Mises
    stresses (``max_*``), and ratios of positive quantities (``*_over_*``, ``*_to_*``, ``* / *``)
    are non-negative. Forces, approaches and interferences may be negative (adhesion, a pulled
    flat) and are not bounded.
    """
    lowered = name.lower()
    if "fraction" in lowered or lowered.endswith("_share") or lowered.startswith("share"):
        return (0.0, 1.0)
    words = lowered.replace("/", " / ")
    if (
        unit in NON_NEGATIVE_UNITS
        or lowered in ROOT_MEAN_SQUARE
        or lowered in ("iterations", "residual")
        or lowered.startswith(("number_of", "k_l", "mu", "crossover", "max_pressure", "max_von_mises"))
        or lowered.endswith(("_springs", "_area", "patches", "_gap", "von_mises"))
        or "_over_" in lowered
        or "_to_" in lowered
        or " / " in words
    ):
        return (0.0, math.inf)
    return None


def convergence_order(sizes: list[float], values: list[float]) -> tuple[float, float] | None:
    r"""Return the observed order of convergence and the Richardson extrapolation of three grids.

    ``sizes`` are the three finest pixel sizes h (any order), ``values`` the quantity on each.
    Solves :math:`(w_3 - w_2)/(w_2 - w_1) = (h_3^p - h_2^p)/(h_2^p - h_1^p)` for p (h1 < h2 < h3)
    and extrapolates :math:`w_0 = w_1 - (w_2 - w_1)\, h_1^p / (h_2^p - h_1^p)`. None with fewer
    than three grids, or where the differences do not shrink monotonically (no asymptotic range).
    """
    from scipy import optimize

    if len(sizes) < 3:
        return None
    (h1, w1), (h2, w2), (h3, w3) = sorted(zip(sizes, values, strict=True))[:3]
    ratio = (w3 - w2) / (w2 - w1) if w2 != w1 else float("inf")
    if not (math.isfinite(ratio) and ratio > 0):
        return None

    def excess(p: float) -> float:
        return (h3**p - h2**p) / (h2**p - h1**p) - ratio

    try:
        p = optimize.brentq(excess, 1e-3, 10.0)
    except ValueError:
        return None
    return p, w1 - (w2 - w1) * h1**p / (h2**p - h1**p)
