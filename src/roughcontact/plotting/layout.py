"""Figures and axes for every plot: a new figure, or the caller's axes (nothing touches pyplot's state)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..units import prefixed_scale


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


@dataclass(frozen=True)
class ColourScale:
    """The ends of a colour bar [SI] and what the reader is told about them.

    Attributes
    ----------
    low, high : float
        Values at the two ends of the colour map (SI).
    words : str
        What the ends are, for the colour bar's label ("" when they are the data's own range).
    extend : str
        Matplotlib's ``extend`` of the colour bar: the ends that values beyond the scale reach.
    """

    low: float
    high: float
    words: str = ""
    extend: str = "neither"

    def prefixed(self, unit: str) -> tuple[float, str]:
        """Return (SI value of one shown unit, its label): the prefix for the larger end of the scale."""
        return prefixed_scale(max(abs(self.low), abs(self.high)) or 1.0, unit)


EMPTY = "0.88"
"""Colour of the points of a map where there is nothing (no contact): light grey, off every colour map."""


def empty_grey(cmap: str):
    """Return the colour map ``cmap`` with masked values drawn :data:`EMPTY` grey."""
    import matplotlib

    return matplotlib.colormaps[cmap].with_extremes(bad=EMPTY)


def shared_colorbar(
    image, axes, label: str, unit: str, scale: ColourScale, *, shrink: float = 1.0, location: str = "right"
) -> None:
    """Draw one colour bar for ``axes`` drawn with ``scale``: label, prefixed unit, what the ends clip.

    ``shrink`` scales the bar's length (:meth:`matplotlib.figure.Figure.colorbar`); ``location``
    "bottom" lays it under maps wider than tall, where a bar beside them would be short and its
    label longer than the bar.
    """
    shown = scale.prefixed(unit)[1]
    text = f"{label} ({shown})" if shown else label
    text += f"\n{scale.words}" if scale.words else ""
    image.figure.colorbar(image, ax=axes, extend=scale.extend, label=text, shrink=shrink, location=location)


def clipped_limits(
    values: np.ndarray, percentiles: tuple[float, float] = CLIP_PERCENTILES
) -> tuple[float, float]:
    """Return the colour limits: the ``percentiles`` of the finite ``values`` (NaN ignored)."""
    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    if finite.size == 0:
        return 0.0, 1.0
    low, high = (float(v) for v in np.percentile(finite, percentiles))
    if high > low:
        return low, high
    half = 0.5 * abs(low) or 0.5
    return low - half, low + half


def colour_scale(
    *fields, percentiles: tuple[float, float] = CLIP_PERCENTILES, from_zero: bool = False
) -> ColourScale:
    """Return one colour scale for every field given (values pooled), clipped so no spike sets it.

    Parameters
    ----------
    *fields : array_like
        The fields of one figure's panels (NaN ignored).
    percentiles : (float, float)
        Percentiles at the two ends ((0, 100): the full range).
    from_zero : bool
        For a field that is zero or positive and zero over much of the map (contact pressure,
        the gap, stress under a few contacts): the scale starts at 0 and ends at the upper
        percentile of the nonzero values, so the contacts, not the empty area, set it.
    """
    values = np.concatenate([np.ravel(np.asarray(f, dtype=float)) for f in fields])
    if from_zero:
        positive = values[values > 0]
        high = clipped_limits(positive, (0, percentiles[1]))[1] if positive.size else 1.0
        clipped = percentiles[1] < 100 and positive.size and positive.max() > high
        words = f"top: {percentiles[1]:g}th pct. of nonzero" if clipped else ""
        return ColourScale(0.0, high, words, "max" if clipped else "neither")
    low, high = clipped_limits(values, percentiles)
    if tuple(percentiles) == (0, 100):
        return ColourScale(low, high)
    return ColourScale(low, high, clip_words(percentiles), "both")


def clip_words(percentiles: tuple[float, float]) -> str:
    """Say on a colour bar what its ends are (``"clipped to 0.5-99.5 pct."``: short, a bar is narrow)."""
    low, high = percentiles
    return "full range" if (low, high) == (0, 100) else f"clipped to {low:g}-{high:g} pct."


def legend(
    ax: Axes,
    *,
    fontsize: str | float | None = None,
    loc: str = "best",
    ncol: int = 1,
    bbox_to_anchor: tuple[float, float] | None = None,
    extra: tuple = (),
) -> None:
    """Add a legend of what the axes show: labelled lines with at least one drawable point.

    A line whose points are all NaN (a quantity undefined for every case), or all non-positive
    on a logarithmic axis, draws nothing and gets no entry; with no entry left, no legend.
    ``extra``: (handle, label) pairs appended as given (what a line style means, say). The other
    keywords are :meth:`matplotlib.axes.Axes.legend`'s.
    """
    kept = [(h, label) for h, label in zip(*ax.get_legend_handles_labels(), strict=True) if _drawn(ax, h)]
    kept += list(extra)
    if kept:
        ax.legend(
            *zip(*kept, strict=True), fontsize=fontsize, loc=loc, ncol=ncol, bbox_to_anchor=bbox_to_anchor
        )


def _drawn(ax: Axes, handle) -> bool:
    if not hasattr(handle, "get_xydata"):
        return True  # patches, collections: drawn as given
    x, y = np.asarray(handle.get_xdata(), dtype=float), np.asarray(handle.get_ydata(), dtype=float)
    shown = np.isfinite(x) & np.isfinite(y)
    if ax.get_xscale() == "log":
        shown &= x > 0
    if ax.get_yscale() == "log":
        shown &= y > 0
    return bool(shown.any())
