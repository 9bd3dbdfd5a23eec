"""The options of paper 000's Winkler-Lennard-Jones model beside its two bodies, as one object.

:func:`~roughcontact.winkler_lj.winkler_lj_model` and
:func:`~roughcontact.winkler_lj.solve_winkler_lj` take the surfaces and materials as arguments and
everything else about the model (the layer, the law's range, the surface energies, the readings,
the hold, the gap field) as ``options=WinklerLJOptions(layer_thickness=50e-9)``; paper 000's
scenario (:func:`roughcontact.papers.paper000.paper000_options`) and the study kind ``friction``
build the same object. Release 0.1's keywords (``layer_thickness=``, ``epsilon=``, ...) still work
one release, with a DeprecationWarning (:func:`folded_options`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

from ..errors import InputError
from .bem import GAP_MODELS
from .readings import Readings


@dataclass(frozen=True)
class WinklerLJOptions:
    """How paper 000's Winkler-Lennard-Jones model is set up, beside its two bodies (SI).

    Attributes
    ----------
    layer_thickness : float
        Winkler layer height h [m] (paper 000: the thickness of the measured layer, 50 nm).
    epsilon : float
        Equilibrium distance of eq. 7 [m] (paper 000: 2 nm), > 0.
    surface_energy, counter_surface_energy : float, optional
        gamma1, gamma2 [J/m^2]; default the materials' ``surface_energy``.
    readings : Readings, optional
        Readings of the disputed equations (default :class:`~roughcontact.winkler_lj.Readings()`).
    resample : bool
        Interpolate two topographies of different pixel sizes onto a common grid instead of
        refusing them.
    relaxation : callable, optional
        E(t) [Pa] of the surface material (hold time); e.g. a PronySeries.
    hold_time : float
        Time held in contact before sliding [s]; used with ``relaxation``.
    tip_radius : float, optional
        Radius R of the half-sphere tip [m], used only with ``readings.base="half_sphere"``;
        default the ``radius`` the counter topography was generated with
        (:func:`~roughcontact.topography.generate.sphere_with_roughness`).
    gap_model : {"winkler", "bem"}
        The gap field of the friction sums (eqs. 8-17): ``"winkler"`` (default, paper 000): the
        springs' l_i = d - z_i - dz_i from eq. 2; ``"bem"``: the adhesive boundary-element
        solution's gap and pressure at the same load (see
        :meth:`~roughcontact.winkler_lj.WinklerLJModel.solve`; each solve runs the
        boundary-element solver, seconds on 64^2).
    bem_boundary : {"free", "periodic"}
        Boundary of the boundary-element window with ``gap_model="bem"`` (default free).
    """

    layer_thickness: float
    epsilon: float = 2e-9
    surface_energy: float | None = None
    counter_surface_energy: float | None = None
    readings: Readings | None = None
    resample: bool = False
    relaxation: Callable[[float], float] | None = None
    hold_time: float = 0.0
    tip_radius: float | None = None
    gap_model: str = "winkler"
    bem_boundary: str = "free"


OPTION_KEYWORDS = (
    "layer_thickness",
    "epsilon",
    "surface_energy",
    "counter_surface_energy",
    "readings",
    "resample",
    "relaxation",
    "hold_time",
    "tip_radius",
    "gap_model",
    "bem_boundary",
)
"""The keywords of release 0.1 that :class:`WinklerLJOptions` holds now."""


def folded_options(
    options: WinklerLJOptions | None,
    *,
    layer_thickness: float | None = None,
    epsilon: float | None = None,
    surface_energy: float | None = None,
    counter_surface_energy: float | None = None,
    readings: Readings | None = None,
    resample: bool | None = None,
    relaxation: Callable[[float], float] | None = None,
    hold_time: float | None = None,
    tip_radius: float | None = None,
    gap_model: str | None = None,
    bem_boundary: str | None = None,
) -> WinklerLJOptions:
    """Return ``options`` with the old keywords a call gave (:data:`OPTION_KEYWORDS`) applied.

    Without ``options`` the old keywords make a new :class:`WinklerLJOptions` (``layer_thickness``
    among them, as it always was required); a keyword given as None keeps its default.
    """
    given = {
        "layer_thickness": layer_thickness,
        "epsilon": epsilon,
        "surface_energy": surface_energy,
        "counter_surface_energy": counter_surface_energy,
        "readings": readings,
        "resample": resample,
        "relaxation": relaxation,
        "hold_time": hold_time,
        "tip_radius": tip_radius,
        "gap_model": gap_model,
        "bem_boundary": bem_boundary,
    }
    given = {name: value for name, value in given.items() if value is not None}
    if options is None:
        if "layer_thickness" not in given:
            raise InputError(
                "layer_thickness",
                "the Winkler layer has no thickness.",
                "give options=WinklerLJOptions(layer_thickness=50e-9, ...).",
            )
        return WinklerLJOptions(**given)
    return replace(options, **given)


def check_gap_model(gap_model: str, boundary: str, readings: Readings) -> None:
    """Refuse an unknown ``gap_model`` or ``bem_boundary``, and equation 2's readings changed with "bem"."""
    if gap_model not in GAP_MODELS:
        raise InputError("gap_model", f"unknown gap model {gap_model!r}.", f"use one of {list(GAP_MODELS)}.")
    if boundary not in ("free", "periodic"):
        raise InputError("bem_boundary", f"unknown boundary {boundary!r}.", "use 'free' or 'periodic'.")
    if gap_model == "bem":
        changed = {
            k: v for k, v in readings.changed().items() if k in ("balance_terms", "adhesion_sign", "contact")
        }
        if changed:
            raise InputError(
                "gap_model",
                f"gap_model='bem' replaces eq. 2 by the boundary-element solution, so the readings of "
                f"eq. 2 {changed} have no meaning there.",
                "leave balance_terms, adhesion_sign and contact at their defaults, "
                "or use gap_model='winkler'.",
            )
