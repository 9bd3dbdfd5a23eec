"""Shapes with roughness, as the seed papers use them.

Paper 002's raised island and the rough sphere of papers 000 (AFM tip) and 001 (ball).
"""

from __future__ import annotations

import math

import numpy as np

from ...checks import positive
from ...errors import InputError
from ..surface import Topography
from .grid import PERIOD_TOLERANCE, checked_hurst, grid_of
from .noise import checked_band
from .random_fields import self_affine
from .shapes import sphere


def raised_island_arguments(
    shape, size, island_size, thickness, rms_height, hurst, substrate_height, short_cutoff=None, modes="grid"
):
    """Check and normalise the arguments of :func:`raised_island`."""
    shape, size = grid_of(shape, size)
    short_cutoff, modes = checked_band(short_cutoff, modes)
    island_size = positive(island_size, "island_size", example="25e-6", unit="m")
    thickness = positive(thickness, "thickness", example="1e-6", unit="m")
    rms_height = positive(rms_height, "rms_height", example="1e-9", unit="m", allow_zero=True)
    hurst = checked_hurst(hurst)
    substrate_height = float(substrate_height)
    if not math.isfinite(substrate_height):
        raise InputError("substrate_height", "must be finite.", "give a height in metres.")
    if island_size > min(size):
        raise InputError(
            "island_size",
            f"{island_size:.6g} m is wider than the scan {size} m.",
            "use a smaller island or a larger size.",
        )
    return shape, size, island_size, thickness, rms_height, hurst, substrate_height, short_cutoff, modes


def raised_island(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    island_size: float,
    thickness: float,
    rms_height: float = 0.0,
    hurst: float = 0.8,
    seed: int | None = None,
    substrate_height: float = 0.0,
    short_cutoff: float | None = None,
    modes: str = "grid",
) -> Topography:
    r"""Make a raised square island on a flat substrate, rough on top: the SU-8 sample of paper 002.

    Heights are ``substrate_height`` outside the island and ``substrate_height + thickness +
    roughness`` on it. The island is the square (segment, for a profile) of side ``island_size``
    centred on the grid point ``(n // 2) * spacing``: a point belongs to it when its distance to the
    centre along every axis is at most ``island_size / 2``. The roughness is a self-affine field
    (:func:`self_affine` on the whole grid, no long cutoff, ``short_cutoff`` and ``modes`` as given)
    restricted to the island, then shifted to zero mean and rescaled so its rms *over the island
    pixels* equals ``rms_height`` exactly. With ``modes="wavevector"`` the field is the same on
    every grid up to that one factor, which the grid's island pixels set.

    Paper 002: a 25 um x 25 um island, t = 6.3 um thick, scanned over 60 um x 60 um.

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny).
    size : float or tuple of float
        Physical size of the scan [m] (>= island_size).
    island_size : float
        Side of the square island [m].
    thickness : float
        Island height above the substrate [m].
    rms_height : float
        Rq of the island top [m] (0: smooth).
    hurst : float
        Hurst exponent of the roughness, in (0, 1].
    seed : int, optional
        Seed of the roughness.
    substrate_height : float
        Height of the substrate [m].
    short_cutoff : float, optional
        Shortest wavelength of the roughness [m] (default: to the corners of the grid; required
        with ``modes="wavevector"``).
    modes : {"grid", "wavevector"}
        How the roughness is drawn, see :func:`self_affine`.

    Returns
    -------
    Topography
        Non-periodic surface; ``info["modes"]`` records ``modes``.

    References
    ----------
    Seed paper 002, section II (raised SU-8 squares, Fig. 2).
    """
    shape, size, island_size, thickness, rms_height, hurst, substrate_height, short_cutoff, modes = (
        raised_island_arguments(
            shape, size, island_size, thickness, rms_height, hurst, substrate_height, short_cutoff, modes
        )
    )
    on_island = np.ones(shape, dtype=bool)
    for axis, (n, s) in enumerate(zip(shape, size, strict=True)):
        x = np.arange(n) * s / n - (n // 2) * s / n
        inside = np.abs(x) <= island_size / 2 * (1 + PERIOD_TOLERANCE)
        on_island &= np.expand_dims(inside, tuple(a for a in range(len(shape)) if a != axis))
    heights = np.full(shape, substrate_height)
    heights[on_island] += thickness
    if rms_height > 0:
        roughness = self_affine(
            shape, size, hurst=hurst, rms_height=1.0, seed=seed, short_cutoff=short_cutoff, modes=modes
        ).heights[on_island]
        roughness = roughness - roughness.mean()
        heights[on_island] += roughness * rms_height / np.sqrt(np.mean(roughness**2))
    info = {
        "name": "raised island",
        "generator": "raised_island",
        "island_size": island_size,
        "thickness": thickness,
        "rms_height": rms_height,
        "hurst": hurst,
        "seed": seed,
        "short_cutoff": short_cutoff,
        "modes": modes,
    }
    return Topography(heights, size, periodic=False, info=info)


def sphere_with_roughness(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    radius: float,
    rms_height: float,
    hurst: float = 0.8,
    seed: int | None = None,
    kind: str = "paraboloid",
    short_cutoff: float | None = None,
    long_cutoff: float | None = None,
    modes: str = "grid",
) -> Topography:
    """Rough sphere: :func:`sphere` plus :func:`self_affine` roughness of rms ``rms_height``.

    Models the AFM tip of paper 000 (a sphere with roughness, 20 nm pixels over 5 um scans) and
    the rough ball of paper 001 (whose "flattened roughness" is what remains after
    :func:`roughcontact.topography.process.remove_sphere`). The roughness is periodic with the
    grid size; the sum is not, so the result is marked non-periodic.

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny).
    size : float or tuple of float
        Physical size [m].
    radius : float
        Radius of curvature R [m].
    rms_height : float
        Rq of the roughness [m] (> 0).
    hurst : float
        Hurst exponent in (0, 1].
    seed : int, optional
        Seed of the roughness.
    kind : {"paraboloid", "sphere"}
        Shape of the body, see :func:`sphere`.
    short_cutoff, long_cutoff : float, optional
        Roughness cutoffs [m], see :func:`self_affine`.
    modes : {"grid", "wavevector"}
        How the roughness is drawn, see :func:`self_affine` (``"wavevector"`` needs
        ``short_cutoff``; its rms is then ``rms_height`` in expectation, not exactly).

    Returns
    -------
    Topography
        Non-periodic surface; the apex of the smooth body is at 0 at the grid point ``(n // 2) * spacing``;
        ``info["modes"]`` records ``modes``.

    References
    ----------
    Seed paper 000 (AFM tip sphere and roughness); seed paper 001, section 4 (ball roughness).
    doi:10.1115/1.4045900
    """
    body = sphere(shape, size, radius=radius, kind=kind)
    roughness = self_affine(
        shape,
        size,
        hurst=hurst,
        rms_height=rms_height,
        seed=seed,
        short_cutoff=short_cutoff,
        long_cutoff=long_cutoff,
        modes=modes,
    )
    info = {
        **dict(body.info),
        "name": f"rough {kind}",
        "generator": "sphere_with_roughness",
        "rms_height": rms_height,
        "hurst": hurst,
        "seed": seed,
        "modes": modes,
    }
    return Topography(body.heights + roughness.heights, body.size, periodic=False, info=info)
