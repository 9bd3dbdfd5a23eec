"""Figures of the pre-sliding analysis of paper 001: hysteresis loops, stick/slip maps, lateral stiffness.

* :func:`plot_hysteresis_loops` - friction loops, simulated and measured (paper 001 Figs. 13-14);
* :func:`plot_displacement_path` - the tangential displacement programme (Fig. 6);
* :func:`plot_pressure_maps` - contact pressure, whole field and zoomed-in view (Figs. 8-9);
* :func:`plot_stick_slip_maps` - normalised shear sqrt(qx^2 + qy^2)/(mu p) maps (Figs. 11-12);
* :func:`plot_lateral_stiffness` - K_L at points A, B, C vs normal load with Mindlin (Fig. 15);
* :func:`plot_loop_analysis` - a loop's record, its last loop, the eq. 9 fits and the points (Fig. 10).

The ``*_figure`` functions draw a study's figures from cases of the ``presliding`` and
``loop_analysis`` models (:mod:`roughcontact.plotting.cases`), with a compared loop
(:class:`MeasuredLoop`, named by its origin: measured or synthetic) beside.

Inputs are SI (m, N, N/m). The loops and the lateral stiffness are shown in the paper's fixed units,
µm, mN and mN/µm (= kN/m); the maps' lengths in the prefix :func:`roughcontact.units.prefixed_scale`
chooses for their extent. Each function returns the :class:`matplotlib.figure.Figure` (its axes are
``fig.axes``); nothing is shown and no pyplot state is touched (Agg-safe).

The ``plot_*`` functions live in :mod:`.presliding_results` and are served from here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.axes import Axes

from ..cases import evenly_chosen, grouped, realisations_of, with_fields
from ..contact.presliding import MINDLIN_READINGS as READINGS
from ..contact.presliding import POINT_NAMES as POINTS
from ..contact.presliding import mindlin_ratios, rough_vs_smooth, verdict_words
from ..origin import MEASURED, DataOrigin
from ..spread import spread
from ..units import format_si
from .cases import caption, panel_per_case
from .presliding_results import (
    FORCE_SCALE,
    POINT_COLOURS,
    STIFFNESS_SCALE,
    plot_displacement_path,
    plot_hysteresis_loops,
    plot_lateral_stiffness,
    plot_loop_analysis,
    plot_pressure_maps,
    plot_stick_slip_maps,
)
from .presliding_results import MINDLIN_STYLES as MINDLIN_STYLES  # served here, as before
from .presliding_results import SLIP_LEVEL as SLIP_LEVEL

__all__ = [  # the figures of one result (from .presliding_results) and of a study's cases
    "MeasuredLoop",
    "lateral_stiffness_figure",
    "loop_analysis_figure",
    "loops_figure",
    "path_figure",
    "plot_displacement_path",
    "plot_hysteresis_loops",
    "plot_lateral_stiffness",
    "plot_loop_analysis",
    "plot_pressure_maps",
    "plot_stick_slip_maps",
    "pressure_figure",
    "shear_maps",
    "stick_slip_figure",
]


@caption(
    "The friction record (grey; measured or synthetic, as its file says) with its last loop, the eq. 9 "
    "fits of its pre-sliding branches and the points A, B, C with their lateral stiffness K_L "
    "(paper 001 Fig. 10)."
)
def loop_analysis_figure(cases):
    """Draw each case (grey), its last loop, the equation 9 fits and the points with their K_L (figure 10).

    Cases of the ``loop_analysis`` model (or :class:`~roughcontact.experiment.friction_loop.LoopAnalysis`
    results through :func:`~roughcontact.plotting.cases.as_cases`), one panel each, up to four. A
    record is called what its file's ``# origin:`` line says (the case's stored ``origin``): a
    synthetic loop is never labelled measured.
    """

    def draw(case, data, ax):
        force = case.scalars["normal_force"] * 1e3
        source = case.parameters.get("loop")
        name = Path(source).name if source else case.label
        origin = data.attrs.get("origin")
        title = f"{origin} loop {name}, F0 = {force:g} mN" if origin else f"{name}, F0 = {force:g} mN"
        plot_loop_analysis(
            {key: data[key].values for key in data.variables},
            case.scalars,
            title=title,
            ax=ax,
            record=f"{origin} record" if origin else "case",
        )

    return panel_per_case(cases, draw)


def _number(case, name: str) -> float:
    """Return a stored scalar as a float (nan where it was not finite, stored as None)."""
    value = case.scalars.get(name)
    return math.nan if value is None else float(value)


@dataclass(frozen=True)
class MeasuredLoop:
    """A compared friction loop to draw beside the cases: the loop, its analysis, its place and origin.

    The class keeps its name (the study key is ``measured_loop``), but the loop is called what its
    file says it is (``origin``): a synthetic loop is never labelled measured.

    Attributes
    ----------
    loop : FrictionLoop
        From :func:`~roughcontact.experiment.friction_loop.read_loop_csv`.
    analysis : LoopAnalysis
        Its analysis (:func:`~roughcontact.experiment.friction_loop.analyse_loop`).
    name : str
        Its name in legends (the file's).
    normal_force : float
        F0 of the loop [N].
    sample : str or None
        The sample it belongs to; None: every sample.
    origin : DataOrigin
        Measured, reconstructed or synthetic (the file's ``# origin:`` header, ``roughcontact.origin``).
    """

    loop: Any
    analysis: Any
    name: str
    normal_force: float
    sample: str | None = None
    origin: DataOrigin = MEASURED

    @property
    def legend(self) -> str:
        """The loop's name in a legend, by its origin: ``synthetic loop (paper001_measured_loop.csv)``."""
        return f"{self.origin.word} loop ({self.name})"

    def applies_to(self, sample: str) -> bool:
        """Whether the loop is drawn beside the cases of ``sample``."""
        return self.sample is None or self.sample == sample


def _by_force(cases) -> list:
    return sorted(cases, key=lambda r: _number(r, "normal_force"))


def _realisations_by_load(cases) -> list[list]:
    """Return the realisations of each case (:func:`~roughcontact.cases.realisations_of`), in load order."""
    return sorted(realisations_of(cases).values(), key=lambda group: _number(group[0], "normal_force"))


@caption(
    "Friction force against tangential displacement of every case, one panel per sample, with the "
    "loop of [analysis.compare] where given, named by its origin (measured or synthetic, as its file "
    "says; paper 001 Figs. 13-14)."
)
def loops_figure(cases, measured: MeasuredLoop | None = None, title: str = ""):
    """Draw the friction loops of every case, one panel per sample, with a compared loop (figures 13-14).

    ``title`` names a panel of cases without a sample.
    """
    from .layout import new_figure

    groups = grouped(with_fields(cases))
    if not groups:
        return None
    figure, axes = new_figure(1, len(groups), width=5.5, height=4.2)
    word = _realisation_word(cases)
    for ax, (sample, group) in zip(axes[0], groups.items(), strict=True):
        curves, spreads = [], []
        for cases in _realisations_by_load(group):
            case = cases[0]
            data = case.dataset()
            force, mu = _number(case, "normal_force"), _number(case, "friction_coefficient")
            label = f"{force * 1e3:g} mN, μ {mu:g}"
            loads = data["normal_force"].values[1:] if "normal_force" in data else None
            if loads is not None and np.ptp(loads) > 1e-9 * loads.max():  # a combined programme
                label = f"F_n {format_si(loads.min(), 'N')} to {format_si(loads.max(), 'N')}, μ {mu:g}"
            if data.attrs.get("control") == "force":
                label += ", force control"
            loops = [(np.asarray(c.dataset()["delta_x"]), np.asarray(c.dataset()["force_x"])) for c in cases]
            curve, each = _mean_loop(loops, label, word)
            curves.append(curve)
            spreads.append(each)
        overlay = []
        if measured is not None and measured.applies_to(sample):
            loop, analysis = measured.loop, measured.analysis
            shift = float(np.min(loop.displacement[analysis.loop]))
            overlay.append(
                (
                    loop.displacement - shift,
                    loop.force,
                    f"{measured.origin.word} loop ({measured.name}, "
                    f"{measured.normal_force * 1e3:g} mN, shifted {-shift * 1e6:+.2f} µm)",
                )
            )
        plot_hysteresis_loops(
            curves, overlay, realisations=spreads, ax=ax, title=f"{sample or title}: friction loops"
        )
    return figure


def _mean_loop(
    loops: list[tuple[np.ndarray, np.ndarray]], label: str, word: str = "realisations"
) -> tuple[tuple, list[tuple]]:
    """Return the loop to draw thick for one load's realisations, and the realisations to draw thin.

    One realisation is itself. Several under one displacement programme (the same steps, as
    paper 001's) give their mean force at each step, labelled with their number; programmes whose
    steps differ (the step control inserted steps) give the first loop and say so. ``word`` says
    what the realisations are (paper 001's generated balls: ``"stand-in balls"``).
    """
    if len(loops) == 1:
        return (*loops[0], label), []
    each = [(delta, force, "") for delta, force in loops]
    first = loops[0][0]
    if all(delta.shape == first.shape and np.allclose(delta, first, rtol=1e-9, atol=0) for delta, _ in loops):
        mean = np.mean([force for _, force in loops], axis=0)
        return (first, mean, f"{label}: mean of {len(loops)} {word} (thin: each)"), each
    return (*loops[0], f"{label}: {len(loops)} {word} (thin; their steps differ)"), each[1:]


@caption(
    "Normalised shear √(q_x² + q_y²)/(μ p) at the points A, B, C of the last loop (or the stored "
    "steps), zoomed to the contact: 1 slips, below 1 sticks (paper 001 Figs. 11-12)."
)
def stick_slip_figure(cases):
    """Draw the normalised shear of up to three cases: A, B, C of the last loop or kept steps (figures 11-12).

    One row per case; NaN (outside the contact) blank, zoomed to the contacts.
    """
    chosen = evenly_chosen(with_fields(cases), 3)
    if not chosen:
        return None
    panels = []
    for case in chosen:
        data = case.dataset()
        name = _case_name(case)
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
                step_name = f"{_ball_name(case)} {format_si(loads[int(data['map_step'][index])], 'N')}"
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
    """Draw stored normalised shear maps, zoomed to the contacts (paper 001 figures 11-12).

    ``panels``: (title, map on (x, y), x, y) per panel, the coordinates [m] at pixel centres; NaN
    (outside the contact) is blank. The zoom is the box of every finite pixel, widened by 10 %.
    """
    maps, extents, masks = {}, {}, []
    for label, values, x, y in panels:
        values, x, y = np.asarray(values, dtype=float), np.asarray(x), np.asarray(y)
        maps[label] = values.T  # rows along y
        extents[label] = _pixel_box(x, y)
        masks.append((np.isfinite(values), x, y))
    return plot_stick_slip_maps(maps, extents, zoom=_zoom(masks), columns=columns)


def _ball_name(case) -> str:
    """Return the ball's name: its sample, or its topography."""
    return case.parameters.get("sample") or case.parameters["topography"]


def _case_name(case) -> str:
    """Return the ball and its load, as the paper names its cases (``POM-like ball 25 mN``)."""
    return f"{_ball_name(case)} {_number(case, 'normal_force') * 1e3:g} mN"


@caption(
    "Contact pressure of up to three cases: the whole computed field with the zoomed box (left) and "
    "the zoom on the contact with its outline (right), on one colour scale (paper 001 Figs. 8-9)."
)
def pressure_figure(cases):
    """Draw the contact pressure of up to three cases, whole field and zoom on the contact (figures 8-9)."""
    chosen = evenly_chosen(_by_force(with_fields(cases)), 3)
    if not chosen:
        return None
    maps, extents, masks = {}, {}, []
    for case in chosen:
        data = case.dataset()
        pressure, x, y = (
            np.asarray(data["pressure"], dtype=float),
            np.asarray(data["x"]),
            np.asarray(data["y"]),
        )
        maps[_case_name(case)] = pressure.T  # rows along y
        extents[_case_name(case)] = _pixel_box(x, y)
        masks.append((pressure > 0, x, y))
    zoom = _zoom(masks)
    return None if zoom is None else plot_pressure_maps(maps, extents, zoom=zoom)


@caption(
    "The tangential displacement programme δ_x applied step by step (paper 001 Fig. 6); the last "
    "loop, which is analysed, is shaded and its points A, B, C marked. A combined programme's normal "
    "force is dashed on the right axis."
)
def path_figure(cases):
    """Draw the tangential displacement programme, step by step, with the last loop (figure 6).

    Cases that share one programme draw one line; the points A, B, C of the first case are marked.
    The realisations of a case share its programme (the step control may insert other steps in
    each): the first realisation's is drawn.
    """
    chosen = [group[0] for group in realisations_of(with_fields(cases)).values()]
    if not chosen:
        return None
    first = chosen[0].dataset()
    distinct: list[tuple[object, np.ndarray]] = []  # (case, delta_x) of each different programme
    for case in chosen:
        delta = np.asarray(case.dataset()["delta_x"], dtype=float)
        if not any(d.shape == delta.shape and np.allclose(d, delta, rtol=1e-9, atol=0) for _, d in distinct):
            distinct.append((case, delta))
    if len(distinct) == 1:
        names = ["programme"]
    else:  # named by ball and load, or by the swept values where those do not tell them apart
        names = [_case_name(case) for case, _ in distinct]
        if len(set(names)) < len(names):
            names = [case.label for case, _ in distinct]
    paths = dict(zip(names, (delta for _, delta in distinct), strict=True))
    positions = {
        name: _row_positions(case.dataset()) for name, (case, _) in zip(names, distinct, strict=True)
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
    refined = any(_number(case, "inserted_steps") > 0 for case, _ in distinct)
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


def _realisation_word(cases) -> str:
    """Return what the realisations are: paper 001's generated balls are stand-ins of Table 2's roughness."""
    return (
        "stand-in balls"
        if any(case.scalars.get("table2_rq") is not None for case in cases)
        else "realisations"
    )


def _verdict_line(at_load) -> str:
    """Sum up one ball's verdict against Mindlin over a sample's loads and points, in both readings.

    ``at_load``: the cases of each load, each list the realisations of one case. Empty with fewer
    than two realisations (no interval to judge). See
    ``roughcontact.contact.presliding.rough_vs_smooth``.
    """
    words: dict[str, list[str]] = {reading: [] for reading in READINGS}
    decided = 0
    for cases in at_load:
        if len(cases) < 2:
            return ""
        for point in POINTS:
            references = {
                reading: [_number(r, f"K_L_{point}_mindlin_{reading}") for r in cases] for reading in READINGS
            }
            verdicts = rough_vs_smooth(
                mindlin_ratios([_number(r, f"K_L_{point}") for r in cases], references)
            )
            for reading in READINGS:
                words[reading].append(verdicts[reading].word)
            decided += verdict_words(verdicts, "printed") != verdicts["printed"].word
    total = len(words["johnson"])

    def tally(reading: str) -> str:
        counts = {word: words[reading].count(word) for word in dict.fromkeys(words[reading])}
        return ", ".join(f"{word} {count}/{total}" for word, count in counts.items())

    line = f"one ball vs Mindlin (95 % prediction): Johnson {tally('johnson')}"
    line += f"; as printed {tally('printed')}"
    if decided:
        line += f"\n({decided}/{total} as printed decided by eq. 12's printed factor 4, not by the roughness)"
    return line


@caption(
    "Lateral stiffness K_L at the points A, B, C against the normal force, simulated beside Mindlin's "
    "smooth ball in both readings of eq. 12, one panel per sample (paper 001 Fig. 15). Over "
    "realisations: the mean with the 95 % interval of the mean (capped bars) and the 95 % prediction "
    "interval of one ball (thin lines), and the verdict of one ball against Mindlin in the title."
)
def lateral_stiffness_figure(cases, measured: MeasuredLoop | None = None, title: str = ""):
    """Draw K_L at A, B, C against F0 with Mindlin in both readings, one panel per sample (figure 15).

    Over realisations, each load shows the mean with its 95 % interval (capped bars) and the 95 %
    prediction interval of one ball (thin lines); the panel's title sums up one ball's verdict
    against Mindlin in both readings (``roughcontact.contact.presliding.rough_vs_smooth``),
    saying where eq. 12's printed factor 4 decides it. A ``measured`` loop's K_L is marked at its
    load, named by its origin; ``title`` names a panel of cases without a sample. None where no
    case has an analysed loop (its K_L are undefined).
    """
    from .layout import new_figure

    if not any(np.isfinite(_number(r, f"K_L_{p}")) for r in cases for p in POINTS):
        return None  # no case has a loop to analyse: Mindlin's curves alone compare with nothing
    groups = grouped(cases)
    every = [_number(r, "normal_force") for r in cases]
    low, high = min(every), max(every)
    if high <= low * (1 + 1e-9):
        low, high = 0.8 * low, 1.2 * high
    dense = np.linspace(low, high, 50)
    word = _realisation_word(cases)
    figure, axes = new_figure(1, len(groups), width=5.5, height=5.6)
    for number, (ax, (sample, group)) in enumerate(zip(axes[0], groups.items(), strict=True)):
        at_load = _realisations_by_load(group)
        firsts = [cases[0] for cases in at_load]
        loads = [_number(case, "normal_force") for case in firsts]
        spreads = {
            p: [spread((_number(r, f"K_L_{p}") for r in cases), bounds=(0.0, math.inf)) for cases in at_load]
            for p in POINTS
        }
        simulated = {p: [s.mean for s in spreads[p]] for p in POINTS}
        count = max(len(cases) for cases in at_load)
        interval = {p: [s.half_width for s in spreads[p]] for p in POINTS} if count > 1 else None
        prediction = None
        if count > 1:
            ends = {p: [s.prediction() for s in spreads[p]] for p in POINTS}
            prediction = {p: ([e[0] for e in ends[p]], [e[1] for e in ends[p]]) for p in POINTS}
        drawn = dict(interval=interval, prediction=prediction, realisations=count, realisation_word=word)
        curves = _mindlin_curves(firsts, dense)
        if curves is None:  # materials differ within the sample: Mindlin at the cases' loads only
            curves = {
                reading: {p: [_number(r, f"K_L_{p}_mindlin_{reading}") for r in firsts] for p in POINTS}
                for reading in READINGS
            }
            plot_lateral_stiffness(loads, simulated, mindlin=curves, ax=ax, **drawn)
        else:
            plot_lateral_stiffness(dense, mindlin=curves, ax=ax)
            plot_lateral_stiffness(loads, simulated, ax=ax, **drawn)
        if measured is not None and measured.applies_to(sample):
            stiffness = measured.analysis.lateral_stiffness
            for point in POINTS:
                ax.plot(
                    measured.normal_force / FORCE_SCALE,
                    stiffness[point] / STIFFNESS_SCALE,
                    "s",
                    markerfacecolor="none",
                    markersize=9,
                    color=POINT_COLOURS.get(point),
                    label=f"{point} {measured.legend}",
                )
        heading = f"({chr(ord('a') + number)}) {sample or title}"
        verdict = _verdict_line(at_load)
        ax.set_title(f"{heading}\n{verdict}" if verdict else heading, fontsize="small" if verdict else None)
        shown = measured if measured is not None and measured.applies_to(sample) else None
        _stiffness_legend(ax, count, word, shown)
    return figure


def _stiffness_legend(ax: Axes, count: int, word: str, measured: MeasuredLoop | None) -> None:
    """Put a short legend under a K_L panel: colours name the points once, styles what is drawn."""
    from matplotlib.lines import Line2D

    grey = "0.3"
    handles = [Line2D([], [], color=POINT_COLOURS[p], linewidth=3, label=f"point {p}") for p in POINTS]
    handles += [
        Line2D([], [], color=grey, linestyle="--", label="Mindlin (Johnson, textbook)"),
        Line2D([], [], color=grey, linestyle="-.", label="Mindlin (eq. 12 as printed, 4x)"),
    ]
    if count > 1:
        handles += [
            Line2D(
                [], [], color=grey, marker="o", linestyle="none", label=f"mean ± 95 % CI ({count} {word})"
            ),
            Line2D([], [], color=grey, linewidth=0.8, alpha=0.5, label="one ball: 95 % prediction interval"),
        ]
    else:
        handles.append(Line2D([], [], color=grey, marker="o", linestyle="none", label="simulated"))
    if measured is not None:
        handles.append(
            Line2D(
                [],
                [],
                color=grey,
                marker="s",
                markerfacecolor="none",
                linestyle="none",
                label=measured.legend,
            )
        )
    ax.legend(handles=handles, fontsize="x-small", ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.15))
