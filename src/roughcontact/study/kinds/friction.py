r"""Study kind ``friction``: the Winkler-layer Lennard-Jones friction of paper 000 at one load per case.

Wraps :func:`roughcontact.winkler_lj.winkler_lj_model` and its ``solve(load)`` (details and the
derivations on the Winkler-layer page). The two topographies (``topography``, e.g. a polysilicon
scan, and ``counter_topography``, e.g. the AFM tip) are merged into one composite surface z_i facing a rigid
flat (paper 000, Fig. 1); each pixel is a spring, a cuboid of top area S (the pixel area) and
height h (``layer_thickness``, the Winkler layer):

* eq. 1: E = [(1 - nu1^2) / E1 + (1 - nu2^2) / E2]^-1 (``material`` and ``counter_body``; no
  ``counter_body``: a rigid counter-body);
* eqs. 3-4: spring stress P_i = E dz_i / (k h), k = (1 + s)(1 - 2s) / (1 - s), s = sqrt(nu1 nu2)
  (the uniaxial-strain reading; eq. 4 prints the denominator 1 - nu1 nu2);
* eqs. 5-7: attraction f(l) = (8 dgamma / 3 eps) [(eps / l)^3 - (eps / l)^9] (``epsilon``),
  dgamma from the two surface energies (``surface_energy``, ``counter_surface_energy``; default
  the materials' own);
* eq. 2: sum P_i S - sum f(l_i) S = N (``normal_force``) for the separation d, l_i = d - z_i;
* eq. 8: extension dz_i = f(l_i) k h / E of the springs in adhesive contact;
* eqs. 9-15: lateral force Q_i = sqrt(2 W_i / (c H_i)) that breaks the bond of an adhesive spring
  (shear work of the cuboid = the bond energy e(l_ia) S of eq. 14);
* eqs. 16-17: the same for the springs in mechanical contact, from the distance l_im where the
  repulsion of eq. 7 carries P_i;
* friction F = sum Q_i, split into its adhesive and mechanical parts, and mu = F / N.

Paper 000's equations have unit and sign problems and gaps; every disputed choice is a named
reading (:class:`~roughcontact.winkler_lj.readings.Readings`), given in the study file as a table of
name = value strings, e.g. ``readings = {contact = "zero_gap", adhesive_cutoff = "20 nm"}``
(``adhesive_cutoff`` takes a length with its unit, or ``inf``). A reading not
named keeps its default, the physically consistent one, or the value of the preset named by
``reading``: ``"default"``, ``"paper"`` (the paper's own reading,
:data:`~roughcontact.winkler_lj.readings.PAPER`: printed eqs. 4, 12, 15 and 17 and dgamma, the
half-sphere tip of section 3.1, which gives the paper's headline results) or ``"printed"``
(every equation as printed, :data:`~roughcontact.winkler_lj.readings.PRINTED`); the entries of the
``readings`` table change the preset's fields, e.g. ``reading = "paper"`` with ``readings =
{adhesive_range = "maugis_dugdale"}``. The half-sphere tip (``base = "half_sphere"``, in the
``"paper"`` preset) needs the tip's radius: ``tip_radius``, default the ``radius`` the counter
topography was generated with. Stated assumptions of the model (paper
000, sections 2-3): elastic contact only (no plasticity), the flat is rigid, the cuboid tops are
the scan's pixels (S = 20 nm x 20 nm in the paper), epsilon = 2 nm and h = the thickness of the
measured layer (50 nm), the defaults here.

Gap model (``gap_model``): ``"winkler"`` (default, the paper's): eq. 2 gives the springs'
separations l_i = d - z_i - dz_i that the friction sums (eqs. 8-17) use; ``"bem"``: the friction
sums use the gap and pressure of the adhesive boundary-element solution at the same load instead
(the elastic half-space under the same composite surface, contact modulus E of eq. 1 and
paper 000's law ``LennardJones(dgamma, epsilon)``, free boundary; its state on the loading branch
whose force equals ``normal_force`` within 1e-6 of it): pixels in repulsion are the mechanical
springs with the BEM pressure, the others bond at l = g + epsilon
(:meth:`~roughcontact.winkler_lj.WinklerLJModel.solve`). Eq. 2's readings (``balance_terms``,
``adhesion_sign``, ``contact``) must keep their defaults there, and ``crossover`` is refused (a
search over loads of boundary-element solves). The scalar ``gap_model`` says which was used; with
``"bem"`` also ``bem_force`` and ``bem_load_error``.

Hold time (paper 000, end of section 2: "a time-dependent elastic modulus"): with
``relaxed_modulus`` the surface material is a standard linear solid from its Young's modulus E0 to
``relaxed_modulus`` with ``relaxation_time`` tau, and E(hold_time) = E_inf + (E0 - E_inf)
exp(-t / tau) replaces E0 in eq. 1 (as ``roughcontact friction --relaxed-modulus``).

Scalars: those of :meth:`~roughcontact.winkler_lj.WinklerLJResult.scalars` (mu, friction, its
adhesive and mechanical parts, separation, springs in each state, ...), the readings that differ
from the defaults (``readings``, e.g. ``contact=zero_gap``, or ``defaults``), the ratio of adhesive to
mechanical friction, the model's constants (contact modulus, Winkler factor, shear modulus, work
of adhesion, spring stiffness and area), the load the layer can carry and, with ``crossover =
true``, the load where mechanical friction overtakes adhesive friction (paper 000, section 6:
about 600 uN for Ra 1.7 nm). Fields: :meth:`~roughcontact.winkler_lj.WinklerLJResult.to_xarray`
cropped to the springs that carry friction (mechanical or bonded) and a margin of
:data:`FIELD_MARGIN` pixels (outside them Q_i = 0 by construction); none when that window exceeds
:data:`FIELD_POINTS` points.

Figures: ``friction_vs_load`` (mu and the adhesive and mechanical friction against the load, one
line per sample; needs several loads), ``mu_boxes`` and ``mu_means`` (the simulated mu per sample
beside the measured values when the analysis has a ``compare`` table; paper 000, Figs. 9 and 8).
Tables: ``comparison`` (per-sample two-sample t-test and the Pearson r of the means, paper 000
section 5, with ``compare``) and ``by_sample`` (mean, standard deviation and number of mu values
per sample and load).

References
----------
Seed paper 000, "Simulation model for frictional contact of two elastic surfaces in micro/nanoscale
and its validation", eqs. 1-17, sections 3-5.
"""

