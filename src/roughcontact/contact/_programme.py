r"""The incremental frictional stepper and the programme driver shared by the frictional solvers.

One step takes the state of the previous step (pressure, shear tractions, the accumulated relative
tangential displacement s and the slip the pressure causes) to a prescribed normal target (force
or approach) and tangential target (force or rigid displacement). With Dundurs' beta != 0 and
``coupling`` the two problems are solved together by block Gauss-Seidel passes:

1. the normal contact at the step's target with the separation h_0 + u_z(q) (the gap the shear
   tractions open, :meth:`~roughcontact.elasticity.tangential.TractionCompliance.normal_from_shear`);
2. the tangential increment at the bound mu p of the new pressure, under the local Coulomb law of
   paper 001 eq. 3, with the known field e = s_p(p) - s_old (the slip the pressure causes, minus
   the relative displacement reached at the previous step: increments, not totals);

until p and q change by less than ``coupling_tolerance`` of their maxima between passes. Without
coupling (Goodman's approximation, or beta = 0 where the coupling terms vanish) one normal solve
(skipped when the normal target did not move) and one tangential increment make a step.

The driver (:func:`run`) walks the user's programme points and, with ``max_stick_change``, inserts
steps where the stick fraction (stick area / contact area) would fall by more than that amount in
one step: the step is retried over a shorter part of the segment towards the same programme point
(adaptive step control, the user's points are always solved exactly). A rising stick fraction is
not refined (points stick again at once, whatever the step), but a step that reverses the
direction of the normal or tangential move starts from a stick fraction of 1: right after a
reversal every point sticks. After a reversal the stick fraction falls from 1 to 0 at full slip,
so ``max_stick_change = 0.1`` puts at least 10 steps between a reversal and full slip; for
Cattaneo-Mindlin the stick area falls linearly with the displacement, so the inserted steps come
out nearly evenly spaced.

References
----------
Chen, W. W. and Wang, Q. J. (2008). J. Tribol. 130, 041402 (coupled partial slip by FFT).
Spence, D. A. (1975). J. Elasticity 5, 297-319 (frictional normal loading).
Mindlin, R. D. and Deresiewicz, H. (1953). J. Appl. Mech. 20, 327-344 (load histories).
Seed paper 001, eqs. 1-4.
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from functools import cached_property, partial

import numpy as np

from .._version import __version__
from ..elasticity.tangential import TractionCompliance
from ..errors import ConvergenceError, InputError
from ..progress import tracked
from . import _box, _constrained_cg, _shear_apg, _shear_cg
from .normal import compliance_for
from .paths import as_path
from .tangential_result import TangentialPathResult, TangentialState

# Iterations the plain method gets under precondition="auto" before the preconditioned retry.
PLAIN_ITERATIONS = 500
# Shortest inserted step, as a fraction of the user's segment (step control stops refining there).
SHORTEST_STEP = 1.0 / 256


@dataclass(frozen=True)
class State:
    """The converged state after a step: what the next step starts from (SI, on the grid).

    ``slip`` is the accumulated relative tangential displacement s = C q + s_p(p) - delta of
    every point (in contact or not: a point that touches later sticks where it is then);
    ``slip_from_pressure`` the part s_p(p) the pressure causes (zero when uncoupled); ``normal``
    the normal target that was met, (control, value).
    """

    pressure: np.ndarray
    shear: tuple[np.ndarray, np.ndarray]
    slip: tuple[np.ndarray, np.ndarray]
    slip_from_pressure: tuple[np.ndarray, np.ndarray]
    approach: float
    normal: tuple[str, float] | None

    @classmethod
    def unloaded(cls, shape) -> State:
        """No load and no history: the bodies just touch."""
        zero = np.zeros(shape)
        return cls(zero, (zero, zero), (zero, zero), (zero, zero), 0.0, None)


class ContactLost(Exception):
    """The normal target of a step leaves no contact."""


@dataclass(frozen=True)
class Step:
    """A converged step: the new state, the increment's results and the solver effort."""

    state: State
    increment: object  # _shear_cg.ShearResult (same fields for _shear_apg)
    iterations: int
    passes: int


