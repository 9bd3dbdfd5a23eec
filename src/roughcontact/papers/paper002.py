"""Seed paper 002's printed inputs and numbers, and the paper-vs-ours table.

The printed spectral moments (eqs. 1-3) and Table I reproduce R_asp, sigma_s, omega_c and psi with
the standard composite modulus 1/E' = sum (1 - nu^2)/E; eq. 7 as printed, with (1 - nu), does not,
and the printed E' = 8.31 GPa matches neither form (:doc:`/asperity`).

References
----------
Seed paper 002, "Contact stress analysis of lightly compressed thin films: modeling and
experimentation", eqs. 1-9, Table I and section IV (DOI not given in the seed text).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._deprecation import renamed
from ..asperity.greenwood_williamson import gaussian_summits
from ..asperity.load_unload import StatisticalLoadUnload, statistical_load_unload
from ..asperity.parameters import AsperityParameters, asperity_parameters
from ..contact.load_unload import (
    LoadUnloadResult,
    force_targets,
    load_unload,
    plasticity_model,
)
from ..errors import InputError
from ..materials import Material, get_material
from ..topography import Topography
from ..topography.generate import gaussian_random, matched_moments, raised_island
from ..topography.statistics import mccool_parameters
from ..units import written

MOMENTS = {"m0": 0.00213279e-12, "m2": 0.00230023, "m4": 0.0171036e12}
"""Printed spectral moments (eqs. 1-3) in SI: m0 [m^2], m2 [-], m4 [1/m^2]."""

ISLAND_SIDE = 25e-6
"""Side of the raised square [m] (section II)."""

FILM_THICKNESS = 6.3e-6
"""Measured island thickness [m] (section II)."""

PEAK_FORCE = 1000e-6
"""Peak load of the compression test [N] (section III)."""

REFERENCE_FORCE = 25e-6
"""Load at which the interference is taken as zero [N] (section III)."""

TIP_ROUGHNESS = 10e-9
"""Upper bound of the flat tip's roughness [m] (section III), used for the psi = 2.06 remark."""

MATERIAL, SUBSTRATE, PUNCH = "SU-8", "silicon wafer", "diamond flat tip"
"""The library materials of the film, its substrate and the flat punch (Table I)."""


def asperity_keys() -> dict[str, Any]:
    """Return the keys of paper 002's ``asperity`` analysis as a study file writes them (with units).

    The printed moments (eqs. 1-3), the film and the punch (Table I), the peak load, the nominal
    area of the island and the reference load: what ``paper002 = true`` fills in where an analysis
    leaves a key out.
    """
    return {
        "m0": written(MOMENTS["m0"], "m^2"),
        "m2": MOMENTS["m2"],
        "m4": written(MOMENTS["m4"], "1/m^2"),
        "material": MATERIAL,
        "counter_body": PUNCH,
        "max_force": written(PEAK_FORCE, "N"),
        "nominal_area": written(ISLAND_SIDE**2, "m^2"),
        "reference_force": written(REFERENCE_FORCE, "N"),
    }


def load_unload_keys() -> dict[str, Any]:
    """Return the keys of paper 002's ``load_unload`` analysis (the island under the punch), with units.

    The film on its substrate (Table I, section II), the peak and reference loads (section III):
    what ``paper002 = true`` fills in where an analysis leaves a key out.
    """
    return {
        "material": MATERIAL,
        "substrate": SUBSTRATE,
        "film_thickness": written(FILM_THICKNESS, "m"),
        "max_force": written(PEAK_FORCE, "N"),
        "reference_force": written(REFERENCE_FORCE, "N"),
    }


STATISTICAL_WORDS = "slightly over-predicts"
"""Paper 002's words on the KKE model (sections VII and VIII: it "slightly overpredicted the surface
deformation when compared to experiment"), shown beside the ratio of KKE to the BEM that a study
measures. The paper compares ONE island (the measured one) with the model, without an interval."""

