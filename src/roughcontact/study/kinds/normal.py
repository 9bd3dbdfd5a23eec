"""Study kind ``normal``: one normal contact of a rough surface against a flat per case.

Wraps :func:`roughcontact.contact.solve_normal` (FFT boundary elements, constrained conjugate
gradients; paper 001 eq. 4): load control by ``mean_pressure`` or ``force``, displacement control
by ``approach``; elastic-perfectly-plastic with ``hardness``; the body a half-space, or a film of
``film_thickness`` on a rigid base or bonded to a ``substrate``; von Mises stress on the planes
``stress_depths`` below the surface (half-space solution under the contact pressure).

Figures: ``contact`` (pressure and gap maps of up to four cases), ``area_load`` (real contact
area against load, one line per sample), ``load_approach`` (load against approach), ``von_mises``
(von Mises maps at the first stress depth).
"""

from __future__ import annotations

from typing import Annotated, Literal

import numpy as np
from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...contact.result import NormalContactResult
from ...units import format_si
from ..kind import CaseOutput, CaseParameters, Kind, caption
from ..schema import Force, Length, MaterialName, Pressure, TopographyName
from .common import evenly_chosen, grouped, scalar_series


class NormalParameters(CaseParameters):
    """Keys of a ``model = "normal"`` analysis (SI after validation)."""

    topography: TopographyName
    """The rough surface (heights towards the flat)."""
    material: MaterialName
    """The surface's body (the film with film_thickness)."""
    counter_body: MaterialName | None = None
    """The flat's material; default rigid."""
    mean_pressure: Pressure | None = None
    """Load control by the nominal mean pressure (one of three targets)."""
    force: Force | None = None
    """Load control by the total force."""
    approach: Length | None = None
    """Displacement control by the rigid approach from the first touch."""
    hardness: Pressure | None = None
    """Caps the pressure: elastic-perfectly-plastic surface."""
    boundary: Literal["periodic", "free"] | None = None
    """Default: periodic for a periodic surface, else free."""
    film_thickness: Length | None = None
    """The body is a film of this thickness (on film_base or substrate)."""
    substrate: MaterialName | None = None
    """Elastic substrate the film is bonded to."""
    film_base: Literal["bonded", "frictionless"] = "bonded"
    """Rigid base of a film without a substrate."""
    tolerance: float = Field(default=1e-8, gt=0.0, lt=1.0)
    """Scale-free residual of the solver."""
    stress_depths: list[Annotated[Length, Field(ge=0.0)]] = Field(default_factory=list)
    """Depths of von Mises maps below the surface (0 or more)."""

    @model_validator(mode="after")
    def _one_target(self) -> NormalParameters:
        given = [k for k in ("mean_pressure", "force", "approach") if getattr(self, k) is not None]
        if len(given) != 1:
            raise PydanticCustomError(
                "quantity",
                "give exactly one of mean_pressure, force, approach (found {found})",
                {"found": ", ".join(given) or "none", "fix": "e.g. mean_pressure = '20 MPa'"},
            )
        if self.substrate is not None and self.film_thickness is None:
            raise PydanticCustomError(
                "quantity", "a substrate needs film_thickness", {"fix": "add film_thickness = '50 nm'"}
            )
        return self


def check_inputs(parameters: NormalParameters, known) -> None:
    """Refuse at validation a free line contact and a load the scan cannot carry.

    See :func:`~roughcontact.contact.normal.check_line_boundary` and ``check_carried``.
    """
    from ...contact.normal import check_carried, check_line_boundary
    from ...materials import contact_modulus

    grid = known.grid(parameters.topography)
    if grid is None:
        return
    shape, size = grid
    check_line_boundary(len(shape), parameters.boundary)
    if parameters.film_thickness is not None:
        return
    nominal = size[0] * size[1] if len(shape) == 2 else size[0]
    name = next(key for key in ("force", "mean_pressure", "approach") if getattr(parameters, key) is not None)
    value = getattr(parameters, name)
    pressure = value / nominal if name == "force" else value
    modulus = contact_modulus(known.material(parameters.material), known.material(parameters.counter_body))
    check_carried(name, value, pressure, size, modulus, parameters.hardness)


