"""The immutable :class:`Topography`: heights in metres on a regular grid of known physical size.

Conventions (used everywhere in roughcontact)
---------------------------------------------
* Array axis 0 is x, axis 1 is y. ``heights[i, j]`` is the height at
  ``x = i * spacing[0]``, ``y = j * spacing[1]`` (pixel corners, first pixel at 0).
* Heights and sizes are in metres. Positive heights point out of the body, towards
  the counter-surface.
* ``size`` is the physical extent of the grid: ``shape[k] * spacing[k]``. For a periodic
  topography it is the period.
* A 1D topography is a line scan (profile) along x.
* Every height is finite: missing points are dealt with when a file is read
  (:func:`roughcontact.topography.io.read_topography`, ``undefined=``), never carried silently.
  Points whose heights were invented (``filled``: interpolated where the instrument recorded
  nothing) and measured points standing alone amid undefined ones (``specks``) stay marked, so
  that a result resting on them can say so (:mod:`roughcontact.contact.trust`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

import numpy as np

from ..checks import flag, no_string
from ..errors import InputError

LARGEST = 1e100
"""Largest magnitude of a height or a physical size [m] that roughcontact computes with.

Beyond it float64 overflows in the sums every surface needs: the squares of its heights, slopes
and curvatures summed over a grid of up to 1e10 points with pixels down to a femtometre stay below
1e270 (float64 ends at 1.8e308); a height of 1e300 m already overflows its own square. Such a
number is no height (a typo, or an instrument's marker of a missing point) and is refused where
it is read, naming the point."""


def largest_point(values: np.ndarray) -> tuple[tuple[int, ...], float] | None:
    """Return the index and the value of the first value beyond :data:`LARGEST` in magnitude (None if none).

    NaN (an undefined point) is not beyond it.
    """
    with np.errstate(invalid="ignore"):
        beyond = np.abs(values) > LARGEST
    if not beyond.any():
        return None
    index = tuple(int(i) for i in np.argwhere(beyond)[0])
    return index, float(values[index])


KEEP = object()
"""Default of :meth:`Topography.with_heights`' masks: keep the present ones (None removes them)."""


def _frozen_mapping(info: Mapping[str, Any] | None) -> Mapping[str, Any]:
    return MappingProxyType(dict(info or {}))


def _mask(mask, shape: tuple[int, ...], name: str) -> np.ndarray | None:
    """Return a read-only bool copy of ``mask`` (None when absent or all False); refuse another shape."""
    if mask is None:
        return None
    mask = np.array(mask, dtype=bool)
    if mask.shape != shape:
        raise InputError(name, f"mask of shape {mask.shape} on a grid of {shape}.", "give one per point.")
    if not mask.any():
        return None
    mask.flags.writeable = False
    return mask


def _same_mask(a: np.ndarray | None, b: np.ndarray | None) -> bool:
    return (a is None and b is None) or (a is not None and b is not None and np.array_equal(a, b))


@dataclass(frozen=True, eq=False)
class Topography:
    """A measured or generated surface: heights [m] on a regular grid of physical ``size`` [m].

    Parameters
    ----------
    heights : array_like, shape (nx,) or (nx, ny)
        Surface heights in metres. Must be finite. Copied and made read-only.
    size : float or tuple of float
        Physical extent in metres along each axis (one value per axis; a scalar is
        accepted for a 1D profile or a square map).
    periodic : bool
        Whether the surface repeats with period ``size`` (generated surfaces usually do,
        measured ones do not).
    info : mapping, optional
        Metadata: source file, instrument, channel, units of the file, processing history.
    filled : ndarray of bool, optional
        True where the height was interpolated, not measured (undefined points of the file that
        were filled). None (or all False) when every height was measured.
    specks : ndarray of bool, optional
        True at measured points in groups of a few standing alone amid undefined ones
        (:func:`roughcontact.topography.process.find_specks`): often outliers of an instrument
        that lost the region. None when there are none.

    Raises
    ------
    InputError
        Empty or non-finite heights, a height beyond ``LARGEST`` (1e100 m) in magnitude, a size that
        is not positive and finite (or beyond ``LARGEST``), or a size whose number of values does
        not match the number of axes, masks of another shape.
    """

    heights: np.ndarray
    size: tuple[float, ...]
    periodic: bool = False
    info: Mapping[str, Any] = field(default_factory=dict)
    filled: np.ndarray | None = None
    specks: np.ndarray | None = None

    def __post_init__(self):
        heights = np.array(self.heights, dtype=float)  # always a private copy
        if heights.ndim not in (1, 2):
            raise InputError(
                "heights",
                f"expected a 1D profile or a 2D map, got an array with {heights.ndim} dimensions.",
                "pass heights of shape (nx,) or (nx, ny).",
            )
        if heights.size == 0 or min(heights.shape) < 2:
            raise InputError(
                "heights",
                f"grid {heights.shape} has fewer than 2 points along an axis.",
                "give at least 2 x 2 points (2 for a profile).",
            )
        bad = ~np.isfinite(heights)
        if bad.any():
            raise InputError(
                "heights",
                f"{int(bad.sum())} of {heights.size} heights are NaN or infinite.",
                "fill them first (read_topography(..., undefined='interpolate')) or crop them away.",
            )
        huge = largest_point(heights)
        if huge is not None:
            index, value = huge
            point = ", ".join(str(i) for i in index)
            raise InputError(
                "heights",
                f"the height at point ({point}) is {value:.3g} m, beyond {LARGEST:.0e} m: no surface is "
                "that high, and the sums of squares of such heights overflow.",
                "correct that value (a typo, or an instrument's marker of a missing point: make it NaN "
                "and fill it, roughcontact.topography.process.fill_undefined).",
            )
        no_string(self.size, "size")
        size = np.atleast_1d(np.asarray(self.size, dtype=float))
        if size.size == 1 and heights.ndim == 2:
            size = np.repeat(size, 2)
        if size.shape != (heights.ndim,):
            raise InputError(
                "size",
                f"got {size.size} values for a {heights.ndim}D topography.",
                f"give {heights.ndim} physical lengths in metres.",
            )
        if not np.all(np.isfinite(size)) or np.any(size <= 0) or np.any(size > LARGEST):
            raise InputError(
                "size",
                f"physical size {tuple(float(s) for s in size)} m must be positive and finite "
                f"(at most {LARGEST:.0e} m).",
                "give the scan size in metres (or with a unit at the CLI, e.g. '10 um').",
            )
        heights.flags.writeable = False
        for name in ("filled", "specks"):
            object.__setattr__(self, name, _mask(getattr(self, name), heights.shape, name))
        object.__setattr__(self, "heights", heights)
        object.__setattr__(self, "size", tuple(float(s) for s in size))
        object.__setattr__(self, "periodic", flag(self.periodic, "periodic"))
        object.__setattr__(self, "info", _frozen_mapping(self.info))

    # --- geometry -------------------------------------------------------------------------------
    @property
    def dim(self) -> int:
        """Number of axes: 1 for a profile, 2 for a map."""
        return self.heights.ndim

    @property
    def shape(self) -> tuple[int, ...]:
        """Number of grid points along each axis."""
        return self.heights.shape

    @property
    def spacing(self) -> tuple[float, ...]:
        """Pixel size [m] along each axis, ``size / shape``."""
        return tuple(s / n for s, n in zip(self.size, self.shape, strict=True))

    @property
    def pixel_area(self) -> float:
        """Area of one pixel [m^2] (length [m] for a profile)."""
        return math.prod(self.spacing)

    @property
    def area(self) -> float:
        """Nominal (projected) area [m^2] (length [m] for a profile)."""
        return math.prod(self.size)

    def coordinates(self) -> tuple[np.ndarray, ...]:
        """Return the 1D coordinate arrays [m] of the grid points, one per axis."""
        return tuple(np.arange(n) * h for n, h in zip(self.shape, self.spacing, strict=True))

    def meshgrid(self) -> tuple[np.ndarray, ...]:
        """Return coordinate arrays [m] broadcast to ``shape`` (``indexing='ij'``)."""
        return tuple(np.meshgrid(*self.coordinates(), indexing="ij"))

    # --- derived surfaces -----------------------------------------------------------------------
    def with_heights(
        self,
        heights: np.ndarray,
        *,
        step: str | None = None,
        size: float | tuple[float, ...] | None = None,
        periodic: bool | None = None,
        info: Mapping[str, Any] | None = None,
        filled: np.ndarray | None | object = KEEP,
        specks: np.ndarray | None | object = KEEP,
    ) -> Topography:
        """Return a new topography with other heights (on the same grid unless ``size``).

        Parameters
        ----------
        heights : ndarray
            New heights [m], same shape as ``self.heights`` unless a new ``size`` comes with them.
        step : str, optional
            Processing step appended to ``info['history']``.
        size, periodic, info : optional
            Replacements of these fields (None: kept).
        filled, specks : ndarray of bool or None, optional
            Replacements of the masks (None: no mask; default :data:`KEEP`, the present ones).
        """
        heights = np.asarray(heights, dtype=float)
        if size is None and heights.shape != self.shape:
            raise InputError(
                "heights",
                f"shape {heights.shape} does not match the grid {self.shape}.",
                "pass a new size together with a new grid.",
            )
        info = dict(self.info if info is None else info)
        if step:
            info["history"] = (*info.get("history", ()), step)
        changes: dict[str, Any] = {
            name: value for name, value in (("size", size), ("periodic", periodic)) if value is not None
        }
        masks = {"filled": filled, "specks": specks}
        changes |= {name: value for name, value in masks.items() if value is not KEEP}
        return replace(self, heights=heights, info=info, **changes)

    def __repr__(self) -> str:
        size_um = " x ".join(f"{s * 1e6:.4g}" for s in self.size)
        grid = " x ".join(str(n) for n in self.shape)
        name = self.info.get("name") or self.info.get("source", "")
        label = f" {name!r}" if name else ""
        return f"<Topography{label} {grid} points, {size_um} um, periodic={self.periodic}>"

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Topography):
            return NotImplemented
        return (
            self.size == other.size
            and self.periodic == other.periodic
            and np.array_equal(self.heights, other.heights)
            and dict(self.info) == dict(other.info)
            and all(_same_mask(getattr(self, n), getattr(other, n)) for n in ("filled", "specks"))
        )

    __hash__ = None  # mutable-looking numpy content; equality is by value


def topography_argument(value, field: str = "topography") -> Topography:
    """Return ``value`` after checking that it is a :class:`Topography` (for the public solvers).

    A NumPy array of heights carries no physical size; the fix says how to give it one.

    Raises
    ------
    InputError
        ``value`` is not a Topography.
    """
    if isinstance(value, Topography):
        return value
    if isinstance(value, np.ndarray):
        fix = f"give the heights their size, Topography(heights, size=5e-6) in metres, as {field}."
    else:
        fix = "read one with read_topography(path) or make one with roughcontact.generate."
    raise InputError(field, f"expected a Topography, got {type(value).__name__}.", fix)
