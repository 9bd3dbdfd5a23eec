"""Figures of normal contact results: pressure and gap maps, load-approach curves, von Mises maps."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..units import prefixed_scale
from .layout import axes_for, legend


def _map(ax: Axes, result, values: np.ndarray, label: str, cmap: str):
    fig = ax.figure
    topography = result.topography
    size_scale, size_label = prefixed_scale(max(topography.size), "m")
    x, y = (c / size_scale for c in topography.coordinates())
    image = ax.pcolormesh(x, y, values.T, cmap=cmap, shading="auto", rasterized=True)
    ax.set_aspect("equal")
    ax.set_xlabel(f"x ({size_label})")
    ax.set_ylabel(f"y ({size_label})")
    fig.colorbar(image, ax=ax, label=label)


def plot_pressure(result, ax: Axes | None = None, *, cmap: str = "magma"):
    """Draw the contact pressure map of a 2D NormalContactResult; returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    scale, unit = prefixed_scale(float(result.pressure.max()) or 1.0, "Pa")
    _map(ax, result, result.pressure / scale, f"pressure ({unit})", cmap)
    ax.set_title(f"contact pressure, {100 * result.contact_fraction:.2g} % in contact")
    return fig, ax


def plot_gap(result, ax: Axes | None = None, *, cmap: str = "viridis"):
    """Draw the gap map of a 2D NormalContactResult (contact where the gap is zero); returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    scale, unit = prefixed_scale(float(np.max(result.gap)) or 1e-9, "m")
    _map(ax, result, result.gap / scale, f"gap ({unit})", cmap)
    ax.set_title(f"gap, mean {result.mean_gap / scale:.3g} {unit}")
    return fig, ax


def plot_load_approach(curve: dict, ax: Axes | None = None, *, label: str | None = None):
    """Draw force against approach from ``LoadUnloadResult.curve()`` (or any dict with those keys)."""
    fig, ax = axes_for(ax)
    approach, force = np.asarray(curve["approach"]), np.asarray(curve["force"])
    a_scale, a_unit = prefixed_scale(float(np.max(np.abs(approach))) or 1e-9, "m")
    f_scale, f_unit = prefixed_scale(float(np.max(np.abs(force))) or 1.0, "N")
    branches = np.asarray(curve.get("branch", ["loading"] * len(force)))
    for branch, style in (("loading", "-o"), ("unloading", "--s")):
        keep = branches == branch
        if keep.any():
            name = branch if label is None else f"{label}, {branch}"
            ax.plot(approach[keep] / a_scale, force[keep] / f_scale, style, ms=3, label=name)
    ax.set_xlabel(f"approach ({a_unit})")
    ax.set_ylabel(f"force ({f_unit})")
    legend(ax)
    ax.grid(True, alpha=0.3)
    return fig, ax


def plot_contact_area(curve: dict, ax: Axes | None = None):
    """Draw real contact area against force from a load curve dict; returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    ax.plot(np.asarray(curve["force"]), np.asarray(curve["contact_area"]), "-o", ms=3)
    ax.set_xlabel("force (N)")
    ax.set_ylabel("real contact area (m²)")
    ax.grid(True, alpha=0.3)
    return fig, ax


def plot_von_mises(stress, depth_index: int, ax: Axes | None = None, *, cmap: str = "inferno"):
    """Draw the von Mises stress on the plane ``stress.depths[depth_index]``; returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    vm = stress.von_mises()[depth_index]
    scale, unit = prefixed_scale(float(vm.max()) or 1.0, "Pa")
    size_scale, size_label = prefixed_scale(max(stress.size), "m")
    nx, ny = vm.shape
    x = np.arange(nx) * stress.size[0] / nx / size_scale
    y = np.arange(ny) * stress.size[1] / ny / size_scale
    image = ax.pcolormesh(x, y, vm.T / scale, cmap=cmap, shading="auto", rasterized=True)
    ax.set_aspect("equal")
    ax.set_xlabel(f"x ({size_label})")
    ax.set_ylabel(f"y ({size_label})")
    fig.colorbar(image, ax=ax, label=f"von Mises ({unit})")
    d_scale, d_unit = prefixed_scale(float(stress.depths[depth_index]) or 1e-9, "m")
    ax.set_title(f"von Mises at z = {stress.depths[depth_index] / d_scale:.3g} {d_unit}")
    return fig, ax


def plot_contact_overview(result) -> Figure:
    """Return a two-panel figure: pressure and gap maps of a NormalContactResult."""
    fig = Figure(figsize=(10.0, 4.2), layout="constrained")
    left, right = fig.subplots(1, 2)
    plot_pressure(result, left)
    plot_gap(result, right)
    return fig