PRINTED = {
    "summit_radius": 5.08e-6,
    "summit_height_std": 0.0431e-6,
    "contact_modulus": 8.31e9,
    "contact_pressure_factor": 0.544,
    "critical_interference": 0.0125e-6,
    "plasticity_index": 1.86,
    "plasticity_index_rough_tip": 2.06,
}
"""The values printed in section IV (SI)."""


@dataclass(frozen=True)
class ComparisonRow:
    """One row of the paper-vs-ours table (SI).

    Attributes
    ----------
    key : str
        Name of the quantity.
    symbol : str
        Its symbol in the paper, with the equation.
    unit : str
        SI unit ("" for dimensionless).
    paper : float or None
        Printed value (None where the paper prints none).
    standard : float
        Ours with the standard composite modulus (1 - nu^2).
    printed_eq7 : float
        Ours with eq. 7 as printed (1 - nu).
    """

    key: str
    symbol: str
    unit: str
    paper: float | None
    standard: float
    printed_eq7: float

    @property
    def deviation(self) -> float | None:
        """Relative deviation of the standard value from the paper's [-] (None without a printed value)."""
        return None if self.paper is None else self.standard / self.paper - 1.0


def comparison() -> list[ComparisonRow]:
    """Recompute section IV of paper 002 from its printed moments and Table I, in both readings of equation 7.

    The last row is the plasticity index for a 10 nm rough tip: the paper's 2.06 follows from adding
    the roughnesses linearly (sigma_s + 10 nm); the "standard" column adds them in quadrature (the
    sound combination of independent roughnesses), the "printed_eq7" column linearly with the
    standard modulus, which reproduces 2.06.

    Returns
    -------
    list of ComparisonRow
    """
    sample, tip = get_material(MATERIAL), get_material(PUNCH)
    ours = {
        form: asperity_parameters(**MOMENTS, sample=sample, counter_body=tip, modulus_form=form)
        for form in ("standard", "paper002_eq7_printed")
    }
    standard, printed = ours["standard"], ours["paper002_eq7_printed"]
    rows = [
        ComparisonRow("bandwidth", "alpha = m0 m4 / m2^2", "", None, standard.bandwidth, printed.bandwidth),
        ComparisonRow(
            "summit_density", "eta (McCool)", "1/m^2", None, standard.summit_density, printed.summit_density
        ),
    ]
    symbols = {
        "summit_radius": ("R_asp (eq. 4)", "m"),
        "summit_height_std": ("sigma_s (eq. 5)", "m"),
        "contact_modulus": ("E' (eq. 7)", "Pa"),
        "contact_pressure_factor": ("K (eq. 8)", ""),
        "critical_interference": ("omega_c (eq. 6)", "m"),
        "plasticity_index": ("psi (eq. 9)", ""),
    }
    for key, (symbol, unit) in symbols.items():
        rows.append(
            ComparisonRow(key, symbol, unit, PRINTED[key], getattr(standard, key), getattr(printed, key))
        )
    rows.append(
        ComparisonRow(
            "critical_load",
            "W_c = P_c (Hertz at omega_c)",
            "N",
            None,
            standard.critical_load,
            printed.critical_load,
        )
    )
    sigma, omega_c = standard.summit_height_std, standard.critical_interference
    rows.append(
        ComparisonRow(
            "plasticity_index_rough_tip",
            "psi, 10 nm tip (quadrature | linear)",
            "",
            PRINTED["plasticity_index_rough_tip"],
            math.sqrt(math.hypot(sigma, TIP_ROUGHNESS) / omega_c),
            math.sqrt((sigma + TIP_ROUGHNESS) / omega_c),
        )
    )
    return rows


def parameters() -> AsperityParameters:
    """Return the asperity parameters of SU-8 against the diamond flat tip from the printed moments (SI)."""
    return asperity_parameters(**MOMENTS, sample=get_material(MATERIAL), counter_body=get_material(PUNCH))


