r"""Study kind ``theories``: which theory predicts my surface? Persson, BGT and GW beside the BEM.

One case is one surface (one realisation) at one load, through
:func:`roughcontact.theory.compare_theories`: the boundary-element solution, its contact area
counted in pixels and corrected for the pixelated perimeter (Yastrebov et al. 2017), its mean gap
and its distribution of contact pressures; beside it, from the surface's own spectrum, Persson's
area :math:`\operatorname{erf}(\sqrt2 p_0/(E^* g))`, distribution of pressures and mean separation
(Persson 2001, 2007), Bush-Gibson-Thomas's small-load area :math:`\sqrt{2\pi} p_0/(E^* g)` and
Greenwood-Williamson's area and separation from the spectral moments. The load is
``reduced_pressure`` (:math:`p_0/(E^* g)`, :math:`g` the surface's spectral rms gradient) or
``mean_pressure`` (with its unit); sweep it (``[analysis.sweep] reduced_pressure = [0.005, 0.01,
...]``) and add ``realisations = N`` to run N draws of a generated surface at each load.

Tables, over the realisations of each setting: ``area`` and ``gap`` judge each theory against the
BEM at each load (the theory's value, the BEM mean with its 95 % confidence interval, the mean
deviation theory/BEM - 1 on the same realisation with its interval, and the verdict on the mean:
``over-predicts`` or ``under-predicts`` where the interval lies above or below 0, ``not
established`` where it holds 0; :func:`roughcontact.theory.against_bem`); ``kappa`` does the same for
the small-load slope :math:`\kappa` of the BEM's corrected area, fitted through the origin over the
loads of each realisation whose corrected area is at most ``kappa_max_fraction``, against Persson's
1.596 and BGT's 2.507. A measured scan is one realisation: its rows have no interval.

Scalars per case: the BEM's raw and corrected areas and their ``area_load_slope``, its mean gap,
Persson's, BGT's and GW's areas and gaps at the load (:meth:`TheoryComparison.load_scalars`), the
spectral ``rms_gradient`` :math:`g` beside the grid's finite-difference one, the moments and
bandwidth. Dataset: the histogram of contact pressures and Persson's area against magnification.

Figures: ``area`` (relative contact area against :math:`p_0/(E^* g)` and against :math:`p_0`, the BEM's
mean and 95 % band over realisations, corrected and raw, every theory beside it), ``gap`` (mean gap
over the rms height, the same way), ``pressure`` (distribution of contact pressures at three loads,
the BEM's histogram against Persson's :math:`P(\sigma)`), ``kappa`` (:math:`A/A_0` over
:math:`p_0/(E^* g)` per load, with Persson's and BGT's slopes) and ``magnification`` (Persson's area as
the roughness is resolved wavelength by wavelength).

A scan solved with a free boundary is a window: the theories are of an infinite surface, so its
areas are compared (mind the edge's share of the load) and its mean gap, which holds the
half-space's settlement under the window, is not. Theory and sources: the documentation's page on
the theories.
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

import numpy as np
from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...theory.comparison import KAPPA_MAX_FRACTION, TheoryComparison
from ..kind import CaseOutput, CaseParameters, Kind, figure
from ..schema import MaterialName, Pressure, TopographyName

_POSITIVE = Field(gt=0.0, allow_inf_nan=False)


class TheoriesParameters(CaseParameters):
    """Keys of a ``model = "theories"`` analysis (SI after validation)."""

    topography: TopographyName
    """The rough surface (a map), levelled."""
    material: MaterialName
    """The surface's body."""
    counter_body: MaterialName | None = None
    """The flat's material; default rigid."""
    reduced_pressure: Annotated[float, _POSITIVE] | None = None
    """The load as p0 / (E* g), g the surface's spectral rms gradient (one of two)."""
    mean_pressure: Annotated[Pressure, _POSITIVE] | None = None
    """The load as a nominal pressure (with its unit)."""
    boundary: Literal["periodic", "free"] | None = None
    """The BEM's boundary; default periodic for a periodic surface, else free."""
    tolerance: float = Field(default=1e-8, gt=0.0, lt=1.0)
    """Scale-free residual of the solver."""
    gamma: float = Field(default=0.4, gt=0.0, le=1.0)
    """Persson's (2007) correction of the mean separation (0.4)."""
    kappa_max_fraction: float = Field(default=KAPPA_MAX_FRACTION, gt=0.0, le=1.0)
    """Largest corrected contact area of a load in the small-load fit of kappa (the kappa table)."""
    bins: int = Field(default=48, ge=4, le=1000)
    """Bins of the histogram of contact pressures."""

    @model_validator(mode="after")
    def _one_load(self) -> TheoriesParameters:
        given = [k for k in ("reduced_pressure", "mean_pressure") if getattr(self, k) is not None]
        if len(given) != 1:
            raise PydanticCustomError(
                "quantity",
                "give exactly one of «reduced_pressure» and «mean_pressure» (found {found})",
                {
                    "found": ", ".join(f"«{k}»" for k in given) or "none",
                    "fix": "e.g. «reduced_pressure=0.05», swept over a few loads",
                },
            )
        return self


