r"""Mindlin's smooth ball, the reference of paper 001's rough one: K_L (equations 10-12) and verdicts.

:func:`mindlin_reference` gives the smooth ball of the same radius, load and materials in both
readings of equation 12 (the textbook one and the paper's printed one, 4x larger);
:func:`mindlin_ratios`, :func:`rough_vs_smooth` and :func:`verdict_words` judge a rough ball's
K_L against it over realisations. The rough ball itself is
:func:`~roughcontact.contact.presliding.presliding`.

References
----------
Seed paper 001, eqs. 10-12. doi:10.1115/1.4045900
K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, sec. 7.4.
doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..analytic.mindlin import (
    hertz_contact_radius,
    lateral_stiffness,
    sliding_displacement,
    tangential_displacement,
    tangential_force,
)
from ..checks import finite_array, positive
from ..errors import InputError
from ..materials import Material, compliance_sum, contact_modulus, johnson_shear_modulus
from ..spread import Spread, Verdict, spread

POINTS = (0.25, 0.5, 0.75)
"""Fractions of a branch's pre-sliding force span at the loop points A, B, C (paper 001 Fig. 10; assumed)."""


POINT_NAMES = ("A", "B", "C")
"""The loop points of paper 001 Fig. 10 at which K_L is evaluated."""


MINDLIN_READINGS = ("johnson", "printed")
"""The two readings of Mindlin's K_L (paper 001 eqs. 10-12): textbook (Johnson) and as printed (4x)."""


NORMALISATIONS = MINDLIN_READINGS
"""Readings of paper 001 eqs. 10 and 12, see :func:`mindlin_reference`."""


@dataclass(frozen=True)
class MindlinReference:
    """Mindlin's smooth ball (paper 001 equations 10-12) for one ball, load and friction coefficient.

    Attributes
    ----------
    friction_coefficient : float
        mu_f [-].
    normal_force : float
        F0 [N].
    contact_radius : float
        Hertz radius a from eq. 11 [m].
    shear_modulus : float
        The modulus that multiplies the prefactors 3/16 and 8: G* for ``"johnson"``, G_s (= 4 G*)
        for ``"printed"`` [Pa].
    normalisation : str
        ``"johnson"`` or ``"printed"``.
    """

    friction_coefficient: float
    normal_force: float
    contact_radius: float
    shear_modulus: float
    normalisation: str

    @property
    def sliding_distance(self) -> float:
        """delta_0 = 3 mu F0 / (16 a G) [m] (equation 10)."""
        return sliding_displacement(
            self.friction_coefficient, self.normal_force, self.contact_radius, self.shear_modulus
        )

    @property
    def initial_stiffness(self) -> float:
        """K_L at F_x = 0: 8 a G [N/m] (equation 12)."""
        return 8.0 * self.contact_radius * self.shear_modulus

    def force(self, displacement):
        """F_x(delta_x), equation 10 [N] (saturated at mu F0 beyond delta_0)."""
        return tangential_force(
            displacement,
            self.friction_coefficient,
            self.normal_force,
            self.contact_radius,
            self.shear_modulus,
        )

    def displacement(self, force):
        """delta_x(F_x), inverse of equation 10 [m]."""
        return tangential_displacement(
            force, self.friction_coefficient, self.normal_force, self.contact_radius, self.shear_modulus
        )

    def lateral_stiffness(self, force):
        """K_L = 8 a G (1 - F_x / (mu F0))^(1/3), equation 12 [N/m], at tangential force F_x [N]."""
        return lateral_stiffness(
            force, self.friction_coefficient, self.normal_force, self.contact_radius, self.shear_modulus
        )

    def point_stiffness(self, fractions=(0.25, 0.5, 0.75)) -> np.ndarray:
        """K_L [N/m] at the loop points A, B, C of :mod:`roughcontact.experiment.friction_loop`.

        A point at the fraction f of a sliding branch's force span 2 mu F0 lies where the
        Masing branch has changed by 2 Q_M(x/2) = f 2 mu F0, so its stiffness is eq. 12 at
        F_x = f mu F0: K_L = 8 a G (1 - f)^(1/3).
        """
        f = np.asarray(fractions, dtype=float)
        if np.any((f < 0) | (f > 1)) or not np.all(np.isfinite(f)):
            raise InputError("fractions", f"{fractions!r} must lie in [0, 1].", "use e.g. (0.25, 0.5, 0.75).")
        return self.initial_stiffness * np.cbrt(1.0 - f)

    def lateral_stiffness_at_displacement(self, displacement):
        """K_L = 3 mu F0 / (2 delta_0) (1 - delta_x / delta_0)^(1/2), equation 12 [N/m]."""
        delta0 = self.sliding_distance
        x = np.minimum(np.abs(finite_array(displacement, "displacement")) / delta0, 1.0)
        stiffness = 1.5 * self.friction_coefficient * self.normal_force / delta0 * np.sqrt(1.0 - x)
        return float(stiffness) if np.ndim(displacement) == 0 else stiffness


