"""From two bodies to paper 000's Winkler-Lennard-Jones model: the composite surface, E, k and dgamma.

:func:`winkler_lj_model` merges the surfaces, takes eq. 1's modulus, eq. 4's factor and the work of
adhesion of the two surface energies, and sorts the springs once (:class:`.model.WinklerLJModel`);
:func:`solve_winkler_lj` is one load of it.
"""

from __future__ import annotations

import math

import numpy as np

from .._deprecation import folded, renamed
from ..checks import positive
from ..errors import InputError
from ..materials import Material, check_material
from ..topography import Topography
from ..topography.process import combine
from ..topography.surface import topography_argument
from .model import WinklerLJModel
from .options import OPTION_KEYWORDS, WinklerLJOptions, check_gap_model, folded_options
from .readings import Readings
from .results import WinklerLJResult
from .springs import composite_modulus, winkler_factor
from .viscoelastic import material_after_hold


def surface_energy_of(value: float | None, body: Material | None, field_name: str) -> float:
    """Return the surface energy [J/m^2] given, else the body's; refuse none and a non-positive one."""
    if value is None and body is not None:
        value = body.surface_energy
    if value is None:
        raise InputError(
            field_name,
            "no surface energy given" + (f" and {body.name!r} has none." if body is not None else "."),
            "give the body's surface energy (e.g. '50 mJ/m^2'; in Python SI, 0.05 J/m^2), "
            "or a material that has one.",
        )
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise InputError(
            field_name,
            f"{value!r} J/m^2 is not a positive surface energy.",
            "surface energies are positive: tens of mJ/m^2 for oxides and silicon (0.05 J/m^2 in SI).",
        )
    return value


def _tip_radius(value: float | None, tip: Topography | None, readings: Readings) -> float | None:
    """R of the half-sphere tip: ``value``, else the radius ``tip`` was generated with; None if unused."""
    if readings.base != "half_sphere":
        return None if value is None else positive(value, "tip_radius", example="1e-6", unit="m")
    if value is None and tip is not None:
        value = tip.info.get("radius")
    if value is None:
        raise InputError(
            "tip_radius",
            "readings.base='half_sphere' measures z_i and d from the base of the half-sphere tip, "
            "and no tip radius is known.",
            "give tip_radius (paper 000: 1e-6 m, a 2 um diameter tip) or a counter topography "
            "generated as a sphere.",
        )
    return positive(value, "tip_radius", example="1e-6", unit="m")


def _within_half_sphere(surface: Topography, tip: Topography | None, radius: float) -> np.ndarray:
    """Pixels under the half-sphere tip: within ``radius`` of its apex (the tip's highest point).

    Without a tip topography on the composite's grid the apex is the composite's highest point.
    """
    apex_heights = surface.heights if tip is None or tip.shape != surface.shape else tip.heights
    apex = np.unravel_index(int(np.argmax(apex_heights)), apex_heights.shape)
    squared = sum(
        ((np.arange(n) - a) * h).reshape([-1 if k == axis else 1 for k in range(surface.dim)]) ** 2
        for axis, (n, a, h) in enumerate(zip(surface.shape, apex, surface.spacing, strict=True))
    )
    return squared <= radius * radius


def work_of_adhesion(
    surface_energy_1: float, surface_energy_2: float, *, reading: str = "girifalco_good"
) -> float:
    r"""Work of adhesion dgamma of two surfaces [J/m^2] (paper 000, below equation 7).

    ``"girifalco_good"`` (default): dgamma = 2 sqrt(gamma1 gamma2), the dispersive
    (Berthelot / Girifalco-Good) estimate of gamma1 + gamma2 - gamma12, which gives 2 gamma for two
    identical surfaces. ``"printed"``: dgamma = sqrt(gamma1 gamma2), as printed (half of it).

    Parameters
    ----------
    surface_energy_1, surface_energy_2 : float
        Surface free energies [J/m^2].
    reading : {"girifalco_good", "printed"}
        See above.

    Returns
    -------
    float
        dgamma [J/m^2].

    References
    ----------
    L. A. Girifalco, R. J. Good, J. Phys. Chem. 61 (1957) 904-909. doi:10.1021/j150553a013.
    J. N. Israelachvili, *Intermolecular and Surface Forces*, 3rd ed., 2011, ch. 17.
    doi:10.1016/C2009-0-21560-1.
    """
    factor = 2.0 if reading == "girifalco_good" else 1.0
    return factor * math.sqrt(surface_energy_1 * surface_energy_2)


