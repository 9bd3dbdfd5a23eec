"""Figures of a topography: height map (or profile) and its power spectral density.

Uses the object-oriented matplotlib API (:class:`matplotlib.figure.Figure`), never pyplot,
so it works on machines without a display and leaves no global state behind.
"""

from __future__ import annotations

import matplotlib
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..cases import evenly_chosen
from ..topography import Topography
from ..topography.process import find_specks
from ..topography.statistics import psd_1d, psd_radial
from ..units import format_si, prefixed_scale
from .cases import caption
from .layout import CLIP_PERCENTILES, axes_for, colour_scale, shared_colorbar


def _title(topography: Topography) -> str:
    return str(topography.info.get("name") or topography.info.get("source") or "topography")


def plot_heights(
    topography: Topography,
    ax: Axes | None = None,
    *,
    cmap: str = "viridis",
    undefined: np.ndarray | None = None,
    percentiles: tuple[float, float] = CLIP_PERCENTILES,
):
    """Draw the height map of a 2D topography (or the profile of a 1D one).

    The colour scale spans the ``percentiles`` of the heights (0.5 and 99.5 by default, said on
    the colour bar, the ends marked as extended), so that one spike or dust particle does not
    turn the rest of the map into one colour.

    Parameters
    ----------
    topography : Topography
        Surface to draw; heights are shown about their mean.
    ax : matplotlib.axes.Axes, optional
        Axes to draw into; a new figure is made when omitted.
    cmap : str
        Colour map of the height map.
    undefined : ndarray of bool, optional
        Points the instrument did not case: drawn grey and left out of the colour scale, as are
        the measured points in specks amid them
        (:func:`roughcontact.topography.process.find_specks`).
    percentiles : (float, float)
        Percentiles of the heights at the two ends of the colour scale ((0, 100): the full range).

    Returns
    -------
    fig, ax
        The figure and the axes drawn into.
    """
    fig, ax = axes_for(ax)
    heights = np.array(topography.heights, dtype=float)
    specks = None
    if undefined is not None:
        heights[undefined] = np.nan
        specks = find_specks(undefined)
    heights -= np.nanmean(heights if specks is None else np.where(specks, np.nan, heights))
    surface = heights if specks is None else np.where(specks, np.nan, heights)  # what sets the scale
    size_scale, size_label = prefixed_scale(max(topography.size), "m")
    scale = colour_scale(surface, percentiles=percentiles)
    height_scale, height_label = scale.prefixed("m")
    coords = [c / size_scale for c in topography.coordinates()]
    if topography.dim == 1:
        ax.plot(coords[0], heights / height_scale, lw=0.8)
        ax.set_ylabel(f"height ({height_label})")
    else:
        colours = matplotlib.colormaps[cmap].with_extremes(bad="0.6")
        image = ax.pcolormesh(
            coords[0],
            coords[1],
            heights.T / height_scale,
            cmap=colours,
            shading="auto",
            rasterized=True,
            vmin=scale.low / height_scale,
            vmax=scale.high / height_scale,
        )
        ax.set_aspect("equal")
        ax.set_ylabel(f"y ({size_label})")
        shared_colorbar(image, ax, "height", "m", scale)
    ax.set_xlabel(f"x ({size_label})")
    title = _title(topography)
    if undefined is not None and undefined.any():
        title += f"\n{100 * np.count_nonzero(undefined) / undefined.size:.3g} % undefined (grey)"
        if specks.any():
            title += f"\n{np.count_nonzero(specks)} specks amid them off the colour scale"
    ax.set_title(title)
    return fig, ax


