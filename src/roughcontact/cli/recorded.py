"""Every option a command is given is used or refused: the options a handler reads are recorded.

:func:`roughcontact.cli.main` wraps the parsed options in :class:`RecordedOptions`; after the
handler, :func:`refuse_unused` names each option the user typed that the command did not read (an
option of another mode, say), instead of ignoring it silently.
"""

from __future__ import annotations

import argparse
from collections.abc import Iterable, Mapping
from typing import Any

from ..errors import InputError


class RecordedOptions:
    """A command's parsed options that remember which of them the command read.

    :func:`roughcontact.cli.main` hands every handler its options wrapped in one: reading an
    option (``args.path``, ``getattr(args, "stroke", None)``) marks it used. Before a command
    computes anything it calls :func:`refuse_unused`, which refuses every option the user typed
    that the path the command took never read: ``presliding --paper001 --path my.csv`` runs the
    paper's own programme, so ``--path`` would be dropped without a word. One mechanism for
    every command and path; a handler names what decided its path with :meth:`taking`.

    Parameters
    ----------
    namespace : argparse.Namespace
        The parsed options.
    given : dict of str to str
        The options the user typed: destination -> the option string as typed (``--path``).
    """

    def __init__(
        self,
        namespace: argparse.Namespace,
        given: Mapping[str, str],
        options: Mapping[str, str] | None = None,
    ):
        object.__setattr__(self, "_namespace", namespace)
        object.__setattr__(self, "_given", dict(given))
        object.__setattr__(self, "_options", dict(options or {}))
        object.__setattr__(self, "_read", set())
        object.__setattr__(self, "_path", [])

    def __getattr__(self, name: str) -> Any:
        value = getattr(object.__getattribute__(self, "_namespace"), name)
        object.__getattribute__(self, "_read").add(name)
        return value

    def __setattr__(self, name: str, value: Any) -> None:
        setattr(object.__getattribute__(self, "_namespace"), name, value)

    def taking(self, reason: str, other: str, *, options: Iterable[str] | None = None) -> None:
        """Say what decided the command's path and how to take the other one.

        ``reason``: ``"--paper001 runs the paper's own programme"``; ``other``: ``"leave out
        --paper001 to run your own"``; ``options``: the destinations it explains (default every
        unused one). :func:`refuse_unused` gives both when it refuses an option this path does
        not read.
        """
        dests = None if options is None else frozenset(options)
        object.__getattribute__(self, "_path").append((reason, other, dests))

    def option_for(self, dest: str) -> str | None:
        """Return the option string of destination ``dest`` in this command (None if it has none)."""
        return object.__getattribute__(self, "_options").get(dest)

    def unused_options(self) -> dict[str, str]:
        """Return the options typed but never read: destination -> the option as typed."""
        read = object.__getattribute__(self, "_read")
        return {
            dest: option
            for dest, option in object.__getattribute__(self, "_given").items()
            if dest not in read
        }

    def reasons_for(self, dest: str) -> list[tuple[str, str]]:
        """Return what decided the path for option ``dest`` and how to take the other (:meth:`taking`)."""
        return [(r, o) for r, o, d in object.__getattribute__(self, "_path") if d is None or dest in d]


def option_strings(parser: argparse.ArgumentParser) -> dict[str, str]:
    """Return each destination of ``parser``'s options and its first long option string (``--pressure``)."""
    found = {}
    for action in parser._actions:
        if action.option_strings:
            long = [text for text in action.option_strings if text.startswith("--")]
            found.setdefault(action.dest, (long or action.option_strings)[0])
        elif action.dest not in ("handler",):
            found.setdefault(action.dest, action.dest.upper())
    return found


def given_options(parser: argparse.ArgumentParser, argv: Iterable[str]) -> dict[str, str]:
    """Return the options of ``parser`` that ``argv`` types: destination -> the option string typed.

    Read from the words themselves, so an option typed with its default value counts as given.
    Abbreviations argparse accepts (``--pres`` for ``--pressure``) count under their option.
    """
    actions = parser._option_string_actions  # argparse's own table of option strings
    given: dict[str, str] = {}
    for word in argv:
        if word == "--":
            break
        if not word.startswith("-") or word in ("-", "-v", "-vv", "--verbose"):
            continue
        option = word.split("=", 1)[0]
        action = actions.get(option)
        if action is None and option.startswith("--"):
            matches = [a for text, a in actions.items() if text.startswith(option)]
            action = matches[0] if len({id(a) for a in matches}) == 1 else None
        if action is not None and action.dest not in ("help",):
            given.setdefault(action.dest, option)
    return given


def refuse_unused(args) -> None:
    """Refuse every option the user typed that the command's path did not read (see :class:`RecordedOptions`).

    Raises
    ------
    InputError
        Naming each unused option and why: the options that chose the path, or that the command
        does not use it in this combination.
    """
    if not isinstance(args, RecordedOptions):
        return
    unused = args.unused_options()
    if not unused:
        return
    groups: dict[tuple, list[str]] = {}
    for dest, option in sorted(unused.items(), key=lambda item: item[1]):
        groups.setdefault(tuple(args.reasons_for(dest)), []).append(option)
    found = []
    for path, options in groups.items():
        because = "; ".join(reason for reason, _ in path) or "the command does not use it with these options"
        them = "it" if len(options) == 1 else "them"
        fix = f"leave {them} out" + "".join(f", or {other}" for _, other in path) + "."
        found.append(
            (", ".join(options), f"{'is' if len(options) == 1 else 'are'} not used: {because}.", fix)
        )
    if len(found) == 1:
        raise InputError(*found[0])
    lines = [f"{option}: {problem} Fix: {fix}" for option, problem, fix in found]
    raise InputError(", ".join(sorted(unused.values())), "not used:\n  " + "\n  ".join(lines))
