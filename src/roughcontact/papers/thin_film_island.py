r"""Flat-punch compression of a raised thin-film island: the deterministic model of seed paper 002.

A rough island (paper 002: a 25 um x 25 um SU-8 square, 6.3 um thick, on a silicon wafer) is loaded
by a rigid flat punch to a peak force and unloaded, with the elastic-perfectly-plastic surface model
of :mod:`roughcontact.contact.plastic`: the pressure is capped at the hardness, the overlap at the cap
is kept as plastic flattening, and unloading is elastic on the flattened surface. The steps are
force-controlled at the paper's loads, so the von Mises maps of Figs. 8-9 (loading 0-1000 uN,
unloading 800-0 uN) come straight from the steps. The interference follows the experiment's
convention: omega = 0 where the loading branch carries 25 uN, the smallest load the nanoindenter
resolves.

The body is the film bonded to its substrate (:class:`~roughcontact.elasticity.halfspace.ElasticLayer`;
the layer is laterally infinite, so the island's free side walls are not modelled) or, without a
substrate, a half-space of the film's material. The von Mises stress is that of the same body (the
film on its substrate, or the half-space) under the step's surface pressure
(:func:`~roughcontact.elasticity.stress.subsurface_stress`).

How this differs from the paper's explicit finite elements (LS-DYNA, piecewise-linear plasticity,
10 800 elements): plasticity is confined to the surface (pressure cap at H; no subsurface plastic zone,
no hardening, no residual stress after unloading, so the maps at 0 uN on unloading are empty where the
FEM shows residual stress), strains are small, the analysis is quasi-static (no inertia or rate), and
the topography here is a synthetic stand-in unless a measured scan is given. It should agree with the
FEM on the load-interference curve where the contact pressure has saturated at H over a plastic zone
that is shallow compared with the contact patches, and on where contact (high stress) forms.

References
----------
Seed paper 002, sections II-III and VI, Figs. 7-9.
Almqvist, A. et al. (2007), Tribol. Int. 40, 574-579. doi:10.1016/j.triboint.2005.11.008
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .._deprecation import moved
from ..contact import NormalContactResult, compliance_for
from ..contact.plastic import (
    LOAD_UNLOAD_UNITS,
    capped_path,
    flattened_at,
    load_unload_curve,
    load_unload_dataset,
    load_unload_scalars,
)
from ..contact.volume_plastic import VOLUME_UNITS, VolumePlasticResult, solve_elastic_plastic
from ..elasticity.halfspace import ElasticLayer
from ..elasticity.stress import StressField, subsurface_stress
from ..errors import InputError
from ..materials import Material
from ..topography import Topography
from . import paper002

PLASTICITY = ("surface", "volume")
"""Plasticity models of :func:`compress_island`: the surface cap at the hardness, or J2 in the volume."""


@dataclass(frozen=True)
class IslandCompression:
    """Load-unload of an island against a rigid flat punch, force-controlled (SI).

    Attributes
    ----------
    steps : tuple of NormalContactResult
        One solution per target load, loading then unloading (unloading on the flattened surface;
        every ``approach`` counts from the original surface's first touch).
    branch : ndarray of str
        "loading" or "unloading" per step.
    interference : ndarray
        omega [m] per step in the experiment's convention (zero at ``reference_force`` on loading).
    plastic_deformation : ndarray
        Plastic flattening at the peak [m].
    residual_interference : float
        omega at which the unloaded surface carries no load [m].
    reference_force : float
        Load of zero interference [N].
    hardness : float
        Pressure cap [Pa].
    poissons_ratio : float
        Of the film, for the stress maps.
    layer : ElasticLayer, optional
        The film on its substrate, whose stress the maps show (None: a half-space of the film).
    """

    steps: tuple[NormalContactResult, ...]
    branch: np.ndarray
    interference: np.ndarray
    plastic_deformation: np.ndarray
    residual_interference: float
    reference_force: float
    hardness: float
    poissons_ratio: float
    layer: ElasticLayer | None = None

    UNITS: ClassVar[dict[str, str]] = LOAD_UNLOAD_UNITS
    """SI unit of each dimensional scalar of :meth:`scalars`."""

    @property
    def peak(self) -> int:
        """Index of the peak load: the last step of the loading branch."""
        return int(np.flatnonzero(self.branch == "loading")[-1])

    @property
    def converged(self) -> bool:
        """True when every step met its tolerance (the solver raises rather than return otherwise)."""
        return all(step.converged for step in self.steps)

    @property
    def iterations(self) -> int:
        """Iterations of every step's solve together."""
        return sum(step.iterations for step in self.steps)

    @property
    def residual(self) -> float:
        """Largest residual of the steps."""
        return max(step.residual for step in self.steps)

    def curve(self) -> dict[str, np.ndarray]:
        """Return the path, one entry per step (:func:`~roughcontact.contact.plastic.load_unload_curve`).

        ``approach`` is the interference in the experiment's convention (zero at
        ``reference_force`` on loading), ``plastic_fraction`` the fraction of the real contact
        area at the hardness.
        """
        return load_unload_curve(self.steps, self.peak + 1, self.interference)

    def scalars(self) -> dict[str, float]:
        """Return the peak, the residual interference and the plastic flow (SI; units in :attr:`UNITS`)."""
        found = load_unload_scalars(
            self.steps,
            self.peak,
            self.interference[self.peak],
            self.residual_interference,
            self.plastic_deformation,
            self.hardness,
        )
        return found | {"iterations": self.iterations, "residual": self.residual}

    def to_xarray(self):
        """Return the curve as an ``xarray.Dataset`` on the dimension ``point`` (SI, with units)."""
        return load_unload_dataset(self.curve(), self.scalars() | {"reference_force": self.reference_force})

    def stress(self, index: int, depths=(0.0,), *, padding: int = 2) -> StressField:
        """Return the subsurface stress of step ``index`` on the planes ``depths`` [m] (``.von_mises()``).

        That of the film on its substrate when the island was compressed with one, else of a half-space.
        """
        step = self.steps[index]
        return subsurface_stress(
            step.pressure,
            step.topography.size,
            depths,
            poissons_ratio=self.poissons_ratio,
            boundary="free",
            padding=padding,
            layer=self.layer,
        )


@dataclass(frozen=True)
class IslandVolumeCompression:
    """Load-unload of an island with plasticity in the volume (``compress_island(plasticity="volume")``).

    Attributes
    ----------
    path : VolumePlasticResult
        The steps, loading then unloading, with their fields (pressure, von Mises and plastic
        strain at every depth, residual stress at the end).
    interference : ndarray
        omega [m] per step in the experiment's convention (zero at ``reference_force`` on loading).
    residual_interference : float
        omega at which the unloaded surface first touches the punch [m].
    reference_force : float
        Load of zero interference [N].
    """

    path: VolumePlasticResult
    interference: np.ndarray
    residual_interference: float
    reference_force: float

    UNITS: ClassVar[dict[str, str]] = VOLUME_UNITS
    """SI unit of each dimensional scalar of :meth:`scalars`."""

    @property
    def peak(self) -> int:
        """Index of the peak load."""
        return self.path.peak

    @property
    def branch(self) -> np.ndarray:
        """Branch of each step: "loading" or "unloading"."""
        return self.path.branch

    @property
    def force(self) -> np.ndarray:
        """Load of each step [N]."""
        return self.path.force

    @property
    def converged(self) -> bool:
        """True when every step met its tolerance (the solver raises otherwise)."""
        return self.path.converged

    @property
    def iterations(self) -> int:
        """Fixed-point iterations of all steps."""
        return self.path.iterations

    @property
    def residual(self) -> float:
        """Largest final residual of the steps."""
        return self.path.residual

    def curve(self) -> dict[str, np.ndarray]:
        """Return the path, one entry per step; ``approach`` is the interference (zero at the reference)."""
        return self.path.curve() | {"approach": self.interference}

    def scalars(self) -> dict[str, float]:
        """Return the path's scalars with the interferences in the experiment's convention (SI)."""
        return self.path.scalars() | {
            "peak_interference": float(self.interference[self.peak]),
            "residual_interference": self.residual_interference,
        }

    def to_xarray(self):
        """Return the curve as an ``xarray.Dataset`` on the dimension ``point`` (SI, with units)."""
        data = self.path.to_xarray()
        data["approach"] = ("point", self.interference, {"units": "m"})
        data.attrs.update(self.scalars() | {"reference_force": self.reference_force})
        return data


def _volume_depth(topography: Topography, layers: int, substrate, film_thickness: float) -> float:
    """Default depth of the plastic volume: cells as thick as a pixel, within the film if there is one."""
    depth = layers * min(topography.spacing)
    return depth if substrate is None else min(depth, film_thickness)


def _default_loading(peak_force: float, reference_force: float) -> np.ndarray:
    return np.unique(np.concatenate([np.linspace(0.0, peak_force, 11), [reference_force]]))


def compress_island(
    topography: Topography,
    material: Material,
    *,
    peak_force: float = paper002.PEAK_FORCE,
    substrate: Material | None = None,
    film_thickness: float = paper002.FILM_THICKNESS,
    hardness: float | None = None,
    loading_forces=None,
    unloading_forces=None,
    reference_force: float = paper002.REFERENCE_FORCE,
    tolerance: float = 1e-8,
    plasticity: str = "surface",
    yield_strength: float | None = None,
    hardening_modulus: float = 0.0,
    depth: float | None = None,
    layers: int = 16,
) -> IslandCompression | IslandVolumeCompression:
    """Load an island to ``peak_force`` with a rigid flat punch and unload it (paper 002 Figs. 7-9).

    Parameters
    ----------
    topography : Topography
        Non-periodic heights [m] towards the punch (e.g. :func:`~roughcontact.papers.paper002.paper002_island`
        or a measured scan).
    material : Material
        The film (paper 002: ``get_material("SU-8")``); its hardness is the cap unless ``hardness``.
    peak_force : float
        Peak load [N] (1000 uN).
    substrate : Material, optional
        The substrate the film of ``film_thickness`` is bonded to (``get_material("silicon wafer")``);
        default: the film is a half-space.
    film_thickness : float
        Film thickness [m] (6.3 um), used with ``substrate``.
    hardness : float, optional
        Pressure cap [Pa].
    loading_forces, unloading_forces : array_like, optional
        Target loads [N]; default loading 0, reference, 0.1 ... 1.0 x peak, and unloading through the
        loading targets in reverse, down to 0. The loading list must end at ``peak_force``.
    reference_force : float
        Load of zero interference [N] (25 uN); it must be one of the loading targets.
    tolerance : float
        Solver tolerance (:func:`~roughcontact.contact.solve_normal`).
    plasticity : {"surface", "volume"}
        "surface": the pressure cap at the hardness (the cheaper approximation, module docstring);
        "volume": J2 plasticity below the surface
        (:func:`~roughcontact.contact.volume_plastic.solve_elastic_plastic`), with the film's
        ``yield_strength`` (default the material's), ``hardening_modulus`` [Pa] and a volume
        ``depth`` [m] of ``layers`` cells (default: cells as thick as a pixel, within the film).

    Returns
    -------
    IslandCompression or IslandVolumeCompression

    Raises
    ------
    InputError
        No hardness, targets that do not rise to the peak or fall from it, a reference force not among
        the loading targets; see :func:`~roughcontact.contact.solve_normal` for the solver's.
    ConvergenceError
        A step did not converge.
    """
    if plasticity not in PLASTICITY:
        raise InputError("plasticity", f"unknown plasticity {plasticity!r}.", f"use one of {PLASTICITY}.")
    if loading_forces is None:
        loading = _default_loading(peak_force, reference_force)
    else:
        loading = np.asarray(loading_forces, dtype=float)
    unloading = loading[::-1][1:] if unloading_forces is None else np.asarray(unloading_forces, dtype=float)
    if loading[-1] != peak_force or np.any(np.diff(loading) <= 0):
        raise InputError("loading_forces", "must rise strictly to peak_force.", "e.g. [0, 25e-6, ..., 1e-3].")
    if np.any(np.diff(np.concatenate([[peak_force], unloading])) >= 0):
        raise InputError("unloading_forces", "must fall strictly from peak_force.", "e.g. [8e-4, ..., 0].")
    if not np.any(loading == reference_force):
        raise InputError("reference_force", "is not among the loading targets.", "add it to loading_forces.")
    if plasticity == "volume":
        path = solve_elastic_plastic(
            topography,
            material,
            forces=np.concatenate([loading, unloading]),
            yield_strength=yield_strength,
            hardening_modulus=hardening_modulus,
            depth=_volume_depth(topography, layers, substrate, film_thickness) if depth is None else depth,
            layers=layers,
            substrate=substrate,
            film_thickness=film_thickness if substrate is not None else None,
            boundary="free",
            contact_tolerance=tolerance,
            branch=["loading"] * loading.size + ["unloading"] * unloading.size,
        )
        zero = path.approach[int(np.flatnonzero(loading == reference_force)[0])]
        return IslandVolumeCompression(
            path, path.approach - zero, path.residual_interference - zero, reference_force
        )
    hardness = material.hardness if hardness is None else hardness
    if hardness is None:
        raise InputError("hardness", "the material has no hardness.", "pass hardness= in Pa.")
    layer = None
    if substrate is None:
        compliance = compliance_for(topography, material, boundary="free")
    else:
        layer = ElasticLayer(film_thickness, material, base=substrate)
        compliance = compliance_for(topography, None, layer=layer, boundary="free")
    options = dict(hardness=hardness, compliance=compliance, tolerance=tolerance)
    steps = capped_path(topography, "force", loading, options, what="loading steps")
    flattened, offset = flattened_at(topography, steps[-1])
    steps += capped_path(flattened, "force", unloading, options, offset=offset, what="unloading steps")
    zero = steps[int(np.flatnonzero(loading == reference_force)[0])].approach
    approach = np.array([s.approach for s in steps])
    return IslandCompression(
        steps=tuple(steps),
        branch=np.array(["loading"] * loading.size + ["unloading"] * unloading.size),
        interference=approach - zero,
        plastic_deformation=steps[loading.size - 1].plastic_deformation,
        residual_interference=offset - zero,
        reference_force=reference_force,
        hardness=float(hardness),
        poissons_ratio=material.poissons_ratio,
        layer=layer,
    )


def __getattr__(name: str):
    """Serve :func:`roughcontact.papers.paper002.paper002_island`, which moved there, with a warning."""
    return moved(__name__, name, {"paper002_island": "roughcontact.papers.paper002"})
