"""Contact solvers: normal contact (elastic, elastic-plastic, layered) and their results."""

from .normal import compliance_for, solve_normal
from .result import NormalContactResult

__all__ = ["NormalContactResult", "compliance_for", "solve_normal"]
