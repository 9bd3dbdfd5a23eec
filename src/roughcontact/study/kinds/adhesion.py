r"""Study kind ``adhesion``: adhesive contact of a surface with a flat through a load-unload cycle.

Wraps :func:`roughcontact.contact.solve_adhesive` (boundary elements with an interaction law of
the gap, :mod:`roughcontact.contact.interaction`): the flat approaches from ``start`` to
``max_approach`` in ``steps`` equal steps and withdraws by the same steps until the surfaces are
apart; jumps in and out of contact are bracketed to ``jump_resolution`` and reported.

* ``law``: ``"maugis_dugdale"`` (constant tension w / rho up to the range rho), ``"exponential"``
  (w exp(-g / rho)) or ``"lennard_jones"`` (paper 000's eq. 7, range = eps);
  ``interaction_range`` is rho or eps.
* Work of adhesion: ``work_of_adhesion``, or from the surface energies (``surface_energy``,
  ``counter_surface_energy``; default the materials' own) by ``combining_rule``:
  ``"girifalco_good"`` dgamma = 2 sqrt(gamma1 gamma2) (Girifalco and Good 1957; 2 gamma for
  identical surfaces, the default) or ``"printed"`` dgamma = sqrt(gamma1 gamma2), as paper 000
  prints it below its eq. 7.
* Two rough bodies: ``counter_topography`` is merged with ``topography`` into their composite
  (:func:`~roughcontact.topography.process.combine`), against a rigid flat; the contact modulus
  is that of ``material`` and ``counter_body``. The body is a half-space, or a film of
  ``film_thickness`` on a rigid base or bonded to a ``substrate`` (as model ``normal``).
* ``winkler = true``: paper 000's Winkler-layer Lennard-Jones springs beside it, on the same
  composite surface and approaches (:func:`~roughcontact.papers.paper000.winkler_beside_bem`; the
  law must be ``lennard_jones`` with eps = ``interaction_range``, the springs' height
  ``layer_thickness``, dgamma and the spring constant by the ``reading`` preset of the friction
  model; ``combining_rule`` overrides the preset's dgamma rule).

Approaches count from the first touch of the undeformed surface (negative: apart); on a periodic
surface the approach of the mean plane (see :class:`~roughcontact.contact.AdhesiveResult`).

On a generated sphere the smooth sphere's closed forms stand beside the result: the Maugis
parameter, the Maugis-Dugdale, JKR and DMT pull-off forces (:func:`sphere_references`).

Figures: ``force_approach`` (the cycle of each case, jumps dotted, pull-off marked; the Winkler
curve dashed), ``maps`` (pressure and gap at the pull-off), ``pull_off`` (pull-off against the
swept work of adhesion or range). Table ``adhesion`` (per case: pull-off, jumps, hysteresis, areas,
resolution; the Winkler numbers beside).
"""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...contact.adhesive_result import AdhesiveResult
from ...errors import InputError
from ..kind import CaseOutput, CaseParameters, Kind, figure, fill_from_paper
from ..schema import Length, MaterialName, SurfaceEnergy, TopographyName

START_RANGES = 5.0
"""Default start of the programme: this many interaction ranges apart (the Lennard-Jones and
exponential tractions there are below 1 % of their peak; Maugis-Dugdale's is zero)."""

WINKLER_PREFIX = "winkler_"
"""Scalars and curves of paper 000's Winkler springs carry this prefix beside the BEM's."""


