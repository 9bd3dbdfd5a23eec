r"""Study kind ``presliding``: a rough ball's partial-slip friction loops and K_L against Mindlin (paper 001).

One case is one rough ball (heights *with* its spherical shape, as paper 001 Fig. 4) pressed on a
flat with a constant normal force F0 and taken through paper 001's tangential programme; it wraps
:func:`roughcontact.models.paper001.presliding_case`:

1. Normal contact (paper 001 eq. 4): FFT boundary elements on a free (non-periodic) grid, load
   control, complementarity p = 0 where g > 0 and p > 0 where g = 0, with the integral of p equal
   to F0. With ``window`` only the central ``window`` x ``window`` pixels are solved
   (:func:`~roughcontact.models.paper001.central_window`; only the centre of the ball touches,
   paper Figs. 8-9); the pressure must vanish on the window's border, else the case fails and
   asks for a larger window.
2. Tangential programme: the displacement path of paper Fig. 6, delta_x: 0 -> d_s -> 0 repeated
   ``cycles`` times (default 4, as the paper), ``steps_per_stroke`` steps per branch spaced
   quadratically from each reversal so the short pre-sliding part is resolved. Each step is an
   increment under the local Coulomb law of eq. 3: a point sticks (|q| < mu_f p and no change of
   the relative displacement s = u - delta, eq. 1) or slips (|q| = mu_f p, s changes). With
   ``coupling`` (default) the pressure is re-solved under the shear of dissimilar materials
   (paper sec. 2, "included in an iterative manner"); without it the Goodman approximation holds.
3. The last loop (the converged one, paper sec. 4) is analysed by
   :func:`roughcontact.experiment.friction_loop.analyse_loop`: the stroke, mu from the sliding
   plateaus, the energy dissipated, and the eq. 9 fit F_x = c1 (1 - (1 - c2 delta_x)^n) of the
   branch along increasing displacement, with K_L = dF_x/d delta_x = c1 c2 n (1 - c2
   delta_x)^(n - 1) at the points A, B, C (Fig. 10).
4. Mindlin's smooth-ball reference for a ball of ``radius`` (eqs. 10-12): a^3 = 3 F0 R / (4 E_s)
   with 1/E_s = sum (1 - nu^2)/E (eq. 11), and K_L = 8 a G (1 - F_x/(mu_f F0))^(1/3) (eq. 12)
   at the same points, in two readings (:func:`roughcontact.analytic.mindlin.paper001_mindlin`):
   ``johnson``, the textbook one, 1/G = 1/G* = sum (2 - nu)/G_i, to which eq. 12's prefactor 8
   belongs; ``printed``, the paper's 1/G_s = sum (2 - nu)(1 + nu)/(2E) = sum (2 - nu)/(4 G_i),
   which makes K_L exactly 4 times Johnson's (a known typo of the paper, kept to reproduce its
   Fig. 15).

Stated assumptions (the paper does not define these; from :mod:`roughcontact.experiment.friction_loop`
and :mod:`roughcontact.models.paper001`): points A, B and C lie where the fitted force change has
reached 0.25, 0.5 and 0.75 of the branch's pre-sliding force span (2 mu_f F0 for a loop that slides
both ways), so Mindlin's K_L there is eq. 12 at F_x = f mu_f F0; the bodies are linear elastic (the
paper argues the polymer balls stay elastic) without visco-elasticity (so the measured loops'
curved corners are absent); static and kinetic friction coefficients are equal; the counter-face
(paper: a silicon wafer) is smooth; ``counter`` absent means a rigid flat.

Scalars (SI, plain names; :data:`UNITS` gives the units): the inputs (normal_force, stroke,
friction_coefficient, radius), the contact (contact_area, patches, max_pressure), the last loop
(stroke_from_loop, mu_from_loop, energy_last_loop, presliding_distance, eq9_c1, eq9_c2, eq9_n),
K_L_A, K_L_B, K_L_C and their Mindlin values K_L_A_mindlin_johnson, ..., K_L_C_mindlin_printed,
Mindlin's hertz_radius and sliding_distance_mindlin (2 delta_0, Johnson), and the numerics
(window_size, pixel, steps, coupling).

Dataset: the whole loop (``displacement`` and ``force`` at every step from the unloaded start, with
the stick and slip areas), the normal-contact ``pressure`` map, and the normalised shear
sqrt(q_x^2 + q_y^2)/(mu_f p) at points A, B, C of the last loop (``normalised_shear``, < 1 stick,
1 slip, NaN outside the contact; paper Figs. 11-12) on the solved window's x/y coordinates
(the maps in single precision, to keep the files small). The maps are those of the computed step
nearest to each point (``point_step``); with few steps in the pre-sliding part two points can
share a step, which the ``stick_slip`` titles show by the displacement from the reversal.

Figures: ``loops`` (every case's hysteresis loops, one panel per sample, with the measured loop of
``[analysis.compare]``; Figs. 13-14), ``stick_slip`` (stick/slip maps at A, B, C for up to three
cases, zoomed to the contact; Figs. 11-12), ``lateral_stiffness`` (K_L at A, B, C against F0 with
both Mindlin readings, one panel per sample; Fig. 15). Tables: ``lateral_stiffness`` (per case
K_L simulated against Mindlin, with their ratios) and, with ``[analysis.compare]``,
``measured_loop`` (stroke, mu and K_L at A, B, C of the measured loop beside the simulated cases at
its normal force).

References
----------
Seed paper 001, "Evaluation of pre-sliding behavior at a rough interface: modeling and experiment",
J. Appl. Mech. (2020), eqs. 1-4 and 9-12, Figs. 6 and 10-15, Tables 1-2. doi:10.1115/1.4045900

K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, secs. 7.2 and 7.4.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

import numpy as np
from pydantic import Field, field_validator
from pydantic_core import PydanticCustomError

from ...errors import InputError
from ..kind import CaseOutput, CaseParameters, Kind
from ..schema import Force, Length, MaterialName, Strict, TopographyName
from .common import evenly_chosen, grouped

POINTS = ("A", "B", "C")
"""The loop points of paper 001 Fig. 10 at which K_L is evaluated."""

READINGS = ("johnson", "printed")
"""The two readings of Mindlin's K_L (eqs. 10-12): textbook (Johnson) and as printed (4x)."""

