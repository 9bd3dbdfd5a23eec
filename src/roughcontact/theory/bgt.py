r"""Bush, Gibson and Thomas's theory of elastic rough contact, in its small-load limit.

Bush, Gibson and Thomas (1975) treat the summits of an isotropic Gaussian surface as elliptic
paraboloids whose principal curvatures and heights follow the random-process statistics of Nayak
(1971), each pressed in Hertz contact with the flat, independently of the others. At large
separation (small load) only the highest summits touch, and the area and the load they carry fall
off together as the separation grows: their ratio tends to a constant, the real area grows in
proportion to the load,

.. math::

    \frac{A}{A_0} = \sqrt{\frac{\pi}{m_2}}\, \frac{p_0}{E^*} = \kappa_\mathrm{BGT}\, \frac{p_0}{E^* g},
    \qquad \kappa_\mathrm{BGT} = \sqrt{2\pi} = 2.507,

with :math:`m_2` the mean-square slope per direction and :math:`g = \sqrt{2 m_2}` the rms gradient
of the surface (the :math:`g` of Persson's theory, :mod:`roughcontact.theory.persson`, whose slope is
:math:`\sqrt{8/\pi} = 1.596`). Boundary-element solutions lie between the two (Hyun et al. 2004:
:math:`\kappa \approx 2`). The slope does not depend on the bandwidth :math:`\alpha` as long as the
band is broad; the full BGT curve at finite load does (through Nayak's summit statistics) and is not
implemented here: :func:`bgt_contact_fraction` is the small-load law, meaningful while
:math:`A/A_0` is a few per cent, the regime where the theories are compared by their slope
(Persson 2006, sec. 3.3, reviews the full theory).

References
----------
Bush, A. W., Gibson, R. D. and Thomas, T. R. (1975). The elastic contact of a rough surface. Wear
35, 87-111. doi:10.1016/0043-1648(75)90145-3

Nayak, P. R. (1971). Random process model of rough surfaces. J. Lubr. Technol. 93, 398-407.
doi:10.1115/1.3451150

Persson, B. N. J. (2006). Contact mechanics for randomly rough surfaces. Surf. Sci. Rep. 61, 201-227.
doi:10.1016/j.surfrep.2006.04.001

Hyun, S., Pei, L., Molinari, J.-F. and Robbins, M. O. (2004). Finite-element analysis of contact
between elastic self-affine surfaces. Phys. Rev. E 70, 026117. doi:10.1103/PhysRevE.70.026117
"""

from __future__ import annotations

import math

import numpy as np

from ..checks import positive
from .persson import checked_pressures

__all__ = ["KAPPA", "bgt_contact_fraction"]

KAPPA = math.sqrt(2.0 * math.pi)
r"""BGT's small-load slope of :math:`A/A_0` against :math:`p_0/(E^* g)`, :math:`\sqrt{2\pi} = 2.507`."""


def bgt_contact_fraction(mean_pressure, *, contact_modulus: float, rms_gradient: float) -> np.ndarray:
    r"""Bush-Gibson-Thomas's relative contact area at small load, :math:`\sqrt{2\pi}\, p_0/(E^* g)`.

    Parameters
    ----------
    mean_pressure : float or array_like
        Nominal pressure :math:`p_0` [Pa], >= 0.
    contact_modulus : float
        :math:`E^*` [Pa].
    rms_gradient : float
        :math:`g = \sqrt{2 m_2}`, the rms gradient of the 2D surface [-].

    Returns
    -------
    ndarray
        :math:`A/A_0` [-] per pressure (at least 1D): the small-load law, not capped at 1; meaningful
        while it is small.

    References
    ----------
    Bush, Gibson and Thomas (1975) doi:10.1016/0043-1648(75)90145-3
    """
    positive(contact_modulus, "contact_modulus", example=1e9, unit="Pa")
    positive(rms_gradient, "rms_gradient", example="0.1 (dimensionless)")
    return KAPPA * checked_pressures(mean_pressure) / (contact_modulus * rms_gradient)
