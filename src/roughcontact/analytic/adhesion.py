r"""Closed-form adhesive contacts: JKR, DMT and Maugis-Dugdale spheres; JKR wavy surface.

Conventions: SI units; E* [Pa] is Johnson's contact modulus, 1/E* = sum (1 - nu_i^2)/E_i;
w [J/m^2] is the work of adhesion; pressures and forces are positive in compression, and the
pull-off functions return the *magnitude* of the most tensile force (or mean pressure).

Sphere (paraboloid of radius R [m]) on a flat
---------------------------------------------

.. math::

    F_{JKR} = \tfrac32 \pi w R, \qquad F_{DMT} = 2 \pi w R, \qquad
    \mu = \left(\frac{R w^2}{E^{*2} z_0^3}\right)^{1/3}, \qquad
    \lambda = 2\sigma_0 \left(\frac{R}{\pi w K^2}\right)^{1/3}, \; K = \tfrac43 E^*

Maugis-Dugdale (cohesive stress sigma0 [Pa] acting out to r = c beyond the contact radius a),
in Maugis' variables A = a (K/(pi w R^2))^(1/3), P = F/(pi w R),
Delta = delta (K^2/(pi^2 w^2 R))^(1/3) and m = c/a (Maugis 1992, eqs. 6.17 and after; Johnson &
Greenwood 1997, eqs. 2-4):

.. math::

    \frac{\lambda A^2}{2}\left[\sqrt{m^2-1} + (m^2-2)\arctan\sqrt{m^2-1}\right]
    + \frac{4\lambda^2 A}{3}\left[\sqrt{m^2-1}\arctan\sqrt{m^2-1} - m + 1\right] = 1

    P = A^3 - \lambda A^2\left[\sqrt{m^2-1} + m^2\arctan\sqrt{m^2-1}\right], \qquad
    \Delta = A^2 - \tfrac43 A \lambda \sqrt{m^2-1}

Limits: lambda -> infinity gives JKR, P = A^3 - sqrt(6 A^3), Delta = A^2 - (2/3) sqrt(6 A);
lambda -> 0 gives DMT, P = A^3 - 2, Delta = A^2.

Wavy surface (Johnson 1995)
---------------------------

Plane strain, one body with the profile h(x) = Delta (1 - cos(2 pi x / lambda)) against a flat,
i.e. :mod:`roughcontact.analytic.westergaard`'s surface with the same ``amplitude`` Delta [m]
(half the peak-to-valley height) and ``wavelength`` lambda [m]. With p* = pi E* Delta / lambda
[Pa] (the mean pressure for full contact without adhesion), psi = pi a / lambda and the contact
half-width a [m] per period,

.. math::

    \alpha = \sqrt{\frac{2 \lambda w}{\pi^2 \Delta^2 E^*}}, \qquad
    \frac{\bar p}{p^*} = \sin^2\psi - \alpha \sqrt{\tan\psi}

from the stress intensity factor of the periodic flat-punch term,
K_I = p_1 sqrt(lambda cot psi) with p_1 = p* sin^2 psi - p_bar, and G = K_I^2 / (2 E*) = w.

References
----------
Johnson, K. L., Kendall, K., Roberts, A. D. (1971). Proc. R. Soc. Lond. A 324, 301-313.
doi:10.1098/rspa.1971.0141
Derjaguin, B. V., Muller, V. M., Toporov, Yu. P. (1975). J. Colloid Interface Sci. 53, 314-326.
doi:10.1016/0021-9797(75)90018-1
Tabor, D. (1977). J. Colloid Interface Sci. 58, 2-13. doi:10.1016/0021-9797(77)90366-6
Maugis, D. (1992). J. Colloid Interface Sci. 150, 243-269. doi:10.1016/0021-9797(92)90285-T
Johnson, K. L., Greenwood, J. A. (1997). J. Colloid Interface Sci. 192, 326-333.
doi:10.1006/jcis.1997.4984
Johnson, K. L. (1995). Int. J. Solids Struct. 32, 423-430. doi:10.1016/0020-7683(94)00111-9
Carbone, G., Mangialardi, L. (2004). J. Mech. Phys. Solids 52, 1267-1287.
doi:10.1016/j.jmps.2003.12.001
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ..checks import positive
from ..errors import InputError

#: Johnson parameter alpha above which a wavy surface jumps into full contact at zero load:
#: the maximum of sin^2 psi - alpha sqrt(tan psi) is zero at psi = pi/3, alpha = 3^(3/4)/4.
WAVY_JKR_SPONTANEOUS_ALPHA = 3.0**0.75 / 4.0  # = 0.5699 [-]

#: Johnson parameter above which no stable partial contact exists at any mean pressure:
#: max of 4 sin^(3/2) psi cos^(5/2) psi, at tan^2 psi = 3/5.
WAVY_JKR_NO_PARTIAL_CONTACT_ALPHA = 4.0 * (3.0 / 8.0) ** 0.75 * (5.0 / 8.0) ** 1.25  # = 1.0651


# --- sphere on flat -------------------------------------------------------------------------


def jkr_pull_off(work_of_adhesion: float, radius: float) -> float:
    r"""JKR pull-off force [N] of a sphere on a flat, :math:`\tfrac32 \pi w R` (load control).

    Parameters
    ----------
    work_of_adhesion : float
        w [J/m^2].
    radius : float
        Sphere (paraboloid) radius R [m].

    Returns
    -------
    float
        Magnitude of the most tensile force [N].

    References
    ----------
    Johnson, Kendall, Roberts (1971), eq. 11. doi:10.1098/rspa.1971.0141
    """
    return 1.5 * math.pi * positive(work_of_adhesion, "work_of_adhesion") * positive(radius, "radius")


def dmt_pull_off(work_of_adhesion: float, radius: float) -> float:
    r"""DMT pull-off force [N] of a sphere on a flat, :math:`2 \pi w R`.

    Parameters
    ----------
    work_of_adhesion : float
        w [J/m^2].
    radius : float
        Sphere (paraboloid) radius R [m].

    Returns
    -------
    float
        Magnitude of the most tensile force [N].

    References
    ----------
    Derjaguin, Muller, Toporov (1975). doi:10.1016/0021-9797(75)90018-1
    """
    return 2.0 * math.pi * positive(work_of_adhesion, "work_of_adhesion") * positive(radius, "radius")


def tabor_parameter(
    work_of_adhesion: float, radius: float, contact_modulus: float, equilibrium_distance: float
) -> float:
    r"""Tabor parameter :math:`\mu = (R w^2 / (E^{*2} z_0^3))^{1/3}` [-].

    Parameters
    ----------
    work_of_adhesion : float
        w [J/m^2].
    radius : float
        Sphere radius R [m].
    contact_modulus : float
        E* [Pa], 1/E* = sum (1 - nu^2)/E.
    equilibrium_distance : float
        z0 [m], the separation at which the interaction stress vanishes.

    References
    ----------
    Tabor (1977), doi:10.1016/0021-9797(77)90366-6; in this (E*) form as in Johnson & Greenwood
    (1997), doi:10.1006/jcis.1997.4984.
    """
    w = positive(work_of_adhesion, "work_of_adhesion")
    r = positive(radius, "radius")
    e = positive(contact_modulus, "contact_modulus")
    z0 = positive(equilibrium_distance, "equilibrium_distance")
    return (r * w**2 / (e**2 * z0**3)) ** (1.0 / 3.0)


def maugis_parameter(
    work_of_adhesion: float, radius: float, contact_modulus: float, peak_stress: float
) -> float:
    r"""Maugis parameter :math:`\lambda = 2\sigma_0 (R/(\pi w K^2))^{1/3}`, K = 4E*/3 [-].

    Equivalently :math:`\lambda = \sigma_0 (9R / (2\pi w E^{*2}))^{1/3}`. Note the K: written with
    E* in place of K the value would be (16/9)^(1/3) = 1.21 times larger.

    When sigma0 is the peak of the Lennard-Jones 9-3 law, sigma0 = 16 w / (9 sqrt(3) z0), this is
    :math:`\lambda = \frac{16}{9\sqrt3}\left(\frac{9}{2\pi}\right)^{1/3}\mu = 1.1571\,\mu`
    (the "lambda = 1.16 mu" of Johnson & Greenwood 1997).

    Parameters
    ----------
    work_of_adhesion : float
        w [J/m^2] = sigma0 * h0, h0 [m] being the Dugdale range.
    radius : float
        Sphere radius R [m].
    contact_modulus : float
        E* [Pa].
    peak_stress : float
        Dugdale cohesive stress sigma0 [Pa].

    References
    ----------
    Maugis (1992), eq. 6.13 with K = 4E*/3, doi:10.1016/0021-9797(92)90285-T;
    Johnson & Greenwood (1997), doi:10.1006/jcis.1997.4984.
    """
    w = positive(work_of_adhesion, "work_of_adhesion")
    r = positive(radius, "radius")
    k = 4.0 / 3.0 * positive(contact_modulus, "contact_modulus")
    s0 = positive(peak_stress, "peak_stress")
    return 2.0 * s0 * (r / (math.pi * w * k**2)) ** (1.0 / 3.0)


def _md_residual(s: float, a: float, lam: float) -> float:
    """Maugis' eq. 6.17 minus 1, in s = sqrt(m^2 - 1) >= 0 (increasing in s)."""
    at = math.atan(s)
    # s + (s^2 - 1) atan s, and s atan s - (m - 1) with m - 1 = s^2/(1 + m), free of cancellation
    s_minus_at = s**3 / 3.0 - s**5 / 5.0 + s**7 / 7.0 if s < 1e-2 else s - at
    first = s_minus_at + s * s * at
    second = s * at - s * s / (1.0 + math.sqrt(1.0 + s * s))
    return 0.5 * lam * a * a * first + 4.0 / 3.0 * lam * lam * a * second - 1.0


