"""Where a table of values comes from: measured, reconstructed from reported statistics, or synthetic.

A comparison is only as strong as the data it compares with. A friction coefficient measured on
the instrument, one rebuilt from the p values a paper reports, and one drawn by a script from a
model are different kinds of evidence, and a value built from roughcontact's own output agrees with
roughcontact *by construction*. Every file of compared data (a ``sample,mu`` table, a friction
loop, an indentation curve) says which it is in its ``#`` header, and the word travels with the
values into table columns, legends, report sentences and terminal lines.

The header lines, read by :func:`origin_of` (case-insensitive keys)::

    # origin: synthetic            (or: measured, reconstructed)
    # by construction: built from examples/paper000.toml's default simulation

``origin`` names the kind of data; ``by construction`` (any text: what it was built from) marks
values derived from this model's own output, so that agreement with them is no evidence: a
comparison against them reports "by construction" and gives no agreement verdict.

Without an ``origin:`` line the file is read as measured (it was given where measured data go),
unless a comment line calls it synthetic or reconstructed; either way
:attr:`DataOrigin.declared` says whether the file said so itself.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from enum import StrEnum

from .errors import InputError


class Origin(StrEnum):
    """The kind of data in a file of values compared with a simulation."""

    MEASURED = "measured"
    RECONSTRUCTED = "reconstructed"
    SYNTHETIC = "synthetic"


_WORDS = {
    Origin.MEASURED: "measured",
    Origin.RECONSTRUCTED: "reconstructed from reported statistics",
    Origin.SYNTHETIC: "synthetic",
}
_KEY = re.compile(r"^\s*(origin|by construction)\s*:\s*(.*?)\s*$", re.IGNORECASE)
_HINT = re.compile(r"\b(synthetic|reconstructed)\b", re.IGNORECASE)


@dataclass(frozen=True)
class DataOrigin:
    """The origin of a file's values, as its header states it.

    Attributes
    ----------
    kind : Origin
        Measured, reconstructed or synthetic.
    by_construction : str or None
        What the values were built from when they derive from this model's own output (the
        header's ``by construction:`` line); None otherwise.
    declared : bool
        Whether the header has an ``origin:`` line (False: inferred from its words, or the
        default, measured).
    """

    kind: Origin = Origin.MEASURED
    by_construction: str | None = None
    declared: bool = False

    @property
    def word(self) -> str:
        """The one-word label of a column or a legend: ``measured``, ``reconstructed``, ``synthetic``."""
        return self.kind.value

    @property
    def words(self) -> str:
        """The label in a sentence: ``reconstructed from reported statistics`` for reconstructed data."""
        return _WORDS[self.kind]

    @property
    def values(self) -> str:
        """The values named in a sentence: ``measured values``, ``values reconstructed from ...``."""
        return (
            "values reconstructed from reported statistics"
            if self.kind is Origin.RECONSTRUCTED
            else (f"{self.words} values")
        )

    @property
    def is_measured(self) -> bool:
        """True for measured data (and only then may a comparison call them measured)."""
        return self.kind is Origin.MEASURED

    def caveat(self) -> str:
        """Say in one sentence what a comparison with these values can show ('' for measured data)."""
        if self.by_construction:
            return (
                f"The {self.values} were built from this model's own output, so any agreement is by "
                f"construction, not a validation (their file: {self.by_construction})."
            )
        if self.kind is Origin.SYNTHETIC:
            return "The values are synthetic: agreeing with them exercises the comparison, validates nothing."
        if self.kind is Origin.RECONSTRUCTED:
            return (
                "The values are reconstructed from reported statistics, not measured: they carry the "
                "reported means and spreads, not the instrument's values."
            )
        return ""


MEASURED = DataOrigin()
"""The origin of values given without a header that says otherwise."""


def origin_of(comments: Iterable[str], *, field: str = "origin") -> DataOrigin:
    """Return the origin a file's ``#`` comment lines declare (see the module docstring).

    Parameters
    ----------
    comments : iterable of str
        The comment lines, with or without their leading ``#``.
    field : str
        The key or option that names the file, for the error.

    Raises
    ------
    InputError
        An ``origin:`` line with another word than measured, reconstructed or synthetic.
    """
    kind, declared, built, hinted = Origin.MEASURED, False, None, None
    for line in comments:
        text = line.strip().lstrip("#").strip()
        match = _KEY.match(text)
        if match and match.group(1).lower() == "origin":
            word = match.group(2).lower()
            try:
                kind = Origin(word)
            except ValueError:
                raise InputError(
                    field,
                    f"its header says 'origin: {match.group(2)}'.",
                    "write '# origin: measured', '# origin: reconstructed' or '# origin: synthetic'.",
                ) from None
            declared = True
        elif match:
            built = match.group(2) or "this model's output"
        elif hinted is None and (hint := _HINT.search(text)):
            word = hint.group(1).lower()
            hinted = Origin.RECONSTRUCTED if word == "reconstructed" else Origin.SYNTHETIC
    if not declared and hinted is not None:
        kind = hinted
    return DataOrigin(kind, built, declared)
