"""Figures of the Winkler-Lennard-Jones friction model and of its validation (paper 000, figures 8-9).

``plot_*`` draw one sweep or comparison on optional axes; ``*_figure`` draw a study's figure from
the cases of the ``friction`` model (:mod:`roughcontact.plotting.cases`).
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from ..cases import at_load, axis_words, grouped, loads_of, setting_of, surface_origin
from ..units import format_si, prefixed_scale
from .cases import caption
from .layout import axes_for, legend

BOX_FROM = 5
"""Fewest values a box is drawn for: quartiles of fewer values are not quartiles (points only then)."""


def draw_boxes(ax: Axes, data, positions, colours, width: float = 0.7) -> list:
    """Draw one box per list of values (quartiles, whiskers min to max) with every value as a point.

    Lists of fewer than :data:`BOX_FROM` values get their points and a median tick, no box. The
    points (spread sideways a little so equal values stay apart) are always drawn. Returns one
    legend handle per list (a patch of its colour).
    """
    from matplotlib.patches import Patch

    spread = np.random.default_rng(0)
    boxed = [k for k, values in enumerate(data) if len(values) >= BOX_FROM]
    if boxed:
        boxes = ax.boxplot(
            [data[k] for k in boxed],
            positions=[positions[k] for k in boxed],
            whis=(0, 100),
            widths=width,
            patch_artist=True,
            medianprops={"color": "k"},
            manage_ticks=False,
        )
        for box, k in zip(boxes["boxes"], boxed, strict=True):
            box.set_facecolor(colours[k])
            box.set_alpha(0.6)
    for k, (values, position, colour) in enumerate(zip(data, positions, colours, strict=True)):
        values = np.asarray(values, dtype=float)
        offsets = spread.uniform(-0.15, 0.15, values.size) * width
        ax.plot(
            position + offsets, values, "o", color="k" if k in boxed else colour, markersize=3.5, zorder=3
        )
        if k not in boxed and values.size:
            ax.plot(
                [position - 0.3 * width, position + 0.3 * width], [np.median(values)] * 2, "-", color=colour
            )
    ax.set_ylim(bottom=0)  # mu from 0: a few percent between samples must look like a few percent
    return [Patch(facecolor=colour, alpha=0.6) for colour in colours]


def box_words(data) -> str:
    """Say what the boxes of ``data`` are, for a title: quartiles, or points where too few values."""
    if all(len(values) >= BOX_FROM for values in data):
        return "boxes: quartiles, whiskers: min to max"
    if not any(len(values) >= BOX_FROM for values in data):
        return f"each value a point, line: median (fewer than {BOX_FROM} values: no boxes)"
    return f"boxes: quartiles, whiskers: min to max; points and median only below {BOX_FROM} values"


def plot_mu_boxes(comparison, ax: Axes | None = None, *, simulated: str = "simulated"):
    """Draw box plots of simulated and compared mu per sample (paper 000, figure 9); returns ``(fig, ax)``.

    The compared values are labelled by their origin (measured, reconstructed from reported
    statistics, synthetic) and "by construction" where they were built from this model.

    Boxes span the first to third quartile and the whiskers the minimum to maximum, as in the
    paper; every value is drawn as a point on its box.

    Parameters
    ----------
    comparison : Comparison
        From :func:`roughcontact.experiment.compare`.
    ax : matplotlib Axes, optional
        Axes to draw on.
    simulated : str
        The legend entry of the simulated values; say the scans' origin where it is known
        (``"simulated on synthetic scans"``).

    Returns
    -------
    (Figure, Axes)
    """
    fig, ax = axes_for(ax, figsize=(6.0, 4.0))
    data, positions, colours = [], [], []
    for k, sample in enumerate(comparison.samples):
        data += [sample.simulated, sample.measured]
        positions += [3 * k + 0.6, 3 * k + 1.4]
        colours += ["tab:blue", "tab:orange"]
    boxes = draw_boxes(ax, data, positions, colours)
    ax.set_xticks([3 * k + 1 for k in range(len(comparison.samples))])
    ax.set_xticklabels([f"{s.sample}\np = {s.p_value:.2g}" for s in comparison.samples])
    ax.set_ylabel("coefficient of friction μ")
    ax.legend(boxes[:2], [simulated, _compared_label(comparison)])
    built = "p values and r by construction; " if comparison.by_construction else ""
    ax.set_title(
        f"simulated vs {comparison.origin.word}, Pearson r = {comparison.pearson_r:.2f}\n"
        f"({built}{box_words(data)})",
        fontsize="medium",
    )
    return fig, ax


def _compared_label(comparison) -> str:
    """Return the legend entry of the compared values: their origin, and whether built from this model."""
    origin = comparison.origin
    return f"{origin.words} (built from this model)" if comparison.by_construction else origin.words


def plot_mu_means(comparison, ax: Axes | None = None, *, simulated: str = "simulated"):
    """Draw the mean mu per sample with one standard deviation, simulated beside compared (figure 8).

    Takes and returns what :func:`plot_mu_boxes` does: a ``Comparison``, optional axes and the
    legend entry of the simulated values; ``(fig, ax)``.
    """
    fig, ax = axes_for(ax, figsize=(6.0, 4.0))
    x = np.arange(len(comparison.samples))
    sides = (
        (-0.18, "simulated", simulated, "tab:blue"),
        (0.18, "measured", _compared_label(comparison), "tab:orange"),
    )
    for offset, kind, label, colour in sides:
        means = [getattr(s, f"{kind}_mean") for s in comparison.samples]
        spread = [getattr(s, f"{kind}_std") for s in comparison.samples]
        ax.bar(x + offset, means, width=0.36, yerr=spread, capsize=4, color=colour, alpha=0.7, label=label)
    ax.set_xticks(x)
    ax.set_xticklabels([s.sample for s in comparison.samples])
    ax.set_ylabel("mean coefficient of friction μ (± 1 s.d.)")
    legend(ax)
    return fig, ax


def plot_friction_vs_load(sweep, ax: Axes | None = None, *, crossover: float | None = None):
    """Draw friction and its adhesive and mechanical parts against the load, log-log.

    Parameters
    ----------
    sweep : FrictionSweep
        From :meth:`roughcontact.winkler_lj.WinklerLJModel.sweep`.
    ax : matplotlib Axes, optional
        Axes to draw on.
    crossover : float, optional
        Load where mechanical friction overtakes adhesive friction [N], marked by a line.

    Returns
    -------
    (Figure, Axes)
    """
    fig, ax = axes_for(ax)
    scale, unit = prefixed_scale(float(np.max(sweep.normal_force)), "N")
    for name, style in (("friction", "k-"), ("adhesive_friction", "b--"), ("mechanical_friction", "r-.")):
        values = np.asarray(getattr(sweep, name))
        shown = values > 0
        label = name.replace("_", " ")
        ax.loglog(sweep.normal_force[shown] / scale, values[shown] / scale, style, label=label)
    if crossover is not None:
        ax.axvline(
            crossover / scale, color="grey", lw=0.8, label=f"crossover {format_si(crossover, 'N', digits=3)}"
        )
    ax.set_xlabel(f"normal load ({unit})")
    ax.set_ylabel(f"friction force ({unit})")
    legend(ax)
    return fig, ax


@caption(
    "Left: coefficient of friction μ = F/N against the normal load. Right: its adhesive (solid) and "
    "mechanical (dashed) parts, with the mean crossover load dotted; one colour per sample (paper 000). "
    "Where a sample has several scans per load the lines are their means and the shaded bands their "
    "range (smallest to largest scan)."
)
def friction_vs_load_figure(cases):
    """Draw mu and the adhesive and mechanical friction against the load, a colour per sample.

    Means over the replicates (scans) at each load, with their range shaded where there are
    several; None for fewer than two loads.
    """
    from .layout import new_figure

    loads = loads_of(cases)
    if len(loads) < 2:
        return None
    scale, unit = (1e-3, "mN") if loads[-1] >= 1e-3 else (1e-6, "µN") if loads[-1] >= 1e-6 else (1e-9, "nN")
    figure, axes = new_figure(1, 2, width=5.5)
    mu_axis, force_axis = axes[0]
    groups = grouped(cases)
    scans = max(len(at_load(group, load)) for group in groups.values() for load in loads_of(group))
    colours = [f"C{k % 10}" for k in range(len(groups))]
    for colour, (sample, group) in zip(colours, groups.items(), strict=True):
        label = sample or None
        load, mu, low, high = _mean_and_range(group, "mu")
        mu_axis.semilogx(load / scale, mu, "o-", color=colour, label=label)
        if scans > 1:
            mu_axis.fill_between(load / scale, low, high, color=colour, alpha=0.2, lw=0)
        for name, style in (("adhesive_friction", "-"), ("mechanical_friction", "--")):
            load, force, low, high = _mean_and_range(group, name)
            shown = force > 0
            force_axis.loglog(load[shown] / scale, force[shown] / scale, style, color=colour)
            if scans > 1:
                kept = low > 0
                force_axis.fill_between(
                    load[kept] / scale, low[kept] / scale, high[kept] / scale, color=colour, alpha=0.15, lw=0
                )
        crossovers = [r.scalars.get("crossover_load") for r in group]
        crossovers = [float(c) for c in crossovers if c is not None]
        if crossovers:
            force_axis.axvline(np.mean(crossovers) / scale, color=colour, lw=0.8, ls=":")
    mu_axis.set_xlabel(f"normal load ({unit})")
    mu_axis.set_ylabel("coefficient of friction μ")
    kind = surface_origin(cases)
    scans_words = f"{scans} {kind} scans" if kind else f"{scans} scans"
    mu_axis.set_title("μ against load" + (f" (mean and range of {scans_words})" if scans > 1 else ""))
    force_axis.set_xlabel(f"normal load ({unit})")
    force_axis.set_ylabel(f"friction force ({unit})")
    force_axis.set_title("adhesive (solid) and mechanical (dashed) friction")
    if any(groups):
        legend(mu_axis, fontsize="small")
    return figure


def _simulated_words(cases) -> str:
    """Return the legend entry of values simulated on ``cases``' scans: ``simulated on synthetic scans``.

    A generated stand-in is never read as a measured scan; cases that do not say their surfaces'
    origin (stored before it was recorded) read ``simulated``.
    """
    kind = surface_origin(cases)
    return f"simulated on {kind} scans" if kind else "simulated"


def _mean_and_range(cases, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Return the distinct loads and the mean, smallest and largest of scalar ``name`` at each."""
    loads = loads_of(cases)
    values = [
        [float(v) for c in at_load(cases, load) if (v := c.scalars.get(name)) is not None] for load in loads
    ]
    stats = np.array([(np.mean(v), np.min(v), np.max(v)) if v else (np.nan,) * 3 for v in values])
    return np.asarray(loads), stats[:, 0], stats[:, 1], stats[:, 2]


