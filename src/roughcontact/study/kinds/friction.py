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
from collections.abc import Sequence
from dataclasses import fields
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import Field, field_validator, model_serializer, model_validator
from pydantic_core import PydanticCustomError

from ...cases import at_load, by_sample, grouped, loads_of
from ...errors import InputError
from ...papers import paper000
from ...topography import statistics
from ...winkler_lj import WinklerLJResult
from ..kind import CaseOutput, CaseParameters, CaseRecord, FigureContext, Kind, figure, fill_from_paper
from ..schema import Force, Length, MaterialName, Pressure, Strict, SurfaceEnergy, Time, TopographyName
from ..store import Table
from .common import box_around

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
    if parameters.crossover:
        scalars["crossover_load"] = model.crossover_load()
    return CaseOutput(scalars, _cropped(result), tuple(result.range_warnings()))


# --- figures and tables (from stored records) ------------------------------------------------------


def _at_one_load(records: Sequence[CaseRecord], load: float | None) -> list[CaseRecord]:
    """Return the records at ``load``, or all of them when the analysis has one load; else InputError."""
    loads = loads_of(records)
    if load is None:
        if len(loads) > 1:
            raise InputError(
                "compare.normal_force",
                f"the analysis has {len(loads)} loads ({loads[0]:.4g} to {loads[-1]:.4g} N) and the "
                "measured values are at one.",
                "add normal_force = '10 uN' (the load of the measurements) to [analysis.compare].",
            )
        return list(records)
    chosen = at_load(records, load)
    if not chosen:
        raise InputError(
            "compare.normal_force",
            f"no case at {load:.6g} N (the analysis has {', '.join(f'{x:.6g}' for x in loads)} N).",
            "set compare.normal_force to one of the analysis' loads.",
        )
    return chosen


def comparison(records: Sequence[CaseRecord], context: FigureContext):
    """Compare the simulated mu per sample with the measured CSV of ``[analysis.compare]``.

    Parameters
    ----------
    records : sequence of CaseRecord
        The analysis' finished cases.
    context : FigureContext
        ``context.compare`` is a :class:`FrictionCompare`.

    Returns
    -------
    Comparison
        From :func:`roughcontact.experiment.compare.compare`, over the samples found on both sides
        (samples on one side only are left out with a warning).

    Raises
    ------
    InputError
        Several loads and no ``compare.normal_force``, an unreadable CSV, no sample in common, or fewer
        than two values in a sample.
    """
    from ...experiment.compare import compare, read_measured

    spec = context.compare
    simulated = by_sample(_at_one_load(records, spec.normal_force), "mu")
    measured = read_measured(spec.measured)
    common = [s for s in simulated if s in measured]
    left_out = sorted(set(simulated) ^ set(measured))
    if not common:
        raise InputError(
            "compare.measured",
            f"no sample in common: simulated {list(simulated)}, measured {list(measured)}.",
            "name the samples of the analysis as in the CSV's sample column.",
        )
    if left_out:
        log.warning("%s: samples %s are on one side only and are left out", context.analysis, left_out)
    return compare(
        {s: simulated[s] for s in common},
        {s: measured[s] for s in common},
        alpha=spec.alpha,
        equal_var=spec.equal_var,
        origin=measured.origin,
    )


def by_reading(records: Sequence[CaseRecord]) -> dict[str, list[CaseRecord]]:
    """Return the records grouped by their readings (:func:`reading_label`), in order of first appearance."""
    groups: dict[str, list[CaseRecord]] = {}
    for record in records:
        groups.setdefault(reading_label(record.parameters), []).append(record)
    return groups


def _comparison_or_none(records, context):
    """Return the comparison with ``[analysis.compare]`` for the figures (its errors reach the report).

    None without one, and for an analysis of several readings (the figures would pool them; the
    ``comparison`` table has a row per reading and sample).
    """
    if context.compare is None or len(by_reading(records)) > 1:
        return None
    return comparison(records, context)


