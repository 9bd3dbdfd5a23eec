r"""Single-asperity elastic-plastic laws: a sphere of radius R against a rigid flat.

Every law is written in the dimensionless interference :math:`\omega^* = \omega/\omega_c` and gives
the load in units of the critical load (or in newtons where the law is dimensional):

=====================================  ===========================================================
:func:`critical_interference`          Chang-Etsion-Bogy (1987) onset of yield, paper 002 eq. 6
:func:`contact_pressure_factor`        K = 0.454 + 0.41 nu (paper 002 eq. 8)
:func:`critical_load`                  Hertz load at omega_c, P_c = (2/3) pi K H R omega_c
:func:`plasticity_index`               psi = sqrt(sigma_s / omega_c) (paper 002 eq. 9)
:func:`kogut_etsion_load`              Kogut-Etsion (2002) P/P_c, 0 <= omega* <= 110
:func:`kogut_etsion_area`              Kogut-Etsion (2002) A/A_c, A_c = pi R omega_c
:func:`jackson_green_load`             Jackson-Green (2005) P/P_c with its own omega_c and P_c
:func:`paper002_eq10_load`             paper 002 eq. 10, the sound reading or as printed
:func:`unloading_exponent`             n = 1.5 (omega*_max)^-0.0331 (EKK 2005, paper 002 eq. 11)
:func:`residual_interference_ratio`    omega_res / omega_max (EKK 2005)
:func:`unloading_load`                 paper 002 eq. 11 with the EKK residual and exponent
:func:`unloading_area_exponent`        m = (omega*_max)^-0.12 (EKK/KKE unloading area, recalled)
:func:`unloading_area`                 A = A_max ((omega - omega_res)/(omega_max - omega_res))^m
=====================================  ===========================================================

Interferences outside a fit's validity range are refused (:class:`~roughcontact.errors.InputError`
naming the range) rather than extrapolated. Which coefficients were checked against independent
sources is listed in :doc:`/asperity`.

References
----------
.. [CEB] W. R. Chang, I. Etsion and D. B. Bogy, "An elastic-plastic model for the contact of rough
   surfaces", J. Tribol. 109 (1987) 257-263. doi:10.1115/1.3261348
.. [KE] L. Kogut and I. Etsion, "Elastic-plastic contact analysis of a sphere and a rigid flat",
   J. Appl. Mech. 69 (2002) 657-662. doi:10.1115/1.1490373
.. [JG] R. L. Jackson and I. Green, "A finite element study of elasto-plastic hemispherical contact
   against a rigid flat", J. Tribol. 127 (2005) 343-354. doi:10.1115/1.1866166
.. [EKK] I. Etsion, Y. Kligerman and Y. Kadin, "Unloading of an elastic-plastic loaded spherical
   contact", Int. J. Solids Struct. 42 (2005) 3716-3729. doi:10.1016/j.ijsolstr.2004.12.006
.. [KKE] Y. Kadin, Y. Kligerman and I. Etsion, "Unloading an elastic-plastic contact of rough
   surfaces", J. Mech. Phys. Solids 54 (2006) 2652-2674. doi:10.1016/j.jmps.2006.07.005
.. [KKE-M] Y. Kadin, Y. Kligerman and I. Etsion, "Multiple loading-unloading of an elastic-plastic
   spherical contact", Int. J. Solids Struct. 43 (2006) 7119-7127 (cited from memory; no DOI given).
.. [P002] "Contact stress analysis of lightly compressed thin films: modeling and experimentation"
   (seed paper 002; DOI not given in the seed text), eqs. 6-11.
"""

from __future__ import annotations

import math

import numpy as np

from .._deprecation import renamed
from ..checks import poissons_ratio_checked, positive
from ..errors import InputError

KOGUT_ETSION_MAX = 110.0
"""Upper end of the Kogut-Etsion fits in omega* (fully plastic beyond)."""

_PAPER002_READINGS = ("sound", "printed")


