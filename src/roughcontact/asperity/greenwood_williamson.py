r"""Greenwood-Williamson summits: the population (Gaussian or measured heights) and the GW integrals.

A rough surface against a flat is a population of spherical summits of one radius R, density eta
and heights z (about the summits' mean plane) drawn from a distribution phi. At separation d
between the flat and the summits' mean plane, the summits with z > d touch with interference
omega = z - d. For elastic (Hertz) summits on a nominal area A_n (Greenwood and Williamson 1966):

.. math::

    N = \eta A_n F_0(h), \quad
    A = \pi \eta A_n R \sigma_s F_1(h), \quad
    P = \tfrac43 \eta A_n E' R^{1/2} \sigma_s^{3/2} F_{3/2}(h), \qquad
    F_n(h) = \int_h^\infty (s - h)^n \phi^*(s)\, ds

with h = d / sigma_s and phi* the standardised summit-height density. For the Gaussian
F_0(h) = Q(h) = erfc(h/sqrt2)/2 and F_1(h) = phi(h) - h Q(h) in closed form; other orders are
integrated numerically. The summits' mean plane lies y_s = 4 sqrt(m0) / sqrt(pi alpha) above the
surface mean plane (McCool 1986), so the separation from the surface mean plane is d + y_s.

The measured option replaces phi by the heights of the summits found on the topography
(8-neighbour maxima); the integrals become averages over those summits.

References
----------
.. [GW] J. A. Greenwood and J. B. P. Williamson, "Contact of nominally flat surfaces", Proc. R. Soc.
   A 295 (1966) 300-319. doi:10.1098/rspa.1966.0242
.. [McC] J. I. McCool, "Comparison of models for the contact of rough surfaces", Wear 107 (1986)
   37-60. doi:10.1016/0043-1648(86)90045-1
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import integrate, special

from ..checks import positive
from ..errors import InputError
from ..topography import Topography
from ..topography.statistics import McCoolParameters, mccool_parameters_of, summits

SUMMIT_DISTRIBUTIONS = ("gaussian", "measured")


@dataclass(frozen=True)
class SummitDistribution:
    """A summit population: density, radius and a discrete height distribution (SI).

    Attributes
    ----------
    summit_density : float
        eta [1/m^2].
    summit_radius : float
        R [m].
    summit_height_std : float
        sigma_s [m] (of the distribution below).
    summit_mean_offset : float
        Height of the summits' mean plane above the surface mean plane [m].
    heights : ndarray
        Summit heights about the summits' mean plane [m]: quadrature nodes (Gaussian) or the
        measured summits.
    weights : ndarray
        Their probabilities (sum 1).
    kind : {"gaussian", "measured"}
        Where the heights come from.
    """

    summit_density: float
    summit_radius: float
    summit_height_std: float
    summit_mean_offset: float
    heights: np.ndarray
    weights: np.ndarray
    kind: str

    def expected_overlap(self, order: float, separation) -> np.ndarray:
        r"""E[(z - d)_+^n] over the summits [m^n]: sigma_s^n F_n(d/sigma_s) for the Gaussian.

        Parameters
        ----------
        order : float
            n >= 0.
        separation : float or array_like
            d [m] from the summits' mean plane.

        Returns
        -------
        ndarray
            The expectation for each separation [m^n].
        """
        d = np.atleast_1d(np.asarray(separation, dtype=float))
        if self.kind == "gaussian":
            return self.summit_height_std**order * gw_integral(order, d / self.summit_height_std)
        overlap = np.maximum(self.heights[None, :] - d[:, None], 0.0)
        touching = overlap > 0
        powered = np.where(touching, overlap, 1.0) ** order * touching
        return powered @ self.weights


def gaussian_summits(
    mccool: McCoolParameters, *, nodes: int = 4001, extent: float = 8.0
) -> SummitDistribution:
    """Summits with Gaussian heights (standard deviation sigma_s), on a fine uniform quadrature grid.

    The grid (midpoint rule over +-``extent`` sigma_s) carries the history of each height class in
    the statistical load-unload model; the GW integrals of the elastic model use closed forms and
    adaptive quadrature instead.

    Parameters
    ----------
    mccool : McCoolParameters
        From :func:`roughcontact.topography.statistics.mccool_parameters`.
    nodes : int
        Number of height classes (>= 101).
    extent : float
        Half-width of the grid in units of sigma_s (>= 5; the tail beyond 8 holds 6e-16).

    Returns
    -------
    SummitDistribution
    """
    if nodes < 101:
        raise InputError("nodes", f"need at least 101 height classes, got {nodes}.", "use nodes >= 101.")
    if not extent >= 5.0:
        raise InputError("extent", f"{extent!r} sigma_s truncates the Gaussian.", "use extent >= 5.")
    step = 2.0 * extent / nodes
    standard = -extent + step * (np.arange(nodes) + 0.5)
    weights = np.exp(-0.5 * standard**2)
    return SummitDistribution(
        summit_density=mccool.summit_density,
        summit_radius=mccool.summit_radius,
        summit_height_std=mccool.summit_height_std,
        summit_mean_offset=mccool.summit_mean_offset,
        heights=standard * mccool.summit_height_std,
        weights=weights / weights.sum(),
        kind="gaussian",
    )


def measured_summits(topography: Topography, *, mccool: McCoolParameters | None = None) -> SummitDistribution:
    """Summits with the measured height distribution of a topography.

    The heights are those of the 8-neighbour maxima (:func:`roughcontact.topography.statistics.summits`),
    taken about their own mean; the density and radius stay McCool's (from the spectral moments),
    since pixel maxima over-count summits on noisy scans.

    Parameters
    ----------
    topography : Topography
        A 2D surface [m].
    mccool : McCoolParameters, optional
        Density and radius to use (default: from the topography's moments).

    Returns
    -------
    SummitDistribution

    Raises
    ------
    InputError
        Fewer than 10 summits on the surface.
    """
    mccool = mccool_parameters_of(topography) if mccool is None else mccool
    found = summits(topography).heights
    if found.size < 10:
        raise InputError(
            "topography",
            f"only {found.size} summits found; a height distribution needs more.",
            "use a larger scan or the Gaussian distribution.",
        )
    mean = float(found.mean())
    return SummitDistribution(
        summit_density=mccool.summit_density,
        summit_radius=mccool.summit_radius,
        summit_height_std=float(found.std()),
        summit_mean_offset=mean,
        heights=found - mean,
        weights=np.full(found.size, 1.0 / found.size),
        kind="measured",
    )


def summits_of(mccool: McCoolParameters, distribution: str, topography: Topography | None = None):
    """Return the summit population of the spectral moments: Gaussian heights, or a scan's measured ones.

    Parameters
    ----------
    mccool : McCoolParameters
        Density, radius and height deviation of the summits (paper 002 eqs. 4-5).
    distribution : {"gaussian", "measured"}
        :func:`gaussian_summits`, or :func:`measured_summits` of ``topography``.
    topography : Topography, optional
        Needed for ``"measured"``.

    Returns
    -------
    SummitDistribution

    Raises
    ------
    InputError
        ``"measured"`` without a topography, or an unknown distribution.
    """
    if distribution == "gaussian":
        return gaussian_summits(mccool)
    if distribution != "measured":
        raise InputError(
            "distribution", f"unknown distribution {distribution!r}.", "use 'gaussian' or 'measured'."
        )
    if topography is None:
        raise InputError(
            "distribution", "'measured' needs a topography.", "give a topography, or 'gaussian'."
        )
    return measured_summits(topography, mccool=mccool)


def gw_integral(order: float, h) -> np.ndarray:
    r"""Greenwood-Williamson integral of the standard Gaussian, F_n(h) [-].

    .. math:: F_n(h) = \int_h^\infty (s - h)^n \frac{e^{-s^2/2}}{\sqrt{2\pi}}\, ds

    Closed forms for n = 0 (Q(h) = erfc(h / sqrt 2) / 2) and n = 1 (phi(h) - h Q(h)); adaptive
    quadrature otherwise. F_0(0) = 1/2, F_1(0) = 1/sqrt(2 pi),
    F_n(0) = 2^{n/2} Gamma((n+1)/2) / (2 sqrt pi).

    Parameters
    ----------
    order : float
        n >= 0.
    h : float or array_like
        Standardised separation d / sigma_s [-].

    Returns
    -------
    ndarray
        F_n(h), the shape of ``h`` (at least 1D).

    References
    ----------
    Greenwood and Williamson (1966), eqs. 5-7. doi:10.1098/rspa.1966.0242
    """
    if not (math.isfinite(order) and order >= 0):
        raise InputError("order", f"must be >= 0, got {order!r}.", "use n = 0, 1, 3/2, ...")
    h = np.atleast_1d(np.asarray(h, dtype=float))
    tail = 0.5 * special.erfc(h / math.sqrt(2.0))
    if order == 0:
        return tail
    density = np.exp(-0.5 * h**2) / math.sqrt(2.0 * math.pi)
    if order == 1:
        return density - h * tail

    def one(value: float) -> float:
        result, _ = integrate.quad(
            lambda s: (s - value) ** order * math.exp(-0.5 * s * s), value, np.inf, epsabs=0, epsrel=1e-12
        )
        return result / math.sqrt(2.0 * math.pi)

    return np.array([one(value) for value in h])


@dataclass(frozen=True)
class GreenwoodWilliamsonContact:
    """Elastic GW contact at given separations (SI).

    Attributes
    ----------
    separation : ndarray
        d from the summits' mean plane [m].
    number_of_contacts : ndarray
        N [-].
    contact_area : ndarray
        A [m^2].
    force : ndarray
        P [N].
    """

    separation: np.ndarray
    number_of_contacts: np.ndarray
    contact_area: np.ndarray
    force: np.ndarray


def greenwood_williamson(
    separation, distribution: SummitDistribution, *, contact_modulus: float, nominal_area: float = 1.0
) -> GreenwoodWilliamsonContact:
    r"""Count the contacts, real contact area and load of elastic GW summits against a flat.

    .. math:: N = \eta A_n F_0, \quad A = \pi\eta A_n R \sigma_s F_1, \quad
              P = \tfrac43 \eta A_n E' R^{1/2}\sigma_s^{3/2} F_{3/2}

    Parameters
    ----------
    separation : float or array_like
        d from the summits' mean plane [m].
    distribution : SummitDistribution
        The summits.
    contact_modulus : float
        E' [Pa].
    nominal_area : float
        A_n [m^2] (default 1: values per unit nominal area).

    Returns
    -------
    GreenwoodWilliamsonContact

    References
    ----------
    Greenwood and Williamson (1966). doi:10.1098/rspa.1966.0242
    """
    positive(contact_modulus, "contact_modulus", example=7.97e9, unit="Pa")
    positive(nominal_area, "nominal_area", example=625e-12, unit="m^2")
    d = np.atleast_1d(np.asarray(separation, dtype=float))
    count = distribution.summit_density * nominal_area
    radius = distribution.summit_radius
    return GreenwoodWilliamsonContact(
        separation=d,
        number_of_contacts=count * distribution.expected_overlap(0, d),
        contact_area=math.pi * count * radius * distribution.expected_overlap(1, d),
        force=4.0 / 3.0 * count * contact_modulus * math.sqrt(radius) * distribution.expected_overlap(1.5, d),
    )