def _comparison_table(records, context):
    """Tabulate the t-tests and Pearson r against ``[analysis.compare]``, per reading where several."""
    if context.compare is None:
        return None
    groups = by_reading(records)
    rows, notes = [], []
    for label, group in groups.items():
        result = comparison(group, context)  # its errors are listed in the report
        common = {
            "alpha": result.alpha,
            "test": "student" if result.equal_var else "welch",
            "pearson_r": result.pearson_r,
            "pearson_p": result.pearson_p,
        }
        reading = {"reading": label} if len(groups) > 1 else {}
        rows += [reading | row | common for row in result.table()]
        notes = result.notes()
    return Table(rows, notes)


def per_reading(table):
    """Return ``table`` computed for each reading (and gap model) of the analysis apart.

    An analysis that sweeps the readings holds several models of the same scans; pooling their mu
    into one mean or one trend would mix them. With several readings each row starts with its
    ``reading`` (:func:`reading_label`).
    """

    def separately(records, context):
        groups = by_reading(records)
        rows = []
        for label, group in groups.items():
            named = {"reading": label} if len(groups) > 1 else {}
            rows += [named | row for row in table(group, context) or ()]
        return rows or None

    separately.__doc__ = table.__doc__
    return separately


def _by_sample(records, context):
    """Mean, spread and range of mu per sample and load over its replicates (None without replicates).

    With one case per sample and load the table would only repeat the cases' own rows.
    """
    rows = []
    for sample, group in grouped(records).items():
        for load in loads_of(group):
            chosen = at_load(group, load)
            mu = np.array([float(r.scalars["mu"]) for r in chosen])
            row: dict[str, Any] = {
                "sample": sample,
                "normal_force [N]": load,
                "n": mu.size,
                "mu_mean": float(mu.mean()),
                "mu_std": float(mu.std(ddof=1)) if mu.size > 1 else None,
                "mu_min": float(mu.min()),
                "mu_max": float(mu.max()),
            }
            for name in ("friction", "adhesive_friction", "mechanical_friction", "crossover_load"):
                values = [r.scalars.get(name) for r in chosen]
                values = [float(v) for v in values if v is not None]
                if values:
                    row[f"{name}_mean [N]"] = float(np.mean(values))
            rows.append(row)
    return rows if any(row["n"] > 1 for row in rows) else None


def _ra_trend(records, context):
    """Whether simulated mu changes with the samples' Ra beyond the scatter of the realisations.

    Per load, over every case: the least-squares slope of mu against the Ra of the sample's
    surface (``surface_ra``) with its 95 % interval and p value (``scipy.stats.linregress``),
    and the one-way ANOVA of mu across the samples (``scipy.stats.f_oneway``). ``trend`` says
    ``mu rises with Ra`` / ``mu falls with Ra`` where the slope's interval excludes 0, else
    ``within the scatter``. None with fewer than two samples or without realisations.
    """
    from scipy import stats

    rows = []
    for load in loads_of(records):
        chosen = [r for r in at_load(records, load) if r.scalars.get("surface_ra") is not None]
        samples = grouped(chosen)
        if len(samples) < 2 or len(chosen) <= len(samples):
            continue
        ra = np.array([float(r.scalars["surface_ra"]) for r in chosen])
        mu = np.array([float(r.scalars["mu"]) for r in chosen])
        if np.ptp(ra) <= 1e-12 * ra.max():
            continue
        fit = stats.linregress(ra, mu)
        half = float(stats.t.ppf(0.975, ra.size - 2)) * fit.stderr
        anova = stats.f_oneway(*[[float(r.scalars["mu"]) for r in group] for group in samples.values()])
        low, high = fit.slope - half, fit.slope + half
        trend = "mu rises with Ra" if low > 0 else "mu falls with Ra" if high < 0 else "within the scatter"
        rows.append(
            {
                "normal_force [N]": load,
                "samples": len(samples),
                "n": ra.size,
                "dmu_dRa [1/m]": fit.slope,
                "dmu_dRa 95% low [1/m]": low,
                "dmu_dRa 95% high [1/m]": high,
                "slope_p_value": fit.pvalue,
                "anova_p_value": float(anova.pvalue),
                "trend": trend,
            }
        )
    return rows or None


