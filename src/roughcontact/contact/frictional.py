r"""Frictional contact under any combined normal and tangential programme: :func:`solve_frictional`.

A rough body and a flat start unloaded (they just touch, no history). Each step of the programme
prescribes the normal force or the normal approach AND the tangential force or rigid tangential
displacement of the flat; either may stay constant from step to step. The normal and tangential
problems of every step are solved together under the local Coulomb law of paper 001 eq. 3 with
the history of the previous step (slip increments, not totals), and with the normal-tangential
coupling of dissimilar materials (Dundurs' beta) in both directions: the shear tractions open
the gap, the pressure moves the surface tangentially (:mod:`roughcontact.contact._programme`
describes the block Gauss-Seidel passes and the step control).

What this covers:

* frictional normal loading (Spence 1975: for beta != 0 a central stick zone whose radius is a
  fixed fraction of the contact radius while the load grows, with shear locked in);
* unloading with friction, oblique loading at a constant angle (Mindlin and Deresiewicz 1953),
  normal-load cycling at constant tangential force, and paper 001's tangential programme started
  from a frictional normal loading;
* ``coupling=False``: Goodman's approximation (the coupling terms dropped), which is exact for
  beta = 0 (similar materials, or two incompressible bodies).

The programme's rows are solved exactly; with ``max_stick_change`` steps are inserted where the
stick fraction changes fast (after reversals), and ``programme_index`` of the result says which
row each step belongs to.

References
----------
Spence, D. A. (1975). J. Elasticity 5, 297-319 (the Hertz problem with finite friction).
Mindlin, R. D. and Deresiewicz, H. (1953). J. Appl. Mech. 20, 327-344 (oblique loading).
Johnson, K. L. (1985). Contact Mechanics, secs. 5.5 and 7.3.
Seed paper 001, eqs. 1-4.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .._deprecation import folded
from ..errors import InputError
from ..materials import Material
from ..topography import Topography
from ..topography.surface import topography_argument
from . import _programme
from .normal import resolve_boundary
from .shear_solver import DEFAULT, SOLVER_KEYWORDS, ShearSolver, folded_solver
from .tangential_result import TangentialPathResult

NORMAL_CONTROLS = ("force", "approach")


def _normal_programme(normal_force, approach, steps: int) -> tuple[str, np.ndarray]:
    """Return (control, (n,) values) of the normal column (exactly one of force and approach)."""
    if (normal_force is None) == (approach is None):
        raise InputError(
            "normal_force",
            "give the normal programme as exactly one of normal_force and approach (one value per step).",
            "e.g. normal_force=np.full(n, 50e-3).",
        )
    control = "force" if normal_force is not None else "approach"
    values = np.asarray(normal_force if normal_force is not None else approach, dtype=float)
    if values.ndim == 0:
        values = np.full(steps, float(values))
    name = "normal_force" if control == "force" else "approach"
    if values.shape != (steps,):
        raise InputError(
            name,
            f"{values.shape[0] if values.ndim else 1} values for {steps} tangential steps.",
            "give one per step.",
        )
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        raise InputError(name, f"step {int(bad[0])} is not a finite number.", "remove or fill it.")
    low = np.flatnonzero(values <= 0)
    if low.size:
        raise InputError(
            name,
            f"step {int(low[0])}: the normal {control} is {values[low[0]]:.6g} (SI): contact is lost there.",
            "keep it above zero; a programme that separates the bodies ends at the step before.",
        )
    return control, values


@folded("solver", SOLVER_KEYWORDS, folded_solver)
def solve_frictional(
    topography: Topography,
    material: Material,
    *,
    friction_coefficient: float,
    normal_force=None,
    approach=None,
    displacement=None,
    force=None,
    counter_body: Material | None = None,
    boundary: str | None = None,
    coupling: bool = True,
    max_stick_change: float | None = None,
    solver: ShearSolver = DEFAULT,
    fields_at: str | Sequence[int] = "all",
) -> TangentialPathResult:
    """Solve a combined normal and tangential programme from the unloaded state.

    Parameters
    ----------
    topography : Topography
        The rough body (heights [m]; a ball with its spherical shape for paper 001).
    material : Material
        The rough body's material.
    friction_coefficient : float
        mu of the local Coulomb law (> 0).
    normal_force, approach : array_like, shape (n,) or float
        Exactly one: the normal force [N] or the rigid normal approach of the flat from first
        touch [m] after each step (a scalar holds it constant). Must stay > 0.
    displacement, force : array_like, shape (n,) or (n, 2)
        Exactly one: the rigid tangential displacement of the flat [m] or the tangential force
        on the rough body [N] after each step (1D: along x). Under force control ``|F|`` must stay
        below mu times the normal force (else the contact slides: the message says so).
    counter_body : Material, optional
        The flat (default rigid).
    boundary : {"free", "periodic"}, optional
        Default: "periodic" for a periodic topography, else "free". A periodic surface needs
        tangential force control.
    coupling : bool
        Solve the normal-tangential coupling of dissimilar materials (default). False is
        Goodman's approximation.
    max_stick_change : float, optional
        Step control: insert steps where the stick fraction would change by more than this in one
        step (e.g. 0.1); the rows are always solved.
    solver : ShearSolver
        Numerics of the increments (:class:`~roughcontact.contact.shear_solver.ShearSolver`), as
        for :func:`~roughcontact.contact.tangential.solve_tangential`.
    fields_at : {"all", "last", "none"} or sequence of int
        Programme rows whose fields are kept.

    Returns
    -------
    TangentialPathResult
        ``normal`` is None (the programme starts unloaded); ``normal_load`` and ``approach`` per
        step; ``dissipation`` per step.

    Raises
    ------
    InputError
        Both or neither controls in a direction, rows of different lengths, NaN rows, a normal force
        or approach <= 0 (contact lost: the step is named), a tangential force at or above mu
        times the normal force (sliding), displacement control of a periodic surface, mu <= 0.
    ConvergenceError
        A step or its coupling passes did not converge (residual and iterations given).
    """
    topography = topography_argument(topography, "topography")
    if not isinstance(topography, Topography) or topography.dim != 2:
        raise InputError("topography", "a 2D Topography is needed.", "load or generate a 2D map.")
    if not isinstance(material, Material):
        raise InputError("material", "a Material is needed (shear moduli and Poisson's ratios).", None)
    boundary = resolve_boundary(topography, boundary)
    tangential_control, path = _programme.tangential_programme(displacement, force, boundary)
    normal_control, normal_values = _normal_programme(normal_force, approach, len(path))
    _programme.check_max_stick_change(max_stick_change)
    stepper, parameters = _programme.build(
        topography,
        material,
        counter_body,
        boundary=boundary,
        friction_coefficient=friction_coefficient,
        coupling=coupling,
        solver=solver,
        name="solve_frictional",
    )
    record, _ = _programme.run(
        stepper,
        _programme.State.unloaded(topography.shape),
        (normal_control, normal_values),
        (tangential_control, path),
        start=(0.0, np.zeros(2)),
        keep=_programme.steps_to_keep(fields_at, len(path)),
        max_stick_change=max_stick_change,
        what="frictional steps",
    )
    parameters.update(
        control=tangential_control,
        normal_control=normal_control,
        normal_loading="frictional",  # the normal load is part of the programme, friction acts from the start
        boundary=boundary,
        max_stick_change=max_stick_change,
    )
    return _programme.result(None, topography, record, parameters)