def plot_psd(topography: Topography, ax: Axes | None = None):
    """Draw the power spectral density on log-log axes (radially averaged for a map).

    Parameters
    ----------
    topography : Topography
        Surface whose PSD is drawn.
    ax : matplotlib.axes.Axes, optional
        Axes to draw into; a new figure is made when omitted.

    Returns
    -------
    fig, ax
        The figure and the axes drawn into.
    """
    fig, ax = axes_for(ax)
    if topography.dim == 1:
        wavevector, psd = psd_1d(topography)
        ax.set_ylabel("PSD C¹ᴰ (m³)")
    else:
        wavevector, psd = psd_radial(topography)
        ax.set_ylabel("PSD C²ᴰ (m⁴)")
    keep = (wavevector > 0) & (psd > 0)
    ax.loglog(wavevector[keep], psd[keep], lw=1.0)
    ax.set_xlabel("wavevector q (rad/m)")
    ax.grid(True, which="major", alpha=0.3)
    ax.set_title("power spectral density")
    return fig, ax


def plot_overview(topography: Topography, *, undefined: np.ndarray | None = None) -> Figure:
    """Return a two-panel figure: height map (or profile) and PSD, as ``roughcontact plot`` writes it.

    With ``undefined`` (points the instrument did not case) the second panel shows where they
    are instead of the PSD, which needs every point.
    """
    fig = Figure(figsize=(10.0, 4.2), layout="constrained")
    left, right = fig.subplots(1, 2)
    plot_heights(topography, left, undefined=undefined)
    if undefined is None or not undefined.any():
        plot_psd(topography, right)
        return fig
    size_scale, size_label = prefixed_scale(max(topography.size), "m")
    coords = [c / size_scale for c in topography.coordinates()]
    if topography.dim == 1:
        right.plot(coords[0], undefined.astype(float), drawstyle="steps-mid")
        right.set_ylabel("undefined (1) / measured (0)")
    else:
        right.pcolormesh(coords[0], coords[1], undefined.T, cmap="Greys", shading="auto", rasterized=True)
        right.set_aspect("equal")
        right.set_ylabel(f"y ({size_label})")
    right.set_xlabel(f"x ({size_label})")
    right.set_title(f"undefined points (black): {np.count_nonzero(undefined)} of {undefined.size}")
    return fig


@caption(
    "Height maps of up to four surfaces about their mean plane, as used (levelled files, generated "
    "surfaces as made); colours clipped to the 0.5-99.5 percentiles of each map, titles give Sq."
)
def heights_figure(cases):
    """Draw the height maps (or profiles) of up to four cases of the ``statistics`` model."""
    from .layout import legend, new_figure
    from .study import map_axes

    chosen = evenly_chosen(cases, 4)
    fields = [case.dataset() for case in chosen]
    if "y" not in fields[0].dims:
        figure, axes = new_figure(1, 1, width=7.0)
        for case, data in zip(chosen, fields, strict=True):
            axes[0][0].plot(data["x"] * 1e6, data["heights"] * 1e9, label=case.label)
        axes[0][0].set_xlabel("x (µm)")
        axes[0][0].set_ylabel("height (nm)")
        legend(axes[0][0])
        return figure
    figure, axes = new_figure(1, len(chosen), width=3.8, height=3.2)
    for column, (case, data) in enumerate(zip(chosen, fields, strict=True)):
        map_axes(axes[0][column], data["heights"], "height", "m")
        axes[0][column].set_title(f"{case.label}\nSq {format_si(case.scalars['Sq'], 'm', digits=3)}")
    return figure


@caption(
    "Power spectral density C(q) of every surface against the wavevector q = 2π/λ (radially averaged "
    "for maps; normalised so that it integrates to the mean square height, Jacobs et al. 2017)."
)
def psd_figure(cases):
    """Draw the PSD of every case of the ``statistics`` model on one plot."""
    from .layout import legend, new_figure

    figure, axes = new_figure(1, 1)
    ax = axes[0][0]
    for case in cases:
        data = case.dataset()
        ax.loglog(data["q"], data["psd"], label=case.label)
    ax.set_xlabel("wavevector q (rad/m)")
    ax.set_ylabel(f"PSD ({cases[0].dataset()['psd'].attrs['units']})")
    ax.set_title("power spectral density")
    if 1 < len(cases) <= 12:
        legend(ax, fontsize="small")
    return figure
