"""Running a command's study and printing its answer: the summary and tables, or one JSON document.

The study layer runs it (:func:`roughcontact.study.answers.answer`): with ``-o OUT`` each case,
``results.csv``, the tables, the figures and ``report.html`` are written as for ``roughcontact
run``; without it nothing is written. This module only prints what the answer says.
"""

from __future__ import annotations

import json
import sys

from .._json import json_ready
from ..errors import InputError
from .options import EXIT_CASES_FAILED, CommandStudy, refuse_unused


def run_command(command: CommandStudy, args) -> int:
    """Validate and run a command's study, then print its answer (or ``--json``); return the exit status.

    The study runs through :func:`roughcontact.study.answers.answer`, in memory or into ``-o``; a
    model's refusal during the run is named by the option that set the value.

    Parameters
    ----------
    command : CommandStudy
        The study the command built from its options.
    args : argparse.Namespace
        The command's options (``output``, ``json``, ``dpi``, ``overwrite``).
    """
    from ..study.answers import answer, reusable

    as_json, output = args.json, getattr(args, "output", None)
    replace, dpi = (getattr(args, "overwrite", False), getattr(args, "dpi", 150)) if output else (False, 150)
    if output is None:
        args.taking("without -o nothing is written", "add -o OUT", options=("dpi", "overwrite"))
    refuse_unused(args)  # every option the command's path did not read, before anything is computed
    command.options = getattr(args, "option_for", None)
    study = command.build()
    for note in study.notes:
        print(f"roughcontact: note: {command.render(note)}", file=sys.stderr)
    if not as_json:
        from ..study.report import preparation_line

        for name, prepared in study.prepared.items():
            print(command.render(preparation_line(name, prepared)))
    try:
        resume = output is not None and reusable(output, study, replace=replace)
        result = answer(
            study, output, resume=resume, progress=sys.stderr.isatty(), raise_errors=True, dpi=dpi
        )
    except InputError as error:
        raise command.input_error(error) from None
    for note in [] if result.summary is None else result.summary.notes:
        print(f"roughcontact: note: {note}", file=sys.stderr)
    for _, line in result.warnings():  # on stderr, where a person sees them, also with --json
        print(f"roughcontact: warning: {command.render(line)}", file=sys.stderr)
    if as_json:
        print(json.dumps(json_ready(result.document(command.render)), indent=2))
    else:
        print("\n".join(result.text_lines(command.render)))
        _combined_notes(result)
        if result.report is not None:
            print(f"wrote {result.folder}: results.csv, cases/, tables/, figures/ and {result.report.name}")
    return not_made(result.problems())


def not_made(problems: list[str]) -> int:
    """Say each table or figure that could not be made; return the exit status (non-zero if any).

    A product the command was asked for (a comparison, a figure) that fails is a failure of the
    command, also when every case finished.
    """
    for problem in problems:
        print(f"roughcontact: not made: {problem}", file=sys.stderr)
    return EXIT_CASES_FAILED if problems else 0


def _combined_notes(result) -> None:
    """Say how a combined quantity the answer shows was found (E* of two bodies, Δγ of two energies)."""
    from ..study.methods import combined_quantities
    from ..study.run import materials_used

    materials = {row["material"]: row for row in materials_used(result.study)}
    for analysis in result.analyses:
        for line in combined_quantities(analysis, materials):
            print(f"  how combined: {line}")
