"""Figures of adhesive contact over a load-unload cycle: force against approach, maps at pull-off, pull-off.

Figure functions on cases (:mod:`roughcontact.plotting.cases`): study records of the ``adhesion``
model, or :class:`~roughcontact.contact.adhesive_result.AdhesiveResult` objects through
:func:`~roughcontact.plotting.cases.as_cases`.
"""

from __future__ import annotations

import numpy as np

from ..cases import box_around, evenly_chosen, with_fields
from ..contact.adhesive_result import LINE_NAMES
from .cases import caption


def _scale(values, unit: str) -> tuple[float, str]:
    from ..units import prefixed_scale

    finite = np.abs(np.asarray(values, dtype=float))
    finite = finite[np.isfinite(finite)]
    return prefixed_scale(float(finite.max()) if finite.size else 1.0, unit)


def _scalar(scalars, name: str) -> float:
    """Return a case's scalar ``name`` (a line contact's under its name in ``adhesive_result.LINE_NAMES``)."""
    return scalars[name] if name in scalars else scalars[LINE_NAMES[name]]


def _per_length(cases) -> bool:
    """Whether the cases are line contacts (forces per length, lengths for areas)."""
    return any(LINE_NAMES["pull_off_force"] in r.scalars for r in cases)


BRANCH_STYLES = {"loading": "-", "unloading": "-."}
"""Line style of each branch of the boundary-element cycle (the Winkler springs are dashed)."""


def _draw_cycle(ax, data, case, colour, scales, retraced: bool) -> None:
    """Draw one case's cycle: loading solid, unloading dash-dotted, jumps dotted; Winkler dashed.

    ``retraced`` (:func:`_retraced`): the unloading lies on the loading and is left out, since
    drawn over it it would only hide the loading's style.
    """
    (a_scale, _), (f_scale, _) = scales
    approach = np.asarray(data["approach"]) / a_scale
    force = np.asarray(data["force"]) / f_scale
    jump = np.asarray(data["jump"], dtype=bool)
    turn = int(np.argmax(approach))  # the deepest approach ends the loading branch
    for branch, part in (("loading", slice(0, turn + 1)), ("unloading", slice(turn, len(force)))):
        if branch == "unloading" and retraced:
            break
        _draw_branch(ax, approach[part], force[part], jump[part], BRANCH_STYLES[branch], colour)
    scalars = case.scalars
    pull_off = _scalar(scalars, "pull_off_force")
    force_unit = "N/m" if _per_length([case]) else "N"
    ax.plot(
        scalars["pull_off_approach"] / a_scale,
        -pull_off / f_scale,
        "v",
        color=colour,
        label=f"{case.label}: pull-off {_with_unit(pull_off, _scale([pull_off], force_unit))}",
    )
    if "winkler_force" in data:
        winkler = np.asarray(data["winkler_force"]) / f_scale
        end = turn + 1 if retraces(approach, winkler, turn) else len(winkler)
        ax.plot(approach[:end], winkler[:end], "--", color=colour, lw=1.2)
        ax.plot(
            scalars["winkler_pull_off_approach"] / a_scale,
            -scalars["winkler_pull_off_force"] / f_scale,
            "s",
            mfc="none",
            color=colour,
            label=f"Winkler springs: pull-off {_with_unit(scalars['winkler_pull_off_force'])}",
        )


def _retraced(data) -> bool:
    """Whether a stored cycle's boundary-element unloading lies on its loading (:func:`retraces`)."""
    approach = np.asarray(data["approach"])
    return retraces(approach, np.asarray(data["force"]), int(np.argmax(approach)))


def retraces(approach: np.ndarray, force: np.ndarray, turn: int) -> bool:
    """Whether the unloading branch (after index ``turn``) lies on the loading one (to 0.1 % of the range)."""
    load_a, load_f = approach[: turn + 1], force[: turn + 1]
    back_a, back_f = approach[turn:][::-1], force[turn:][::-1]
    if back_a.size < 2 or not (np.all(np.diff(load_a) > 0) and np.all(np.diff(back_a) > 0)):
        return False
    shared = load_a[(load_a >= back_a[0]) & (load_a <= back_a[-1])]
    if shared.size == 0:
        return False
    difference = np.abs(np.interp(shared, load_a, load_f) - np.interp(shared, back_a, back_f))
    return bool(difference.max() <= 1e-3 * (np.ptp(force) or 1.0))


def _draw_branch(ax, approach, force, jump, style: str, colour) -> None:
    """Draw the solved steps of one branch joined in ``style``, and each jump between two steps dotted."""
    start = 0
    for end in [*np.flatnonzero(jump[1:]) + 1, len(force)]:
        ax.plot(approach[start:end], force[start:end], style, color=colour, lw=1.4)
        if end < len(force):
            ax.plot(approach[end - 1 : end + 1], force[end - 1 : end + 1], ":", color=colour, lw=1.0)
        start = end


