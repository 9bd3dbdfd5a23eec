"""The one result protocol of roughcontact: scalars, units, fields, and how a solver ended.

Every public result (normal contact, load-unload, tangential path, Winkler-Lennard-Jones friction,
statistical load-unload, indentation, loop analysis, ...) speaks the same vocabulary, the idea of
scipy's ``OptimizeResult``:

* ``scalars()`` returns a flat ``dict`` of plain names (``contact_area``, ``mu``, ``K_L_A``: letters,
  digits and underscores, no units, no spaces or brackets) to JSON-ready values in SI units;
* the class attribute ``UNITS`` maps each dimensional scalar to its SI unit (``"m^2"``, ``"N/m"``);
  a scalar it does not name is dimensionless (or a label);
* ``to_xarray()`` returns the fields and curves as an ``xarray.Dataset``, each variable with its
  ``units`` attribute;
* a result a solver produced also has ``converged``, ``iterations`` and ``residual``.

Tables, the study report, the command line's ``--json`` and its printed summaries all derive
from these, so a new result needs nothing else to be shown everywhere; in a notebook, it shows
itself by inheriting :class:`roughcontact.display_html.NotebookDisplay`.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any, ClassVar, Protocol, runtime_checkable

SCALAR_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
"""What a scalar's name may be: a plain identifier (no unit, space or bracket in it)."""


@runtime_checkable
class Result(Protocol):
    """A public result: see the module docstring."""

    UNITS: ClassVar[Mapping[str, str]]

    def scalars(self) -> dict[str, Any]:
        """Return the scalar results (SI) under plain names."""
        ...

    def to_xarray(self) -> Any:
        """Return the fields and curves as an ``xarray.Dataset`` (SI, ``units`` attributes)."""
        ...


@runtime_checkable
class SolverResult(Result, Protocol):
    """A result an iterative solver produced: how it ended, besides the :class:`Result` protocol."""

    @property
    def converged(self) -> bool:
        """True when the solver met its tolerance (solvers raise rather than return otherwise)."""
        ...

    @property
    def iterations(self) -> Any:
        """Iterations the solver took (per step for results of several steps)."""
        ...

    @property
    def residual(self) -> Any:
        """The solver's residual at the returned iterate (per step for results of several steps)."""
        ...


def units_of(result: Any) -> dict[str, str]:
    """Return the ``UNITS`` table of a result (instance or class) as a plain dict ({} without one)."""
    return dict(getattr(result, "UNITS", None) or {})


LEVELLING = "levelling"
"""The scalar that says how a measured surface was levelled before a solver used it (a label)."""


def levelling_of(topography: Any) -> dict[str, str]:
    """Return ``{"levelling": mode}`` for a surface whose levelling is recorded, else ``{}``.

    A surface read from a file is levelled as it is read (``read_topography``'s ``detrend``, the
    commands' ``--detrend``, a study's ``detrend``), and its ``info['detrend']`` records how:
    ``"plane"``, ``"none"`` (the tilt kept), ... . The results computed on it add this label to
    their :meth:`~Result.scalars`, so that a number is never read without knowing whether its scan
    was levelled (``--json``, the tables and a notebook's display show it). A generated or
    hand-made surface records none, and its results have no such entry.
    """
    info = getattr(topography, "info", None) or {}
    mode = info.get("detrend")
    return {} if mode is None else {LEVELLING: str(mode)}