def _w_star(w_star, field: str = "w_star", upper: float = math.inf, lower: float = 0.0) -> np.ndarray:
    values = np.asarray(w_star, dtype=float)
    if not np.all(np.isfinite(values)):
        raise InputError(field, "interferences must be finite.", "give omega / omega_c as finite numbers.")
    if values.size and (values.min() < lower or values.max() > upper):
        raise InputError(
            field,
            f"values from {values.min():.4g} to {values.max():.4g} are outside the fit's validity "
            f"range {lower:g} <= omega* <= {upper:g}.",
            "stay inside the range (the law is not extrapolated); beyond omega* = 110 the asperity is "
            "fully plastic (P = 2 pi R omega H, Kogut and Etsion 2002).",
        )
    return values


def _out(values: np.ndarray, like):
    return float(values) if np.ndim(like) == 0 else values


def contact_pressure_factor(poissons_ratio: float) -> float:
    r"""Maximum-contact-pressure factor K of Chang, Etsion and Bogy (paper 002 equation 8) [-].

    .. math:: K = 0.454 + 0.41\,\nu

    The mean contact pressure at the onset of yield is K H (H the hardness).

    Parameters
    ----------
    poissons_ratio : float
        Poisson's ratio of the softer body [-], in (-1, 0.5].

    Returns
    -------
    float
        K [-] (0.544 for nu = 0.22).

    Raises
    ------
    InputError
        nu outside (-1, 0.5].

    References
    ----------
    Chang, Etsion and Bogy (1987), doi:10.1115/1.3261348; Kogut and Etsion (2002),
    doi:10.1115/1.1490373. Seed paper 002, eq. 8.
    """
    poissons_ratio_checked(poissons_ratio)
    return 0.454 + 0.41 * poissons_ratio


def critical_interference(
    *, hardness: float, poissons_ratio: float, contact_modulus: float, radius: float
) -> float:
    r"""Critical interference at the onset of plastic yield (Chang-Etsion-Bogy; paper 002 equation 6) [m].

    .. math:: \omega_c = \left(\frac{\pi K H}{2 E'}\right)^2 R, \qquad K = 0.454 + 0.41\,\nu

    Parameters
    ----------
    hardness : float
        Hardness H of the softer body [Pa].
    poissons_ratio : float
        Its Poisson's ratio nu [-] (enters K).
    contact_modulus : float
        Composite modulus E' [Pa], 1/E' = sum (1 - nu_i^2)/E_i (see :doc:`/asperity` for
        paper 002's misprinted eq. 7).
    radius : float
        Asperity (summit) radius R [m].

    Returns
    -------
    float
        omega_c [m] (0.0125 um for paper 002's SU-8 island).

    Raises
    ------
    InputError
        A non-positive hardness, modulus or radius, or nu outside (-1, 0.5].

    References
    ----------
    Chang, Etsion and Bogy (1987), doi:10.1115/1.3261348. Seed paper 002, eqs. 6 and 8.
    """
    positive(hardness, "hardness", example="0.462e9", unit="Pa")
    positive(contact_modulus, "contact_modulus", example="7.97e9", unit="Pa")
    positive(radius, "radius", example="5.08e-6", unit="m")
    factor = contact_pressure_factor(poissons_ratio)
    return (math.pi * factor * hardness / (2.0 * contact_modulus)) ** 2 * radius


def critical_load(*, hardness: float, poissons_ratio: float, contact_modulus: float, radius: float) -> float:
    r"""Critical load P_c: the Hertz load at the critical interference [N].

    .. math:: P_c = \tfrac43 E' R^{1/2} \omega_c^{3/2} = \tfrac23 \pi K H R\, \omega_c

    Paper 002 uses W_c in eq. 10 without defining it; this is the definition of Kogut and Etsion
    (2002) and Etsion et al. (2005). The critical contact area is A_c = pi R omega_c.

    Parameters
    ----------
    hardness, poissons_ratio, contact_modulus, radius
        As in :func:`critical_interference`.

    Returns
    -------
    float
        P_c [N].

    References
    ----------
    Kogut and Etsion (2002), doi:10.1115/1.1490373.
    """
    interference = critical_interference(
        hardness=hardness, poissons_ratio=poissons_ratio, contact_modulus=contact_modulus, radius=radius
    )
    return 2.0 / 3.0 * math.pi * contact_pressure_factor(poissons_ratio) * hardness * radius * interference


