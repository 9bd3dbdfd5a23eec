r"""Westergaard's periodic line contact of a wavy surface z = A cos(2 pi x / lambda) on a flat.

Plane strain, E* = E / (1 - nu^2) per body. Full contact needs p* = pi E* A / lambda; below it
the contact half-width a and the pressure are

.. math::

    \bar p = p^* \sin^2\frac{\pi a}{\lambda}, \qquad
    p(x) = \frac{2 \bar p \cos(\pi x/\lambda)}{\sin^2(\pi a/\lambda)}
           \sqrt{\sin^2\frac{\pi a}{\lambda} - \sin^2\frac{\pi x}{\lambda}}, \quad |x| \le a

References
----------
Westergaard, H. M. (1939). J. Appl. Mech. 6, A49-A53.
Johnson, K. L. (1985). Contact Mechanics, sec. 13.2, eqs. 13.7-13.9.
doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import math

import numpy as np


def westergaard_contact_half_width(
    mean_pressure: float, *, amplitude: float, wavelength: float, contact_modulus: float
) -> float:
    """Contact half-width a [m] at ``mean_pressure`` [Pa]; lambda/2 in full contact."""
    full = math.pi * contact_modulus * amplitude / wavelength
    if mean_pressure >= full:
        return wavelength / 2.0
    return wavelength / math.pi * math.asin(math.sqrt(mean_pressure / full))


def westergaard_pressure(
    x: np.ndarray, mean_pressure: float, *, amplitude: float, wavelength: float, contact_modulus: float
) -> np.ndarray:
    """Pressure [Pa] at x [m] (x = 0 at a crest), in partial or full contact."""
    x = np.asarray(x, dtype=float)
    full = math.pi * contact_modulus * amplitude / wavelength
    if mean_pressure >= full:
        return mean_pressure + full * np.cos(2.0 * math.pi * x / wavelength)
    s2 = mean_pressure / full
    x = (x + wavelength / 2.0) % wavelength - wavelength / 2.0  # nearest crest at 0
    inside = np.clip(s2 - np.sin(math.pi * x / wavelength) ** 2, 0.0, None)
    return (
        2.0
        * mean_pressure
        * np.cos(math.pi * x / wavelength)
        / s2
        * np.sqrt(inside)
        * (np.cos(math.pi * x / wavelength) > 0)
    )