def statistical_curve(law: str = "kogut_etsion") -> StatisticalLoadUnload:
    """Return the statistical load-unload of the paper's island (Gaussian summits of the printed moments).

    Table I's SU-8 against the diamond flat tip, 1000 uN on the 25 x 25 um square, interference zero at
    25 uN, as in the paper's Fig. 7.

    Parameters
    ----------
    law : str
        Loading law of one summit (:data:`roughcontact.asperity.load_unload.LOADING_LAWS`).

    Returns
    -------
    StatisticalLoadUnload
    """
    su8 = get_material(MATERIAL)
    return statistical_load_unload(
        gaussian_summits(mccool_parameters(**MOMENTS)),
        contact_modulus=parameters().contact_modulus,
        hardness=su8.hardness,
        poissons_ratio=su8.poissons_ratio,
        yield_strength=su8.yield_strength,
        max_force=PEAK_FORCE,
        nominal_area=ISLAND_SIDE**2,
        reference_force=REFERENCE_FORCE,
        law=law,
    )


ISLAND_ROUGHNESS = ("moments", "gaussian")
"""Stand-ins of the island's roughness: matched to all three printed moments, or to m0 and m2 only."""

ISLAND_HURST = 0.8
"""Hurst exponent of the matched-moments stand-in (assumed: the paper gives the moments only)."""


def paper002_island(
    shape: int | tuple[int, int] = 64, *, seed: int = 1, margin: float = 2.5e-6, roughness: str = "moments"
) -> Topography:
    """Return a synthetic stand-in for paper 002's measured island (the scan itself is not published).

    A raised square of side 25 um and thickness 6.3 um
    (:func:`~roughcontact.topography.generate.raised_island`) in a window ``margin`` wider on each
    side, its top carrying roughness chosen by ``roughness``:

    * ``"moments"`` (default): :func:`~roughcontact.topography.generate.matched_moments` of the
      paper's printed m0, m2 and m4 (eqs. 1-3; bandwidth alpha = 6.9), a plateau and power law of
      Hurst :data:`ISLAND_HURST` (assumed) over the window's period, drawn per wavevector
      (``modes="wavevector"``): the same island on every grid, so a mesh-convergence study refines
      one surface. Its expected moments are the paper's; one realisation scatters about them
      (12 % in m0, 5 % in m2, 3.5 % in m4 on a 25 um square), and grids coarser than 19 pixels per
      shortest wavelength (1.07 um) hold the same field truncated, whose finite-difference m4
      reads low (``coarse="truncate"``; 64 px: 63 %, 256 px: 91 %, 512 px: 92 % of the paper's on
      the 25 um square).
    * ``"gaussian"`` (release 0.2): Gaussian-correlated roughness with the paper's m0 exactly
      (Rq = 46.2 nm) and the correlation length xi = sqrt(2 m0 / m2) = 1.36 um, which gives the
      paper's m2 for a Gaussian autocorrelation (m2 = 2 m0 / xi^2); its bandwidth is alpha = 3
      (the paper's surface: 6.9), so m4 and R_asp differ from the printed ones, and another grid
      draws another surface.

    Parameters
    ----------
    shape : int or (int, int)
        Grid points (64 runs in about a second per step; 128 resolves xi with 4 pixels).
    seed : int
        Seed of the roughness.
    margin : float
        Substrate margin around the island [m].
    roughness : {"moments", "gaussian"}
        The stand-in's roughness, see above.

    Returns
    -------
    Topography
        Non-periodic heights [m], island top about 6.3 um above the substrate; ``info`` records
        the roughness and the target moments.
    """
    if not margin >= 0:
        raise InputError("margin", f"must be >= 0, got {margin!r}.", "give a margin in m.")
    if roughness not in ISLAND_ROUGHNESS:
        raise InputError("roughness", f"unknown stand-in {roughness!r}.", f"use one of {ISLAND_ROUGHNESS}.")
    shape = (shape, shape) if isinstance(shape, int) else tuple(shape)
    size = ISLAND_SIDE + 2.0 * margin
    flat = raised_island(shape, size, island_size=ISLAND_SIDE, thickness=FILM_THICKNESS)
    on_island = flat.heights > 0.5 * FILM_THICKNESS
    heights = flat.heights.copy()
    info = dict(flat.info, name="paper 002 island (synthetic)", seed=seed, roughness=roughness, **MOMENTS)
    if roughness == "moments":
        field = matched_moments(
            shape, size, **MOMENTS, hurst=ISLAND_HURST, seed=seed, modes="wavevector", coarse="truncate"
        )
        heights[on_island] += field.heights[on_island]
        info |= {k: field.info[k] for k in ("short_cutoff", "long_cutoff", "hurst", "resolved")}
        step = "roughness of paper 002's m0, m2, m4 (matched_moments, per wavevector)"
        return flat.with_heights(heights, step=step, info=info)
    correlation = math.sqrt(2.0 * MOMENTS["m0"] / MOMENTS["m2"])
    field = gaussian_random(shape, size, rms_height=1.0, correlation_length=correlation, seed=seed).heights
    top = field[on_island] - field[on_island].mean()
    heights[on_island] += top * math.sqrt(MOMENTS["m0"] / np.mean(top**2))
    info["correlation_length"] = correlation
    return flat.with_heights(heights, step="Gaussian-correlated roughness with paper 002's m0, m2", info=info)