@dataclass
class Stepper:
    """Solves the steps of one programme: what stays fixed along it, and one method per part of a step.

    Attributes
    ----------
    operator : TractionCompliance
        Tangential (and coupling) compliance of the pair.
    build_normal_operator : callable
        Returns the surface compliance of the normal problem (called on first use).
    separation : ndarray
        h_0 = max(h) - h [m].
    mu : float
    coupled : bool
        Alternate normal and tangential solves (beta != 0 and coupling asked for).
    tolerance, coupling_tolerance, max_iterations, max_passes
        Of the increments, the coupling passes and their limits.
    precondition : {"auto", True, False} or None
        The conjugate gradients' ``precondition`` option (:func:`preconditioning`); None selects
        ``apg``.
    apg : dict or None
        Options of :func:`_shear_apg.solve_increment` (the accelerated projected gradients).
    name : str
        The public solver, named in convergence messages.
    """

    operator: TractionCompliance
    build_normal_operator: Callable[[], object]
    separation: np.ndarray
    mu: float
    coupled: bool
    tolerance: float
    coupling_tolerance: float
    max_iterations: int
    max_passes: int
    precondition: object
    apg: dict | None
    name: str = "solve_tangential"
    box: tuple[slice, slice] | None = field(default=None, init=False)

    @cached_property
    def normal_operator(self):
        """The normal problem's compliance (built when a step first needs a normal solve)."""
        return self.build_normal_operator()

    def step(self, state: State, normal: tuple[str, float], tangential: dict) -> Step:
        """Take ``state`` to the normal target ``normal`` and the tangential control ``tangential``.

        At a held normal target on a free surface the coupling passes run on the box around the
        contact (``box`` of :meth:`normal_solve` and :meth:`slip_from_pressure`); once they
        converge, the whole grid's normal solve checks the pressure (no iteration unless a point
        outside the box overlaps, and then the passes go on over the whole grid) and s_p(p) is
        formed on the whole grid for the state.

        Raises :class:`ContactLost` when the normal target leaves no contact.
        """
        pressure, slip_from_p, (qx, qy) = state.pressure, state.slip_from_pressure, state.shear
        approach = state.approach
        moved = normal != state.normal
        on_box = not moved and self.operator.boundary == "free"
        iterations = 0
        for coupling_pass in range(1, self.max_passes + 1):
            previous_p, previous_q = pressure, (qx, qy)
            sheared = self.coupled and (np.any(qx) or np.any(qy))
            box = _box.contact_box(pressure > 0, self.box) if on_box and sheared else None
            if box is not None:
                self.box = box
            if (coupling_pass == 1 and moved) or sheared:
                pressure, approach, _ = self.normal_solve(
                    (qx, qy) if sheared else None, pressure, normal, box
                )
                if self.coupled:
                    slip_from_p = self.slip_from_pressure(pressure, box)
            if not np.any(pressure > 0):
                raise ContactLost
            offset = (slip_from_p[0] - state.slip[0], slip_from_p[1] - state.slip[1])
            increment, used = self.increment(pressure, offset, (qx, qy), tangential)
            qx, qy = increment.qx, increment.qy
            iterations += used
            change = 0.0
            if self.coupled:
                scale_p = max(float(np.max(pressure)), 1e-300)
                change = max(
                    float(np.max(np.abs(pressure - previous_p))) / scale_p,
                    float(np.max(np.abs(qx - previous_q[0]) + np.abs(qy - previous_q[1])))
                    / (self.mu * scale_p),
                )
            if change > self.coupling_tolerance:
                continue
            if box is not None:  # the passes converged on the box: the whole grid's check
                checked, approach, iterated = self.normal_solve(previous_q, pressure, normal)
                if iterated:  # a point outside the box overlaps: go on over the whole grid
                    pressure, on_box = checked, False
                    continue
                slip_from_p = self.slip_from_pressure(pressure)
                offset = (slip_from_p[0] - state.slip[0], slip_from_p[1] - state.slip[1])
            increment = self.with_slip(increment, offset)
            new = State(
                pressure,
                (qx, qy),
                (state.slip[0] + increment.wx, state.slip[1] + increment.wy),
                slip_from_p,
                approach,
                normal,
            )
            return Step(new, increment, iterations, coupling_pass)
        raise ConvergenceError(
            f"{self.name} (normal-tangential coupling)", change, self.max_passes, self.coupling_tolerance
        )

    def normal_solve(self, shear, pressure, normal, box=None):
        """Return the pressure, approach and iterations at the normal target, with u_z(q) of ``shear``.

        The approach is the rigid approach of the flat from first touch of the undeformed surface.
        With ``box`` the problem is solved on the box alone, with its own operators (exact there:
        q vanishes outside it, :func:`~roughcontact.elasticity.kernels.sub_grid_operator`); the
        pressure is 0 outside the box until :meth:`step` checks the answer on the whole grid.
        """
        region = (slice(None), slice(None)) if box is None else box
        compliance, traction = self.normal_operator, self.operator
        if box is not None:
            shape = _box.shape_of(box)
            compliance, traction = compliance.window(shape), traction.window(shape)
        separation, offset = self.separation[region], 0.0
        if shear is not None:
            separation = separation + traction.normal_from_shear(shear[0][region], shear[1][region])
            offset = float(separation.min())
            separation -= offset
        control, value = normal
        initial = pressure[region]
        raw = _constrained_cg.solve(
            compliance,
            separation,
            pixel_area=self.operator.pixel_area,
            initial_pressure=initial if np.any(initial > 0) else None,
            tolerance=self.tolerance,
            max_iterations=self.max_iterations,
            solver=f"{self.name} (normal contact)",
            **({"force": value} if control == "force" else {"approach": value - offset}),
        )
        solved = raw.pressure
        if box is not None:
            solved = np.zeros(pressure.shape)
            solved[box] = raw.pressure
        return solved, raw.approach + offset, raw.iterations

    def slip_from_pressure(self, pressure, box=None):
        """Return s_p(p) on the whole grid, or with ``box``'s own operator (0 outside the box)."""
        if box is None:
            return self.operator.slip_from_pressure(pressure)
        sx, sy = np.zeros(pressure.shape), np.zeros(pressure.shape)
        sx[box], sy[box] = self.operator.window(_box.shape_of(box)).slip_from_pressure(pressure[box])
        return sx, sy

    def increment(self, pressure, offset, initial, control):
        """Return the tangential increment at fixed pressure and its iterations (a failed plain try's too).

        On a free surface the increment is solved on a box around the contact
        (:func:`~roughcontact.contact._box.contact_box`, :meth:`TractionCompliance.window`: the
        same problem, since q vanishes outside the contact); its slip increment w is then left
        None until :meth:`with_slip` forms it on the whole grid, once for the converged coupling
        pass.
        """
        box = None
        if self.operator.boundary == "free":
            box = self.box = _box.contact_box(pressure > 0, self.box)
        if box is None:
            return self._increment(self.operator, pressure, offset, initial, control)
        operator = self.operator.window(_box.shape_of(box))
        increment, used = self._increment(
            operator,
            pressure[box],
            (offset[0][box], offset[1][box]),
            (initial[0][box], initial[1][box]),
            control,
        )
        qx, qy, stick = (
            np.zeros(pressure.shape),
            np.zeros(pressure.shape),
            np.zeros(pressure.shape, dtype=bool),
        )
        qx[box], qy[box], stick[box] = increment.qx, increment.qy, increment.stick
        return replace(increment, qx=qx, qy=qy, wx=None, wy=None, stick=stick), used

    def with_slip(self, increment, offset):
        """Return ``increment`` with its slip increment w = C q + e - delta on the whole grid.

        An increment solved on a box has none yet (:meth:`increment`): w is formed from its
        tractions by one application of the whole grid's operator (the next steps need it where
        points may touch later).
        """
        if increment.wx is not None:
            return increment
        wx, wy = self.operator.shear(increment.qx, increment.qy)
        wx += offset[0] - increment.delta[0]
        wy += offset[1] - increment.delta[1]
        return replace(increment, wx=wx, wy=wy)

    def _increment(self, operator, pressure, offset, initial, control):
        """:meth:`increment` with ``operator`` on the grid of its arguments."""
        arguments = dict(
            pixel_area=operator.pixel_area,
            initial=initial,
            tolerance=self.tolerance,
            solver=self.name,
            **control,
        )
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

        first, fallback = preconditioning(self.precondition, operator)
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


