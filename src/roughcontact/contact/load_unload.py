r"""Elastic-plastic load-unload of a rough surface (or a film on a substrate) against a rigid flat.

One door, :func:`load_unload`, with the plastic model as a typed option:

* :class:`SurfacePlasticity` (the default, the cheaper approximation): the pressure never exceeds
  the hardness H; where it reaches H the surface flows plastically by exactly the overlap that the
  elastic solution cannot remove, so the flattened surface keeps that deformation for the rest of
  the path (Almqvist et al. 2007; Sahlin et al. 2010). Loading is path-independent in this model
  (the solution at an approach is that of the capped problem on the original surface), so each
  loading point is solved from the original surface, warm-started from the previous one;
  unloading is elastic on the surface flattened at the peak, h' = h - d_p, and the residual
  interference is the approach at which it first carries load, delta_res = min(h0 + d_p). Its von
  Mises stress (:meth:`LoadUnloadResult.stress`) is that of the elastic body under each step's
  surface pressure.
* :class:`VolumePlasticity`: J2 plasticity with linear hardening below the surface
  (:func:`~roughcontact.contact.volume_plastic.solve_elastic_plastic`), with residual stress after
  unloading.

The programme is ``max_force`` or ``max_approach`` with ``steps`` points per branch, or the force
targets ``forces`` (rising to the peak; unloading back through them, or ``unloading_forces``).
The body is a half-space of ``material`` or, with ``substrate`` and ``film_thickness``, a film
bonded to its substrate (:class:`~roughcontact.elasticity.halfspace.ElasticLayer`; laterally
infinite, so an island's free side walls are not modelled). The interference counts from the
first touch, or from the load ``reference_force`` on loading (paper 002: 25 uN, the smallest load
its nanoindenter resolves).

Two interferences after the peak, under two names: ``residual_interference`` is the interference at
zero load, where the unloaded surface first touches the flat; ``interference_at_return_force`` is
the interference where the unloading branch comes back to the *return force*, ``reference_force``
(paper 002: 25 uN, the load at which an experiment, or the statistical KKE model of
:mod:`roughcontact.asperity.load_unload`, ends its unloading curve), or zero load without one.

How the surface model differs from elastic-plastic finite elements (paper 002's LS-DYNA): no
plastic zone below the surface, no hardening, no residual stress, small strains, no pile-up, so it
agrees with them where the plastic zone is shallow compared with the contact and the pressure has
saturated at H, and over-predicts the plastic flow of isolated asperities at the onset of yield.

References
----------
Almqvist, A., Sahlin, F., Larsson, R. and Glavatskih, S. (2007). Tribol. Int. 40, 574-579.
doi:10.1016/j.triboint.2005.11.008
Sahlin, F., Larsson, R., Almqvist, A., Lugt, P. M. and Marklund, P. (2010). Proc. IMechE J
224, 335-351. doi:10.1243/13506501JET658
Seed paper 002 (SU-8 island load-unload, sections III and VI, Figs. 7-9).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, fields, replace
from typing import ClassVar

import numpy as np

from .._deprecation import folded, renamed
from ..display_html import NotebookDisplay
from ..elasticity.halfspace import ElasticLayer
from ..elasticity.stress import StressField, subsurface_stress
from ..errors import InputError
from ..materials import Material
from ..progress import tracked
from ..topography import Topography
from ..topography.surface import topography_argument
from .normal import compliance_for, solve_normal
from .result import NormalContactResult
from .volume_plastic import VOLUME_UNITS, VolumePlasticResult, solve_elastic_plastic

LOAD_UNLOAD_UNITS = {
    "peak_force": "N",
    "peak_interference": "m",
    "residual_interference": "m",
    "interference_at_return_force": "m",
    "return_force": "N",
    "peak_contact_area": "m^2",
    "peak_contact_area_corrected": "m^2",
    "max_pressure": "Pa",
    "max_plastic_deformation": "m",
    "hardness": "Pa",
}
"""SI units of the scalars of a load-unload with surface plasticity."""

CURVE_VARIABLES = {
    "approach": ("m", "interference (approach of the flat)"),
    "force": ("N", "load"),
    "contact_area": ("m^2", "real contact area"),
    "contact_area_corrected": ("m^2", "real contact area corrected for its pixelated perimeter"),
    "plastic_fraction": ("", "fraction of the real contact area at the hardness"),
    "max_pressure": ("Pa", "largest contact pressure"),
}
"""Unit and meaning of each variable of a surface-plasticity load-unload curve."""


@dataclass(frozen=True)
class SurfacePlasticity:
    """The pressure capped at the hardness; the overlap at the cap kept as plastic flattening.

    Attributes
    ----------
    hardness : float, optional
        The cap [Pa]; default the material's hardness.
    """

    hardness: float | None = None


@dataclass(frozen=True)
class VolumePlasticity:
    """J2 plasticity with linear isotropic hardening below the surface (:mod:`.volume_plastic`).

    Attributes
    ----------
    yield_strength : float, optional
        Initial yield strength [Pa]; default the material's.
    hardening_modulus : float
        Linear hardening slope [Pa] (0: elastic-perfectly plastic).
    depth : float, optional
        Depth [m] of the plastic volume; default ``layers`` cells as thick as a pixel (within the
        film, where there is one).
    layers : int
        Cells through the depth.
    """

    yield_strength: float | None = None
    hardening_modulus: float = 0.0
    depth: float | None = None
    layers: int = 16


Plasticity = SurfacePlasticity | VolumePlasticity
"""The plastic models of :func:`load_unload`."""

PLASTICITY = {"surface": SurfacePlasticity, "volume": VolumePlasticity}
"""The models by name: ``plasticity="surface"`` is ``SurfacePlasticity()``."""

PLASTICITY_KEYS = {name: tuple(option.name for option in fields(model)) for name, model in PLASTICITY.items()}
"""The keys of each model by name: ``"surface"``: hardness; ``"volume"``: yield_strength, ... layers."""


def plasticity_model(
    plasticity: Plasticity | str = "surface",
    *,
    hardness: float | None = None,
    yield_strength: float | None = None,
    hardening_modulus: float | None = None,
    depth: float | None = None,
    layers: int | None = None,
) -> Plasticity:
    """Return the plastic model of :func:`load_unload` that ``plasticity`` names, with its keys.

    The one place that turns a name (a study's or a command's ``plasticity``, paper 002's) into a
    model: ``"surface"`` is ``SurfacePlasticity(hardness)``, ``"volume"`` is
    ``VolumePlasticity(yield_strength, hardening_modulus, depth, layers)``. A key given as None
    keeps the model's default; the keys of the other model are not used (a study's table holds
    both). A :class:`SurfacePlasticity` or :class:`VolumePlasticity` is returned as it is.

    Raises
    ------
    InputError
        An unknown name (field ``plasticity``).
    """
    if isinstance(plasticity, SurfacePlasticity | VolumePlasticity):
        return plasticity
    if plasticity not in PLASTICITY:
        raise InputError(
            "plasticity",
            f"unknown plasticity {plasticity!r}.",
            "use 'surface' or 'volume', or SurfacePlasticity(...) / VolumePlasticity(...).",
        )
    given = {
        "hardness": hardness,
        "yield_strength": yield_strength,
        "hardening_modulus": hardening_modulus,
        "depth": depth,
        "layers": layers,
    }
    keys = {key: given[key] for key in PLASTICITY_KEYS[plasticity] if given[key] is not None}
    return PLASTICITY[plasticity](**keys)


@dataclass(frozen=True)
class LoadUnloadResult(NotebookDisplay):
    """A load-unload path (all SI): the curve, the peak and the residual interference.

    Attributes
    ----------
    branch : ndarray of str
        "loading" or "unloading" per step.
    interference : ndarray
        Interference [m] per step: the approach of the flat from the first touch of the original
        surface, less its value at ``reference_force`` on loading where one was given.
    residual_interference : float
        Interference [m] at zero load: where the unloaded surface first touches the flat.
    reference_force : float or None
        Load of zero interference [N] (None: the first touch); also the return force
        (:attr:`interference_at_return_force`).
    steps : tuple of NormalContactResult
        Surface plasticity: one solution per step (unloading on the flattened surface; every
        ``approach`` counts from the original surface's first touch). Empty for volume plasticity.
    plastic_deformation : ndarray or None
        Surface plasticity: the plastic flattening at the peak [m].
    hardness : float or None
        Surface plasticity: the pressure cap [Pa].
    poissons_ratio : float or None
        Of the body, for :meth:`stress`.
    layer : ElasticLayer or None
        The film on its substrate, whose stress :meth:`stress` gives (None: a half-space).
    volume : VolumePlasticResult or None
        Volume plasticity: the steps with their fields (pressure, von Mises stress and plastic
        strain at every depth, residual stress at the end).
    """

    branch: np.ndarray
    interference: np.ndarray
    residual_interference: float
    reference_force: float | None = None
    steps: tuple[NormalContactResult, ...] = ()
    plastic_deformation: np.ndarray | None = None
    hardness: float | None = None
    poissons_ratio: float | None = None
    layer: ElasticLayer | None = None
    volume: VolumePlasticResult | None = None

    UNITS: ClassVar[dict[str, str]] = LOAD_UNLOAD_UNITS | VOLUME_UNITS
    """SI unit of each dimensional scalar of :meth:`scalars` (surface or volume plasticity)."""

    @property
    def peak(self) -> int:
        """Index of the peak load: the last step of the loading branch."""
        return int(np.flatnonzero(self.branch == "loading")[-1])

    @property
    def loading(self) -> tuple[NormalContactResult, ...]:
        """Surface plasticity: the steps of the loading branch."""
        return self.steps[: self.peak + 1]

    @property
    def unloading(self) -> tuple[NormalContactResult, ...]:
        """Surface plasticity: the steps of the unloading branch (on the flattened surface)."""
        return self.steps[self.peak + 1 :]

    @property
    def return_force(self) -> float:
        """The load [N] at which :attr:`interference_at_return_force` is read: ``reference_force`` or 0."""
        return 0.0 if self.reference_force is None else float(self.reference_force)

    @property
    def interference_at_return_force(self) -> float:
        """Interference [m] where the unloading branch comes back to :attr:`return_force` (NaN if never).

        The interference of the unloading step that carries the return force (to 1e-4 of it, as a
        force-controlled step reaches its target), else interpolated linearly in the force between
        the two steps around it (the peak counts as the first point of the branch). At zero
        return force it is the interference of the first unloading point without load, the
        :attr:`residual_interference` where the programme ends at zero load. This is the number to
        compare with the statistical model's (:class:`~roughcontact.asperity.StatisticalLoadUnload`),
        whose unloading curve ends at the same load.
        """
        peak = self.peak
        force = np.asarray(self.force, dtype=float)[peak:]
        interference = np.asarray(self.interference, dtype=float)[peak:]
        target = self.return_force
        tolerance = 1e-4 * max(target, 1e-9 * float(force[0]))
        exact = np.flatnonzero(np.abs(force - target) <= tolerance)
        if exact.size:
            return float(interference[exact[0]])
        below = np.flatnonzero(force < target)
        if below.size == 0 or below[0] == 0:
            return float("nan")
        i = int(below[0])
        share = (force[i - 1] - target) / (force[i - 1] - force[i])
        return float(interference[i - 1] + share * (interference[i] - interference[i - 1]))

    @property
    def path(self) -> VolumePlasticResult | None:
        """Release 0.1's name of :attr:`volume` (kept one release, with a DeprecationWarning)."""
        warnings.warn(
            "LoadUnloadResult.path is now .volume; the old name goes in the next release.",
            DeprecationWarning,
            stacklevel=2,
        )
        return self.volume

    @property
    def force(self) -> np.ndarray:
        """Load of each step [N]."""
        return self.volume.force if self.volume is not None else np.array([s.force for s in self.steps])

    @property
    def converged(self) -> bool:
        """True when every step met its tolerance (the solvers raise rather than return otherwise)."""
        if self.volume is not None:
            return self.volume.converged
        return all(step.converged for step in self.steps)

    @property
    def iterations(self) -> int:
        """Iterations of every step's solve together."""
        if self.volume is not None:
            return self.volume.iterations
        return sum(step.iterations for step in self.steps)

    @property
    def residual(self) -> float:
        """Largest residual of the steps."""
        if self.volume is not None:
            return self.volume.residual
        return max(step.residual for step in self.steps)

    def curve(self) -> dict[str, np.ndarray]:
        """Return the path, one entry per step; ``approach`` is the interference.

        Surface plasticity: ``branch``, ``approach``, ``force`` [N], ``contact_area`` [m^2] (the
        pixel count) and ``contact_area_corrected`` [m^2] (for its pixelated perimeter,
        :mod:`roughcontact.contact.area`; NaN for a profile), ``plastic_fraction`` (of the real
        contact area at the hardness) and ``max_pressure`` [Pa];
        volume plasticity: :meth:`VolumePlasticResult.curve` with the interference as ``approach``.
        """
        if self.volume is not None:
            return self.volume.curve() | {"approach": self.interference}
        steps = self.steps
        return {
            "branch": self.branch,
            "approach": np.asarray(self.interference, dtype=float),
            "force": np.array([s.force for s in steps]),
            "contact_area": np.array([s.contact_area for s in steps]),
            "contact_area_corrected": np.array([_corrected_area(s) for s in steps]),
            "plastic_fraction": np.array([plastic_fraction(s) for s in steps]),
            "max_pressure": np.array([float(s.pressure.max()) for s in steps]),
        }

    def scalars(self) -> dict[str, float]:
        """Return the peak and residual interferences and the plastic flow or stresses (SI; :attr:`UNITS`).

        ``residual_interference`` is at zero load, ``interference_at_return_force`` at the
        ``return_force`` on unloading (module notes).
        """
        interferences = {
            "peak_interference": float(self.interference[self.peak]),
            "residual_interference": float(self.residual_interference),
            "interference_at_return_force": self.interference_at_return_force,
            "return_force": self.return_force,
        }
        if self.volume is not None:
            return self.volume.scalars() | interferences
        top = self.steps[self.peak]
        return {
            "peak_force": top.force,
            **interferences,
            "peak_contact_area": top.contact_area,
            "peak_contact_area_corrected": _corrected_area(top),
            "plastic_fraction_at_peak": plastic_fraction(top),
            "max_pressure": max(float(step.pressure.max()) for step in self.steps),
            "max_plastic_deformation": float(np.max(self.plastic_deformation)),
            "hardness": float(self.hardness),
            "iterations": self.iterations,
            "residual": self.residual,
        }

    def range_warnings(self) -> list[str]:
        """Say where the solution leaves its model's range (volume plasticity: its strains and depth)."""
        return self.volume.range_warnings() if self.volume is not None else []

    def to_xarray(self):
        """Return the curve as an ``xarray.Dataset`` on the dimension ``point`` (SI, with units)."""
        import xarray as xr

        reference = {} if self.reference_force is None else {"reference_force": self.reference_force}
        if self.volume is not None:
            data = self.volume.to_xarray()
            data["approach"] = ("point", self.interference, {"units": "m"})
            data.attrs.update(self.scalars() | reference)
            return data
        curve = self.curve()
        data = {"branch": ("point", np.asarray(curve["branch"]).astype(str))}
        for name, (unit, meaning) in CURVE_VARIABLES.items():
            data[name] = (
                "point",
                np.asarray(curve[name], dtype=float),
                {"units": unit, "long_name": meaning},
            )
        attributes = self.scalars() | reference
        return xr.Dataset(data, attrs={k: v for k, v in attributes.items() if v is not None})

    def stress(self, index: int, depths=(0.0,), *, padding: int = 2) -> StressField:
        """Return the subsurface stress of surface-plasticity step ``index`` on the planes ``depths`` [m].

        That of the film on its substrate where the body is one, else of a half-space, under the
        step's surface pressure (``.von_mises()`` for the maps). Volume plasticity keeps its own
        stresses (``volume.von_mises``).
        """
        if self.volume is not None:
            raise InputError(
                "index",
                "a volume-plasticity path keeps its own stress fields.",
                "read result.volume.von_mises (steps, layers, x, y) instead.",
            )
        step = self.steps[index]
        return subsurface_stress(
            step.pressure,
            step.topography.size,
            depths,
            poissons_ratio=self.poissons_ratio,
            boundary=step.boundary,
            padding=padding,
            layer=self.layer,
        )


@renamed(peak_force="max_force")
def force_targets(max_force: float, steps: int = 10, reference_force: float | None = None) -> np.ndarray:
    """Return the loading targets 0, W/n, ..., W [N] (``steps`` = n), with ``reference_force`` among them.

    For ``forces=`` of :func:`load_unload` (unloading goes back down through them).
    """
    targets = np.linspace(0.0, max_force, steps + 1)
    return targets if reference_force is None else np.unique(np.concatenate([targets, [reference_force]]))


def _corrected_area(step: NormalContactResult) -> float:
    """Return the step's contact area corrected for its pixelated perimeter [m^2]; NaN for a line contact."""
    return step.contact_area_corrected if step.topography.dim == 2 else math.nan


def plastic_fraction(step: NormalContactResult) -> float:
    """Fraction of a step's real contact area where the pressure is at the hardness."""
    return float(step.plastic_mask.sum() / max(np.count_nonzero(step.contact_mask), 1))


def _old_plasticity(plasticity, **old) -> Plasticity:
    """Return the plasticity of release 0.1's keywords (``hardness=``, or J2's ``depth=`` and the like)."""
    volume = plasticity == "volume" or (plasticity is None and "hardness" not in old)
    return plasticity_model("volume" if volume else "surface", **old)


@folded("plasticity", ("hardness", "yield_strength", "hardening_modulus", "depth", "layers"), _old_plasticity)
def load_unload(
    topography: Topography,
    material: Material,
    *,
    max_force: float | None = None,
    max_approach: float | None = None,
    forces=None,
    steps: int = 10,
    unloading_forces=None,
    reference_force: float | None = None,
    plasticity: Plasticity | str = "surface",
    counter_body: Material | None = None,
    substrate: Material | None = None,
    film_thickness: float | None = None,
    boundary: str | None = None,
    tolerance: float = 1e-8,
    max_iterations: int = 10_000,
) -> LoadUnloadResult:
    """Load to a peak and unload, with the pressure capped at the hardness or J2 in the volume.

    Parameters
    ----------
    topography : Topography
        Surface [m], heights towards the flat.
    material : Material
        The body (with ``substrate``: the film); its hardness or yield strength unless the
        plasticity gives one.
    max_force, max_approach : float
        The peak force [N] or approach [m]; with ``steps`` points per branch (surface plasticity:
        the loading branch at equal approaches up to the peak's, the unloading one at equal
        approaches down to the residual interference; volume plasticity: equal increments of the
        force or approach up and down to zero).
    forces : array_like
        Or the loading force targets [N], rising strictly to the peak (force control).
    steps : int
        Points per branch with ``max_force`` or ``max_approach``.
    unloading_forces : array_like, optional
        With ``forces``: the unloading targets, falling strictly from the peak (default: the
        loading targets in reverse).
    reference_force : float, optional
        With ``forces``: the load of zero interference on loading (one of the targets; paper 002:
        25 uN); default the first touch.
    plasticity : SurfacePlasticity, VolumePlasticity, "surface" or "volume"
        The plastic model (module docstring).
    counter_body : Material, optional
        The flat (default rigid; surface plasticity only).
    substrate : Material, optional
        The substrate a film of ``film_thickness`` [m] of ``material`` is bonded to.
    film_thickness : float, optional
        With ``substrate``.
    boundary : {"periodic", "free"}, optional
        Default: the topography's periodic flag.
    tolerance, max_iterations
        Of the contact solves (:func:`roughcontact.contact.solve_normal`).

    Returns
    -------
    LoadUnloadResult

    Raises
    ------
    InputError
        No or several programmes, targets that do not rise to the peak or fall from it, a
        reference force not among the loading targets, no hardness, a film without its substrate
        or thickness; the solvers' refusals.
    ConvergenceError
        A step did not converge.

    Examples
    --------
    >>> path = load_unload(island, get_material("SU-8"), forces=np.linspace(0, 1e-3, 11))  # doctest: +SKIP
    >>> j2 = VolumePlasticity(depth=5e-5)
    >>> deep = load_unload(ball, steel, max_force=2e-3, plasticity=j2)  # doctest: +SKIP
    """
    topography = topography_argument(topography, "topography")
    plasticity = plasticity_model(plasticity)
    programmes = {"max_force": max_force, "max_approach": max_approach, "forces": forces}
    given = [name for name, value in programmes.items() if value is not None]
    if len(given) != 1:
        raise InputError(
            "max_force",
            "give exactly one programme: max_force, max_approach or forces "
            f"(found {', '.join(given) or 'none'}).",
            "e.g. max_force=1e-3 (N), or forces=np.linspace(0, 1e-3, 11).",
        )
    if (substrate is None) != (film_thickness is None):
        raise InputError(
            "substrate", "a film needs both substrate and film_thickness.", "give both, or neither."
        )
    layer = None if substrate is None else ElasticLayer(film_thickness, material, base=substrate)
    if forces is None:
        if steps < 2:
            raise InputError("steps", f"need at least 2 steps, got {steps}.", "use steps >= 2.")
        if reference_force is not None or unloading_forces is not None:
            raise InputError(
                "reference_force", "goes with force targets (forces=...).", "give forces=, or leave it out."
            )
        peak = ("force", max_force) if max_force is not None else ("approach", max_approach)
        targets = None
    else:
        targets = _force_targets(forces, unloading_forces, reference_force)
        peak = None
    if isinstance(plasticity, VolumePlasticity):
        if counter_body is not None:
            raise InputError(
                "counter_body", "volume plasticity is solved against a rigid flat.", "leave it out."
            )
        programme = (peak, steps, targets, reference_force)
        return _volume_path(
            topography, material, plasticity, programme, substrate, film_thickness, boundary, tolerance
        )
    hardness = material.hardness if plasticity.hardness is None else plasticity.hardness
    if hardness is None:
        raise InputError(
            "hardness",
            "no hardness given and the material has none.",
            "give SurfacePlasticity(hardness=...) in Pa.",
        )
    compliance = compliance_for(
        topography,
        None if layer is not None else material,
        counter_body=counter_body,
        layer=layer,
        boundary=boundary,
    )
    options = dict(
        hardness=hardness, tolerance=tolerance, max_iterations=max_iterations, compliance=compliance
    )
    if targets is None:
        solved, branch, residual = _approach_path(topography, peak, steps, options)
        zero = 0.0
    else:
        loading, unloading = targets
        solved = capped_path(topography, "force", loading, options, what="loading steps")
        flattened, residual = flattened_at(topography, solved[-1])
        solved += capped_path(flattened, "force", unloading, options, offset=residual, what="unloading steps")
        branch = np.array(["loading"] * loading.size + ["unloading"] * unloading.size)
        zero = (
            0.0
            if reference_force is None
            else solved[int(np.flatnonzero(loading == reference_force)[0])].approach
        )
    approach = np.array([s.approach for s in solved])
    peak_index = int(np.flatnonzero(branch == "loading")[-1])
    return LoadUnloadResult(
        branch=branch,
        interference=approach - zero,
        residual_interference=residual - zero,
        reference_force=reference_force,
        steps=tuple(solved),
        plastic_deformation=solved[peak_index].plastic_deformation,
        hardness=float(hardness),
        poissons_ratio=material.poissons_ratio,
        layer=layer,
    )


def _force_targets(forces, unloading_forces, reference_force) -> tuple[np.ndarray, np.ndarray]:
    """Check the force targets: loading rising strictly to the peak, unloading falling from it."""
    loading = np.asarray(forces, dtype=float)
    unloading = loading[::-1][1:] if unloading_forces is None else np.asarray(unloading_forces, dtype=float)
    if loading.ndim != 1 or loading.size < 2 or np.any(np.diff(loading) <= 0):
        raise InputError("forces", "must rise strictly to the peak force.", "e.g. [0, 25e-6, ..., 1e-3].")
    if np.any(np.diff(np.concatenate([[loading[-1]], unloading])) >= 0):
        raise InputError(
            "unloading_forces", "must fall strictly from the peak force.", "e.g. [8e-4, ..., 0]."
        )
    if reference_force is not None and not np.any(loading == reference_force):
        raise InputError("reference_force", "is not among the loading targets.", "add it to forces.")
    return loading, unloading


def _approach_path(topography: Topography, peak: tuple[str, float], steps: int, options: dict):
    """Surface plasticity to a peak force or approach: equal approaches up, and down to the residual."""
    top = solve_normal(topography, **{peak[0]: peak[1]}, **options)
    loading = capped_path(topography, "approach", np.linspace(0.0, top.approach, steps)[1:-1], options)
    loading.append(top)
    flattened, residual = flattened_at(topography, top)
    unloading = capped_path(
        flattened, "approach", np.linspace(top.approach, residual, steps)[1:], options, offset=residual
    )
    branch = np.array(["loading"] * len(loading) + ["unloading"] * len(unloading))
    return loading + unloading, branch, residual


def _volume_path(
    topography, material, plasticity, programme, substrate, film_thickness, boundary, tolerance
) -> LoadUnloadResult:
    """J2 plasticity in the volume through the programme (:func:`~.volume_plastic.solve_elastic_plastic`).

    ``programme`` is (peak, steps, force targets, reference force) as :func:`load_unload` made it.
    """
    peak, steps, targets, reference_force = programme
    depth = plasticity.depth
    if depth is None:
        depth = plasticity.layers * min(topography.spacing)
        depth = depth if substrate is None else min(depth, film_thickness)
    common = dict(
        yield_strength=plasticity.yield_strength,
        hardening_modulus=plasticity.hardening_modulus,
        depth=depth,
        layers=plasticity.layers,
        substrate=substrate,
        film_thickness=film_thickness,
        contact_tolerance=tolerance,
    )
    if targets is None:
        up = np.linspace(0.0, peak[1], steps + 1)[1:]
        programme = np.concatenate([up, up[::-1][1:], [0.0]])
        kind = "forces" if peak[0] == "force" else "approaches"
        path = solve_elastic_plastic(topography, material, boundary=boundary, **{kind: programme}, **common)
        zero = 0.0
    else:
        loading, unloading = targets
        path = solve_elastic_plastic(
            topography,
            material,
            forces=np.concatenate([loading, unloading]),
            boundary=boundary,
            branch=["loading"] * loading.size + ["unloading"] * unloading.size,
            **common,
        )
        zero = (
            0.0
            if reference_force is None
            else path.approach[int(np.flatnonzero(loading == reference_force)[0])]
        )
    return LoadUnloadResult(
        branch=np.asarray(path.branch),
        interference=path.approach - zero,
        residual_interference=path.residual_interference - zero,
        reference_force=reference_force,
        poissons_ratio=material.poissons_ratio,
        volume=path,
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
    touch: approaches are given, and returned, from the original surface's first touch.
    """
    steps, previous = [], None
    for target in tracked(targets, what=what):
        local = max(float(target) - offset, 0.0) if kind == "approach" else float(target)
        previous = solve_normal(topography, **{kind: local}, initial=previous, **options)
        steps.append(replace(previous, approach=previous.approach + offset))
    return steps
