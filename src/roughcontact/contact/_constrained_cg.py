r"""The one constrained conjugate-gradient engine behind every normal contact solve.

It solves the discrete contact problem of a rigid flat pressed onto a surface of initial
separation h0 >= 0 (min h0 = 0 at the first point to touch) [m] with a compliance operator K:

.. math::

    g = K p + h_0 - \delta, \qquad 0 \le p \le p_{max}, \qquad
    g \ge 0 \text{ where } p = 0, \quad g = 0 \text{ where } 0 < p < p_{max}, \quad
    g \le 0 \text{ where } p = p_{max}

(paper 001 eq. 4 with an optional pressure cap, the hardness of an elastic-perfectly-plastic
surface, where the overlap -g is plastic flow), either at a given total force (load control:
the approach delta is the Lagrange multiplier of the force) or at a given approach delta
(displacement control). The iteration is Polonsky and Keer's (1999) conjugate gradient
projected on the feasible set, with the box constraint of Almqvist et al. (2007) for the cap:

1. u = K p (one FFT pair); g = u + h0 - delta with delta = mean of u + h0 over the free set
   {0 < p < p_max} (load control) or the given delta.
2. Residual (below); stop when it is below the tolerance.
3. Conjugate direction t = z + beta t_old on the free set with z = g, or z = M g with the
   preconditioner M = K^{-1} of the unrestricted operator applied in Fourier space and restricted
   to the free set (Vollebregt 2014; one more FFT pair, in single precision, several times fewer
   iterations on rough surfaces). Plain: beta = (g.z) / (g.z)_old (Fletcher-Reeves), reset to
   0 after a step in which points entered the contact (Polonsky-Keer). Preconditioned: the
   Polak-Ribiere+ coefficient beta = max(0, z.(g - g_old) / (g.z)_old), kept across changes
   of the set and reset only where t would not be a descent direction (g.t <= 0, known before
   t is formed from the sums over the set of g t_old and t_old). Resetting at every change, as
   Polonsky-Keer do, turns the whole phase in which the contact set is still being found into
   preconditioned steepest descent, and that phase grows with the grid: on the benchmark's
   self-affine surfaces (tolerance 1e-10) 43, 66, 110, 240 iterations from 256^2 to 2048^2
   with resets, 42, 48, 66, 82 with Polak-Ribiere+ (113 at 4096^2, tolerance 4e-10 at its
   round-off floor); Fletcher-Reeves kept across changes was as fast under load control and
   slower under displacement control (115 instead of 73 at 1024^2). This engine solves one
   grid; without a warm start, :func:`roughcontact.contact._box.solve` first runs it on the
   grid coarsened 2 x 2 (down to 64 pixels, each level warm-started from the one below, as
   aspher's ``solve_nested``) and starts the fine grid from that answer, which saves the fine
   level's first iterations (48 -> 39, 66 -> 54, 82 -> 69 at 512^2 to 2048^2, the coarse
   levels costing 4-6 fine iterations; see there). Points at the cap with g > 0 (which want
   to unload) join the free set. Under load control a constant is
   subtracted from t on the free set so that it sums to zero there (the step then keeps the force;
   Polonsky-Keer instead remove the free-set mean of r = K t, which equals this when t sums to
   zero). Step tau = (g.t) / (t.K t), with t.K t computed in Fourier space by Parseval's theorem
   from one forward FFT of t in single precision (K t itself is never formed). Preconditioned,
   the points out of contact that overlap (p = 0 with g < 0) join the set too.
4. p -= tau t on the set; clip to [0, p_max]. Plain: points out of contact that overlap enter by
   -tau g (Polonsky-Keer's I_ol step); clip again. Preconditioned they already took part in the
   step: -tau g would be no pressure there, since tau is dimensionless when t is built from M g
   (with that step the solver stalled at a residual of 0.1 on a 2048^2 self-affine surface);
   "entered" means p went from 0 to positive, which resets the conjugacy as in Polonsky-Keer.
5. Load control: rescale the pressure to the target force (Polonsky-Keer; lazily, as a factor
   that the next iteration's passes apply while they read p and u). A cap is only
   supported under displacement control (the caller finds the approach of a force by root
   finding, :mod:`roughcontact.contact.load_unload`).

Residual (scale-free: the same number in nm or m, at any load):

.. math::

    r = \max\left(\frac{\sum_{E} p_i |g_i|}{\sum_{E} p_i}, \;
                 \max_{p_i < p_{max}} (-g_i)^+, \; \max_{p_i = p_{max}} (g_i)^+\right) / s_h

with E the elastic contact points (0 < p < p_max) and s_h the rms of h0 about its mean plus the
rms of u about its mean (a height scale of the problem). The first term is the pressure-weighted
mean gap over the elastic contact (zero at the solution), the others the worst violations of
the gap conditions: overlap anywhere below the cap (so a point with a vanishing pressure cannot
hide an overlap), and an open gap under a capped pressure.

Cost of an iteration: one FFT pair in double precision (K p) and, in single precision, one pair
(M g, preconditioned only; on the window's own grid, also for a free boundary) and one forward
transform (t.K t), with five fused elementwise passes
(:mod:`roughcontact.contact._cg_kernels`) that write p, g and t straight into the transforms'
input buffers and read K p and M g where the transforms leave them
(:meth:`~roughcontact.elasticity.halfspace.SurfaceCompliance.staged`). Single precision
(relative error about 1e-7) only steers the iteration, a direction and a step length; the gap
and the residual come from K p in double precision, so the converged answer is that of a
double-precision solver (measured against double-precision M and t.K t: the same iteration
counts, pressures within 5e-11 of the peak on 256^2 to 1024^2 self-affine surfaces at
tolerance 1e-10, 5e-14 on a free Hertz case). The
returned pressure and gap are from the same iterate (never a mixed state).

On the GPU (an operator with ``device="gpu"``) the same iteration runs on CuPy arrays: the
passes are :mod:`roughcontact.contact._cg_kernels_gpu`'s CUDA kernels, with the same arguments
and results, and the transforms cuFFT's. The fields are float64, or float32 with the
operator's ``precision="single"`` (the sums stay float64); the returned fields stay on the
device, for the caller to copy (:func:`roughcontact._device.to_host`).

References
----------
Polonsky, I. A. and Keer, L. M. (1999). Wear 231, 206-219. doi:10.1016/S0043-1648(99)00113-1
Almqvist, A., Sahlin, F., Larsson, R. and Glavatskih, S. (2007). Tribol. Int. 40, 574-579.
doi:10.1016/j.triboint.2005.11.008
Vollebregt, E. A. H. (2014). J. Optim. Theory Appl. 162, 931-953. doi:10.1007/s10957-013-0499-x
Rey, V., Anciaux, G. and Molinari, J.-F. (2017). Comput. Mech. 60, 69-81.
doi:10.1007/s00466-017-1392-5
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._device import gpu_module
from ..elasticity.halfspace import SurfaceCompliance
from ..errors import ConvergenceError
from . import _cg_kernels


@dataclass(frozen=True)
class EngineResult:
    """Raw solution of :func:`solve`: fields of one iterate, approach, iterations, residual."""

    pressure: np.ndarray
    displacement: np.ndarray
    gap: np.ndarray
    approach: float
    iterations: int
    residual: float


def _rms(values) -> float:
    return math.sqrt(float(((values - values.mean()) ** 2).mean()))


def device_tools(compliance: SurfaceCompliance):
    """Return the array module and the fused passes of ``compliance``'s device (numpy and numba, or CuPy)."""
    if compliance.device == "gpu":
        from . import _cg_kernels_gpu

        return gpu_module().cupy, _cg_kernels_gpu
    return np, _cg_kernels