def _md_zero(lam: float) -> tuple[float, float, float]:
    """(P, Delta, C) in the limit A -> 0 at a finite nondimensional cohesive radius C = m A.

    Eq. 6.17 becomes (pi lam / 4) C^2 + (4 lam^2 / 3)(pi/2 - 1) C = 1; P = -(pi/2) lam C^2 and
    Delta = -(4/3) lam C.
    """
    qa, qb = math.pi * lam / 4.0, 4.0 / 3.0 * lam * lam * (math.pi / 2.0 - 1.0)
    c = 2.0 / (qb + math.sqrt(qb * qb + 4.0 * qa))
    return -0.5 * math.pi * lam * c * c, -4.0 / 3.0 * lam * c, c


def _md_point(a: float, lam: float) -> tuple[float, float, float]:
    """(P, Delta, m) at one nondimensional contact radius a >= 0."""
    if a == 0.0:
        p, delta, _ = _md_zero(lam)
        return p, delta, math.inf
    hi = 1.0
    while _md_residual(hi, a, lam) < 0.0:
        hi *= 2.0
    s = brentq(_md_residual, 0.0, hi, args=(a, lam), xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=500)
    m = math.sqrt(1.0 + s * s)
    p = a**3 - lam * a * a * (s + m * m * math.atan(s))
    delta = a * a - 4.0 / 3.0 * a * lam * s
    return p, delta, m


