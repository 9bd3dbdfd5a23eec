"""Closed-form contact solutions used to validate the solvers (and useful on their own)."""

from .adhesion import (
    WAVY_JKR_NO_PARTIAL_CONTACT_ALPHA,
    WAVY_JKR_SPONTANEOUS_ALPHA,
    MaugisDugdaleContact,
    WavyJKR,
    dmt_pull_off,
    jkr_pull_off,
    maugis_dugdale,
    maugis_dugdale_curve,
    maugis_dugdale_pull_off,
    maugis_parameter,
    tabor_parameter,
    wavy_adhesion_parameter,
    wavy_jkr,
    wavy_jkr_mean_pressure,
    wavy_jkr_pressure,
    wavy_jkr_pull_off,
)
from .flat_punch import flat_punch_pressure, flat_punch_stiffness
from .hertz import HertzContact, hertz
from .westergaard import westergaard_contact_half_width, westergaard_pressure

__all__ = [
    "WAVY_JKR_NO_PARTIAL_CONTACT_ALPHA",
    "WAVY_JKR_SPONTANEOUS_ALPHA",
    "HertzContact",
    "MaugisDugdaleContact",
    "WavyJKR",
    "dmt_pull_off",
    "flat_punch_pressure",
    "flat_punch_stiffness",
    "hertz",
    "jkr_pull_off",
    "maugis_dugdale",
    "maugis_dugdale_curve",
    "maugis_dugdale_pull_off",
    "maugis_parameter",
    "tabor_parameter",
    "wavy_adhesion_parameter",
    "wavy_jkr",
    "wavy_jkr_mean_pressure",
    "wavy_jkr_pressure",
    "wavy_jkr_pull_off",
    "westergaard_contact_half_width",
    "westergaard_pressure",
]
