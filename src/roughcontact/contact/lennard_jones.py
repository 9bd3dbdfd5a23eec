r"""The Lennard-Jones (n = 2, m = 8) force law of two half-spaces (paper 000, equations 5-7, 14, 16).

The interaction energy per unit area of two flat half-spaces at distance l that follows from a
pairwise 6-12 Lennard-Jones potential is w(l) = -A / l^2 + B / l^8 (paper 000, eq. 5 with n = 2 and
m = 8). Fixing its zero of force at the equilibrium distance epsilon and the work to separate the
surfaces from epsilon to infinity at the work of adhesion dgamma (eq. 6) gives A = 4 dgamma eps^2 / 3,
B = A eps^6 / 4 and the *attractive* stress (positive = attraction) of eq. 7,

.. math:: f(l) = \frac{8\,\Delta\gamma}{3\,\varepsilon}
          \left[\left(\frac{\varepsilon}{l}\right)^3 - \left(\frac{\varepsilon}{l}\right)^9\right],

negative (repulsive) for l < epsilon, zero at l = epsilon, largest at l = 3^(1/6) epsilon, where it is
16 dgamma / (9 sqrt(3) eps) ~ 1.026 dgamma / eps. The energy per area to pull the surfaces from l to
infinity against it (eq. 14) is

.. math:: e(l) = \int_l^\infty f\,dl' = \frac{8\,\Delta\gamma}{3}
          \left(\frac{\varepsilon^2}{2 l^2} - \frac{\varepsilon^8}{8 l^8}\right),
          \qquad e(\varepsilon) = \Delta\gamma.

All functions work on arrays and in any consistent unit system; SI inside roughcontact.

References
----------
J. A. Greenwood, "Adhesion of elastic spheres", Proc. R. Soc. Lond. A 453 (1997) 1277-1297,
doi:10.1098/rspa.1997.0070 (the same law, written with the work of adhesion dgamma).
V. M. Muller, V. S. Yushchenko, B. V. Derjaguin, J. Colloid Interface Sci. 77 (1980) 91-101,
doi:10.1016/0021-9797(80)90419-1.
J. N. Israelachvili, *Intermolecular and Surface Forces*, 3rd ed., Academic Press, 2011,
doi:10.1016/C2009-0-21560-1.
Seed paper 000, eqs. 5-7, 14, 16.
"""

from __future__ import annotations

import numpy as np

PEAK_DISTANCE_RATIO = 3.0 ** (1.0 / 6.0)
"""l / epsilon at which the attraction of eq. 7 is largest (d f / d l = 0)."""

PEAK_STRESS_FACTOR = 16.0 / (9.0 * np.sqrt(3.0))
"""max f = PEAK_STRESS_FACTOR * dgamma / epsilon (~1.0264)."""

DUGDALE_RANGE_RATIO = 1.0 + 1.0 / PEAK_STRESS_FACTOR
"""l / epsilon at the edge of the equivalent Dugdale zone, 1 + 9 sqrt(3) / 16 (~1.974)."""


def dugdale_range(epsilon: float) -> float:
    r"""Largest bond distance of the Dugdale zone equivalent to equation 7 [m].

    Maugis (1992) replaces a force law by a constant stress sigma0 acting from the equilibrium
    distance over a further separation h0, with the same work of adhesion, sigma0 h0 = dgamma; with
    sigma0 the peak stress of eq. 7, 16 dgamma / (9 sqrt(3) eps), h0 = 9 sqrt(3) eps / 16 ~ 0.974 eps
    (Maugis' h0 = 0.97 z0). Bonds end at l = eps + h0, independent of dgamma. There the attraction of
    eq. 7 is 0.332 of its peak and e(l) = 0.341 dgamma remains of the bond energy.

    Parameters
    ----------
    epsilon : float
        Equilibrium distance [m].

    Returns
    -------
    float
        eps (1 + 9 sqrt(3) / 16) [m].

    References
    ----------
    D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269, doi:10.1016/0021-9797(92)90285-T.
    """
    return DUGDALE_RANGE_RATIO * epsilon


