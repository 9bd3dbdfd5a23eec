"""Figure helpers for studies: grids of axes and field maps drawn from stored ``xarray`` fields.

The study kinds (:mod:`roughcontact.study.kinds`) draw their figures from stored case records,
not from solver result objects; these helpers take ``xarray.DataArray`` fields on ``x``/``y``
coordinates [m] and choose readable units.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from ..units import prefixed_scale
from .layout import ColourScale, colour_scale, empty_grey, shared_colorbar


def map_length_scale(field) -> tuple[float, str]:
    """Return (SI value of one shown length unit, its label) for the x, y axes of a stored 2D field."""
    x, y = np.asarray(field["x"]), np.asarray(field["y"])
    return prefixed_scale(max(np.ptp(x), np.ptp(y)) or 1e-9, "m")


def map_axes(
    ax: Axes,
    field,
    label: str,
    unit: str,
    *,
    cmap: str = "viridis",
    scale: ColourScale | None = None,
    colorbar: bool = True,
    empty: float | None = None,
):
    """Draw a 2D field (``xarray.DataArray`` on x, y [m]) as a map with a colour bar in readable units.

    ``unit`` is the field's unprefixed SI unit (``"Pa"``, ``"m"``, ``"N/m"``, ``""``); the colour bar
    shows it with the prefix :func:`roughcontact.units.prefixed_scale` chooses for the larger end.
    ``scale`` gives the ends (one scale for every panel of a figure); without it the field's own
    0.5-99.5 percentiles (:func:`~roughcontact.plotting.layout.colour_scale`). The colour bar says
    when its ends clip the data. With ``colorbar=False`` none is drawn: the caller draws one for
    several panels of the same scale (:func:`~roughcontact.plotting.layout.shared_colorbar`).
    ``empty``: a value that means "nothing here" (0 for a contact pressure), drawn light grey, so a
    sparse field's few points stand out instead of sinking into the colour map's dark end.
    Returns the drawn mesh.
    """
    x, y = np.asarray(field["x"]), np.asarray(field["y"])
    values = np.asarray(field, dtype=float).T
    scale = scale or colour_scale(values)
    if empty is not None:
        values = np.ma.masked_equal(values, empty)
        cmap = empty_grey(cmap)
    factor, _ = scale.prefixed(unit)
    size_scale, size_unit = map_length_scale(field)
    image = ax.pcolormesh(
        x / size_scale,
        y / size_scale,
        values / factor,
        cmap=cmap,
        shading="auto",
        rasterized=True,
        vmin=scale.low / factor,
        vmax=scale.high / factor,
    )
    ax.set_aspect("equal")
    ax.set_xlabel(f"x ({size_unit})")
    ax.set_ylabel(f"y ({size_unit})")
    if colorbar:
        shared_colorbar(image, [ax], label, unit, scale)
    return image


def profile_axes(ax: Axes, fields: list, labels: list[str | None], name: str, unit: str):
    """Draw 1D fields (``xarray.DataArray`` on x [m]) as curves on one axes, in readable units.

    For line contacts (a profile solved in plane strain): pressure or gap against x, one curve per
    case, the y axis from 0 in the prefixed unit of the largest value.
    """
    x_scale, x_unit = prefixed_scale(max(float(np.ptp(np.asarray(f["x"]))) for f in fields) or 1e-9, "m")
    largest = max(float(np.nanmax(np.abs(np.asarray(f)))) for f in fields) or 1.0
    y_scale, y_unit = prefixed_scale(largest, unit)
    for field, label in zip(fields, labels, strict=True):
        ax.plot(np.asarray(field["x"]) / x_scale, np.asarray(field) / y_scale, lw=0.8, label=label)
    ax.set_xlabel(f"x ({x_unit})")
    ax.set_ylabel(f"{name} ({y_unit})")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
