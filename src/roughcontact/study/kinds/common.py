"""Helpers the study kinds' run functions share: grid coordinates of a dataset, boxes around fields.

Choosing and grouping cases for figures and tables, and the box around a field
(:func:`~roughcontact.cases.box_around`, also used to crop stored fields), are in
:mod:`roughcontact.cases`.
"""

from __future__ import annotations

from ...cases import box_around

__all__ = ["box_around", "grid"]


def grid(topography) -> tuple[tuple[str, ...], dict]:
    """Return the dimension names (``("x",)`` or ``("x", "y")``) and the xarray coordinates [m] of a grid."""
    axes = ("x", "y")[: topography.dim]
    coordinates = {a: (a, c, {"units": "m"}) for a, c in zip(axes, topography.coordinates(), strict=True)}
    return axes, coordinates
