"""Paper 000's Winkler springs: their composite modulus (equation 1) and factor k (equation 4).

Each spring of the layer carries P = E / (k h) dz (eq. 3); E is the composite modulus of the two
surfaces (:func:`composite_modulus`, the Hertz E* with the paper's plain-number signature) and k
the factor of eq. 4 (:func:`winkler_factor`), in the printed reading or the uniaxial-strain one
(``readings.winkler_factor``, :doc:`/winkler_lj`).
"""

from __future__ import annotations

import math

from ..checks import poissons_ratio_checked
from ..errors import InputError
from ..materials import Material, contact_modulus


def composite_modulus(
    youngs_modulus_1: float, poissons_ratio_1: float, youngs_modulus_2: float, poissons_ratio_2: float
) -> float:
    r"""Composite Young's modulus of paper 000, equation 1 [Pa]: the Hertz E* with plain numbers.

    .. math:: E = \left(\frac{1 - \nu_1^2}{E_1} + \frac{1 - \nu_2^2}{E_2}\right)^{-1}

    Identical to :func:`contact_modulus` (which it calls); kept under paper 000's name and
    signature for the Winkler-layer friction model.

    Parameters
    ----------
    youngs_modulus_1, youngs_modulus_2 : float
        Young's moduli of the two surfaces [Pa].
    poissons_ratio_1, poissons_ratio_2 : float
        Poisson's ratios of the two surfaces [-].

    Returns
    -------
    float
        Composite modulus [Pa].

    Raises
    ------
    InputError
        Invalid moduli or Poisson's ratios (the field names which body).

    References
    ----------
    Seed paper 000, eq. 1. K. L. Johnson, *Contact Mechanics*, 1985, section 4.2.
    doi:10.1017/CBO9781139171731
    """
    return contact_modulus(
        _numbered_material(youngs_modulus_1, poissons_ratio_1, 1),
        _numbered_material(youngs_modulus_2, poissons_ratio_2, 2),
    )


def _numbered_material(youngs_modulus: float, poissons_ratio: float, number: int) -> Material:
    """Build a Material from plain numbers, renaming error fields to ``youngs_modulus_<number>``."""
    try:
        return Material(youngs_modulus, poissons_ratio)
    except InputError as error:
        raise InputError(f"{error.field}_{number}", error.problem, error.fix) from None


_WINKLER_READINGS = ("paper000_eq4_printed", "uniaxial_strain")


def winkler_factor(
    poissons_ratio_1: float, poissons_ratio_2: float, *, reading: str = "paper000_eq4_printed"
) -> float:
    r"""Factor k of the Winkler springs of paper 000 (equation 3: P = E / (k h) dz) [-].

    ``"paper000_eq4_printed"`` (default, the paper's formula, with s = sqrt(nu1 nu2)):

    .. math:: k = \frac{(1 + s)(1 - 2 s)}{1 - \nu_1 \nu_2}

    For one material (nu1 = nu2 = nu) it reduces to (1 - 2 nu) / (1 - nu), because
    1 - nu^2 = (1 - nu)(1 + nu); it is *not* the uniaxial-strain (laterally constrained column)
    factor E / M = (1 + nu)(1 - 2 nu) / (1 - nu). The paper's denominator is ambiguous (seed
    README); ``"uniaxial_strain"`` replaces it by (1 - s), which does reduce to
    (1 + nu)(1 - 2 nu) / (1 - nu):

    .. math:: k = \frac{(1 + s)(1 - 2 s)}{1 - s}

    Both give k = 0 (infinitely stiff springs) for nu1 = nu2 = 0.5 and k = 1 for nu = 0.

    Parameters
    ----------
    poissons_ratio_1, poissons_ratio_2 : float
        Poisson's ratios of the two surfaces [-], each in [0, 0.5]: the geometric mean
        sqrt(nu1 nu2) is undefined for a negative product and meaningless for auxetic materials.
    reading : {"paper000_eq4_printed", "uniaxial_strain"}
        Which denominator, see above.

    Returns
    -------
    float
        k [-].

    Raises
    ------
    InputError
        A Poisson's ratio outside [0, 0.5], or an unknown ``reading``.

    References
    ----------
    Seed paper 000, eqs. 3-4.
    """
    for number, value in ((1, poissons_ratio_1), (2, poissons_ratio_2)):
        field = f"poissons_ratio_{number}"
        poissons_ratio_checked(value, field)
        if value < 0:
            raise InputError(
                field,
                f"{value!r} < 0: sqrt(nu1 * nu2) of paper 000 eq. 4 is undefined.",
                "give 0 <= nu <= 0.5; the Winkler factor has no reading for auxetic materials.",
            )
    if reading not in _WINKLER_READINGS:
        raise InputError(
            "reading", f"unknown reading {reading!r}.", f"choose one of {list(_WINKLER_READINGS)}."
        )
    product = poissons_ratio_1 * poissons_ratio_2
    root = math.sqrt(product)
    denominator = 1.0 - product if reading == "paper000_eq4_printed" else 1.0 - root
    return (1.0 + root) * (1.0 - 2.0 * root) / denominator
