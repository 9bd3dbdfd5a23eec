"""Figures and axes for every plot: a new figure, or the caller's axes (nothing touches pyplot's state)."""

from __future__ import annotations

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
