r"""Boussinesq's rigid flat circular punch of radius a on an elastic half-space.

.. math:: F = 2 a E^* \delta, \qquad p(r) = \frac{F}{2\pi a \sqrt{a^2 - r^2}}

References
----------
Johnson, K. L. (1985). Contact Mechanics, sec. 3.8, eqs. 3.35-3.37.
doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import math

import numpy as np


def flat_punch_stiffness(*, radius: float, contact_modulus: float) -> float:
    """Return the normal stiffness dF/d(approach) = 2 a E* [N/m]."""
    return 2.0 * radius * contact_modulus


def flat_punch_pressure(r: np.ndarray, *, radius: float, force: float) -> np.ndarray:
    """Pressure [Pa] at r [m] < a (infinite at the edge, 0 outside)."""
    r = np.asarray(r, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        p = force / (2.0 * math.pi * radius * np.sqrt(radius**2 - r**2))
    return np.where(r < radius, p, 0.0)