def island_roughness(shape: int = 256, *, seed: int = 1) -> Topography:
    """Return the roughness of the island's top alone, periodic over the island's side (25 um).

    The stand-in of :func:`paper002_island` without the island's step: the printed m0, m2 and m4
    (eqs. 1-3) drawn per wavevector by :func:`~roughcontact.topography.generate.matched_moments`
    (Hurst :data:`ISLAND_HURST`, assumed; ``coarse="truncate"``: below 19 pixels per shortest
    wavelength the grid holds the field truncated), over the island's side as the period. For the
    theories of rough contact (:mod:`roughcontact.theory`), which are of an infinite surface: the
    top's contact is their question, the island's edge a punch's.

    Parameters
    ----------
    shape : int
        Grid points per side (256: a pixel of 98 nm, 11 per shortest wavelength).
    seed : int
        Seed of the roughness.

    Returns
    -------
    Topography
        Periodic heights [m], zero mean.
    """
    return matched_moments(
        (shape, shape),
        ISLAND_SIDE,
        **MOMENTS,
        hurst=ISLAND_HURST,
        seed=seed,
        modes="wavevector",
        coarse="truncate",
    )


def island_pressures(count: int = 5) -> np.ndarray:
    """Return nominal pressures on the island's top [Pa]: the paper's loads over its 25 um x 25 um.

    ``count`` loads spaced logarithmically from the reference load (25 uN, where the paper takes the
    interference as zero) to the peak (1000 uN), over the island's area: 0.04 to 1.6 MPa.
    """
    return np.geomspace(REFERENCE_FORCE, PEAK_FORCE, count) / ISLAND_SIDE**2


def island_top_moments(island: Topography, *, edge: float = 0.2e-6) -> dict[str, float]:
    """Return the spectral moments (equations 1-3) and bandwidth of a stand-in island's top and the paper's.

    The top is the window of the island (heights above half the film thickness) less ``edge`` [m]
    on each side (the step of the side walls). Keys ``top_m0``, ``top_m2``, ``top_m4``,
    ``top_bandwidth`` (this draw, finite differences of
    :func:`~roughcontact.topography.statistics.spectral_moments`) and ``paper_m0`` ... (printed).
    """
    from ..topography.process import crop
    from ..topography.statistics import spectral_moments

    top = island.heights > 0.5 * FILM_THICKNESS
    if not top.any():
        raise InputError("topography", "no island top (nothing above half the film thickness).", None)
    spacing = [s / n for s, n in zip(island.size, island.shape, strict=True)]
    box = [np.flatnonzero(top.any(axis=1 - axis)) for axis in (0, 1)]
    window = [(b[0] * h + edge, (b[-1] + 1) * h - edge) for b, h in zip(box, spacing, strict=True)]
    moments = spectral_moments(crop(island, *window))
    printed = MOMENTS["m0"] * MOMENTS["m4"] / MOMENTS["m2"] ** 2
    return {
        "top_m0": moments.m0,
        "top_m2": moments.m2,
        "top_m4": moments.m4,
        "top_bandwidth": moments.m0 * moments.m4 / moments.m2**2,
        **{f"paper_{name}": value for name, value in MOMENTS.items()},
        "paper_bandwidth": printed,
    }


