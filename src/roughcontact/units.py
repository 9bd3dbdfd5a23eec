"""Physical quantities written with units, converted once to SI.

This is the only module that parses unit strings. Users speak "20 nm", "70 GPa",
"72 mJ/m^2", "10 uN", "0.1 um/s"; the code works in m, kg, s, N, Pa and J.

Grammar: ``<number> <unit>`` where ``<unit>`` is a product/quotient of SI-prefixed
symbols with optional integer powers, e.g. ``mJ/m^2``, ``N*m``, ``um/s``,
``m**-1``. The micro prefix may be written ``u``, ``µ`` (U+00B5) or ``μ`` (U+03BC).

Dimensions are exponent triples (length, mass, time); an expected dimension is
given by name (``"length"``, ``"pressure"``, ...) and a mismatch raises
:class:`~roughcontact.errors.UnitError` naming the value and what was expected.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from decimal import Decimal
from numbers import Real
from typing import Any

from .errors import UnitError

Dimension = tuple[int, int, int]  # exponents of (m, kg, s)

DIMENSIONS: dict[str, Dimension] = {
    "dimensionless": (0, 0, 0),
    "length": (1, 0, 0),
    "area": (2, 0, 0),
    "inverse_length": (-1, 0, 0),
    "inverse_area": (-2, 0, 0),  # spectral moment m4 (1/m^2)
    "time": (0, 0, 1),
    "frequency": (0, 0, -1),
    "velocity": (1, 0, -1),
    "force": (1, 1, -2),
    "force_rate": (1, 1, -3),
    "pressure": (-1, 1, -2),
    "energy": (2, 1, -2),
    "surface_energy": (0, 1, -2),  # J/m^2 = N/m
    "stiffness": (0, 1, -2),  # N/m, same dimension as surface energy
}

SI_UNITS: dict[str, str] = {
    "dimensionless": "",
    "length": "m",
    "area": "m^2",
    "inverse_length": "1/m",
    "inverse_area": "1/m^2",
    "time": "s",
    "frequency": "Hz",
    "velocity": "m/s",
    "force": "N",
    "force_rate": "N/s",
    "pressure": "Pa",
    "energy": "J",
    "surface_energy": "J/m^2",
    "stiffness": "N/m",
}
"""The SI unit each dimension is computed in."""

_PREFIXES = {
    p: Decimal(f"1e{e}")
    for p, e in {
        "Y": 24, "Z": 21, "E": 18, "P": 15, "T": 12, "G": 9, "M": 6, "k": 3, "h": 2, "da": 1,
        "d": -1, "c": -2, "m": -3, "u": -6, "n": -9, "p": -12, "f": -15, "a": -18,
    }.items()
}  # fmt: skip

# symbol -> (factor to SI, dimension); prefixable symbols only. Factors are Decimals so that
# "10 uN" becomes exactly the float nearest 1e-5, not 9.999999999999999e-06.
_BASE_UNITS: dict[str, tuple[Decimal, Dimension]] = {
    "m": (Decimal(1), DIMENSIONS["length"]),
    "g": (Decimal("1e-3"), (0, 1, 0)),
    "s": (Decimal(1), DIMENSIONS["time"]),
    "N": (Decimal(1), DIMENSIONS["force"]),
    "Pa": (Decimal(1), DIMENSIONS["pressure"]),
    "J": (Decimal(1), DIMENSIONS["energy"]),
    "Hz": (Decimal(1), DIMENSIONS["frequency"]),
}
# symbols that take no prefix
_PLAIN_UNITS: dict[str, tuple[Decimal, Dimension]] = {
    "Å": (Decimal("1e-10"), DIMENSIONS["length"]),
    "angstrom": (Decimal("1e-10"), DIMENSIONS["length"]),
    "micron": (Decimal("1e-6"), DIMENSIONS["length"]),
    "microns": (Decimal("1e-6"), DIMENSIONS["length"]),
    "in": (Decimal("0.0254"), DIMENSIONS["length"]),
    "min": (Decimal(60), DIMENSIONS["time"]),
    "h": (Decimal(3600), DIMENSIONS["time"]),
    "bar": (Decimal("1e5"), DIMENSIONS["pressure"]),
    "psi": (Decimal("6894.757293168361"), DIMENSIONS["pressure"]),
    "%": (Decimal("1e-2"), DIMENSIONS["dimensionless"]),
}

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_QUANTITY_RE = re.compile(rf"^\s*({_NUMBER})\s*(.*?)\s*$")
_FACTOR_RE = re.compile(r"^([^^]+?)(?:\^([-+]?\d+))?$")


def _normalise(unit: str) -> str:
    return (
        unit.replace("**", "^")
        .replace("µ", "u")
        .replace("μ", "u")
        .replace("·", "*")
        .replace(" ", "")
        .replace("²", "^2")
    )


def _symbol(symbol: str) -> tuple[Decimal, Dimension]:
    if symbol in _PLAIN_UNITS:
        return _PLAIN_UNITS[symbol]
    if symbol in _BASE_UNITS:
        return _BASE_UNITS[symbol]
    for prefix in sorted(_PREFIXES, key=len, reverse=True):
        rest = symbol[len(prefix) :]
        if symbol.startswith(prefix) and rest in _BASE_UNITS:
            factor, dimension = _BASE_UNITS[rest]
            return _PREFIXES[prefix] * factor, dimension
    raise KeyError(symbol)


def _terms(unit: str) -> list[tuple[str, int]]:
    """Split a unit expression into (symbol, power) terms: ``"mJ/m^2"`` -> ``[("mJ", 1), ("m", -2)]``.

    Symbols are checked by :func:`_symbol`; an unreadable term or an unknown symbol raises
    :class:`UnitError`.
    """
    text = _normalise(unit)
    if text in ("", "1"):
        return []
    numerator, *denominators = text.split("/")
    parts = [(p, 1) for p in numerator.split("*") if p not in ("", "1")]
    for den in denominators:
        parts += [(p, -1) for p in den.split("*")]
    terms = []
    for part, sign in parts:
        match = _FACTOR_RE.match(part)
        if match is None:
            raise UnitError(
                "unit", f"cannot read {unit!r}.", "write units like 'nm', 'GPa', 'mJ/m^2', 'um/s'."
            )
        symbol, power = match.group(1), int(match.group(2) or 1) * sign
        try:
            _symbol(symbol)
        except KeyError:
            raise UnitError(
                "unit",
                f"unknown unit symbol {symbol!r} in {unit!r}.",
                "use SI symbols with prefixes (nm, um, mm, m, uN, mN, N, MPa, GPa, mJ/m^2, s).",
            ) from None
        terms.append((symbol, power))
    return terms


def unit_factor(unit: str) -> tuple[Decimal, Dimension]:
    """Return the factor to SI and the dimension of a unit expression.

    Parameters
    ----------
    unit : str
        Unit expression such as ``"nm"``, ``"mJ/m^2"`` or ``"uN/s"``; ``""`` is dimensionless.

    Returns
    -------
    factor : decimal.Decimal
        Multiply a value in ``unit`` by this to get SI (exact decimal arithmetic).
    dimension : tuple of int
        Exponents of (m, kg, s).

    Raises
    ------
    UnitError
        If a symbol is unknown.
    """
    factor, dims = Decimal(1), [0, 0, 0]
    for symbol, power in _terms(unit):
        sym_factor, sym_dim = _symbol(symbol)
        factor *= sym_factor**power
        dims = [d + power * s for d, s in zip(dims, sym_dim, strict=True)]
    return factor, (dims[0], dims[1], dims[2])


def split_quantity(text: str, *, field: str = "value") -> tuple[str, str]:
    """Split ``"20 nm"`` into its number and unit as written: ``("20", "nm")``; ``"3"`` gives ``("3", "")``.

    Raises
    ------
    UnitError
        ``text`` does not start with a number.
    """
    match = _QUANTITY_RE.match(text)
    if match is None:
        raise UnitError(field, f"cannot read {text!r} as a number with a unit.", "write e.g. '1 uN'.")
    number, unit = match.groups()
    return number, unit


def _dimension_name(dimension: Dimension) -> str:
    names = [name for name, dim in DIMENSIONS.items() if dim == dimension]
    return " or ".join(names) if names else f"m^{dimension[0]} kg^{dimension[1]} s^{dimension[2]}"


def quantity(
    value: str | Real, expected: str | None = None, *, field: str = "value", require_unit: bool = False
) -> float:
    """Convert a quantity to SI, checking its dimension.

    Parameters
    ----------
    value : str or float
        ``"20 nm"``, ``"70 GPa"``, ... A bare number (or a string holding only a number)
        is taken to be in SI already, unless ``require_unit``.
    expected : str, optional
        Expected dimension, a key of :data:`DIMENSIONS` (``"length"``, ``"pressure"``, ...).
        Without it any known unit is converted (``quantity("20 MPa")`` is 2e7): what a Python user
        types to turn a value with a unit into the SI number a function takes.
    field : str
        Name of the input, used in error messages.
    require_unit : bool
        Refuse a bare number of a dimensional quantity (zero excepted: it is zero in any unit),
        suggesting the units the user probably meant. The edges set it (command options, study
        files): there ``--size 5`` meaning a 5 m AFM scan, or ``--pressure 20`` meaning 20 Pa, is
        a silent wrong answer, whereas Python code computes in SI throughout.

    Returns
    -------
    float
        The value in SI units.

    Raises
    ------
    UnitError
        Unknown unit, unreadable value or wrong dimension; the message names ``field``,
        the value and the expected dimension.

    Examples
    --------
    >>> quantity("72 mJ/m^2", "surface_energy")
    0.072
    """
    if expected is not None and expected not in DIMENSIONS:
        raise ValueError(f"unknown dimension {expected!r}; choose from {sorted(DIMENSIONS)}")
    if require_unit and expected not in ("dimensionless", None):
        _refuse_bare(value, expected, field)
    if isinstance(value, Real) and not isinstance(value, bool):
        result = float(value)
    elif isinstance(value, str):
        match = _QUANTITY_RE.match(value)
        if match is None:
            raise UnitError(
                field,
                f"cannot read {value!r} as a {expected or 'quantity'}.",
                f"write a number and a unit, e.g. {_EXAMPLES.get(expected, '20 MPa')!r}.",
            )
        number, unit = match.groups()
        try:
            factor, dimension = unit_factor(unit)
        except UnitError as error:
            raise UnitError(field, f"{error.problem} (in {value!r})", error.fix) from None
        if unit and expected is not None and dimension != DIMENSIONS[expected]:
            raise UnitError(
                field,
                f"{value!r} is a {_dimension_name(dimension)}, expected a {expected}.",
                f"give a {expected}, e.g. {_EXAMPLES.get(expected, '1')!r}.",
            )
        result = float(Decimal(number) * factor)
    else:
        raise UnitError(field, f"expected a number or a string with a unit, got {type(value).__name__}.")
    if not math.isfinite(result):
        raise UnitError(field, f"{value!r} is not finite.", "give a finite number.")
    return result


_LIKELY_UNITS = {
    "length": ("um", "nm"),
    "area": ("um^2",),
    "inverse_length": ("1/um",),
    "inverse_area": ("1/um^2",),
    "time": ("s", "ms"),
    "velocity": ("um/s",),
    "force": ("mN", "uN"),
    "force_rate": ("uN/s",),
    "pressure": ("MPa", "GPa"),
    "energy": ("nJ",),
    "surface_energy": ("mJ/m^2",),
    "stiffness": ("N/m",),
    "frequency": ("Hz",),
}
"""Units a bare number of each dimension was probably meant in (MEMS and AFM scales), first most likely."""


def _refuse_bare(value: str | Real, expected: str, field: str) -> None:
    """Raise UnitError for a bare non-zero number of ``expected``, suggesting the units it may have meant."""
    if isinstance(value, bool) or not isinstance(value, str | Real):
        return  # quantity's own type check says what is wrong
    text = str(value).strip()
    if not re.fullmatch(_NUMBER, text) or float(text) == 0.0:
        return
    si = SI_UNITS[expected]
    guesses = " or ".join(repr(f"{text} {unit}") for unit in _LIKELY_UNITS.get(expected, ()))
    name = expected.replace("_", " ")
    raise UnitError(
        field,
        f"{text} has no unit, and {'an' if name[0] in 'aeiou' else 'a'} {name} needs one.",
        f"did you mean {guesses}? Write the unit, even for SI ('{text} {si}').",
    )


def length_unit_factor(unit: str, *, field: str = "unit") -> float:
    """Return the factor that converts lengths in ``unit`` (e.g. ``"nm"``, ``"µm"``) to metres.

    A unit that cannot be read, or is not a length, is refused naming ``field`` (the option or key
    that gave it).
    """
    try:
        factor, dimension = unit_factor(unit)
    except UnitError as error:
        raise UnitError(field, error.problem, "give one of 'nm', 'um', 'mm', 'm'.") from None
    if dimension != DIMENSIONS["length"]:
        raise UnitError(field, f"{unit!r} is not a length unit.", "give one of 'nm', 'um', 'mm', 'm'.")
    return float(factor)


_EXAMPLES = {
    "length": "20 nm",
    "area": "1 um^2",
    "time": "5 s",
    "velocity": "0.1 um/s",
    "force": "10 uN",
    "force_rate": "50 uN/s",
    "pressure": "70 GPa",
    "energy": "1 nJ",
    "surface_energy": "72 mJ/m^2",
    "stiffness": "35.5 N/m",
    "inverse_length": "1 1/um",
    "inverse_area": "0.0171 1/um^2",
    "frequency": "1 Hz",
}


_DISPLAY_PREFIXES = (
    ("T", 12), ("G", 9), ("M", 6), ("k", 3), ("", 0), ("m", -3), ("µ", -6), ("n", -9), ("p", -12),
    ("f", -15), ("a", -18),
)  # fmt: skip
"""The prefixes values are shown with (symbol, power of ten), largest first."""
_DENOMINATOR_PREFIXES = (("m", -3), ("µ", -6), ("n", -9))
"""Prefixes a quotient's denominator takes when no prefix of its numerator reads (``GPa/µm``)."""
_CORE_PREFIXES = ("G", "M", "k", "", "m", "µ", "n", "p")
"""The numerator prefixes that go with a prefixed denominator (``GPa/µm``, not ``TPa/mm``)."""
_SAME_AS = {"kN/m": "mN/µm", "MN/m": "N/µm"}
"""Labels written in an equal unit: a stiffness in paper 001's mN and µm (K_L in mN/µm, not kN/m)."""
_SUPERSCRIPTS = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
MISSING = "none"
"""What a quantity without a value (None, NaN) reads as, in place of a number and a unit."""
READABLE = (1e-3, 1e6)
"""The numbers written without an exponent (``0.001234``, ``20190``): where a prefix cannot put a
value between 1 and 1000 (a square steps six decades a prefix) it may stay in this range."""


