r"""Mesh convergence of the island compression (paper 002 figure 6), said in full.

Paper 002 refines its FEM mesh and shows the error of :math:`\omega_{max}` against the finest mesh
falling monotonically. Here a mesh study is cases of the same island on several grids (a generator
of ``modes = "wavevector"`` draws one surface at every resolution) and, at each grid, several
realisations of it (``replicate``): the same draws on every grid. For every quantity the paper's
figure and the statistical comparison use (``QUANTITIES``: the peak interference, the
interference where unloading returns to the reference load, the real contact area at the peak),
:func:`mesh_convergence` gives per grid

* the value: the mean over the realisations with its 95 % confidence interval (within
  ``BOUNDS``: none of these quantities is negative) and the standard deviation of one draw;
* the change per refinement: the mean's relative change from the next coarser grid, and each
  draw's (signed: a change of sign is a non-monotone sequence);

and over the three finest grids, for the mean and for each draw, the observed order of convergence
and the Richardson extrapolation (:func:`roughcontact.spread.convergence_order`) where the changes
shrink monotonically at an order of at least ``MIN_ORDER``, and otherwise why there is none:
``not monotone`` (the change changes sign), ``changes do not shrink`` (it keeps its sign and does
not shrink on refinement) or an order too low to be asymptotic. A refinement that changes a
quantity by much less than the realisations scatter it is converged enough for a comparison
between models, with or without an order; a quantity whose changes do not shrink is not converged,
whatever its scatter. The table and its sentences give both numbers so a reader can tell.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ..spread import Spread, convergence_order, spread
from ..units import format_si

QUANTITIES = {
    "peak_interference": "m",
    "interference_at_return_force": "m",
    "peak_contact_area": "m^2",
}
"""The scalars a mesh study of the island reports, with their SI units (those the cases have)."""

BOUNDS = (0.0, math.inf)
"""Range of the reported quantities: interferences past the reference load and areas are >= 0."""


def _parameters(case: Any) -> Mapping[str, Any]:
    return getattr(case, "parameters", None) or {}


def _relative_change(fine: float, coarse: float) -> float:
    """Signed relative change from ``coarse`` to ``fine`` (NaN where undefined)."""
    if not (math.isfinite(fine) and math.isfinite(coarse)) or coarse == 0:
        return math.nan
    return fine / coarse - 1.0


MIN_ORDER = 0.5
"""Smallest observed order taken as one: below it the three finest grids are not in the asymptotic range.