_Positive = Field(gt=0.0, allow_inf_nan=False)


class PreslidingParameters(CaseParameters):
    """Keys of a ``model = "presliding"`` analysis (SI after validation).

    Attributes
    ----------
    surface : str
        The ball: a topography with its spherical shape (paper Fig. 4), e.g. a generated
        ``sphere_with_roughness``.
    window : int or None
        Solve only the central ``window`` x ``window`` pixels (free boundary); None solves the
        whole surface.
    material, counter : str
        The ball's material and the flat's (None: a rigid flat).
    normal_force : float
        F0 [N] (paper Table 1: 25, 50, 75 mN).
    stroke : float
        d_s [m], the range of the displacement path (Table 1).
    friction_coefficient : float
        mu_f of the local Coulomb law (Table 1), > 0.
    radius : float
        Ball radius R for Mindlin's reference [m] (default 5 mm: the paper's 10 mm balls).
    cycles, steps_per_stroke : int
        Cycles of the Fig. 6 path (default 4) and steps per branch (default 20).
    coupling : bool
        Normal-tangential coupling of dissimilar materials (default True, as the paper).
    tolerance : float
        Relative tolerance of the normal and tangential solvers.
    """

    surface: TopographyName
    window: Annotated[int, Field(ge=3)] | None = None
    material: MaterialName
    counter: MaterialName | None = None
    normal_force: Annotated[Force, _Positive]
    stroke: Annotated[Length, _Positive]
    friction_coefficient: Annotated[float, _Positive]
    radius: Annotated[Length, _Positive] = 5e-3
    cycles: Annotated[int, Field(ge=1)] = 4
    steps_per_stroke: Annotated[int, Field(ge=4)] = 20
    coupling: bool = True
    tolerance: float = Field(default=1e-8, gt=0.0, lt=1.0)


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
    displacement_unit: str = "um"
    force_unit: str = "mN"
    normal_force: Annotated[Force, _Positive]
    sample: str | None = None

    @field_validator("displacement_unit", "force_unit")
    @classmethod
    def _known_unit(cls, value: str, info) -> str:
        from ...units import quantity

        dimension, examples = {
            "displacement_unit": ("length", "'um', 'nm' or 'm'"),
            "force_unit": ("force", "'mN', 'uN' or 'N'"),
        }[info.field_name]
        try:
            quantity(f"1 {value}", dimension, field=info.field_name)
        except InputError as error:
            raise PydanticCustomError(
                "quantity",
                "{problem}",
                {
                    "problem": f"{value!r} is not a unit of {dimension} ({error.problem.rstrip('.')})",
                    "fix": f"give one, e.g. {examples}.",
                },
            ) from None
        return value