from __future__ import annotations

import difflib
import logging
import math
from dataclasses import fields
from pathlib import Path
from typing import Any, Literal

from pydantic import Field, field_validator, model_serializer, model_validator
from pydantic_core import PydanticCustomError

from ...errors import InputError
from ...papers import paper000
from ...topography import statistics
from ...winkler_lj import WinklerLJResult
from ..kind import CaseOutput, CaseParameters, Kind, figure, fill_from_paper
from ..schema import Force, Length, MaterialName, Pressure, Strict, SurfaceEnergy, Time, TopographyName
from .common import box_around
from .friction_tables import by_reading as by_reading  # the names the kind has always served
from .friction_tables import (
    by_sample_table,
    claims_table,
    comparison_or_none,
    comparison_table,
    per_reading,
    ra_trend_table,
)
from .friction_tables import comparison as comparison
from .friction_tables import comparison_origin as comparison_origin
from .friction_tables import reading_label as reading_label

log = logging.getLogger(__name__)

FIELD_MARGIN = 4
"""Pixels kept around the springs that carry friction when the fields are stored."""

FIELD_POINTS = 128 * 128
"""Most grid points of stored fields (about 0.7 MB a case); larger windows store no fields."""


class FrictionParameters(CaseParameters):
    """Keys of a ``model = "friction"`` analysis (SI after validation).

    Attributes
    ----------
    topography : str
        The rough surface (paper 000: a polysilicon scan).
    counter_topography : str, optional
        The counter-body's topography (paper 000: the AFM tip), merged with ``topography``.
    material, counter_body : str
        Materials of the surface's body and of the counter-body (None: rigid).
    normal_force : float
        Normal load N [N].
    layer_thickness, epsilon : float
        Winkler layer height h and the Lennard-Jones equilibrium distance [m] (paper 000: 50 nm, 2 nm).
    surface_energy, counter_surface_energy : float, optional
        gamma1, gamma2 [J/m^2]; default the materials' own.
    reading : str
        Preset the ``readings`` table changes: ``"default"``, ``"paper"`` or ``"printed"``.
    readings : dict
        Reading name -> value (strings; ``adhesive_cutoff`` in metres after validation).
    tip_radius : float, optional
        Radius of the half-sphere tip [m] (``base = "half_sphere"``); default the generated tip's.
    resample : bool
        Bring topographies of different pixel sizes onto a common grid instead of refusing them.
    relaxed_modulus, relaxation_time, hold_time : float, optional
        Standard linear solid of the surface's body [Pa, s] and the hold time before sliding [s].
    crossover : bool
        Also find the load where mechanical friction overtakes adhesive friction.
    gap_model : str
        ``"winkler"`` (the springs' gaps of eq. 2) or ``"bem"`` (the adhesive BEM's gap field).
    paper000 : bool
        Fill in paper 000's materials, load, layer, epsilon and surface energies
        (:func:`roughcontact.papers.paper000.friction_keys`) where the analysis leaves them out.
    """

    topography: TopographyName
    counter_topography: TopographyName | None = None
    material: MaterialName
    counter_body: MaterialName | None = None
    normal_force: Force
    layer_thickness: Length = paper000.LAYER_THICKNESS
    epsilon: Length = paper000.EPSILON
    surface_energy: SurfaceEnergy | None = None
    counter_surface_energy: SurfaceEnergy | None = None
    reading: str = "default"
    readings: dict[str, str | float] = Field(default_factory=dict)
    tip_radius: Length | None = None
    resample: bool = False
    relaxed_modulus: Pressure | None = None
    relaxation_time: Time = 1.0
    hold_time: Time = 0.0
    crossover: bool = False
    gap_model: Literal["winkler", "bem"] = "winkler"
    paper000: bool = Field(default=False, exclude=True)
    """Fill in paper 000's scenario (stored as the keys it fills, not as the flag)."""

    @model_validator(mode="before")
    @classmethod
    def _paper000_scenario(cls, data: Any) -> Any:
        return fill_from_paper(data, "paper000", paper000.friction_keys)

    @model_serializer(mode="wrap")
    def _without_unset_newer_keys(self, handler):
        """Leave ``reading``, ``tip_radius`` and ``gap_model`` out at their defaults (old keys stay valid)."""
        data = handler(self)
        if data.get("reading") == "default":
            del data["reading"]
        if data.get("gap_model") == "winkler":
            del data["gap_model"]
        if data.get("tip_radius", 0.0) is None:
            del data["tip_radius"]
        return data

    @field_validator("reading")
    @classmethod
    def _check_preset(cls, value: str) -> str:
        from ...winkler_lj.readings import PRESETS

        if value not in PRESETS:
            close = difflib.get_close_matches(value, list(PRESETS), n=1)
            hint = f"did you mean {close[0]!r}? " if close else ""
            raise PydanticCustomError(
                "readings",
                "unknown preset of the readings",
                {"fix": f"{hint}reading is one of {list(PRESETS)}."},
            )
        return value

    @field_validator("readings")
    @classmethod
    def _check_readings(cls, value: dict[str, str | float]) -> dict[str, str]:
        return normalized_readings(value)

    @model_validator(mode="after")
    def _check(self) -> FrictionParameters:
        bad = [
            name
            for name in ("normal_force", "layer_thickness", "epsilon", "relaxation_time")
            if not (math.isfinite(getattr(self, name)) and getattr(self, name) > 0)
        ]
        if bad:
            raise PydanticCustomError(
                "quantity",
                "{names} must be positive and finite",
                {
                    "names": ", ".join(f"«{name}»" for name in bad),
                    "fix": "e.g. " + ", ".join(f"«{name}={_EXAMPLES[name]}»" for name in bad),
                    "field": bad[0],
                },
            )
        if self.hold_time < 0 or (self.relaxed_modulus is not None and not self.relaxed_modulus > 0):
            raise PydanticCustomError(
                "quantity",
                "«hold_time» must be 0 or more and «relaxed_modulus» positive",
                {"fix": "e.g. «relaxed_modulus=80 GPa», «hold_time=30 s»"},
            )
        if self.gap_model == "bem" and self.crossover:
            raise PydanticCustomError(
                "quantity",
                "«crossover» is not searched with «gap_model=bem» (a boundary-element solve per load)",
                {"fix": "leave «crossover» out, or use «gap_model=winkler»", "field": "crossover"},
            )
        if self.hold_time > 0 and self.relaxed_modulus is None:
            raise PydanticCustomError(
                "quantity",
                "a «hold_time» needs «relaxed_modulus» (the surface's body is elastic otherwise)",
                {"fix": "add «relaxed_modulus=80 GPa» (and «relaxation_time»), or leave «hold_time» out"},
            )
        return self