def plasticity_index(summit_height_std: float, critical_interference: float) -> float:
    r"""Plasticity index of Chang, Etsion and Bogy in the form of paper 002 equation 9 [-].

    .. math:: \psi = \sqrt{\sigma_s / \omega_c}

    psi < 0.6 is nearly all-elastic contact, psi > 1 mostly plastic (Greenwood and Williamson).

    Parameters
    ----------
    summit_height_std : float
        Standard deviation of summit heights sigma_s [m].
    critical_interference : float
        omega_c [m].

    Returns
    -------
    float
        psi [-] (1.86 for paper 002).

    References
    ----------
    Greenwood and Williamson (1966), doi:10.1098/rspa.1966.0242; Chang, Etsion and Bogy (1987),
    doi:10.1115/1.3261348. Seed paper 002, eq. 9.
    """
    positive(summit_height_std, "summit_height_std", example="4.31e-8", unit="m")
    positive(critical_interference, "critical_interference", example="1.25e-8", unit="m")
    return math.sqrt(summit_height_std / critical_interference)


def kogut_etsion_load(w_star):
    r"""Kogut-Etsion (2002) load of an elastic-plastic sphere on a rigid flat, P/P_c [-].

    .. math::

        \frac{P}{P_c} = \begin{cases}
            \omega^{*3/2} & 0 \le \omega^* \le 1 \ (\text{Hertz})\\
            1.03\,\omega^{*1.425} & 1 < \omega^* \le 6\\
            1.40\,\omega^{*1.263} & 6 < \omega^* \le 110
        \end{cases}

    The fits jump by 3 % at omega* = 1 (1 -> 1.03) and by 1.7 % at omega* = 6, as published.

    Parameters
    ----------
    w_star : float or array_like
        omega / omega_c [-], 0 <= omega* <= 110.

    Returns
    -------
    float or ndarray
        P / P_c [-].

    Raises
    ------
    InputError
        omega* outside [0, 110] (fully plastic beyond: P = 2 pi R omega H).

    References
    ----------
    Kogut and Etsion (2002), J. Appl. Mech. 69, 657-662, eqs. 11-12. doi:10.1115/1.1490373
    """
    w = _w_star(w_star, upper=KOGUT_ETSION_MAX)
    load = np.where(w <= 1.0, w**1.5, np.where(w <= 6.0, 1.03 * w**1.425, 1.40 * w**1.263))
    return _out(load, w_star)


def kogut_etsion_area(w_star):
    r"""Kogut-Etsion (2002) contact area of an elastic-plastic sphere, A/A_c with A_c = pi R omega_c [-].

    .. math::

        \frac{A}{A_c} = \begin{cases}
            \omega^* & 0 \le \omega^* \le 1 \ (\text{Hertz})\\
            0.93\,\omega^{*1.136} & 1 < \omega^* \le 6\\
            0.94\,\omega^{*1.146} & 6 < \omega^* \le 110
        \end{cases}

    Parameters
    ----------
    w_star : float or array_like
        omega / omega_c [-], 0 <= omega* <= 110.

    Returns
    -------
    float or ndarray
        A / A_c [-].

    Raises
    ------
    InputError
        omega* outside [0, 110].

    References
    ----------
    Kogut and Etsion (2002), eqs. 13-14. doi:10.1115/1.1490373 (coefficients cross-checked against an
    independent implementation, :doc:`/asperity`).
    """
    w = _w_star(w_star, upper=KOGUT_ETSION_MAX)
    area = np.where(w <= 1.0, w, np.where(w <= 6.0, 0.93 * w**1.136, 0.94 * w**1.146))
    return _out(area, w_star)


