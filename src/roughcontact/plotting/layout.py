"""Figures and axes for every plot: a new figure, or the caller's axes (nothing touches pyplot's state)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure


def axes_for(ax: Axes | None, figsize=(5.0, 4.0)) -> tuple[Figure, Axes]:
    """Return ``ax`` and its figure, or a new figure of ``figsize`` inches with one axes."""
    if ax is not None:
        return ax.figure, ax
    figure = Figure(figsize=figsize, layout="constrained")
    return figure, figure.add_subplot()


def new_figure(rows: int, columns: int, *, width: float = 5.0, height: float = 4.0) -> tuple[Figure, list]:
    """Return a figure and its axes as a list of rows (each a list of axes)."""
    figure = Figure(figsize=(width * columns, height * rows), layout="constrained")
    axes = figure.subplots(rows, columns, squeeze=False)
    return figure, [list(row) for row in axes]


CLIP_PERCENTILES = (0.5, 99.5)
"""Percentiles at the ends of the colour scale of height and pressure maps (one spike sets nothing)."""


def clipped_limits(
    values: np.ndarray, percentiles: tuple[float, float] = CLIP_PERCENTILES
) -> tuple[float, float]:
    """Return the colour limits: the ``percentiles`` of the finite ``values`` (NaN ignored)."""
    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    if finite.size == 0:
        return 0.0, 1.0
    low, high = (float(v) for v in np.percentile(finite, percentiles))
    return (low, high) if high > low else (low - 0.5, low + 0.5)


def clip_words(percentiles: tuple[float, float]) -> str:
    """Say on a colour bar what its ends are (``"colours clipped to 0.5-99.5 %"``)."""
    low, high = percentiles
    return "full range" if (low, high) == (0, 100) else f"colours clipped to {low:g}-{high:g} percentile"
