"""Contact solvers: normal contact (elastic, elastic-plastic, layered), load paths and their results."""

from .normal import compliance_for, solve_normal
from .plastic import LoadUnloadResult, load_unload
from .result import NormalContactResult
from .sweep import load_path

__all__ = [
    "LoadUnloadResult",
    "NormalContactResult",
    "compliance_for",
    "load_path",
    "load_unload",
    "solve_normal",
]