def run(parameters: NormalParameters, inputs) -> CaseOutput:
    """Solve one case; scalars as :meth:`NormalContactResult.scalars` plus E* and stress maxima."""
    import xarray as xr

    from ...contact import solve_normal
    from ...elasticity.halfspace import ElasticLayer
    from ...elasticity.stress import subsurface_stress

    surface = inputs.topography(parameters.topography)
    material = inputs.material(parameters.material)
    layer = None
    if parameters.film_thickness is not None:
        base = inputs.material(parameters.substrate) or parameters.film_base
        layer = ElasticLayer(parameters.film_thickness, material, base=base)
    result = solve_normal(
        surface,
        None if layer is not None else material,
        counter_body=inputs.material(parameters.counter_body),
        layer=layer,
        mean_pressure=parameters.mean_pressure,
        force=parameters.force,
        approach=parameters.approach,
        hardness=parameters.hardness,
        boundary=parameters.boundary,
        tolerance=parameters.tolerance,
    )
    scalars = result.scalars()
    # stored: pressure and gap (with the result's scalars as attributes); displacement and heights
    # follow from them and the input, and would double each case's file (docs/studies.md, Overhead)
    dataset = result.to_xarray()[["pressure", "gap"]]
    if parameters.stress_depths and surface.dim == 2:
        stress = subsurface_stress(
            result.pressure,
            surface.size,
            parameters.stress_depths,
            poissons_ratio=material.poissons_ratio,
            boundary=result.boundary,
        )
        von_mises = stress.von_mises()
        peak, (x, y, z) = stress.max_von_mises()
        scalars |= {"max_von_mises": peak, "max_von_mises_depth": z}
        dataset["von_mises"] = xr.DataArray(
            von_mises,
            dims=("depth", "x", "y"),
            coords={"depth": ("depth", np.asarray(parameters.stress_depths), {"units": "m"})},
            attrs={"units": "Pa"},
        )
    return CaseOutput(scalars, dataset, tuple(result.range_warnings()))


@caption(
    "Contact pressure (top) and gap (bottom) of up to four cases; each row shares one colour scale, "
    "from 0 to the 99.5th percentile of its nonzero values. Titles give the case and the fraction of "
    "the nominal area in contact. A line scan (plane-strain line contact) is drawn as profiles: "
    "pressure and gap against x, one curve per case."
)
def _contact_maps(records, context):
    from ...plotting.layout import colour_scale, legend, new_figure, shared_colorbar
    from ...plotting.study import map_axes, profile_axes

    chosen = evenly_chosen([r for r in records if r.fields_path is not None], 4)
    fields = [record.dataset() for record in chosen]
    if not chosen:
        return None
    if "y" not in fields[0].dims:
        figure, axes = new_figure(2, 1, width=6.4, height=2.6)
        labels = [
            f"{r.label}: {100 * r.scalars['contact_fraction']:.3g} % in contact" if len(chosen) > 1 else None
            for r in chosen
        ]
        profile_axes(axes[0][0], [data["pressure"] for data in fields], labels, "pressure", "Pa")
        profile_axes(axes[1][0], [data["gap"] for data in fields], labels, "gap", "m")
        if len(chosen) > 1:
            legend(axes[0][0])
        else:
            axes[0][0].set_title(
                f"{chosen[0].label}\n{100 * chosen[0].scalars['contact_fraction']:.3g} % in contact"
            )
        return figure
    figure, axes = new_figure(2, len(chosen), width=3.6 if len(chosen) > 1 else 4.6, height=3.2)
    for row, (name, cmap) in enumerate((("pressure", "magma"), ("gap", "viridis"))):
        unit = "Pa" if name == "pressure" else "m"
        shared = colour_scale(*(data[name] for data in fields), from_zero=True)
        for column, data in enumerate(fields):
            image = map_axes(
                axes[row][column], data[name], name, unit, cmap=cmap, scale=shared, colorbar=False
            )
        shared_colorbar(image, axes[row], name, unit, shared)
    for record, ax in zip(chosen, axes[0], strict=True):
        ax.set_title(f"{record.label}\n{100 * record.scalars['contact_fraction']:.3g} % in contact")
    return figure


