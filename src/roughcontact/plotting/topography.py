"""Figures of a topography: height map (or profile) and its power spectral density.

Uses the object-oriented matplotlib API (:class:`matplotlib.figure.Figure`), never pyplot,
so it works on machines without a display and leaves no global state behind.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..topography import Topography
from ..topography.statistics import psd_1d, psd_radial
from ..units import prefixed_scale
from .layout import axes_for


def _title(topography: Topography) -> str:
    return str(topography.info.get("name") or topography.info.get("source") or "topography")


def plot_heights(topography: Topography, ax: Axes | None = None, *, cmap: str = "viridis"):
    """Draw the height map of a 2D topography (or the profile of a 1D one).

    Parameters
    ----------
    topography : Topography
        Surface to draw; heights are shown about their mean.
    ax : matplotlib.axes.Axes, optional
        Axes to draw into; a new figure is made when omitted.
    cmap : str
        Colour map of the height map.

    Returns
    -------
    fig, ax
        The figure and the axes drawn into.
    """
    fig, ax = axes_for(ax)
    heights = topography.heights - topography.heights.mean()
    size_scale, size_label = prefixed_scale(max(topography.size), "m")
    height_scale, height_label = prefixed_scale(float(np.ptp(heights)) or 1e-9, "m")
    coords = [c / size_scale for c in topography.coordinates()]
    if topography.dim == 1:
        ax.plot(coords[0], heights / height_scale, lw=0.8)
        ax.set_ylabel(f"height ({height_label})")
    else:
        image = ax.pcolormesh(
            coords[0], coords[1], heights.T / height_scale, cmap=cmap, shading="auto", rasterized=True
        )
        ax.set_aspect("equal")
        ax.set_ylabel(f"y ({size_label})")
        fig.colorbar(image, ax=ax, label=f"height ({height_label})")
    ax.set_xlabel(f"x ({size_label})")
    ax.set_title(_title(topography))
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


def plot_overview(topography: Topography) -> Figure:
    """Return a two-panel figure: height map (or profile) and PSD, as ``roughcontact plot`` writes it."""
    fig = Figure(figsize=(10.0, 4.2), layout="constrained")
    left, right = fig.subplots(1, 2)
    plot_heights(topography, left)
    plot_psd(topography, right)
    return fig
