"""Processing of topographies: fill, find specks, detrend, remove a sphere, crop, resample, combine.

Filling undefined points and finding isolated specks work on raw height arrays (before a
Topography exists); detrending, background removal, keeping filled points out of contact,
cropping, resampling and combining two surfaces into one composite work on topographies.
Backgrounds are fitted to the measured points only (not to filled points or specks); the masks
of filled points and specks follow every step.

Every function returns a new :class:`~roughcontact.topography.surface.Topography` and records
the step in ``info['history']``.
"""

from __future__ import annotations

import math

import numpy as np
import scipy

from ..errors import InputError
from ..units import format_si
from .plausible import FLAT
from .surface import Topography


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
        raise InputError(
            field,
            "every point is undefined; there is nothing to interpolate from.",
            "check the file and the channel.",
        )
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
    laplacian = scipy.sparse.csc_matrix((vals, (rows, cols)), shape=(n, n))
    # regions cut off from every measured point would be singular: they cannot exist here because
    # the grid is connected and at least one point is defined.
    heights[missing] = scipy.sparse.linalg.spsolve(laplacian, rhs)
    return heights


SPECK = 10
"""Measured points in a connected group smaller than this, amid undefined ones, are a speck."""


def find_specks(undefined: np.ndarray, *, max_points: int = SPECK) -> np.ndarray:
    """Return the measured points in connected groups of fewer than ``max_points`` points.

    An instrument that loses most of a region often keeps scattered single pixels there, of any
    height (SurfaceTopography's ``frt-2.frt``: 244 such points, 0.75 % of its defined ones, down
    to -70 um on a surface that spans 5 um). Filled around them, they stand up as spikes and take
    the contact of the whole surface. Groups are 4-connected; a file without undefined points has
    no specks.

    Parameters
    ----------
    undefined : ndarray of bool
        True where the file holds no height.
    max_points : int
        Groups of fewer measured points than this are specks (default :data:`SPECK`).

    Returns
    -------
    ndarray of bool
        True at the points of the specks.
    """
    if not undefined.any():
        return np.zeros(undefined.shape, dtype=bool)
    labels, count = scipy.ndimage.label(~undefined)
    sizes = scipy.ndimage.sum(~undefined, labels, np.arange(1, count + 1))
    return np.isin(labels, 1 + np.flatnonzero(sizes < max_points))


def measured_points(topography: Topography) -> np.ndarray:
    """Return True where a height was measured and is not a speck (what backgrounds are fitted to)."""
    trusted = np.ones(topography.shape, dtype=bool)
    for mask in (topography.filled, topography.specks):
        if mask is not None:
            trusted &= ~mask
    return trusted


def exclude_filled(topography: Topography) -> Topography:
    """Keep the filled (interpolated) points out of contact: lower them below every measured point.

    Their heights are invented, so a contact they carry is invented too
    (:mod:`roughcontact.contact.trust` measures how much). Lowered to the lowest measured height
    minus the measured peak-to-valley height, they can only touch after every measured point has
    (full contact); they carry no pressure, and since a point without pressure acts on no other,
    the contact of the measured points is the one they would have with the filled points cut out
    of the contact problem. The gap over the lowered points is not a physical gap, and the rim of
    the measured region around them is an edge like a free window's (a contact cut by it is pressed
    like the edge of a punch): contact results count it with the window's edge
    (:func:`roughcontact.contact.trust.contact_shares`). ``info['filled_excluded']`` says it was done.

    Parameters
    ----------
    topography : Topography
        A levelled surface with ``filled`` points (a surface without them is returned as it is).

    Returns
    -------
    Topography
    """
    if topography.filled is None:
        return topography
    measured = topography.heights[~topography.filled]
    floor = measured.min() - np.ptp(measured)
    heights = np.where(topography.filled, floor, topography.heights)
    count = int(np.count_nonzero(topography.filled))
    info = {**topography.info, "filled_excluded": True}
    step = f"exclude_filled: {count} filled points lowered out of contact"
    return topography.with_heights(heights, step=step, info=info)


# --- least-squares backgrounds -------------------------------------------------------------------

_DETREND_MODES = ("mean", "plane", "curvature")

