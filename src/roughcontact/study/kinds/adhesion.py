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

from ...contact.adhesive_result import LINE_NAMES, AdhesiveResult
from ...errors import InputError
from ..kind import CaseOutput, CaseParameters, Kind, caption, fill_from_paper
from ..schema import Length, MaterialName, SurfaceEnergy, TopographyName
from .common import box_around, evenly_chosen

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
                "start must lie below max_approach (the flat approaches, then withdraws)",
                {"fix": "e.g. start = '-5 nm', max_approach = '3 nm'", "field": "start"},
            )
        if self.substrate is not None and self.film_thickness is None:
            raise PydanticCustomError(
                "quantity", "a substrate needs film_thickness", {"fix": "add film_thickness = '50 nm'"}
            )
        for name in ("work_of_adhesion", "surface_energy", "counter_surface_energy"):
            value = getattr(self, name)
            if value is not None and not (value > 0 or (value == 0 and name != "work_of_adhesion")):
                raise PydanticCustomError(
                    "quantity",
                    "{name} must be positive (an energy per area that the surfaces gain by touching)",
                    {"name": name, "fix": f"e.g. {name} = '72 mJ/m^2'", "field": name},
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
                    "winkler = true compares with paper 000's springs: it needs law = 'lennard_jones', "
                    "dgamma from the surface energies and a half-space (found {found})",
                    {
                        "found": ", ".join(wrong),
                        "fix": "remove them or set winkler = false",
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
                f"give {key} = '72 mJ/m^2', or work_of_adhesion = '100 mJ/m^2' directly.",
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
    from ...winkler_lj.readings import Readings

    counter = parameters.counter_topography
    items = [f"work_of_adhesion={parameters.combining_rule}"] if parameters.combining_rule else []
    both = winkler_beside_bem(
        inputs.topography(parameters.topography),
        inputs.material(parameters.material),
        inputs.material(parameters.counter_body),
        approach=parameters.programme(),
        counter_topography=None if counter is None else inputs.topography(counter),
        layer_thickness=parameters.layer_thickness,
        epsilon=parameters.interaction_range,
        surface_energy=parameters.surface_energy,
        counter_surface_energy=parameters.counter_surface_energy,
        readings=Readings.from_strings(items, preset=parameters.reading),
        resample=parameters.resample,
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


def _scale(values, unit: str) -> tuple[float, str]:
    from ...units import prefixed_scale

    finite = np.abs(np.asarray(values, dtype=float))
    finite = finite[np.isfinite(finite)]
    return prefixed_scale(float(finite.max()) if finite.size else 1.0, unit)


def _scalar(scalars, name: str) -> float:
    """Return a case's scalar ``name`` (a line contact's under its name in ``adhesive_result.LINE_NAMES``)."""
    return scalars[name] if name in scalars else scalars[LINE_NAMES[name]]


def _per_length(records) -> bool:
    """Whether the cases are line contacts (forces per length, lengths for areas)."""
    return any(LINE_NAMES["pull_off_force"] in r.scalars for r in records)


def _draw_cycle(ax, data, record, colour, scales) -> None:
    """One case's cycle: solved steps joined, a jump dotted, the pull-off marked; Winkler dashed."""
    (a_scale, _), (f_scale, _) = scales
    approach = np.asarray(data["approach"]) / a_scale
    force = np.asarray(data["force"]) / f_scale
    jump = np.asarray(data["jump"], dtype=bool)
    start = 0
    for end in [*np.flatnonzero(jump), len(force)]:
        ax.plot(approach[start:end], force[start:end], "-", color=colour, lw=1.4)
        if end < len(force):
            ax.plot(approach[end - 1 : end + 1], force[end - 1 : end + 1], ":", color=colour, lw=1.0)
        start = end
    scalars = record.scalars
    pull_off = _scalar(scalars, "pull_off_force")
    force_unit = "N/m" if _per_length([record]) else "N"
    ax.plot(
        scalars["pull_off_approach"] / a_scale,
        -pull_off / f_scale,
        "v",
        color=colour,
        label=f"{record.label}: pull-off {_with_unit(pull_off, _scale([pull_off], force_unit))}",
    )
    if "winkler_force" in data:
        ax.plot(approach, np.asarray(data["winkler_force"]) / f_scale, "--", color=colour, lw=1.2)
        ax.plot(
            scalars["winkler_pull_off_approach"] / a_scale,
            -scalars["winkler_pull_off_force"] / f_scale,
            "s",
            mfc="none",
            color=colour,
            label=f"Winkler springs: pull-off {_with_unit(scalars['winkler_pull_off_force'])}",
        )


def _approach_limits(datasets) -> tuple[float, float]:
    """Return the ends of the force-approach axes [m]: from a tenth of the span before any force is felt.

    The programme starts several ranges apart, where nothing happens; the axes begin where the
    force of any case first exceeds 0.1 % of the largest force of all of them.
    """
    approach = [np.asarray(d["approach"]) for d in datasets]
    force = [np.abs(np.asarray(d["force"])) for d in datasets]
    largest = max(float(f.max()) for f in force) or 1.0
    felt = [a[f > 1e-3 * largest] for a, f in zip(approach, force, strict=True)]
    first = min((float(a.min()) for a in felt if a.size), default=min(float(a.min()) for a in approach))
    right = max(float(a.max()) for a in approach)
    left = max(first - 0.1 * (right - first), min(float(a.min()) for a in approach))
    return left, right + 0.02 * (right - left)


def _with_unit(value: float, scale: tuple[float, str] | None = None) -> str:
    """``value`` [N or m^2] in ``scale`` (its own prefix without one), three digits."""
    scale = scale or _scale([value], "N")
    return f"{value / scale[0]:.3g} {scale[1]}"


@caption(
    "Normal force against the flat's approach (from the first touch of the undeformed surface) over "
    "the load-unload cycle of up to six cases (left: the whole cycle; right: near the pull-off, forces "
    "within 1.5 times the largest pull-off force): solid, the boundary-element solution step by step; "
    "dotted, a jump into or out of contact (bracketed to the jump resolution); triangle, the pull-off "
    "force; dashed and open square, paper 000's Winkler-layer springs on the same surface and their "
    "pull-off (winkler = true). The area "
    "inside a cycle is the energy it dissipates."
)
def _force_approach(records, context):
    from ...plotting.layout import legend, new_figure

    chosen = evenly_chosen([r for r in records if r.fields_path is not None], 6)
    if not chosen:
        return None
    datasets = [record.dataset() for record in chosen]
    scales = (
        _scale(np.concatenate([np.asarray(d["approach"]) for d in datasets]), "m"),
        _scale(
            np.concatenate([np.asarray(d["force"]) for d in datasets]),
            "N/m" if "y" not in datasets[0].dims else "N",
        ),
    )
    figure, axes = new_figure(1, 2, width=5.4, height=4.4)
    whole, zoom = axes[0]
    for ax in (whole, zoom):
        for index, (record, data) in enumerate(zip(chosen, datasets, strict=True)):
            _draw_cycle(ax, data, record, f"C{index}", scales)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_xlabel(f"approach ({scales[0][1]})")
        ax.set_ylabel(f"normal force ({scales[1][1]})")
    whole.set_xlim(*(limit / scales[0][0] for limit in _approach_limits(datasets)))
    tension = max(float(_scalar(r.scalars, "pull_off_force")) for r in chosen) or 1.0
    zoom.set_ylim(-ZOOM * tension / scales[1][0], ZOOM * tension / scales[1][0])
    left, _ = _approach_limits(datasets)
    right = max(
        float(np.asarray(d["approach"])[np.asarray(d["force"]) <= ZOOM * tension].max()) for d in datasets
    )
    zoom.set_xlim(left / scales[0][0], right / scales[0][0])
    winkler = any("winkler_force" in d for d in datasets)
    whole.set_title("load-unload cycle" + (" (dashed: Winkler springs)" if winkler else ""))
    zoom.set_title("near the pull-off")
    ax = zoom
    legend(ax, fontsize="small")
    return figure


ZOOM = 1.5
"""The right panel of ``force_approach`` spans forces of +-this many times the largest pull-off."""


MAP_MARGIN = 4
"""Pixels kept around the region within :data:`GAP_RANGES` interaction ranges of the flat (``maps``)."""

GAP_RANGES = 3.0
"""The ``maps`` figure shows gaps up to this many interaction ranges (farther ones saturate)."""


def _near_contact(data, interaction_range: float):
    """Return the maps with ``relative_gap`` (gap / range), cropped to where it is below :data:`GAP_RANGES`.

    The box keeps :data:`MAP_MARGIN` pixels around that region; a profile is returned whole.
    """
    data = data.assign(relative_gap=data["gap"] / interaction_range)
    if "y" not in data.dims:
        return data
    box = box_around(np.asarray(data["relative_gap"].transpose("x", "y")) < GAP_RANGES, MAP_MARGIN)
    return data if box is None else data.isel(x=box[0], y=box[1])


@caption(
    "Contact pressure (top; compressive positive, tensile negative, on one symmetric colour scale "
    "clipped to the 0.5-99.5 percentiles of all panels) and gap in units of the case's interaction "
    "range (bottom; 0 to 3, farther gaps saturate) at the pull-off of up to three cases (2D "
    "surfaces), each cropped to where the gap is below three ranges. Titles give "
    "the case, its pull-off force and the contact and interaction areas there."
)
def _maps(records, context):
    from ...plotting.layout import ColourScale, clipped_limits, new_figure, shared_colorbar
    from ...plotting.study import map_axes

    chosen = evenly_chosen([r for r in records if r.fields_path is not None], 3)
    fields = [
        _near_contact(r.dataset().sel(state="pull_off"), r.scalars["interaction_length"]) for r in chosen
    ]
    if not chosen or "y" not in fields[0].dims:
        return None
    figure, axes = new_figure(2, len(chosen), width=3.8 if len(chosen) > 1 else 4.8, height=3.3)
    pooled = np.concatenate([np.ravel(np.asarray(f["pressure"])) for f in fields])
    low, high = clipped_limits(pooled, (0.5, 99.5))
    bound = max(abs(low), abs(high)) or 1.0
    pressure_scale = ColourScale(-bound, bound, "colours clipped to 0.5-99.5 percentile", "both")
    gap_scale = ColourScale(0.0, GAP_RANGES, f"top: {GAP_RANGES:g} ranges", "max")
    rows = (
        ("pressure", "pressure", "Pa", "RdBu_r", pressure_scale),
        ("relative_gap", "gap / interaction range", "", "viridis", gap_scale),
    )
    for row, (name, label, unit, cmap, scale) in enumerate(rows):
        for column, data in enumerate(fields):
            image = map_axes(
                axes[row][column], data[name], label, unit, cmap=cmap, scale=scale, colorbar=False
            )
        shared_colorbar(image, axes[row], label, unit, scale)
    line = _per_length(chosen)
    force_unit = _scale([_scalar(r.scalars, "pull_off_force") for r in chosen], "N/m" if line else "N")
    area_unit = _scale(
        [_scalar(r.scalars, "interaction_area_at_pull_off") for r in chosen], "m" if line else "m^2"
    )
    for record, ax in zip(chosen, axes[0], strict=True):
        s = record.scalars
        ax.set_title(
            f"{record.label}\npull-off {_with_unit(_scalar(s, 'pull_off_force'), force_unit)}\ncontact "
            f"{_with_unit(_scalar(s, 'contact_area_at_pull_off'), area_unit)}, interacting "
            f"{_with_unit(_scalar(s, 'interaction_area_at_pull_off'), area_unit)}",
            fontsize="small",
        )
    return figure


_SWEPT = (("work_of_adhesion", "J/m^2", "work of adhesion"), ("interaction_length", "m", "interaction range"))
"""Scalars the ``pull_off`` figure puts on its abscissa, the first that differs between cases."""


@caption(
    "Pull-off force against the work of adhesion (or, when that is the same for every case, the "
    "interaction range) over the cases, with paper 000's Winkler springs beside (winkler = true) and, "
    "on a generated sphere, the Maugis-Dugdale pull-off of the smooth sphere (dotted)."
)
def _pull_off(records, context):
    from ...plotting.layout import legend, new_figure

    swept = [entry for entry in _SWEPT if len({float(r.scalars[entry[0]]) for r in records}) > 1]
    if not swept:
        return None
    name, unit, words = swept[0]
    order = sorted(records, key=lambda r: float(r.scalars[name]))
    x = np.array([float(r.scalars[name]) for r in order])
    series = {
        "boundary elements": ("pull_off_force", "o-"),
        "Winkler springs (paper 000)": ("winkler_pull_off_force", "s--"),
        "Maugis-Dugdale, smooth sphere": ("maugis_dugdale_pull_off", "kx:"),
    }
    x_scale = _scale(x, unit)
    y_scale = _scale(
        [_scalar(r.scalars, "pull_off_force") for r in order], "N/m" if _per_length(order) else "N"
    )
    figure, axes = new_figure(1, 1)
    ax = axes[0][0]
    for label, (key, style) in series.items():
        y = np.array(
            [float(r.scalars.get(key, r.scalars.get(LINE_NAMES.get(key, ""), np.nan))) for r in order]
        )
        ax.plot(x / x_scale[0], y / y_scale[0], style, label=label)
    ax.set_xlabel(f"{words} ({x_scale[1]})")
    ax.set_ylabel(f"pull-off force ({y_scale[1]})")
    ax.set_title("pull-off force")
    legend(ax)
    return figure


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
    figures={"force_approach": _force_approach, "maps": _maps, "pull_off": _pull_off},
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
)