def _dataset(case, surface):
    """Return the loop, the pressure and the normalised shear maps at A, B, C on the window's x/y."""
    import xarray as xr

    result, analysis = case.result, case.analysis
    displacement, force = case.loop()
    contact = result.normal.contact_area
    names = tuple(case.point_steps)
    maps = np.stack([result.states[case.point_steps[p]].normalised_shear for p in names])
    x, y = surface.coordinates()
    return xr.Dataset(
        {
            "displacement": ("step", displacement, {"units": "m", "long_name": "tangential displacement"}),
            "force": ("step", force, {"units": "N", "long_name": "friction force F_x"}),
            "stick_area": ("step", np.concatenate([[contact], result.stick_area]), {"units": "m^2"}),
            "slip_area": ("step", np.concatenate([[0.0], result.slip_area]), {"units": "m^2"}),
            "pressure": (("x", "y"), result.normal.pressure.astype(np.float32), {"units": "Pa"}),
            "normalised_shear": (
                ("point", "x", "y"),
                maps.astype(np.float32),
                {"units": "1", "long_name": "sqrt(q_x^2 + q_y^2) / (mu p)"},
            ),
            "point_step": ("point", np.array([case.point_steps[p] + 1 for p in names], dtype=np.int32)),
            "point_displacement": ("point", np.asarray(analysis.branch.point_displacement), {"units": "m"}),
            "point_force": ("point", np.asarray(analysis.branch.point_force), {"units": "N"}),
        },
        coords={
            "step": ("step", np.arange(displacement.size)),
            "x": ("x", x, {"units": "m"}),
            "y": ("y", y, {"units": "m"}),
            "point": ("point", list(names)),
        },
        attrs={
            "last_loop_start": int(analysis.loop.start),
            "last_loop_stop": int(analysis.loop.stop),
            "reversal_displacement": float(analysis.branch.reversal_displacement),
        },
    )


def run(parameters: PreslidingParameters, inputs) -> CaseOutput:
    """Run paper 001's programme on one ball at one load; scalars as listed in the module docstring."""
    from ...analytic.mindlin import paper001_mindlin
    from ...models.paper001 import central_window, presliding_case

    surface = inputs.topography(parameters.surface)
    if parameters.window is not None:
        surface = central_window(surface, parameters.window)
    material = inputs.material(parameters.material)
    counter = inputs.material(parameters.counter)
    ball = parameters.sample or parameters.surface
    case = presliding_case(
        surface,
        material,
        counter,
        parameters.normal_force,
        stroke=parameters.stroke,
        friction_coefficient=parameters.friction_coefficient,
        radius=parameters.radius,
        label=f"{ball} at {parameters.normal_force * 1e3:g} mN",
        ball=ball,
        cycles=parameters.cycles,
        steps_per_stroke=parameters.steps_per_stroke,
        coupling=parameters.coupling,
        tolerance=parameters.tolerance,
    )
    reference = paper001_mindlin(
        mu=parameters.friction_coefficient,
        normal_force=parameters.normal_force,
        radius=parameters.radius,
        material=material,
        counter=counter,
    )
    scalars = _scalars(case, reference, parameters.radius)
    return CaseOutput(scalars, _dataset(case, surface))


