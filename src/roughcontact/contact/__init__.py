"""Contact solvers: normal contact (elastic, elastic-plastic, layered), tangential programmes, load paths.

``normal`` (:func:`solve_normal`: FFT boundary elements, load or approach control, hardness, films),
``tangential`` (:func:`solve_tangential`: partial slip under a displacement or force programme),
``frictional`` (:func:`solve_frictional`: combined normal and tangential programmes with friction
from the unloaded state),
``adhesive`` (:func:`solve_adhesive`: adhesive contact through an approach programme, with the
interaction laws of ``interaction``: :class:`MaugisDugdale`, :class:`Exponential`,
:class:`LennardJones`),
``load_unload`` (:func:`load_unload`: elastic-plastic load-unload, the pressure capped at the
hardness or J2 plasticity in the volume), ``presliding``
(:func:`presliding`: a rough ball under a tangential programme, its last loop and Mindlin's smooth
ball, paper 001's model), ``sweep``
(:func:`load_path`: warm-started sequences of normal solves), ``paths`` (tangential programmes:
paper 001's stroke path, symmetric cycles, a CSV) and their results, each with ``scalars()``,
``UNITS`` and ``to_xarray()`` (:mod:`roughcontact.results`).
"""

from .adhesive import solve_adhesive
from .adhesive_result import AdhesiveResult
from .frictional import solve_frictional
from .interaction import Exponential, LennardJones, MaugisDugdale
from .load_unload import LoadUnloadResult, SurfacePlasticity, VolumePlasticity, load_unload
from .normal import compliance_for, solve_normal
from .paths import read_path_csv, read_programme_csv, stroke_path, symmetric_path
from .presliding import PreslidingResult, presliding
from .result import NormalContactResult
from .shear_solver import ShearSolver
from .sweep import load_path
from .tangential import solve_tangential
from .tangential_result import TangentialPathResult, TangentialState

__all__ = [
    "AdhesiveResult",
    "Exponential",
    "LennardJones",
    "LoadUnloadResult",
    "MaugisDugdale",
    "SurfacePlasticity",
    "VolumePlasticity",
    "NormalContactResult",
    "PreslidingResult",
    "TangentialPathResult",
    "TangentialState",
    "compliance_for",
    "load_path",
    "load_unload",
    "presliding",
    "ShearSolver",
    "solve_frictional",
    "read_path_csv",
    "read_programme_csv",
    "solve_adhesive",
    "solve_normal",
    "solve_tangential",
    "stroke_path",
    "symmetric_path",
]