def mindlin_reference(
    *,
    friction_coefficient: float,
    normal_force: float,
    radius: float,
    material: Material,
    counter_body: Material | None = None,
    normalisation: str = "johnson",
) -> MindlinReference:
    r"""Mindlin's smooth-ball reference (paper 001 equations 10-12) for a ball of ``radius`` on a flat.

    Eq. 11 gives a^3 = 3 F0 R / (4 E_s) with 1/E_s = sum (1 - nu^2)/E. Eqs. 10 and 12 give
    delta_0 = 3 mu F0 / (16 a G) and K_L = 8 a G (1 - F_x/(mu F0))^(1/3), where G is

    * ``normalisation="johnson"`` (default): Johnson's G*, 1/G* = sum (2 - nu)/G. This is the
      textbook Mindlin solution (Johnson 1985, eq. 7.42), to which the prefactors 3/16 and 8
      belong.
    * ``normalisation="printed"``: the paper's G_s as printed, 1/G_s = sum (2 - nu)(1 + nu)/(2E)
      = sum (2 - nu)/(4G), i.e. G_s = 4 G*. Combined with the prefactors 3/16 and 8 this makes
      delta_0 4 times smaller and K_L exactly 4 times larger than Johnson's (the force at a given
      fraction of mu F0 is unchanged). Use it only to reproduce the paper's printed numbers
      (Fig. 15, dashed lines). The consistent form with G_s would be delta_0 = 3 mu F0/(4 a G_s)
      and K_L = 2 a G_s, which equals the ``"johnson"`` reading.

    Parameters
    ----------
    friction_coefficient : float
        mu_f [-] (paper Table 1).
    normal_force : float
        F0 [N].
    radius : float
        Ball radius R [m] (paper: 5 mm, a 10 mm ball).
    material, counter_body : Material, Material or None
        The two bodies (``counter_body=None`` is rigid), e.g. HDPE (0.98 GPa, 0.5) and silicon
        (130 GPa, 0.28) from Table 2.
    normalisation : {"johnson", "printed"}
        See above.

    Returns
    -------
    MindlinReference
        a, the modulus used, delta_0 and the force and stiffness functions.

    Raises
    ------
    InputError
        Unknown ``normalisation``, non-positive numbers or bodies that are not Materials.
    """
    if normalisation not in NORMALISATIONS:
        raise InputError(
            "normalisation",
            f"unknown normalisation {normalisation!r}.",
            "choose 'johnson' (textbook Mindlin, default) or 'printed' (paper 001 as printed, "
            "K_L 4x larger).",
        )
    positive(friction_coefficient, "friction_coefficient", example="0.153")
    a = hertz_contact_radius(normal_force, radius, contact_modulus(material, counter_body))
    if normalisation == "johnson":
        g = johnson_shear_modulus(material, counter_body)
    else:
        g = effective_shear_modulus_paper001(material, counter_body)
    return MindlinReference(float(friction_coefficient), float(normal_force), a, g, normalisation)


READING_WORDS = {
    "johnson": "Johnson's Mindlin",
    "printed": "Mindlin as printed (eq. 12, 4x Johnson's)",
}
"""How tables, notes and figures name each reading of Mindlin's K_L (:data:`MINDLIN_READINGS`)."""


