r"""The box around the contact: free-surface solves on the part of the grid that holds the contact.

On a free (non-periodic) surface the displacement of a point depends only on its offset from each
loaded pixel, so tractions that vanish outside a box of the grid give at the box's points exactly
the displacements of the whole grid's operator when the box's own zero-padded operator is used
(:func:`roughcontact.elasticity.kernels.sub_grid_operator`; the operators' ``window`` methods). Where the
contact covers a small part of the window, a ball on a flat (paper 001) or an island (paper 002),
the solvers iterate on the box with transforms a quarter of the size or less, and answer the same
problem: the tractions vanish outside the contact.

Normal contact (:func:`solve`), whose contact set is not known before the solve:

1. without a warm start, the same problem is first solved on the grid coarsened 2 x 2
   (block-averaged separation, the same force, or the approach less the coarse separation's
   offset), itself solved this way down to :data:`COARSEST` pixels and to a looser tolerance
   (:data:`COARSE_TOLERANCE`): a coarse-to-fine cascade, periodic or free, each level
   warm-started from the one below;
2. on a free half-space the problem is then solved on the box around the contact of the warm
   start or of the coarser level's answer, from that pressure;
3. the whole grid's solve, warm-started from that answer, finishes. On a free surface it is the
   box's check: its first residual finds the answer converged (no iteration) unless a point
   outside the box overlaps (a patch that the coarse level lost, or a contact that outgrew the
   warm start's box), and then it iterates on the whole grid to the answer. On a periodic
   surface, a layer, or a contact spread over more than :data:`BOX_AREA` of the grid, it is the
   fine level of the cascade. What is returned is always the whole grid's converged answer.

What the cascade saves is the fine level's first iterations, in which the Polak-Ribiere+
iteration brings the residual from the order of 1 to the coarse answer's 1e-2 (its rate per
iteration is that of the fine level throughout, so the later iterations are as many as from a
cold start). On the benchmark's periodic self-affine surfaces (tolerance 1e-10): 48 -> 39,
66 -> 54 and 82 -> 69 fine iterations at 512^2, 1024^2 and 2048^2, the coarse levels costing
the equivalent of 4-6 fine iterations; pressures within 4e-9 of the peak of a cold start. An
earlier prototype of this cascade had found no saving (87 against 80 fine iterations at 2048^2);
its code was not kept, and the measurement is not reproduced by this one.

Tangential increments (:mod:`roughcontact.contact._programme`) know their contact set, the points
with a pressure, so they use :func:`contact_box` directly.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from .._device import namespace, to_host
from ..elasticity.halfspace import SurfaceCompliance
from ..errors import ConvergenceError
from . import _constrained_cg

BOX_AREA = 0.5
"""A box is used when its area is at most this fraction of the grid's."""
COARSEST = 64
"""The cascade stops coarsening below twice this many pixels on a side."""
COARSE_TOLERANCE = 1e-4
"""The coarse levels are solved to this residual (or the problem's, if looser): they only steer.

Measured on the benchmark's periodic 1024^2 surface (tolerance 1e-10): coarse levels solved to
1e-6 or to 1e-4 leave the same 54 fine iterations; 1e-4 takes 14 iterations at 512^2 instead of 23."""


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
    rows = np.flatnonzero(to_host(contact.any(axis=1)))  # the rows and columns of a GPU array come over
    columns = np.flatnonzero(to_host(contact.any(axis=0)))
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
    **problem,
) -> _constrained_cg.EngineResult:
    """Solve a normal contact from the coarse-to-fine cascade, through the box around its contact.

    Arguments as :func:`roughcontact.contact._constrained_cg.solve` (``problem``: the target,
    ``force`` or ``approach``, and the solver options); see the module docstring. ``iterations``
    of the result counts the box's iterations and the whole grid's (not those of the coarse
    levels).
    """
    counted = [0]
    start = initial_pressure
    if start is None or not bool((start > 0).any()):
        start = _coarse_answer(operator, separation, pixel_area, problem)
    boxed = _on_box(operator, separation, pixel_area, start, problem, counted)
    whole = _constrained_cg.solve(
        operator,
        separation,
        pixel_area=pixel_area,
        initial_pressure=start if boxed is None else boxed,
        **problem,
    )
    return replace(whole, iterations=whole.iterations + counted[0])


def _on_box(operator, separation, pixel_area, start, problem, counted) -> np.ndarray | None:
    """Return the problem's pressure solved on the box around ``start``'s contact, embedded in the grid.

    None where there is no box: no start, no exact sub-grid operator (:func:`has_boxes`), or a
    box not worth it (:func:`contact_box`). Adds the box's iterations to ``counted[0]``.
    """
    if start is None or not has_boxes(operator):
        return None
    box = contact_box(start > 0)
    if box is None:
        return None
    inner = _constrained_cg.solve(
        operator.window(shape_of(box)),
        separation[box],
        pixel_area=pixel_area,
        initial_pressure=start[box],
        **problem,
    )
    counted[0] += inner.iterations
    pressure = namespace(separation).zeros(separation.shape)
    pressure[box] = inner.pressure
    return pressure


def _coarse_answer(operator, separation, pixel_area, problem) -> np.ndarray | None:
    """Return the answer on the grid coarsened 2 x 2, repeated onto this grid.

    The coarse level is solved the same way (its own coarser level, then its box or, without
    one, its whole grid), to :data:`COARSE_TOLERANCE` at the tightest. None below the coarsest
    level, on a periodic grid with an odd side, where the coarse problem has no contact, or
    where a coarse level does not converge (the fine level then starts cold and reports its own
    convergence).
    """
    shape = separation.shape
    if min(shape) < 2 * COARSEST or (operator.boundary == "periodic" and (shape[0] % 2 or shape[1] % 2)):
        return None
    coarse_shape = (shape[0] // 2, shape[1] // 2)
    heights = separation[: 2 * coarse_shape[0], : 2 * coarse_shape[1]]
    heights = heights.reshape(coarse_shape[0], 2, coarse_shape[1], 2).mean(axis=(1, 3))
    offset = float(heights.min())
    heights = heights - offset
    coarse_problem = dict(problem, tolerance=max(problem.get("tolerance", 0.0), COARSE_TOLERANCE))
    if problem.get("approach") is not None:
        coarse_problem["approach"] = problem["approach"] - offset
        if coarse_problem["approach"] <= 0:
            return None
    coarse = operator.coarse()
    start = _coarse_answer(coarse, heights, 4 * pixel_area, coarse_problem)
    try:
        pressure = _on_box(coarse, heights, 4 * pixel_area, start, coarse_problem, [0])
        if pressure is None:
            pressure = _constrained_cg.solve(
                coarse, heights, pixel_area=4 * pixel_area, initial_pressure=start, **coarse_problem
            ).pressure
    except ConvergenceError:  # e.g. a small max_iterations: only the warm start is lost
        return None
    fine = namespace(separation).zeros(shape)
    rows, columns = coarse_shape
    blocks = fine[: 2 * rows, : 2 * columns].reshape(rows, 2, columns, 2)
    blocks[...] = pressure[:, None, :, None]  # a view of ``fine`` (splitting axes never copies)
    return fine
