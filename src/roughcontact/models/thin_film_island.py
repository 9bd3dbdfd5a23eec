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
substrate, a half-space of the film's material. The von Mises stress is that of a half-space under the
step's surface pressure (:func:`~roughcontact.elasticity.stress.subsurface_stress`).

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

import math
from dataclasses import dataclass

import numpy as np

from ..contact import NormalContactResult, compliance_for, solve_normal
from ..elasticity.halfspace import ElasticLayer
from ..elasticity.stress import StressField, subsurface_stress
from ..errors import InputError
from ..materials import Material
from ..topography import Topography
from ..topography.generate import gaussian_random, raised_island
from . import paper002


def paper002_island(
    shape: int | tuple[int, int] = 64, *, seed: int = 1, margin: float = 2.5e-6
) -> Topography:
    """Return a synthetic stand-in for paper 002's measured island (the scan itself is not published).

    A raised square of side 25 um and thickness 6.3 um
    (:func:`~roughcontact.topography.generate.raised_island`) in a window ``margin`` wider on each
    side. Its top carries Gaussian-correlated roughness with the paper's m0 exactly (Rq = 46.2 nm)
    and the correlation length xi = sqrt(2 m0 / m2) = 1.36 um, which gives the paper's m2 for a
    Gaussian autocorrelation (m2 = 2 m0 / xi^2). A Gaussian ACF has the bandwidth alpha = 3 (the
    paper's surface: 6.9), so m4 and R_asp differ from the printed ones.

    Parameters
    ----------
    shape : int or (int, int)
        Grid points (64 runs in about a second per step; 128 resolves xi with 4 pixels).
    seed : int
        Seed of the roughness.
    margin : float
        Substrate margin around the island [m].

    Returns
    -------
    Topography
        Non-periodic heights [m], island top about 6.3 um above the substrate.
    """
    if not margin >= 0:
        raise InputError("margin", f"must be >= 0, got {margin!r}.", "give a margin in m.")
    shape = (shape, shape) if isinstance(shape, int) else tuple(shape)
    size = paper002.ISLAND_SIDE + 2.0 * margin
    flat = raised_island(shape, size, island_size=paper002.ISLAND_SIDE, thickness=paper002.FILM_THICKNESS)
    moments = paper002.MOMENTS
    correlation = math.sqrt(2.0 * moments["m0"] / moments["m2"])
    roughness = gaussian_random(
        shape, size, rms_height=1.0, correlation_length=correlation, seed=seed
    ).heights
    on_island = flat.heights > 0.5 * paper002.FILM_THICKNESS
    top = roughness[on_island] - roughness[on_island].mean()
    heights = flat.heights.copy()
    heights[on_island] += top * math.sqrt(moments["m0"] / np.mean(top**2))
    info = dict(flat.info, name="paper 002 island (synthetic)", correlation_length=correlation, seed=seed)
    return flat.with_heights(heights, step="Gaussian-correlated roughness with paper 002's m0, m2", info=info)


@dataclass(frozen=True)
class IslandCompression:
    """Load-unload of an island against a rigid flat punch, force-controlled (SI).

    Attributes
    ----------
    steps : tuple of NormalContactResult
        One solution per target load, loading then unloading (unloading on the flattened surface;
        its ``approach`` counts from that surface's own first touch).
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
    """

    steps: tuple[NormalContactResult, ...]
    branch: np.ndarray
    interference: np.ndarray
    plastic_deformation: np.ndarray
    residual_interference: float
    reference_force: float
    hardness: float
    poissons_ratio: float

    def curve(self) -> dict[str, np.ndarray]:
        """Return branch, approach (interference) [m], force [N], area [m^2], plastic fraction, p_max."""
        return {
            "branch": self.branch,
            "approach": self.interference,
            "force": np.array([s.force for s in self.steps]),
            "contact_area": np.array([s.contact_area for s in self.steps]),
            "plastic_fraction": np.array([s.plastic_mask.mean() for s in self.steps]),
            "max_pressure": np.array([float(s.pressure.max()) for s in self.steps]),
        }

    def stress(self, index: int, depths=(0.0,), *, padding: int = 2) -> StressField:
        """Return the subsurface stress of step ``index`` on the planes ``depths`` [m] (``.von_mises()``)."""
        step = self.steps[index]
        return subsurface_stress(
            step.pressure,
            step.topography.size,
            depths,
            poissons_ratio=self.poissons_ratio,
            boundary="free",
            padding=padding,
        )


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
) -> IslandCompression:
    """Load an island to ``peak_force`` with a rigid flat punch and unload it (paper 002 Figs. 7-9).

    Parameters
    ----------
    topography : Topography
        Non-periodic heights [m] towards the punch (e.g. :func:`paper002_island` or a measured scan).
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

    Returns
    -------
    IslandCompression

    Raises
    ------
    InputError
        No hardness, targets that do not rise to the peak or fall from it, a reference force not among
        the loading targets; see :func:`~roughcontact.contact.solve_normal` for the solver's.
    ConvergenceError
        A step did not converge.
    """
    hardness = material.hardness if hardness is None else hardness
    if hardness is None:
        raise InputError("hardness", "the material has no hardness.", "pass hardness= in Pa.")
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
    if substrate is None:
        compliance = compliance_for(topography, material, boundary="free")
    else:
        layer = ElasticLayer(film_thickness, material, base=substrate)
        compliance = compliance_for(topography, None, layer=layer, boundary="free")
    options = dict(hardness=hardness, compliance=compliance, tolerance=tolerance)

    steps, previous = [], None
    for force in loading:
        previous = solve_normal(topography, force=float(force), initial=previous, **options)
        steps.append(previous)
    plastic = previous.plastic_deformation
    flattened = topography.with_heights(topography.heights - plastic, step="plastic flattening at the peak")
    # The flattened surface's first touch lies this much further than the original one's.
    offset = float(np.min(topography.heights.max() - topography.heights + plastic))
    previous = None
    for force in unloading:
        previous = solve_normal(flattened, force=float(force), initial=previous, **options)
        steps.append(previous)

    zero = steps[int(np.flatnonzero(loading == reference_force)[0])].approach
    approach = np.array([s.approach for s in steps]) + np.where(
        np.arange(len(steps)) < loading.size, 0.0, offset
    )
    return IslandCompression(
        steps=tuple(steps),
        branch=np.array(["loading"] * loading.size + ["unloading"] * unloading.size),
        interference=approach - zero,
        plastic_deformation=plastic,
        residual_interference=offset - zero,
        reference_force=reference_force,
        hardness=float(hardness),
        poissons_ratio=material.poissons_ratio,
    )
