"""How the tangential engine solves its increments: one options object for both of its doors.

:func:`~roughcontact.contact.tangential.solve_tangential` (a programme from a normal contact) and
:func:`~roughcontact.contact.frictional.solve_frictional` (a combined programme from the unloaded
state) run the same stepper (:mod:`roughcontact.contact._programme`); the numerics of its
increments and of the normal-tangential coupling passes are this one :class:`ShearSolver`, given
as ``solver=ShearSolver(tolerance=1e-10)``. The physics (the friction coefficient, the
coupling of dissimilar materials, the programme) stays in the functions' own keywords.
"""

from __future__ import annotations

from dataclasses import dataclass, replace


@dataclass(frozen=True)
class ShearSolver:
    """Numerical options of the tangential increments (paper 001's partial-slip engine).

    Attributes
    ----------
    tolerance : float
        Scale-free residual of each tangential increment (and of the coupled normal solves).
    coupling_tolerance : float
        Relative change of p and q between coupling passes that ends a step.
    max_iterations, max_coupling_iterations : int
        Limits; beyond them :class:`~roughcontact.errors.ConvergenceError` is raised.
    precondition : {"auto", True, False}
        True builds the conjugate directions from the Fourier-inverse preconditioned gradient;
        False gives the plain projected conjugate gradients; "auto" (default) runs the plain
        method and, where it has not converged within ``PLAIN_ITERATIONS``, the preconditioned
        one. Applies to ``method="cg"``; ``method="apg"`` takes "auto" or False.
    method : {"auto", "cg", "apg"}
        Increment solver (both reach the same residual): Polonsky-Keer's projected conjugate
        gradients, or accelerated projected gradients with adaptive restart; "auto" takes "apg"
        when a body has nu > 0 (measured 7-146x faster there, ``benchmarks/tangential_apg.py``),
        else "cg".
    workers : int, optional
        FFT threads.
    """

    tolerance: float = 1e-8
    coupling_tolerance: float = 1e-6
    max_iterations: int = 10_000
    max_coupling_iterations: int = 50
    precondition: bool | str = "auto"
    method: str = "auto"
    workers: int | None = None


DEFAULT = ShearSolver()
"""The default options (a frozen instance, shared safely as a default argument)."""

SOLVER_KEYWORDS = (
    "tolerance",
    "coupling_tolerance",
    "max_iterations",
    "max_coupling_iterations",
    "precondition",
    "method",
    "workers",
)
"""The keywords of release 0.1 that :class:`ShearSolver` holds now."""


def folded_solver(
    solver: ShearSolver | None,
    *,
    tolerance: float | None = None,
    coupling_tolerance: float | None = None,
    max_iterations: int | None = None,
    max_coupling_iterations: int | None = None,
    precondition: bool | str | None = None,
    method: str | None = None,
    workers: int | None = None,
) -> ShearSolver:
    """Return ``solver`` (default :class:`ShearSolver`) with the old keywords a call gave applied."""
    given = {
        "tolerance": tolerance,
        "coupling_tolerance": coupling_tolerance,
        "max_iterations": max_iterations,
        "max_coupling_iterations": max_coupling_iterations,
        "precondition": precondition,
        "method": method,
        "workers": workers,
    }
    return replace(solver or DEFAULT, **{name: value for name, value in given.items() if value is not None})
