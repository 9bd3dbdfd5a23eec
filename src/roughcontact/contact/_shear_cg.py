r"""Constrained conjugate gradients for one increment of partial-slip tangential contact.

At a fixed pressure p the shear tractions q = (q_x, q_y) of one load step solve (paper 001 eq. 3)

.. math::

    w = C q + e - \delta, \qquad |q_i| \le c_i = \mu p_i, \qquad
    w_i = 0 \text{ where } |q_i| < c_i \;(\text{stick}), \qquad
    w_i = -\lambda_i q_i,\ \lambda_i \ge 0 \text{ where } |q_i| = c_i \;(\text{slip})

with C the tangential compliance of the pair, w the slip increment of the step, e a known field
(the previous step's slip with the sign reversed, plus the slip the pressure causes when normal
and tangential problems are coupled) and delta the rigid tangential displacement of the flat,
given (displacement control) or the Lagrange multiplier of the total force sum(q) A_px = F
(force control). These are the optimality conditions of the convex problem
min 1/2 q.Cq + q.(e - delta) over the product of discs |q_i| <= c_i (a second-order-cone
constrained quadratic programme): the slip opposes the traction, and dissipation is never
negative.

The iteration generalises Polonsky and Keer's (1999) projected conjugate gradients from the
half-line p >= 0 to discs:

1. s = C q (two FFT pairs); w = s + e - delta, with delta the mean of s + e over the stick set
   under force control.
2. Stick set: contact points inside their disc, and points on the rim whose slip increment does
   not oppose the traction (w.q >= 0: they want to stick again). Slip set: the others.
3. Direction: z = w on the stick set and the component of w tangent to the rim (perpendicular to
   q) on the slip set, so slipping points may turn; under force control the sum of z is removed
   over the stick set. t = z + beta t_old with beta = |z|^2/|z_old|^2, reset to 0 whenever the
   stick set changed (Polonsky-Keer's reset when points enter or leave).
4. tau = (z.t) / (t.Ct + sum_slip lambda_i |t_i|^2) (t.Ct by Parseval's theorem from two
   forward FFTs; C t itself is never formed), where the second term, with the slip multiplier
   lambda_i = -w_i.q_i / (|q_i| c_i), is the curvature the rim adds when a slipping point turns
   (the Hessian of the Lagrangian on the rim; without it a slipping contact under a large slip
   increment overshoots and never settles); q -= tau t; project every point radially onto its
   disc; under force control give the lost force back to the stick set (uniformly, projected
   again) until the total is met.

Residual (scale-free, the same number in nm or m):

.. math::

    r = \frac{\sum_{stick} c_i |w_i| + \sum_{slip} c_i |w_i^{\perp}|}{\sum c_i}\Big/ s_0,
    \qquad s_0 = \mathrm{rms}_{A_c} |s + e| + |\delta|

the traction-weighted mean violation of the stick and slip-direction conditions over the
contact, relative to the displacement scale of the step; s_0 is at least rms_{A_c} |C q| (a step
that sticks everywhere at delta = 0, as in a frictional normal loading, has s + e = 0 at its
solution). |q_i| <= c_i holds to round-off at every returned iterate.

References
----------
Polonsky, I. A. and Keer, L. M. (1999). Wear 231, 206-219. doi:10.1016/S0043-1648(99)00113-1
Vollebregt, E. A. H. (2014). J. Optim. Theory Appl. 162, 931-953 (the convex formulation).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError, InputError
from . import _shear_kernels as kernels

# |q| within this fraction of the bound counts as on the rim.
RIM = 1e-12
# Force-control redistribution passes per iteration.
_REDISTRIBUTE = 50


@dataclass(frozen=True)
class ShearResult:
    """One converged increment.

    Tractions [Pa], slip increment w [m] (everywhere, also out of contact), rigid displacement
    [m], stick set (contact points not slipping), iterations and residual.
    """

    qx: np.ndarray
    qy: np.ndarray
    wx: np.ndarray
    wy: np.ndarray
    delta: tuple[float, float]
    stick: np.ndarray
    iterations: int
    residual: float


def _project(qx, qy, bound):
    """Radial projection of each (qx, qy) onto its disc of radius ``bound`` (in place)."""
    norm = np.hypot(qx, qy)
    over = norm > bound
    scale = np.where(over, bound / np.where(over, norm, 1.0), 1.0)
    qx *= scale
    qy *= scale


def _give_back(qx, qy, bound, stick, target, pixel_area):
    """Shift the stick points' tractions until sum(q) A_px meets ``target`` (force control)."""
    for _ in range(_REDISTRIBUTE):
        missing = (target[0] / pixel_area - qx.sum(), target[1] / pixel_area - qy.sum())
        scale = max(abs(target[0]), abs(target[1])) / pixel_area
        if abs(missing[0]) + abs(missing[1]) <= 1e-14 * max(scale, bound.sum()):
            return
        room = stick & (np.hypot(qx, qy) < bound * (1 - RIM))
        if not room.any():
            room = bound > 0
        n = room.sum()
        qx[room] += missing[0] / n
        qy[room] += missing[1] / n
        _project(qx, qy, bound)