LEVELLING = {
    "none": "not levelled (detrend none: the tilt of the scan is kept)",
    "mean": "mean height removed only (detrend mean: the tilt is kept)",
    "plane": "levelled: least-squares plane subtracted",
    "curvature": "levelled: least-squares quadratic (tilt and curvature) subtracted",
    "sphere": "levelled: fitted sphere subtracted",
}
"""What :func:`level` can remove from a measured scan (nothing, or a fitted background), and how
the commands, ``inspect`` and the report say it."""


def scale_to_ra(topography: Topography, ra: float) -> Topography:
    """Return the topography with its heights scaled so that its Ra is exactly ``ra`` [m].

    Paper 000 gives its samples by Ra; the generators set the rms height, so a generated surface is
    scaled afterwards (the shape of its height distribution, and so Rq / Ra, is kept).
    """
    from .statistics import ra as arithmetic_mean_deviation

    current = arithmetic_mean_deviation(topography)
    if not (math.isfinite(ra) and ra > 0 and current > 0):
        raise InputError(
            "ra", f"cannot scale Ra {current:g} m to {ra} m.", "give a positive Ra of a rough surface."
        )
    return topography.with_heights(topography.heights * (ra / current), step=f"scaled to Ra {ra:g} m")


def _normalised_coordinates(topography: Topography, *, scale: float | None = None) -> list[np.ndarray]:
    """Centred grid coordinates divided by ``scale`` (default: each axis' own size), for conditioning."""
    grids = topography.meshgrid()
    scales = [scale] * topography.dim if scale else topography.size
    return [(g - g.mean()) / s for g, s in zip(grids, scales, strict=True)]


