"""Theories of the elastic contact of a rough surface, evaluated from the surface's own spectrum.

``spectrum`` takes the modes of a map and their power from its PSD (as ``roughcontact inspect``
computes it); ``persson`` holds Persson's relative contact area (and its magnification-dependent
form), his distribution of contact pressures and his (2007) mean separation; ``bgt`` Bush, Gibson and
Thomas's small-load area; ``gw`` Greenwood and Williamson's area and separation from the spectral
moments (the summits of :mod:`roughcontact.asperity`); ``comparison`` sweeps the load on a surface
with the boundary-element method and sets every theory beside it, with the BEM's area corrected for
its pixelated perimeter (:mod:`roughcontact.contact.area`) and its small-load slope kappa, and judges
each theory against the BEM over realisations. Theory and validation: :doc:`/theories`.
"""

from .bgt import bgt_contact_fraction
from .comparison import (
    KAPPA_MAX_FRACTION,
    REDUCED_PRESSURES,
    THEORIES,
    TheoryComparison,
    TheoryDeviation,
    against_bem,
    compare_theories,
    kappa_fit,
)
from .gw import GreenwoodWilliamsonAtPressure, gw_at_pressure
from .persson import (
    persson_contact_fraction,
    persson_contact_fraction_magnified,
    persson_mean_separation,
    persson_pressure_distribution,
)
from .spectrum import Spectrum, surface_spectrum

__all__ = [
    "KAPPA_MAX_FRACTION",
    "REDUCED_PRESSURES",
    "THEORIES",
    "GreenwoodWilliamsonAtPressure",
    "Spectrum",
    "TheoryComparison",
    "TheoryDeviation",
    "against_bem",
    "bgt_contact_fraction",
    "compare_theories",
    "gw_at_pressure",
    "kappa_fit",
    "persson_contact_fraction",
    "persson_contact_fraction_magnified",
    "persson_mean_separation",
    "persson_pressure_distribution",
    "surface_spectrum",
]
