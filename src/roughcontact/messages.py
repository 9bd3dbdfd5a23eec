"""Messages as data: what an error, a warning or a note says about a key, said in each door's words.

A user meets roughcontact through one of three doors: Python (``solve_normal(...,
boundary="periodic")``), a study file (``boundary = "periodic"``) or the command line
(``--boundary periodic``). A message that names a setting must name it as that user would type it.
So a message names keys as *data*, not as words: in its text a key is written ``«boundary»`` and a
setting ``«boundary=periodic»``, and each door renders them (:func:`render`):

* ``«exclude_filled»``: ``exclude_filled`` (Python, study file), ``--exclude-filled`` (command line);
* ``«boundary=periodic»``: ``boundary='periodic'``, ``boundary = "periodic"``, ``--boundary periodic``;
* ``«exclude_filled=true»``: ``exclude_filled=True``, ``exclude_filled = true``, ``--exclude-filled``;
* ``«max_filled=0.3»``: ``max_filled=0.3``, ``max_filled = 0.3``, ``--max-filled 0.3``;
* ``«max_force=10 uN»``: ``max_force=quantity('10 uN')``, ``max_force = "10 uN"``, ``--max-force '10 uN'``.

Python takes SI numbers: a quantity with a unit is written there as :func:`roughcontact.quantity`
of it, which converts it. The command line names a
key by the option a command gives it (``mean_pressure`` is ``--pressure``): the door passes the
mapping (``option_of``); a key the command has no option for is named as the study key it is, so
the text never invents an option.
Nothing rewrites prose after the fact: only the marked keys change between doors.

:class:`Message` is a ``str`` whose value is the Python rendering (what a Python user prints) and
that keeps its marked form (``.marked``) for the other doors; :func:`marked` returns it for any
string. :class:`~roughcontact.errors.InputError` keeps its problem and fix marked and renders them
with :meth:`~roughcontact.errors.InputError.rendered`.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from enum import StrEnum

MARK = re.compile(r"«([A-Za-z_][A-Za-z0-9_.]*)(?:=([^«»]*))?»")
"""A marked key ``«key»`` or setting ``«key=value»`` in a message (group 1 the key, 2 the value)."""


class Door(StrEnum):
    """The way a user reached roughcontact: Python, a study file or the command line."""

    PYTHON = "python"
    STUDY = "study"
    CLI = "cli"


def key(name: str, value: object = None) -> str:
    """Return the marked form of a key (``«name»``) or, with ``value``, of a setting (``«name=value»``)."""
    if value is None:
        return f"«{name}»"
    text = "true" if value is True else "false" if value is False else str(value)
    return f"«{name}={text}»"


def is_number(text: str) -> bool:
    """Return whether ``text`` reads as a number (``float`` takes it: ``"1e-9"``, ``"nan"``, ``" 2 "``)."""
    try:
        float(text)
    except ValueError:
        return False
    return True


def _python_value(text: str) -> str:
    if text == "..." or text.isupper():  # a placeholder: «friction_coefficient=...», «realisations=N»
        return text
    if text in ("true", "false"):
        return "True" if text == "true" else "False"
    if is_number(text) or text.startswith(("(", "[")):
        return text
    if (
        any(c.isdigit() for c in text)
        and any(c.isalpha() for c in text.split()[-1])
        and len(text.split()) == 2
    ):
        return f"quantity({text!r})"  # Python takes SI numbers: roughcontact.quantity('10 uN') gives one
    return repr(text)


def _study_value(text: str) -> str:
    if text in ("true", "false", "...") or text.isupper() or is_number(text) or text.startswith(("[", "{")):
        return text
    return f'"{text}"'


def _cli_value(text: str) -> str:
    return f"'{text}'" if " " in text else text


def default_option(name: str) -> str:
    """Return the option a command line spells a key as by default: ``--`` and dashes (``--max-filled``)."""
    return "--" + name.replace("_", "-")


def render(
    text: str | None, door: Door | str, option_of: Callable[[str], str | None] | None = None
) -> str | None:
    """Return ``text`` with its marked keys and settings in the words of ``door``.

    Parameters
    ----------
    text : str or None
        A message with ``«key»`` and ``«key=value»`` marks (a plain text passes unchanged).
    door : Door or str
        ``"python"``, ``"study"`` or ``"cli"``.
    option_of : callable, optional
        For the command line: key -> the option of this command (``"mean_pressure"`` ->
        ``"--pressure"``), None where it has none (the study key is then named as such). Default:
        :func:`default_option`.
    """
    if not text:
        return text
    door = Door(door)
    text = getattr(text, "marked", text)

    def one(match: re.Match) -> str:
        name, value = match.group(1), match.group(2)
        if door is Door.PYTHON:
            return name if value is None else f"{name}={_python_value(value)}"
        if door is Door.STUDY:
            return name if value is None else f"{name} = {_study_value(value)}"
        option = (option_of or default_option)(name)
        if option is None:  # this command has no option for it: a study file's key, said so
            return (
                f"{name} (a study key)" if value is None else f"{name} = {_study_value(value)} (a study key)"
            )
        if value is None or value == "true":
            return option
        return f"{option} {_cli_value(value)}"

    return MARK.sub(one, str(text))


class Message(str):
    """A message whose value is its Python rendering and which keeps its marked form for the other doors.

    ``Message("Use «boundary=periodic».")`` prints as ``Use boundary='periodic'.`` and
    ``.marked`` is the text with its marks (:func:`render` it for the study file or the command line).
    """

    marked: str

    def __new__(cls, marked: str) -> Message:
        """Make the message from its marked text."""
        original = getattr(marked, "marked", marked)
        made = super().__new__(cls, render(original, Door.PYTHON))
        made.marked = original
        return made


def marked(text: str) -> str:
    """Return the marked form of a message (a plain string is its own)."""
    return getattr(text, "marked", text)


def as_messages(function: Callable[..., list[str]]) -> Callable[..., list[Message]]:
    """Make ``function``'s returned strings :class:`Message` objects (a result's ``range_warnings``).

    A Python user prints them in Python's words; a study or a command keeps them marked
    (:func:`marked`) and says them in its own.
    """
    import functools

    @functools.wraps(function)
    def said(*args, **kwargs) -> list[Message]:
        return [Message(text) for text in function(*args, **kwargs)]

    return said