def reading_label(parameters: dict[str, Any]) -> str:
    """Name a case's readings in words: its preset, and the fields its ``readings`` table changes in it.

    ``default``, ``paper``, ``default but adhesive_range=all_springs, base=half_sphere``; a gap
    model other than the springs' is added (``, gap model bem``).
    """
    from ...winkler_lj.readings import Readings

    label = parameters.get("reading") or "default"
    preset = Readings.preset(label)
    given = parameters.get("readings") or {}
    changed = {key: value for key, value in given.items() if str(getattr(preset, key, None)) != str(value)}
    if changed:
        label += " but " + ", ".join(f"{key}={value}" for key, value in changed.items())
    if parameters.get("gap_model") not in (None, "winkler"):
        label += f", gap model {parameters['gap_model']}"
    return label


def _claim_cells(values: list[float], claim) -> tuple[dict[str, Any], str]:
    """Return the columns of one of paper 000's claims (our mean and intervals) and its verdict.

    ``factor from paper``: the smallest factor f for which the prediction interval lies within
    [v / f, v f] of the printed value v, so that a reader can apply another tolerance than
    :data:`~roughcontact.papers.paper000.ROUGHLY`.
    """
    from ...spread import natural_bounds, spread

    name = claim.quantity + (f" ({claim.sample})" if claim.sample else "")
    unit = " [N]" if claim.quantity.endswith("load") else ""
    verdict_column = f"paper {claim.where}: {claim.short}"
    if not values:
        why = " (crossover = true computes it)" if claim.quantity == "crossover_load" else ""
        return {verdict_column: f"not computed{why}"}, "not computed"
    summary = spread(values, bounds=natural_bounds(claim.quantity))
    low, high = summary.prediction()
    verdict = summary.within(claim.value / paper000.ROUGHLY, claim.value * paper000.ROUGHLY, of="one")
    verdict = {"inside": "kept", "outside": "not kept"}.get(verdict, verdict)
    factor = max(claim.value / low, high / claim.value) if low > 0 else math.inf
    cells = {
        f"{name} n": summary.n,
        f"{name} mean{unit}": summary.mean,
        f"{name} 95% prediction low{unit}": low,
        f"{name} 95% prediction high{unit}": high,
        f"{name} 95% mean low{unit}": summary.ci95_low,
        f"{name} 95% mean high{unit}": summary.ci95_high,
        f"{name} factor from paper": factor,
        verdict_column: verdict,
    }
    return cells, verdict


def _p_value_cell(records, context) -> tuple[str, str]:
    """Return the p values of one reading's mu against ``[analysis.compare]`` and the claim's verdict."""
    if context.compare is None:
        return "no compared values", "not tested"
    try:
        result = comparison(records, context)
    except InputError as error:  # the comparison table says why; the other claims still stand
        return f"no comparison ({error.problem})", "not tested"
    shown = ", ".join(f"{s.sample} {s.p_value:.2g}" for s in result.samples)
    if result.by_construction:
        return shown, "no verdict: the values were built from this model"
    kept = all(s.p_value > paper000.P_THRESHOLD for s in result.samples)
    against = "" if result.origin.is_measured else f" (against {result.origin.words} values)"
    return shown, ("kept" if kept else "not kept") + against


