r"""Adhesive normal contact under an approach programme: :func:`solve_adhesive`.

The elastic body (half-space, periodic or free window, or a layer) meets a rigid flat through an
interaction law of the gap (:mod:`roughcontact.contact.interaction`: Maugis-Dugdale, exponential
or paper 000's Lennard-Jones 9-3), the full elastic counterpart of paper 000's Winkler springs.
Each approach of the programme is an energy minimisation started from the previous state
(:mod:`roughcontact.contact._adhesive_engine`), so the solution follows its branch through
loading and unloading, with the hysteresis of adhesion.

Instabilities. Where a branch ends (a fold of the force-approach curve) the surfaces jump: into
contact on loading (jump-in) and out of it on unloading (jump-out, after the most tensile force).
A step that dissipates energy (its work exceeds the drop of the energy by more than a few pixels'
worth of w), or raises the energy beyond its work, is halved, down to ``jump_resolution``; a step
that still dissipates is a jump, bracketed to that resolution and reported
(``jump`` per step; the first on loading and the last on unloading as ``jump_in_approach`` and
``jump_out_approach``). Inserted steps are marked (``requested`` is False for them).

Detachment. With ``until_detached`` (default) the last stroke of the programme continues, with
its step, until nothing touches any more (no pixel at the wall, or none in repulsion for the
Lennard-Jones law), so the pull-off and the hysteresis are always complete.

The pull-off force is the most tensile force of the curve (the load-control pull-off: every
approach-controlled branch passes through it before it jumps), refined by the vertex of a parabola
through the smallest force and its neighbours when they lie on one branch.

Hysteresis: the work done by the flat along the programme, the sum of F d(approach) (the trapezoid
rule; across a jump over a bracket of at most ``jump_resolution``); for a programme that starts
and ends apart, the energy dissipated by the adhesive cycle.
"""

from __future__ import annotations

import numpy as np

from .._version import __version__
from ..checks import finite_array, no_string, positive
from ..elasticity.halfspace import ElasticLayer
from ..errors import InputError
from ..materials import Material
from ..progress import tracked
from ..topography import Topography
from ..topography.surface import topography_argument
from ._adhesive_engine import AdhesiveEnergy
from .adhesive_result import AdhesiveResult
from .interaction import cohesive_zone_length
from .normal import check_heights, compliance_for

MAX_HALVINGS = 16
"""A step is halved at most this many times before it is refused (a jump is bracketed before)."""

JUMP_PIXELS = 10.0
"""A step that dissipates more than this many pixels' worth of w (w times the pixel area) and
keeps doing so when halved down to the jump resolution is a jump."""

MAX_DETACHING_STEPS = 1000
"""Steps of the last stroke added at most to reach detachment (``until_detached``)."""


def _programme(approach) -> np.ndarray:
    no_string(approach, "approach")
    values = finite_array(np.atleast_1d(approach), "approach")
    if values.ndim != 1 or values.size == 0:
        raise InputError(
            "approach",
            "give one approach or a 1D sequence of them.",
            "e.g. approach=[-2e-9, 5e-9, -5e-9] (m).",
        )
    return values


def solve_adhesive(
    topography: Topography,
    material: Material | float | None,
    interaction,
    *,
    approach,
    counter_body: Material | None = None,
    layer: ElasticLayer | None = None,
    boundary: str | None = None,
    tolerance: float = 1e-6,
    max_iterations: int = 20_000,
    jump_resolution: float | None = None,
    until_detached: bool = True,
) -> AdhesiveResult:
    """Follow the adhesive contact of ``topography`` with a flat through an approach programme.

    Parameters
    ----------
    topography : Topography
        Heights [m] pointing towards the flat (detrended; two rough bodies: their composite).
    material : Material or float
        The body's material (with ``counter_body`` the flat's), or E* [Pa]; None with ``layer``.
    interaction : MaugisDugdale, Exponential or LennardJones
        The surface interaction law (:mod:`roughcontact.contact.interaction`).
    approach : float or sequence of float
        The flat's approach [m] at each step, from the first touch of the undeformed surface
        (negative: apart). Loading then unloading, e.g. ``[-5e-9, ..., 10e-9, ..., -5e-9]``.
        Steps are inserted where the state changes fast (see the module docstring).
    counter_body : Material, optional
        The flat's material (default rigid).
    layer : ElasticLayer, optional
        The body is a layer or a film on a substrate.
    boundary : {"periodic", "free"}, optional
        Default: the topography's periodic flag.
    tolerance : float
        Largest force imbalance of a pixel, relative to the law's peak tension.
    max_iterations : int
        Iterations per step before :class:`~roughcontact.errors.ConvergenceError`.
    jump_resolution : float, optional
        Width [m] to which a jump is bracketed (default: a quarter of the law's length).
    until_detached : bool
        Continue the last stroke until the surfaces are apart (default True).

    Returns
    -------
    AdhesiveResult

    Raises
    ------
    InputError
        Bad law, programme or grid; a Lennard-Jones compression beyond the law's bound; a step
        that cannot be resolved.
    ConvergenceError
        A step did not converge (its residual and iterations are reported).
    """
    topography = topography_argument(topography, "topography")
    programme = _programme(approach)
    if not all(hasattr(interaction, name) for name in ("energy", "traction", "stiffness")):
        raise InputError(
            "interaction",
            f"{interaction!r} is not an interaction law.",
            "pass MaugisDugdale(w, rho), Exponential(w, rho) or LennardJones(w, eps) "
            "from roughcontact.contact.interaction (a law of your own needs energy, traction and "
            "stiffness of the gap).",
        )
    check_heights(topography)
    positive(tolerance, "tolerance", example=1e-6)
    if jump_resolution is None:
        jump_resolution = 0.25 * interaction.length
    positive(jump_resolution, "jump_resolution", example=1e-10, unit="m")
    compliance = compliance_for(
        topography, material, counter_body=counter_body, layer=layer, boundary=boundary
    )
    heights = topography.heights.reshape(compliance.shape)
    energy = AdhesiveEnergy(compliance, heights.max() - heights, interaction)
    path = _Path(energy, jump_resolution, tolerance, max_iterations)
    path.start(float(programme[0]))
    for target in tracked(programme[1:], what="adhesive steps"):
        path.advance(float(target), requested=True)
    if until_detached and programme.size > 1 and programme[-1] < programme[-2]:
        stride = float(programme[-1] - programme[-2])
        for _ in range(MAX_DETACHING_STEPS):
            if not path.touching():
                break
            path.advance(path.states[-1].delta + stride, requested=False)
        else:
            raise InputError(
                "approach",
                f"still in contact {MAX_DETACHING_STEPS} steps of {-stride:.4g} m after the programme ended.",
                "end the programme at a lower approach.",
            )
    return AdhesiveResult.from_states(
        topography=topography,
        interaction=interaction,
        states=path.states,
        requested=np.array(path.requested),
        jump=np.array(path.jumps),
        pixel_area=topography.pixel_area,
        contact_modulus=compliance.contact_modulus,
        boundary=compliance.boundary,
        tolerance=tolerance,
        cohesive_zone=cohesive_zone_length(interaction, compliance.contact_modulus),
        parameters={
            "jump_resolution": jump_resolution,
            "until_detached": until_detached,
            "version": __version__,
        },
    )


