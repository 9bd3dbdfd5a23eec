r"""Study kind ``presliding``: a rough ball on a flat under a tangential programme, K_L against Mindlin.

One case is one rough ball (heights *with* its spherical shape, as paper 001 Fig. 4) pressed on a
flat with a constant normal force F0 and taken through a tangential programme: paper 001's (give
``stroke``) or your own (give ``path``, a CSV file). It wraps
:func:`roughcontact.contact.presliding.presliding`:

1. Normal contact (paper 001 eq. 4): FFT boundary elements on a free (non-periodic) grid, load
   control, complementarity p = 0 where g > 0 and p > 0 where g = 0, with the integral of p equal
   to F0. With ``window`` only the central ``window`` x ``window`` pixels are solved
   (:func:`~roughcontact.papers.paper001.central_window`; only the centre of the ball touches,
   paper Figs. 8-9); the pressure must vanish on the window's border, else the case fails and
   asks for a larger window.
2. The programme. Paper 001's (``stroke``): the displacement path of Fig. 6, delta_x: 0 -> d_s -> 0
   repeated ``cycles`` times (default 4, as the paper), ``steps_per_stroke`` steps per branch
   spaced quadratically from each reversal so the short pre-sliding part is resolved. Yours
   (``path``): a CSV with one row per step, x and optionally y, and a unit in every column's
   header (:func:`roughcontact.contact.paths.read_path_csv`); lengths (``x [um], y [um]``)
   prescribe the rigid tangential displacement of the flat, forces (``Q_x [mN], Q_y [mN]``) the
   tangential force, which must stay below mu_f F0 (gross sliding under force control is refused).
   Each step is an increment under the local Coulomb law of eq. 3: a point sticks (|q| < mu_f p
   and no change of the relative displacement s = u - delta, eq. 1) or slips (|q| = mu_f p, s
   changes). With ``coupling`` (default) the pressure is re-solved under the shear of dissimilar
   materials (paper sec. 2, "included in an iterative manner"); without it Goodman's approximation
   holds. The file is read and checked when the study is validated, and its content is part of
   each case's key (editing it reruns the cases on ``--resume``); it must be readable where the
   case runs (a Dask worker on another machine needs the same path).
3. The last loop (the converged one, paper sec. 4), where the x programme closes one that slides,
   is analysed by :func:`roughcontact.experiment.friction_loop.analyse_loop`: the stroke, mu from
   the sliding plateaus, the energy dissipated, and the eq. 9 fit F_x = c1 (1 - (1 - c2
   delta_x)^n) of the branch along increasing displacement, with K_L = dF_x/d delta_x = c1 c2 n
   (1 - c2 delta_x)^(n - 1) at the points A, B, C (Fig. 10). A loop that never slides, a force
   programme and a pre-sliding part with fewer than the 4 steps the fit needs are not analysed:
   those scalars are NaN and ``analysis_note`` says why.
4. Mindlin's smooth-ball reference for a ball of ``radius`` (eqs. 10-12): a^3 = 3 F0 R / (4 E_s)
   with 1/E_s = sum (1 - nu^2)/E (eq. 11), and K_L = 8 a G (1 - F_x/(mu_f F0))^(1/3) (eq. 12)
   at the same points, in two readings (:func:`roughcontact.contact.presliding.mindlin_reference`):
   ``johnson``, the textbook one, 1/G = 1/G* = sum (2 - nu)/G_i, to which eq. 12's prefactor 8
   belongs; ``printed``, the paper's 1/G_s = sum (2 - nu)(1 + nu)/(2E) = sum (2 - nu)/(4 G_i),
   which makes K_L exactly 4 times Johnson's (a known typo of the paper, kept to reproduce its
   Fig. 15).

Stated assumptions (the paper does not define these; from :mod:`roughcontact.experiment.friction_loop`
and :mod:`roughcontact.papers.paper001`): points A, B and C lie where the fitted force change has
reached 0.25, 0.5 and 0.75 of the branch's pre-sliding force span (2 mu_f F0 for a loop that slides
both ways), so Mindlin's K_L there is eq. 12 at F_x = f mu_f F0; the bodies are linear elastic (the
paper argues the polymer balls stay elastic) without visco-elasticity (so the measured loops'
curved corners are absent); static and kinetic friction coefficients are equal; the counter-face
(paper: a silicon wafer) is smooth; no ``counter_body`` means a rigid flat.

Scalars: :meth:`roughcontact.contact.presliding.PreslidingResult.scalars` (units in its ``UNITS``).
Dataset: :meth:`~roughcontact.contact.presliding.PreslidingResult.to_xarray` (every step from the
unloaded start, the pressure map, the normalised shear sqrt(q_x^2 + q_y^2)/(mu_f p) at the points
A, B, C of the last loop, or at the last reversals and step of your programme, in single
precision). With few steps in the pre-sliding part two points can share a step, which the
``stick_slip`` titles show by the displacement from the reversal.

Figures: ``path`` (the displacement programme with the analysed last loop and the points A, B, C;
Fig. 6), ``pressure`` (the contact pressure of up to three cases, whole field beside a zoom on
the contact; Figs. 8-9), ``loops`` (every case's hysteresis loops, one panel per sample, with the
measured loop of ``[analysis.compare]``; Figs. 13-14), ``stick_slip`` (stick/slip maps of up to three cases,
zoomed to the contact; Figs. 11-12), ``lateral_stiffness`` (K_L at A, B, C against F0 with
both Mindlin readings, one panel per sample; Fig. 15). Tables: ``lateral_stiffness`` (per case
K_L simulated against Mindlin, with their ratios) and, with ``[analysis.compare]``,
``measured_loop`` (stroke, mu and K_L at A, B, C of the measured loop beside the simulated cases at
its normal force).

References
----------
Seed paper 001, "Evaluation of pre-sliding behavior at a rough interface: modeling and experiment",
J. Appl. Mech. (2020), eqs. 1-4 and 9-12, Figs. 6, 8-15, Tables 1-2. doi:10.1115/1.4045900

K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, secs. 7.2 and 7.4.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...contact.presliding import MINDLIN_READINGS as READINGS
from ...contact.presliding import POINT_NAMES as POINTS
from ...contact.presliding import PreslidingResult
from ...papers import paper001
from ...units import format_si
from ..kind import CaseOutput, CaseParameters, Kind, caption, fill_from_paper
from ..schema import Force, ForceUnit, Length, LengthUnit, MaterialName, Strict, TopographyName
from .common import evenly_chosen, grouped

_Positive = Field(gt=0.0, allow_inf_nan=False)


class PreslidingParameters(CaseParameters):
    """Keys of a ``model = "presliding"`` analysis (SI after validation).

    Attributes
    ----------
    topography : str
        The ball: a topography with its spherical shape (paper Fig. 4), e.g. a generated
        ``sphere_with_roughness``.
    window : int or None
        Solve only the central ``window`` x ``window`` pixels (free boundary); None solves the
        whole surface.
    material, counter_body : str
        The ball's material and the flat's (None: a rigid flat).
    normal_force : float
        F0 [N] (paper Table 1: 25, 50, 75 mN); not with a ``path`` that has a normal column.
    friction_coefficient : float
        mu_f of the local Coulomb law (Table 1), > 0.
    radius : float
        Ball radius R for Mindlin's reference [m] (default 5 mm: the paper's 10 mm balls).
    stroke : float
        d_s [m], the range of paper 001's displacement path (Table 1); or give ``path``.
    cycles, steps_per_stroke : int
        Cycles of the Fig. 6 path (default 4) and steps per branch (default 20).
    path : Path
        Your programme instead of paper 001's: a CSV relative to the study file, one row per step,
        ``x [um]`` (and ``y [um]``) for displacement control or ``Q_x [mN]`` (and ``Q_y [mN]``)
        for force control; with a normal column (``F_n [mN]`` or ``z [um]``) a combined
        programme from the unloaded state (:func:`roughcontact.contact.frictional.solve_frictional`).
    maps : int
        With ``path``: steps whose shear maps are stored, the last ``maps - 1`` reversals and the
        last step.
    coupling : bool
        Normal-tangential coupling of dissimilar materials (default True, as the paper).
    normal_loading : {"auto", "frictional", "frictionless"}
        How F0 is applied before the programme: with friction (locked-in shear, Spence 1975), or
        frictionless (Goodman's start); "auto" (default) is "frictional" for dissimilar materials.
    loading_steps : int
        Steps of the frictional normal loading (default 10; raise it to 30 or more when beta/mu
        approaches 1, docs/frictional_programmes.md).
    max_stick_change : float
        Step control: steps are inserted where the stick fraction would fall by more than this in
        one step (default 0.1: at least 10 steps from each reversal to full slip); 0 turns it off
        (the programme's points only).
    tolerance : float
        Relative tolerance of the normal and tangential solvers.
    paper001 : bool
        Fill in paper 001's ball material, the wafer, the radius and, at a load of Table 1, its
        stroke and mu (:func:`roughcontact.papers.paper001.presliding_keys`) where the analysis
        leaves them out; the ball is ``material`` or else ``sample`` (HDPE or POM).
    """

    topography: TopographyName
    window: Annotated[int, Field(ge=3)] | None = None
    material: MaterialName
    counter_body: MaterialName | None = None
    normal_force: Annotated[Force, _Positive] | None = None
    friction_coefficient: Annotated[float, _Positive]
    radius: Annotated[Length, _Positive] = paper001.RADIUS
    stroke: Annotated[Length, _Positive] | None = None
    cycles: Annotated[int, Field(ge=1)] = 4
    steps_per_stroke: Annotated[int, Field(ge=4)] = 20
    path: Path | None = None
    maps: Annotated[int, Field(ge=1, le=12)] = 4
    coupling: bool = True
    normal_loading: Literal["auto", "frictional", "frictionless"] = "auto"
    loading_steps: Annotated[int, Field(ge=2)] = 10
    max_stick_change: Annotated[float, Field(ge=0.0, lt=1.0)] = 0.1
    tolerance: float = Field(default=1e-8, gt=0.0, lt=1.0)
    paper001: bool = Field(default=False, exclude=True)
    """Fill in paper 001's scenario (stored as the keys it fills, not as the flag)."""

    @model_validator(mode="before")
    @classmethod
    def _paper001_scenario(cls, data: Any) -> Any:
        return fill_from_paper(data, "paper001", _paper001_keys)

    @model_validator(mode="after")
    def _one_programme(self) -> PreslidingParameters:
        if (self.stroke is None) == (self.path is None):
            given = "both" if self.stroke is not None else "neither"
            raise PydanticCustomError(
                "quantity",
                "give the stroke of paper 001's programme or your own path, exactly one (found {given})",
                {
                    "given": given,
                    "fix": "e.g. stroke = '2.8 um', or path = 'programme.csv'",
                    "field": "stroke",
                },
            )
        return self


def _paper001_keys(given: Mapping[str, Any]) -> dict[str, Any]:
    """Return paper 001's keys for the ball of ``material`` (or ``sample``) at ``normal_force``."""
    from ...errors import InputError
    from ...units import quantity

    ball = given.get("material") or given.get("sample")
    try:
        name = paper001.ball_name(str(ball))
    except InputError:
        raise PydanticCustomError(
            "quantity",
            "paper001 = true needs the ball (HDPE or POM), found {ball}",
            {"ball": repr(ball), "fix": "give sample = 'HDPE' (or 'POM'), or material = 'HDPE'"},
        ) from None
    try:
        force = quantity(given.get("normal_force"), "force")
    except (InputError, TypeError, ValueError):
        force = None  # no load (or one the validation reports): no stroke and mu from Table 1
    needed = "friction_coefficient" not in given or not {"stroke", "path"} & set(given)
    if force is not None and needed:
        try:
            paper001.table1(name, force)
        except InputError as error:
            raise PydanticCustomError(
                "quantity", "{problem}", {"problem": error.problem, "fix": error.fix, "field": "normal_force"}
            ) from None
    return paper001.presliding_keys(name, force)


class PreslidingCompare(Strict):
    """The ``[analysis.compare]`` table: a measured friction loop (CSV) to set beside the cases.

    Attributes
    ----------
    measured_loop : Path
        CSV of displacement and force (:func:`roughcontact.experiment.friction_loop.read_loop_csv`:
        columns found by name, ``#`` comments), relative to the study file.
    displacement_unit, force_unit : str
        Units of its columns (default um and mN).
    normal_force : float
        F0 of the measured loop [N]; the loop is compared with the cases at this force.
    sample : str or None
        The sample (ball) the loop belongs to; None compares it with every sample.
    """

    measured_loop: Path
    displacement_unit: LengthUnit = "um"
    force_unit: ForceUnit = "mN"
    normal_force: Annotated[Force, _Positive]
    sample: str | None = None


def check(parameters: PreslidingParameters) -> None:
    """Read a programme file at validation time (its errors name the file, row or column).

    The normal force comes from ``normal_force`` or from the path's normal column, exactly one.
    """
    from ...errors import InputError

    combined = False
    if parameters.path is not None:
        from ...contact.paths import read_programme_csv

        combined = read_programme_csv(parameters.path).normal is not None
    if combined and parameters.normal_force is not None:
        raise InputError(
            "normal_force",
            f"{parameters.path} has a normal column, which sets the normal force of every step.",
            "remove normal_force, or the path's normal column.",
        )
    if not combined and parameters.normal_force is None:
        raise InputError("normal_force", "missing.", "e.g. normal_force = '25 mN' (paper 001 Table 1).")


def run(parameters: PreslidingParameters, inputs) -> CaseOutput:
    """Run the programme on one ball at one load; scalars and dataset of :class:`PreslidingResult`."""
    from ...contact.presliding import presliding
    from ...papers.paper001 import central_window

    surface = inputs.topography(parameters.topography)
    if parameters.window is not None:
        surface = central_window(surface, parameters.window)
    if parameters.path is not None:
        from ...contact.paths import read_programme_csv

        path, control, normal_path, normal_control = read_programme_csv(parameters.path)
        programme = {"path": path, "control": control, "maps": parameters.maps}
        if normal_path is not None:
            programme |= {"normal_path": normal_path, "normal_control": normal_control}
    else:
        programme = {
            "stroke": parameters.stroke,
            "cycles": parameters.cycles,
            "steps_per_stroke": parameters.steps_per_stroke,
        }
    ball = parameters.sample or parameters.topography
    result = presliding(
        surface,
        inputs.material(parameters.material),
        inputs.material(parameters.counter_body),
        normal_force=parameters.normal_force,
        friction_coefficient=parameters.friction_coefficient,
        radius=parameters.radius,
        coupling=parameters.coupling,
        normal_loading=parameters.normal_loading,
        loading_steps=parameters.loading_steps,
        max_stick_change=parameters.max_stick_change or None,
        tolerance=parameters.tolerance,
        label=ball if parameters.normal_force is None else f"{ball} at {parameters.normal_force * 1e3:g} mN",
        **programme,
    )
    return CaseOutput(result.scalars(), result.to_xarray())


# --- figures and tables (from stored records only) -----------------------------------------------


def _number(record, name: str) -> float:
    """Return a stored scalar as a float (nan where it was not finite, stored as None)."""
    value = record.scalars.get(name)
    return math.nan if value is None else float(value)


def _by_force(records) -> list:
    return sorted(records, key=lambda r: _number(r, "normal_force"))


def _measured(context):
    """Return the measured loop of ``[analysis.compare]`` and its analysis, or None (none, or file gone).

    A file that was there when the study ran but is missing now (a report drawn on another
    machine) leaves the measured overlay out rather than failing the figure.
    """
    from ...contact.presliding import POINTS as FRACTIONS
    from ...experiment.friction_loop import analyse_loop, read_loop_csv

    compare = context.compare
    if compare is None or not Path(compare.measured_loop).is_file():
        return None
    loop = read_loop_csv(compare.measured_loop, compare.displacement_unit, compare.force_unit)
    return loop, analyse_loop(loop.displacement, loop.force, compare.normal_force, fractions=FRACTIONS)


def _compares_with(compare, sample: str) -> bool:
    return compare is not None and (compare.sample is None or compare.sample == sample)


@caption(
    "Friction force against tangential displacement of every case, one panel per sample, with the "
    "measured loop of [analysis.compare] where given (paper 001 Figs. 13-14)."
)
def _loops(records, context):
    """Friction loops of every case, one panel per sample, with the measured loop (Figs. 13-14)."""
    from ...plotting.layout import new_figure
    from ...plotting.presliding import plot_hysteresis_loops

    groups = grouped([r for r in records if r.fields_path is not None])
    if not groups:
        return None
    measured = _measured(context)
    figure, axes = new_figure(1, len(groups), width=5.5, height=4.2)
    for ax, (sample, group) in zip(axes[0], groups.items(), strict=True):
        curves = []
        for record in _by_force(group):
            data = record.dataset()
            force, mu = _number(record, "normal_force"), _number(record, "friction_coefficient")
            label = f"{force * 1e3:g} mN, μ {mu:g}"
            loads = data["normal_force"].values[1:] if "normal_force" in data else None
            if loads is not None and np.ptp(loads) > 1e-9 * loads.max():  # a combined programme
                label = f"F_n {format_si(loads.min(), 'N')} to {format_si(loads.max(), 'N')}, μ {mu:g}"
            if data.attrs.get("control") == "force":
                label += ", force control"
            curves.append((np.asarray(data["delta_x"]), np.asarray(data["force_x"]), label))
        overlay = []
        if measured is not None and _compares_with(context.compare, sample):
            loop, analysis = measured
            shift = float(np.min(loop.displacement[analysis.loop]))
            overlay.append(
                (
                    loop.displacement - shift,
                    loop.force,
                    f"measured {Path(context.compare.measured_loop).name} "
                    f"({context.compare.normal_force * 1e3:g} mN, shifted {-shift * 1e6:+.2f} µm)",
                )
            )
        plot_hysteresis_loops(curves, overlay, ax=ax, title=f"{sample or context.analysis}: friction loops")
    return figure


@caption(
    "Normalised shear √(q_x² + q_y²)/(μ p) at the points A, B, C of the last loop (or the stored "
    "steps), zoomed to the contact: 1 slips, below 1 sticks (paper 001 Figs. 11-12)."
)
def _stick_slip(records, context):
    """Normalised shear maps of up to three cases: A, B, C of the last loop, or kept steps (Figs. 11-12)."""
    chosen = evenly_chosen([r for r in records if r.fields_path is not None], 3)
    if not chosen:
        return None
    panels = []
    for record in chosen:
        data = record.dataset()
        name = _case_name(record)
        reversal = data.attrs.get("reversal_displacement")
        for index, label in enumerate(np.asarray(data["map"]).astype(str)):
            delta = float(data["delta_x"][int(data["map_step"][index])])
            if label in POINTS and reversal is not None:
                shown = f"{label} (Δδ {abs(delta - float(reversal)) * 1e6:.2g} µm)"
            else:
                shown = f"{label} (δx {delta * 1e6:.3g} µm)"
            loads = data["normal_force"].values if "normal_force" in data else None
            step_name = name
            if loads is not None and np.ptp(loads[1:]) > 1e-9 * loads.max():  # a combined programme
                step_name = f"{_ball_name(record)} {format_si(loads[int(data['map_step'][index])], 'N')}"
            values = data["normalised_shear"].isel(map=index)
            panels.append((f"{step_name}, {shown}", values, data["x"], data["y"]))
    columns = max(len(panels) // len(chosen), 1)
    return shear_maps(panels, columns=columns)


def _pixel_box(x, y) -> tuple[float, float, float, float]:
    """Return the extent [m] of a map whose pixel centres are ``x``, ``y``."""
    hx = x[1] - x[0] if x.size > 1 else 0.0
    hy = y[1] - y[0] if y.size > 1 else 0.0
    return (x[0] - hx / 2, x[-1] + hx / 2, y[0] - hy / 2, y[-1] + hy / 2)


def _zoom(masks) -> tuple[float, float, float, float] | None:
    """Return the box [m] of the pixels in any (mask on (x, y), x, y), widened by 10 %; None if none."""
    boxes = []
    for inside, x, y in masks:
        if inside.any():
            hx = x[1] - x[0] if x.size > 1 else 0.0
            hy = y[1] - y[0] if y.size > 1 else 0.0
            i, j = np.nonzero(inside)
            boxes.append((x[i.min()] - hx, x[i.max()] + hx, y[j.min()] - hy, y[j.max()] + hy))
    if not boxes:
        return None
    x0, x1 = min(b[0] for b in boxes), max(b[1] for b in boxes)
    y0, y1 = min(b[2] for b in boxes), max(b[3] for b in boxes)
    pad = 0.1 * max(x1 - x0, y1 - y0)
    return (x0 - pad, x1 + pad, y0 - pad, y1 + pad)


def shear_maps(panels, columns: int):
    """Draw stored normalised shear maps, zoomed to the contacts (paper 001 Figs. 11-12).

    ``panels``: (title, map on (x, y), x, y) per panel, the coordinates [m] at pixel centres; NaN
    (outside the contact) is blank. The zoom is the box of every finite pixel, widened by 10 %.
    """
    from ...plotting.presliding import plot_stick_slip_maps

    maps, extents, masks = {}, {}, []
    for label, values, x, y in panels:
        values, x, y = np.asarray(values, dtype=float), np.asarray(x), np.asarray(y)
        maps[label] = values.T  # rows along y
        extents[label] = _pixel_box(x, y)
        masks.append((np.isfinite(values), x, y))
    return plot_stick_slip_maps(maps, extents, zoom=_zoom(masks), columns=columns)


def _ball_name(record) -> str:
    """Return the ball's name: its sample, or its topography."""
    return record.parameters.get("sample") or record.parameters["topography"]


def _case_name(record) -> str:
    """Return the ball and its load, as the paper names its cases (``POM-like ball 25 mN``)."""
    return f"{_ball_name(record)} {_number(record, 'normal_force') * 1e3:g} mN"


@caption(
    "Contact pressure of up to three cases: the whole computed field with the zoomed box (left) and "
    "the zoom on the contact with its outline (right), on one colour scale (paper 001 Figs. 8-9)."
)
def _pressure(records, context):
    """Draw the contact pressure of up to three cases, whole field and zoom on the contact (Figs. 8-9)."""
    from ...plotting.presliding import plot_pressure_maps

    chosen = evenly_chosen(_by_force([r for r in records if r.fields_path is not None]), 3)
    if not chosen:
        return None
    maps, extents, masks = {}, {}, []
    for record in chosen:
        data = record.dataset()
        pressure, x, y = (
            np.asarray(data["pressure"], dtype=float),
            np.asarray(data["x"]),
            np.asarray(data["y"]),
        )
        maps[_case_name(record)] = pressure.T  # rows along y
        extents[_case_name(record)] = _pixel_box(x, y)
        masks.append((pressure > 0, x, y))
    zoom = _zoom(masks)
    return None if zoom is None else plot_pressure_maps(maps, extents, zoom=zoom)


@caption(
    "The tangential displacement programme δ_x applied step by step (paper 001 Fig. 6); the last "
    "loop, which is analysed, is shaded and its points A, B, C marked. A combined programme's normal "
    "force is dashed on the right axis."
)
def _path(records, context):
    """Draw the tangential displacement programme, step by step, with the last loop (Fig. 6).

    Cases that share one programme draw one line; the points A, B, C of the first case are marked.
    """
    from ...plotting.presliding import plot_displacement_path

    chosen = [r for r in records if r.fields_path is not None]
    if not chosen:
        return None
    first = chosen[0].dataset()
    distinct: list[tuple[object, np.ndarray]] = []  # (record, delta_x) of each different programme
    for record in chosen:
        delta = np.asarray(record.dataset()["delta_x"], dtype=float)
        if not any(d.shape == delta.shape and np.allclose(d, delta, rtol=1e-9, atol=0) for _, d in distinct):
            distinct.append((record, delta))
    if len(distinct) == 1:
        names = ["programme"]
    else:  # named by ball and load, or by the swept values where those do not tell them apart
        names = [_case_name(record) for record, _ in distinct]
        if len(set(names)) < len(names):
            names = [record.label for record, _ in distinct]
    paths = dict(zip(names, (delta for _, delta in distinct), strict=True))
    positions = {
        name: _row_positions(record.dataset()) for name, (record, _) in zip(names, distinct, strict=True)
    }
    start, stop = first.attrs.get("last_loop_start"), first.attrs.get("last_loop_stop")
    points = {
        str(name): int(step)
        for name, step in zip(
            np.asarray(first["map"]).astype(str), np.asarray(first["map_step"]), strict=True
        )
        if str(name) in POINTS
    }
    normal = first["normal_force"].values if "normal_force" in first else None
    refined = any(_number(record, "inserted_steps") > 0 for record, _ in distinct)
    return plot_displacement_path(
        paths,
        last_loop=None if start is None else (int(start), int(stop)),
        points=points,
        normal_force=normal,
        positions=positions if refined else None,
    )


def _row_positions(data) -> np.ndarray:
    """Return each stored step's place on the axis of the programme's rows (0 is the start).

    A row's own step sits at the row's number; steps the step control inserted before it sit in
    between, in proportion to how far the tangential displacement (or, where it holds, the normal
    force) has gone from the previous row.
    """
    if "programme_point" not in data:
        return np.arange(data["delta_x"].size, dtype=float)
    row = np.asarray(data["programme_point"], dtype=int)
    moves = [np.asarray(data["delta_x"], dtype=float)]
    if "normal_force" in data:
        moves.append(np.asarray(data["normal_force"], dtype=float))
    end = {0: 0}  # row -> the index of its own step (the last step with its number)
    for index, number in enumerate(row):
        end[int(number)] = index
    out = row.astype(float)
    for index in range(1, row.size):
        number = int(row[index])
        if index == end[number]:
            continue
        before, after = end.get(number - 1, 0), end[number]
        for series in moves:
            span = series[after] - series[before]
            if abs(span) > 1e-12 * max(np.max(np.abs(series)), 1e-300):
                out[index] = number - 1 + (series[index] - series[before]) / span
                break
        else:
            out[index] = number - 1 + (index - before) / (after - before)
    return out


def _mindlin_curves(group, loads: np.ndarray) -> dict[str, dict[str, np.ndarray]] | None:
    """Return Mindlin's K_L at ``loads`` from a group's stored values, or None if they cannot be scaled.

    With the materials and the radius fixed, eq. 11 gives a proportional to F0^(1/3), and eq. 12
    at a fixed fraction f of mu_f F0 (the points A, B, C) gives K_L = 8 a G (1 - f)^(1/3),
    independent of mu_f: so K_L(F0) = K_L(F0_case) (F0 / F0_case)^(1/3), drawn as a smooth curve.
    """
    keys = {
        (r.parameters["material"], r.parameters.get("counter_body"), r.parameters["radius"]) for r in group
    }
    if len(keys) != 1:
        return None
    first = group[0]
    scale = np.cbrt(loads / _number(first, "normal_force"))
    return {
        reading: {p: _number(first, f"K_L_{p}_mindlin_{reading}") * scale for p in POINTS}
        for reading in READINGS
    }


@caption(
    "Lateral stiffness K_L at the points A, B, C against the normal force, simulated beside Mindlin's "
    "smooth ball in both readings of eq. 12, one panel per sample (paper 001 Fig. 15)."
)
def _lateral_stiffness(records, context):
    """Draw K_L at A, B, C against F0 with Mindlin in both readings, one panel per sample (Fig. 15)."""
    from ...plotting.layout import legend, new_figure
    from ...plotting.presliding import POINT_COLOURS, plot_lateral_stiffness

    groups = grouped(records)
    measured = _measured(context)
    every = [_number(r, "normal_force") for r in records]
    low, high = min(every), max(every)
    if high <= low * (1 + 1e-9):
        low, high = 0.8 * low, 1.2 * high
    dense = np.linspace(low, high, 50)
    figure, axes = new_figure(1, len(groups), width=5.5, height=5.2)
    for number, (ax, (sample, group)) in enumerate(zip(axes[0], groups.items(), strict=True)):
        group = _by_force(group)
        loads = [_number(r, "normal_force") for r in group]
        simulated = {p: [_number(r, f"K_L_{p}") for r in group] for p in POINTS}
        curves = _mindlin_curves(group, dense)
        if curves is None:  # materials differ within the sample: Mindlin at the cases' loads only
            curves = {
                reading: {p: [_number(r, f"K_L_{p}_mindlin_{reading}") for r in group] for p in POINTS}
                for reading in READINGS
            }
            plot_lateral_stiffness(loads, simulated, mindlin=curves, ax=ax)
        else:
            plot_lateral_stiffness(dense, mindlin=curves, ax=ax)
            plot_lateral_stiffness(loads, simulated, ax=ax)
        if measured is not None and _compares_with(context.compare, sample):
            stiffness = measured[1].lateral_stiffness
            for point in POINTS:
                ax.plot(
                    context.compare.normal_force * 1e3,
                    stiffness[point] * 1e-3,  # N/m -> mN/um
                    "s",
                    markerfacecolor="none",
                    markersize=9,
                    color=POINT_COLOURS.get(point),
                    label=f"{point} measured loop",
                )
        ax.set_title(f"({chr(ord('a') + number)}) {sample or context.analysis}")
        legend(ax, fontsize="x-small", ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.15))
    return figure


def _ratio(numerator: float, denominator: float) -> float:
    return numerator / denominator if denominator and math.isfinite(denominator) else math.nan


_INPUTS = {
    "normal_force [N]": "normal_force",
    "stroke [m]": "stroke",
    "friction_coefficient": "friction_coefficient",
    "mu_from_loop": "mu_from_loop",
}
_LOOP = {
    "stroke [m]": "stroke_from_loop",
    "mu": "mu_from_loop",
    "energy_last_loop [J]": "energy_last_loop",
    "presliding_distance [m]": "presliding_distance",
}
"""Table column -> stored scalar, of the cases' inputs and of their last loop."""


def _columns(record, columns: dict[str, str]) -> dict[str, float]:
    return {header: _number(record, name) for header, name in columns.items()}


def _lateral_stiffness_table(records, context):
    """Per case: K_L at A, B, C simulated, Mindlin (Johnson and as printed) and their ratios [N/m]."""
    rows = []
    for record in records:
        row = {"case": record["case"], "sample": record.parameters.get("sample", "")}
        row |= _columns(record, _INPUTS)
        for point in POINTS:
            simulated = _number(record, f"K_L_{point}")
            row[f"K_L_{point} [N/m]"] = simulated
            for reading in READINGS:
                reference = _number(record, f"K_L_{point}_mindlin_{reading}")
                row[f"K_L_{point}_mindlin_{reading} [N/m]"] = reference
                row[f"K_L_{point} / mindlin_{reading}"] = _ratio(simulated, reference)
        rows.append(row)
    return rows


def _measured_loop_table(records, context):
    """Tabulate the measured loop's stroke, mu and K_L at A, B, C beside the simulated cases at its F0."""
    measured = _measured(context)
    if measured is None:
        return None
    loop, analysis = measured
    compare = context.compare
    row = {
        "source": f"measured: {Path(compare.measured_loop).name}",
        "sample": compare.sample or "",
        "normal_force [N]": compare.normal_force,
        "stroke [m]": analysis.stroke,
        "mu": analysis.mu,
        "energy_last_loop [J]": analysis.energy,
        "presliding_distance [m]": analysis.branch.sliding_distance,
    }
    row |= {f"K_L_{p} [N/m]": analysis.lateral_stiffness[p] for p in POINTS}
    rows = [row]
    for record in records:
        sample = record.parameters.get("sample", "")
        force = _number(record, "normal_force")
        if not _compares_with(compare, sample) or not math.isclose(force, compare.normal_force, rel_tol=1e-6):
            continue
        simulated = {
            "source": f"simulated: case {record['case']}",
            "sample": sample,
            "normal_force [N]": force,
        }
        simulated |= _columns(record, _LOOP)
        for point in POINTS:
            value = _number(record, f"K_L_{point}")
            simulated[f"K_L_{point} [N/m]"] = value
            simulated[f"K_L_{point} simulated / measured"] = _ratio(value, analysis.lateral_stiffness[point])
        rows.append(simulated)
    return rows


KIND = Kind(
    name="presliding",
    summary="rough ball on a flat: partial-slip loops under paper 001's programme (Fig. 6) or yours (CSV), "
    "last-loop K_L at A, B, C vs Mindlin",
    parameters=PreslidingParameters,
    run=run,
    units=PreslidingResult.UNITS,
    figures={
        "path": _path,
        "pressure": _pressure,
        "loops": _loops,
        "stick_slip": _stick_slip,
        "lateral_stiffness": _lateral_stiffness,
    },
    tables={"lateral_stiffness": _lateral_stiffness_table, "measured_loop": _measured_loop_table},
    compare=PreslidingCompare,
    check=check,
    headline=(
        "contact_area",
        "last_stick_fraction",
        "mu_from_loop",
        "stroke_from_loop",
        "K_L_A",
        "K_L_B",
        "K_L_C",
    ),
    renamed={"surface": "topography", "counter": "counter_body"},
)
