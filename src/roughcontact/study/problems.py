"""Problems found in a study document: where each sits, what is wrong, how to fix it.

A study is validated whole before anything is computed, and every problem is collected rather
than the first one raised. Each :class:`Problem` keeps both how its place is *shown*
(``analysis[0] (contact) case 2 {'load': '1 kN'}.load``) and where it *is* in the document (the
path ``("analysis", 0, "load")``), so a front end that built the document from its own options
(the command line) can name the option the user typed instead of the study key.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel, ValidationError

from ..errors import InputError
from ..messages import Door, marked, render

Path = tuple[str | int, ...]
"""Where a value sits in a study document: section, table or analysis index, key, ..."""


@dataclass(frozen=True)
class Where:
    """A place in the study document: its path and its label in messages."""

    path: Path
    label: str

    def child(self, key: str | int, label: str | None = None) -> Where:
        """Return the place of ``key`` inside this one (shown as ``label``, default ``LABEL.key``)."""
        return Where((*self.path, key), label if label is not None else f"{self.label}.{key}")


class Problem(tuple):
    """One problem of a study document: a ``(field, problem, fix)`` triple that knows its place.

    It iterates, indexes and compares as the triple, in a study file's words (two cases meeting
    the same problem of a shared table report it once); ``path`` says where the value sits in the
    document, and the marked texts (:mod:`roughcontact.messages`) let another door say it in its
    own words (:meth:`said`).

    Attributes
    ----------
    field : str
        The place as shown to the user.
    problem : str
        What is wrong, with the value where it helps (a study file's words).
    fix : str or None
        How to fix it (a study file's words).
    path : tuple
        Where the value sits in the document (``("materials", "film", "youngs_modulus")``).
    cli_fix : str or None
        The fix on the command line where it differs in substance from a study file's (marked).
    """

    path: Path
    cli_fix: str | None

    def __new__(cls, field: str, problem: str, fix: str | None, path: Path = (), cli_fix: str | None = None):
        """Make the triple, with its ``path`` in the document."""
        self = super().__new__(cls, (field, render(problem, Door.STUDY), render(fix, Door.STUDY)))
        self.path = tuple(path)
        self.cli_fix = None if cli_fix is None else marked(cli_fix)
        self.marked = (marked(problem), None if fix is None else marked(fix))
        return self

    @property
    def field(self) -> str:
        """The place as shown to the user."""
        return self[0]

    @property
    def problem(self) -> str:
        """What is wrong."""
        return self[1]

    @property
    def fix(self) -> str | None:
        """How to fix it."""
        return self[2]

    def said(self, door: Door | str, option_of=None) -> tuple[str, str | None]:
        """Return (problem, fix) in the words of ``door`` (the command line's: ``option_of`` names keys)."""
        problem, fix = self.marked
        if Door(door) is Door.CLI and self.cli_fix is not None:
            fix = self.cli_fix
        return render(problem, door, option_of), render(fix, door, option_of)


def _label(where: Where, loc: tuple) -> str:
    parts = [where.label] if where.label else []
    for item in loc:
        if isinstance(item, int):
            parts[-1] = f"{parts[-1]}[{item}]" if parts else f"[{item}]"
        elif "[" not in str(item) and "(" not in str(item):  # skip pydantic's union branch tags
            parts.append(str(item))
    return ".".join(parts)


def _path(where: Where, loc: tuple) -> Path:
    return (*where.path, *(item for item in loc if "[" not in str(item) and "(" not in str(item)))


def from_validation_error(
    error: ValidationError, where: Where, schema: type[BaseModel] | None
) -> list[Problem]:
    """Turn a pydantic error into problems that show the bad value and say how to fix it."""
    problems = []
    for item in error.errors(include_url=False):
        context = item.get("ctx") or {}
        value = item.get("input")
        whole_table = not item["loc"]  # a model-level check: the value is the whole table
        if whole_table and context.get("field"):  # ... that names the key it is about
            item = item | {"loc": (context["field"],)}
            value = value.get(context["field"]) if isinstance(value, dict) else None
            whole_table = value is None
        shown = "" if item["type"] == "missing" or whole_table else f" (got {value!r})"
        fix, cli_fix = context.get("fix"), None
        if item["type"] == "missing":
            missing = item["loc"][-1]
            problem, fix = "is required but missing.", f"add «{missing}=...» to the table."
            cli_fix = f"add «{missing}=...»"
        elif item["type"] == "extra_forbidden":
            known = list(schema.model_fields) if schema is not None else []
            close = difflib.get_close_matches(str(item["loc"][-1]), known, n=1)
            problem = "is not a known key."
            fix = (
                f"did you mean {close[0]!r}?" if close else f"use one of {known}." if known else "remove it."
            )
            shown = ""
        elif item["type"] in ("quantity", "shape", "topography", "material"):
            problem = context.get("problem") or item["msg"]
            problem = problem.rstrip(".") + "."
            shown = "" if repr(value) in problem or str(value) in problem else shown
        elif item["type"] in _BOUND_WORDS:
            bound = context.get(_BOUND_WORDS[item["type"]][0])
            shown_bound = f"{bound:g}" if isinstance(bound, int | float) else str(bound)
            problem = _BOUND_WORDS[item["type"]][1].format(bound=shown_bound)
            problem = "must be positive." if problem == "must be above 0." else problem
            fix = fix or _generic_fix(item["type"], context)
        else:
            problem = item["msg"].removeprefix("Value error, ").rstrip(".") + "."
            fix = fix or _generic_fix(item["type"], context)
        problems.append(
            Problem(_label(where, item["loc"]), problem + shown, fix, _path(where, item["loc"]), cli_fix)
        )
    return _one_per_typo(problems)


def _one_per_typo(problems: list[Problem]) -> list[Problem]:
    """Drop "is required but missing" where an unknown key beside it is that key misspelt.

    ``materail = "SiO2"`` is one typo: its fix ("did you mean 'material'?") says all; that
    ``material`` is then missing is the same problem again.
    """
    meant = {
        (p.path[:-1], p.fix.removeprefix("did you mean ").rstrip("?").strip("'\""))
        for p in problems
        if p.problem == "is not a known key." and p.fix and p.fix.startswith("did you mean ")
    }
    return [p for p in problems if not (p.problem == "is required but missing." and _at(p) in meant)]


def _at(problem: Problem) -> tuple:
    """Return (the table's path, the key) of a problem."""
    return problem.path[:-1], problem.path[-1] if problem.path else None


_BOUND_WORDS = {
    "greater_than": ("gt", "must be above {bound}."),
    "greater_than_equal": ("ge", "must be {bound} or more."),
    "less_than": ("lt", "must be below {bound}."),
    "less_than_equal": ("le", "must be {bound} or less."),
}
"""pydantic's bound checks in our words (``must be above 0.``), with the bound's context key."""


def _generic_fix(kind: str, context: dict) -> str | None:
    """Return a fix for pydantic's own checks (bounds, choices, types), which carry none."""
    bounds = {"greater_than": "gt", "greater_than_equal": "ge", "less_than": "lt", "less_than_equal": "le"}
    if kind in bounds:
        words = {"gt": "above", "ge": "at least", "lt": "below", "le": "at most"}[bounds[kind]]
        bound = context.get(bounds[kind])
        return (
            f"give a value {words} {bound:g}."
            if isinstance(bound, int | float)
            else f"give a value {words} {bound}."
        )
    if kind == "literal_error":
        return f"use one of {context.get('expected')}."
    if kind in ("int_parsing", "int_type", "int_from_float"):
        return "give a whole number, e.g. 3."
    if kind in ("float_parsing", "float_type", "finite_number"):
        return "give a finite number, e.g. 0.3."
    if kind in ("bool_parsing", "bool_type"):
        return "write true or false."
    if kind in ("string_type", "list_type", "tuple_type", "dict_type"):
        return "see roughcontact models NAME for the key's type."
    return None


def collect(problems: list[Problem], where: Where, schema: type[BaseModel], raw: Any):
    """Validate ``raw`` with ``schema``; on failure append its problems and return None."""
    try:
        return schema.model_validate(raw)
    except ValidationError as error:
        problems.extend(from_validation_error(error, where, schema))
    except InputError as error:
        problems.append(Problem(where.label, error.problem, error.fix, where.path))
    return None