class _Path:
    """The states solved so far, and the step control that brackets jumps.

    A step is a jump when it dissipates energy: the work of the force over the step (trapezoid
    rule) differs from the drop of the total energy by more than :data:`JUMP_PIXELS` pixels' worth
    of w. On a branch the difference is the trapezoid rule's error, which falls eightfold with each
    halving of the step; across a jump it is the energy the jump dissipates, whatever the step.
    So a step above the threshold is halved until it falls below it (a branch, resolved) or the
    step reaches the resolution (a jump, bracketed). A step on which the body starts or stops
    touching uses a tenth of the threshold (the jump-in and jump-out of a single contact).

    A step whose energy rises by more than the threshold above the work done on it is halved too.
    No branch step does that, but a relaxation started from the previous state can leave its
    branch (an unloading step longer than the Maugis-Dugdale range starts every contact pixel out
    of range, and the relaxation runs to the detached state, dropping a contact that should hold;
    found by tests/validation/test_adhesive_wavy.py); and across a jump the trapezoid rule's error
    (up to half the force times the step) has either sign. So the threshold applies to the size of
    the difference, and a step at the resolution that still exceeds it is a jump.
    """

    def __init__(self, energy: AdhesiveEnergy, resolution: float, tolerance, max_iterations):
        self.energy, self.resolution = energy, resolution
        self.options = {"tolerance": tolerance, "max_iterations": max_iterations}
        self.states, self.requested, self.jumps = [], [], []
        self._threshold = JUMP_PIXELS * energy.law.work_of_adhesion * energy.pixel_area

    def start(self, delta: float) -> None:
        start = np.zeros(self.energy.grid)
        self._keep(self.energy.relax(start, delta, **self.options), True, False)

    def _keep(self, state, requested: bool, jump: bool) -> None:
        self.states.append(state)
        self.requested.append(requested)
        self.jumps.append(jump)

    def touching(self) -> bool:
        """Whether the last state touches (see :meth:`_touching`)."""
        return self._touching(self.states[-1])

    def _touching(self, state) -> bool:
        """Whether a pixel of ``state`` is in contact (the law's ``in_contact``)."""
        return bool(np.any(self.energy.law.in_contact(state.gap)))

    def _dissipated(self, old, new) -> float:
        """Energy the step from ``old`` to ``new`` dissipated [J]: its work minus the energy change."""
        area = self.energy.pixel_area
        work = 0.5 * (old.pressure.sum() + new.pressure.sum()) * area * (new.delta - old.delta)
        return work - (new.energy - old.energy)

    def advance(self, target: float, *, requested: bool) -> None:
        """Step to ``target`` [m], bracketing any jump on the way to the resolution."""
        while True:
            last = self.states[-1]
            step = target - last.delta
            if step == 0.0:
                return
            for _ in range(MAX_HALVINGS):
                candidate = self.energy.relax(last.displacement, last.delta + step, **self.options)
                dissipated = self._dissipated(last, candidate)
                touch = self._touching(last) != self._touching(candidate)
                jump = abs(dissipated) > self._threshold * (0.1 if touch else 1.0)
                if not jump or abs(step) <= self.resolution:
                    break
                step *= 0.5
            else:
                raise InputError(
                    "approach",
                    f"the step from {last.delta:.4g} m could not be resolved in {MAX_HALVINGS} halvings.",
                    "give a finer programme or a larger jump_resolution.",
                )
            reached = candidate.delta == target
            self._keep(candidate, requested and reached, jump)
            if reached:
                return