def mindlin_ratios(stiffness, mindlin: Mapping[str, Any]) -> dict[str, Spread]:
    """Return the spread of K_L / K_L,Mindlin over realisations, in each reading of equation 12.

    Parameters
    ----------
    stiffness : iterable of float
        K_L at one point (A, B or C) of each realisation [N/m]; NaN where a loop was not analysed
        (left out).
    mindlin : dict
        Reading (``"johnson"``, ``"printed"``) -> Mindlin's K_L at the same point for each
        realisation [N/m].

    Returns
    -------
    dict
        Reading -> :class:`~roughcontact.spread.Spread` of the ratio (bounded below by 0).
    """
    values = [float(k) for k in stiffness]
    ratios = {}
    for reading, references in mindlin.items():
        each = [
            k / float(m) if float(m) > 0 and math.isfinite(float(m)) else math.nan
            for k, m in zip(values, references, strict=True)
        ]
        ratios[reading] = spread(each, bounds=(0.0, math.inf))
    return ratios


def rough_vs_smooth(ratios: Mapping[str, Spread]) -> dict[str, Verdict]:
    """Judge where one rough ball's K_L lies against Mindlin's smooth ball, in each reading of equation 12.

    Paper 001's claim (the rough ball is laterally softer than Mindlin's smooth one) is about one
    ball. The ratios of :func:`mindlin_ratios` over realisations (balls drawn with the same
    statistics) are judged with :meth:`~roughcontact.spread.Spread.verdict` ``(1.0, of="one")``: the
    95 % prediction interval of one more ball, the interval of the mean beside it
    (``Verdict.mean_interval``). ``below`` where one ball's ratio lies below 1 at 95 %, ``above``
    where it lies above, ``not established`` where the interval holds 1, ``one realisation``
    without an interval.
    """
    return {reading: ratio.verdict(1.0, of="one") for reading, ratio in ratios.items()}


def verdict_words(verdicts: Mapping[str, Verdict], reading: str) -> str:
    """Return a reading's verdict word, saying so where equation 12's printed factor 4 decides it.

    The printed reading's K_L is exactly 4x Johnson's (:func:`mindlin_reference`). Where its
    verdict differs from Johnson's for the same ball and point, the roughness does not decide it:
    the constant does, e.g. ``"below (decided by eq. 12's printed factor 4: with Johnson's Mindlin
    not established)"``.
    """
    word = verdicts[reading].word
    textbook = verdicts.get("johnson")
    if reading != "johnson" and textbook is not None and textbook.word != word:
        return f"{word} (decided by eq. 12's printed factor 4: with Johnson's Mindlin {textbook.word})"
    return word


def effective_shear_modulus_paper001(a: Material, b: Material | None = None) -> float:
    r"""Effective shear modulus G_s as defined in paper 001 (below equation 10) [Pa].

    .. math:: \frac{1}{G_s} = \sum_i \frac{(2 - \nu_i)(1 + \nu_i)}{2 E_i}
              = \sum_i \frac{2 - \nu_i}{4 G_i}

    This is 4 times Johnson's G* (:func:`johnson_shear_modulus`): G_s = 4 G*. Paper 001 uses it
    with the prefactors of Johnson's Mindlin solution (delta_0 = 3 mu F0 / (16 a G),
    K_L = 8 a G), which belong to G*; used with G_s as printed, K_L is 4 times the textbook
    Mindlin stiffness. With G_s the consistent prefactors are delta_0 = 3 mu F0 / (4 a G_s)
    and K_L = 2 a G_s.

    Parameters
    ----------
    a : Material
        First body.
    b : Material or None
        Second body; ``None`` is rigid.

    Returns
    -------
    float
        G_s [Pa].

    References
    ----------
    Seed paper 001, text below eq. 10. doi:10.1115/1.4045900
    """
    return 1.0 / compliance_sum(a, b, lambda m: (2.0 - m.poissons_ratio) / (4.0 * m.shear_modulus))
