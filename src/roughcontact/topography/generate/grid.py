"""The grid and the arguments every generator checks: shape and size, the Hurst exponent, lengths per axis."""

from __future__ import annotations

import numpy as np

from ...checks import no_string, positive
from ...errors import InputError

PERIOD_TOLERANCE = 1e-9
"""Relative: a size within this of a whole number of wavelengths is periodic."""


def grid_of(
    shape: int | tuple[int, ...], size: float | tuple[float, ...]
) -> tuple[tuple[int, ...], tuple[float, ...]]:
    """Return the (shape, size [m]) a generator makes of its ``shape`` and ``size`` arguments, checked.

    ``shape`` is 1 or 2 integers >= 2 (an int: a profile), ``size`` positive lengths [m], one or
    one per axis.

    Raises
    ------
    InputError
        Naming ``shape`` or ``size``.
    """
    dims = (shape,) if isinstance(shape, (int, np.integer)) else tuple(shape)
    integers = all(isinstance(n, (int, np.integer)) and not isinstance(n, bool) for n in dims)
    if len(dims) not in (1, 2) or not integers or min(dims) < 2:
        raise InputError(
            "shape",
            f"{shape!r} is not 1 or 2 integers >= 2.",
            "give (nx,) for a profile or (nx, ny) for a map, at least 2 points per axis.",
        )
    no_string(size, "size")
    lengths = np.atleast_1d(np.asarray(size, dtype=float))
    if lengths.size == 1:
        lengths = np.repeat(lengths, len(dims))
    if lengths.shape != (len(dims),) or not np.all(np.isfinite(lengths)) or np.any(lengths <= 0):
        raise InputError(
            "size",
            f"{np.asarray(size, dtype=float).tolist()} is not {len(dims)} positive finite length(s).",
            "give the physical size in metres, one value or one per axis.",
        )
    return tuple(int(n) for n in dims), tuple(float(s) for s in lengths)


def checked_hurst(hurst: float) -> float:
    """Return the Hurst exponent ``hurst`` as a float; InputError outside (0, 1]."""
    hurst = float(hurst)
    if not 0 < hurst <= 1:
        raise InputError(
            "hurst",
            f"Hurst exponent {hurst!r} is outside (0, 1].",
            "give 0 < hurst <= 1 (0.8 is typical of many engineering surfaces).",
        )
    return hurst


def per_axis(value: float | tuple[float, ...], dim: int, field: str, example: str) -> tuple[float, ...]:
    """Return one positive length [m] per axis of ``dim`` from one value or one per axis.

    InputError names ``field`` (with ``example``) where a value is not positive or the count is wrong.
    """
    values = np.atleast_1d(np.asarray(value, dtype=float))
    if values.size == 1:
        values = np.repeat(values, dim)
    if values.shape != (dim,):
        raise InputError(field, f"got {values.size} values for {dim} axes.", f"give one value or {dim}.")
    return tuple(positive(v, field, example=example, unit="m") for v in values)