def _label(terms: list[tuple[str, int]], prefixes: dict[int, str] | None = None) -> str:
    """Write (symbol, power) terms as a unit label, ``prefixes[k]`` on term number k: "µm²", "GPa/µm"."""
    prefixes = prefixes or {}

    def term(index: int, symbol: str, power: int) -> str:
        shown = prefixes.get(index, "") + symbol
        return shown if abs(power) == 1 else shown + str(abs(power)).translate(_SUPERSCRIPTS)

    numerator = [term(k, s, p) for k, (s, p) in enumerate(terms) if p > 0]
    denominator = [term(k, s, p) for k, (s, p) in enumerate(terms) if p < 0]
    if not denominator:
        return "·".join(numerator)
    return "·".join(numerator or ["1"]) + "".join(f"/{d}" for d in denominator)


def _decades_outside(value: float, scale: float) -> float:
    """How many decades ``value / scale`` lies outside [1, 1000) (0 inside)."""
    shown = math.log10(abs(value) / scale)
    return max(-shown, shown - math.log10(1000 * (1 - 1e-12)), 0.0)


def prefixed_scale(value: float, unit: str) -> tuple[float, str]:
    """Return ``(scale, label)``: the SI prefix in which ``value`` [``unit``] reads between 1 and 1000.

    ``value / scale`` is the number to show in ``label``. The prefix (T, G, M, k, none, m, µ, n,
    p, f, a; powers of 1000) goes on the first prefixable symbol of the numerator (of the
    denominator when the numerator has none) and acts with that symbol's power, so areas and
    inverse lengths are shown in prefixed metres: 3e-12 m^2 is 3 µm² and 2e6 1/m is 2 1/µm. The
    prefix whose number ``value / scale`` lies in [1, 1000), or nearest to it in decades, is chosen
    (a square steps six decades a prefix: 5.4e-13 m^2 is 0.54 µm², not 5.4e5 nm²). A quotient
    whose numerator no prefix puts there also prefixes its denominator, with the largest of m, µ,
    n that does beside a numerator prefix from G to p (9.8e17 Pa/m is 978.7 GPa/µm); a stiffness
    in kN/m or MN/m is labelled in the equal mN/µm or N/µm (paper 001's K_L, in its mN and µm).
    0 and non-finite values and units without a prefixable symbol (``""``, ``"%"``) get scale 1.
    Powers are written as superscripts and products with a middle dot (``"N*m"`` -> ``"N·m"``).

    This chooses a scale: an axis or a column shows numbers in it. To write one number use
    :func:`format_si`, which never writes a prefix with an exponent (a value no prefix brings
    near [1, 1000) is written in the SI unit, ``8.164e-22 J``).

    Parameters
    ----------
    value : float
        Value in the SI unit ``unit`` (typically the typical or largest magnitude to be shown).
    unit : str
        Unit expression without prefixes: ``"m"``, ``"Pa"``, ``"N"``, ``"J"``, ``"m^2"``, ``"N/m"``,
        ``"J/m^2"``, ``"1/m"``; symbols that take no prefix (``"%"``, ``"min"``) are kept as written.

    Returns
    -------
    scale : float
        SI value of one ``label``: 1e-6 for "µm", 1e-12 for "µm²", 1e-3 for "mN/m", 1e6 for "1/µm".
    label : str
        The prefixed unit.

    Raises
    ------
    UnitError
        An unknown symbol, or a prefixed one (``"nm"``, ``"kN/m"``; ``"kg"`` is allowed).

    Examples
    --------
    >>> prefixed_scale(2.5e-8, "m")
    (1e-09, 'nm')
    >>> prefixed_scale(3e-12, "m^2")
    (1e-12, 'µm²')
    >>> prefixed_scale(4e4, "N/m")
    (1000.0, 'mN/µm')
    """
    terms = _terms(unit)
    prefixed = [s for s, _ in terms if s not in _BASE_UNITS and s not in _PLAIN_UNITS and s != "kg"]
    if prefixed:
        raise UnitError(
            "unit",
            f"{unit!r} has the prefixed symbol {prefixed[0]!r}; the value must be in unprefixed units.",
            "give the value in SI: m, N, Pa, J, m^2, N/m.",
        )
    prefixable = [k for k, (symbol, power) in enumerate(terms) if symbol in _BASE_UNITS and power > 0]
    prefixable += [k for k, (symbol, power) in enumerate(terms) if symbol in _BASE_UNITS and power < 0]
    if not prefixable or value == 0 or not math.isfinite(value):
        return 1.0, _label(terms)
    index = prefixable[0]
    power = terms[index][1]
    choices = sorted(
        ((float(f"1e{exponent * power}"), prefix) for prefix, exponent in _DISPLAY_PREFIXES), reverse=True
    )
    scale, prefix = min(
        choices, key=lambda c: (_decades_outside(value, c[0]), -math.log10(abs(value) / c[0]))
    )
    prefixes = {index: prefix}
    below = [k for k in prefixable[1:] if terms[k][1] == -1 and power > 0]
    if _decades_outside(value, scale) > 0 and below:
        for den_prefix, den_exponent in _DENOMINATOR_PREFIXES:
            fits = [
                (s * float(f"1e{-den_exponent}"), p)
                for s, p in choices
                if p in _CORE_PREFIXES and _decades_outside(value, s * float(f"1e{-den_exponent}")) == 0
            ]
            if fits:
                scale, prefix = fits[0]
                prefixes = {index: prefix, below[0]: den_prefix}
                break
    label = _label(terms, prefixes)
    return scale, _SAME_AS.get(label, label)