def _scalars(case, reference, radius: float) -> dict[str, Any]:
    """Return the scalars under plain names (:meth:`PreslidingCase.scalars` has units in its keys)."""
    row = case.scalars()
    branch = case.analysis.branch
    scalars: dict[str, Any] = {
        "normal_force": row["F0 [N]"],
        "stroke": row["stroke [m]"],
        "friction_coefficient": row["mu"],
        "radius": radius,
        "contact_area": row["contact_area [m^2]"],
        "patches": row["patches"],
        "max_pressure": float(np.max(case.result.normal.pressure)),
        "stroke_from_loop": case.analysis.stroke,
        "mu_from_loop": row["mu_from_loop"],
        "energy_last_loop": row["energy_last_loop [J]"],
        "presliding_distance": branch.sliding_distance,
        "eq9_c1": branch.c1,
        "eq9_c2": branch.c2,
        "eq9_n": branch.n,
    }
    for point in POINTS:
        scalars[f"K_L_{point}"] = row[f"K_L_{point} [N/m]"]
    for reading in READINGS:
        for point in POINTS:
            scalars[f"K_L_{point}_mindlin_{reading}"] = row[f"K_L_{point}_mindlin_{reading} [N/m]"]
    return scalars | {
        "hertz_radius": reference.contact_radius,
        "sliding_distance_mindlin": 2.0 * reference.sliding_distance,
        "window_size": row["note_window [m]"],
        "pixel": row["note_pixel [m]"],
        "steps": row["note_steps"],
        "coupling": row["note_coupling"],
    }


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
    from ...experiment.friction_loop import analyse_loop, read_loop_csv
    from ...models.paper001 import POINTS as FRACTIONS

    compare = context.compare
    if compare is None or not Path(compare.measured_loop).is_file():
        return None
    loop = read_loop_csv(compare.measured_loop, compare.displacement_unit, compare.force_unit)
    return loop, analyse_loop(loop.displacement, loop.force, compare.normal_force, fractions=FRACTIONS)


def _compares_with(compare, sample: str) -> bool:
    return compare is not None and (compare.sample is None or compare.sample == sample)


def _loops(records, context):
    """Friction loops of every case, one panel per sample, with the measured loop (Figs. 13-14)."""
    from ...plotting.presliding import plot_hysteresis_loops
    from ...plotting.study import new_figure

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
            curves.append((np.asarray(data["displacement"]), np.asarray(data["force"]), label))
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


def _stick_slip(records, context):
    """Normalised shear maps at A, B, C of the last loop for up to three cases (Figs. 11-12)."""
    chosen = evenly_chosen([r for r in records if r.fields_path is not None], 3)
    if not chosen:
        return None
    panels = []
    for record in chosen:
        data = record.dataset()
        name = f"{record.parameters.get('sample') or record.parameters['surface']} "
        name += f"{_number(record, 'normal_force') * 1e3:g} mN"
        reversal = float(data.attrs.get("reversal_displacement", 0.0))
        for point in np.asarray(data["point"]).astype(str):
            step = int(data["point_step"].sel(point=point))
            moved = abs(float(data["displacement"][step]) - reversal)
            values = data["normalised_shear"].sel(point=point)
            panels.append((f"{name}, {point} (Δδ {moved * 1e6:.2g} µm)", values, data["x"], data["y"]))
    return shear_maps(panels, columns=len(POINTS))


def shear_maps(panels, columns: int):
    """Draw stored normalised shear maps, zoomed to the contacts (paper 001 Figs. 11-12).

    ``panels``: (title, map on (x, y), x, y) per panel, the coordinates [m] at pixel centres; NaN
    (outside the contact) is blank. The zoom is the box of every finite pixel, widened by 10 %.
    """
    from ...plotting.presliding import plot_stick_slip_maps

    maps, extents, boxes = {}, {}, []
    for label, values, x, y in panels:
        values, x, y = np.asarray(values, dtype=float), np.asarray(x), np.asarray(y)
        hx = x[1] - x[0] if x.size > 1 else 0.0
        hy = y[1] - y[0] if y.size > 1 else 0.0
        maps[label] = values.T  # rows along y
        extents[label] = (x[0] - hx / 2, x[-1] + hx / 2, y[0] - hy / 2, y[-1] + hy / 2)
        inside = np.isfinite(values)
        if inside.any():
            i, j = np.nonzero(inside)
            boxes.append((x[i.min()] - hx, x[i.max()] + hx, y[j.min()] - hy, y[j.max()] + hy))
    zoom = None
    if boxes:
        x0, x1 = min(b[0] for b in boxes), max(b[1] for b in boxes)
        y0, y1 = min(b[2] for b in boxes), max(b[3] for b in boxes)
        pad = 0.1 * max(x1 - x0, y1 - y0)
        zoom = (x0 - pad, x1 + pad, y0 - pad, y1 + pad)
    return plot_stick_slip_maps(maps, extents, zoom=zoom, columns=columns)