def jackson_green_critical_interference(
    *, yield_strength: float, poissons_ratio: float, contact_modulus: float, radius: float
) -> float:
    r"""Jackson-Green (2005) critical interference, from the yield strength [m].

    .. math:: \omega_c = \left(\frac{\pi C S_y}{2 E'}\right)^2 R, \qquad C = 1.295\, e^{0.736\nu}

    Parameters
    ----------
    yield_strength : float
        Yield strength S_y [Pa].
    poissons_ratio : float
        nu [-].
    contact_modulus : float
        E' [Pa].
    radius : float
        R [m].

    Returns
    -------
    float
        omega_c [m].

    References
    ----------
    Jackson and Green (2005), eqs. 3 and 5. doi:10.1115/1.1866166
    """
    positive(yield_strength, "yield_strength", example="0.165e9", unit="Pa")
    positive(contact_modulus, "contact_modulus", example="7.97e9", unit="Pa")
    positive(radius, "radius", example="5.08e-6", unit="m")
    poissons_ratio_checked(poissons_ratio)
    factor = 1.295 * math.exp(0.736 * poissons_ratio)
    return (math.pi * factor * yield_strength / (2.0 * contact_modulus)) ** 2 * radius


def jackson_green_load(
    w_star, *, yield_strength: float, poissons_ratio: float, contact_modulus: float, radius: float
):
    r"""Jackson-Green (2005) load of an elastic-plastic hemisphere on a rigid flat, P/P_c [-].

    omega* = omega / omega_c with omega_c of :func:`jackson_green_critical_interference` and
    P_c = (4/3) (R/E')^2 (C pi S_y / 2)^3 (the Hertz load at that omega_c). Hertz for
    omega* <= 1.9; above it

    .. math::

        \frac{P}{P_c} = e^{-0.25\,\omega^{*5/12}}\,\omega^{*3/2}
            + \frac{4 H_G}{C S_y}\left(1 - e^{-\omega^{*5/9}/25}\right)\omega^*,

        \frac{H_G}{S_y} = 2.84\left(1 - e^{-0.82 (a/R)^{-0.7}}\right), \quad
        \frac aR = \sqrt{\frac{\omega}{R}}\left(\frac{\omega^*}{1.9}\right)^{B/2}, \quad
        B = 0.14\, e^{23 S_y/E'}.

    Parameters
    ----------
    w_star : float or array_like
        omega / omega_c (Jackson-Green omega_c) [-], >= 0.
    yield_strength, poissons_ratio, contact_modulus, radius
        As in :func:`jackson_green_critical_interference`.

    Returns
    -------
    float or ndarray
        P / P_c [-].

    References
    ----------
    Jackson and Green (2005), eqs. 6-7, 17-18 and 21-23. doi:10.1115/1.1866166
    """
    w = _w_star(w_star)
    omega_c = jackson_green_critical_interference(
        yield_strength=yield_strength,
        poissons_ratio=poissons_ratio,
        contact_modulus=contact_modulus,
        radius=radius,
    )
    factor = 1.295 * math.exp(0.736 * poissons_ratio)
    exponent_b = 0.14 * math.exp(23.0 * yield_strength / contact_modulus)
    plastic = w > 1.9
    wp = np.where(plastic, w, 1.9)  # keep the unused branch finite
    radius_ratio = np.sqrt(wp * omega_c / radius) * (wp / 1.9) ** (exponent_b / 2.0)
    hardness_ratio = 2.84 * (1.0 - np.exp(-0.82 * radius_ratio**-0.7))
    elastic_plastic = (
        np.exp(-0.25 * wp ** (5.0 / 12.0)) * wp**1.5
        + 4.0 * hardness_ratio / factor * (1.0 - np.exp(-(wp ** (5.0 / 9.0)) / 25.0)) * wp
    )
    return _out(np.where(plastic, elastic_plastic, w**1.5), w_star)