def _curve_of_cases(records, x: str, y: str, scales: tuple[float, float], labels: tuple[str, str, str]):
    """One scalar against another over the cases, a line per sample (None for fewer than 2 cases)."""
    from ...plotting.layout import legend, new_figure

    if len(records) < 2:
        return None
    figure, axes = new_figure(1, 1)
    ax = axes[0][0]
    groups = grouped(records)
    for sample, group in groups.items():
        abscissa, ordinate = scalar_series(group, x, y)
        ax.plot(abscissa * scales[0], ordinate * scales[1], "o-", label=sample or None)
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    ax.set_title(labels[2])
    if any(groups):
        legend(ax)
    return figure


@caption(
    "Real contact area as a fraction of the nominal area against the nominal mean pressure, one line "
    "per sample."
)
def _area_load(records, context):
    labels = (
        "nominal mean pressure (MPa)",
        "real contact area (% of nominal)",
        "real contact area against load",
    )
    return _curve_of_cases(records, "mean_pressure", "contact_fraction", (1e-6, 100.0), labels)


@caption(
    "Normal force (per unit length for a line scan) against the rigid approach counted from the "
    "first touch, one line per sample."
)
def _load_approach(records, context):
    if records and "force_per_length" in records[0].scalars:
        labels = ("approach (nm)", "force per length (N/m)", "load against approach")
        return _curve_of_cases(records, "approach", "force_per_length", (1e9, 1.0), labels)
    labels = ("approach (nm)", "force (µN)", "load against approach")
    return _curve_of_cases(records, "approach", "force", (1e9, 1e6), labels)


@caption(
    "Von Mises stress at the first stored depth below the surface for up to four cases, on one colour "
    "scale from 0 to the largest value of all the panels."
)
def _von_mises(records, context):
    from ...plotting.layout import colour_scale, new_figure, shared_colorbar
    from ...plotting.study import map_axes

    chosen = evenly_chosen([r for r in records if "max_von_mises" in r.scalars], 4)
    if not chosen:
        return None
    figure, axes = new_figure(1, len(chosen), width=3.6 if len(chosen) > 1 else 4.6, height=3.2)
    fields = [record.dataset()["von_mises"].isel(depth=0) for record in chosen]
    shared = colour_scale(*fields, from_zero=True, percentiles=(0, 100))  # smooth: the full range
    for column, (record, field) in enumerate(zip(chosen, fields, strict=True)):
        ax = axes[0][column]
        image = map_axes(ax, field, "von Mises stress", "Pa", cmap="inferno", scale=shared, colorbar=False)
        ax.set_title(f"{record.label}\nz = {format_si(float(field.depth), 'm', digits=3)}")
    shared_colorbar(image, axes[0], "von Mises stress", "Pa", shared)
    return figure


KIND = Kind(
    name="normal",
    summary="normal contact against a flat: FFT-BEM, load or approach control, optional hardness/film",
    parameters=NormalParameters,
    run=run,
    check_inputs=check_inputs,
    units=NormalContactResult.UNITS | {"max_von_mises": "Pa", "max_von_mises_depth": "m"},
    figures={
        "contact": _contact_maps,
        "area_load": _area_load,
        "load_approach": _load_approach,
        "von_mises": _von_mises,
    },
    headline=(
        "force",
        "force_per_length",
        "mean_pressure",
        "approach",
        "contact_fraction",
        "number_of_patches",
        "max_pressure",
    ),
    renamed={"surface": "topography", "counter": "counter_body"},
)
