"""Slopes and curvatures from finite differences (``derivative="forward"`` or ``"central"``) and Sdr."""

from __future__ import annotations

import numpy as np

from ...errors import InputError
from ..surface import Topography

DERIVATIVES = ("central", "forward")


def _check_derivative(derivative: str) -> None:
    if derivative not in DERIVATIVES:
        raise InputError(
            "derivative", f"unknown finite-difference scheme {derivative!r}.", f"choose one of {DERIVATIVES}."
        )


def _shifted(heights: np.ndarray, axis: int, shift: int, periodic: bool) -> np.ndarray:
    """Return ``heights[i + shift]`` along ``axis``; wrapped if periodic, else zero-filled (masked later)."""
    if periodic:
        return np.roll(heights, -shift, axis=axis)
    out = np.zeros_like(heights)
    n = heights.shape[axis]
    src = [slice(None)] * heights.ndim
    dst = [slice(None)] * heights.ndim
    src[axis] = slice(max(shift, 0), n + min(shift, 0))
    dst[axis] = slice(max(-shift, 0), n - max(shift, 0))
    out[tuple(dst)] = heights[tuple(src)]
    return out


_FIRST = {"central": ((1, 0.5), (-1, -0.5)), "forward": ((1, 1.0), (0, -1.0))}  # (shift, weight) / h


_SECOND = ((1, 1.0), (0, -2.0), (-1, 1.0))  # (shift, weight) / h**2


def finite_differences(
    topography: Topography, order: int, derivative: str = "forward"
) -> tuple[list[np.ndarray], np.ndarray]:
    """Return finite-difference derivatives of order 1 or 2 along each axis and the mask of valid points.

    Returns one array per axis (``d^order z / dx_k^order`` [m^(1-order)]) and a boolean mask of the
    points where every stencil lies on the grid (all True for a periodic surface). ``derivative``
    picks the first-derivative scheme; second derivatives are always centred.
    """
    _check_derivative(derivative)
    heights = topography.heights
    stencil = _FIRST[derivative] if order == 1 else _SECOND
    valid = np.ones(heights.shape, dtype=bool)
    slopes = []
    for axis, spacing in enumerate(topography.spacing):
        slopes.append(
            sum(w * _shifted(heights, axis, s, topography.periodic) for s, w in stencil) / spacing**order
        )
        if not topography.periodic:
            low, high = min(s for s, _ in stencil), max(s for s, _ in stencil)
            edge = [slice(None)] * heights.ndim
            edge[axis] = slice(0, -low) if low < 0 else slice(0, 0)
            valid[tuple(edge)] = False
            edge[axis] = slice(heights.shape[axis] - high, None)
            valid[tuple(edge)] = False
    if not valid.any():
        raise InputError(
            "topography",
            f"grid {heights.shape} is too small for {derivative} differences "
            f"of order {order} on a non-periodic surface.",
            "use a larger grid (at least 3 points per axis).",
        )
    return slopes, valid


def rms_slope(topography: Topography, *, derivative: str = "forward") -> float:
    r"""Root mean square slope (gradient) [dimensionless].

    .. math:: h'_\mathrm{rms} = \sqrt{\langle (\partial z/\partial x)^2 + (\partial z/\partial y)^2\rangle}

    (Sdq of ISO 25178-2 for maps, Rdq of ISO 4287 for profiles: only the x term). For maps this is
    ``sqrt(2 m2)`` with m2 of paper 002 eq. 2; for profiles ``sqrt(m2)``.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).
    derivative : {"central", "forward"}
        Finite-difference scheme, see the module notes.

    References
    ----------
    ISO 25178-2:2012 (Sdq); Jacobs et al. (2017) doi:10.1088/2051-672X/aa51f8
    """
    slopes, valid = finite_differences(topography, 1, derivative)
    return float(np.sqrt(np.mean(sum(s**2 for s in slopes)[valid])))


def rms_curvature(topography: Topography) -> float:
    r"""Root mean square curvature [1/m].

    Maps: the rms of the mean curvature in the small-slope approximation,

    .. math:: \kappa_\mathrm{rms} = \sqrt{\langle (\nabla^2 z / 2)^2 \rangle}

    (half the rms Laplacian, the definition of SurfaceTopography's ``rms_curvature_from_area`` and
    of Jacobs et al. 2017); profiles: ``sqrt(<(d^2 z/dx^2)^2>)`` (Rddq), which equals ``sqrt(m4)``.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]); second derivatives by the centred three-point stencil.

    References
    ----------
    Jacobs, Junge and Pastewka (2017), Surf. Topogr.: Metrol. Prop. 5, 013001.
    doi:10.1088/2051-672X/aa51f8
    """
    curvatures, valid = finite_differences(topography, 2)
    laplacian = sum(curvatures)
    factor = 0.5 if topography.dim == 2 else 1.0
    return float(factor * np.sqrt(np.mean(laplacian[valid] ** 2)))


def sdr(topography: Topography) -> float:
    r"""Developed interfacial area ratio Sdr of a map (ISO 25178-2), dimensionless (0.01 is 1 %).

    .. math:: S_{dr} = \left\langle \sqrt{1 + (\partial z/\partial x)^2 + (\partial z/\partial y)^2}
              \right\rangle - 1

    the true area of the surface over its projected area, less one, with forward differences
    (each pixel's two segment slopes; on a non-periodic map the last row and column are left out).
    It grows as Sdq^2 / 2 for small slopes.

    Raises
    ------
    InputError
        For a profile (Sdr is an areal parameter).
    """
    if topography.dim != 2:
        raise InputError("topography", "Sdr is an areal parameter; this is a profile.", "pass a map.")
    slopes, valid = finite_differences(topography, 1, "forward")
    return float(np.mean(np.sqrt(1.0 + sum(s**2 for s in slopes))[valid]) - 1.0)