def solve(
    compliance: SurfaceCompliance,
    separation: np.ndarray,
    *,
    pixel_area: float,
    force: float | None = None,
    approach: float | None = None,
    cap: float | None = None,
    initial_pressure: np.ndarray | None = None,
    tolerance: float = 1e-8,
    max_iterations: int = 10_000,
    solver: str = "normal contact",
    precondition: bool = True,
) -> EngineResult:
    """Solve the contact problem of the module docstring.

    Parameters
    ----------
    compliance : SurfaceCompliance
        The linear surface compliance K (p [Pa] -> u [m]); the iteration runs on its
        :meth:`~roughcontact.elasticity.halfspace.SurfaceCompliance.staged` transforms (K p, the
        preconditioner M and t.K t).
    separation : ndarray
        Initial separation h0 [m] (>= 0, 0 at the highest point).
    pixel_area : float
        Area of one pixel [m^2]; force = pixel_area * sum(p).
    force, approach : float
        Exactly one: total force [N] (load control) or rigid approach [m] (displacement control).
    cap : float, optional
        Largest pressure [Pa] (hardness); None for elastic contact.
    initial_pressure : ndarray, optional
        Warm start [Pa] (e.g. the previous step of a load path).
    tolerance : float
        Stop when the residual of the module docstring is below it.
    max_iterations : int
        Raise :class:`ConvergenceError` beyond this.
    solver : str
        Name used in error messages.
    precondition : bool
        Build the conjugate directions from M g restricted to the free set, with M the compliance's
        Fourier inverse in single precision (True), or from g (plain Polonsky-Keer).

    Returns
    -------
    EngineResult

    Raises
    ------
    ConvergenceError
        Not converged in ``max_iterations`` (residual and iterations reported).
    """
    load_control = force is not None
    if load_control and cap is not None:
        raise ValueError("a pressure cap needs displacement control")
    xp, kernels = device_tools(compliance)
    dtype = compliance.field_dtype
    h0 = xp.asarray(separation)
    upper = cap if cap is not None else np.inf
    # Pixel self-stiffness 1/K_ii [Pa/m]: turns an overlap into the pressure that closes it alone.
    stiffness = 1.0 / compliance.self_compliance
    if not load_control and approach <= float(h0.min()):
        p = xp.zeros_like(h0)  # nothing overlaps: p = 0 is the exact solution, whatever the warm start
    elif initial_pressure is not None:
        p = xp.clip(xp.asarray(initial_pressure), 0.0, upper)
    elif load_control:
        p = xp.full(h0.shape, 0.0)
    else:
        p = xp.clip((approach - h0) * stiffness, 0.0, upper)
    if load_control:
        target = force / pixel_area  # target sum of pixel pressures
        if float(p.sum()) <= 0:
            p = xp.full(h0.shape, target / h0.size)
        p *= target / float(p.sum())  # p is the engine's own array (a clipped copy or a new one)
    height_scale = _rms(h0)
    h0 = xp.ascontiguousarray(h0, dtype=dtype)
    p = xp.ascontiguousarray(p, dtype=dtype)  # stored pressure; the true one is scale * p
    scale = 1.0
    # Work arrays, reused every iteration (fresh large arrays cost page faults on every pass).
    t, g = xp.zeros_like(h0), xp.empty_like(h0)
    free = xp.empty(h0.shape, dtype=np.uint8)
    g_previous = xp.zeros(h0.shape, dtype=np.float32) if precondition else None  # Polak-Ribiere
    g_norm_old = 1.0
    conjugate = False
    # Preconditioned: overlapping points with p = 0 join the step set, so the step itself gives them a
    # pressure (see the module docstring); plain Polonsky-Keer lets them enter by -tau g.
    admit = precondition
    delta = approach
    halved, halved_at, lowest = np.inf, 0, np.inf  # stall detection (preconditioned): see STALL_ITERATIONS
    with compliance.staged() as ops:  # the transforms' input buffers, written by the fused passes
        ops.pressure[...] = p
        for iteration in range(max_iterations + 1):
            u = z = None  # on the GPU each transform returns a new array: never hold two of them
            u = ops.displacement()  # K p of the stored p, in the transform's buffer
            statistics = kernels.displacement_statistics(p, u, h0, upper, scale)
            elastic_count, elastic_sum, u_sum, uu_sum = statistics
            if load_control:
                delta = elastic_sum / elastic_count if elastic_count else float((scale * u + h0).min())
            sums = kernels.gap_and_residual(p, u, h0, delta, upper, scale, t, g, ops.approximate, free, admit)
            p_sum, pg_sum, overlap, opened, free_count, gg_sum, g_sum, t_sum, gt_old = sums
            u_std = np.sqrt(max(uu_sum / u.size - (u_sum / u.size) ** 2, 0.0))
            residual = _residual(pg_sum / p_sum if p_sum > 0 else 0.0, overlap, opened, height_scale + u_std)
            if residual <= tolerance:
                p *= scale  # the engine's own array
                if xp is np:
                    u = scale * u  # out of the transform's buffer, which the next solve reuses
                else:
                    u *= scale  # an array of its own on the GPU: no second copy of the largest grids
                return EngineResult(p, u, g, float(delta), iteration, residual)
            if iteration == max_iterations:
                break
            lowest = min(lowest, residual)
            if residual < 0.5 * halved:
                halved, halved_at = residual, iteration
            elif precondition and iteration - halved_at >= STALL_ITERATIONS:
                raise ConvergenceError(solver, residual, iteration, tolerance, stalled_at=lowest)
            if not precondition:
                z, z_sum, gz_sum = g, g_sum, gg_sum  # read on the step set only
            else:  # M g restricted to the step set (Vollebregt 2014), M in single precision
                z = ops.precondition()
                z_sum, gz_sum, previous_z_sum, previous_sum = kernels.restricted_sums(z, g, free, g_previous)
            # Load control: the direction sums to zero over the step set, so the step keeps the force.
            mean = 1.0 / free_count if load_control and free_count else 0.0
            shift = z_sum * mean
            g_norm = gz_sum - shift * g_sum
            if not precondition:  # Polonsky-Keer: Fletcher-Reeves, reset when points entered
                beta = g_norm / g_norm_old if conjugate else 0.0
            elif iteration > 0:  # Polak-Ribiere+, kept across changes of the set (module docstring)
                beta = max((g_norm - (previous_z_sum - shift * previous_sum)) / g_norm_old, 0.0)
                if g_norm + beta * (gt_old - t_sum * g_sum * mean) <= 0.0:
                    beta = 0.0  # not a descent direction: restart
            else:
                beta = 0.0
            shift += beta * t_sum * mean
            gt_sum = kernels.update_direction(t, z, shift, beta, free, g, ops.direction)
            g_norm_old = g_norm
            tkt = ops.quadratic_form()  # t . K t by Parseval, single precision
            tau = gt_sum / tkt if tkt > 0 else 0.0
            # Plain Polonsky-Keer: entering points get p = -step g, tau or, when it is undefined (empty
            # step set), the pixel self-stiffness 1/K_ii [Pa/m], the pressure that closes a lone overlap.
            step = tau if tau > 0 else stiffness
            entered, p_sum = kernels.update_pressure(p, t, g, tau, step, upper, admit, scale, ops.pressure)
            conjugate = entered == 0
            scale = target / p_sum if load_control and p_sum > 0 else 1.0
    raise ConvergenceError(solver, residual, max_iterations, tolerance)


STALL_ITERATIONS = 200
"""Preconditioned iterations without the residual halving after which a solve is declared stalled.

Converging solves halve it every 3-15 iterations at the longest (self-affine 256^2 to 2048^2,
free Hertz). Below a floor the residual stops falling altogether: with preconditioning or
without, in double or in single precision, on the benchmark's self-affine surfaces (tolerance
asked 1e-14 to 1e-16) it stalls at about 1e-13, 1e-12, 7e-12, 7e-11 and 1.2e-10 at 256^2, 512^2,
1024^2, 2048^2 and 4096^2, with the set fixed and the gap error spread over the whole contact.
Plain Polonsky-Keer is not checked: it can go 900 iterations without halving and then converge
(free Hertz at 256^2).
"""


def _residual(weighted_gap: float, overlap: float, open_gap: float, height_scale: float) -> float:
    """Return the scale-free residual of the module docstring from its three terms [m]."""
    worst = max(weighted_gap, overlap, open_gap)
    return worst / height_scale if height_scale > 0 else 0.0
