"""Figures of the Winkler-Lennard-Jones friction model and of its validation (paper 000, Figs. 8-9)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from ..units import prefixed_scale
from .layout import axes_for, legend


def draw_boxes(ax: Axes, data, positions, colours, width: float = 0.7) -> list:
    """Draw one box per list of values (quartiles, whiskers min to max) with every value as a point.

    The points (spread sideways a little so equal values stay apart) show what a box of few values
    cannot: one scan per sample draws a point on a flat box. Returns the boxes (legend handles).
    """
    boxes = ax.boxplot(
        data, positions=positions, whis=(0, 100), widths=width, patch_artist=True, medianprops={"color": "k"}
    )
    spread = np.random.default_rng(0)
    for box, values, position, colour in zip(boxes["boxes"], data, positions, colours, strict=True):
        box.set_facecolor(colour)
        box.set_alpha(0.6)
        values = np.asarray(values, dtype=float)
        offsets = spread.uniform(-0.15, 0.15, values.size) * width
        ax.plot(position + offsets, values, "o", color="k", markersize=3, alpha=0.7, zorder=3)
    return boxes["boxes"]


def plot_mu_boxes(comparison, ax: Axes | None = None):
    """Draw box plots of simulated and measured mu per sample (paper 000, Fig. 9); returns ``(fig, ax)``.

    Boxes span the first to third quartile and the whiskers the minimum to maximum, as in the
    paper; every value is drawn as a point on its box.

    Parameters
    ----------
    comparison : Comparison
        From :func:`roughcontact.experiment.compare`.
    ax : matplotlib Axes, optional
        Axes to draw on.

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
    ax.legend(boxes[:2], ["simulation", "measurement"])
    ax.set_title(f"simulated vs measured, Pearson r = {comparison.pearson_r:.2f}")
    return fig, ax


def plot_mu_means(comparison, ax: Axes | None = None):
    """Draw the mean mu per sample with one standard deviation, simulated beside measured (Fig. 8).

    Takes and returns what :func:`plot_mu_boxes` does: a ``Comparison`` and optional axes;
    ``(fig, ax)``.
    """
    fig, ax = axes_for(ax, figsize=(6.0, 4.0))
    x = np.arange(len(comparison.samples))
    for offset, kind, colour in ((-0.18, "simulated", "tab:blue"), (0.18, "measured", "tab:orange")):
        means = [getattr(s, f"{kind}_mean") for s in comparison.samples]
        spread = [getattr(s, f"{kind}_std") for s in comparison.samples]
        ax.bar(x + offset, means, width=0.36, yerr=spread, capsize=4, color=colour, alpha=0.7, label=kind)
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
        ax.axvline(crossover / scale, color="grey", lw=0.8, label=f"crossover {crossover / scale:.3g} {unit}")
    ax.set_xlabel(f"normal load ({unit})")
    ax.set_ylabel(f"friction force ({unit})")
    legend(ax)
    return fig, ax