def _claims_table(records, context):
    """Judge paper 000's claims about its simulations under each reading of the analysis.

    One row per reading (:func:`reading_label`) of the cases of paper 000's scenario (polysilicon
    against SiO2 at the paper's 10 uN, as ``paper000 = true`` sets it): the ratio of adhesive to
    mechanical friction over every scan (the paper: "roughly 40 times ... for all the
    SiO2-polysilicon contacts", sec. 5), the crossover load of
    the Ra 1.7 nm scans ("about 600 uN", sec. 6; with ``crossover = true``) and the t-test p
    values against ``[analysis.compare]`` (p > 0.1 for every sample, sec. 5). A claim is *kept*
    where the 95 % prediction interval of one scan lies within a factor
    :data:`~roughcontact.papers.paper000.ROUGHLY` of the printed value, *not kept* where it lies
    wholly outside, *not established* where it straddles an edge of that band. Compared values
    built from this model's output judge no reading (``by construction``). The notes say which
    claims each reading keeps and whether any keeps them all. None for other analyses, or with one
    scan per reading.
    """
    from ...cases import at_load

    bodies = (paper000.MATERIAL, paper000.TIP_MATERIAL)
    chosen = [
        r for r in records if (r.parameters.get("material"), r.parameters.get("counter_body")) == bodies
    ]
    chosen = at_load(chosen, paper000.NORMAL_FORCE) if chosen else []
    if not chosen:
        return None
    readings = by_reading(chosen)
    if all(len(group) < 2 for group in readings.values()):
        return None  # one scan per reading: no interval to judge with
    rows, kept = [], {}
    for label, group in readings.items():
        row: dict[str, Any] = {"reading": label}
        verdicts = []
        for claim in paper000.CLAIMS:
            cases = [r for r in group if claim.sample in (None, r.parameters.get("sample"))]
            values = [float(v) for r in cases if (v := r.scalars.get(claim.quantity)) is not None]
            cells, verdict = _claim_cells(values, claim)
            row |= cells
            verdicts.append(verdict)
        shown, verdict = _p_value_cell(group, context)
        row |= {"p values": shown, f"paper sec. 5: p > {paper000.P_THRESHOLD:g}": verdict}
        verdicts.append(verdict)
        judged = [v for v in verdicts if v in ("kept", "not kept", "not established")]
        row["claims kept"] = f"{judged.count('kept')} of {len(judged)} judged"
        kept[label] = verdicts
        rows.append(row)
    return Table(rows, _claims_notes(kept, context))


def _claims_notes(kept: dict[str, list[str]], context) -> list[str]:
    """Return the sentences that go with the claims table: how it judges, and what it finds."""
    names = [f"{c.short} ({c.where})" for c in paper000.CLAIMS] + [f"p > {paper000.P_THRESHOLD:g} (sec. 5)"]
    notes = [
        "Paper 000's claims: "
        + "; ".join(f"'{c.words}' ({c.where})" for c in paper000.CLAIMS)
        + f"; t-test p > {paper000.P_THRESHOLD:g} for every sample (sec. 5).",
        "Each claim is judged with the 95 % prediction interval of one scan: kept where it lies within a "
        f"factor {paper000.ROUGHLY:g} of the printed value (our reading of 'roughly' and 'about'; the "
        "paper gives none), not kept where it lies wholly outside that band, not established otherwise. "
        "'factor from paper' is the smallest factor that would keep it; the mean's interval is beside it.",
    ]
    if context.compare is not None:
        origin = comparison_origin(context)
        if origin.by_construction:
            notes.append(
                f"The compared mu are {origin.values}, built from this model's own output, so their p "
                "values judge no reading; paper 000 publishes no measured mu, so its p-value claim cannot "
                f"be tested here (their file: {origin.by_construction})."
            )
        elif not origin.is_measured:
            notes.append(origin.caveat())
    full = [label for label, verdicts in kept.items() if all(v == "kept" for v in verdicts)]
    if full:
        notes.append(f"Keeps every claim: {', '.join(full)}.")
    else:
        parts = []
        for label, verdicts in kept.items():
            which = [name for name, v in zip(names, verdicts, strict=True) if v == "kept"]
            parts.append(f"{label}: {', '.join(which) if which else 'none'}")
        notes.append("No reading keeps every claim. Kept, per reading: " + "; ".join(parts) + ".")
    return notes


def comparison_origin(context):
    """Return the origin of the values of ``[analysis.compare]`` (measured unless their file says so)."""
    from ...experiment.compare import read_measured

    return read_measured(context.compare.measured).origin


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
        "mu_boxes": figure("friction.mu_boxes_figure", {"comparison": _comparison_or_none}),
        "mu_means": figure("friction.mu_means_figure", {"comparison": _comparison_or_none}),
    },
    tables={
        "comparison": _comparison_table,
        "claims": _claims_table,
        "by_sample": per_reading(_by_sample),
        "ra_trend": per_reading(_ra_trend),
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