class AdhesionParameters(CaseParameters):
    """Keys of a ``model = "adhesion"`` analysis (SI after validation)."""

    topography: TopographyName
    """The rough surface (heights towards the flat)."""
    counter_topography: TopographyName | None = None
    """The counter-body's surface, merged with topography into their composite."""
    material: MaterialName
    """The surface's body (the film with film_thickness)."""
    counter_body: MaterialName | None = None
    """The flat's material; default rigid."""
    law: Literal["maugis_dugdale", "exponential", "lennard_jones"] = "maugis_dugdale"
    """Interaction law of the gap."""
    interaction_range: Length
    """rho (Maugis-Dugdale, exponential) or eps (Lennard-Jones) [m]."""
    work_of_adhesion: SurfaceEnergy | None = None
    """dgamma [J/m^2]; default from the surface energies by combining_rule."""
    surface_energy: SurfaceEnergy | None = None
    """gamma1 [J/m^2]; default the material's."""
    counter_surface_energy: SurfaceEnergy | None = None
    """gamma2 [J/m^2]; default the counter-body's."""
    combining_rule: Literal["girifalco_good", "printed"] | None = None
    """2 sqrt(g1 g2) (girifalco_good, default) or sqrt(g1 g2) as paper 000 prints it."""
    max_approach: Length
    """Deepest approach of the cycle [m], from the first touch."""
    start: Length | None = None
    """First (and last requested) approach [m]; default five interaction ranges apart."""
    steps: int = Field(default=40, ge=2, le=2000)
    """Equal steps from start to max_approach (and back); more are inserted at fast changes."""
    jump_resolution: Length | None = None
    """Width to which jumps are bracketed [m]; default a quarter of the range."""
    boundary: Literal["periodic", "free"] | None = None
    """Default: periodic for a periodic surface, else free."""
    film_thickness: Length | None = None
    """The body is a film of this thickness (on film_base or substrate)."""
    substrate: MaterialName | None = None
    """Elastic substrate the film is bonded to."""
    film_base: Literal["bonded", "frictionless"] = "bonded"
    """Rigid base of a film without a substrate."""
    resample: bool = False
    """Bring topography and counter_topography onto a common grid instead of refusing them."""
    tolerance: float = Field(default=1e-6, gt=0.0, lt=1.0)
    """Largest force imbalance of a pixel relative to the peak tension."""
    winkler: bool = False
    """Also evaluate paper 000's Winkler-layer springs on the same surface and approaches."""
    layer_thickness: Length = 50e-9
    """Height h of paper 000's Winkler layer (winkler = true)."""
    reading: Literal["default", "paper", "printed"] = "default"
    """Preset of paper 000's readings for the Winkler springs (winkler = true)."""
    paper000: bool = Field(default=False, exclude=True)
    """Fill in paper 000's bodies, surface energies, law and layer
    (:func:`roughcontact.papers.paper000.adhesion_keys`) where the analysis leaves them out."""

    @model_validator(mode="before")
    @classmethod
    def _paper000_scenario(cls, data: Any) -> Any:
        from ...papers.paper000 import adhesion_keys

        return fill_from_paper(data, "paper000", adhesion_keys)

    @property
    def first_approach(self) -> float:
        """``start``, or :data:`START_RANGES` interaction ranges apart [m]."""
        return self.start if self.start is not None else -START_RANGES * self.interaction_range

    @model_validator(mode="after")
    def _check(self) -> AdhesionParameters:
        if not self.first_approach < self.max_approach:
            raise PydanticCustomError(
                "quantity",
                "«start» must lie below «max_approach» (the flat approaches, then withdraws)",
                {"fix": "e.g. «start=-5 nm», «max_approach=3 nm»", "field": "start"},
            )
        if self.substrate is not None and self.film_thickness is None:
            raise PydanticCustomError(
                "quantity", "a substrate needs «film_thickness»", {"fix": "add «film_thickness=50 nm»"}
            )
        for name in ("work_of_adhesion", "surface_energy", "counter_surface_energy"):
            value = getattr(self, name)
            if value is not None and not (value > 0 or (value == 0 and name != "work_of_adhesion")):
                raise PydanticCustomError(
                    "quantity",
                    "«{name}» must be positive (an energy per area that the surfaces gain by touching)",
                    {"name": name, "fix": f"e.g. «{name}=72 mJ/m^2»", "field": name},
                )
        if self.winkler:
            problems = {
                "law": self.law != "lennard_jones",
                "work_of_adhesion": self.work_of_adhesion is not None,
                "film_thickness": self.film_thickness is not None,
            }
            wrong = [name for name, bad in problems.items() if bad]
            if wrong:
                raise PydanticCustomError(
                    "quantity",
                    "«winkler=true» compares with paper 000's springs: it needs «law=lennard_jones», "
                    "dgamma from the surface energies and a half-space (found {found})",
                    {
                        "found": ", ".join(f"«{name}»" for name in wrong),
                        "fix": "leave them out, or «winkler» out",
                        "field": wrong[0],
                    },
                )
        return self

    def programme(self) -> np.ndarray:
        """Return the requested approaches [m]: ``start`` to ``max_approach`` and back, ``steps`` each way."""
        loading = np.linspace(self.first_approach, self.max_approach, self.steps + 1)
        return np.concatenate([loading, loading[-2::-1]])


