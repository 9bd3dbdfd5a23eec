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
from typing import ClassVar

import numpy as np

from ..errors import InputError
from ..materials import Material
from ..progress import tracked
from ..topography import Topography
from .normal import compliance_for, solve_normal
from .result import NormalContactResult
from .volume_plastic import VolumePlasticResult, solve_elastic_plastic

LOAD_UNLOAD_UNITS = {
    "peak_force": "N",
    "peak_interference": "m",
    "residual_interference": "m",
    "peak_contact_area": "m^2",
    "max_pressure": "Pa",
    "max_plastic_deformation": "m",
    "hardness": "Pa",
}
"""SI units of the scalars of a load-unload result (:class:`LoadUnloadResult` and paper 002's island)."""

CURVE_VARIABLES = {
    "approach": ("m", "interference (approach of the flat)"),
    "force": ("N", "load"),
    "contact_area": ("m^2", "real contact area"),
    "plastic_fraction": ("", "fraction of the real contact area at the hardness"),
    "max_pressure": ("Pa", "largest contact pressure"),
}
"""Unit and meaning of each variable of a load-unload curve."""


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

    UNITS: ClassVar[dict[str, str]] = LOAD_UNLOAD_UNITS
    """SI unit of each dimensional scalar of :meth:`scalars`."""

    @property
    def converged(self) -> bool:
        """True when every step met its tolerance (the solver raises rather than return otherwise)."""
        return all(step.converged for step in self.loading + self.unloading)

    @property
    def iterations(self) -> int:
        """Iterations of every step's solve together."""
        return sum(step.iterations for step in self.loading + self.unloading)

    @property
    def residual(self) -> float:
        """Largest residual of the steps."""
        return max(step.residual for step in self.loading + self.unloading)

    def curve(self) -> dict[str, np.ndarray]:
        """Return the path, one entry per step in order (:func:`load_unload_curve`)."""
        steps = self.loading + self.unloading
        return load_unload_curve(steps, len(self.loading), [step.approach for step in steps])

    def scalars(self) -> dict[str, float]:
        """Return the peak, the residual interference and the plastic flow (SI; units in :attr:`UNITS`)."""
        steps, peak = self.loading + self.unloading, len(self.loading) - 1
        found = load_unload_scalars(
            steps,
            peak,
            steps[peak].approach,
            self.residual_interference,
            self.plastic_deformation,
            self.hardness,
        )
        return found | {"iterations": self.iterations, "residual": self.residual}

    def to_xarray(self):
        """Return the curve as an ``xarray.Dataset`` on the dimension ``point`` (SI, with units)."""
        return load_unload_dataset(self.curve(), self.scalars())


def plastic_fraction(step: NormalContactResult) -> float:
    """Fraction of a step's real contact area where the pressure is at the hardness."""
    return float(step.plastic_mask.sum() / max(np.count_nonzero(step.contact_mask), 1))


def load_unload_curve(steps, loading: int, approach) -> dict[str, np.ndarray]:
    """Return a load-unload path as arrays, one entry per step (the first ``loading`` steps load).

    ``branch`` (loading/unloading), ``approach`` [m] (as given: the interference in the
    caller's convention), ``force`` [N], ``contact_area`` [m^2], ``plastic_fraction`` (of the real
    contact area at the hardness) and ``max_pressure`` [Pa].
    """
    return {
        "branch": np.array(["loading"] * loading + ["unloading"] * (len(steps) - loading)),
        "approach": np.asarray(approach, dtype=float),
        "force": np.array([s.force for s in steps]),
        "contact_area": np.array([s.contact_area for s in steps]),
        "plastic_fraction": np.array([plastic_fraction(s) for s in steps]),
        "max_pressure": np.array([float(s.pressure.max()) for s in steps]),
    }


def load_unload_scalars(
    steps, peak: int, interference: float, residual: float, plastic: np.ndarray, hardness: float
) -> dict[str, float]:
    """Return the scalars of a load-unload path (units in :data:`LOAD_UNLOAD_UNITS`).

    ``steps`` are the solutions in order, ``peak`` the index of the peak load, ``interference``
    its interference and ``residual`` the residual interference [m] (both in the caller's
    convention), ``plastic`` the plastic flow depth [m], ``hardness`` the cap [Pa].
    """
    top = steps[peak]
    return {
        "peak_force": top.force,
        "peak_interference": float(interference),
        "residual_interference": float(residual),
        "peak_contact_area": top.contact_area,
        "plastic_fraction_at_peak": float(
            top.plastic_mask.sum() / max(np.count_nonzero(top.contact_mask), 1)
        ),
        "max_pressure": max(float(step.pressure.max()) for step in steps),
        "max_plastic_deformation": float(np.max(plastic)),
        "hardness": float(hardness),
    }


