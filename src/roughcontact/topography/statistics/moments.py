"""Spectral moments m0, m2, m4 (paper 002 equations 1-3) and McCool's asperity parameters (equations 4-5)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...checks import positive
from ...errors import InputError
from ..surface import Topography, topography_argument
from .amplitude import centred
from .slopes import finite_differences

MCCOOL_MIN_BANDWIDTH = 0.8968  # sigma_s = 0 at this bandwidth (McCool 1986; paper 002 eq. 5)


@dataclass(frozen=True)
class SpectralMoments:
    """Spectral moments of a surface (paper 002 equations 1-3), SI.

    Attributes
    ----------
    m0 : float
        Mean square height [m^2].
    m2 : float
        Mean square slope per direction [dimensionless].
    m4 : float
        Mean square curvature per direction [1/m^2].
    """

    m0: float
    m2: float
    m4: float


def spectral_moments(topography: Topography, *, derivative: str = "forward") -> SpectralMoments:
    r"""Zeroth, second and fourth spectral moments, exactly as paper 002 equations 1-3.

    .. math::

        m_0 = \langle z^2 \rangle, \quad
        m_2 = \tfrac12\left(\langle z_x^2\rangle + \langle z_y^2\rangle\right), \quad
        m_4 = \tfrac12\left(\langle z_{xx}^2\rangle + \langle z_{yy}^2\rangle\right)

    with z about its mean and the averages over the grid (over the points where the stencil fits
    for a non-periodic surface). For a profile only the x terms are kept (no factor 1/2). For an
    isotropic surface these are the moments of a single profile (Nayak 1971).

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).
    derivative : {"central", "forward"}
        First-derivative scheme for m2 (module notes); m4 always uses the centred second
        difference.

    Returns
    -------
    SpectralMoments
        m0 [m^2], m2 [-], m4 [1/m^2].

    References
    ----------
    Seed paper 002, eqs. 1-3. Nayak (1971) doi:10.1115/1.3451150. McCool (1986)
    doi:10.1016/0043-1648(86)90045-1
    """
    topography = topography_argument(topography, "topography")
    m0 = float(np.mean(centred(topography) ** 2))
    averages = []
    for order in (1, 2):
        derivatives, valid = finite_differences(topography, order, derivative)
        averages.append(float(np.mean([np.mean(d[valid] ** 2) for d in derivatives])))
    return SpectralMoments(m0=m0, m2=averages[0], m4=averages[1])


@dataclass(frozen=True)
class McCoolParameters:
    r"""Asperity (summit) parameters of a Gaussian isotropic surface from its spectral moments, SI.

    Attributes
    ----------
    bandwidth : float
        Nayak's bandwidth parameter :math:`\alpha = m_0 m_4 / m_2^2` [-].
    summit_density : float
        Summit density :math:`\eta = m_4 / (6\pi\sqrt3\, m_2)` [1/m^2].
    summit_radius : float
        Mean summit radius of curvature :math:`R = 0.375\sqrt{\pi/m_4}` [m] (paper 002 eq. 4).
    summit_height_std : float
        Standard deviation of summit heights
        :math:`\sigma_s = \sqrt{1 - 0.8968/\alpha}\,\sqrt{m_0}` [m] (paper 002 eq. 5).
    summit_mean_offset : float
        Height of the summits' mean plane above the surface mean plane,
        :math:`y_s = 4\sqrt{m_0}/\sqrt{\pi\alpha}` [m].
    """

    bandwidth: float
    summit_density: float
    summit_radius: float
    summit_height_std: float
    summit_mean_offset: float


def mccool_parameters(*, m0: float, m2: float, m4: float) -> McCoolParameters:
    r"""McCool's asperity parameters from the spectral moments (paper 002 equations 4-5).

    .. math::

        \alpha = \frac{m_0 m_4}{m_2^2}, \quad
        \eta = \frac{m_4}{6\pi\sqrt3\, m_2}, \quad
        R = 0.375\sqrt{\frac{\pi}{m_4}}, \quad
        \sigma_s = \sqrt{1 - \frac{0.8968}{\alpha}}\sqrt{m_0}, \quad
        y_s = \frac{4\sqrt{m_0}}{\sqrt{\pi\alpha}}

    The density is Nayak's (1971) summit density of an isotropic Gaussian surface; R, sigma_s and
    y_s are McCool's (1986) large-bandwidth approximations for the summits (R is the mean summit
    radius, ``y_s`` the distance from the surface mean plane up to the mean plane of the summits).
    Paper 002 prints eqs. 4-5 and reproduces R = 5.08 um and sigma_s = 0.0431 um from its moments.

    Parameters
    ----------
    m0 : float
        Mean square height [m^2].
    m2 : float
        Mean square slope per direction [dimensionless].
    m4 : float
        Mean square curvature per direction [1/m^2].

    Returns
    -------
    McCoolParameters
        bandwidth [-], summit_density [1/m^2], summit_radius [m], summit_height_std [m],
        summit_mean_offset [m].

    Raises
    ------
    InputError
        A moment that is not positive and finite (field: that moment), or a bandwidth below 0.8968
        where sigma_s would be imaginary (field: ``m2``; the three moments are then inconsistent,
        e.g. from a grid too coarse for the curvatures).

    References
    ----------
    McCool, J. I. (1986). Wear 107, 37-60. doi:10.1016/0043-1648(86)90045-1
    Nayak, P. R. (1971). J. Lubr. Technol. 93, 398-407. doi:10.1115/1.3451150
    Seed paper 002, eqs. 4-5.
    """
    m0 = positive(m0, "m0", example="2.1e-15", unit="m^2")
    m2 = positive(m2, "m2", example="2.3e-3 (mean square slope, dimensionless)")
    m4 = positive(m4, "m4", example="1.7e10", unit="1/m^2")
    bandwidth = m0 * m4 / m2**2
    if bandwidth < MCCOOL_MIN_BANDWIDTH:
        raise InputError(
            "m2",
            f"bandwidth alpha = m0 m4 / m2^2 = {bandwidth:.4g} is below "
            f"{MCCOOL_MIN_BANDWIDTH}, so sigma_s is undefined.",
            "check the units of the moments (SI: m^2, -, 1/m^2) and that they come from one "
            "surface on a grid fine enough to resolve its curvatures.",
        )
    return McCoolParameters(
        bandwidth=bandwidth,
        summit_density=m4 / (6.0 * math.pi * math.sqrt(3.0) * m2),
        summit_radius=0.375 * math.sqrt(math.pi / m4),
        summit_height_std=math.sqrt(1.0 - MCCOOL_MIN_BANDWIDTH / bandwidth) * math.sqrt(m0),
        summit_mean_offset=4.0 * math.sqrt(m0) / math.sqrt(math.pi * bandwidth),
    )


def mccool_parameters_of(topography: Topography, *, derivative: str = "forward") -> McCoolParameters:
    """McCool parameters of a surface: :func:`spectral_moments` then :func:`mccool_parameters`.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).
    derivative : str
        Finite difference of the slopes and curvatures, as in :func:`spectral_moments`.

    Raises
    ------
    InputError
        (field ``topography``) for a flat surface or one whose moments give alpha < 0.8968.
    """
    moments = spectral_moments(topography, derivative=derivative)
    try:
        return mccool_parameters(m0=moments.m0, m2=moments.m2, m4=moments.m4)
    except InputError as error:
        raise InputError(
            "topography",
            f"its spectral moments are unusable ({error.field}: {error.problem})",
            "pass a rough, non-flat surface sampled finely enough to resolve its curvatures.",
        ) from error