def _mindlin_curves(group, loads: np.ndarray) -> dict[str, dict[str, np.ndarray]] | None:
    """Return Mindlin's K_L at ``loads`` from a group's stored values, or None if they cannot be scaled.

    With the materials and the radius fixed, eq. 11 gives a proportional to F0^(1/3), and eq. 12
    at a fixed fraction f of mu_f F0 (the points A, B, C) gives K_L = 8 a G (1 - f)^(1/3),
    independent of mu_f: so K_L(F0) = K_L(F0_case) (F0 / F0_case)^(1/3), drawn as a smooth curve.
    """
    keys = {(r.parameters["material"], r.parameters.get("counter"), r.parameters["radius"]) for r in group}
    if len(keys) != 1:
        return None
    first = group[0]
    scale = np.cbrt(loads / _number(first, "normal_force"))
    return {
        reading: {p: _number(first, f"K_L_{p}_mindlin_{reading}") * scale for p in POINTS}
        for reading in READINGS
    }


def _lateral_stiffness(records, context):
    """Draw K_L at A, B, C against F0 with Mindlin in both readings, one panel per sample (Fig. 15)."""
    from ...plotting.presliding import POINT_COLOURS, plot_lateral_stiffness
    from ...plotting.study import new_figure

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
        ax.legend(fontsize="x-small", ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.15))
    return figure


def _ratio(numerator: float, denominator: float) -> float:
    return numerator / denominator if denominator and math.isfinite(denominator) else math.nan


def _lateral_stiffness_table(records, context):
    """Per case: K_L at A, B, C simulated, Mindlin (Johnson and as printed) and their ratios [N/m]."""
    rows = []
    for record in records:
        row = {
            "case": record["case"],
            "sample": record.parameters.get("sample", ""),
            "normal_force [N]": _number(record, "normal_force"),
            "stroke [m]": _number(record, "stroke"),
            "friction_coefficient": _number(record, "friction_coefficient"),
            "mu_from_loop": _number(record, "mu_from_loop"),
        }
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
            "stroke [m]": _number(record, "stroke_from_loop"),
            "mu": _number(record, "mu_from_loop"),
            "energy_last_loop [J]": _number(record, "energy_last_loop"),
            "presliding_distance [m]": _number(record, "presliding_distance"),
        }
        for point in POINTS:
            value = _number(record, f"K_L_{point}")
            simulated[f"K_L_{point} [N/m]"] = value
            simulated[f"K_L_{point} simulated / measured"] = _ratio(value, analysis.lateral_stiffness[point])
        rows.append(simulated)
    return rows


UNITS = {
    "normal_force": "N",
    "stroke": "m",
    "radius": "m",
    "contact_area": "m^2",
    "max_pressure": "Pa",
    "stroke_from_loop": "m",
    "energy_last_loop": "J",
    "presliding_distance": "m",
    "eq9_c1": "N",
    "eq9_c2": "1/m",
    **{f"K_L_{p}": "N/m" for p in POINTS},
    **{f"K_L_{p}_mindlin_{r}": "N/m" for r in READINGS for p in POINTS},
    "hertz_radius": "m",
    "sliding_distance_mindlin": "m",
    "window_size": "m",
    "pixel": "m",
}
"""Scalar name -> SI unit (the results table's column headers)."""

KIND = Kind(
    name="presliding",
    summary="rough ball on a flat: partial-slip loops (Fig. 6 path), last-loop K_L at A, B, C vs Mindlin",
    parameters=PreslidingParameters,
    run=run,
    units=UNITS,
    figures={"loops": _loops, "stick_slip": _stick_slip, "lateral_stiffness": _lateral_stiffness},
    tables={"lateral_stiffness": _lateral_stiffness_table, "measured_loop": _measured_loop_table},
    compare=PreslidingCompare,
)
