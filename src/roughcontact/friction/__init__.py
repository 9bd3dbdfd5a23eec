"""Friction models: the Winkler-layer + Lennard-Jones adhesive friction model of paper 000."""

from .readings import PAPER, PRINTED, Readings
from .viscoelastic import PronySeries, material_after_hold, standard_linear_solid
from .winkler_lj import (
    FrictionSweep,
    WinklerLJModel,
    WinklerLJResult,
    solve_winkler_lj,
    winkler_lj_model,
    work_of_adhesion,
)

__all__ = [
    "PAPER",
    "PRINTED",
    "FrictionSweep",
    "PronySeries",
    "Readings",
    "WinklerLJModel",
    "WinklerLJResult",
    "material_after_hold",
    "solve_winkler_lj",
    "standard_linear_solid",
    "winkler_lj_model",
    "work_of_adhesion",
]
