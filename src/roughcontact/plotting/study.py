"""Figure helpers for studies: grids of axes and field maps drawn from stored ``xarray`` fields.

The study kinds (:mod:`roughcontact.study.kinds`) draw their figures from stored case records,
not from solver result objects; these helpers take ``xarray.DataArray`` fields on ``x``/``y``
coordinates [m] and choose readable units.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from ..units import prefixed_scale


def map_axes(
    ax: Axes, field, label: str, unit: str, *, cmap: str = "viridis", symmetric: bool = False
) -> None:
    """Draw a 2D field (``xarray.DataArray`` on x, y [m]) as a map with a colour bar in readable units.

    ``unit`` is the field's unprefixed SI unit (``"Pa"``, ``"m"``, ``"N/m"``, ``""``); the colour bar
    shows it with the prefix :func:`roughcontact.units.prefixed_scale` chooses for the largest value.
    """
    x, y = np.asarray(field["x"]), np.asarray(field["y"])
    values = np.asarray(field).T
    largest = float(np.nanmax(np.abs(values))) or 1.0
    scale, shown = prefixed_scale(largest, unit)
    size_scale, size_unit = prefixed_scale(max(x.max() - x.min(), y.max() - y.min()) or 1e-9, "m")
    limits = {"vmin": -largest / scale, "vmax": largest / scale} if symmetric else {}
    image = ax.pcolormesh(
        x / size_scale, y / size_scale, values / scale, cmap=cmap, shading="auto", rasterized=True, **limits
    )
    ax.set_aspect("equal")
    ax.set_xlabel(f"x ({size_unit})")
    ax.set_ylabel(f"y ({size_unit})")
    ax.figure.colorbar(image, ax=ax, label=f"{label} ({shown})" if shown else label)