A discretisation of this kind converges at order 1 or more (the contact edge moves by a pixel); an
"order" of 0.2 fitted to three grids says that the changes hardly shrink, and the Richardson
extrapolation built on it lands far from every grid (even below zero for a positive quantity)."""


def trend(sizes: Sequence[float], values: Sequence[float]) -> tuple[tuple[float, float] | None, str]:
    """Return (order, words) of a quantity over grids: the observed order and extrapolation, or why none.

    ``order`` is ``(p, extrapolated)`` of :func:`roughcontact.spread.convergence_order` over the three
    finest grids where p >= ``MIN_ORDER``, else None; ``words`` is ``observed order 1.93`` or why
    there is none: ``2 grids: no order``, ``not monotone`` (the change over the three finest grids
    changes sign), ``changes do not shrink`` (it keeps its sign but does not shrink on refinement) or
    ``order 0.16, too low: not asymptotic``.
    """
    pairs = sorted((h, w) for h, w in zip(sizes, values, strict=True) if math.isfinite(w))
    if len(pairs) < 3:
        return None, f"{len(pairs)} grid{'s' if len(pairs) != 1 else ''}: no order"
    (h1, w1), (h2, w2), (h3, w3) = pairs[:3]
    found = convergence_order([h1, h2, h3], [w1, w2, w3])
    if found is not None and found[0] >= MIN_ORDER:
        return found, f"observed order {found[0]:.3g}"
    if found is not None:
        return None, f"order {found[0]:.2g}, too low: not asymptotic"
    if (w3 - w2) * (w2 - w1) <= 0:
        return None, "not monotone"
    return None, "changes do not shrink"


@dataclass(frozen=True)
class GridValue:
    """A quantity on one grid over its realisations (SI).

    Attributes
    ----------
    grid_points : int
        Points of the grid (elements).
    pixel_size : float
        Its pixel size h [m].
    spread : Spread
        The quantity over the realisations on this grid that every grid has (interval of the mean
        within ``BOUNDS``).
    change : float
        Relative change of the mean from the next coarser grid (signed; NaN on the coarsest).
    draw_changes : dict of int to float
        Each realisation's (by its ``replicate``) relative change from the next coarser grid.
    """

    grid_points: int
    pixel_size: float
    spread: Spread
    change: float
    draw_changes: dict[int, float]


@dataclass(frozen=True)
class QuantityConvergence:
    """One quantity against the grid: its value per grid, its changes and its order (or why none).

    Attributes
    ----------
    quantity, unit : str
        The scalar and its SI unit.
    grids : tuple of GridValue
        Coarsest first.
    order : (float, float) or None
        Observed order and Richardson extrapolation of the means over the three finest grids.
    trend : str
        The means' trend in words (``trend``).
    draw_trends : dict of int to str
        Each realisation's trend in words, by its ``replicate``.
    left_out : tuple of int
        Realisations missing on some grid (a failed or pending case): left out of the means, which
        compare the grids over the same draws; their own changes and trends are still given.
    """

    quantity: str
    unit: str
    grids: tuple[GridValue, ...]
    order: tuple[float, float] | None
    trend: str
    draw_trends: dict[int, str]
    left_out: tuple[int, ...] = ()

    @property
    def finest(self) -> GridValue:
        """The finest grid's value."""
        return self.grids[-1]

    @property
    def finest_from_extrapolation(self) -> float:
        """Relative distance of the finest grid's mean from the Richardson extrapolation (NaN without one)."""
        if self.order is None:
            return math.nan
        return abs(self.finest.spread.mean - self.order[1]) / abs(self.order[1])

    def summary(self) -> str:
        """Say the quantity's convergence in one sentence: last change, trend of the mean and of each draw."""
        finest, grids = self.finest, self.grids
        name = self.quantity.replace("_", " ")
        draws = ", ".join(
            f"{100 * c:+.2g} %" for _, c in sorted(finest.draw_changes.items()) if math.isfinite(c)
        )
        text = (
            f"{name}: the mean changes {100 * finest.change:+.2g} % from {grids[-2].grid_points} to "
            f"{finest.grid_points} points" + (f" (each draw: {draws})" if draws else "")
        )
        if len(grids) >= 3:
            text += f"; over the three finest grids, mean: {self.trend}"
            if self.order is not None:
                text += (
                    f" (Richardson extrapolation {format_si(self.order[1], self.unit)}, finest grid "
                    f"{100 * self.finest_from_extrapolation:.2g} % from it)"
                )
        by_trend: dict[str, list[str]] = {}
        for replicate, words in sorted(self.draw_trends.items()):
            by_trend.setdefault(words, []).append(str(replicate))
        if by_trend and len(grids) >= 3:
            text += "; per draw: " + ", ".join(
                f"{words} (draw{'s' if len(r) > 1 else ''} {', '.join(r)})" for words, r in by_trend.items()
            )
        if self.left_out:
            missing = ", ".join(map(str, self.left_out))
            text += (
                f". Draw{'s' if len(self.left_out) > 1 else ''} {missing} left out of the means: not on "
                "every grid"
            )
        spread_ = finest.spread
        if spread_.n > 1 and spread_.mean:
            text += (
                f". One draw differs from another by {100 * spread_.std / abs(spread_.mean):.2g} % "
                "(std over mean on the finest grid)"
            )
        return text + "."

    def rows(self) -> list[dict[str, Any]]:
        """Return one table row per grid (values in the row's ``unit``; changes relative).

        Columns: ``quantity``, ``unit``, ``grid_points``, ``pixel_size [m]``, ``n``, ``mean``,
        ``ci95_low``, ``ci95_high`` (of the mean), ``std`` (of one draw), ``change_from_coarser (%)``
        (of the mean), ``change_per_draw (%)`` (each draw's) and, on the finest grid,
        ``observed_order`` (of the mean; none where there is none) and ``trend`` (the mean's in
        words, ``trend``; :meth:`summary` says the rest).
        """
        rows = []
        for grid in self.grids:
            row = {
                "quantity": self.quantity,
                "unit": self.unit,
                "grid_points": grid.grid_points,
                "pixel_size [m]": grid.pixel_size,
                "n": grid.spread.n,
                "mean": grid.spread.mean,
                "ci95_low": grid.spread.ci95_low,
                "ci95_high": grid.spread.ci95_high,
                "std": grid.spread.std,
                "change_from_coarser (%)": None if math.isnan(grid.change) else 100 * grid.change,
                "change_per_draw (%)": ", ".join(
                    f"{100 * c:+.2g}" for _, c in sorted(grid.draw_changes.items()) if math.isfinite(c)
                ),
            }
            if grid is self.finest:
                row["observed_order"] = None if self.order is None else self.order[0]
                row["trend"] = self.trend
            rows.append(row)
        return rows