def load_unload_dataset(curve: dict[str, np.ndarray], attributes: dict):
    """Return a load-unload curve as an ``xarray.Dataset`` on the dimension ``point`` (units attached)."""
    import xarray as xr

    data = {"branch": ("point", np.asarray(curve["branch"]).astype(str))}
    for name, (unit, meaning) in CURVE_VARIABLES.items():
        data[name] = ("point", np.asarray(curve[name], dtype=float), {"units": unit, "long_name": meaning})
    return xr.Dataset(data, attrs={k: v for k, v in attributes.items() if v is not None})


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
    plasticity: str = "surface",
    **volume,
) -> LoadUnloadResult | VolumePlasticResult:
    """Load to ``max_force`` or ``max_approach`` and unload, with the pressure capped at the hardness.

    With ``plasticity="volume"`` the body yields below the surface instead (J2 plasticity,
    :func:`~roughcontact.contact.volume_plastic.solve_elastic_plastic`, which takes the keywords in
    ``volume``: ``depth``, ``layers``, ``yield_strength``, ``hardening_modulus``, ...): ``steps``
    equal increments of force (or approach) up to the peak and back down to zero.

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
    LoadUnloadResult, or VolumePlasticResult for ``plasticity="volume"``
    """
    if plasticity not in ("surface", "volume"):
        raise InputError("plasticity", f"unknown plasticity {plasticity!r}.", "use 'surface' or 'volume'.")
    if plasticity == "volume":
        if counter_body is not None:
            raise InputError(
                "counter_body", "volume plasticity is solved against a rigid flat.", "leave it out."
            )
        peak = max_force if max_force is not None else max_approach
        up = np.linspace(0.0, peak, steps + 1)[1:]
        programme = np.concatenate([up, up[::-1][1:], [0.0]])
        kind = "forces" if max_force is not None else "approaches"
        return solve_elastic_plastic(
            topography,
            material,
            boundary=boundary,
            contact_tolerance=tolerance,
            **{kind: programme},
            **volume,
        )
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
    loading = capped_path(topography, "approach", np.linspace(0.0, peak.approach, steps)[1:-1], options)
    loading.append(peak)
    flattened, residual = flattened_at(topography, peak)
    unloading = capped_path(
        flattened, "approach", np.linspace(peak.approach, residual, steps)[1:], options, offset=residual
    )
    return LoadUnloadResult(
        tuple(loading), tuple(unloading), peak.plastic_deformation, residual, float(hardness)
    )


def flattened_at(topography: Topography, peak: NormalContactResult) -> tuple[Topography, float]:
    """Return the surface flattened by the plastic flow of ``peak`` and its first touch [m].

    The first touch (the residual interference) is measured from the original surface's first
    touch: min(h_max - h + d_p).
    """
    plastic = peak.plastic_deformation
    flattened = topography.with_heights(
        topography.heights - plastic, step="plastic flattening at the peak load"
    )
    return flattened, float(np.min(topography.heights.max() - topography.heights + plastic))


def capped_path(
    topography: Topography, kind: str, targets, options: dict, *, offset: float = 0.0, what: str = "steps"
) -> list[NormalContactResult]:
    """Solve the capped contact at each target force or approach in turn, each warm-started from the last.

    ``kind`` is "force" or "approach"; ``options`` go to :func:`solve_normal` (the hardness, the
    compliance, tolerances). For a flattened surface (:func:`flattened_at`) ``offset`` is its first
    touch: approaches are given, and returned, from the original surface's first touch (the one
    load-unload path of :func:`load_unload` and of paper 002's island).
    """
    steps, previous = [], None
    for target in tracked(targets, what=what):
        local = max(float(target) - offset, 0.0) if kind == "approach" else float(target)
        previous = solve_normal(topography, **{kind: local}, initial=previous, **options)
        steps.append(_shifted(previous, offset))
    return steps


def _shifted(result: NormalContactResult, offset: float) -> NormalContactResult:
    """Return the result with its approach measured ``offset`` further (from the original first touch)."""
    return replace(result, approach=result.approach + offset)
