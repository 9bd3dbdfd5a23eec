r"""Greenwood and Williamson's elastic rough contact at a nominal pressure, from the spectral moments.

The summit population is McCool's (1986) for an isotropic Gaussian surface of moments
:math:`m_0, m_2, m_4` (:func:`~roughcontact.topography.statistics.mccool_parameters`: density
:math:`\eta = m_4/(6\pi\sqrt3\, m_2)`, radius :math:`R = 0.375\sqrt{\pi/m_4}`, summit height deviation
:math:`\sigma_s`, and the summits' mean plane :math:`y_s = 4\sqrt{m_0}/\sqrt{\pi\alpha}` above the
surface's), and the contact is the elastic GW integrals of
:func:`roughcontact.asperity.greenwood_williamson` per unit nominal area,

.. math::

    \frac{A}{A_0} = \pi \eta R \sigma_s F_1(h), \qquad
    p_0 = \tfrac43 \eta E^* R^{1/2} \sigma_s^{3/2} F_{3/2}(h), \qquad h = d/\sigma_s,

with :math:`d` the distance from the summits' mean plane to the flat. :func:`gw_at_pressure` solves
the second for :math:`d` at each :math:`p_0` and returns the first, and the mean separation
:math:`\bar u = d + y_s` of the flat from the surface's mean plane (the summits do not deform the
bulk, so the plane does not move; the boundary-element mean gap of a periodic surface is measured
from the same plane). The summits do not interact, so at small load
:math:`A/A_0 \approx \kappa\, p_0/(E^* g)` with a :math:`\kappa` that grows slowly as the load falls
(:math:`F_1/F_{3/2} \sim h^{1/2}`), not a constant; and nothing keeps :math:`A/A_0` below 1.

References
----------
Greenwood, J. A. and Williamson, J. B. P. (1966). Contact of nominally flat surfaces. Proc. R. Soc. A
295, 300-319. doi:10.1098/rspa.1966.0242

McCool, J. I. (1986). Comparison of models for the contact of rough surfaces. Wear 107, 37-60.
doi:10.1016/0043-1648(86)90045-1
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import optimize

from ..asperity.greenwood_williamson import gaussian_summits, greenwood_williamson
from ..checks import positive
from ..errors import InputError
from ..topography.statistics import SpectralMoments, mccool_parameters

__all__ = ["GreenwoodWilliamsonAtPressure", "gw_at_pressure"]


@dataclass(frozen=True)
class GreenwoodWilliamsonAtPressure:
    """GW's contact at given nominal pressures (SI).

    Attributes
    ----------
    mean_pressure : ndarray
        :math:`p_0` [Pa].
    contact_fraction : ndarray
        :math:`A/A_0` [-].
    mean_separation : ndarray
        Flat to the surface's mean plane, :math:`d + y_s` [m].
    summit_separation : ndarray
        Flat to the summits' mean plane, :math:`d` [m].
    """

    mean_pressure: np.ndarray
    contact_fraction: np.ndarray
    mean_separation: np.ndarray
    summit_separation: np.ndarray


def gw_at_pressure(
    mean_pressure, *, contact_modulus: float, moments: SpectralMoments
) -> GreenwoodWilliamsonAtPressure:
    r"""Greenwood and Williamson's area fraction and mean separation at nominal pressures (module notes).

    Parameters
    ----------
    mean_pressure : float or array_like
        :math:`p_0` [Pa], > 0.
    contact_modulus : float
        :math:`E^*` [Pa].
    moments : SpectralMoments
        :math:`m_0, m_2, m_4` of the surface (per direction, paper 002 eqs. 1-3).

    Returns
    -------
    GreenwoodWilliamsonAtPressure

    Raises
    ------
    InputError
        A pressure that is not positive, or moments whose bandwidth is below McCool's 0.8968.

    References
    ----------
    Greenwood and Williamson (1966) doi:10.1098/rspa.1966.0242; McCool (1986)
    doi:10.1016/0043-1648(86)90045-1
    """
    positive(contact_modulus, "contact_modulus", example=1e9, unit="Pa")
    pressure = np.atleast_1d(np.asarray(mean_pressure, dtype=float))
    if not np.all(np.isfinite(pressure) & (pressure > 0)):
        raise InputError(
            "mean_pressure", f"must be finite and > 0, got {mean_pressure!r}.", "e.g. 20e6 (Pa)."
        )
    mccool = mccool_parameters(m0=moments.m0, m2=moments.m2, m4=moments.m4)
    summits = gaussian_summits(mccool)
    sigma = mccool.summit_height_std

    def excess(h: float, target: float) -> float:
        force = greenwood_williamson(h * sigma, summits, contact_modulus=contact_modulus).force[0]
        return np.log(force) - np.log(target)

    separation = []
    for target in pressure:
        low, high = -2.0, 8.0
        while excess(low, target) < 0:
            low *= 2.0
        while excess(high, target) > 0:
            high *= 2.0
        separation.append(optimize.brentq(excess, low, high, args=(target,), xtol=1e-12, rtol=1e-12) * sigma)
    d = np.asarray(separation)
    area = greenwood_williamson(d, summits, contact_modulus=contact_modulus).contact_area
    return GreenwoodWilliamsonAtPressure(
        mean_pressure=pressure,
        contact_fraction=area,
        mean_separation=d + mccool.summit_mean_offset,
        summit_separation=d,
    )