def preconditioning(precondition, operator):
    """(first preconditioner, fallback) of the ``precondition`` option: None means plain."""
    if precondition == "auto":
        return None, operator.inverse_shear
    if precondition is True or precondition is False:
        return (operator.inverse_shear if precondition else None), None
    raise InputError("precondition", f"got {precondition!r}.", "use 'auto', True or False.")


def check_max_stick_change(value) -> None:
    """Refuse a ``max_stick_change`` outside (0, 1) (None turns the step control off)."""
    if value is not None and not (isinstance(value, float | int) and 0 < value < 1):
        raise InputError(
            "max_stick_change",
            f"got {value!r}.",
            "give a fraction in (0, 1), e.g. 0.1, or None (no step control).",
        )


@dataclass
class Record:
    """Per-step series of a programme, filled by :func:`run` (SI; named as the result's fields)."""

    normal_load: list
    approach: list
    displacement: list
    force: list
    contact_area: list
    stick_area: list
    slip_area: list
    dissipation: list
    iterations: list
    coupling_iterations: list
    residual: list
    programme_index: list
    states: dict

    @classmethod
    def empty(cls) -> Record:
        return cls(*([] for _ in range(12)), {})

    def arrays(self) -> dict:
        """Return the series as arrays (the keyword arguments of the result)."""
        out = {
            name: np.asarray(getattr(self, name)) for name in self.__dataclass_fields__ if name != "states"
        }
        out["displacement"] = out["displacement"].reshape(-1, 2)
        out["force"] = out["force"].reshape(-1, 2)
        out["iterations"] = out["iterations"].astype(int)
        out["coupling_iterations"] = out["coupling_iterations"].astype(int)
        out["states"] = self.states
        return out