def maugis_dugdale_curve(
    maugis_parameter: float, contact_radius: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r"""Maugis-Dugdale sphere: load, approach and m = c/a at nondimensional contact radii A.

    Solves Maugis' eq. 6.17 (see the module docstring) for m > 1 at each A by bracketing and
    Brent's method in s = sqrt(m^2 - 1) (the residual increases monotonically in s); A = 0 is
    the closed-form limit a -> 0 at finite c (m = inf).

    Parameters
    ----------
    maugis_parameter : float
        lambda [-] (:func:`maugis_parameter`).
    contact_radius : array_like
        A = a (4 E* / (3 pi w R^2))^(1/3) [-], >= 0.

    Returns
    -------
    P, Delta, m : numpy.ndarray
        P = F / (pi w R) [-] (positive compressive), Delta = delta (16 E*^2/(9 pi^2 w^2 R))^(1/3)
        [-] (approach, positive into the flat) and m = c/a [-], each shaped like A.

    References
    ----------
    Maugis (1992), eqs. 6.17-6.19, doi:10.1016/0021-9797(92)90285-T; Johnson & Greenwood (1997),
    eqs. 2-4, doi:10.1006/jcis.1997.4984.
    """
    lam = positive(maugis_parameter, "maugis_parameter")
    a = np.asarray(contact_radius, dtype=float)
    if not np.all(np.isfinite(a)) or np.any(a < 0.0):
        raise InputError("contact_radius", "must be finite and >= 0.", "Pass nondimensional radii A >= 0.")
    out = np.array([_md_point(float(ai), lam) for ai in a.ravel()]).reshape((*a.shape, 3))
    return out[..., 0], out[..., 1], out[..., 2]


@dataclass(frozen=True)
class MaugisDugdaleContact:
    """Dimensional Maugis-Dugdale state: force [N], approach [m], cohesive radius c [m] (arrays)."""

    contact_radius: np.ndarray
    force: np.ndarray
    approach: np.ndarray
    cohesive_radius: np.ndarray
    maugis_parameter: float


def maugis_dugdale(
    contact_radius: np.ndarray,
    *,
    radius: float,
    contact_modulus: float,
    work_of_adhesion: float,
    peak_stress: float,
) -> MaugisDugdaleContact:
    """Maugis-Dugdale sphere in SI units at contact radii a [m] (see :func:`maugis_dugdale_curve`).

    Parameters
    ----------
    contact_radius : array_like
        a [m], >= 0.
    radius : float
        Sphere radius R [m].
    contact_modulus : float
        E* [Pa].
    work_of_adhesion : float
        w [J/m^2].
    peak_stress : float
        sigma0 [Pa].
    """
    lam = maugis_parameter(work_of_adhesion, radius, contact_modulus, peak_stress)
    k = 4.0 / 3.0 * contact_modulus
    length = (math.pi * work_of_adhesion * radius**2 / k) ** (1.0 / 3.0)  # a = A * length [m]
    a = np.asarray(contact_radius, dtype=float)
    p, delta, m = maugis_dugdale_curve(lam, a / length)
    with np.errstate(invalid="ignore"):
        cohesive = np.where(a == 0.0, _md_zero(lam)[2] * length, m * a)
    return MaugisDugdaleContact(
        contact_radius=a,
        force=p * math.pi * work_of_adhesion * radius,
        approach=delta * (math.pi**2 * work_of_adhesion**2 * radius / k**2) ** (1.0 / 3.0),
        cohesive_radius=cohesive,
        maugis_parameter=lam,
    )


def maugis_dugdale_pull_off(maugis_parameter: float) -> float:
    r"""Maugis-Dugdale pull-off under load control, :math:`-\min_A P(A)` = F_c / (pi w R) [-].

    The minimum of the load over contact radii A >= 0 (the most tensile force on the stable
    branch). 1.5 for lambda -> infinity (JKR), 2 for lambda -> 0 (DMT). The minimum is at a
    finite radius for every lambda > 0, tending to A = 0 only as lambda -> 0 (measured: A_c =
    0.021 at lambda = 0.01, 0.20 at 0.1, 0.90 at 1; the JKR value is 1.5^(1/3) = 1.145).
    Found on a grid of 121 radii in [0, 3] and refined by a bounded scalar minimisation.

    Parameters
    ----------
    maugis_parameter : float
        lambda [-].

    Returns
    -------
    float
        Positive nondimensional pull-off force P_c = F_c / (pi w R) [-].
    """
    lam = positive(maugis_parameter, "maugis_parameter")
    grid = np.linspace(0.0, 3.0, 121)
    loads = np.array([_md_point(float(a), lam)[0] for a in grid])
    i = int(np.argmin(loads))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    res = minimize_scalar(
        lambda a: _md_point(float(a), lam)[0], bounds=(lo, hi), method="bounded", options={"xatol": 1e-10}
    )
    return -min(float(res.fun), float(loads[i]))


# --- wavy surface (Johnson 1995) ------------------------------------------------------------


def wavy_adhesion_parameter(
    wavelength: float, amplitude: float, contact_modulus: float, work_of_adhesion: float
) -> float:
    r"""Johnson's parameter :math:`\alpha = \sqrt{2 \lambda w / (\pi^2 \Delta^2 E^*)}` [-].

    alpha^2 = (2/pi) w / (Delta p*): surface energy over the elastic energy of flattening.

    Parameters
    ----------
    wavelength : float
        lambda [m].
    amplitude : float
        Delta [m], half the peak-to-valley height (as ``amplitude`` in westergaard.py).
    contact_modulus : float
        E* [Pa].
    work_of_adhesion : float
        w [J/m^2].

    References
    ----------
    Johnson (1995), doi:10.1016/0020-7683(94)00111-9.
    """
    lam = positive(wavelength, "wavelength")
    d = positive(amplitude, "amplitude")
    e = positive(contact_modulus, "contact_modulus")
    w = positive(work_of_adhesion, "work_of_adhesion")
    return math.sqrt(2.0 * lam * w / (math.pi**2 * d**2 * e))


def _half_width(contact_half_width: np.ndarray, wavelength: float) -> np.ndarray:
    a = np.asarray(contact_half_width, dtype=float)
    if not np.all(np.isfinite(a)) or np.any(a < 0.0) or np.any(a >= wavelength / 2.0):
        raise InputError(
            "contact_half_width",
            "must lie in [0, wavelength/2).",
            "Full contact (a = wavelength/2) has no JKR partial-contact solution; use 0 <= a < wavelength/2.",
        )
    return a


def wavy_jkr_mean_pressure(
    contact_half_width: np.ndarray,
    wavelength: float,
    amplitude: float,
    contact_modulus: float,
    work_of_adhesion: float,
) -> np.ndarray:
    r"""Mean pressure [Pa] (compressive positive) of the JKR wavy contact at half-width a [m].

    .. math::

        \bar p = p^* \left(\sin^2\frac{\pi a}{\lambda} - \alpha\sqrt{\tan\frac{\pi a}{\lambda}}\right),
        \qquad p^* = \frac{\pi E^* \Delta}{\lambda}

    The states with d p_bar / d a > 0 are stable under load control.

    Parameters
    ----------
    contact_half_width : array_like
        a [m], 0 <= a < lambda/2, per period.
    wavelength : float
        lambda [m].
    amplitude : float
        Delta [m], half the peak-to-valley height.
    contact_modulus : float
        E* [Pa].
    work_of_adhesion : float
        w [J/m^2]; alpha = 0 (w -> 0) gives Westergaard's p* sin^2(pi a / lambda).

    References
    ----------
    Johnson (1995), doi:10.1016/0020-7683(94)00111-9; Carbone & Mangialardi (2004),
    doi:10.1016/j.jmps.2003.12.001.
    """
    alpha = wavy_adhesion_parameter(wavelength, amplitude, contact_modulus, work_of_adhesion)
    psi = math.pi * _half_width(contact_half_width, wavelength) / wavelength
    full = math.pi * contact_modulus * amplitude / wavelength
    return full * (np.sin(psi) ** 2 - alpha * np.sqrt(np.tan(psi)))


def wavy_jkr_pressure(
    x: np.ndarray,
    contact_half_width: float,
    wavelength: float,
    amplitude: float,
    contact_modulus: float,
    work_of_adhesion: float,
) -> np.ndarray:
    r"""Contact pressure [Pa] at x [m] (x = 0 at a crest) of the JKR wavy contact of half-width a.

    Westergaard's pressure for half-width a minus a periodic flat-punch tension of mean
    p_1 = p* sin^2 psi - p_bar = sqrt(2 E* w tan psi / lambda):

    .. math::

        p(x) = 2 p^* \cos\theta \sqrt{\sin^2\psi - \sin^2\theta}
               - \frac{p_1 \cos\theta}{\sqrt{\sin^2\psi - \sin^2\theta}}, \quad
        \theta = \frac{\pi x}{\lambda}, \; ``|x|`` < a

    zero outside the contact and -inf at its edges, where p ~ -K_I / sqrt(2 pi (a - ``|x|``)) with
    K_I = p_1 sqrt(lambda cot psi) = sqrt(2 E* w).
    """
    a = float(_half_width(contact_half_width, wavelength))
    full = math.pi * contact_modulus * amplitude / wavelength
    s2 = math.sin(math.pi * a / wavelength) ** 2
    mean = float(wavy_jkr_mean_pressure(a, wavelength, amplitude, contact_modulus, work_of_adhesion))
    p1 = full * s2 - mean
    x = np.asarray(x, dtype=float)
    theta = math.pi * ((x + wavelength / 2.0) % wavelength - wavelength / 2.0) / wavelength
    inside = np.abs(theta) < math.pi * a / wavelength
    root = np.sqrt(np.where(inside, s2 - np.sin(theta) ** 2, 1.0))
    with np.errstate(divide="ignore"):
        p = 2.0 * full * np.cos(theta) * root - p1 * np.cos(theta) / root
    return np.where(inside, p, 0.0)


@dataclass(frozen=True)
class WavyJKR:
    """Load-controlled JKR wavy contact: pull-off, jump into full contact and the Johnson alpha.

    Attributes
    ----------
    alpha : float
        Johnson's parameter [-].
    full_contact_pressure : float
        p* = pi E* Delta / lambda [Pa].
    spontaneous : bool
        alpha >= 3^(3/4)/4 = 0.5699: the surfaces jump into full contact at first touch (zero
        load); JKR theory then has no crack to open and no finite pull-off.
    pull_off_pressure : float
        Magnitude [Pa] of the most tensile mean pressure on the stable partial-contact branch
        (its minimum, at the half-width below); math.inf when ``spontaneous``.
    pull_off_half_width : float
        a [m] at pull-off (nan when ``spontaneous``).
    jump_in_pressure : float
        Mean pressure [Pa] (compressive positive) at which the contact jumps into full contact on
        loading: the maximum of p_bar on the stable branch; 0 when ``spontaneous``.
    jump_in_half_width : float
        a [m] at the jump (the branch maximum; lambda/2 * 2/3 at the spontaneous threshold; nan
        when ``spontaneous``).
    """

    alpha: float
    full_contact_pressure: float
    spontaneous: bool
    pull_off_pressure: float
    pull_off_half_width: float
    jump_in_pressure: float
    jump_in_half_width: float


def wavy_jkr(wavelength: float, amplitude: float, contact_modulus: float, work_of_adhesion: float) -> WavyJKR:
    r"""Pull-off and jump-in of the JKR wavy contact (Johnson 1995), under load control.

    The extrema of p_bar(psi) solve d p_bar / d psi = 0, i.e.
    :math:`4\sin^{3/2}\psi\cos^{5/2}\psi = \alpha`: a minimum psi_1 < arctan sqrt(3/5) (pull-off)
    and a maximum psi_2 > arctan sqrt(3/5) (jump into full contact); both exist for
    alpha < 1.0651. The maximum is <= 0 for alpha >= 3^(3/4)/4 = 0.5699 (at psi = pi/3): then
    no stable partial contact exists at p_bar >= 0 and the surfaces snap into full contact.
    For small alpha, p_bar_c = -3 (alpha/4)^(4/3) p* at psi = (alpha/4)^(2/3).

    Parameters
    ----------
    wavelength, amplitude, contact_modulus, work_of_adhesion : float
        lambda [m], Delta [m] (half peak-to-valley), E* [Pa], w [J/m^2].
    """
    alpha = wavy_adhesion_parameter(wavelength, amplitude, contact_modulus, work_of_adhesion)
    full = math.pi * contact_modulus * amplitude / wavelength
    if alpha >= WAVY_JKR_SPONTANEOUS_ALPHA:
        return WavyJKR(alpha, full, True, math.inf, math.nan, 0.0, math.nan)

    def slope(psi: float) -> float:
        return 4.0 * math.sin(psi) ** 1.5 * math.cos(psi) ** 2.5 - alpha

    def mean(psi: float) -> float:
        return full * (math.sin(psi) ** 2 - alpha * math.sqrt(math.tan(psi)))

    peak = math.atan(math.sqrt(0.6))
    tol = dict(xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=500)
    psi1 = brentq(slope, 0.0, peak, **tol)
    psi2 = brentq(slope, peak, math.pi / 2.0, **tol)
    scale = wavelength / math.pi
    return WavyJKR(alpha, full, False, -mean(psi1), psi1 * scale, mean(psi2), psi2 * scale)


def wavy_jkr_pull_off(
    wavelength: float, amplitude: float, contact_modulus: float, work_of_adhesion: float
) -> float:
    """Pull-off mean pressure [Pa] of the JKR wavy contact, as a positive magnitude.

    The most tensile mean pressure on the stable partial-contact branch (see :func:`wavy_jkr`);
    math.inf for alpha >= 3^(3/4)/4, when the surfaces have jumped into full contact.
    """
    return wavy_jkr(wavelength, amplitude, contact_modulus, work_of_adhesion).pull_off_pressure
