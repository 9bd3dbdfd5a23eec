r"""The contact area of a pixelated contact, corrected for its perimeter (Yastrebov et al. 2017).

A boundary-element solution says, pixel by pixel, whether a point touches. Counting the pixels in
contact, :math:`N_a`, over-estimates the true area by a band along the contact's perimeter: a pixel
the contact edge crosses counts whole when its pressure is positive, and the solution on a grid
keeps such a pixel in contact more often than the continuum contact covers it (the pressure grows
as the square root of the distance inside the edge, so the discrete pressure of a half-covered
pixel is positive). The excess is proportional to the length of the perimeter measured in pixels,
hence it falls only as the first power of the pixel size under refinement: on a rough surface,
whose perimeter is long, the raw area of one surface falls by several per cent from a coarse to a
fine grid.

Yastrebov, Anciaux and Molinari (2017) measure the perimeter by the number :math:`M` of
contact/no-contact switches along the grid lines (between each pair of neighbouring pixels along
x and along y) and correct the count by a constant per switch,

.. math::

    \frac{A^*}{A_0} = \frac{N_a - c\, M}{N^2}, \qquad c = \frac{\pi - 1 + \ln 2}{24} \approx 0.1181,

with :math:`N^2` the pixels of the grid. :math:`M` measures the perimeter :math:`P`: a straight
boundary at angle :math:`\theta` to the x axis crosses :math:`(|\cos\theta| + |\sin\theta|)/\Delta x`
grid lines per unit length, :math:`4/(\pi\Delta x)` on average over directions, so
:math:`M \approx 4 P / (\pi \Delta x)` and the correction removes a band of mean width
:math:`4 c \Delta x / \pi \approx 0.15\,\Delta x` along the perimeter. The constant :math:`c` is the
paper's, from its geometrical analysis of the pixels a contact boundary crosses; what is checked
here (``tests/validation/test_corrected_area.py``) is what it is for: on a Hertz contact and on one
rough surface refined with its modes kept, the corrected area converges faster than the raw count.

A periodic contact counts its switches across the period too (the last pixel of a row against the
first); a free window only inside it, its outer edge not being a contact boundary. A contact pixel
has at most four switches, so :math:`N_a - cM \ge (1 - 4c) N_a > 0`: the correction never
removes a contact. It is derived for maps; a line contact (a profile) is not corrected here.

References
----------
Yastrebov, V. A., Anciaux, G. and Molinari, J.-F. (2017). On the accurate computation of the true
contact-area in mechanical contact of random rough surfaces. Tribol. Int. 114, 161-171.
doi:10.1016/j.triboint.2017.04.023

Yastrebov, V. A., Anciaux, G. and Molinari, J.-F. (2015). From infinitesimal to full contact between
rough surfaces: evolution of the contact area. Int. J. Solids Struct. 52, 83-102.
doi:10.1016/j.ijsolstr.2014.09.019
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["PERIMETER_CORRECTION", "corrected_contact_count", "perimeter_switches"]

PERIMETER_CORRECTION = (math.pi - 1.0 + math.log(2.0)) / 24.0
r"""The constant :math:`c = (\pi - 1 + \ln 2)/24` of Yastrebov et al. (2017): pixels removed per switch."""


def _map(mask) -> np.ndarray:
    mask = np.asarray(mask, dtype=bool)
    if mask.ndim != 2:
        raise InputError(
            "mask",
            f"the perimeter correction is defined for a map (2D contact mask), got {mask.ndim} dimensions.",
            "pass the contact mask of a 2D surface; a line contact is not corrected.",
        )
    return mask


def perimeter_switches(mask, *, periodic: bool) -> int:
    """Count the contact/no-contact switches between neighbouring pixels along x and along y.

    Parameters
    ----------
    mask : array_like of bool, shape (nx, ny)
        True where a pixel is in contact.
    periodic : bool
        Count across the period as well (the last pixel of each line against the first); a free
        window counts the switches inside it only.

    Returns
    -------
    int
        :math:`M`, the number of switches on the grid lines (a measure of the perimeter in pixels).

    Raises
    ------
    InputError
        For a mask that is not 2D.

    References
    ----------
    Yastrebov, Anciaux and Molinari (2017), Tribol. Int. 114, 161. doi:10.1016/j.triboint.2017.04.023
    """
    mask = _map(mask)
    count = 0
    for axis in (0, 1):
        if periodic:
            count += int(np.count_nonzero(mask != np.roll(mask, -1, axis=axis)))
        else:
            count += int(np.count_nonzero(np.diff(mask, axis=axis)))
    return count


def corrected_contact_count(mask, *, periodic: bool) -> float:
    r"""Return the corrected number of contact pixels :math:`N_a - c\,M` (module notes).

    Multiply by the pixel area for the corrected contact area, divide by the number of pixels for
    the corrected contact fraction :math:`A^*/A_0`.

    Parameters
    ----------
    mask : array_like of bool, shape (nx, ny)
        True where a pixel is in contact.
    periodic : bool
        Whether switches across the period count (:func:`perimeter_switches`).

    Returns
    -------
    float
        :math:`N_a - c M` with :math:`c` = :data:`PERIMETER_CORRECTION`, between
        :math:`(1 - 4c) N_a` and :math:`N_a`.

    References
    ----------
    Yastrebov, Anciaux and Molinari (2017), Tribol. Int. 114, 161. doi:10.1016/j.triboint.2017.04.023
    """
    mask = _map(mask)
    return float(np.count_nonzero(mask)) - PERIMETER_CORRECTION * perimeter_switches(mask, periodic=periodic)