_EXAMPLES = {"normal_force": "10 uN", "layer_thickness": "50 nm", "epsilon": "2 nm", "relaxation_time": "1 s"}


def normalized_readings(value: dict[str, Any]) -> dict[str, str]:
    """Check a study's ``readings`` table and return it as ``{name: value}`` strings.

    Every name and value is checked by :class:`~roughcontact.winkler_lj.readings.Readings`
    (through :meth:`~roughcontact.winkler_lj.readings.Readings.from_strings`);
    ``adhesive_cutoff`` may be a length with a unit (``"20 nm"``) and is returned in metres.

    Parameters
    ----------
    value : dict
        Reading name -> value as written in the study file.

    Returns
    -------
    dict of str to str
        Canonical strings, so that the same readings written differently give the same case key.

    Raises
    ------
    pydantic_core.PydanticCustomError
        An unknown name or value; the message names the reading and lists the allowed values.
    """
    from ...units import quantity
    from ...winkler_lj.readings import Readings

    known = [f.name for f in fields(Readings)]
    result: dict[str, str] = {}
    problems: list[tuple[str, str]] = []  # (problem, fix), all of them in one message
    for name, raw in value.items():
        text = str(raw).strip()
        if name not in known:
            close = difflib.get_close_matches(name, known, n=1)
            fix = f"did you mean {close[0]!r}?" if close else f"use one of {known}"
            problems.append((f"unknown reading {name!r}", fix))
            continue
        if name == "adhesive_cutoff":
            try:
                cutoff = (
                    math.inf
                    if text.lower() in ("inf", "infinity")
                    else quantity(raw, "length", require_unit=True)
                )
                text = repr(float(cutoff))
            except InputError as error:
                problems.append(
                    (
                        f"reading 'adhesive_cutoff': {error.problem.rstrip('.')}",
                        "adhesive_cutoff: give a length, e.g. '20 nm', or 'inf'",
                    )
                )
                continue
        try:
            Readings.from_strings([f"{name}={text}"])
        except InputError as error:
            problem = error.problem.rstrip(".").replace("unknown reading", "unknown value")
            problems.append((f"reading {name!r}: {problem}", f"{name}: {error.fix.rstrip('.')}"))
            continue
        result[name] = text
    if problems:
        fix = "; ".join(f for _, f in problems)
        raise PydanticCustomError(
            "readings",
            "{problem}",
            {"problem": "; ".join(p for p, _ in problems), "fix": fix if fix.endswith("?") else fix + "."},
        )
    return result