def work_of_adhesion(parameters: AdhesionParameters, material, counter_body) -> float:
    """Return dgamma [J/m^2]: given, or from the two surface energies by the combining rule.

    Raises
    ------
    InputError
        A surface energy that neither the analysis nor the material gives.
    """
    from ...winkler_lj import work_of_adhesion as combined

    if parameters.work_of_adhesion is not None:
        return parameters.work_of_adhesion
    energies = []
    for key, body, role in (
        ("surface_energy", material, "material"),
        ("counter_surface_energy", counter_body, "counter_body"),
    ):
        value = getattr(parameters, key)
        if value is None and body is not None:
            value = body.surface_energy
        if value is None:
            named = f" {body.name!r}" if body is not None and body.name not in ("", role) else ""
            whose = f"the {role}{named} has none" if body is not None else f"the {role} is rigid"
            raise InputError(
                key,
                f"no surface energy to combine ({whose}).",
                f"give «{key}=72 mJ/m^2», or «work_of_adhesion=100 mJ/m^2» directly.",
            )
        energies.append(value)
    return combined(*energies, reading=parameters.combining_rule or "girifalco_good")


def _layer(parameters: AdhesionParameters, material, inputs):
    from ...elasticity.halfspace import ElasticLayer

    if parameters.film_thickness is None:
        return None
    base = inputs.material(parameters.substrate) or parameters.film_base
    return ElasticLayer(parameters.film_thickness, material, base=base)


def _beside_winkler(parameters: AdhesionParameters, inputs) -> tuple[AdhesiveResult, dict, dict]:
    """Solve the BEM and paper 000's springs on one composite surface: (BEM result, scalars, curves)."""
    from ...papers.paper000 import winkler_beside_bem
    from ...winkler_lj import WinklerLJOptions
    from ...winkler_lj.readings import Readings

    counter = parameters.counter_topography
    items = [f"work_of_adhesion={parameters.combining_rule}"] if parameters.combining_rule else []
    both = winkler_beside_bem(
        inputs.topography(parameters.topography),
        inputs.material(parameters.material),
        inputs.material(parameters.counter_body),
        approach=parameters.programme(),
        counter_topography=None if counter is None else inputs.topography(counter),
        options=WinklerLJOptions(
            layer_thickness=parameters.layer_thickness,
            epsilon=parameters.interaction_range,
            surface_energy=parameters.surface_energy,
            counter_surface_energy=parameters.counter_surface_energy,
            readings=Readings.from_strings(items, preset=parameters.reading),
            resample=parameters.resample,
        ),
        boundary=parameters.boundary or "free",
        tolerance=parameters.tolerance,
    )
    beside = both.scalars()
    scalars = {k: v for k, v in beside.items() if k.startswith(WINKLER_PREFIX) or k.endswith("_ratio")}
    curves = {
        "force": both.winkler.force,
        "contact_area": both.winkler.contact_area,
        "interaction_area": both.winkler.interaction_area,
    }
    return both.bem, scalars, curves


