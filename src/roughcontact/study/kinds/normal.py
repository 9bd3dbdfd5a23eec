"""Study kind ``normal``: one normal contact of a rough surface against a flat per case.

Wraps :func:`roughcontact.contact.solve_normal` (FFT boundary elements, constrained conjugate
gradients; paper 001 eq. 4): load control by ``mean_pressure`` or ``force``, displacement control
by ``approach``; elastic-perfectly-plastic with ``hardness``; the body a half-space, or a film of
``film_thickness`` on a rigid base or bonded to a ``substrate``; von Mises stress on the planes
``stress_depths`` below the surface (half-space solution under the contact pressure).

Figures: ``contact`` (contact-area, pressure and gap maps of up to four cases; sparse contacts
ringed and the most loaded patch enlarged), ``area_load`` (real contact area against load, one
line per sample), ``load_approach`` (load against approach), ``von_mises`` (von Mises maps at the
first stress depth, of the cases under load).
"""

from __future__ import annotations

from typing import Annotated, Literal

import numpy as np
from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...contact.result import NormalContactResult
from ..kind import CaseOutput, CaseParameters, Kind, figure
from ..schema import Force, Length, MaterialName, Pressure, TopographyName

_NON_NEGATIVE = Field(ge=0.0, allow_inf_nan=False)
"""A load or an approach: zero (the unloaded state) or more, finite."""


class NormalParameters(CaseParameters):
    """Keys of a ``model = "normal"`` analysis (SI after validation)."""

    topography: TopographyName
    """The rough surface (heights towards the flat)."""
    material: MaterialName
    """The surface's body (the film with film_thickness)."""
    counter_body: MaterialName | None = None
    """The flat's material; default rigid."""
    mean_pressure: Annotated[Pressure, _NON_NEGATIVE] | None = None
    """Load control by the nominal mean pressure (one of three targets; 0: the unloaded state)."""
    force: Annotated[Force, _NON_NEGATIVE] | None = None
    """Load control by the total force."""
    approach: Annotated[Length, _NON_NEGATIVE] | None = None
    """Displacement control by the rigid approach from the first touch."""
    hardness: Annotated[Pressure, Field(gt=0.0, allow_inf_nan=False)] | None = None
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
                "give exactly one of «mean_pressure», «force», «approach» (found {found})",
                {"found": ", ".join(f"«{k}»" for k in given) or "none", "fix": "e.g. «mean_pressure=20 MPa»"},
            )
        if self.substrate is not None and self.film_thickness is None:
            raise PydanticCustomError(
                "quantity", "a substrate needs «film_thickness»", {"fix": "add «film_thickness=50 nm»"}
            )
        return self


def check_inputs(parameters: NormalParameters, known) -> None:
    """Refuse at validation a free line contact, a load the scan cannot carry, an approach it cannot reach.

    See :func:`~roughcontact.contact.normal.check_line_boundary`, ``check_carried`` and (for a file's
    surface, read at validation) ``check_periodic_approach``.
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
    spec = known.specs.get(parameters.topography)
    surface = known.loaded.get(spec.model_dump_json()) if hasattr(spec, "file") else None
    if name == "approach" and parameters.hardness is None and surface is not None:  # a file, read already
        from ...contact.normal import check_periodic_approach, resolve_boundary
        from ...topography.plausible import is_flat

        if resolve_boundary(surface, parameters.boundary) == "periodic":
            heights = surface.heights
            check_periodic_approach(value, 0.0 if is_flat(heights) else float(heights.max() - heights.mean()))


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
        device=inputs.device,
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


KIND = Kind(
    name="normal",
    summary="normal contact against a flat: FFT-BEM, load or approach control, optional hardness/film",
    parameters=NormalParameters,
    run=run,
    check_inputs=check_inputs,
    units=NormalContactResult.UNITS | {"max_von_mises": "Pa", "max_von_mises_depth": "m"},
    figures={
        "contact": figure("contact.contact_maps_figure"),
        "area_load": figure("contact.area_load_figure"),
        "load_approach": figure("contact.load_approach_figure"),
        "von_mises": figure("contact.von_mises_figure"),
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
    references=(
        "polonsky1999",
        "stanley1997",
        "liu2000",
        "almqvist2007",
        "perriot2004",
        "johnson1985",
        "frigo2005",
    ),
)
