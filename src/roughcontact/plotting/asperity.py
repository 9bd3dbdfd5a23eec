"""Figures of the asperity models and the island compression (paper 002 Figs. 7-9)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..units import unit_factor
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
):
    """Draw load (uN) against omega / omega_c for each curve, loading solid, unloading dashed (Fig. 7).

    Parameters
    ----------
    curves : dict of str to dict
        Label -> curve dict with "branch", "approach" [m] and "force" [N] (``.curve()`` of a
        :class:`~roughcontact.asperity.StatisticalLoadUnload` or an island compression).
    critical_interference : float
        omega_c [m] for the abscissa.
    ax : Axes, optional
        Where to draw.
    measured : dict, optional
        A measured curve with "approach" [m] and "force" [N], drawn as markers.

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
    if measured is not None:
        x = np.asarray(measured["approach"]) / critical_interference
        ax.plot(x, np.asarray(measured["force"]) / _LOAD_SCALE, "k.", ms=3, label="measured")
    ax.set_xlabel("interference ω/ω_c")
    ax.set_ylabel(f"load ({_LOAD_UNIT})")
    legend(ax, fontsize="small")
    ax.grid(True, alpha=0.3)
    return fig, ax


def branch_points(branches: np.ndarray, branch: str) -> np.ndarray:
    """Return the indices of a branch's points; the unloading branch starts at the peak (the point before)."""
    points = np.flatnonzero(np.asarray(branches) == branch)
    if branch == "unloading" and points.size and points[0] > 0:
        points = np.concatenate([[points[0] - 1], points])
    return points


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
    """Draw von Mises maps of an island compression at the chosen steps (Figs. 8-9), one panel each.

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