def check_inputs(parameters: AdhesionParameters, known) -> None:
    """Refuse at validation what the run would: no work of adhesion, unmerged grids, a free profile."""
    from ...contact.normal import check_line_boundary

    work_of_adhesion(parameters, known.material(parameters.material), known.material(parameters.counter_body))
    known.check_pair(parameters.topography, parameters.counter_topography, parameters.resample)
    grid = known.grid(parameters.topography)
    if grid is not None:
        check_line_boundary(len(grid[0]), parameters.boundary)


def run(parameters: AdhesionParameters, inputs) -> CaseOutput:
    """Solve one cycle; scalars as :meth:`AdhesiveResult.scalars` (and the Winkler springs' beside)."""
    from ...contact.adhesive import solve_adhesive
    from ...contact.interaction import LAWS
    from ...topography.process import combine

    scalars: dict[str, Any] = {}
    curves: dict[str, np.ndarray] = {}
    if parameters.winkler:
        result, scalars, curves = _beside_winkler(parameters, inputs)
    else:
        material = inputs.material(parameters.material)
        counter_body = inputs.material(parameters.counter_body)
        surface = inputs.topography(parameters.topography)
        if parameters.counter_topography is not None:
            counter = inputs.topography(parameters.counter_topography)
            surface = combine(surface, counter, resample=parameters.resample)
        law = LAWS[parameters.law](
            work_of_adhesion(parameters, material, counter_body), parameters.interaction_range
        )
        layer = _layer(parameters, material, inputs)
        result = solve_adhesive(
            surface,
            None if layer is not None else material,
            law,
            approach=parameters.programme(),
            counter_body=counter_body,
            layer=layer,
            boundary=parameters.boundary,
            tolerance=parameters.tolerance,
            jump_resolution=parameters.jump_resolution,
        )
    dataset = result.to_xarray()
    for name, values in curves.items():
        dataset[WINKLER_PREFIX + name] = ("step", values, dict(dataset[name].attrs))
    scalars |= sphere_references(result)
    return CaseOutput(result.scalars() | scalars, dataset, tuple(result.range_warnings()))


SPHERES = ("sphere", "sphere_with_roughness")
"""Generators whose surfaces get the smooth sphere's closed forms beside them (their ``radius``)."""


def sphere_references(result: AdhesiveResult) -> dict[str, float]:
    """Return the smooth sphere's JKR, DMT and Maugis-Dugdale pull-off beside a generated sphere's [N].

    For a surface made by a sphere generator (``info["radius"]``; with roughness, the smooth
    sphere of the same radius): the Maugis parameter lambda = 2 sigma0 (R / (pi w K^2))^(1/3)
    with sigma0 the law's peak tension, the Maugis-Dugdale load-control pull-off at that lambda
    (Maugis 1992; for the exponential and Lennard-Jones laws the Maugis-Dugdale law of the same
    w and peak tension, the usual equivalence, Greenwood 1997), JKR 1.5 pi w R and DMT 2 pi w R.
    Empty for other surfaces and for profiles (a cylinder's pull-off is per length, not given here).
    """
    from ...analytic.adhesion import dmt_pull_off, jkr_pull_off, maugis_dugdale_pull_off, maugis_parameter

    info = result.topography.info
    if info.get("generator") not in SPHERES or result.topography.dim != 2:
        return {}
    law, radius = result.interaction, float(info["radius"])
    w = law.work_of_adhesion
    lam = maugis_parameter(w, radius, result.contact_modulus, law.peak_tension)
    reference = maugis_dugdale_pull_off(lam) * math.pi * w * radius
    return {
        "sphere_radius": radius,
        "maugis_parameter": lam,
        "maugis_dugdale_pull_off": reference,
        "pull_off_to_maugis_dugdale": result.pull_off_force / reference,
        "jkr_pull_off": jkr_pull_off(w, radius),
        "dmt_pull_off": dmt_pull_off(w, radius),
    }


