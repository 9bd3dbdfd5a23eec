"""Processing of topographies: filling undefined points, detrending, background removal,
cropping, resampling and combining two surfaces into one composite.

Every function returns a new :class:`~roughcontact.topography.surface.Topography` and records
the step in ``info['history']``.
"""

from __future__ import annotations

import numpy as np
from scipy import sparse
from scipy.sparse import linalg as sparse_linalg

from ..errors import InputError


def fill_undefined(heights: np.ndarray, *, field: str = "heights") -> np.ndarray:
    """Fill undefined (NaN) points by harmonic (Laplace) interpolation from their defined neighbours.

    Each connected region of missing points is filled with the discrete solution of
    Laplace's equation whose boundary values are the surrounding measured heights: the
    smoothest surface through the measured rim, which introduces no new extrema. Measured
    points are left untouched. The grid edges are treated as reflecting (zero normal
    slope). Solved directly with a sparse LU factorisation over the missing points only.

    Parameters
    ----------
    heights : ndarray
        1D or 2D heights with NaN (or inf) at undefined points.
    field : str
        Name used in error messages.

    Returns
    -------
    ndarray
        Copy of ``heights`` with every undefined point replaced.

    Raises
    ------
    InputError
        If no point at all is defined.
    """
    heights = np.array(heights, dtype=float)
    missing = ~np.isfinite(heights)
    if not missing.any():
        return heights
    if missing.all():
        raise InputError(field, "every point is undefined; there is nothing to interpolate from.",
                         "check the file and the channel.")
    index = np.full(heights.shape, -1)
    index[missing] = np.arange(int(missing.sum()))
    coords = np.argwhere(missing)
    rows, cols, vals = [], [], []
    rhs = np.zeros(len(coords))
    degree = np.zeros(len(coords))
    for axis in range(heights.ndim):
        for step in (-1, 1):
            neighbour = coords.copy()
            neighbour[:, axis] += step
            inside = (neighbour[:, axis] >= 0) & (neighbour[:, axis] < heights.shape[axis])
            me = np.flatnonzero(inside)
            nb = tuple(neighbour[inside].T)
            degree[me] += 1
            unknown = index[nb] >= 0
            rows.append(me[unknown])
            cols.append(index[nb][unknown])
            vals.append(-np.ones(int(unknown.sum())))
            np.add.at(rhs, me[~unknown], heights[nb][~unknown])
    n = len(coords)
    rows = np.concatenate([np.arange(n), *rows])
    cols = np.concatenate([np.arange(n), *cols])
    vals = np.concatenate([degree, *vals])
    laplacian = sparse.csc_matrix((vals, (rows, cols)), shape=(n, n))
    # regions cut off from every measured point would be singular: they cannot exist here because
    # the grid is connected and at least one point is defined.
    heights[missing] = sparse_linalg.spsolve(laplacian, rhs)
    return heights