def paper002_eq10_load(w_star, *, critical_load: float, reading: str = "sound"):
    r"""Return the load of one asperity by the loading law of paper 002, equation 10 [N].

    ``reading="sound"`` (default) reads the trailing "+ 1" as part of the normalised load, so the law
    is continuous with Hertz at omega_c:

    .. math:: W = W_c\left[1.32\,(\omega^* - 1)^{1.27} + 1\right] \quad (\omega^* \ge 1),
              \qquad W = W_c\,\omega^{*3/2} \quad (\omega^* < 1)

    ``reading="printed"`` is the equation as printed, W = 1.32 W_c (omega* - 1)^1.27 + 1, with the
    bare "1" taken as 1 N: dimensionally inconsistent (it adds 1 N, a million times the paper's
    loads) and kept only to trace the printed text.

    Parameters
    ----------
    w_star : float or array_like
        omega / omega_c [-], 0 <= omega* <= 110 (the Kogut-Etsion range the fit replaces; the paper
        gives none).
    critical_load : float
        W_c [N], not defined in the paper; :func:`critical_load` gives the usual one.
    reading : {"sound", "printed"}
        See above.

    Returns
    -------
    float or ndarray
        W [N].

    Raises
    ------
    InputError
        An unknown reading, a non-positive critical load or omega* outside [0, 110].

    References
    ----------
    Seed paper 002, eq. 10 (attributed there to Kadin, Kligerman and Etsion 2006,
    doi:10.1016/j.jmps.2006.07.005; not verified against that paper).
    """
    if reading not in _PAPER002_READINGS:
        raise InputError("reading", f"unknown reading {reading!r}.", f"use one of {_PAPER002_READINGS}.")
    positive(critical_load, "critical_load", example="1e-6", unit="N")
    w = _w_star(w_star, upper=KOGUT_ETSION_MAX)
    excess = np.maximum(w - 1.0, 0.0) ** 1.27
    if reading == "sound":
        load = critical_load * np.where(w < 1.0, w**1.5, 1.32 * excess + 1.0)
    else:
        load = np.where(w < 1.0, critical_load * w**1.5, 1.32 * critical_load * excess + 1.0)
    return _out(load, w_star)


def unloading_exponent(max_w_star):
    r"""Exponent of the unloading law (paper 002 equation 11; Etsion, Kligerman and Kadin 2005) [-].

    .. math:: n = 1.5\,(\omega^*_{max})^{-0.0331}

    Parameters
    ----------
    max_w_star : float or array_like
        omega_max / omega_c [-], 1 <= omega*_max <= 110 (n = 1.5, Hertz, below 1).

    Returns
    -------
    float or ndarray
        n [-].

    References
    ----------
    Etsion, Kligerman and Kadin (2005), doi:10.1016/j.ijsolstr.2004.12.006. Seed paper 002, eq. 11.
    """
    w = _w_star(max_w_star, "max_w_star", upper=KOGUT_ETSION_MAX)
    return _out(1.5 * np.maximum(w, 1.0) ** -0.0331, max_w_star)


def residual_interference_ratio(max_w_star):
    r"""Residual interference after unloading, omega_res / omega_max (Etsion, Kligerman and Kadin 2005).

    .. math:: \frac{\omega_{res}}{\omega_{max}}
              = 1.02\left[1 - \left(\frac{\omega^*_{max} + 5.9}{6.9}\right)^{-0.54}\right]
              \quad (1 \le \omega^*_{max} \le 110), \qquad 0 \text{ below } 1.

    Zero at omega*_max = 1 (elastic unloading) and rising monotonically (0.80 at 110).

    Parameters
    ----------
    max_w_star : float or array_like
        omega_max / omega_c [-], 0 <= omega*_max <= 110.

    Returns
    -------
    float or ndarray
        omega_res / omega_max [-].

    References
    ----------
    Etsion, Kligerman and Kadin (2005), eq. 16 (not verified against the paper's text: recalled
    from the literature, see :doc:`/asperity`). doi:10.1016/j.ijsolstr.2004.12.006
    """
    w = _w_star(max_w_star, "max_w_star", upper=KOGUT_ETSION_MAX)
    ratio = 1.02 * (1.0 - ((np.maximum(w, 1.0) + 5.9) / 6.9) ** -0.54)
    return _out(ratio, max_w_star)