def _numeric(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def mesh_convergence(
    cases: Iterable[Any], quantities: Mapping[str, str] = QUANTITIES
) -> list[QuantityConvergence] | None:
    """Return each quantity against the grid (paper 002 figure 6): values, changes, orders (module notes).

    Parameters
    ----------
    cases : iterable
        Finished cases of one mesh study (anything with ``scalars`` and, optionally,
        ``parameters``): the same island on several grids (``scalars["grid_points"]`` and
        ``scalars["pixel_size"]``), each grid with the same realisations
        (``parameters["replicate"]``, 0 where absent). Cases should differ in nothing else.
    quantities : mapping
        Scalar name -> SI unit; those no case has are left out.

    Returns
    -------
    list of QuantityConvergence or None
        One per quantity present, in the order of ``quantities``; None with fewer than two grids.
    """
    grids: dict[int, list[Any]] = {}
    for case in cases:
        points = case.scalars.get("grid_points")
        if points is not None:
            grids.setdefault(int(points), []).append(case)
    if len(grids) < 2:
        return None
    ordered = sorted(grids.items())
    sizes = [float(group[0].scalars["pixel_size"]) for _, group in ordered]
    found = []
    for quantity, unit in quantities.items():
        per_grid = [
            {int(_parameters(c).get("replicate", 0)): float(c.scalars[quantity]) for c in group
             if _numeric(c.scalars.get(quantity))}
            for _, group in ordered
        ]  # fmt: skip
        if not any(per_grid):
            continue
        # the mean compares grids over the same draws: one missing on some grid (failed, pending)
        # would move it by the scatter between draws, not by the grid
        common = set.intersection(*(set(draws) for draws in per_grid))
        left_out = tuple(sorted({r for draws in per_grid for r in draws} - common))
        values = []
        for number, ((points, _), draws) in enumerate(zip(ordered, per_grid, strict=True)):
            summary = spread((v for r, v in draws.items() if r in common), bounds=BOUNDS)
            coarser = per_grid[number - 1] if number else {}
            change = _relative_change(summary.mean, values[-1].spread.mean) if values else math.nan
            draw_changes = {r: _relative_change(v, coarser[r]) for r, v in draws.items() if r in coarser}
            values.append(GridValue(points, sizes[number], summary, change, draw_changes))
        order, words = trend(sizes, [v.spread.mean for v in values])
        replicates = sorted({r for draws in per_grid for r in draws})
        draw_trends = {
            r: trend(
                [h for h, draws in zip(sizes, per_grid, strict=True) if r in draws],
                [draws[r] for draws in per_grid if r in draws],
            )[1]
            for r in replicates
        }
        if len(replicates) < 2:
            draw_trends = {}  # one draw: its trend is the mean's
        found.append(QuantityConvergence(quantity, unit, tuple(values), order, words, draw_trends, left_out))
    return found or None