def readings_of(parameters: FrictionParameters):
    """Return the :class:`~roughcontact.winkler_lj.readings.Readings` of a case."""
    from ...winkler_lj.readings import Readings

    items = (f"{name}={text}" for name, text in parameters.readings.items())
    return Readings.from_strings(items, preset=parameters.reading)


def _check_relaxed(relaxed: float, material) -> None:
    if relaxed > material.youngs_modulus:
        raise InputError(
            "relaxed_modulus",
            f"{relaxed:.4g} Pa is above the Young's modulus {material.youngs_modulus:.4g} Pa "
            f"of {material.name!r}.",
            "a relaxed (long-time) modulus is at most the instantaneous one.",
        )


def check_inputs(parameters: FrictionParameters, known) -> None:
    """Refuse at validation what the model would: a profile, grids that do not merge, no surface energy.

    See :func:`roughcontact.winkler_lj.winkler_lj_model`.
    """
    from ...winkler_lj import surface_energy_of

    material, counter_body = known.material(parameters.material), known.material(parameters.counter_body)
    if parameters.relaxed_modulus is not None:
        _check_relaxed(parameters.relaxed_modulus, material)
    surface_energy_of(parameters.surface_energy, material, "surface_energy")
    surface_energy_of(parameters.counter_surface_energy, counter_body, "counter_surface_energy")
    grid = known.grid(parameters.topography)
    if grid is not None and len(grid[0]) != 2:
        raise InputError(
            "topography", "paper 000's Winkler model takes a map, not a profile.", "give a 2D scan."
        )
    known.check_pair(parameters.topography, parameters.counter_topography, parameters.resample)