def check_below_sliding(force, bound: np.ndarray, pixel_area: float) -> None:
    """Refuse a tangential force at or above mu F_0 = sum(mu p) A_px: the contact slides as a whole."""
    capacity = float(bound.sum()) * pixel_area
    if np.hypot(*force) >= capacity * (1 - 1e-12):
        raise InputError(
            "force",
            f"|F_t| = {np.hypot(*force):.6g} N reaches the sliding force mu F_0 = {capacity:.6g} N: "
            "the contact slides as a whole (no partial-slip solution).",
            "keep the tangential force below mu F_0, or prescribe a displacement path.",
        )


@dataclass
class Optimality:
    """The optimality check of an iterate (:func:`optimality`): the residual and what the CG reuses."""

    residual: float
    changed: bool
    n_stick: int
    stick_sum: tuple[float, float]
    z_norm: float


def optimality(qx, qy, c_flat, sx, sy, delta, state, flat, offset) -> Optimality:
    """Classify stick and slip, fill ``flat``'s directions and return the scale-free residual.

    ``sx, sy`` is C q + e (w = C q + e - delta on return); the residual is that of the module
    docstring (the same for both increment solvers, so a tolerance means the same). The scale s_0
    has the floor rms_{A_c} |C q| (C q = s + e - e, with ``offset`` = e): a step that sticks
    everywhere with delta = 0 (a frictional normal loading) ends with s + e = 0, and the elastic
    displacement of its tractions is then its scale.
    """
    changed, violation, weight, ss, cc, n_contact, n_stick, zsx, zsy, z_norm = kernels.classify(
        qx.ravel(), qy.ravel(), c_flat, sx.ravel(), sy.ravel(), offset[0].ravel(), offset[1].ravel(),
        delta[0], delta[1], RIM, state, flat["zx"], flat["zy"], flat["nx"], flat["ny"], flat["bend"],
    )  # fmt: skip
    scale = max(np.sqrt(ss / n_contact) + np.hypot(*delta), np.sqrt(cc / n_contact)) if n_contact else 0.0
    residual = violation / weight / scale if scale > 0.0 and weight > 0.0 else 0.0
    return Optimality(float(residual), bool(changed), int(n_stick), (zsx, zsy), z_norm)


def _stick_sum(z, state):
    """Sum of z over the stick set."""
    return float(z[state == kernels.STICK].sum())


def _slip_sum(z, state):
    """Sum of z over the slip set (their tangential moves also change the total force)."""
    return float(z[state == kernels.SLIP].sum())