def _least_squares(
    heights: np.ndarray, terms: list[np.ndarray], where: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Fit ``heights`` at the points ``where`` (default all) by a linear combination of ``terms``.

    Returns (fitted background on every point, coefficients).
    """
    design = np.stack([np.broadcast_to(t, heights.shape).ravel() for t in terms], axis=1)
    fitted = slice(None) if where is None else where.ravel()
    coefficients = np.linalg.lstsq(design[fitted], heights.ravel()[fitted], rcond=None)[0]
    return (design @ coefficients).reshape(heights.shape), coefficients


def detrend(topography: Topography, mode: str = "plane") -> Topography:
    """Subtract a least-squares polynomial background.

    ===============  =========================================  ==================
    ``mode``         2D background                              1D (profile)
    ===============  =========================================  ==================
    ``"mean"``       a                                          a
    ``"plane"``      a + b x + c y                              a + b x (line)
    ``"curvature"``  a + b x + c y + d x^2 + e x y + f y^2      a + b x + d x^2
    ===============  =========================================  ==================

    The fit is an ordinary least-squares fit over the measured grid points (coordinates centred
    and scaled internally for conditioning; filled points and specks are left out of the fit,
    :func:`measured_points`), so detrending twice changes nothing beyond rounding.

    Periodic surfaces: ``"mean"`` keeps them periodic. A periodic surface has no tilt or
    curvature in the periodic sense, and subtracting a plane or quadratic makes its opposite
    edges disagree, so ``"plane"`` and ``"curvature"`` return ``periodic=False``.

    Parameters
    ----------
    topography : Topography
        Surface to detrend (heights [m]).
    mode : {"mean", "plane", "curvature"}
        Background to remove, see the table.

    Returns
    -------
    Topography
        Heights [m] minus the fitted background, step recorded in ``info['history']``.

    Raises
    ------
    InputError
        Unknown ``mode``.
    """
    if mode not in _DETREND_MODES:
        raise InputError("mode", f"unknown detrend mode {mode!r}.", f"choose one of {list(_DETREND_MODES)}.")
    coordinates = _normalised_coordinates(topography)
    terms = [np.ones(topography.shape)]
    if mode in ("plane", "curvature"):
        terms += coordinates
    if mode == "curvature":
        terms += [a * b for i, a in enumerate(coordinates) for b in coordinates[i:]]
    background, _ = _least_squares(topography.heights, terms, measured_points(topography))
    return topography.with_heights(
        topography.heights - background,
        step=f"detrend(mode={mode!r})",
        periodic=topography.periodic and mode == "mean",
    )


def default_levelling(periodic: bool) -> str:
    """Return the levelling of a measured scan that names none: ``"plane"``, ``"mean"`` if ``periodic``.

    The one default of every door: ``read_topography``, the commands' ``--detrend`` and a study
    file's ``detrend``. A plane would make a periodic surface's opposite edges disagree.
    """
    return "mean" if periodic else "plane"


def check_levelling(mode: str, periodic: bool) -> str:
    """Return ``mode`` after checking that it is one of ``LEVELLING`` and keeps a periodic surface so.

    Raises
    ------
    InputError
        (field ``detrend``) an unknown levelling, or one that removes a background from a periodic
        surface (which then no longer repeats).
    """
    if mode not in LEVELLING:
        raise InputError("detrend", f"unknown levelling {mode!r}.", f"choose one of {', '.join(LEVELLING)}.")
    if periodic and mode not in ("none", "mean"):
        raise InputError(
            "detrend",
            f"{mode} removes a background from a periodic surface, which then no longer repeats.",
            "use «detrend=mean» (or «detrend=none») for a periodic surface, or leave «periodic» out.",
        )
    return mode


def level(topography: Topography, mode: str) -> Topography:
    """Remove the background ``mode`` names (one of ``LEVELLING``) from a measured scan.

    ``"none"`` returns the surface as read; ``"mean"``, ``"plane"`` and ``"curvature"`` are
    :func:`detrend`; ``"sphere"`` is :func:`remove_sphere` (its fitted radius is recorded in
    ``info['history']``). The commands, study files and ``read_topography`` level measured scans
    with ``"plane"`` unless told otherwise (:func:`default_levelling`): the tilt of a raw AFM scan
    is an artefact of mounting, and left in it decides where a flat touches (issue 15:
    SurfaceTopography's ``mi-1.mi`` touches along one edge, 5.6 % contact raw against 10.1 %
    levelled).

    ``info['detrend']`` records ``mode`` (``"none"`` included), as the commands' ``--json`` and a
    study's provenance name it; the results of the solvers show it. A surface that levelling
    leaves flat (a constant or a perfect plane: what remains varies by no more than
    :data:`~roughcontact.topography.plausible.FLAT` of the heights' magnitude, the round-off of
    the fit) is returned as exactly flat, every height 0, with the step in ``info['history']``:
    its round-off would otherwise read as a roughness of 1e-24 m with summits of gigametres.

    Raises
    ------
    InputError
        Unknown ``mode`` (named ``detrend``, the option and study key that set it).
    """
    check_levelling(mode, periodic=False)
    info = {**topography.info, "detrend": mode}
    if mode == "none":
        return topography.with_heights(topography.heights, info=info)
    levelled = remove_sphere(topography)[0] if mode == "sphere" else detrend(topography, mode)
    levelled = levelled.with_heights(levelled.heights, info={**levelled.info, "detrend": mode})
    magnitude = float(np.max(np.abs(topography.heights)))
    leftover = float(np.max(np.abs(levelled.heights)))
    if leftover == 0 or not leftover <= FLAT * magnitude:
        return levelled
    step = (
        f"flat: levelled heights are {leftover:.3g} m at most, round-off of their magnitude "
        f"{magnitude:.3g} m (at most {FLAT:g} of it): set to 0"
    )
    return levelled.with_heights(np.zeros(topography.shape), step=step)


def remove_sphere(topography: Topography, *, fit: str = "sphere") -> tuple[Topography, float]:
    """Remove a spherical background (e.g. the ball of paper 001) and return its radius.

    The surface is fitted by a cap of curvature kappa = 1 / R whose apex (x0, y0, z0) is free,
    so tilt is absorbed by the apex position:

    * ``fit="paraboloid"``: z = z0 - kappa r^2 / 2, with r^2 = (x - x0)^2 + (y - y0)^2; linear
      least squares in the expanded form a + b x + c y + d (x^2 + y^2), one curvature (isotropic).
    * ``fit="sphere"`` (default): the exact cap z = z0 - kappa r^2 / (1 + sqrt(1 - kappa^2 r^2)),
      by nonlinear least squares (vertical residuals) started from the paraboloid fit. A
      paraboloid fitted to a true sphere is biased at order (r / R)^2 and leaves a residual of
      order r^4 / (8 R^3). For paper 001's geometry (1.1 mm scan of a 5 mm-radius ball, apex off
      centre) we measured a 0.56 % radius bias and a 0.28 um peak residual, comparable with the
      POM roughness (0.67 um rms), hence this default.

    Heights point out of the body, so a ball (convex cap) gives R > 0 and a dimple R < 0. A
    profile (1D) is fitted by a circle / parabola in the same way. The result is non-periodic.

    Parameters
    ----------
    topography : Topography
        Surface of a curved body (heights [m]).
    fit : {"sphere", "paraboloid"}
        Background model, see above.

    Returns
    -------
    flattened : Topography
        Heights [m] minus the fitted cap ("flattened roughness", paper 001 Fig. 5).
    radius : float
        Fitted radius of curvature R [m] (signed as above).

    Raises
    ------
    InputError
        Unknown ``fit``, or a surface without any curvature (use :func:`detrend` instead).

    References
    ----------
    Seed paper 001, section 4 (flattened roughness of the balls). doi:10.1115/1.4045900
    """
    if fit not in ("sphere", "paraboloid"):
        raise InputError("fit", f"unknown fit {fit!r}.", "choose 'sphere' or 'paraboloid'.")
    scale = max(topography.size)  # one length scale for all axes keeps the curvature isotropic
    coordinates = _normalised_coordinates(topography, scale=scale)
    heights = topography.heights / scale
    radial = sum(c**2 for c in coordinates)
    trusted = measured_points(topography)
    background, (offset, *slopes, quadratic) = _least_squares(
        heights, [np.ones(heights.shape), *coordinates, radial], trusted
    )
    if quadratic == 0:
        raise InputError(
            "topography",
            "the surface has no curvature to fit a sphere to.",
            "use detrend(topography, mode='plane') for a flat surface.",
        )
    curvature = -2.0 * quadratic  # dimensionless: kappa * scale
    if fit == "sphere":
        apex = [-s / (2.0 * quadratic) for s in slopes]
        start = [*apex, offset - sum(s**2 for s in slopes) / (4.0 * quadratic), curvature]
        solution = scipy.optimize.least_squares(
            lambda p: (_spherical_cap(coordinates, p) - heights)[trusted],
            start,
            x_scale="jac",
            ftol=1e-15,
            xtol=1e-15,
            gtol=1e-15,
        )
        background, curvature = _spherical_cap(coordinates, solution.x), solution.x[-1]
    radius = scale / curvature
    flattened = topography.with_heights(
        topography.heights - background * scale,
        periodic=False,
        step=f"remove_sphere(fit={fit!r}) radius={radius:.6g} m",
    )
    return flattened, float(radius)


def _spherical_cap(coordinates: list[np.ndarray], parameters: np.ndarray) -> np.ndarray:
    """Heights of a spherical cap with apex (*centre, apex_height) and curvature (all dimensionless)."""
    *centre, apex_height, curvature = parameters
    radial = sum((c - c0) ** 2 for c, c0 in zip(coordinates, centre, strict=True))
    return apex_height - curvature * radial / (1.0 + np.sqrt(np.maximum(1.0 - curvature**2 * radial, 0.0)))


# --- grids ---------------------------------------------------------------------------------------

_PIXEL_TOLERANCE = 1e-9  # fraction of a pixel below which a coordinate counts as on a grid point


def crop(
    topography: Topography, x: tuple[float, float] | None = None, y: tuple[float, float] | None = None
) -> Topography:
    """Cut out a rectangular window given in metres.

    Intervals are half-open: grid point i along x (at ``x_i = i * spacing[0]``, the first point at
    0) is kept when ``start <= x_i < stop``; a coordinate within 1e-9 pixel of a grid point counts
    as on it, so round-off in ``start``/``stop`` does not shift the window by a pixel. ``None``
    keeps the whole axis. The new grid starts again at 0 with the same spacing, and its size is
    the number of kept points times the spacing. The result is non-periodic.

    Parameters
    ----------
    topography : Topography
        Surface to crop.
    x, y : tuple of float, optional
        (start, stop) [m] along x and y; ``y`` only for a 2D map.

    Returns
    -------
    Topography
        The window, step recorded in ``info['history']``.

    Raises
    ------
    InputError
        A window on an axis the topography lacks, with start >= stop, or keeping fewer than 2
        points along an axis.
    """
    window = crop_window(topography.shape, topography.spacing, x, y)
    heights = topography.heights[window]
    size = tuple(n * s for n, s in zip(heights.shape, topography.spacing, strict=True))
    masks = {n: None if m is None else m[window] for n, m in _masks(topography).items()}
    return topography.with_heights(heights, size=size, periodic=False, step=f"crop(x={x}, y={y})", **masks)


def crop_window(
    shape: tuple[int, ...], spacing: tuple[float, ...], x: tuple | None, y: tuple | None = None
) -> tuple[slice, ...]:
    """Return the index window of the points ``start <= x_i < stop`` (see :func:`crop`) per axis.

    Raises
    ------
    InputError
        A window on an axis the grid lacks, with start >= stop, or keeping fewer than 2 points.
    """
    if y is not None and len(shape) == 1:
        raise InputError("y", "a profile (1D topography) has no y axis.", "crop a profile along x only.")
    slices = []
    for field, window, n, step in zip(("x", "y"), (x, y), shape, spacing, strict=False):
        if window is None:
            slices.append(slice(None))
            continue
        start, stop = (float(v) for v in window)
        first, last = (max(0, min(n, math.ceil(v / step - _PIXEL_TOLERANCE))) for v in (start, stop))
        if not start < stop or last - first < 2:
            raise InputError(
                field,
                f"window ({start:.6g}, {stop:.6g}) m keeps {max(last - first, 0)} points "
                f"of a grid of {n} points spaced {step:.6g} m.",
                "give start < stop [m] spanning at least 2 grid points inside the topography.",
            )
        slices.append(slice(first, last))
    return tuple(slices)


def _masks(topography: Topography) -> dict[str, np.ndarray | None]:
    return {"filled": topography.filled, "specks": topography.specks}


def _sample_masks(topography: Topography, shape, spacing) -> dict[str, np.ndarray | None]:
    """Return the masks on a resampled grid: a point is marked where a marked point enters its value.

    Cubic splines reach two points on either side; the mask is widened by one point and sampled
    linearly, so a new point within a pixel of a marked one is marked.
    """
    result = {}
    for name, mask in _masks(topography).items():
        if mask is None:
            result[name] = None
            continue
        wide = scipy.ndimage.binary_dilation(mask, iterations=1).astype(float)
        axes = list(zip(shape, spacing, topography.shape, topography.spacing, strict=True))
        grid = np.meshgrid(*[np.arange(n) * (new / old) for n, new, _, old in axes], indexing="ij")
        mode = "grid-wrap" if topography.periodic else "nearest"
        result[name] = scipy.ndimage.map_coordinates(wide, grid, order=1, mode=mode) > 0
    return result


def _spacing_tuple(spacing: float | tuple[float, ...], dim: int, field: str) -> tuple[float, ...]:
    values = np.atleast_1d(np.asarray(spacing, dtype=float))
    if values.size == 1:
        values = np.repeat(values, dim)
    if values.shape != (dim,) or not np.all(np.isfinite(values)) or np.any(values <= 0):
        raise InputError(
            field,
            f"{np.asarray(spacing, dtype=float).tolist()} is not {dim} positive finite length(s).",
            f"give the pixel size in metres, one value or one per axis ({dim}).",
        )
    return tuple(float(v) for v in values)


def _sample(topography: Topography, shape: tuple[int, ...], spacing: tuple[float, ...]) -> np.ndarray:
    """Heights at the grid points ``j * spacing`` (j < shape) by cubic-spline interpolation.

    Axes whose spacing is unchanged are sampled at the original points exactly; when no axis
    changes the heights are sliced, not interpolated. Periodic surfaces wrap around.
    """
    axes = list(zip(shape, spacing, topography.shape, topography.spacing, strict=True))
    if all(math.isclose(new, old, rel_tol=1e-12) and n <= m for n, new, m, old in axes):
        return topography.heights[tuple(slice(n) for n in shape)].copy()
    positions = [np.arange(n) * (new / old) for n, new, _, old in axes]
    grid = np.meshgrid(*positions, indexing="ij")
    mode = "grid-wrap" if topography.periodic else "nearest"
    return scipy.ndimage.map_coordinates(topography.heights, grid, order=3, mode=mode)


def _shape_for(
    topography: Topography, spacing: tuple[float, ...]
) -> tuple[tuple[int, ...], tuple[float, ...]]:
    """Return the shape and spacing of the resampled grid (see resample)."""
    if topography.periodic:
        shape = tuple(max(2, round(s / h)) for s, h in zip(topography.size, spacing, strict=True))
        return shape, tuple(s / n for s, n in zip(topography.size, shape, strict=True))
    return _points_within(topography, spacing), spacing


def _points_within(topography: Topography, spacing: tuple[float, ...]) -> tuple[int, ...]:
    """Count the points ``j * spacing`` per axis up to the last grid point of ``topography``."""
    return tuple(
        math.floor((n - 1) * old / new + _PIXEL_TOLERANCE) + 1
        for n, old, new in zip(topography.shape, topography.spacing, spacing, strict=True)
    )


def resample(topography: Topography, spacing: float | tuple[float, ...]) -> Topography:
    """Interpolate a topography onto a grid of another pixel size.

    Interpolation is by cubic B-splines (``scipy.ndimage.map_coordinates``, order 3), wrapping
    around for periodic surfaces. It is exact on the original grid points, so an unchanged
    spacing returns the heights unchanged. There is no anti-alias filter: when coarsening,
    wavelengths shorter than two new pixels alias; low-pass filter first if they matter.

    The new grid keeps the first point at 0 and

    * non-periodic: takes exactly the requested spacing h and as many points as fit up to the
      last original point (no extrapolation): n' = floor((n - 1) dx / h) + 1, so the size
      n' h differs from the original size by less than max(dx, h);
    * periodic: keeps the period exactly and periodicity, with n' = round(size / h) points, so
      the spacing is size / n' (within half a pixel in n' of the request).

    Parameters
    ----------
    topography : Topography
        Surface to resample.
    spacing : float or tuple of float
        New pixel size [m], one value or one per axis.

    Returns
    -------
    Topography
        Resampled surface, step recorded in ``info['history']``.

    Raises
    ------
    InputError
        A spacing that is not positive and finite, or with the wrong number of values.
    """
    shape, spacing = _shape_for(topography, _spacing_tuple(spacing, topography.dim, "spacing"))
    heights = _sample(topography, shape, spacing)
    size = tuple(n * h for n, h in zip(shape, spacing, strict=True))
    masks = (
        _masks(topography) if heights.shape == topography.shape else _sample_masks(topography, shape, spacing)
    )
    return topography.with_heights(heights, size=size, step=f"resample(spacing={spacing})", **masks)


def common_spacing(a: Topography, b: Topography) -> tuple[float, ...]:
    """Return the finer of the two pixel sizes along each axis [m].

    Parameters
    ----------
    a, b : Topography
        Two surfaces with the same number of axes.

    Returns
    -------
    tuple of float
        ``min(a.spacing[k], b.spacing[k])`` for each axis k.
    """
    _check_same_dim(a, b)
    return tuple(min(p, q) for p, q in zip(a.spacing, b.spacing, strict=True))


def _check_same_dim(a: Topography, b: Topography) -> None:
    if a.dim != b.dim:
        raise InputError("b", f"a is {a.dim}D and b is {b.dim}D.", "combine two maps or two profiles.")


def check_same_grid(a: tuple, b: tuple) -> None:
    """Refuse two grids, each ``(shape, size [m])``, that :func:`combine` cannot merge without resampling.

    Raises
    ------
    InputError
        Field ``b``: another number of axes, points or physical size (relative 1e-9), both shown.
    """
    (shape_a, size_a), (shape_b, size_b) = a, b
    if len(shape_a) != len(shape_b):
        raise InputError(
            "b", f"a is {len(shape_a)}D and b is {len(shape_b)}D.", "combine two maps or two profiles."
        )
    same_size = all(math.isclose(p, q, rel_tol=1e-9) for p, q in zip(size_a, size_b, strict=True))
    if tuple(shape_a) != tuple(shape_b) or not same_size:
        which = "shape" if tuple(shape_a) != tuple(shape_b) else "size"
        shown = [" x ".join(format_si(side, "m") for side in size) for size in (size_a, size_b)]
        grids = [" x ".join(map(str, shape)) for shape in (shape_a, shape_b)]
        raise InputError(
            "b",
            f"grid {which} differs: a is {grids[0]} points over {shown[0]}, b is {grids[1]} points over "
            f"{shown[1]}.",
            "pass resample=True to interpolate both onto a common grid.",
        )


def combine(a: Topography, b: Topography, *, resample: bool = False) -> Topography:
    r"""Composite topography of two rough surfaces touching face to face.

    The contact of two rough elastic bodies is mapped onto a rough surface against a rigid
    flat (paper 000 sums the asperities of the two topographies; paper 001 eq. 2 gives the
    initial gap h = max(z1) + max(z2) - (z1 + z2)). The composite height is

    .. math:: z = z_1 + z_2 - \langle z_1 + z_2 \rangle

    with each z_i measured from its own reference plane and pointing towards the other body
    (detrend or :func:`remove_sphere` first). The mean is removed because only height
    differences matter for the gap. No mirroring is done: point (x, y) of ``a`` faces point
    (x, y) of ``b``; flip one surface first if its scan was recorded in a mirrored frame.
    The result is symmetric: ``combine(a, b)`` and ``combine(b, a)`` have equal heights.

    Grids: by default both must have the same shape and physical size (relative 1e-9). With
    ``resample=True`` both are interpolated (cubic splines, as in :func:`resample`) onto one
    common grid: both grids start at 0; the window is the overlap (up to the smaller extent
    per axis); the spacing is the finer of the two per axis (:func:`common_spacing`), so no
    measured detail is thrown away. Two periodic surfaces of equal period stay periodic with
    n = round(period / spacing) points; otherwise the result is non-periodic.

    Parameters
    ----------
    a, b : Topography
        The two surfaces (heights [m]).
    resample : bool
        Bring mismatched grids onto a common grid instead of refusing them.

    Returns
    -------
    Topography
        Composite heights [m]; ``info['sources']`` holds both inputs' info, and the step is
        recorded in ``info['history']``.

    Raises
    ------
    InputError
        A profile with a map (always), or different shapes or sizes without ``resample=True``.

    References
    ----------
    Seed paper 000, section 2 (summed asperities, Fig. 1); seed paper 001, eq. 2.
    doi:10.1115/1.4045900
    """
    _check_same_dim(a, b)
    same_size = all(math.isclose(p, q, rel_tol=1e-9) for p, q in zip(a.size, b.size, strict=True))
    if not resample:
        check_same_grid((a.shape, a.size), (b.shape, b.size))
        heights_a, heights_b, size, periodic = a.heights, b.heights, a.size, a.periodic and b.periodic
        masks = [_masks(a), _masks(b)]
    else:
        spacing = common_spacing(a, b)
        periodic = a.periodic and b.periodic and same_size
        if periodic:
            shape, spacing = _shape_for(a, spacing)
        else:
            shape = tuple(map(min, _points_within(a, spacing), _points_within(b, spacing)))
        heights_a, heights_b = _sample(a, shape, spacing), _sample(b, shape, spacing)
        size = tuple(n * h for n, h in zip(shape, spacing, strict=True))
        masks = [_sample_masks(a, shape, spacing), _sample_masks(b, shape, spacing)]
    heights = heights_a + heights_b
    info = {"name": "composite", "sources": (dict(a.info), dict(b.info))}
    either = {
        name: None
        if masks[0][name] is None and masks[1][name] is None
        else np.logical_or(*(np.zeros(heights.shape, bool) if m[name] is None else m[name] for m in masks))
        for name in ("filled", "specks")
    }
    result = Topography(heights - heights.mean(), size, periodic=periodic, info=info, **either)
    return result.with_heights(result.heights, step=f"combine(resample={resample})")


def central_window(scan: Topography, window: int) -> Topography:
    """Return the central ``window`` x ``window`` pixels of a scan (at its resolution), non-periodic.

    What paper 001 solves of a ball's scan: only the centre touches, and the window's free
    boundary cuts nothing that carries load (the presliding runner checks, ``check_inside``).
    """
    nx, ny = scan.shape
    if window > min(nx, ny):
        raise InputError("window", f"{window} px exceeds the scan ({nx} x {ny}).", "use a smaller window.")
    hx, hy = scan.spacing
    i, j = (nx - window) // 2, (ny - window) // 2
    return crop(scan, ((i - 0.5) * hx, (i + window - 0.5) * hx), ((j - 0.5) * hy, (j + window - 0.5) * hy))
