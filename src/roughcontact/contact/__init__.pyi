"""The public names of :mod:`roughcontact.contact`, each re-exported from its module: the one list of them.

Type checkers and IDEs read this stub; the package reads it too (:func:`roughcontact._lazy.attach_stub`):
the names here are its ``__all__``, each loaded from its module on first use.
"""

from .adhesive import solve_adhesive as solve_adhesive
from .adhesive_result import AdhesiveResult as AdhesiveResult
from .frictional import solve_frictional as solve_frictional
from .interaction import Exponential as Exponential
from .interaction import LennardJones as LennardJones
from .interaction import MaugisDugdale as MaugisDugdale
from .load_unload import LoadUnloadResult as LoadUnloadResult
from .load_unload import SurfacePlasticity as SurfacePlasticity
from .load_unload import VolumePlasticity as VolumePlasticity
from .load_unload import load_unload as load_unload
from .normal import compliance_for as compliance_for
from .normal import solve_normal as solve_normal
from .paths import read_path_csv as read_path_csv
from .paths import read_programme_csv as read_programme_csv
from .paths import stroke_path as stroke_path
from .paths import symmetric_path as symmetric_path
from .presliding import PreslidingResult as PreslidingResult
from .presliding import presliding as presliding
from .result import NormalContactResult as NormalContactResult
from .shear_solver import ShearSolver as ShearSolver
from .sweep import load_path as load_path
from .tangential import solve_tangential as solve_tangential
from .tangential_result import TangentialPathResult as TangentialPathResult
from .tangential_result import TangentialState as TangentialState

__all__: list[str]