IslandCompression = LoadUnloadResult
"""What :func:`compress_island` returns, with either plastic model: the one load-unload result."""

IslandVolumeCompression = LoadUnloadResult
"""The same result with volume plasticity (release 0.1 had two classes)."""


@renamed(peak_force="max_force")
def compress_island(
    topography: Topography,
    material: Material,
    *,
    max_force: float = PEAK_FORCE,
    substrate: Material | None = None,
    film_thickness: float = FILM_THICKNESS,
    hardness: float | None = None,
    loading_forces=None,
    unloading_forces=None,
    reference_force: float = REFERENCE_FORCE,
    tolerance: float = 1e-8,
    plasticity: str = "surface",
    yield_strength: float | None = None,
    hardening_modulus: float = 0.0,
    depth: float | None = None,
    layers: int = 16,
) -> LoadUnloadResult:
    """Load paper 002's island to ``max_force`` with a rigid flat punch and unload it (figures 7-9).

    Paper 002's scenario on :func:`roughcontact.contact.load_unload.load_unload`: force control at
    the paper's loads (0, 100, ..., 1000 uN and 25 uN, unloading back through them), interference zero at
    ``reference_force`` (25 uN, the smallest load the paper's nanoindenter resolves), the film of
    ``film_thickness`` (6.3 um) bonded to ``substrate`` where one is given, a free boundary.

    Parameters
    ----------
    topography : Topography
        Non-periodic heights [m] towards the punch (:func:`paper002_island` or a measured scan).
    material : Material
        The film (``get_material("SU-8")``); its hardness caps the pressure unless ``hardness``.
    max_force, reference_force : float
        [N] (1000 uN and 25 uN).
    substrate : Material, optional
        The substrate (``get_material("silicon wafer")``); default: the film is a half-space.
    film_thickness : float
        [m], with ``substrate``.
    hardness : float, optional
        Pressure cap [Pa] of the surface model.
    loading_forces, unloading_forces : array_like, optional
        Target loads [N]; default the paper's and back down. The loading list must end at
        ``max_force``.
    tolerance : float
        Of the contact solves.
    plasticity : {"surface", "volume"}
        The cap at the hardness, or J2 in the volume with ``yield_strength``, ``hardening_modulus``,
        ``depth`` and ``layers`` (:class:`~roughcontact.contact.load_unload.VolumePlasticity`).

    Returns
    -------
    LoadUnloadResult
    """
    if loading_forces is None:
        loading = force_targets(max_force, 10, reference_force)
    else:
        loading = np.asarray(loading_forces, dtype=float)
    if loading[-1] != max_force:
        raise InputError("loading_forces", "must rise strictly to max_force.", "e.g. [0, 25e-6, ..., 1e-3].")
    model = plasticity_model(
        plasticity,
        hardness=hardness,
        yield_strength=yield_strength,
        hardening_modulus=hardening_modulus,
        depth=depth,
        layers=layers,
    )
    try:
        return _compress(topography, material, loading, unloading_forces, reference_force, model, substrate,
                         film_thickness, tolerance)  # fmt: skip
    except InputError as error:
        if error.field != "forces":
            raise
        raise InputError("loading_forces", error.problem, error.fix) from None


def _compress(
    topography, material, loading, unloading, reference_force, model, substrate, film_thickness, tolerance
):
    return load_unload(
        topography,
        material,
        forces=loading,
        unloading_forces=unloading,
        reference_force=reference_force,
        plasticity=model,
        substrate=substrate,
        film_thickness=film_thickness if substrate is not None else None,
        boundary="free",
        tolerance=tolerance,
    )
