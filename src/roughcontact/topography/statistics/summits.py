"""Summits: points strictly higher than all their neighbours."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..surface import Topography
from .amplitude import centred


@dataclass(frozen=True)
class Summits:
    """Local maxima of a surface.

    Attributes
    ----------
    indices : ndarray of int, shape (count, dim)
        Grid indices of the summits.
    positions : ndarray, shape (count, dim)
        Their coordinates [m].
    heights : ndarray, shape (count,)
        Their heights above the mean plane [m].
    """

    indices: np.ndarray
    positions: np.ndarray
    heights: np.ndarray

    @property
    def count(self) -> int:
        """Number of summits."""
        return len(self.heights)


def summits(topography: Topography) -> Summits:
    """Find the summits: points strictly higher than all their neighbours.

    Neighbours are the 8 surrounding pixels of a map (2 for a profile). Periodic surfaces wrap
    around; on non-periodic ones the edge points are never summits (their neighbourhood is
    incomplete). Plateaus (equal neighbours) give no summit.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).

    Returns
    -------
    Summits
        Indices, positions [m] and heights about the mean plane [m] of the summits.

    References
    ----------
    Greenwood, J. A. and Williamson, J. B. P. (1966). Proc. R. Soc. A 295, 300-319.
    doi:10.1098/rspa.1966.0242 (summits as 8-neighbour maxima: Greenwood 1984, doi:10.1098/rspa.1984.0006)
    """
    z = centred(topography)
    is_summit = np.ones(z.shape, dtype=bool)
    for shift in np.ndindex(*(3,) * z.ndim):
        offset = tuple(s - 1 for s in shift)
        if any(offset):
            is_summit &= z > np.roll(z, offset, axis=tuple(range(z.ndim)))
    if not topography.periodic:
        interior = np.zeros(z.shape, dtype=bool)
        interior[(slice(1, -1),) * z.ndim] = True
        is_summit &= interior
    indices = np.argwhere(is_summit)
    positions = indices * np.asarray(topography.spacing)
    return Summits(indices=indices, positions=positions, heights=z[is_summit])
