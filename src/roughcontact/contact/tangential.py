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

Assumptions, stated: the normal loading that precedes the programme is frictionless (the slip
the pressure causes then is free; history starts at the first tangential step); points that
come into contact during a step stick where they are unless the Coulomb law makes them slip;
the friction coefficient is constant (no static/kinetic distinction, as in the paper).

References
----------
Mindlin, R. D. and Deresiewicz, H. (1953). J. Appl. Mech. 20, 327-344.
Chen, W. W. and Wang, Q. J. (2008). J. Tribol. 130, 041402 (coupled partial slip by FFT).
Bazrafshan, M., de Rooij, M. B. and Schipper, D. J. (2019). Int. J. Mech. Sci. 155, 9-18 (paper 001 ref. 28).
Seed paper 001, eqs. 1-4.
"""

from __future__ import annotations

import numbers
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .._version import __version__
from ..elasticity.halfspace import SurfaceCompliance
from ..elasticity.tangential import TractionCompliance
from ..errors import ConvergenceError, InputError
from ..materials import Material, contact_modulus
from ..progress import tracked
from . import _constrained_cg, _shear_apg, _shear_cg
from .normal import compliance_for
from .paths import as_path
from .result import NormalContactResult
from .tangential_result import TangentialPathResult, TangentialState

# Iterations the plain method gets under precondition="auto" before the preconditioned retry.
PLAIN_ITERATIONS = 500
METHODS = ("auto", "cg", "apg")


def _check_inputs(normal, material, counter_body, friction_coefficient):
    if not isinstance(normal, NormalContactResult):
        raise InputError("normal", f"got {type(normal).__name__}.", "pass the result of solve_normal.")
    if normal.hardness is not None:
        raise InputError("normal", "the normal contact is elastic-plastic.", "solve it without hardness.")
    if not isinstance(material, Material):
        raise InputError("material", "a Material is needed (shear moduli and Poisson's ratios).", None)
    mu = friction_coefficient
    if not (isinstance(mu, numbers.Real) and np.isfinite(mu) and mu > 0):
        raise InputError("friction_coefficient", f"must be positive and finite, got {mu!r}.", "e.g. 0.15.")
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


def _steps_to_keep(fields_at, steps: int) -> set[int]:
    if isinstance(fields_at, str):
        if fields_at not in ("all", "none", "last"):
            raise InputError("fields_at", f"unknown {fields_at!r}.", "use 'all', 'none', 'last' or indices.")
        return {"all": set(range(steps)), "none": set(), "last": {steps - 1}}[fields_at]
    fix = f"give step indices in [-{steps}, {steps - 1}], or 'all', 'none', 'last'."
    if not isinstance(fields_at, Sequence | np.ndarray):
        raise InputError("fields_at", f"got {fields_at!r}.", fix)
    keep = set()
    for index in fields_at:
        if not isinstance(index, numbers.Integral) or isinstance(index, bool) or not -steps <= index < steps:
            raise InputError("fields_at", f"{index!r} is not a step index of a {steps}-step path.", fix)
        keep.add(int(index) % steps)
    return keep


def solve_tangential(
    normal: NormalContactResult,
    material: Material,
    *,
    friction_coefficient: float,
    displacement=None,
    force=None,
    counter_body: Material | None = None,
    coupling: bool = True,
    tolerance: float = 1e-8,
    coupling_tolerance: float = 1e-6,
    max_iterations: int = 10_000,
    max_coupling_iterations: int = 50,
    fields_at: str | Sequence[int] = "all",
    precondition: bool | str = "auto",
    workers: int | None = None,
    method: str = "auto",
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
        tangential force on the rough body [N] (force control: |F| must stay below mu F_0).
        A periodic surface needs force control: the mean tangential displacement of a periodic
        half-space is undetermined.
    counter_body : Material, optional
        The flat (default: rigid). Paper 001: silicon wafer.
    coupling : bool
        Iterate the normal-tangential coupling of dissimilar materials (default; see the module
        docstring). False gives the uncoupled (Goodman) solution.
    tolerance : float
        Scale-free residual of each tangential increment (and of the coupled normal solves).
    coupling_tolerance : float
        Relative change of p and q between coupling passes that ends a step.
    max_iterations, max_coupling_iterations : int
        Limits; beyond them :class:`~roughcontact.errors.ConvergenceError` is raised.
    fields_at : {"all", "last", "none"} or sequence of int
        Steps whose full fields are kept in ``states`` (per-step scalars are always kept).
    precondition : {"auto", True, False}
        True builds the conjugate directions from the Fourier-inverse preconditioned gradient
        (two more FFT pairs per iteration); False gives the plain projected conjugate
        gradients. "auto" (default) runs the plain method with at most
        ``PLAIN_ITERATIONS`` iterations and, if it has not converged, solves the increment
        again preconditioned. Measured: on a rough ball (sparse contact) the plain method is
        3-8x faster; near full sliding on a smooth sphere it can stall where the
        preconditioned one converges. Applies to ``method="cg"``; ``method="apg"`` takes
        "auto" or False and refuses True.
    workers : int, optional
        FFT threads.
    method : {"auto", "cg", "apg"}
        Increment solver; both solve the same programme to the same residual. "cg":
        Polonsky-Keer's projected conjugate gradients on the discs
        (:mod:`~roughcontact.contact._shear_cg`). "apg": accelerated projected gradients with
        constant momentum and adaptive restart (:mod:`~roughcontact.contact._shear_apg`), one
        operator application per iteration and a rate that does not depend on the slip
        directions staying fixed. "auto" (default): "apg" when a body has nu > 0 (the Cerruti
        kernel couples x and y, B = sum nu_i/G_i > 0, and slipping points turn), else "cg" (and
        "cg" whenever ``precondition=True``). Measured (``benchmarks/tangential_apg.py``): for
        nu = 0.5 apg is 48-146x faster on a rough ball and a smooth sphere at 128^2 and 7-13x on
        paper 001's balls; for nu = 0 cg is 2-4x faster.

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
    _check_inputs(normal, material, counter_body, friction_coefficient)
    if method not in METHODS:
        raise InputError("method", f"unknown increment solver {method!r}.", "use 'auto', 'cg' or 'apg'.")
    if method == "apg" and precondition is True:
        raise InputError(
            "precondition",
            "the accelerated projected-gradient solver (method='apg') takes no Fourier preconditioner.",
            "use precondition='auto' or False with method='apg', or method='cg'.",
        )
    if (displacement is None) == (force is None):
        raise InputError(
            "path", "give exactly one of displacement and force.", "e.g. displacement=stroke_path(3e-6)."
        )
    load_control = force is not None
    path = as_path(force if load_control else displacement, "force" if load_control else "displacement")
    if normal.boundary == "periodic" and not load_control:
        raise InputError(
            "displacement",
            "a periodic half-space has no fixed point, so a rigid tangential displacement loads nothing.",
            "prescribe a force path (force=...), or solve a free (non-periodic) window.",
        )
    mu = float(friction_coefficient)
    topography = normal.topography
    shape = topography.shape
    operator = TractionCompliance(
        shape, topography.size, material, counter_body, boundary=normal.boundary, workers=workers
    )
    coupled = coupling and operator.coupled
    pixel_area = operator.pixel_area
    keep = _steps_to_keep(fields_at, len(path))
    if method == "auto":
        method = "apg" if operator.pair.B > 0 and precondition is not True else "cg"
    # method="apg": the kernel's smallest eigenvalue bounds the strong convexity (constant momentum)
    apg = {"strong_convexity": _shear_apg.kernel_extremes(operator)[0]} if method == "apg" else None

    pressure = np.array(normal.pressure)
    heights = topography.heights
    separation = heights.max() - heights
    normal_force = normal.force
    normal_operator = (
        compliance_for(
            topography, material, counter_body=counter_body, boundary=normal.boundary, workers=workers
        )
        if coupled
        else None
    )
    slip_from_p = operator.slip_from_pressure(pressure) if coupled else (np.zeros(shape), np.zeros(shape))
    slip_x, slip_y = slip_from_p[0].copy(), slip_from_p[1].copy()  # frictionless normal loading
    qx, qy = np.zeros(shape), np.zeros(shape)

    n = len(path)
    record = {k: np.zeros(n) for k in ("contact", "stick", "slip", "residual")}
    forces = np.zeros((n, 2))
    displacements = np.zeros((n, 2))
    iterations = np.zeros(n, dtype=int)
    passes = np.zeros(n, dtype=int)
    states: dict[int, TangentialState] = {}
    stepper = _Stepper(
        operator=operator,
        normal_operator=normal_operator,
        separation=separation,
        normal_force=normal_force,
        mu=mu,
        tolerance=tolerance,
        coupling_tolerance=coupling_tolerance,
        max_iterations=max_iterations,
        max_passes=max_coupling_iterations,
        preconditioner=_preconditioning(precondition, operator) if apg is None else None,
        apg=apg,
    )
    for step, target in enumerate(tracked(path, what="tangential steps")):
        control = {"force": tuple(target)} if load_control else {"displacement": tuple(target)}
        pressure, slip_from_p, increment, iterations[step], passes[step] = stepper.step(
            pressure, slip_from_p, (qx, qy), (slip_x, slip_y), control
        )
        qx, qy = increment.qx, increment.qy
        contact = pressure > 0
        wx = np.where(contact, increment.wx, 0.0)
        wy = np.where(contact, increment.wy, 0.0)
        slip_x, slip_y = slip_x + increment.wx, slip_y + increment.wy
        stick = increment.stick & contact
        displacements[step] = increment.delta
        forces[step] = (qx.sum() * pixel_area, qy.sum() * pixel_area)
        record["contact"][step] = contact.sum() * pixel_area
        record["stick"][step] = stick.sum() * pixel_area
        record["slip"][step] = (contact & ~stick).sum() * pixel_area
        record["residual"][step] = increment.residual
        if step in keep:
            states[step] = TangentialState(
                shear_x=qx.copy(),
                shear_y=qy.copy(),
                pressure=pressure.copy(),
                slip_x=slip_x.copy(),
                slip_y=slip_y.copy(),
                slip_increment_x=wx,
                slip_increment_y=wy,
                stick=stick,
                displacement=increment.delta,
                friction_coefficient=mu,
                pixel_area=pixel_area,
            )
    return TangentialPathResult(
        normal=normal,
        displacement=displacements,
        force=forces,
        contact_area=record["contact"],
        stick_area=record["stick"],
        slip_area=record["slip"],
        iterations=iterations,
        coupling_iterations=passes,
        residual=record["residual"],
        states=states,
        parameters={
            "friction_coefficient": mu,
            "control": "force" if load_control else "displacement",
            "coupling": bool(coupling),
            "dundurs_beta": operator.pair.dundurs_beta,
            "tolerance": tolerance,
            "precondition": precondition,
            "method": method,
            "version": __version__,
        },
    )


def _preconditioning(precondition, operator):
    """(first preconditioner, fallback) of the ``precondition`` option: None means plain."""
    if precondition == "auto":
        return None, operator.inverse_shear
    if precondition is True or precondition is False:
        return (operator.inverse_shear if precondition else None), None
    raise InputError("precondition", f"got {precondition!r}.", "use 'auto', True or False.")


@dataclass(frozen=True)
class _Stepper:
    """Solves the steps of one path: what stays fixed along it, and one method per part of a step.

    ``normal_operator`` is None when uncoupled (one pass per step). ``apg`` (the options of
    :func:`_shear_apg.solve_increment <roughcontact.contact._shear_apg.solve_increment>`)
    selects the accelerated projected-gradient solver; otherwise ``preconditioner`` is the
    conjugate gradients' (first, fallback) pair of :func:`_preconditioning`.
    """

    operator: TractionCompliance
    normal_operator: SurfaceCompliance | None
    separation: np.ndarray
    normal_force: float
    mu: float
    tolerance: float
    coupling_tolerance: float
    max_iterations: int
    max_passes: int
    preconditioner: tuple | None
    apg: dict | None

    def step(self, pressure, slip_from_p, shear, slip, control):
        """One step: the tangential increment, alternated with normal solves when coupled.

        Returns the pressure, the slip it causes, the increment, the iterations and the passes.
        """
        qx, qy = shear
        iterations = 0
        for coupling_pass in range(1, self.max_passes + 1):
            previous_p, previous_q = pressure, (qx, qy)
            if self.normal_operator is not None and (np.any(qx) or np.any(qy)):
                pressure = self.coupled_pressure(qx, qy, pressure)
                slip_from_p = self.operator.slip_from_pressure(pressure)
            offset = (slip_from_p[0] - slip[0], slip_from_p[1] - slip[1])
            increment, used = self.increment(pressure, offset, (qx, qy), control)
            qx, qy = increment.qx, increment.qy
            iterations += used
            if self.normal_operator is None:
                return pressure, slip_from_p, increment, iterations, coupling_pass
            scale_p = max(float(np.max(pressure)), 1e-300)
            change = max(
                float(np.max(np.abs(pressure - previous_p))) / scale_p,
                float(np.max(np.abs(qx - previous_q[0]) + np.abs(qy - previous_q[1]))) / (self.mu * scale_p),
            )
            if change <= self.coupling_tolerance:
                return pressure, slip_from_p, increment, iterations, coupling_pass
        raise ConvergenceError(
            "solve_tangential (normal-tangential coupling)", change, self.max_passes, self.coupling_tolerance
        )

    def increment(self, pressure, offset, initial, control):
        """Return the increment at fixed pressure and its iterations (a failed plain run's included)."""
        operator = self.operator
        arguments = dict(pixel_area=operator.pixel_area, initial=initial, tolerance=self.tolerance, **control)
        bound = self.mu * pressure
        if self.apg is not None:
            increment = _shear_apg.solve_increment(
                operator.shear, bound, offset, max_iterations=self.max_iterations, **arguments, **self.apg
            )
            return increment, increment.iterations

        def conjugate_gradients(preconditioner, budget):
            return _shear_cg.solve_increment(
                operator.shear,
                operator.shear_energy,
                bound,
                offset,
                max_iterations=budget,
                preconditioner=preconditioner,
                **arguments,
            )

        first, fallback = self.preconditioner
        if fallback is None:
            increment = conjugate_gradients(first, self.max_iterations)
            return increment, increment.iterations
        budget = min(self.max_iterations, PLAIN_ITERATIONS)
        try:
            increment = conjugate_gradients(first, budget)
            return increment, increment.iterations
        except ConvergenceError:
            increment = conjugate_gradients(fallback, self.max_iterations)
            return increment, budget + increment.iterations

    def coupled_pressure(self, qx, qy, pressure):
        """Pressure at F_0 with the normal displacement of the shear tractions added to the separation."""
        shifted = self.separation + self.operator.normal_from_shear(qx, qy)
        shifted -= shifted.min()
        raw = _constrained_cg.solve(
            self.normal_operator,
            shifted,
            pixel_area=self.operator.pixel_area,
            force=self.normal_force,
            initial_pressure=pressure,
            tolerance=self.tolerance,
            max_iterations=self.max_iterations,
            solver="solve_tangential (coupled normal step)",
        )
        return raw.pressure