def build_model(parameters: FrictionParameters, inputs):
    """Return the :class:`~roughcontact.winkler_lj.WinklerLJModel` of a case (topographies merged).

    ``inputs`` holds the case's topographies and materials. Raises InputError for a relaxed modulus
    above the surface material's Young's modulus, or any refusal of
    :func:`~roughcontact.winkler_lj.winkler_lj_model`.
    """
    from ...winkler_lj import WinklerLJOptions, winkler_lj_model
    from ...winkler_lj.viscoelastic import standard_linear_solid

    material = inputs.material(parameters.material)
    relaxation = None
    if parameters.relaxed_modulus is not None:
        _check_relaxed(parameters.relaxed_modulus, material)
        relaxation = standard_linear_solid(
            material.youngs_modulus, parameters.relaxed_modulus, parameters.relaxation_time
        )
    options = WinklerLJOptions(
        layer_thickness=parameters.layer_thickness,
        epsilon=parameters.epsilon,
        surface_energy=parameters.surface_energy,
        counter_surface_energy=parameters.counter_surface_energy,
        readings=readings_of(parameters),
        resample=parameters.resample,
        relaxation=relaxation,
        hold_time=parameters.hold_time if relaxation is not None else 0.0,
        tip_radius=parameters.tip_radius,
        gap_model=parameters.gap_model,
    )
    counter_topography = parameters.counter_topography
    return winkler_lj_model(
        inputs.topography(parameters.topography),
        material,
        inputs.material(parameters.counter_body),
        options=options,
        counter_topography=None if counter_topography is None else inputs.topography(counter_topography),
    )


def _cropped(result) -> Any:
    """Return the result's fields within the box of the springs that carry friction, plus a margin.

    None when that box holds more than :data:`FIELD_POINTS` points (a nominally flat contact,
    where most of the scan carries friction): the scalars are the result then.
    """
    box = box_around(result.mechanical | result.bonded, FIELD_MARGIN)
    if box is None:  # nothing carries friction (only under adhesion_sign="printed")
        return None
    x, y = box
    if (x.stop - x.start) * (y.stop - y.start) > FIELD_POINTS:
        return None
    return result.to_xarray().isel(x=x, y=y)