@renamed(counter="counter_body", counter_surface="counter_topography")
@folded("options", OPTION_KEYWORDS, folded_options)
def winkler_lj_model(
    topography: Topography,
    material: Material,
    counter_body: Material | None = None,
    *,
    options: WinklerLJOptions,
    counter_topography: Topography | None = None,
) -> WinklerLJModel:
    """Prepare the Winkler-Lennard-Jones model of a surface (or two merged surfaces) against a flat.

    Parameters
    ----------
    topography : Topography
        2D heights [m] of the rough surface (paper 000: the polysilicon scan).
    material : Material
        Body of ``topography`` (E1, nu1, gamma1).
    counter_body : Material, optional
        Counter-body (E2, nu2, gamma2); ``None`` is rigid (then ``options.counter_surface_energy``
        is needed).
    options : WinklerLJOptions
        The layer, the law's range, the surface energies, the readings, the hold and the gap field
        (:class:`~roughcontact.winkler_lj.WinklerLJOptions`, e.g.
        ``WinklerLJOptions(layer_thickness=50e-9)``; paper 000's:
        :func:`~roughcontact.papers.paper000.paper000_options`). Release 0.1's keywords
        (``layer_thickness=``, ``epsilon=``, ...) still work one release, with a DeprecationWarning.
    counter_topography : Topography, optional
        Topography of the counter-body (paper 000: the AFM tip); merged with ``topography`` by
        :func:`roughcontact.topography.process.combine`.

    Returns
    -------
    WinklerLJModel

    Raises
    ------
    InputError
        A 1D or mismatched topography (without ``options.resample``), epsilon or layer thickness
        not positive, a missing, zero or negative surface energy, an invalid Poisson's ratio for
        eq. 4, ``readings.base="half_sphere"`` without a tip radius, an unknown ``gap_model`` or
        ``bem_boundary``, ``gap_model="bem"`` with a non-default reading of eq. 2.
    """
    topography = topography_argument(topography, "topography")
    readings = Readings() if options.readings is None else options.readings
    check_gap_model(options.gap_model, options.bem_boundary, readings)
    tip_radius = _tip_radius(options.tip_radius, counter_topography, readings)
    check_material(material, "material")
    check_material(counter_body, "counter_body", rigid=True)
    if not isinstance(topography, Topography) or topography.dim != 2:
        raise InputError("topography", "expected a 2D Topography.", "pass a height map (nx, ny) in metres.")
    surface = topography
    if counter_topography is not None:
        try:
            surface = combine(topography, counter_topography, resample=options.resample)
        except InputError as error:
            raise InputError(
                "counter_topography",
                error.problem,
                "pass resample=True to interpolate both onto a common grid, "
                "or bring the scans to one grid first.",
            ) from error
    epsilon = positive(options.epsilon, "epsilon", example="2e-9", unit="m")
    layer_thickness = positive(options.layer_thickness, "layer_thickness", example="50e-9", unit="m")
    gamma_1 = surface_energy_of(options.surface_energy, material, "surface_energy")
    gamma_2 = surface_energy_of(options.counter_surface_energy, counter_body, "counter_surface_energy")
    if options.relaxation is not None:
        material = material_after_hold(material, options.relaxation, options.hold_time)
    nu_1 = material.poissons_ratio
    if counter_body is None:
        modulus = material.youngs_modulus / (1.0 - nu_1**2)
        nu_2 = nu_1
    else:
        nu_2 = counter_body.poissons_ratio
        modulus = composite_modulus(material.youngs_modulus, nu_1, counter_body.youngs_modulus, nu_2)
    k = winkler_factor(nu_1, nu_2, reading=readings.winkler_factor)
    if k <= 0:
        raise InputError(
            "poissons_ratio",
            f"eq. 4 gives k = {k:.3g} for nu = {nu_1}, {nu_2}: the springs would be rigid.",
            "the Winkler layer needs compressible materials (nu < 0.5).",
        )
    shear_nu = {"geometric": math.sqrt(nu_1 * nu_2), "surface": nu_1, "counter": nu_2}[readings.shear_poisson]
    modelled = np.arange(surface.heights.size)
    if readings.base == "half_sphere":
        modelled = np.flatnonzero(_within_half_sphere(surface, counter_topography, tip_radius))
    heights = surface.heights.ravel()[modelled]
    order = np.argsort(-heights, kind="stable")
    depth = heights.max() - heights[order]
    cumulative = np.concatenate(([0.0], np.cumsum(depth)))
    rank = np.full(surface.heights.size, depth.size, dtype=np.intp)
    rank[modelled[order]] = np.arange(depth.size)
    return WinklerLJModel(
        topography=surface,
        readings=readings,
        epsilon=epsilon,
        layer_thickness=layer_thickness,
        contact_modulus=modulus,
        winkler_factor=k,
        shear_modulus=modulus / (2.0 * (1.0 + shear_nu)),
        work_of_adhesion=work_of_adhesion(gamma_1, gamma_2, reading=readings.work_of_adhesion),
        _depth=depth,
        _cumulative_depth=cumulative,
        _compression_at_depth=np.arange(depth.size) * depth - cumulative[:-1],
        _rank=rank.reshape(surface.shape),
        tip_radius=tip_radius,
        gap_model=options.gap_model,
        bem_boundary=options.bem_boundary,
    )


@renamed(counter="counter_body", load="normal_force")
@folded("options", OPTION_KEYWORDS, folded_options)
def solve_winkler_lj(
    topography: Topography,
    material: Material,
    counter_body: Material | None = None,
    *,
    normal_force: float,
    options: WinklerLJOptions,
    counter_topography: Topography | None = None,
) -> WinklerLJResult:
    """Friction of a surface against a flat at one normal load (paper 000).

    ``winkler_lj_model(...).solve(normal_force)``, which documents the arguments.

    Parameters
    ----------
    topography : Topography
        Rough surface [m].
    material, counter_body : Material
        The two bodies (``counter_body=None``: rigid flat).
    normal_force : float
        Normal load N [N], > 0.
    options : WinklerLJOptions
        The model's options (:class:`~roughcontact.winkler_lj.WinklerLJOptions`; release 0.1's
        keywords still work one release, with a DeprecationWarning).
    counter_topography : Topography, optional
        As in :func:`winkler_lj_model`.

    Returns
    -------
    WinklerLJResult
    """
    model = winkler_lj_model(
        topography, material, counter_body, options=options, counter_topography=counter_topography
    )
    return model.solve(normal_force)
