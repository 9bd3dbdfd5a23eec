"""Amplitude parameters about the mean plane (Sa, Sq, skewness, kurtosis, Sz) and ISO 4287's profile ones."""

from __future__ import annotations

import numpy as np

from ...errors import InputError
from ..surface import Topography


def centred(topography: Topography) -> np.ndarray:
    """Return the heights about the mean plane [m]."""
    return topography.heights - topography.heights.mean()


def ra(topography: Topography) -> float:
    """Arithmetic mean deviation over every point [m]: ``mean(|z - mean(z)|)``.

    Sa of ISO 25178-2 for a map, Ra of ISO 4287 for a profile. (It is also what AFM software
    labels "Ra" for an image, the reading :func:`~roughcontact.topography.process.scale_to_ra`
    takes for paper 000's samples.)
    """
    return float(np.abs(centred(topography)).mean())


def rq(topography: Topography) -> float:
    """Root mean square height over every point [m]: ``sqrt(mean((z - mean(z))**2)) = sqrt(m0)``.

    Sq of ISO 25178-2 for a map, Rq of ISO 4287 for a profile.
    """
    return float(np.sqrt(np.mean(centred(topography) ** 2)))


def _standardised_moment(z: np.ndarray, order: int, heights: np.ndarray) -> float:
    """``<z**order> / <z**2>**(order/2)`` of heights ``z`` about their mean line(s); flat -> InputError."""
    variance = np.mean(z**2)
    if variance <= (np.finfo(float).eps * np.abs(heights).max()) ** 2:
        raise InputError(
            "topography",
            "the surface is flat (Rq = 0): skewness and kurtosis are undefined.",
            "pass a rough surface.",
        )
    return float(np.mean(z**order) / variance ** (order / 2))


def rsk(topography: Topography) -> float:
    """Skewness over every point (Ssk of a map, Rsk of a profile), dimensionless.

    ``mean(z**3) / Rq**3`` with z about the mean.

    Raises
    ------
    InputError
        For a flat surface (Rq = 0).
    """
    return _standardised_moment(centred(topography), 3, topography.heights)


def rku(topography: Topography) -> float:
    """Kurtosis over every point (Sku of a map, Rku of a profile), dimensionless.

    ``mean(z**4) / Rq**4`` (3 for a Gaussian surface).

    Raises
    ------
    InputError
        For a flat surface (Rq = 0).
    """
    return _standardised_moment(centred(topography), 4, topography.heights)


def rz(topography: Topography) -> float:
    """Peak-to-valley height [m]: ``max(z) - min(z)`` over the whole profile or map.

    This is ISO 25178-2 Sz for maps (maximum height of the scale-limited surface) and the total
    height Rt of ISO 4287 for profiles; it is *not* the ISO 4287 Rz averaged over five sampling
    lengths. It does not depend on the mean plane.
    """
    return float(np.ptp(topography.heights))


def profile_parameters(topography: Topography) -> dict[str, float]:
    """ISO 4287 profile parameters along x, pooled over the profiles of a map, SI.

    Each profile (a line of the first axis; for a map ``heights[:, j]``) is taken about its own
    mean line, and the averages run over every point of every profile, as SurfaceTopography's
    ``Rq`` does (so Rq**2 is the mean of the profiles' Rq**2):

    ``Ra = <|z|>``, ``Rq = sqrt(<z**2>)``, ``Rsk = <z**3> / Rq**3``, ``Rku = <z**4> / Rq**4``,
    ``Rdq = sqrt(<(dz/dx)**2>)`` (forward differences) and ``Rt`` the mean over the profiles of
    their highest peak to lowest valley (over the whole profile: the evaluation length is the scan,
    no sampling lengths are cut, so no ISO Rz is given). For a single profile these are the
    parameters of that profile.

    Returns
    -------
    dict of str to float
        "Ra", "Rq" [m], "Rsk", "Rku" (left out when a profile is flat, as in :func:`summary`),
        "Rt" [m], "Rdq" [dimensionless].
    """
    heights = topography.heights
    z = heights - heights.mean(axis=0, keepdims=True)
    if topography.periodic:
        dzdx = (np.roll(heights, -1, axis=0) - heights) / topography.spacing[0]
    else:
        dzdx = np.diff(heights, axis=0) / topography.spacing[0]
    result = {"Ra": float(np.abs(z).mean()), "Rq": float(np.sqrt(np.mean(z**2)))}
    try:
        result |= {"Rsk": _standardised_moment(z, 3, heights), "Rku": _standardised_moment(z, 4, heights)}
    except InputError:
        pass  # flat profiles: skewness and kurtosis undefined, left out as documented
    return result | {
        "Rt": float(np.ptp(heights, axis=0).mean()),
        "Rdq": float(np.sqrt(np.mean(dzdx**2))),
    }
