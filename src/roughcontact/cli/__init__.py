"""Command line: ``roughcontact inspect | plot | contact | adhesion | friction | presliding | run | ...``.

One module per command group: :mod:`.topography` (``inspect``, ``plot``), :mod:`.study` (``run``,
``validate``, ``report``, ``models``, ``demo``, ``cite``), :mod:`.contact`, :mod:`.theories`,
:mod:`.adhesion`, :mod:`.friction`, :mod:`.asperity`, :mod:`.presliding` (``presliding``,
``loop-analysis``) and :mod:`.indentation` (``nanoindent``). What they share is public in
:mod:`.options` (options, a command as a study) and :mod:`.output` (running it and showing its
results).

The edges of the program live here: unit strings from the user are converted once (through
:mod:`roughcontact.units`, inside the study schemas), errors become one readable line naming the
option and an exit status, and logging is configured (only here).
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
from collections.abc import Collection, Sequence

from .._version import __version__
from ..errors import ConvergenceError, InputError
from ..messages import Door
from . import adhesion, asperity, contact, friction, indentation, presliding, study, theories, topography
from .options import (
    EXIT_CASES_FAILED,
    EXIT_INPUT_ERROR,
    EXIT_INTERNAL_ERROR,
    EXIT_INTERRUPTED,
    EXIT_NOT_CONVERGED,
    RecordedOptions,
    given_options,
    option_strings,
)

__all__ = [
    "EXIT_CASES_FAILED",
    "EXIT_INPUT_ERROR",
    "EXIT_INTERNAL_ERROR",
    "EXIT_INTERRUPTED",
    "EXIT_NOT_CONVERGED",
    "build_parser",
    "main",
]

GROUPS = (topography, contact, theories, adhesion, friction, asperity, presliding, indentation, study)
"""The command groups, in the order ``roughcontact --help`` lists them."""


class _Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line and a pointer to ``--help`` (not the whole usage)."""

    def error(self, message: str):
        """Print ``PROG: error: MESSAGE`` and where the options are listed; exit 2."""
        self.exit(2, f"{self.prog}: error: {message}\n  ({self.prog} --help lists the options)\n")


def build_parser(built: Collection[str] | None = None) -> argparse.ArgumentParser:
    """Return the argument parser of the ``roughcontact`` command.

    Parameters
    ----------
    built : collection of str, optional
        The commands whose options are built (with those of their group); the others are
        listed by name and summary only, since their options may need the model or paper
        they describe imported (the defaults in their help). None: every command's.
        :func:`main` builds the one command it runs, so that ``roughcontact --help`` and
        ``--version`` import no numerical or plotting library.
    """
    parser = _Parser(
        prog="roughcontact",
        description="Contact mechanics of rough surfaces from measured topographies.",
    )
    parser.add_argument("--version", action="version", version=f"roughcontact {__version__}")
    parser.add_argument("-v", "--verbose", action="count", default=0, help="more log output (-vv for debug)")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for group in GROUPS:
        if built is None or not set(built).isdisjoint(group.COMMANDS):
            group.add_commands(commands)
        else:
            for name, summary in group.COMMANDS.items():
                commands.add_parser(name, help=summary)
    return parser


def _command(argv: Sequence[str]) -> str | None:
    """Return the command of ``argv``: its first word not an option (the global options take no value)."""
    return next((word for word in argv if not word.startswith("-")), None)


def _subparser(parser: argparse.ArgumentParser, command: str) -> argparse.ArgumentParser:
    """Return the parser of ``command`` (its options are those a user can type after it)."""
    commands = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return commands.choices[command]


def main(argv: Sequence[str] | None = None) -> int:
    """Run the ``roughcontact`` command; return its exit status."""
    argv = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser(built=[command] if (command := _command(argv)) else [])
    args = parser.parse_args(argv)
    command_parser = _subparser(parser, args.command)
    args = RecordedOptions(args, given_options(command_parser, argv), option_strings(command_parser))
    level = (logging.WARNING, logging.INFO, logging.DEBUG)[min(args.verbose, 2)]
    logging.basicConfig(level=level, format="%(levelname)s %(name)s: %(message)s")
    try:
        return args.handler(args)
    except InputError as error:  # named as this command's options where the error names keys
        print(f"roughcontact: error: {error.text(Door.CLI, args.option_for)}", file=sys.stderr)
        return EXIT_INPUT_ERROR
    except ConvergenceError as error:
        print(f"roughcontact: error: {error}", file=sys.stderr)
        return EXIT_NOT_CONVERGED
    except BrokenPipeError:  # the reader went away (roughcontact ... | head): not an error of ours
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no second error at exit
        return 0
    except OSError as error:  # a path the system refuses (permissions, a full disk, ...)
        where = error.filename or "a file"
        print(
            f"roughcontact: error: {where}: {error.strerror or error}. Fix: check the path, its "
            "permissions and the free space.",
            file=sys.stderr,
        )
        return EXIT_INPUT_ERROR
    except Exception as error:  # a bug of ours: said in one line; -vv shows the traceback
        if args.verbose >= 2:
            raise
        print(
            f"roughcontact: internal error: {type(error).__name__}: {error}. This is a bug of roughcontact, "
            "not of your input: please report it with the command line; rerun with -vv for the traceback.",
            file=sys.stderr,
        )
        return EXIT_INTERNAL_ERROR
