r"""Partial-slip tangential contact along a loading programme: :func:`solve_tangential` (paper 001).

A rough body pressed on a flat by a constant normal force F_0 (a converged
:class:`~roughcontact.contact.NormalContactResult`) is loaded by a path of rigid tangential
displacements delta (or forces) of the flat. Each step is an increment with the local Coulomb
law of paper 001 eq. 3 (stick where |q| < mu p and the slip does not change; slip where
|q| = mu p, opposing the slip increment), solved by :mod:`roughcontact.contact._shear_cg`
(``method="cg"``, the default) or :mod:`roughcontact.contact._shear_apg` (``method="apg"``). The
increments carry the history, so unloading and reloading trace Masing-type hysteresis loops
(Mindlin and Deresiewicz 1953).

Normal-tangential coupling (paper 001 sec. 2: "the effect of shear stress components on the
contact pressure is also included in an iterative manner"). For dissimilar materials (Dundurs
beta != 0) the shear tractions move the surface normally and the pressure moves it tangentially
(:mod:`roughcontact.elasticity.tangential`). With ``coupling=True`` each step alternates

1. normal solve at F_0 with the separation h_0 + u_z(q) (warm-started);
2. tangential increment at the new bound mu p, with the slip the pressure causes, s_t(p);

until the pressure and the tractions change by less than ``coupling_tolerance`` relative to
their maxima (a block Gauss-Seidel iteration, as Chen and Wang 2008 and Bazrafshan et al. 2019
describe it). When D = 0 (similar materials, or two incompressible bodies) the coupling terms
vanish identically and the result equals the uncoupled (Goodman) one exactly, which is also
what ``coupling=False`` computes for any pair.

The normal loading that precedes the programme (``normal_loading``):

* ``"frictional"`` (the default when the pair is coupled, beta != 0): F_0 is applied in
  ``loading_steps`` steps from zero under the same Coulomb law, with the tangential displacement
  held at 0 (or the tangential force at 0 under force control). Dissimilar materials then lock in
  shear with a central stick zone (Spence 1975); the programme starts from that state, and the
  loading is kept in ``result.loading``.
* ``"frictionless"``: Goodman's approximation of the start: the slip the pressure causes is free
  and the history starts at the first tangential step (what this solver did before; equal to the
  frictional start when beta = 0).

The steps of both run through the incremental stepper of :mod:`roughcontact.contact._programme`,
which also solves combined normal and tangential programmes
(:func:`roughcontact.contact.frictional.solve_frictional`). Points that come into contact during
a step stick where they are unless the Coulomb law makes them slip; the friction coefficient is
constant (no static/kinetic distinction, as in the paper).

References
----------
Mindlin, R. D. and Deresiewicz, H. (1953). J. Appl. Mech. 20, 327-344.
Spence, D. A. (1975). J. Elasticity 5, 297-319 (the Hertz problem with finite friction).
Chen, W. W. and Wang, Q. J. (2008). J. Tribol. 130, 041402 (coupled partial slip by FFT).
Bazrafshan, M., de Rooij, M. B. and Schipper, D. J. (2019). Int. J. Mech. Sci. 155, 9-18 (paper 001 ref. 28).
Seed paper 001, eqs. 1-4.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .._deprecation import folded
from ..errors import InputError
from ..materials import Material, check_material, contact_modulus
from . import _programme
from .result import NormalContactResult
from .shear_solver import DEFAULT, SOLVER_KEYWORDS, ShearSolver, folded_solver
from .tangential_result import TangentialPathResult

NORMAL_LOADINGS = ("auto", "frictional", "frictionless")


def _loading_mode(normal_loading: str, coupled: bool) -> str:
    """Resolve ``normal_loading``: "auto" is "frictional" when the pair is coupled, else "frictionless"."""
    if normal_loading not in NORMAL_LOADINGS:
        raise InputError(
            "normal_loading",
            f"unknown {normal_loading!r}.",
            "use 'frictional' (friction acts while F_0 is applied), 'frictionless' (Goodman's start) "
            "or 'auto'.",
        )
    if normal_loading == "auto":
        return "frictional" if coupled else "frictionless"
    return normal_loading


def _check_inputs(normal, material, counter_body):
    if not isinstance(normal, NormalContactResult):
        raise InputError("normal", f"got {type(normal).__name__}.", "pass the result of solve_normal.")
    if normal.hardness is not None:
        raise InputError("normal", "the normal contact is elastic-plastic.", "solve it without hardness.")
    check_material(material, "material")
    check_material(counter_body, "counter_body", rigid=True)
    expected = contact_modulus(material, counter_body)
    if not np.isclose(expected, normal.contact_modulus, rtol=1e-9):
        raise InputError(
            "material",
            f"E* = {expected:.6g} Pa of these materials differs from the normal solution's "
            f"{normal.contact_modulus:.6g} Pa (a layered body, or other materials).",
            "solve the normal contact with the same material and counter_body (half-spaces).",
        )
    if normal.topography.dim != 2:
        raise InputError("normal", "tangential contact needs a 2D map.", "pass a 2D topography.")


@folded("solver", SOLVER_KEYWORDS, folded_solver)
def solve_tangential(
    normal: NormalContactResult,
    material: Material,
    *,
    friction_coefficient: float,
    displacement=None,
    force=None,
    counter_body: Material | None = None,
    coupling: bool = True,
    solver: ShearSolver = DEFAULT,
    fields_at: str | Sequence[int] = "all",
    normal_loading: str = "auto",
    loading_steps: int = 10,
    max_stick_change: float | None = None,
) -> TangentialPathResult:
    """Solve a tangential loading programme from a normal contact (paper 001).

    Parameters
    ----------
    normal : NormalContactResult
        Elastic normal contact at the constant normal force F_0 (from :func:`solve_normal`).
    material : Material
        The rough body's material (the one the normal contact was solved with).
    friction_coefficient : float
        mu_f of the local Coulomb law (> 0; paper 001 Table 1: 0.099-0.153).
    displacement, force : array_like, shape (n,) or (n, 2)
        Exactly one: the rigid tangential displacement of the flat after each step [m]
        (a 1D path is along x; e.g. :func:`roughcontact.contact.paths.stroke_path`) or the
        tangential force on the rough body [N] (force control: ``|F|`` must stay below mu F_0).
        A periodic surface needs force control: the mean tangential displacement of a periodic
        half-space is undetermined.
    counter_body : Material, optional
        The flat (default: rigid). Paper 001: silicon wafer.
    coupling : bool
        Iterate the normal-tangential coupling of dissimilar materials (default; see the module
        docstring). False gives the uncoupled (Goodman) solution.
    solver : ShearSolver
        Numerics of the increments: tolerance, limits, preconditioning, the increment method,
        FFT threads (:class:`~roughcontact.contact.shear_solver.ShearSolver`).
    fields_at : {"all", "last", "none"} or sequence of int
        Steps whose full fields are kept in ``states`` (per-step scalars are always kept).
    normal_loading : {"auto", "frictional", "frictionless"}
        How F_0 was applied (module docstring): "auto" (default) is "frictional" for a coupled
        pair (beta != 0 and ``coupling``), else "frictionless" (Goodman's start).
    loading_steps : int
        Steps of the frictional normal loading, F_k = F_0 (k/n)^3 (equal steps of the Hertz
        contact radius; >= 2).
    max_stick_change : float, optional
        Step control: insert steps wherever the stick fraction would change by more than this in
        one step (e.g. 0.1: at least 10 steps between a reversal and full slip; the programme's
        points are all solved). None (default) solves the programme points only.

    Returns
    -------
    TangentialPathResult

    Raises
    ------
    InputError
        mu <= 0, paths with NaN, both or neither path, a force at or above mu F_0 (full
        sliding: the message gives the sliding force), displacement control of a periodic
        surface, materials that do not match the normal solution, an unknown ``method``,
        ``precondition=True`` with ``method="apg"``.
    ConvergenceError
        A step or its coupling iteration did not converge (residual and iterations given).
    """
    if not (isinstance(loading_steps, int) and loading_steps >= 2):
        raise InputError("loading_steps", f"got {loading_steps!r}.", "give an integer >= 2, e.g. 10.")
    _programme.check_max_stick_change(max_stick_change)
    _check_inputs(normal, material, counter_body)
    control, path = _programme.tangential_programme(displacement, force, normal.boundary)
    topography = normal.topography
    stepper, parameters = _programme.build(
        topography,
        material,
        counter_body,
        boundary=normal.boundary,
        friction_coefficient=friction_coefficient,
        coupling=coupling,
        solver=solver,
    )
    loading_mode = _loading_mode(normal_loading, stepper.coupled)
    constant = np.full(len(path), normal.force)
    loading = None
    if loading_mode == "frictional":
        loads = normal.force * (np.arange(1, loading_steps + 1) / loading_steps) ** 3
        record, state = _programme.run(
            stepper,
            _programme.State.unloaded(topography.shape),
            ("force", loads),
            (control, np.zeros((loading_steps, 2))),
            start=(0.0, np.zeros(2)),
            keep={loading_steps - 1},
            what="frictional normal loading steps",
        )
        loading = _programme.result(
            normal,
            topography,
            record,
            {**parameters, "control": control, "stage": "frictional normal loading"},
        )
        stick_fraction = loading.stick_area[-1] / loading.contact_area[-1]
    else:
        state = _programme.frictionless_start(stepper, normal.pressure, normal.approach, normal.force)
        stick_fraction = 1.0  # nothing has slipped yet
    record, _ = _programme.run(
        stepper,
        state,
        ("force", constant),
        (control, path),
        start=(normal.force, np.zeros(2)),
        keep=_programme.steps_to_keep(fields_at, len(path)),
        max_stick_change=max_stick_change,
        stick_fraction=stick_fraction,
    )
    parameters.update(control=control, normal_loading=loading_mode, max_stick_change=max_stick_change)
    return _programme.result(normal, topography, record, parameters, loading=loading)
