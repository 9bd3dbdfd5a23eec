"""Closed-form contact solutions used to validate the solvers (and useful on their own)."""

from .flat_punch import flat_punch_pressure, flat_punch_stiffness
from .hertz import HertzContact, hertz
from .westergaard import westergaard_contact_half_width, westergaard_pressure

__all__ = [
    "HertzContact",
    "flat_punch_pressure",
    "flat_punch_stiffness",
    "hertz",
    "westergaard_contact_half_width",
    "westergaard_pressure",
]
