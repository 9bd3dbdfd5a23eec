r"""Hertz contact of a sphere (paraboloid) on a flat.

.. math::

    a = \left(\frac{3 F R}{4 E^*}\right)^{1/3}, \quad p_0 = \frac{3F}{2\pi a^2}, \quad
    \delta = \frac{a^2}{R}, \quad p(r) = p_0 \sqrt{1 - r^2/a^2}

References
----------
Johnson, K. L. (1985). Contact Mechanics, sec. 4.2, eqs. 4.22-4.24.
doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class HertzContact:
    """Hertz solution: contact radius a [m], peak pressure p0 [Pa], approach [m], force [N]."""

    contact_radius: float
    peak_pressure: float
    approach: float
    force: float

    def pressure(self, r: np.ndarray) -> np.ndarray:
        """Pressure [Pa] at distance r [m] from the centre."""
        r = np.asarray(r, dtype=float)
        return self.peak_pressure * np.sqrt(np.clip(1.0 - (r / self.contact_radius) ** 2, 0.0, None))


def hertz(*, radius: float, contact_modulus: float, force: float) -> HertzContact:
    """Hertz contact of a sphere of ``radius`` [m] pressed by ``force`` [N] (E* [Pa])."""
    a = (3.0 * force * radius / (4.0 * contact_modulus)) ** (1.0 / 3.0)
    return HertzContact(a, 3.0 * force / (2.0 * math.pi * a**2), a**2 / radius, force)