def stress_scale(work_of_adhesion: float, epsilon: float) -> float:
    """Prefactor 8 dgamma / (3 eps) of equation 7 [Pa].

    Parameters
    ----------
    work_of_adhesion : float
        dgamma [J/m^2].
    epsilon : float
        Equilibrium distance [m].

    Returns
    -------
    float
        8 dgamma / (3 eps) [Pa].
    """
    return 8.0 * work_of_adhesion / (3.0 * epsilon)


def attractive_stress(distance, work_of_adhesion: float, epsilon: float) -> np.ndarray:
    r"""Attractive stress f(l) of equation 7 [Pa]; positive attracts, negative repels.

    Parameters
    ----------
    distance : array_like
        Distance l between the surfaces [m], > 0.
    work_of_adhesion : float
        dgamma [J/m^2].
    epsilon : float
        Equilibrium distance [m] (f = 0 there).

    Returns
    -------
    numpy.ndarray
        f(l) [Pa].

    References
    ----------
    Seed paper 000, eq. 7; Greenwood (1997), doi:10.1098/rspa.1997.0070.
    """
    ratio = epsilon / np.asarray(distance, dtype=float)
    cube = ratio * ratio * ratio
    return stress_scale(work_of_adhesion, epsilon) * (cube - cube * cube * cube)


def separation_energy(distance, work_of_adhesion: float, epsilon: float) -> np.ndarray:
    r"""Energy per area to separate the surfaces from l to infinity, equation 14 [J/m^2].

    .. math:: e(l) = \frac{8\Delta\gamma}{3}
              \left(\frac{\varepsilon^2}{2l^2} - \frac{\varepsilon^8}{8l^8}\right)

    Equal to dgamma at l = epsilon (eq. 6); below epsilon it is smaller (the repulsion helps) and
    negative for l < 4^(-1/6) epsilon.

    Parameters
    ----------
    distance : array_like
        l [m], > 0.
    work_of_adhesion : float
        dgamma [J/m^2].
    epsilon : float
        Equilibrium distance [m].

    Returns
    -------
    numpy.ndarray
        e(l) [J/m^2].

    References
    ----------
    Seed paper 000, eqs. 14 and 16.
    """
    ratio = epsilon / np.asarray(distance, dtype=float)
    square = ratio * ratio
    return (8.0 * work_of_adhesion / 3.0) * (0.5 * square - 0.125 * square**4)


def repulsive_distance(pressure, work_of_adhesion: float, epsilon: float) -> np.ndarray:
    r"""Distance l_im <= epsilon at which the repulsion of equation 7 balances a compressive stress [m].

    Solves f(l) = -p on the repulsive branch, i.e. x^9 - x^3 = p / (8 dgamma / 3 eps) with
    x = eps / l >= 1, by the fixed point x <- (p' + x^3)^(1/9) (a contraction with rate
    1 / (3 x^6) <= 1/3), to round-off. This is the l_im of paper 000 (text before eq. 16).

    Parameters
    ----------
    pressure : array_like
        Compressive stress p >= 0 [Pa].
    work_of_adhesion : float
        dgamma [J/m^2], > 0.
    epsilon : float
        Equilibrium distance [m].

    Returns
    -------
    numpy.ndarray
        l_im [m], epsilon at p = 0 and decreasing with p.
    """
    scaled = np.asarray(pressure, dtype=float) / stress_scale(work_of_adhesion, epsilon)
    ratio = np.ones_like(scaled)
    for _ in range(60):  # (1/3)^35 < 1e-16: the loop ends by the tolerance long before
        updated = np.cbrt(np.cbrt(scaled + ratio**3))
        if np.all(np.abs(updated - ratio) <= 4e-16 * updated):
            ratio = updated
            break
        ratio = updated
    return epsilon / ratio
