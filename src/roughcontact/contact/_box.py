r"""The box around the contact: free-surface solves on the part of the grid that holds the contact.

On a free (non-periodic) surface the displacement of a point depends only on its offset from each
loaded pixel, so tractions that vanish outside a box of the grid give at the box's points exactly
the displacements of the whole grid's operator when the box's own zero-padded operator is used
(:func:`roughcontact.elasticity.kernels.sub_grid_operator`; the operators' ``window`` methods). Where the
contact covers a small part of the window, a ball on a flat (paper 001) or an island (paper 002),
the solvers iterate on the box with transforms a quarter of the size or less, and answer the same
problem: the tractions vanish outside the contact.

Normal contact (:func:`solve`), whose contact set is not known before the solve:

1. the box is that of the warm start's contact or, without one, of the answer of the same problem
   on the grid coarsened 2 x 2 (block-averaged separation, the same force, or the approach less
   the coarse separation's offset), itself solved this way down to :data:`COARSEST` pixels, a
   cascade whose levels each iterate on their own box;
2. the problem is solved on the box, warm-started from the coarser level's pressure;
3. the whole grid's solve, warm-started from that answer, is the check: its first residual finds
   the answer converged (no iteration) unless a point outside the box overlaps (a patch that the
   coarse level lost, or a contact that outgrew the warm start's box), and then it iterates on the
   whole grid to the answer. What is returned is always the whole grid's converged answer.

Where the box would cover more than :data:`BOX_AREA` of the grid (contact spread over the window),
the whole grid is solved from the given start: a coarse warm start by itself does not save fine
iterations (measured with the cascade of ``docs/normal_contact.md``).

Tangential increments (:mod:`roughcontact.contact._programme`) know their contact set, the points
with a pressure, so they use :func:`contact_box` directly.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..elasticity.halfspace import SurfaceCompliance
from . import _constrained_cg

BOX_AREA = 0.5
"""A box is used when its area is at most this fraction of the grid's."""
COARSEST = 64
"""The cascade stops coarsening below twice this many pixels on a side."""


def transform_friendly(length: int) -> int:
    """Return the smallest m 2^k >= ``length`` with m in (1, 3, 5, 7, 9, 15).

    Twice such a side is transformed fast by FFTW; measured here (2 cores, the shear operator of a
    free b x b box): 2.2-3.0 ms for b = 256, 264, 288 and 320, against 3.5-5.2 ms for 270, 272 and
    294, so a slightly larger box of such a side is the cheaper one. Steps between candidates are
    at most 20 %.
    """
    best = 1 << max(int(length) - 1, 0).bit_length()
    for m in (3, 5, 7, 9, 15):
        side = m
        while side < length:
            side *= 2
        best = min(best, side)
    return best


