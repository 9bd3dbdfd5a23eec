"""Figures of the asperity models and the island compression (paper 002 figures 7-9)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from ..cases import branch_points, evenly_chosen, grouped, realisations_of, surface_origin, with_fields
from ..units import format_si, unit_factor
from .cases import caption
from .contact import plot_von_mises
from .layout import axes_for, legend

_BRANCH_STYLES = {"loading": "-", "unloading": "--"}
_LOAD_UNIT, _AREA_UNIT = "µN", "µm²"  # fixed, in the units of paper 002's figures
_LOAD_SCALE, _AREA_SCALE = (float(unit_factor(unit)[0]) for unit in (_LOAD_UNIT, _AREA_UNIT))


def plot_load_interference(
    curves: dict[str, dict],
    critical_interference: float,
    ax: Axes | None = None,
    *,
    measured: dict | None = None,
    notes: Sequence[str] = (),
):
    """Draw load (uN) against omega / omega_c for each curve, loading solid, unloading dashed (figure 7).

    Parameters
    ----------
    curves : dict of str to dict
        Label -> curve dict with "branch", "approach" [m] and "force" [N] (``.curve()`` of a
        :class:`~roughcontact.asperity.StatisticalLoadUnload` or an island compression); a curve
        that is the mean over realisations also has "approach_min" and "approach_max" [m], the
        range of the realisations at each load, shaded.
    critical_interference : float
        omega_c [m] for the abscissa.
    ax : Axes, optional
        Where to draw.
    measured : dict, optional
        A measured curve with "approach" [m] and "force" [N], drawn as markers.
    notes : sequence of str
        Lines of text added at the end of the legend, without a symbol (a verdict, say).

    Returns
    -------
    (Figure, Axes)
    """
    fig, ax = axes_for(ax, figsize=(5.5, 4.2))
    for number, (label, curve) in enumerate(curves.items()):
        color = f"C{number % 10}"
        branches = np.asarray(curve["branch"])
        for branch, style in _BRANCH_STYLES.items():
            keep = branch_points(branches, branch)
            if keep.size:
                x = np.asarray(curve["approach"])[keep] / critical_interference
                load = np.asarray(curve["force"])[keep] / _LOAD_SCALE
                ax.plot(x, load, style, color=color, label=f"{label}, {branch}")
                if "approach_min" in curve:
                    low, high = (
                        np.asarray(curve[k])[keep] / critical_interference
                        for k in ("approach_min", "approach_max")
                    )
                    ax.fill_betweenx(load, low, high, color=color, alpha=0.15, linewidth=0)
    if measured is not None:
        x = np.asarray(measured["approach"]) / critical_interference
        ax.plot(x, np.asarray(measured["force"]) / _LOAD_SCALE, "k.", ms=3, label="measured")
    ax.set_xlabel("interference ω/ω_c")
    ax.set_ylabel(f"load ({_LOAD_UNIT})")
    extra = tuple((Line2D([], [], linestyle="none"), note) for note in notes)
    # below the axes: no curve hidden
    legend(ax, fontsize="x-small", loc="upper center", bbox_to_anchor=(0.5, -0.2), extra=extra)
    ax.grid(True, alpha=0.3)
    return fig, ax


def plot_area_load(curves: dict[str, dict], ax: Axes | None = None):
    """Draw the real contact area (um^2) against load (uN), loading solid and unloading dashed, per curve."""
    fig, ax = axes_for(ax)
    for label, curve in curves.items():
        branch = np.asarray(curve["branch"])
        area = np.asarray(curve["contact_area"]) / _AREA_SCALE
        load = np.asarray(curve["force"]) / _LOAD_SCALE
        loading, unloading = branch_points(branch, "loading"), branch_points(branch, "unloading")
        (line,) = ax.plot(load[loading], area[loading], "-o", ms=3, label=f"{label}, loading")
        if unloading.size:
            ax.plot(
                load[unloading], area[unloading], "--", color=line.get_color(), label=f"{label}, unloading"
            )
    ax.set_xlabel(f"load ({_LOAD_UNIT})")
    ax.set_ylabel(f"real contact area ({_AREA_UNIT})")
    legend(ax, fontsize="small")
    ax.grid(True, alpha=0.3)
    return fig, ax


def plot_von_mises_maps(compression, indices: list[int], *, depth: float = 0.0) -> tuple[Figure, np.ndarray]:
    """Draw von Mises maps of an island compression at the chosen steps (figures 8-9), one panel each.

    Parameters
    ----------
    compression : LoadUnloadResult
        From :func:`roughcontact.papers.paper002.compress_island`.
    indices : list of int
        Steps to draw (e.g. those at 0, 200, ..., 1000 uN).
    depth : float
        Depth of the plane [m] (0: the surface, as the paper's maps).

    Returns
    -------
    (Figure, ndarray of Axes)
    """
    columns = min(3, len(indices))
    rows = -(-len(indices) // columns)
    fig = Figure(figsize=(4.2 * columns, 3.6 * rows), layout="constrained")
    axes = np.atleast_1d(fig.subplots(rows, columns)).ravel()
    for ax, index in zip(axes, indices, strict=False):
        plot_von_mises(compression.stress(index, depths=[depth]), 0, ax)
        force = compression.steps[index].force
        ax.set_title(f"{compression.branch[index]}, W = {force / _LOAD_SCALE:.0f} {_LOAD_UNIT}")
    for ax in axes[len(indices) :]:
        ax.set_visible(False)
    return fig, axes


def curve_of(case) -> dict[str, np.ndarray] | None:
    """Return the stored load-unload curve of a finished case as a dict of arrays (None without one)."""
    if not case.has_fields:
        return None
    data = case.dataset()
    if data is None or "branch" not in data:
        return None
    return {name: np.asarray(data[name]) for name in data.data_vars}


def common_omega_c(cases) -> float | None:
    """Return omega_c [m] shared by all ``cases`` (within 1e-9), or None where they differ or have none."""
    values = [r.scalars.get("critical_interference") for r in cases]
    if not values or any(v is None for v in values):
        return None
    return values[0] if np.allclose(values, values[0], rtol=1e-9, atol=0) else None


def draw_load_interference(
    curves: dict[str, dict], omega_c: float | None, measured: dict | None, notes: Sequence[str] = ()
):
    """Paper 002 figure 7: load against omega / omega_c (or against omega in nm where omega_c is not shared).

    Uses :func:`roughcontact.plotting.asperity.plot_load_interference`, which draws at most five
    curves; callers pass at most five. ``notes`` end the legend.
    """
    figure, ax = plot_load_interference(curves, omega_c or 1e-9, measured=measured, notes=notes)
    if omega_c is None:
        ax.set_xlabel("interference ω (nm)")
    else:
        ax.set_title(f"ω_c = {omega_c * 1e9:.3g} nm", fontsize="medium")
    return figure


def _law_words(case) -> str:
    """Return the case's single-asperity loading law in a reader's words (``Kogut-Etsion``)."""
    from ..asperity.load_unload import LAW_NAMES

    law = case.parameters.get("law", "")
    return LAW_NAMES.get(law, law)


def _labelled_curves(cases) -> dict[str, dict]:
    chosen = evenly_chosen(with_fields(cases), 5)
    curves = {}
    for case in chosen:
        curve = curve_of(case)
        if curve is not None:
            law = _law_words(case)
            curves[f"KKE ({law})" if len(chosen) == 1 else f"KKE, {case.label}"] = curve
    return curves


@caption(
    "Load against interference ω/ω_c of the statistical KKE model, loading (solid) and unloading "
    "(dashed), with the measured curve of [analysis.compare] where given (paper 002 Fig. 7)."
)
def asperity_load_interference_figure(cases, measured=None):
    """Draw paper 002's figure 7 for up to five cases of the ``asperity`` model, beside a ``measured`` curve.

    ``measured`` is a dict with ``approach`` [m] and ``force`` [N]
    (:func:`~roughcontact.experiment.load_curve.read_load_curve`). None without a stored curve.
    """
    curves = _labelled_curves(cases)
    if not curves:
        return None
    return draw_load_interference(curves, common_omega_c(with_fields(cases)), measured)


@caption(
    "Real contact area against load from the statistical KKE model, loading (solid) and unloading "
    "(dashed; the single-asperity unloading area of Etsion, Kligerman and Kadin, recalled from the "
    "literature)."
)
def asperity_contact_area_figure(cases):
    """Draw the real contact area against load of cases of the ``asperity`` model (up to five)."""
    curves = _labelled_curves(cases)
    if not curves:
        return None
    figure, ax = plot_area_load(curves)
    ax.set_title("real contact area (statistical)")
    return figure


def _asperity_curves(statistical: Mapping[str, Sequence]) -> tuple[dict[str, dict], list]:
    """Return the curves of the statistical analyses (at most two) and the cases they come from."""
    curves, used = {}, []
    sources = [(name, case) for name, cases in statistical.items() for case in with_fields(cases)]
    for name, case in sources[:2]:
        curve = curve_of(case)
        if curve is None:
            continue
        law = _law_words(case)
        label = f"KKE ({law})" if len(sources) == 1 else f"KKE {name}, {case.label}"
        curves[label] = curve
        used.append(case)
    return curves, used


def verdict_note(statistical_case, group, label: str = "") -> str | None:
    """Return the legend line judging a statistical case's peak interference against BEM realisations.

    KKE's peak over the BEM mean, with the ratio's interval for one island (the paper's claim:
    the prediction interval of one realisation) and for the mean, and the verdict at each level
    (:func:`roughcontact.asperity.comparison.against_realisations`); None where either has no peak.
    """
    from ..asperity.comparison import against_realisations

    peak = statistical_case.scalars.get("peak_interference")
    values = [c.scalars.get("peak_interference") for c in group]
    values = [float(v) for v in values if v is not None]
    if peak is None or not values:
        return None
    found = against_realisations(float(peak), values, quantity="peak_interference")
    head = f"{label}: " if label else ""
    if found.deterministic.n < 2:
        return f"{head}KKE / BEM ω_max = {found.ratio:.3g} (one realisation: no interval)"
    words = []
    for of, level in (("one", "one island"), ("mean", "the mean")):
        low, high = found.ratio_interval(of)
        verdict = found.model_words(of)
        verdict = "holds 1, not established" if verdict == "not established" else f"KKE {verdict}"
        words.append(f"{level} [{low:.3g}, {high:.3g}], {verdict}")
    return f"{head}KKE ω_max / BEM mean = {found.ratio:.3g}; 95 % for {words[0]};\nfor {words[1]}"


@caption(
    "Load against interference ω/ω_c on loading (solid) and unloading (dashed): the deterministic BEM "
    "compression beside the statistical KKE curves of the study's asperity analyses and the measured "
    "curve, where given (paper 002 Fig. 7). The legend's last line gives KKE's peak interference over "
    "the BEM mean with its 95 % interval for one island (prediction interval, the paper's claim) and "
    "for the mean (confidence interval), and whether KKE over-predicts at each level."
)
def island_load_interference_figure(cases, statistical=None, measured=None):
    """Draw paper 002's figure 7 for cases of the ``load_unload`` model, beside the statistical curves.

    ``statistical`` maps an analysis name to cases of the ``asperity`` model (their curves are
    drawn, up to two); ``measured`` as for :func:`asperity_load_interference_figure`. The legend
    ends with :func:`verdict_note` of the first statistical curve against each BEM group.
    """
    curves, used = _asperity_curves(statistical or {})
    own = evenly_chosen(list(realisations_of(with_fields(cases)).items()), 5 - len(curves))
    named = len(own) > 1
    notes = [verdict_note(used[0], group, label if named else "") for label, group in own] if used else []
    for label, group in own:
        curve = _mean_curve([c for c in map(curve_of, group) if c is not None])
        if curve is not None:
            origin = surface_origin(group)
            island = f"{origin} island" if origin else "island"
            model = f"BEM, {island} ({group[0].parameters.get('plasticity', 'surface')} plasticity)"
            if len(own) > 1 and label:
                model += f", {label}"
            if len(group) > 1:
                model += f", mean of {len(group)} realisations (band: their range)"
            curves[model] = curve
    if not curves:
        return None
    return draw_load_interference(curves, common_omega_c(used), measured, [n for n in notes if n])


_QUANTITY_AXES = {
    "peak_interference": ("peak interference ω_max", "nm", 1e-9),
    "interference_at_return_force": ("interference back at the reference load", "nm", 1e-9),
    "peak_contact_area": ("real contact area at the peak", _AREA_UNIT, _AREA_SCALE),
}


@caption(
    "Paper 002 Fig. 6 said in full: each quantity of the island (peak interference, interference back at "
    "the reference load on unloading, real contact area at the peak) against the number of grid points, "
    "mean over the realisations with its 95 % confidence interval, each realisation (the same surface on "
    "every grid) as a thin line; each panel's title gives the change of the mean at the last refinement "
    "and the observed order over the three finest grids, or why there is none (not monotone), with the "
    "Richardson extrapolation where there is one."
)
def mesh_convergence_figure(cases):
    """Draw paper 002's figure 6: one panel per quantity of the mesh study, None for one grid.

    The quantities and their numbers are :func:`roughcontact.asperity.convergence.mesh_convergence`'s.
    """
    from ..asperity.convergence import mesh_convergence

    found = mesh_convergence(cases)
    if found is None:
        return None
    figure = Figure(figsize=(4.6 * len(found), 4.4), layout="constrained")
    axes = np.atleast_1d(figure.subplots(1, len(found))).ravel()
    for ax, quantity in zip(axes, found, strict=True):
        name, unit, scale = _QUANTITY_AXES.get(quantity.quantity, (quantity.quantity, quantity.unit, 1.0))
        points = [g.grid_points for g in quantity.grids]
        means = np.array([g.spread.mean for g in quantity.grids]) / scale
        low = np.array([g.spread.ci95_low for g in quantity.grids]) / scale
        high = np.array([g.spread.ci95_high for g in quantity.grids]) / scale
        count = max(g.spread.n for g in quantity.grids)
        errors = np.nan_to_num(np.vstack([means - low, high - means]))
        label = "mean" + (f" of {count} realisations, 95 % interval" if count > 1 else "")
        ax.errorbar(points, means, yerr=errors, fmt="o-", capsize=3, label=label, zorder=3)
        if count > 1:  # each realisation is one surface on every grid: its own line
            for number, (_, group) in enumerate(grouped(cases, "replicate").items()):
                own = sorted(
                    (int(c.scalars["grid_points"]), float(c.scalars[quantity.quantity]) / scale)
                    for c in group
                    if c.scalars.get(quantity.quantity) is not None
                    and c.scalars.get("grid_points") is not None
                )
                if own:
                    ax.plot(
                        *zip(*own, strict=True),
                        "-",
                        color="0.6",
                        linewidth=0.8,
                        label="each realisation" if number == 0 else None,
                    )
        if quantity.order is not None:
            p, extrapolated = quantity.order
            ax.axhline(
                extrapolated / scale,
                color="0.4",
                linestyle="--",
                linewidth=1.0,
                label=f"Richardson extrapolation {extrapolated / scale:.4g} {unit} (observed order {p:.2f})",
            )
        change = quantity.finest.change
        ax.set_title(f"last refinement {100 * change:+.2g} %\nmean: {quantity.trend}", fontsize="medium")
        ax.set_xscale("log")
        side = [round(math.sqrt(n)) for n in points]  # a square grid of n = side^2 points reads as side²
        ax.set_xticks(points, [f"{s}²" if s * s == n else str(n) for s, n in zip(side, points, strict=True)])
        ax.minorticks_off()
        ax.set_xlabel("grid points (elements)")
        ax.set_ylabel(f"{name} ({unit})")
        ax.grid(True, alpha=0.3)
        legend(ax, fontsize="x-small", loc="upper center", bbox_to_anchor=(0.5, -0.15))  # below the bars
    return figure


def __getattr__(name: str):
    from .._deprecation import moved

    return moved(__name__, name, {"mesh_convergence": "roughcontact.asperity.convergence"})


def _mean_curve(curves: list[dict]) -> dict | None:
    """Return the mean load-interference curve of realisations under one force programme, with its range.

    The curves must share their forces (to 1e-4: each is reached to its solver's tolerance) and
    branches (the same programme); the mean and range are of the interference at each force. One
    curve is returned as it is; None for none, and the first curve where the programmes differ.
    """
    if len(curves) < 2:
        return curves[0] if curves else None
    first = curves[0]
    same = all(
        c["force"].shape == first["force"].shape
        and np.array_equal(c["branch"], first["branch"])
        and np.allclose(c["force"], first["force"], rtol=1e-4, atol=1e-6 * np.max(np.abs(first["force"])))
        for c in curves
    )
    if not same:
        return first
    approaches = np.array([c["approach"] for c in curves])
    return first | {
        "approach": approaches.mean(axis=0),
        "approach_min": approaches.min(axis=0),
        "approach_max": approaches.max(axis=0),
    }


def _grid_colorbar(image, panels, scale) -> None:
    """Draw the von Mises colour bar of a grid of map panels, about two rows tall.

    A bar as tall as a whole grid of small maps dwarfs them.
    """
    from .layout import shared_colorbar

    rows = panels[0].get_gridspec().nrows
    shared_colorbar(image, panels, "von Mises stress", "Pa", scale, shrink=min(1.0, 2.2 / rows))


def _first_case_panels(cases, name: str, *, height: float):
    """Return (case, dataset, figure, axes, count): a grid of up to 3 columns, one panel per stored map.

    The first case with stored fields and the variable ``name``; None when there is none.
    """
    from .layout import new_figure

    case = next(iter(with_fields(cases)), None)
    data = None if case is None else case.dataset()
    if data is None or name not in data:
        return None
    count = data.sizes["map"]
    columns = min(3, count)
    figure, axes = new_figure(-(-count // columns), columns, width=4.2, height=height)
    return case, data, figure, [ax for row in axes for ax in row], count


@caption(
    "Von Mises stress maps of the first case at the stored loads, loading then unloading, on one "
    "colour scale (paper 002 Figs. 8-9); a panel at zero load says so."
)
def island_von_mises_figure(cases):
    """Draw paper 002's figures 8-9: the stored von Mises maps of the first case, loading then unloading."""
    from .layout import colour_scale
    from .study import map_axes

    panels = _first_case_panels(cases, "von_mises", height=3.6)
    if panels is None:
        return None
    case, data, figure, flat, count = panels
    # one scale, the full range: the panels compare, and a smooth stress field has no spike to clip
    shared = colour_scale(data["von_mises"], from_zero=True, percentiles=(0, 100))
    image = None
    for index, ax in enumerate(flat):
        if index >= count:
            ax.set_visible(False)
            continue
        field = data["von_mises"].isel(map=index)
        if float(field.max()) > 0:
            image = map_axes(ax, field, "von Mises", "Pa", cmap="inferno", scale=shared, colorbar=False)
        else:  # no load and nothing left: no plastic strain yet, or the surface model (module notes)
            volume = data.attrs.get("plasticity") == "volume"
            ax.text(
                0.5,
                0.5,
                "no pressure, no stress" + ("" if volume else "\n(no residual stress\nin this model)"),
                ha="center",
                va="center",
                transform=ax.transAxes,
            )
            ax.set_xticks([])
            ax.set_yticks([])
        ax.set_title(f"{str(field.map_branch.values)}, W = {format_si(float(field.map_force), 'N')}")
    if image is not None:
        _grid_colorbar(image, flat[:count], shared)
    depth = float(data.attrs.get("stress_depth", 0.0))
    where = "surface" if depth == 0 else f"z = {format_si(depth, 'm', digits=3)}"
    figure.suptitle(f"von Mises stress ({where})" + (f", {case.label}" if len(cases) > 1 else ""))
    return figure


@caption(
    "Von Mises stress of the first case on a vertical section along x, through the line that carries "
    "the most load at the peak, at the "
    "stored loads, loading then unloading, on one colour scale (volume plasticity only): the plastic "
    "zone below the contacts and, at zero load, the residual stress (paper 002 Fig. 9e)."
)
def von_mises_section_figure(cases):
    """Draw the von Mises stress on the stored vertical section of the first case (volume plasticity)."""
    from .layout import colour_scale

    panels = _first_case_panels(cases, "von_mises_section", height=2.6)
    if panels is None:
        return None
    _, data, figure, flat, count = panels
    sections = data["von_mises_section"]
    shared = colour_scale(sections, from_zero=True, percentiles=(0, 100))
    factor, _ = shared.prefixed("Pa")
    x = sections["x_section"].values * 1e6
    z = sections["z"].values * 1e6
    image = None
    for index, ax in enumerate(flat):
        if index >= count:
            ax.set_visible(False)
            continue
        image = ax.pcolormesh(
            x,
            z,
            sections.isel(map=index).values.T / factor,
            cmap="inferno",
            vmin=shared.low / factor,
            vmax=shared.high / factor,
            shading="nearest",
        )
        ax.invert_yaxis()
        ax.set_xlabel("x (µm)")
        ax.set_ylabel("depth z (µm)")
        force = float(data["von_mises"].map_force[index])
        ax.set_title(f"{str(data['von_mises'].map_branch.values[index])}, W = {format_si(force, 'N')}")
    _grid_colorbar(image, flat[:count], shared)
    figure.suptitle(sections.attrs.get("long_name", "von Mises stress on a section"))
    return figure
