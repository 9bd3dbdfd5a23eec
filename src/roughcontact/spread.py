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
        Student's 95 % confidence interval of the mean (NaN for n < 2).
    min, max : float
        Smallest and largest value.
    """

    n: int
    mean: float
    std: float
    ci95_low: float
    ci95_high: float
    min: float
    max: float

    @property
    def half_width(self) -> float:
        """Half the width of the confidence interval of the mean."""
        return 0.5 * (self.ci95_high - self.ci95_low)

    def against(self, reference: float) -> str:
        """Say where ``reference`` lies for the mean: ``below``/``above`` it, or within its interval.

        ``"below"`` when the whole 95 % interval of the mean lies below ``reference`` (the mean is
        smaller than the reference at that confidence), ``"above"`` when it lies above, else
        ``"within the scatter"``; ``"one realisation"`` where there is no interval (n < 2).
        """
        if not self.n > 1 or not math.isfinite(self.half_width):
            return "one realisation"
        if self.ci95_high < reference:
            return "below"
        if self.ci95_low > reference:
            return "above"
        return "within the scatter"

    def prediction(self) -> tuple[float, float]:
        r"""Return the 95 % prediction interval of one more realisation (NaN for n < 2).

        :math:`\bar x \pm t_{0.975, N-1}\, s \sqrt{1 + 1/N}`: where a single new draw (or one
        measurement of a spot, if the model holds) falls 95 % of the time. Compare one measured
        value with this, not with the interval of the mean.
        """
        if self.n < 2:
            return math.nan, math.nan
        from scipy import stats

        half = float(stats.t.ppf(0.5 + CONFIDENCE / 2, self.n - 1)) * self.std * math.sqrt(1 + 1 / self.n)
        return self.mean - half, self.mean + half

    def row(self) -> dict[str, float | int]:
        """Return the summary as a table row (its keys are the attribute names)."""
        return asdict(self)


def spread(values: Iterable[float]) -> Spread:
    """Summarise ``values`` (one per realisation) by mean, std, 95 % interval of the mean, min and max.

    Parameters
    ----------
    values : iterable of float
        One value per realisation; NaN and infinite values are left out.

    Returns
    -------
    Spread
        With ``n = 0`` and NaN everywhere when no value is finite.
    """
    from scipy import stats

    array = np.asarray([float(v) for v in values], dtype=float)
    array = array[np.isfinite(array)]
    n = int(array.size)
    if n == 0:
        return Spread(0, *(math.nan,) * 6)
    mean = float(array.mean())
    if n == 1:
        return Spread(1, mean, math.nan, math.nan, math.nan, mean, mean)
    std = float(array.std(ddof=1))
    half = float(stats.t.ppf(0.5 + CONFIDENCE / 2, n - 1)) * std / math.sqrt(n)
    return Spread(n, mean, std, mean - half, mean + half, float(array.min()), float(array.max()))


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