def contact_box(
    contact: np.ndarray, previous: tuple[slice, slice] | None = None
) -> tuple[slice, slice] | None:
    """Return a box of the grid around the ``True`` points of ``contact``, or None for the whole grid.

    ``previous`` is kept while it holds the contact (one operator for the steps of a loop). A new
    box has the contact's extent plus a sixteenth and two pixels (room for a growing contact), each
    side rounded up by :func:`transform_friendly`, and sits centred on the contact, shifted inside
    the grid. None when the box's area would exceed :data:`BOX_AREA` of the grid's (the whole grid
    is as cheap) or there is no contact.
    """
    rows, columns = np.flatnonzero(contact.any(axis=1)), np.flatnonzero(contact.any(axis=0))
    if rows.size == 0:
        return None
    extent = ((int(rows[0]), int(rows[-1]) + 1), (int(columns[0]), int(columns[-1]) + 1))
    if previous is not None and all(
        s.start <= lo and hi <= s.stop for s, (lo, hi) in zip(previous, extent, strict=True)
    ):
        return previous
    box = []
    for (lo, hi), n in zip(extent, contact.shape, strict=True):
        side = min(transform_friendly(hi - lo + (hi - lo) // 16 + 2), n)
        start = min(max((lo + hi - side) // 2, 0), n - side)
        box.append(slice(start, start + side))
    sides = (box[0].stop - box[0].start) * (box[1].stop - box[1].start)
    return None if sides > BOX_AREA * contact.size else (box[0], box[1])


def shape_of(box: tuple[slice, slice]) -> tuple[int, int]:
    """Return the grid shape of ``box``."""
    return box[0].stop - box[0].start, box[1].stop - box[1].start


def has_boxes(operator) -> bool:
    """Whether ``operator`` has exact sub-grid operators: a free half-space (no layer)."""
    return operator.boundary == "free" and operator.layer is None


def solve(
    operator: SurfaceCompliance,
    separation: np.ndarray,
    *,
    pixel_area: float,
    initial_pressure: np.ndarray | None = None,
    box: bool = True,
    **problem,
) -> _constrained_cg.EngineResult:
    """Solve a normal contact through the box around its contact (module docstring).

    Arguments as :func:`roughcontact.contact._constrained_cg.solve` (``problem``: the target,
    ``force`` or ``approach``, and the solver options). ``box=False``, a periodic surface or a
    layer: that function, unchanged. ``iterations`` of the result counts the box's iterations and
    the whole grid's (not those of the coarse levels).
    """
    if not (box and has_boxes(operator)):
        return _constrained_cg.solve(
            operator, separation, pixel_area=pixel_area, initial_pressure=initial_pressure, **problem
        )
    counted = [0]
    start = _on_box(operator, separation, pixel_area, initial_pressure, problem, counted)
    whole = _constrained_cg.solve(
        operator,
        separation,
        pixel_area=pixel_area,
        initial_pressure=initial_pressure if start is None else start,
        **problem,
    )
    return replace(whole, iterations=whole.iterations + counted[0])


def _on_box(operator, separation, pixel_area, guess, problem, counted) -> np.ndarray | None:
    """Return the problem's pressure solved on the box around the contact, embedded in the grid.

    The box is that of ``guess``, else of the coarser level's answer; None where no box is worth
    it. Adds the box's iterations to ``counted[0]``.
    """
    if guess is None or not np.any(guess > 0):
        guess = _coarse_answer(operator, separation, pixel_area, problem)
        if guess is None:
            return None
    box = contact_box(guess > 0)
    if box is None:
        return None
    inner = _constrained_cg.solve(
        operator.window(shape_of(box)),
        separation[box],
        pixel_area=pixel_area,
        initial_pressure=guess[box],
        **problem,
    )
    counted[0] += inner.iterations
    pressure = np.zeros(separation.shape)
    pressure[box] = inner.pressure
    return pressure


def _coarse_answer(operator, separation, pixel_area, problem) -> np.ndarray | None:
    """Return the answer on the grid coarsened 2 x 2, repeated onto this grid.

    None below the coarsest level, or where the coarse level found no box worth it.
    """
    shape = separation.shape
    if min(shape) < 2 * COARSEST:
        return None
    coarse_shape = (shape[0] // 2, shape[1] // 2)
    heights = separation[: 2 * coarse_shape[0], : 2 * coarse_shape[1]]
    heights = heights.reshape(coarse_shape[0], 2, coarse_shape[1], 2).mean(axis=(1, 3))
    offset = float(heights.min())
    heights = heights - offset
    coarse_problem = dict(problem)
    if problem.get("approach") is not None:
        coarse_problem["approach"] = problem["approach"] - offset
        if coarse_problem["approach"] <= 0:
            return None
    coarse = operator.coarse()
    if min(coarse_shape) < 2 * COARSEST:  # the coarsest level: solved whole
        pressure = _constrained_cg.solve(
            coarse, heights, pixel_area=4 * pixel_area, **coarse_problem
        ).pressure
    else:
        pressure = _on_box(coarse, heights, 4 * pixel_area, None, coarse_problem, [0])
        if pressure is None:
            return None
    fine = np.zeros(shape)
    fine[: 2 * coarse_shape[0], : 2 * coarse_shape[1]] = np.repeat(np.repeat(pressure, 2, axis=0), 2, axis=1)
    return fine