def run(parameters: FrictionParameters, inputs) -> CaseOutput:
    """Solve one case: the separation at ``normal_force`` (equation 2), friction and mu (equations 8-17)."""
    model = build_model(parameters, inputs)
    result = model.solve(parameters.normal_force)
    constants = model.parameters()
    scalars: dict[str, Any] = dict(result.scalars())
    changed = model.readings.changed()
    scalars["readings"] = ", ".join(f"{k}={v}" for k, v in changed.items()) or "defaults"
    scalars["gap_model"] = result.gap_model
    mechanical = result.mechanical_friction
    scalars["adhesive_to_mechanical"] = result.adhesive_friction / mechanical if mechanical > 0 else None
    for name in (
        "contact_modulus",
        "winkler_factor",
        "shear_modulus",
        "work_of_adhesion",
        "spring_stiffness",
        "spring_area",
    ):
        scalars[name] = constants[name]
    scalars["load_capacity"] = model.load_capacity()
    scalars["surface_ra"] = statistics.ra(inputs.topography(parameters.topography))
    scalars["surface_origin"] = inputs.origin(parameters.topography)  # measured scan or generated stand-in
    if parameters.crossover:
        scalars["crossover_load"] = model.crossover_load()
    return CaseOutput(scalars, _cropped(result), tuple(result.range_warnings()))


class FrictionCompare(Strict):
    """The ``[analysis.compare]`` table of a friction analysis: measured mu per sample.

    Attributes
    ----------
    measured : Path
        CSV with columns ``sample`` and ``mu`` (``#`` lines are comments), relative to the study
        file; the samples are matched with the cases' ``sample`` labels.
    alpha : float
        Threshold of the t-tests (paper 000: 0.1; p > alpha counts as agreement).
    equal_var : bool
        Student's pooled-variance t-test if true; Welch's (default) does not assume that simulation
        and measurement scatter alike.
    normal_force : float, optional
        Load of the measurements [N]; needed only when the analysis sweeps the load (the cases at
        this load are compared).
    """

    measured: Path
    alpha: float = Field(default=0.1, gt=0.0, lt=1.0)
    equal_var: bool = False
    normal_force: Force | None = None


KIND = Kind(
    name="friction",
    summary="Winkler-layer Lennard-Jones friction at one load: mu, adhesive and mechanical parts (paper 000)",
    parameters=FrictionParameters,
    run=run,
    check_inputs=check_inputs,
    units=WinklerLJResult.UNITS
    | {
        "bem_force": "N",
        "crossover_load": "N",
        "load_capacity": "N",
        "contact_modulus": "Pa",
        "shear_modulus": "Pa",
        "work_of_adhesion": "J/m^2",
        "spring_stiffness": "Pa/m",
        "spring_area": "m^2",
        "surface_ra": "m",
    },
    figures={
        "friction_vs_load": figure("friction.friction_vs_load_figure"),
        "mu_boxes": figure("friction.mu_boxes_figure", {"comparison": comparison_or_none}),
        "mu_means": figure("friction.mu_means_figure", {"comparison": comparison_or_none}),
    },
    tables={
        "comparison": comparison_table,
        "claims": claims_table,
        "by_sample": per_reading(by_sample_table),
        "ra_trend": per_reading(ra_trend_table),
    },
    compare=FrictionCompare,
    headline=("mu", "adhesive_friction", "mechanical_friction", "adhesive_to_mechanical", "crossover_load"),
    renamed={
        "surface": "topography",
        "counter_surface": "counter_topography",
        "counter": "counter_body",
        "load": "normal_force",
    },
    references=(
        "paper000",
        "johnson1985",
        "greenwood1997",
        "israelachvili2011",
        "girifalco1957",
        "welch1947",
        "polonsky1999",
        "rey2017",
    ),
)