@renamed(max_load="max_force")
def unloading_load(interference, *, max_interference: float, max_force: float, critical_interference: float):
    r"""Load of an asperity unloaded from omega_max (paper 002 equation 11) [N].

    .. math:: W = W_{max}\left(\frac{\omega - \omega_{res}}{\omega_{max} - \omega_{res}}\right)^{n},
              \quad \omega_{res} \le \omega \le \omega_{max}

    with omega_res from :func:`residual_interference_ratio` and n from :func:`unloading_exponent`;
    zero below omega_res. For omega_max <= omega_c it is the Hertz curve (omega_res = 0, n = 1.5).

    Parameters
    ----------
    interference : float or array_like
        omega [m], 0 <= omega <= omega_max.
    max_interference : float
        omega_max [m].
    max_force : float
        W_max [N], the loading law's load at omega_max.
    critical_interference : float
        omega_c [m].

    Returns
    -------
    float or ndarray
        W [N].

    Raises
    ------
    InputError
        omega above omega_max (that is reloading beyond the maximum: use the loading law), or
        omega_max / omega_c above 110.

    References
    ----------
    Etsion, Kligerman and Kadin (2005), doi:10.1016/j.ijsolstr.2004.12.006. Seed paper 002, eq. 11.
    """
    positive(max_force, "max_force", example="1e-6", unit="N", allow_zero=True)
    stretch, max_w_star = _unloading_stretch(interference, max_interference, critical_interference)
    return _out(max_force * stretch ** unloading_exponent(max_w_star), interference)


def _unloading_stretch(interference, max_interference: float, critical_interference: float):
    """Return (omega - omega_res)/(omega_max - omega_res) clipped to [0, 1], and omega*_max.

    One rule for the load and the area on unloading: both vanish at omega_res and below it.
    omega_max - omega_res >= 0.2 omega_max over the fits' range, so the ratio is always finite.
    """
    positive(max_interference, "max_interference", example="1e-7", unit="m")
    positive(critical_interference, "critical_interference", example="1.25e-8", unit="m")
    omega = np.asarray(interference, dtype=float)
    if not np.all(np.isfinite(omega)):
        raise InputError(
            "interference", "interferences must be finite.", "give omega in m as finite numbers."
        )
    if np.any(omega > max_interference * (1 + 1e-12)):
        raise InputError(
            "interference",
            f"{float(np.max(omega)):.4g} m exceeds max_interference {max_interference:.4g} m.",
            "unloading covers 0 <= omega <= omega_max; beyond it the asperity reloads on its loading law.",
        )
    max_w_star = max_interference / critical_interference
    residual = residual_interference_ratio(max_w_star) * max_interference
    stretch = np.clip((omega - residual) / (max_interference - residual), 0.0, 1.0)
    return stretch, max_w_star


