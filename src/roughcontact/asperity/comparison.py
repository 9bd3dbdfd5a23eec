r"""A statistical model's prediction against a deterministic model's realisations, at the level of the claim.

Paper 002 compares the statistical Kadin-Kogut-Etsion (KKE) curve with ONE island (the measured
one) and says the model "slightly over-predicts" its deformation. Here the deterministic model (the
BEM compression of the island) runs on N realisations of a stand-in island, and a statistical value
:math:`s` (KKE's peak interference, say) is judged against the spread of the N deterministic values
:math:`x_i` (:mod:`roughcontact.spread`):

* for ONE island, with the 95 % prediction interval of one more realisation
  :math:`[x_-, x_+] = \bar x \pm t_{0.975,N-1}\, s_x \sqrt{1 + 1/N}` (the claim's level): the statistical
  model *over-predicts* where the whole interval lies below :math:`s`, *under-predicts* where it lies
  above, and it is *not established* where the interval holds :math:`s`;
* for the mean over islands, the same with the 95 % confidence interval of the mean, shown beside it.

The over-prediction is given as the ratio :math:`s / \bar x` of the statistical value to the
deterministic mean, with each interval carried through the decreasing map :math:`x \mapsto s / x`:
:math:`[s / x_+,\, s / x_-]` (infinite where the interval reaches zero). The ratio's interval therefore
holds 1 exactly when the verdict is "not established" at the same level: the ratio and the verdict
say the same thing. (The mean of the per-realisation ratios :math:`s / x_i` would not: by Jensen's
inequality it exceeds :math:`s / \bar x`, and its interval need not agree with the verdict.)
Quantities are positive (interferences past the reference load, areas): the deterministic spread
is taken within ``POSITIVE`` so that no interval reaches below zero.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from ..spread import Spread, Verdict, spread

POSITIVE = (0.0, math.inf)
"""Bounds of the compared quantities: interferences past the reference load and areas are >= 0."""

MODEL_WORDS = {
    "below": "over-predicts",
    "above": "under-predicts",
    "not established": "not established",
    "one realisation": "one realisation: no interval",
}
"""What the statistical model does, by the verdict on the deterministic spread against its value."""

LEVELS = {"one": "one island", "mean": "the mean"}
"""The claim each interval judges, in words."""


def _over(numerator: float, denominator: float) -> float:
    """``numerator / denominator`` for a positive quantity: infinite at or below 0, NaN when not finite."""
    if not (math.isfinite(numerator) and math.isfinite(denominator)):
        return math.nan
    return numerator / denominator if denominator > 0 else math.inf


@dataclass(frozen=True)
class Comparison:
    """One statistical value against the deterministic model's realisations (SI).

    Attributes
    ----------
    quantity : str
        Name of the compared scalar (``peak_interference``, ``interference_at_return_force``).
    statistical : float
        The statistical model's value.
    deterministic : Spread
        The deterministic model's values over its realisations, within ``POSITIVE``.
    one, mean : Verdict
        The verdict for one island (prediction interval) and for the mean (confidence interval).
    """

    quantity: str
    statistical: float
    deterministic: Spread
    one: Verdict
    mean: Verdict

    def verdict(self, of: str) -> Verdict:
        """Return the verdict at the level ``of`` (``"one"`` or ``"mean"``)."""
        return self.one if of == "one" else self.mean

    def model_words(self, of: str) -> str:
        """Return what the statistical model does at the level ``of`` (``over-predicts``, ...)."""
        return MODEL_WORDS[self.verdict(of).word]

    @property
    def ratio(self) -> float:
        """Statistical value over the deterministic mean [-]."""
        return _over(self.statistical, self.deterministic.mean)

    def ratio_interval(self, of: str) -> tuple[float, float]:
        """Return the ratio's interval at the level ``of``: the verdict's through ``x -> statistical / x``."""
        low, high = self.verdict(of).interval
        return _over(self.statistical, high), _over(self.statistical, low)

    def claim(self, of: str, *, model: str = "KKE", specimen: str = "island") -> str:
        """Say the verdict at the level ``of`` in words (``KKE over-predicts the mean``, ...)."""
        word = self.verdict(of).word
        level = f"one {specimen}" if of == "one" else "the mean"
        if word in ("below", "above"):
            return f"{model} {self.model_words(of)} {level}"
        if word == "not established":
            direction = "over-predicts" if self.statistical > self.deterministic.mean else "under-predicts"
            return f"that {model} {direction} {level} is not established"
        return "one realisation: no interval to judge with"

    def sentence(
        self,
        number: Callable[[float], str],
        *,
        model: str = "KKE",
        deterministic: str = "BEM",
        specimen: str = "island",
        words: str = "",
        name: str = "",
    ) -> str:
        """Say the comparison at both levels with the ratio's intervals and the paper's ``words``.

        ``number`` writes a value with its unit (``lambda v: format_si(v, "m")``); ``model``,
        ``deterministic`` and ``specimen`` name the two models and what one realisation is, ``name``
        the quantity in words (default its name with spaces).
        """
        ratio = "{:.3g}".format
        name = name or self.quantity.replace("_", " ")
        text = (
            f"{model}'s {name} {number(self.statistical)} is {ratio(self.ratio)} times the {deterministic} "
            f"mean {number(self.deterministic.mean)} (n = {self.deterministic.n})."
        )
        for of in ("one", "mean") if self.deterministic.n >= 2 else ():
            verdict = self.verdict(of)
            place = {"below": "above", "above": "below"}.get(verdict.word, "inside")
            interval_name = verdict.interval_name.replace("one realisation", f"one {specimen}")
            low, high = verdict.interval
            r_low, r_high = self.ratio_interval(of)
            text += (
                f" It lies {place} the {interval_name} [{number(low)}, {number(high)}]: "
                f"{self.claim(of, model=model, specimen=specimen)} "
                f"(ratio {model} / {deterministic} {ratio(r_low)} to {ratio(r_high)})."
            )
        if self.deterministic.n < 2:
            text += " One realisation: no interval, no verdict."
        if words:
            text += f' Paper 002\'s words: "{model} {words}".'
        return text


def against_realisations(
    statistical: float, deterministic: Iterable[float], *, quantity: str, bounds=POSITIVE
) -> Comparison:
    """Judge a statistical value against the deterministic values of N realisations (module notes).

    Parameters
    ----------
    statistical : float
        The statistical model's value (KKE's peak interference [m], say).
    deterministic : iterable of float
        The deterministic model's value on each realisation (non-finite ones are left out).
    quantity : str
        Name of the quantity, for the sentence and the table.
    bounds : (float, float)
        The quantity's range (default ``POSITIVE``): intervals are cut there.

    Returns
    -------
    Comparison
    """
    summary: Spread = spread(deterministic, bounds=bounds)
    value = float(statistical)
    return Comparison(
        quantity, value, summary, summary.verdict(value, of="one"), summary.verdict(value, of="mean")
    )