def run(
    stepper: Stepper,
    state: State,
    normal: tuple[str, np.ndarray],
    tangential: tuple[str, np.ndarray],
    *,
    start: tuple[float, np.ndarray],
    keep: set[int],
    max_stick_change: float | None = None,
    stick_fraction: float = np.nan,
    what: str = "tangential steps",
) -> tuple[Record, State]:
    """Solve a programme of user points from ``state``; return its record and the final state.

    Parameters
    ----------
    stepper : Stepper
    state : State
        Where the programme starts.
    normal : (control, (n,) array)
        "force" [N] or "approach" [m] of each programme point.
    tangential : (control, (n, 2) array)
        "force" [N] or "displacement" [m] of each programme point.
    start : (float, (2,) array)
        The programme's values at ``state`` (the first segment starts there).
    keep : set of int
        Programme points whose fields are kept; steps inserted before a kept point are kept when
        the point before it is kept too (or it is the first).
    max_stick_change : float, optional
        Step control (module docstring); None solves the programme points only.
    stick_fraction : float
        Stick fraction of ``state`` (1 after a frictionless normal loading; NaN when unloaded).
    what : str
        Names the steps in the progress bar.
    """
    normal_control, normal_values = normal
    tangential_control, tangential_values = tangential
    record = Record.empty()
    previous = (float(start[0]), np.asarray(start[1], dtype=float))
    reached, last_move = previous, None  # the targets of the last step, and that step's move
    for index in tracked(range(len(normal_values)), what=what):
        target = (float(normal_values[index]), np.asarray(tangential_values[index], dtype=float))
        done, length = 0.0, 1.0
        while done < 1.0:
            length = min(length, 1.0 - done)
            if 1.0 - done - length < 0.3 * length:  # no sliver of a step before the programme point
                length = 1.0 - done
            fraction = done + length
            at_point = fraction >= 1.0
            point = (
                target
                if at_point
                else tuple(a + fraction * (b - a) for a, b in zip(previous, target, strict=True))
            )
            try:
                step = stepper.step(
                    state,
                    (normal_control, float(point[0])),
                    {tangential_control: tuple(map(float, point[1]))},
                )
            except InputError as error:  # e.g. a tangential force at or above mu F_n: name the row
                if error.field != "force":
                    raise
                raise InputError("force", f"programme step {index}: {error.problem}", error.fix) from None
            except ContactLost:
                raise InputError(
                    normal_control,
                    f"programme step {index}: at the normal {normal_control} {point[0]:.6g} (SI) nothing "
                    "is in contact.",
                    "keep the normal force above zero (and the approach above first touch) at every step; "
                    "a programme that separates the bodies ends there.",
                ) from None
            contact = step.state.pressure > 0
            stick = step.increment.stick & contact
            fraction_now = stick.sum() / contact.sum() if contact.any() else np.nan
            # Only a shrinking stick zone is refined (re-sticking happens at once); after a reversal
            # every point sticks first, so the fraction falls from 1 within the step.
            move = (point[0] - reached[0], point[1] - reached[1])
            before = 1.0 if _reverses(move, last_move) else stick_fraction
            change = max(before - fraction_now, 0.0) if np.isfinite(before) else 0.0
            if max_stick_change is not None and change > max_stick_change and length > SHORTEST_STEP:
                length = max(length * min(0.5, 0.8 * max_stick_change / change), SHORTEST_STEP)
                continue
            _append(record, step, contact, stick, stepper, index, keep, at_point)
            state, stick_fraction, done = step.state, fraction_now, fraction
            reached, last_move = point, move
            if max_stick_change is not None:
                length *= min(2.0, 0.8 * max_stick_change / max(change, 1e-3))
        previous = target
    return record, state


