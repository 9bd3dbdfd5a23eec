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
   to the free set (Vollebregt 2014; one more FFT pair, several times fewer iterations on rough
   surfaces); beta = (g.z) / (g.z)_old, reset to 0 after a step in which points entered the
   contact; points at the cap with g > 0 (which want to unload) join the free set; r = K t
   (one FFT pair), with its free-set mean removed under load control; step tau = (g.t) / (r.t).
4. p -= tau t on the free set; clip to [0, p_max]; points out of contact that overlap
   (p = 0 with g < 0) enter by -tau g (Polonsky-Keer's I_ol step); clip again.
5. Load control: rescale the pressure to the target force (Polonsky-Keer). A cap is only
   supported under displacement control (the caller finds the approach of a force by root
   finding, :mod:`roughcontact.contact.plastic`).

Residual (scale-free: the same number in nm or m, at any load):

.. math::

    r = \max\left(\frac{\sum_{E} p_i |g_i|}{\sum_{E} p_i}, \;
                 \max_{p_i < p_{max}} (-g_i)^+, \; \max_{p_i = p_{max}} (g_i)^+\right) / s_h

with E the elastic contact points (0 < p < p_max) and s_h the rms of h0 about its mean plus the
rms of u about its mean (a height scale of the problem). The first term is the pressure-weighted
mean gap over the elastic contact (zero at the solution), the others the worst violations of
the gap conditions: overlap anywhere below the cap (so a point with a vanishing pressure cannot
hide an overlap), and an open gap under a capped pressure. Each iteration costs two
FFT pairs (three preconditioned); the returned pressure and gap are from the same iterate
(never a mixed state).

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

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError


@dataclass(frozen=True)
class EngineResult:
    """Raw solution of :func:`solve`: fields of one iterate, approach, iterations, residual."""

    pressure: np.ndarray
    displacement: np.ndarray
    gap: np.ndarray
    approach: float
    iterations: int
    residual: float


def _rms(values: np.ndarray) -> float:
    return float(np.sqrt(np.mean((values - values.mean()) ** 2)))


def _dot(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.dot(a.ravel(), b.ravel()))


def _residual(pressure, gap, elastic, height_scale, cap, scratch) -> float:
    """Return the scale-free residual of the module docstring; ``elastic`` is the mask 0 < p < p_max."""
    total = float(np.sum(pressure, where=elastic))
    elastic_gap = np.multiply(np.abs(gap, out=scratch), elastic, out=scratch)
    weighted = _dot(pressure, elastic_gap) / total if total > 0 else 0.0
    # Overlap anywhere below the cap (at the cap it is plastic flow, not an error).
    below = pressure < cap if cap is not None else True
    overlap = -float(np.min(gap, where=below, initial=0.0))
    worst = max(weighted, overlap)
    if cap is not None:
        worst = max(worst, float(np.max(gap, where=pressure >= cap, initial=0.0)))
    return worst / height_scale if height_scale > 0 else 0.0


def _std(values: np.ndarray) -> float:
    """Return the standard deviation from two reductions (a height scale: a few digits suffice)."""
    mean = float(values.sum()) / values.size
    return float(np.sqrt(max(_dot(values, values) / values.size - mean * mean, 0.0)))


def solve(
    compliance: Callable[[np.ndarray], np.ndarray],
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
    preconditioner: Callable[[np.ndarray], np.ndarray] | None = None,
) -> EngineResult:
    """Solve the contact problem of the module docstring.

    Parameters
    ----------
    compliance : callable
        p [Pa] -> u [m], the linear surface compliance (e.g. a SurfaceCompliance).
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
    preconditioner : callable, optional
        An approximate inverse of the compliance (e.g. ``SurfaceCompliance.inverse``); the
        conjugate directions are then built from M g restricted to the free set.

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
    h0 = separation
    upper = cap if cap is not None else np.inf
    # Pixel self-stiffness 1/K_ii [Pa/m]: turns an overlap into the pressure that closes it alone.
    impulse = np.zeros_like(h0)
    impulse.flat[0] = 1.0
    stiffness = 1.0 / float(compliance(impulse).flat[0])
    if not load_control and approach <= h0.min():
        p = np.zeros_like(h0)  # nothing overlaps: p = 0 is the exact solution, whatever the warm start
    elif initial_pressure is not None:
        p = np.clip(initial_pressure, 0.0, upper)
    elif load_control:
        p = np.full(h0.shape, 0.0)
    else:
        p = np.clip((approach - h0) * stiffness, 0.0, upper)
    if load_control:
        target = force / pixel_area  # target sum of pixel pressures
        if p.sum() <= 0:
            p = np.full(h0.shape, target / h0.size)
        p = p * _rescale_factor(p, target)
    height_scale = _rms(h0)
    # Work arrays, reused every iteration (fresh large arrays cost page faults on every pass).
    t, g, scratch = np.zeros_like(h0), np.empty_like(h0), np.empty_like(h0)
    free, mask = np.empty(h0.shape, dtype=bool), np.empty(h0.shape, dtype=bool)
    g_norm_old = 1.0
    conjugate = False
    delta = approach
    for iteration in range(max_iterations + 1):
        u = compliance(p)
        np.greater(p, 0.0, out=free)
        if cap is not None:
            free &= np.less(p, cap, out=mask)
        free_count = np.count_nonzero(free)
        np.add(u, h0, out=g)
        if load_control:
            delta = float(np.sum(g, where=free) / free_count) if free_count else float(np.min(g))
        g -= delta
        residual = _residual(p, g, free, height_scale + _std(u), cap, scratch)
        if residual <= tolerance:
            return EngineResult(p, u, g, float(delta), iteration, residual)
        if iteration == max_iterations:
            break
        if cap is not None:
            free |= (p >= cap) & (g > 0)  # capped points that want to unload take part in the step
            free_count = np.count_nonzero(free)
        g_free = np.multiply(g, free, out=scratch)
        z = g_free if preconditioner is None else _preconditioned(preconditioner, g_free, free, load_control)
        g_norm = _dot(g_free, z)
        if conjugate:
            t *= g_norm / g_norm_old
            t += z
            t *= free
        else:
            np.copyto(t, z)
        g_norm_old = g_norm
        r = compliance(t)
        rt = _dot(r, t)  # t = 0 outside the free set
        if load_control and free_count:  # r with its free-set mean removed
            rt -= float(np.sum(r, where=free)) / free_count * float(t.sum())
        tau = _dot(g, t) / rt if rt > 0 else 0.0
        p -= np.multiply(t, tau, out=scratch)
        np.clip(p, 0.0, upper, out=p)
        entering = np.less_equal(p, 0.0, out=mask)
        entering &= g < 0
        conjugate = not entering.any()
        if not conjugate:
            step = tau if tau > 0 else 1.0 / stiffness  # Jacobi step when the free set is empty
            p -= step * np.multiply(g, entering, out=scratch)
            np.clip(p, 0.0, upper, out=p)
        if load_control:
            p *= _rescale_factor(p, target)
    raise ConvergenceError(solver, residual, max_iterations, tolerance)


def _preconditioned(preconditioner, g_free, free, load_control) -> np.ndarray:
    """Return M g on the free set: the inverse of the full operator, restricted (Vollebregt 2014)."""
    z = preconditioner(g_free)
    z *= free
    if load_control:  # keep the step inside the force constraint: zero sum over the free set
        np.subtract(z, z.sum() / np.count_nonzero(free), out=z, where=free)
    return z


def _rescale_factor(p: np.ndarray, target: float) -> float:
    """Return the factor that scales p to sum(p) = target (1 for p = 0)."""
    total = float(p.sum())
    return target / total if total > 0 else 1.0