# --- figures and tables (from stored records) ------------------------------------------------------


_TABLE = {
    "law": ("law", None),
    "work_of_adhesion": ("work_of_adhesion", "J/m^2"),
    "interaction_length": ("interaction_range", "m"),
    "pull_off_force": ("pull_off_force", "N"),
    "pull_off_force_per_length": ("pull_off_force_per_length", "N/m"),
    "pull_off_approach": ("pull_off_approach", "m"),
    "jump_in_approach": ("jump_in_approach", "m"),
    "jump_out_approach": ("jump_out_approach", "m"),
    "dissipated_energy": ("dissipated_energy", "J"),
    "dissipated_energy_per_length": ("dissipated_energy_per_length", "J/m"),
    "max_force": ("max_force", "N"),
    "max_force_per_length": ("max_force_per_length", "N/m"),
    "max_contact_area": ("max_contact_area", "m^2"),
    "max_contact_length": ("max_contact_length", "m"),
    "cohesive_zone_pixels": ("cohesive_zone_pixels", None),
    "maugis_parameter": ("maugis_parameter", None),
    "maugis_dugdale_pull_off": ("maugis_dugdale_pull_off", "N"),
    "pull_off_to_maugis_dugdale": ("bem / maugis_dugdale pull-off", None),
    "winkler_pull_off_force": ("winkler_pull_off_force", "N"),
    "pull_off_ratio": ("winkler / bem pull-off", None),
    "winkler_max_contact_area": ("winkler_max_contact_area", "m^2"),
    "contact_area_ratio": ("winkler / bem contact area", None),
}
"""Stored scalar -> (table column, SI unit) of the ``adhesion`` table (Winkler columns when present)."""


def _table(records, context):
    """Per case: the law, pull-off, jumps, hysteresis, areas, resolution; the Winkler springs beside."""
    rows = []
    for record in records:
        row = {"case": record["case"], "sample": record.parameters.get("sample", "")}
        for name, (header, unit) in _TABLE.items():
            if name in record.scalars:
                row[f"{header} [{unit}]" if unit else header] = record.scalars[name]
        rows.append(row)
    return rows or None


KIND = Kind(
    name="adhesion",
    summary="adhesive contact against a flat: BEM with a Maugis-Dugdale, exponential or Lennard-Jones law, "
    "load-unload cycle, pull-off and jumps; paper 000's Winkler springs beside",
    parameters=AdhesionParameters,
    run=run,
    check_inputs=check_inputs,
    units=AdhesiveResult.UNITS
    | {
        "winkler_pull_off_force": "N",
        "winkler_pull_off_approach": "m",
        "winkler_max_contact_area": "m^2",
        "winkler_max_force": "N",
        "sphere_radius": "m",
        "maugis_dugdale_pull_off": "N",
        "jkr_pull_off": "N",
        "dmt_pull_off": "N",
    },
    figures={
        "force_approach": figure("adhesion.force_approach_figure"),
        "maps": figure("adhesion.adhesion_maps_figure"),
        "pull_off": figure("adhesion.pull_off_figure"),
    },
    tables={"adhesion": _table},
    headline=(
        "pull_off_force",
        "pull_off_force_per_length",
        "pull_off_approach",
        "jump_in_approach",
        "jump_out_approach",
        "dissipated_energy",
        "dissipated_energy_per_length",
        "max_contact_area",
        "max_contact_length",
        "cohesive_zone_pixels",
    ),
    missing={"jump_in_approach": "no jump on loading", "jump_out_approach": "no jump on unloading"},
    references=(
        "paper000",
        "polonsky1999",
        "rey2017",
        "pastewka2014",
        "maugis1992",
        "greenwood1997",
        "israelachvili2011",
        "girifalco1957",
        "johnson1971",
        "derjaguin1975",
        "johnson1997",
        "stanley1997",
        "liu2000",
        "perriot2004",
        "frigo2005",
    ),
)