def _style_legend(ax, winkler: bool, retraced: bool, jumps: bool) -> None:
    """Add the legend of the cases' pull-offs with entries that say what each line style means.

    ``retraced``: every case's unloading lies on its loading, so only the loading is drawn;
    ``jumps``: some case jumps into or out of contact (dotted).
    """
    from matplotlib.lines import Line2D

    from .layout import legend

    styles = [(Line2D([], [], color="0.3", ls=style), f"{branch} (boundary elements)")
              for branch, style in BRANCH_STYLES.items()]  # fmt: skip
    if retraced:
        styles = [(Line2D([], [], color="0.3", ls="-"), "loading; unloading retraces it (boundary elements)")]
    if jumps:
        styles.append((Line2D([], [], color="0.3", ls=":"), "jump into or out of contact"))
    if winkler:
        styles.append((Line2D([], [], color="0.3", ls="--"), "Winkler springs"))
    legend(ax, fontsize="small", extra=tuple(styles))


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
    "within 1.5 times the largest pull-off force): the boundary-element solution step by step, solid on "
    "loading and dash-dotted on unloading; "
    "dotted, a jump into or out of contact (bracketed to the jump resolution); triangle, the pull-off "
    "force; dashed and open square, paper 000's Winkler-layer springs on the same surface and their "
    "pull-off (winkler = true). The area "
    "inside a cycle is the energy it dissipates."
)
def force_approach_figure(cases):
    """Draw the force-approach cycles of up to six cases with fields (see the caption); None without any."""
    from .layout import new_figure

    chosen = evenly_chosen(with_fields(cases), 6)
    if not chosen:
        return None
    datasets = [case.dataset() for case in chosen]
    scales = (
        _scale(np.concatenate([np.asarray(d["approach"]) for d in datasets]), "m"),
        _scale(
            np.concatenate([np.asarray(d["force"]) for d in datasets]),
            "N/m" if "y" not in datasets[0].dims else "N",
        ),
    )
    retraced = [_retraced(data) for data in datasets]  # once per case, for both panels and the legend
    figure, axes = new_figure(1, 2, width=5.4, height=4.4)
    whole, zoom = axes[0]
    for ax in (whole, zoom):
        for index, (case, data) in enumerate(zip(chosen, datasets, strict=True)):
            _draw_cycle(ax, data, case, f"C{index}", scales, retraced[index])
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
    whole.set_title("load-unload cycle")
    zoom.set_title("near the pull-off")
    _style_legend(zoom, winkler, all(retraced), any(bool(np.asarray(d["jump"]).any()) for d in datasets))
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
def adhesion_maps_figure(cases):
    """Draw pressure and gap maps at the pull-off of up to three 2D cases; None for profiles."""
    from .layout import ColourScale, clip_words, clipped_limits, new_figure, shared_colorbar
    from .study import map_axes

    chosen = evenly_chosen(with_fields(cases), 3)
    fields = [
        _near_contact(r.dataset().sel(state="pull_off"), r.scalars["interaction_length"]) for r in chosen
    ]
    if not chosen or "y" not in fields[0].dims:
        return None
    figure, axes = new_figure(2, len(chosen), width=3.8 if len(chosen) > 1 else 4.8, height=3.3)
    pooled = np.concatenate([np.ravel(np.asarray(f["pressure"])) for f in fields])
    low, high = clipped_limits(pooled, (0.5, 99.5))
    bound = max(abs(low), abs(high)) or 1.0
    pressure_scale = ColourScale(-bound, bound, clip_words((0.5, 99.5)), "both")
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
    from ..units import format_si

    line = _per_length(chosen)
    force_unit, area_unit = ("N/m", "m") if line else ("N", "m²")
    for case, ax in zip(chosen, axes[0], strict=True):  # each value in its own prefix (a title, no axis)
        s = case.scalars
        ax.set_title(
            f"{case.label}\npull-off {format_si(_scalar(s, 'pull_off_force'), force_unit, digits=3)}"
            f"\ncontact "
            f"{format_si(_scalar(s, 'contact_area_at_pull_off'), area_unit, digits=3)}, interacting "
            f"{format_si(_scalar(s, 'interaction_area_at_pull_off'), area_unit, digits=3)}",
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
def pull_off_figure(cases):
    """Draw the pull-off force against the swept work of adhesion or range; None when neither varies."""
    from .layout import legend, new_figure

    swept = [entry for entry in _SWEPT if len({float(r.scalars[entry[0]]) for r in cases}) > 1]
    if not swept:
        return None
    name, unit, words = swept[0]
    order = sorted(cases, key=lambda r: float(r.scalars[name]))
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