def _fixed(number: float, digits: int) -> str | None:
    """Write ``number`` to ``digits`` significant digits, no exponent; None outside :data:`READABLE`."""
    text = f"{number:.{digits}g}"
    rounded = float(text)
    if rounded == 0:
        return "0"
    if not READABLE[0] <= abs(rounded) < READABLE[1]:
        return None
    return f"{rounded:.0f}" if "e+" in text else text


def written(value: float, unit: str) -> str:
    """Write an SI value as a study file or an option takes it, exactly (``2.805e-6 m`` as ``"2.805 um"``).

    The prefix of :func:`prefixed_scale` (in ASCII: ``u`` for micro, ``^2`` for a square) and the
    number to 15 significant digits, so that :func:`quantity` reads back the float that was
    written wherever the value is a short decimal (as the papers' numbers are).

    Examples
    --------
    >>> written(10e-6, "N"), written(6.25e-10, "m^2"), written(0.05, "J/m^2")
    ('10 uN', '625 um^2', '50 mJ/m^2')
    """
    scale, label = prefixed_scale(value, unit)
    ascii_label = label.replace("µ", "u").replace("²", "^2").replace("³", "^3").replace("·", "*")
    return f"{value / scale:.15g} {ascii_label}".strip()


def format_si(value: float | None, unit: str, *, digits: int = 4, missing: str = MISSING) -> str:
    """Write one SI value with the SI prefix that puts it between 1 and 1000 (see :func:`prefixed_scale`).

    The rule for every number shown with a unit (tables, summaries, reports, figure titles):
    never a prefix together with an exponent. Where no prefix brings the number into [1, 1000)
    (a square steps six decades a prefix) the nearest one is used while the number still reads
    without an exponent (:data:`READABLE`: ``20190 1/mm²``, ``0.54 µm²``); a value beyond that
    (beyond the prefixes T to a, e.g. a numerical zero ``8.164e-22 J``) is written with an
    exponent in the unprefixed SI unit. A missing value (None or NaN) reads as ``missing``, a
    word, never as a bare unit.

    Parameters
    ----------
    value : float or None
        Value in the SI unit ``unit``.
    unit : str
        Unprefixed SI unit (``"m"``, ``"Pa"``, ``"N"``, ``"N/m"``, ``"m^2"``).
    digits : int
        Significant digits.
    missing : str
        The text of a missing value (``"none (no jump)"``).

    Examples
    --------
    >>> format_si(2.5e-8, "m")
    '25 nm'
    >>> format_si(3e-12, "m^2")
    '3 µm²'
    >>> format_si(8.164e-22, "J"), format_si(None, "m")
    ('8.164e-22 J', 'none')
    """
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return missing
    rounded = float(f"{value:.{digits}g}")  # 999.99996 nm is 1 µm to four digits, not 1000 nm
    scale, label = prefixed_scale(rounded, unit)
    text = _fixed(value / scale, digits) if math.isfinite(value) else f"{value}"
    if text is None:
        text, label = f"{value:.{digits}g}", prefixed_scale(0.0, unit)[1]
    return f"{text} {label}".rstrip()