def _reverses(move, last_move) -> bool:
    """Return True when ``move`` (normal, tangential increments) turns back against ``last_move``."""
    if last_move is None:
        return False
    return bool(move[0] * last_move[0] < 0 or np.dot(move[1], last_move[1]) < 0)


def _append(record: Record, step: Step, contact, stick, stepper, index, keep, at_point):
    """Add one converged step to ``record`` (its fields too when kept)."""
    pixel_area = stepper.operator.pixel_area
    state, increment = step.state, step.increment
    qx, qy = state.shear
    wx = np.where(contact, increment.wx, 0.0)
    wy = np.where(contact, increment.wy, 0.0)
    record.normal_load.append(float(state.pressure.sum() * pixel_area))
    record.approach.append(state.approach)
    record.displacement.append(tuple(increment.delta))
    record.force.append((float(qx.sum() * pixel_area), float(qy.sum() * pixel_area)))
    record.contact_area.append(float(contact.sum() * pixel_area))
    record.stick_area.append(float(stick.sum() * pixel_area))
    record.slip_area.append(float((contact & ~stick).sum() * pixel_area))
    # Frictional work of the step: -sum q.w A >= 0 (the slip increment opposes the traction).
    record.dissipation.append(max(-float(np.sum(qx * wx + qy * wy)) * pixel_area, 0.0))
    record.iterations.append(step.iterations)
    record.coupling_iterations.append(step.passes)
    record.residual.append(increment.residual)
    record.programme_index.append(index)
    kept = index in keep and (at_point or index == 0 or index - 1 in keep)
    if kept:
        record.states[len(record.residual) - 1] = TangentialState(
            shear_x=qx.copy(),
            shear_y=qy.copy(),
            pressure=state.pressure.copy(),
            slip_x=state.slip[0].copy(),
            slip_y=state.slip[1].copy(),
            slip_increment_x=wx,
            slip_increment_y=wy,
            stick=stick,
            displacement=tuple(increment.delta),
            friction_coefficient=stepper.mu,
            pixel_area=pixel_area,
        )


def frictionless_start(stepper: Stepper, pressure, approach, force) -> State:
    """Return the state after a frictionless loading to ``force`` (Goodman's start): q = 0, s = s_p(p)."""
    operator = stepper.operator
    zero = np.zeros(operator.shape)
    slip_from_p = operator.slip_from_pressure(pressure) if stepper.coupled else (zero, zero)
    return replace(
        State.unloaded(operator.shape),
        pressure=np.array(pressure),
        slip=(slip_from_p[0].copy(), slip_from_p[1].copy()),
        slip_from_pressure=slip_from_p,
        approach=float(approach),
        normal=("force", float(force)),
    )