def _simulated_only(cases) -> dict[str, list[float]] | None:
    """Return the simulated mu per sample and setting, for the figures without measured data.

    Within a sample, cases that differ in more than their replicate (a swept gap model, say) are
    separate groups named by what differs (``Ra 1.45 nm, gap model bem``): two settings are two
    boxes, not one box of two values. None for several loads (``friction_vs_load`` shows those).
    """
    if len(loads_of(cases)) > 1:
        return None
    values: dict[str, list[float]] = {}
    for sample, group in grouped(cases).items():
        settings = [setting_of(case) for case in group]
        differ = [
            key
            for key in settings[0]
            if key not in ("sample", "replicate") and len({repr(s.get(key)) for s in settings}) > 1
        ]
        for case, setting in zip(group, settings, strict=True):
            words = [f"{axis_words(key)} {setting.get(key)}" for key in differ]
            name = ", ".join([sample, *words] if sample else words) or "all cases"
            values.setdefault(name, []).append(float(case.scalars["mu"]))
    return values


@caption(
    "Coefficient of friction per sample: simulated (and, with [analysis.compare], the compared values, "
    "labelled measured, reconstructed or synthetic as their file says) as boxes of the quartiles with "
    "whiskers from min to max, every scan as a point (paper 000 Fig. 9)."
)
def mu_boxes_figure(cases, comparison=None):
    """Draw mu per sample as boxes: simulated beside measured with a ``comparison``, else simulated only.

    ``comparison`` is a :class:`~roughcontact.experiment.compare.Comparison` of these cases with
    measured values; without one, None where the cases span several loads.
    """
    from .layout import new_figure

    figure, axes = new_figure(1, 1, width=6.0)
    ax = axes[0][0]
    if comparison is not None:
        plot_mu_boxes(comparison, ax=ax, simulated=_simulated_words(cases))
        return figure
    simulated = _simulated_only(cases)
    if simulated is None:
        return None
    positions = list(range(1, len(simulated) + 1))
    draw_boxes(ax, list(simulated.values()), positions, ["tab:blue"] * len(simulated), width=0.6)
    ax.set_xticks(positions)
    ax.set_xticklabels(list(simulated))
    ax.set_ylabel("coefficient of friction μ")
    ax.set_title(
        f"μ per sample, {_simulated_words(cases)}\n({box_words(list(simulated.values()))})", fontsize="medium"
    )
    return figure