DIGITS = 4
"""Significant digits of every number shown."""


def number(value: Any) -> float | int | None:
    """Return the value as a number (an int stays one), or None for text, booleans, blanks and NaN."""
    if isinstance(value, bool) or value is None:
        return None
    if isinstance(value, int):
        return value
    if isinstance(value, str):
        text = value.strip()
        if text.lstrip("+-").isdigit():
            return int(text)
        try:
            value = float(text)
        except ValueError:
            return None
    try:
        value = float(value)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def blank(value: Any) -> bool:
    """Tell whether a table shows the value as an empty cell: None, "", NaN (as a number or as text)."""
    if value is None or (isinstance(value, str) and value.strip().lower() in ("", "nan")):
        return True
    return isinstance(value, float) and math.isnan(value)


def shown(value: Any, unit: str | None, missing: str = MISSING) -> str:
    """One value as text with its own SI prefix and unit (``2.81 µm``); labels as they are.

    A missing value (None, NaN, blank) reads ``missing``, not a bare unit. The one rule of a
    single value, in the commands' summaries and in a result's display in a notebook.
    """
    if isinstance(value, list):
        return ", ".join(shown(v, unit, missing) for v in value)
    numeric = number(value)
    if numeric is None:
        return missing if blank(value) or isinstance(value, float) else str(value)
    if isinstance(numeric, int) and not unit:
        return str(numeric)
    return format_si(numeric, unit, digits=DIGITS) if unit else f"{numeric:.{DIGITS}g}"