def solve_increment(
    shear: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
    energy: Callable[[np.ndarray, np.ndarray], float],
    bound: np.ndarray,
    offset: tuple[np.ndarray, np.ndarray],
    *,
    pixel_area: float,
    displacement: tuple[float, float] | None = None,
    force: tuple[float, float] | None = None,
    initial: tuple[np.ndarray, np.ndarray] | None = None,
    tolerance: float = 1e-8,
    max_iterations: int = 10_000,
    solver: str = "solve_tangential",
    preconditioner: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]] | None = None,
) -> ShearResult:
    """Solve the increment of the module docstring.

    Parameters
    ----------
    shear : callable
        (q_x, q_y) [Pa] -> (s_x, s_y) [m], the tangential compliance C of the pair.
    energy : callable
        (t_x, t_y) -> t . C t (e.g. ``TractionCompliance.shear_energy``, by Parseval's theorem
        at half the cost of ``shear``): the step length needs nothing else of C t.
    bound : ndarray
        c = mu p [Pa] (0 outside the contact).
    offset : (ndarray, ndarray)
        The known field e [m] of the module docstring.
    pixel_area : float
        [m^2]; the force is pixel_area * sum(q).
    displacement, force : (float, float)
        Exactly one: rigid displacement (delta_x, delta_y) [m] or total force (F_x, F_y) [N].
    initial : (ndarray, ndarray), optional
        Warm start (projected onto the discs first).
    tolerance, max_iterations, solver
        Stop criterion, iteration limit (then :class:`ConvergenceError`), name for messages.
    preconditioner : callable, optional
        An approximate inverse of ``shear`` (e.g. ``TractionCompliance.inverse_shear``): the
        directions are then built from M z restricted like z (two more FFT pairs per iteration).
    """
    shape = bound.shape
    c = np.array(bound, dtype=float)
    contact = c > 0
    ex = np.ascontiguousarray(offset[0], dtype=float)
    ey = np.ascontiguousarray(offset[1], dtype=float)
    load_control = force is not None
    if load_control:
        check_below_sliding(force, c, pixel_area)
    if initial is None:
        qx, qy = np.zeros(shape), np.zeros(shape)
    else:
        qx, qy = np.where(contact, initial[0], 0.0), np.where(contact, initial[1], 0.0)
    _project(qx, qy, c)
    if load_control:
        _give_back(qx, qy, c, contact, force, pixel_area)
    delta = (0.0, 0.0) if load_control else (float(displacement[0]), float(displacement[1]))
    flat = {name: np.zeros(c.size) for name in ("zx", "zy", "nx", "ny", "bend")}
    tx, ty = np.zeros(shape), np.zeros(shape)
    state = np.full(c.size, 255, dtype=np.uint8)
    c_flat = c.ravel()
    previous_norm = 0.0
    residual = np.inf
    for iteration in range(max_iterations + 1):
        sx, sy = shear(qx, qy)
        sx += ex
        sy += ey
        if load_control:
            delta = kernels.interior_mean(qx.ravel(), qy.ravel(), c_flat, sx.ravel(), sy.ravel(), RIM)
        check = optimality(qx, qy, c_flat, sx, sy, delta, state, flat, (ex, ey))
        residual, n_stick, (zsx, zsy), z_norm = check.residual, check.n_stick, check.stick_sum, check.z_norm
        if residual <= tolerance:
            stick = (state == kernels.STICK).reshape(shape)
            return ShearResult(qx, qy, sx, sy, delta, stick, iteration, float(residual))
        if iteration == max_iterations:
            break
        dx, dy = flat["zx"], flat["zy"]
        if preconditioner is not None:
            mx, my = preconditioner(flat["zx"].reshape(shape), flat["zy"].reshape(shape))
            dx, dy = mx.ravel(), my.ravel()
            z_norm, msx, msy = kernels.restrict(dx, dy, flat["zx"], flat["zy"], flat["nx"], flat["ny"], state)
            zsx, zsy = msx, msy
        if load_control and n_stick:
            mean_x = (zsx + _slip_sum(dx, state)) / n_stick
            mean_y = (zsy + _slip_sum(dy, state)) / n_stick
            removed = kernels.remove_stick_mean(dx, dy, state, mean_x, mean_y)
            if preconditioner is None:
                z_norm = removed
            else:
                z_norm -= mean_x * _stick_sum(flat["zx"], state) + mean_y * _stick_sum(flat["zy"], state)
        beta = 0.0 if check.changed or previous_norm == 0.0 else z_norm / previous_norm
        previous_norm = z_norm
        kernels.update_direction(tx.ravel(), ty.ravel(), dx, dy, flat["nx"], flat["ny"], state, beta)
        along_z = float(np.dot(flat["zx"], tx.ravel()) + np.dot(flat["zy"], ty.ravel()))
        curvature = energy(tx, ty) + kernels.rim_curvature(tx.ravel(), ty.ravel(), flat["bend"])
        if curvature <= 0:
            previous_norm = 0.0
            continue
        kernels.step_and_project(qx.ravel(), qy.ravel(), tx.ravel(), ty.ravel(), along_z / curvature, c_flat)
        if load_control:
            _give_back(qx, qy, c, state.reshape(shape) == kernels.STICK, force, pixel_area)
    raise ConvergenceError(solver, float(residual), iteration, tolerance)