METHODS = ("auto", "cg", "apg")


def build(
    topography,
    material,
    counter_body,
    *,
    boundary,
    friction_coefficient,
    coupling,
    solver,
    name="solve_tangential",
) -> tuple[Stepper, dict]:
    """Check the solver options and build the stepper of a programme; return it and the parameters.

    ``method="auto"`` picks "apg" when a body has nu > 0 (the Cerruti kernel couples x and y and
    slipping points turn), else "cg" (see :func:`~roughcontact.contact.tangential.solve_tangential`).
    """
    mu = friction_coefficient
    tolerance, method, precondition, workers = (
        solver.tolerance,
        solver.method,
        solver.precondition,
        solver.workers,
    )
    if not (isinstance(mu, numbers.Real) and np.isfinite(mu) and mu > 0):
        raise InputError("friction_coefficient", f"must be positive and finite, got {mu!r}.", "e.g. 0.15.")
    if method not in METHODS:
        raise InputError("method", f"unknown increment solver {method!r}.", "use 'auto', 'cg' or 'apg'.")
    if method == "apg" and precondition is True:
        raise InputError(
            "precondition",
            "the accelerated projected-gradient solver (method='apg') takes no Fourier preconditioner.",
            "use precondition='auto' or False with method='apg', or method='cg'.",
        )
    operator = TractionCompliance(
        topography.shape, topography.size, material, counter_body, boundary=boundary, workers=workers
    )
    if method == "auto":
        method = "apg" if operator.pair.B > 0 and precondition is not True else "cg"
    # method="apg": the kernel's smallest eigenvalue bounds the strong convexity (constant momentum)
    apg = {"strong_convexity": _shear_apg.kernel_extremes(operator)[0]} if method == "apg" else None
    if apg is None:
        preconditioning(precondition, operator)  # refuses an unknown option before the first step
    stepper = Stepper(
        operator,
        partial(
            compliance_for,
            topography,
            material,
            counter_body=counter_body,
            boundary=boundary,
            workers=workers,
        ),
        topography.heights.max() - topography.heights,
        mu=float(mu),
        coupled=bool(coupling) and operator.coupled,
        tolerance=tolerance,
        coupling_tolerance=solver.coupling_tolerance,
        max_iterations=solver.max_iterations,
        max_passes=solver.max_coupling_iterations,
        precondition=precondition if apg is None else None,
        apg=apg,
        name=name,
    )
    parameters = {
        "friction_coefficient": float(mu),
        "coupling": bool(coupling),
        "dundurs_beta": operator.pair.dundurs_beta,
        "tolerance": tolerance,
        "precondition": precondition,
        "method": method,
        "version": __version__,
    }
    return stepper, parameters


def tangential_programme(displacement, force, boundary) -> tuple[str, np.ndarray]:
    """Return (control, (n, 2) path) of the tangential ``displacement`` or ``force`` (exactly one)."""
    if (displacement is None) == (force is None):
        raise InputError(
            "path", "give exactly one of displacement and force.", "e.g. displacement=stroke_path(3e-6)."
        )
    control = "force" if force is not None else "displacement"
    path = as_path(force if force is not None else displacement, control)
    if boundary == "periodic" and control == "displacement":
        raise InputError(
            "displacement",
            "a periodic half-space has no fixed point, so a rigid tangential displacement loads nothing.",
            "prescribe a force path (force=...), or solve a free (non-periodic) window.",
        )
    return control, path


def steps_to_keep(fields_at, steps: int) -> set[int]:
    """Return the programme points whose fields ``fields_at`` keeps ("all", "none", "last" or indices)."""
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


def result(normal, topography, record: Record, parameters: dict, loading=None) -> TangentialPathResult:
    """Return the programme's :class:`TangentialPathResult` from its record."""
    return TangentialPathResult(
        normal=normal, topography=topography, loading=loading, parameters=parameters, **record.arrays()
    )