def common_scale(values: Sequence[float], unit: str, *, digits: int = 4) -> tuple[float, str] | None:
    """Return the one prefix in which values of one quantity are shown together (a table column).

    The prefix of :func:`prefixed_scale` for the median magnitude of the non-zero finite values, so
    the typical value reads between 1 and 1000 and the unit can go in the column header. Values
    far from the median then read with more digits in that prefix (``0.0015``, ``20190``); where
    one would need an exponent in it (the column spans more than about nine decades, as a
    numerical zero beside real values does), there is no common prefix: None, and each value is
    written with its own (:func:`format_si`, the unit in each cell).

    Examples
    --------
    >>> common_scale([2.805e-6, 4.1e-7], "m")
    (1e-06, 'µm')
    >>> common_scale([2.9e-17, 8.7e-22], "J") is None
    True
    """
    magnitudes = sorted(abs(v) for v in values if v != 0 and math.isfinite(v))
    if not magnitudes:
        return prefixed_scale(0.0, unit)
    middle = len(magnitudes) // 2
    typical = (
        magnitudes[middle] if len(magnitudes) % 2 else math.sqrt(magnitudes[middle - 1] * magnitudes[middle])
    )
    scale, label = prefixed_scale(typical, unit)
    if any(_fixed(v / scale, digits) is None for v in magnitudes):
        return None
    return scale, label
