"""Argument checks shared by the modules of roughcontact.

Each check returns the value in the form the caller computes with (a float or a float array) or
raises :class:`~roughcontact.errors.InputError` naming the argument (the *field*), showing the
offending value and saying how to fix it, e.g.::

    radius: must be positive and finite, got -0.005. Fix: give a positive number in m, e.g. 5e-3 m.
"""

from __future__ import annotations

import math
from numbers import Real

import numpy as np

from .errors import InputError

__all__ = ["finite_array", "flag", "no_string", "positive"]


def no_string(value, field: str) -> None:
    """Refuse a string (alone or in a list or tuple) where Python takes SI numbers, pointing to quantity.

    The commands and study files read ``"20 MPa"``; Python functions compute with SI floats and
    convert nothing, so ``solve_normal(t, m, mean_pressure="20 MPa")`` would otherwise end in a
    NumPy ``TypeError`` that names neither the argument nor the fix.

    Raises
    ------
    InputError
        ``value`` is a ``str`` or holds one: the fix shows ``quantity(...)`` with the value as typed.
    """
    if isinstance(value, tuple | list):
        for item in value:
            no_string(item, field)
    elif isinstance(value, str):
        raise InputError(
            field,
            f"got the string {value!r}; Python functions take numbers in SI units.",
            f"convert it first: {field}=quantity({value!r}) (from roughcontact import quantity).",
        )


def positive(
    value: float,
    field: str,
    *,
    example: str | float | None = None,
    unit: str = "",
    allow_zero: bool = False,
) -> float:
    """Return ``value`` as a float after checking that it is a positive (or zero) finite number.

    Parameters
    ----------
    value : float
        The value to check: a real number (Python or NumPy scalar, or a 0-d array).
    field : str
        Name of the argument, as the user wrote it; becomes the error's ``field``.
    example : str or float, optional
        A typical value in ``unit``, shown in the fix (``"5e-3"`` with ``unit="m"`` reads
        "e.g. 5e-3 m").
    unit : str, optional
        Unit the value is expected in (``"m"``, ``"Pa"``, ``"N"``); empty for a dimensionless
        value or when ``example`` says it.
    allow_zero : bool, optional
        Accept 0 (the value must then be non-negative instead of positive).

    Returns
    -------
    float
        ``float(value)``.

    Raises
    ------
    InputError
        A bool, a string or anything else that is not a real number; NaN or an infinity; a value
        <= 0 (< 0 with ``allow_zero``). The problem shows the value, the fix gives ``example``
        with its ``unit``.

    Examples
    --------
    >>> positive(5e-3, "radius", example="5e-3", unit="m")
    0.005
    >>> positive(0, "rolloff", allow_zero=True)
    0.0
    """
    bound = "non-negative" if allow_zero else "positive"
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    no_string(value, field)
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, Real):
        problem = f"must be a real number, got {type(value).__name__} {value!r}."
        raise InputError(field, problem, _fix(bound, example, unit))
    number = float(value)
    if not math.isfinite(number) or number < 0 or (number == 0 and not allow_zero):
        shown = f"{number!r} {unit}".rstrip()
        raise InputError(field, f"must be {bound} and finite, got {shown}.", _fix(bound, example, unit))
    return number


def _fix(bound: str, example: str | float | None, unit: str) -> str:
    fix = f"give a {bound} number"
    if unit:
        fix += f" in {unit}"
    if example is not None:
        fix += f", e.g. {example} {unit}".rstrip()
    return fix + "."


def finite_array(values, field: str) -> np.ndarray:
    """Return ``values`` as a float array after checking that every element is finite.

    Parameters
    ----------
    values : array_like
        Numbers (a scalar, a sequence or an array of any shape).
    field : str
        Name of the argument, as the user wrote it; becomes the error's ``field``.

    Returns
    -------
    numpy.ndarray
        ``numpy.asarray(values, dtype=float)`` (a 0-d array for a scalar).

    Raises
    ------
    InputError
        Values that are not numbers, or NaN or infinite elements (the problem counts them).

    Examples
    --------
    >>> finite_array([0.0, 1e-6], "displacement")
    array([0.e+00, 1.e-06])
    """
    try:
        array = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise InputError(
            field, f"must be numbers, got {values!r}.", "give a number or a sequence of numbers."
        ) from None
    bad = int(np.count_nonzero(~np.isfinite(array)))
    if bad:
        raise InputError(
            field,
            f"{bad} of {array.size} values are NaN or infinite.",
            "remove or interpolate the missing samples.",
        )
    return array


def poissons_ratio_checked(value: float, field: str = "poissons_ratio") -> float:
    """Return ``value`` as a float after checking that it is a Poisson's ratio, -1 < nu <= 0.5.

    Parameters
    ----------
    value : float
        The ratio (0.5 is incompressible, e.g. rubber).
    field : str
        The name of the input, for the error.

    Raises
    ------
    InputError
        A bool, a non-number, or a value outside (-1, 0.5].
    """
    if isinstance(value, bool) or not isinstance(value, Real) or not (-1.0 < value <= 0.5):
        raise InputError(
            field,
            f"{value!r} is outside (-1, 0.5].",
            "give a Poisson's ratio with -1 < nu <= 0.5 (0.5 = incompressible, e.g. rubber).",
        )
    return float(value)


def flag(value, field: str) -> bool:
    """Return ``value`` as a bool after checking that it is one (``True``/``False``, NumPy's too).

    ``periodic="no"`` would otherwise be truthy and silently mean the opposite of what was meant.
    """
    if isinstance(value, bool | np.bool_):
        return bool(value)
    raise InputError(field, f"expected True or False, got {value!r}.", f"pass {field}=True or {field}=False.")
