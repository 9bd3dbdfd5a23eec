"""Helpers the study kinds share: choosing, grouping and ordering stored case records."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..kind import CaseRecord


def evenly_chosen(items: Sequence, count: int) -> list:
    """At most ``count`` items, evenly spread over ``items`` (first and last included)."""
    if len(items) <= count:
        return list(items)
    picks = np.unique(np.linspace(0, len(items) - 1, count).round().astype(int))
    return [items[i] for i in picks]


def grouped(records: Sequence[CaseRecord], key: str = "sample") -> dict[str, list[CaseRecord]]:
    """Return the records grouped by a parameter (default the sample label), in order of first appearance."""
    groups: dict[str, list[CaseRecord]] = {}
    for record in records:
        groups.setdefault(str(record.parameters.get(key, "")), []).append(record)
    return groups


def grid(topography) -> tuple[tuple[str, ...], dict]:
    """Return the dimension names (``("x",)`` or ``("x", "y")``) and the xarray coordinates [m] of a grid."""
    axes = ("x", "y")[: topography.dim]
    coordinates = {a: (a, c, {"units": "m"}) for a, c in zip(axes, topography.coordinates(), strict=True)}
    return axes, coordinates


def scalar_series(records: Sequence[CaseRecord], *names: str) -> tuple[np.ndarray, ...]:
    """Arrays of the scalars ``names`` over ``records``, ordered by the first of them."""
    values = np.array([[float(r.scalars[name]) for name in names] for r in records], dtype=float)
    values = values[np.argsort(values[:, 0], kind="stable")]
    return tuple(values.T)


def panel_per_case(
    records: Sequence[CaseRecord], draw, *, limit: int = 4, width: float = 5.5, height: float = 4.4
):
    """Return a figure of one panel per stored case (at most ``limit``), or None without any.

    ``draw(record, data, ax)`` draws one case from its record and its loaded fields.
    """
    from ...plotting.layout import new_figure

    chosen = [r for r in records if r.fields_path is not None][:limit]
    if not chosen:
        return None
    figure, axes = new_figure(1, len(chosen), width=width, height=height)
    for ax, record in zip(axes[0], chosen, strict=True):
        draw(record, record.dataset(), ax)
    return figure


def box_around(mask: np.ndarray, margin: int) -> tuple[slice, slice] | None:
    """Return the rows and columns of the smallest box around every True of ``mask``, ``margin`` wider.

    Clipped to the grid; None when ``mask`` holds no True. Crops stored or drawn fields to where
    something happens (a contact, the springs that carry friction).
    """
    rows, columns = np.nonzero(mask)
    if rows.size == 0:
        return None
    nx, ny = mask.shape
    return (
        slice(max(int(rows.min()) - margin, 0), min(int(rows.max()) + margin + 1, nx)),
        slice(max(int(columns.min()) - margin, 0), min(int(columns.max()) + margin + 1, ny)),
    )