def check_inputs(parameters: TheoriesParameters, known) -> None:
    """Refuse at validation a profile (the theories are of a 2D surface)."""
    from ...errors import InputError

    grid = known.grid(parameters.topography)
    if grid is not None and len(grid[0]) != 2:
        raise InputError(
            "topography",
            "the theories of rough contact are of a 2D surface; this is a profile.",
            "give a map.",
        )


def run(parameters: TheoriesParameters, inputs) -> CaseOutput:
    """Solve the case's load on its surface with the BEM and every theory (:func:`compare_theories`)."""
    from ...theory import compare_theories

    result = compare_theories(
        inputs.topography(parameters.topography),
        inputs.material(parameters.material),
        counter_body=inputs.material(parameters.counter_body),
        reduced_pressures=None if parameters.reduced_pressure is None else [parameters.reduced_pressure],
        mean_pressures=None if parameters.mean_pressure is None else [parameters.mean_pressure],
        boundary=parameters.boundary,
        tolerance=parameters.tolerance,
        gamma=parameters.gamma,
        kappa_max_fraction=parameters.kappa_max_fraction,
        bins=parameters.bins,
    )
    keep = [
        "bem_pressure_density",
        "persson_pressure_density",
        "persson_fraction_magnified",
        "reduced_pressure",
    ]
    scalars = result.scalars() | {"surface_origin": inputs.origin(parameters.topography)}
    return CaseOutput(scalars, result.to_xarray()[keep], tuple(result.range_warnings()))


# --- tables ----------------------------------------------------------------------------------------

INTERVAL_NOTE = (
    "deviation = theory / BEM - 1 on each realisation (the theory from that surface's own spectrum); its "
    "mean and the 95 % confidence interval of the mean over the realisations (Student's t), and the verdict "
    "on the claim that the theory predicts the BEM mean: over-predicts (interval above 0), under-predicts "
    "(below 0), not established (the interval holds 0). One realisation (a measured scan) has no interval."
)


def _rows(found, label: str, origin: str, unit: str) -> list[dict]:
    """Return the rows of the deviations with their units in the headers (``bem_mean [m]``).

    Each row names its setting and its surfaces' origin (measured: a file; synthetic: generated).
    """
    from ..display import header

    valued = ("theory_value", "bem_mean", "bem_ci95_low", "bem_ci95_high")
    rows = []
    for one in found:
        row = {k: v for k, v in one.row().items() if k not in ("quantity", "interval")}
        units = {k: unit for k in valued} | {"mean_pressure": "Pa"}
        said = {header(k, units.get(k)): v for k, v in row.items()}
        rows.append({"setting": label, "surface_origin": origin} | said)
    return rows


def _quantity_table(records, quantity: str):
    """Judge each theory's ``contact_fraction`` or ``mean_gap`` against the BEM's at each load."""
    from ...plotting.theories import sweeps
    from ...theory.comparison import against_bem
    from ..store import Table

    rows, notes = [], [INTERVAL_NOTE]
    for sweep in sweeps([r for r in records if r.done]):
        if quantity == "mean_gap" and not sweep.gap_compared:
            continue  # a free window: its mean gap holds the half-space's settlement (its warning says so)
        bem_name, theories, suffix = (
            ("contact_fraction_corrected", ("persson", "bgt", "gw"), "_fraction")
            if quantity == "contact_fraction"
            else ("mean_gap", ("persson", "gw"), "_mean_gap")
        )
        found = against_bem(
            {k: sweep.values(f"{k}{suffix}") for k in theories},
            sweep.values(bem_name),
            quantity=quantity,
            reduced_pressure=sweep.values("reduced_pressure"),
            mean_pressure=sweep.values("mean_pressure"),
            bounds=(0.0, 1.0) if quantity == "contact_fraction" else (0.0, math.inf),
        )
        rows += _rows(found, sweep.label, sweep.origin, "m" if quantity == "mean_gap" else "")
    if not rows:
        return None
    if quantity == "contact_fraction":
        notes.append(
            "The BEM's area is corrected for its pixelated perimeter (Yastrebov et al. 2017); BGT's is its "
            "small-load law, meaningful while the area is a few per cent."
        )
    else:
        notes.append(
            "The BEM's mean gap is the mean of its gap field (periodic: from the surface's mean plane); "
            "Persson's is his (2007) mean separation, GW's the flat's distance from the surface's mean plane."
        )
    return Table(rows, notes)


