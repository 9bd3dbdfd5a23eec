r"""Elastic-perfectly-plastic load-unload of a rough surface against a rigid flat.

The surface model (Almqvist et al. 2007; Sahlin et al. 2010): the pressure never exceeds the
hardness H; where it reaches H the surface flows plastically by exactly the overlap that the
elastic solution cannot remove, so the flattened surface keeps that deformation for the rest
of the path. Loading to a maximum approach (or force) and unloading elastically from the
flattened surface gives the load-interference curve with a residual interference at zero
load, as in paper 002's Fig. 7.

For a monotonic loading branch this surface model is path-independent (the solution at the
largest approach is that of the capped problem on the original surface), so each loading
point is solved directly from the original surface, warm-started from the previous one. The
unloading branch is elastic on the surface flattened at the maximum load: h' = h - d_p. The
residual interference is the approach at which the flattened surface first carries load,
delta_res = min(h0 + d_p) measured from the first touch of the original surface.

How this differs from the explicit finite elements of paper 002: plasticity is confined to the
surface (no plastic zone below it, no hardening, small strains, no pile-up), so it should agree
with FEM where the plastic zone is shallow compared with the contact size and the contact
pressure has saturated at H (Sahlin et al. 2010); it over-predicts the plastic flow depth
for isolated asperities at the onset of yield, where the subsurface yields before the
surface pressure reaches H.

References
----------
Almqvist, A., Sahlin, F., Larsson, R. and Glavatskih, S. (2007). Tribol. Int. 40, 574-579.
doi:10.1016/j.triboint.2005.11.008
Sahlin, F., Larsson, R., Almqvist, A., Lugt, P. M. and Marklund, P. (2010). Proc. IMechE J
224, 335-351. doi:10.1243/13506501JET658
Seed paper 002 (SU-8 island load-unload, Figs. 7-9).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError
from ..materials import Material
from ..topography import Topography
from .normal import compliance_for, solve_normal
from .result import NormalContactResult


@dataclass(frozen=True)
class LoadUnloadResult:
    """A load-unload path: one normal contact result per step, and the curve scalars.

    Attributes
    ----------
    loading, unloading : tuple of NormalContactResult
        The steps of each branch (unloading solved on the flattened surface).
    plastic_deformation : ndarray
        Plastic flow depth d_p [m] at the maximum load (what the surface keeps).
    residual_interference : float
        Approach [m] at which the unloaded, flattened surface carries no load, from the first
        touch of the original surface.
    hardness : float
        The pressure cap [Pa].
    """

    loading: tuple[NormalContactResult, ...]
    unloading: tuple[NormalContactResult, ...]
    plastic_deformation: np.ndarray
    residual_interference: float
    hardness: float

    def curve(self) -> dict[str, np.ndarray]:
        """Return approach [m], force [N], contact area [m^2] and plastic area fraction per step, in order."""
        steps = self.loading + self.unloading
        return {
            "branch": np.array(["loading"] * len(self.loading) + ["unloading"] * len(self.unloading)),
            "approach": np.array([s.approach for s in steps]),
            "force": np.array([s.force for s in steps]),
            "contact_area": np.array([s.contact_area for s in steps]),
            "plastic_fraction": np.array([s.plastic_mask.mean() for s in steps]),
        }


def load_unload(
    topography: Topography,
    material: Material,
    *,
    max_force: float | None = None,
    max_approach: float | None = None,
    hardness: float | None = None,
    steps: int = 10,
    counter_body: Material | None = None,
    boundary: str | None = None,
    tolerance: float = 1e-8,
    max_iterations: int = 10_000,
) -> LoadUnloadResult:
    """Load to ``max_force`` or ``max_approach`` and unload, with the pressure capped at the hardness.

    Parameters
    ----------
    topography : Topography
        Surface [m], heights towards the flat.
    material : Material
        Body material; its ``hardness`` is the cap unless ``hardness`` is given.
    max_force, max_approach : float
        Exactly one: the peak force [N] or peak approach [m].
    hardness : float, optional
        Pressure cap [Pa] (default: ``material.hardness``).
    steps : int
        Points on each branch (loading from the first touch, unloading back to zero load).
    counter_body : Material, optional
        The flat (default rigid).
    boundary : {"periodic", "free"}, optional
        Default: the topography's periodic flag.
    tolerance, max_iterations
        As in :func:`roughcontact.contact.solve_normal`.

    Returns
    -------
    LoadUnloadResult
    """
    hardness = material.hardness if hardness is None else hardness
    if hardness is None:
        raise InputError("hardness", "no hardness given and the material has none.", "pass hardness= in Pa.")
    if steps < 2:
        raise InputError("steps", f"need at least 2 steps, got {steps}.", "use steps >= 2.")
    compliance = compliance_for(topography, material, counter_body=counter_body, boundary=boundary)
    options = dict(
        hardness=hardness, tolerance=tolerance, max_iterations=max_iterations, compliance=compliance
    )
    peak = solve_normal(topography, force=max_force, approach=max_approach, **options)
    loading, previous = [], None
    for approach in np.linspace(0.0, peak.approach, steps)[1:-1]:
        previous = solve_normal(topography, approach=float(approach), initial=previous, **options)
        loading.append(previous)
    loading.append(peak)

    plastic = peak.plastic_deformation
    flattened = topography.with_heights(
        topography.heights - plastic, step="plastic flattening at the peak load"
    )
    separation = topography.heights.max() - topography.heights
    residual = float(np.min(separation + plastic))
    # Unloading is elastic: approaches on the flattened surface are measured from its own first
    # touch (residual above the original one); report them from the original first touch.
    unloading, previous = [], None
    for approach in np.linspace(peak.approach, residual, steps)[1:]:
        local = max(approach - residual, 0.0)
        step = solve_normal(flattened, approach=local, initial=previous, **options)
        previous = step
        unloading.append(_shifted(step, residual))
    return LoadUnloadResult(tuple(loading), tuple(unloading), plastic, residual, float(hardness))


def _shifted(result: NormalContactResult, offset: float) -> NormalContactResult:
    """Return the result with its approach measured ``offset`` further (from the original first touch)."""
    return replace(result, approach=result.approach + offset)
