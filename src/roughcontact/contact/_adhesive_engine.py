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
2. preconditioned direction Z = K G on the free points, K the compliance (the inverse of S, one
   FFT pair): the exact inverse of the elastic Hessian, so the conditioning left is that of the
   interaction and of the active set (a few tens of iterations per step, independent of the grid
   in our measurements); Polak-Ribiere+ conjugation, restarted when the active set changes;
3. step: the minimiser of the elastic quadratic along the direction, at most :data:`MAX_MOVE`
   interaction lengths at any pixel of the window (so that the state settles in the nearest
   minimum instead of crossing a barrier), projected on the bounds, halved until the energy falls
   by the Armijo condition.

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
            The residual is above ``tolerance`` after ``max_iterations``.
        """
        law, scale = self.law, self.scale
        lower = np.full(self.grid, -np.inf)
        self._in_window(lower)[...] = law.lowest_gap - self.separation + delta
        u = np.maximum(displacement, lower)
        elastic = self.elastic_pressure(u)
        energy = self._energy(u, elastic, delta)
        direction = previous = None
        for iteration in range(max_iterations + 1):
            gap = self.gap(u, delta)
            gradient = elastic.copy()
            self._in_window(gradient)[...] -= law.traction(gap)
            free = ~((u <= lower) & (gradient > 0))
            gradient[~free] = 0.0
            residual = float(np.abs(gradient).max() / scale)
            if residual <= tolerance:
                break
            if iteration == max_iterations:
                raise ConvergenceError("solve_adhesive", residual, iteration, tolerance)
            steer = self._fft.convolve(gradient, self._compliance)
            steer[~free] = 0.0
            product = float(np.vdot(gradient, steer))
            if previous is None or not np.array_equal(free, previous[1]):
                direction = -steer
            else:
                beta = max(0.0, (product - float(np.vdot(gradient, previous[2]))) / previous[0])
                direction = beta * direction - steer
                direction[~free] = 0.0
                if np.vdot(gradient, direction) >= 0.0:
                    direction = -steer
            previous = (product, free, steer)
            response = self.elastic_pressure(direction)
            slope = float(np.vdot(gradient, direction))
            curvature = float(np.vdot(direction, response))
            reach = float(np.abs(self._in_window(direction)).max())
            step = -slope / curvature
            if reach > 0.0:
                step = min(step, MAX_MOVE * self.length / reach)
            while True:
                unclipped = u + step * direction
                trial = np.maximum(unclipped, lower)
                clipped = not np.array_equal(trial, unclipped)
                trial_elastic = self.elastic_pressure(trial) if clipped else elastic + step * response
                trial_energy = self._energy(trial, trial_elastic, delta)
                if trial_energy <= energy + 1e-4 * step * slope or step < 1e-12:
                    break
                step *= 0.5
            u, elastic, energy = trial, trial_elastic, trial_energy
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

    def _energy(self, u: np.ndarray, elastic: np.ndarray, delta: float) -> float:
        """Energy per pixel area [J/m^2 summed over pixels] of ``u`` with ``elastic`` = S u."""
        return 0.5 * float(np.vdot(u, elastic)) + float(self.law.energy(self.gap(u, delta)).sum())