def area_table(records, context):
    """Judge each theory's relative contact area against the BEM's corrected area at each load."""
    return _quantity_table(records, "contact_fraction")


def gap_table(records, context):
    """Judge Persson's and GW's mean separation against the BEM's mean gap at each load (periodic only)."""
    return _quantity_table(records, "mean_gap")


def kappa_table(records, context):
    """Judge the BEM's small-load slope kappa over realisations against Persson's 1.596 and BGT's 2.507."""
    from ...plotting.theories import fitted_kappa, sweeps
    from ...spread import spread
    from ...theory.bgt import KAPPA as BGT
    from ...theory.comparison import against_bem
    from ...theory.persson import KAPPA as PERSSON
    from ..store import Table

    rows = []
    for sweep in sweeps([r for r in records if r.done]):
        kappa = fitted_kappa(sweep)[:, None]
        raw = spread(fitted_kappa(sweep, "contact_fraction"), bounds=(0.0, math.inf))
        found = against_bem(
            {"persson": np.full(kappa.shape, PERSSON), "bgt": np.full(kappa.shape, BGT)},
            kappa,
            quantity="kappa",
        )
        for one in found:
            row = {
                k: v
                for k, v in one.row().items()
                if k not in ("reduced_pressure", "mean_pressure", "quantity")
            }
            del row["interval"]
            rows.append(
                {"setting": sweep.label, "surface_origin": sweep.origin}
                | row
                | {
                    "bem_raw_mean": raw.mean,
                    "bem_raw_ci95_low": raw.ci95_low,
                    "bem_raw_ci95_high": raw.ci95_high,
                }
            )
    if not rows or all(math.isnan(row["bem_mean"]) for row in rows):
        return None
    return Table(
        rows,
        [
            "kappa: slope of A/A0 against p0/(E* g) through the origin over the loads of a realisation "
            "whose corrected area is at most kappa_max_fraction; bem_* of the corrected area, bem_raw_* of "
            "the pixel count over the same loads. Published boundary-element values on well-resolved "
            "self-affine surfaces lie near 2 (Hyun et al. 2004; Prodanov et al. 2014; Yastrebov et al. "
            "2017).",
            INTERVAL_NOTE,
        ],
    )


KIND = Kind(
    name="theories",
    summary="Persson, Bush-Gibson-Thomas and Greenwood-Williamson beside the BEM at a load (corrected "
    "areas; swept: kappa)",
    parameters=TheoriesParameters,
    run=run,
    check_inputs=check_inputs,
    units=TheoryComparison.UNITS,
    figures={
        "area": figure("theories.theories_area_figure"),
        "gap": figure("theories.theories_gap_figure"),
        "pressure": figure("theories.theories_pressure_figure"),
        "kappa": figure("theories.theories_kappa_figure"),
        "magnification": figure("theories.theories_magnification_figure"),
    },
    tables={"area": area_table, "gap": gap_table, "kappa": kappa_table},
    headline=(
        "reduced_pressure",
        "contact_fraction",
        "contact_fraction_corrected",
        "persson_fraction",
        "bgt_fraction",
        "gw_fraction",
        "mean_gap",
        "persson_mean_gap",
    ),
    bounds={
        "area_load_slope": (0.0, math.inf),
        "area_load_slope_raw": (0.0, math.inf),
        "rms_gradient": (0.0, math.inf),
        "gw_mean_gap": (0.0, math.inf),  # left out where GW's flat passes below the mean plane
        "bgt_fraction": (0.0, math.inf),  # its small-load law is not capped at 1
        "gw_fraction": (0.0, math.inf),
    },
    references=(
        "persson2001",
        "persson2006",
        "manners2006",
        "persson2007",
        "almqvist2011",
        "bush1975",
        "greenwood1966",
        "nayak1971",
        "mccool1986",
        "jacobs2017",
        "yastrebov2015",
        "yastrebov2017",
        "hyun2004",
        "prodanov2014",
        "polonsky1999",
    ),
)