def unloading_area_exponent(max_w_star):
    r"""Exponent of the contact area on unloading (Etsion, Kligerman and Kadin; KKE 2006) [-].

    .. math:: m_A = (\omega^*_{max})^{-0.12} \quad (1 \le \omega^*_{max} \le 110),
              \qquad m_A = 1 \text{ below } 1 \ (\text{Hertz: } A = \pi R \omega).

    1 at omega*_max = 1 (the Hertz area, linear in omega, retraced) falling to 0.569 at 110: the
    plastically flattened summit keeps most of its area early in the unloading and loses it close
    to omega_res.

    The coefficient -0.12 is recalled from the Etsion-Kligerman-Kadin unloading model as used in the
    statistical model of Kadin, Kligerman and Etsion (2006), **not verified against the papers' text**
    (none was available; EKK 2005's abstract lists fits for the unloading load, the residual
    interference and the residual curvature only, so the area fit may come from Kadin, Kligerman and
    Etsion, Int. J. Solids Struct. 43 (2006) 7119-7127). Independent check: an elastic unloading
    has dP/d omega = 2 E' a (Sneddon), so with P ~ x^n (:func:`unloading_exponent`) the area goes as
    x^(2(n - 1)); 2 (n - 1) = 2 (1.5 omega*_max^-0.0331 - 1) agrees with omega*_max^-0.12 within 2.8 %
    over 1 <= omega*_max <= 110 (and is exactly 1 at 1). See :doc:`/asperity`.

    Parameters
    ----------
    max_w_star : float or array_like
        omega_max / omega_c [-], 0 <= omega*_max <= 110.

    Returns
    -------
    float or ndarray
        m_A [-], in (0.56, 1].

    Raises
    ------
    InputError
        omega*_max outside [0, 110] (beyond it the summit is fully plastic; no unloading fit).

    References
    ----------
    Etsion, Kligerman and Kadin (2005), doi:10.1016/j.ijsolstr.2004.12.006; Kadin, Kligerman and
    Etsion (2006), doi:10.1016/j.jmps.2006.07.005 (both cited from memory, coefficient not verified).
    """
    w = _w_star(max_w_star, "max_w_star", upper=KOGUT_ETSION_MAX)
    return _out(np.maximum(w, 1.0) ** -0.12, max_w_star)


def unloading_area(interference, *, max_interference: float, max_area: float, critical_interference: float):
    r"""Real contact area of an asperity unloaded from omega_max (EKK unloading; KKE 2006) [m^2].

    .. math:: A = A_{max}\left(\frac{\omega - \omega_{res}}{\omega_{max} - \omega_{res}}\right)^{m_A},
              \quad \omega_{res} \le \omega \le \omega_{max}, \qquad A = 0 \text{ below } \omega_{res},

    with omega_res from :func:`residual_interference_ratio` and m_A from
    :func:`unloading_area_exponent` (recalled, not verified against the papers' text; see there).
    A_max is the loading law's area at omega_max, so the area is continuous at the peak; it falls
    monotonically to zero at omega_res, where :func:`unloading_load` vanishes too. For
    omega_max <= omega_c (omega_res = 0, m_A = 1) it is the Hertz area A_max omega / omega_max =
    pi R omega: unloading retraces loading.

    Parameters
    ----------
    interference : float or array_like
        omega [m], 0 <= omega <= omega_max (below omega_res the area is 0).
    max_interference : float
        omega_max [m].
    max_area : float
        A_max [m^2], the loading law's area at omega_max (e.g. pi R omega_c
        :func:`kogut_etsion_area` (omega*_max)).
    critical_interference : float
        omega_c [m].

    Returns
    -------
    float or ndarray
        A [m^2], 0 <= A <= A_max.

    Raises
    ------
    InputError
        omega not finite or above omega_max (reloading: use the loading law), a non-positive
        omega_max or omega_c, a negative A_max, or omega_max / omega_c above 110.

    References
    ----------
    Etsion, Kligerman and Kadin (2005), doi:10.1016/j.ijsolstr.2004.12.006; Kadin, Kligerman and
    Etsion (2006), doi:10.1016/j.jmps.2006.07.005.
    """
    positive(max_area, "max_area", example="1e-13", unit="m^2", allow_zero=True)
    stretch, max_w_star = _unloading_stretch(interference, max_interference, critical_interference)
    return _out(max_area * stretch ** unloading_area_exponent(max_w_star), interference)