@caption(
    "Mean coefficient of friction per sample with one standard deviation, simulated beside the compared "
    "values where given, labelled by their origin (paper 000 Fig. 8)."
)
def mu_means_figure(cases, comparison=None):
    """Draw the mean mu per sample with one standard deviation (see :func:`mu_boxes_figure`)."""
    from .layout import new_figure

    figure, axes = new_figure(1, 1, width=6.0)
    ax = axes[0][0]
    if comparison is not None:
        plot_mu_means(comparison, ax=ax, simulated=_simulated_words(cases))
        built = " (by construction)" if comparison.by_construction else ""
        ax.set_title(f"mean μ per sample, Pearson r of the means = {comparison.pearson_r:.2f}{built}")
        return figure
    simulated = _simulated_only(cases)
    if simulated is None:
        return None
    x = np.arange(len(simulated))
    means = [float(np.mean(v)) for v in simulated.values()]
    single = all(len(v) == 1 for v in simulated.values())  # one value each: a spread of nothing
    spread = None if single else [float(np.std(v, ddof=1)) if len(v) > 1 else 0.0 for v in simulated.values()]
    ax.bar(
        x,
        means,
        width=0.5,
        yerr=spread,
        capsize=4,
        color="tab:blue",
        alpha=0.7,
        label=_simulated_words(cases),
    )
    ax.set_xticks(x)
    ax.set_xticklabels(list(simulated))
    ax.set_ylabel(
        "coefficient of friction μ (one case each)" if single else "mean coefficient of friction μ (± 1 s.d.)"
    )
    legend(ax)
    return figure
