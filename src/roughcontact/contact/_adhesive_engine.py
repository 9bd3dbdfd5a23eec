r"""The energy minimisation behind every adhesive contact solve (one approach of the flat).

Unknown: the elastic surface displacement u [m] (into the body) on the transform grid: the
periodic grid, or for a free boundary the zero-padded grid 2n x 2n, whose padding carries no
interaction. The total energy per pixel area A

.. math::

    \frac{\Pi(u)}{A} = \tfrac12 \sum u \,(S u) + \sum_{\text{window}} \phi(g), \qquad
    g = h_0 - \delta + u, \qquad g \ge g_{min},

with S the surface stiffness (the inverse of the compliance kernel, applied by FFT), phi the
interaction law (:mod:`roughcontact.contact.interaction`) and h0 the undeformed separation
(0 at the highest point), is minimised from the previous state under the bounds g >= 0 (the
hard wall; g >= -eps/2 for the Lennard-Jones law) by a projected nonlinear conjugate gradient:

1. gradient G = S u - p(g) (elastic minus interaction pressure; in the padding of a free window
   S u alone); points at the bound whose G pushes further into it are held (the active set);
2. preconditioned direction Z = D K D G on the free points, K the compliance (the inverse of S,
   one FFT pair) and D = (1 + K_ii k)^(-1/2) a diagonal scaling by the law's stiffness
   k = max(d^2 phi / dg^2, 0) at each pixel (K_ii: a pixel's compliance under its own pressure).
   K alone is the exact inverse of the elastic Hessian S; the interaction adds diag(phi''), which
   on the Lennard-Jones repulsion is many times a pixel's stiffness 1/K_ii (16 w / eps^2 at
   contact, growing as l^-10 in compression), and K then overshoots there by a factor 1 + K_ii k.
   D K D tends to K where k -> 0 (everywhere for Maugis-Dugdale and the exponential law, so their
   iterations are unchanged) and to the Jacobi step G / k on a pixel much stiffer than the body,
   as if held by the wall (the hard-wall laws' active set). Polak-Ribiere+ conjugation in its
   flexible form (the preconditioner changes with the state), restarted when the active set
   changes;
3. step: the minimiser along the direction of the quadratic model with the Hessian S + diag(k),
   at most :data:`MAX_MOVE` interaction lengths at any pixel of the window (so that the state
   settles in the nearest minimum instead of crossing a barrier), projected on the bounds, halved
   until the energy falls by the Armijo condition (a fraction :data:`ARMIJO` of the first-order
   change G . du). Near the solution the energy change of a step reaches the round-off of the
   energy itself (paper 000's sphere at a residual of 1.4e-6: the whole decrease left, 5.6e-14,
   was 1.1e-15 of the energy's size, the sums over pixels carrying errors of that order), where
   the Armijo test accepts or refuses steps at random and the iteration stalls (it did there, for
   20000 iterations). Where the change is below :data:`ROUNDOFF` of the energy's size, the
   decrease is judged instead by the trapezoid rule on the gradients at both ends,
   (G0 + G1) . du / 2 (exact for a quadratic; the approximate Wolfe condition of Hager and Zhang
   2005). A direction along which no step passes in :data:`LINE_SEARCH_HALVINGS` halvings is a
   stall, reported as :class:`~roughcontact.errors.ConvergenceError` with the lowest residual
   reached (``stalled_at``).

Its gradient is the difference of the elastic and the interaction pressures, so a stationary
point is the equilibrium p_elastic = p(g) off the wall and p_elastic >= p(0) on it; in the padding
of a free window p_elastic = 0 at the solution, which is the free boundary: the circulant
embedding of Love's kernel on the padded grid is positive, so its inverse is the stiffness of the
padded periodic problem and its solution restricted to the window is that of the zero-padded
compliance operator of :class:`~roughcontact.elasticity.halfspace.SurfaceCompliance`.

Periodic grids: the mean displacement of a half-space is undetermined (zero stiffness), so the
mean mode is given the stiffness of the longest wavelength (like the preconditioner of the
normal solver, and ContactMechanics' default): the flat's position delta is imposed through that
spring, and the approach reported is delta - mean(u), that of the normal solver's zero-mean
convention (:func:`roughcontact.contact.solve_normal`). The force-approach curve is the same; a
softer control can only move where a jump happens, never the most tensile force (every jump of a
control stiffer than load control comes after it).

Residual: the largest force imbalance |G| of a free pixel relative to the law's peak tension
(a scale-free number, the same in nm or m).

References
----------
Polonsky, I. A. and Keer, L. M. (1999). Wear 231, 206-219 (the projected conjugate gradient).
doi:10.1016/S0043-1648(99)00113-1
Rey, V., Anciaux, G. and Molinari, J.-F. (2017). Comput. Mech. 60, 69-81 (adhesion in the gap
formulation). doi:10.1007/s00466-017-1392-5
Pastewka, L. and Robbins, M. O. (2014). PNAS 111, 3298-3303 (the same minimisation of the
displacements for rough adhesive contact). doi:10.1073/pnas.1320846111
Hager, W. W. and Zhang, H. (2005). SIAM J. Optim. 16, 170-192 (the approximate Wolfe condition,
for line searches where the function's changes are at its round-off). doi:10.1137/030601880
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._backend import RealFFT2
from ..elasticity.halfspace import SurfaceCompliance
from ..errors import ConvergenceError, InputError

MAX_MOVE = 0.5
"""Largest change of the gap in one iteration, in units of the law's length: a descent step must
not carry the state over an energy barrier into another minimum (a jump the programme's step
control is there to bracket)."""

ARMIJO = 1e-4
"""Sufficient decrease: a step must lower the energy by this fraction of its first-order change."""

ROUNDOFF = 1e-10
"""Energy changes below this fraction of the energy's size are round-off: there the decrease is
judged from the gradients at both ends (the trapezoid rule) instead."""

LINE_SEARCH_HALVINGS = 60
"""Halvings of a step before the line search gives up (a stall, reported by ConvergenceError)."""


def _inner(a: np.ndarray, b: np.ndarray) -> float:
    """Return the sum of a * b over the grid, by einsum's own loop rather than a BLAS dot.

    A threaded BLAS dot of a few 10^4 values spins for milliseconds a call when the cores are
    busy (measured here: 8 ms at 128^2 with other jobs running, against 17 us for this loop).
    """
    return float(np.einsum("ij,ij->", a, b))


@dataclass(frozen=True)
class Relaxed:
    """One converged state: displacement on the transform grid and its fields on the window (SI)."""

    displacement: np.ndarray  # u on the transform grid [m]
    gap: np.ndarray  # window [m]
    pressure: np.ndarray  # window, the elastic pressure S u [Pa] (interaction plus wall)
    delta: float  # the flat's imposed position [m]
    approach: float  # zero-mean convention [m] (delta itself for a free boundary)
    iterations: int
    residual: float
    energy: float  # total energy, elastic plus interaction [J] (per metre for a profile)


class AdhesiveEnergy:
    """Energy, gradient and bounds of the adhesive problem on one grid (see the module docstring).

    Parameters
    ----------
    compliance : SurfaceCompliance
        The operator of the grid (its kernel gives the stiffness).
    separation : ndarray
        h0 on the window [m], >= 0.
    law : interaction law
    """

    def __init__(self, compliance: SurfaceCompliance, separation: np.ndarray, law):
        self.law = law
        self.window = compliance.shape
        self.grid = compliance.transform_shape
        self.periodic = compliance.boundary == "periodic"
        self.separation = separation
        stiffness = compliance.inverse_kernel()
        self.length = law.length
        self.pixel_area = compliance.pixel_area
        self.scale = law.peak_tension
        self._stiffness = stiffness
        self._compliance = np.divide(1.0, stiffness, out=np.zeros_like(stiffness), where=stiffness > 0)
        self._fft = RealFFT2(self.grid, compliance.workers)
        impulse = np.zeros(self.grid)
        impulse[0, 0] = 1.0
        self._pixel_compliance = float(self._fft.convolve(impulse, self._compliance)[0, 0])

    def elastic_pressure(self, displacement: np.ndarray) -> np.ndarray:
        """S u on the transform grid [Pa]."""
        return self._fft.convolve(displacement, self._stiffness)

    def _in_window(self, field: np.ndarray) -> np.ndarray:
        return field[: self.window[0], : self.window[1]]

    def gap(self, displacement: np.ndarray, delta: float) -> np.ndarray:
        """Return the gap h0 - delta + u on the window [m]."""
        return self.separation - delta + self._in_window(displacement)

    def relax(
        self, displacement: np.ndarray, delta: float, *, tolerance: float, max_iterations: int
    ) -> Relaxed:
        """Minimise the energy at the flat's position ``delta`` from ``displacement`` (transform grid).

        Raises
        ------
        ConvergenceError
            The residual is above ``tolerance`` after ``max_iterations``, or the line search found
            no step that lowers the energy (``stalled_at``: the lowest residual reached).
        """
        law, scale = self.law, self.scale
        lower = np.full(self.grid, -np.inf)
        self._in_window(lower)[...] = law.lowest_gap - self.separation + delta
        u = np.maximum(displacement, lower)
        elastic = self.elastic_pressure(u)
        energy, magnitude = self._energy(u, elastic, delta)
        direction = previous = None
        lowest = np.inf
        for iteration in range(max_iterations + 1):
            gap = self.gap(u, delta)
            gradient = self._gradient(elastic, gap)
            free = ~((u <= lower) & (gradient > 0))
            projected = np.where(free, gradient, 0.0)
            residual = float(np.abs(projected).max() / scale)
            if residual <= tolerance:
                break
            if iteration == max_iterations:
                raise ConvergenceError("solve_adhesive", residual, iteration, tolerance)
            lowest = min(lowest, residual)
            stiffness = np.maximum(law.stiffness(gap), 0.0)
            steer = self._precondition(projected, stiffness)
            steer[~free] = 0.0
            product = _inner(projected, steer)
            if previous is None or not np.array_equal(free, previous[1]):
                direction = -steer
            else:
                beta = max(0.0, (product - _inner(projected, previous[2])) / previous[0])
                direction = beta * direction - steer
                direction[~free] = 0.0
                if _inner(projected, direction) >= 0.0:
                    direction = -steer
            previous = (product, free, steer)
            response = self.elastic_pressure(direction)
            reach = self._in_window(direction)
            curvature = _inner(direction, response) + _inner(reach * stiffness, reach)
            step = -_inner(projected, direction) / curvature
            largest = float(np.abs(reach).max())
            if largest > 0.0:
                step = min(step, MAX_MOVE * self.length / largest)
            for _ in range(LINE_SEARCH_HALVINGS):
                unclipped = u + step * direction
                trial = np.maximum(unclipped, lower)
                clipped = not np.array_equal(trial, unclipped)
                trial_elastic = self.elastic_pressure(trial) if clipped else elastic + step * response
                trial_energy, trial_magnitude = self._energy(trial, trial_elastic, delta)
                move = trial - u
                decrease = _inner(gradient, move)  # first-order change of the energy, < 0
                change = trial_energy - energy
                if decrease < 0.0 and change <= ARMIJO * decrease:
                    break
                if decrease < 0.0 and abs(change) <= ROUNDOFF * max(magnitude, trial_magnitude):
                    trial_gradient = self._gradient(trial_elastic, self.gap(trial, delta))
                    if 0.5 * _inner(gradient + trial_gradient, move) <= ARMIJO * decrease:
                        break
                step *= 0.5
            else:
                raise ConvergenceError("solve_adhesive", residual, iteration, tolerance, stalled_at=lowest)
            u, elastic, energy, magnitude = trial, trial_elastic, trial_energy, trial_magnitude
        pressure = self._in_window(elastic).copy()
        if not law.hard_wall and np.any(self._in_window(u <= lower)):
            raise InputError(
                "approach",
                f"the compression at {delta:.4g} m reaches the Lennard-Jones law's bound l = eps / 2 "
                f"(a pressure of about {1344 * law.work_of_adhesion / law.length:.3g} Pa).",
                "lower the largest approach of the programme, or use a law with a hard wall.",
            )
        mean = float(u.mean()) if self.periodic else 0.0
        return Relaxed(
            u,
            self.gap(u, delta),
            pressure,
            delta,
            delta - mean,
            iteration,
            residual,
            energy * self.pixel_area,
        )

    def _gradient(self, elastic: np.ndarray, gap: np.ndarray) -> np.ndarray:
        """dPi/du per pixel area [Pa]: S u minus the interaction pressure on the window."""
        gradient = elastic.copy()
        self._in_window(gradient)[...] -= self.law.traction(gap)
        return gradient

    def _precondition(self, gradient: np.ndarray, stiffness: np.ndarray) -> np.ndarray:
        """Return D K D G [m]: the compliance scaled by D = (1 + K_ii k)^(-1/2) on the window.

        k >= 0 is the law's stiffness per pixel (0 where it softens) and K_ii the compliance of a
        pixel under its own pressure. Where k = 0 (everywhere for Maugis-Dugdale and the
        exponential law) this is K G; on a pixel much stiffer than the body it tends to G / k.
        """
        if not stiffness.any():
            return self._fft.convolve(gradient, self._compliance)
        scaling = np.ones(self.grid)
        self._in_window(scaling)[...] = 1.0 / np.sqrt(1.0 + self._pixel_compliance * stiffness)
        return scaling * self._fft.convolve(scaling * gradient, self._compliance)

    def _energy(self, u: np.ndarray, elastic: np.ndarray, delta: float) -> tuple[float, float]:
        """Energy per pixel area [J/m^2 summed over pixels] of ``u`` with ``elastic`` = S u, and its size.

        The size, elastic energy plus the sum of |phi|, sets the round-off of the energy.
        """
        strain = 0.5 * _inner(u, elastic)
        interaction = self.law.energy(self.gap(u, delta))
        return strain + float(interaction.sum()), abs(strain) + float(np.abs(interaction).sum())
