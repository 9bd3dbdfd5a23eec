"""Running a command's study and showing its results: summaries, tables, JSON, the output folder.

A command runs its cases in-process with the study runner (:mod:`roughcontact.study.run`): with
``-o OUT`` each case, ``results.csv``, the tables, the figures and ``report.html`` are written as
for ``roughcontact run``; without it nothing is written. Either way it prints the same summary
(or, with ``--json``, one JSON document) derived from the results' scalars and units.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

from .._json import json_ready
from ..errors import InputError
from ..study.display import columns, shown, text_table
from .options import CommandStudy


def _output_folder(folder: Path, command: CommandStudy, overwrite: bool) -> bool:
    """Check ``-o`` for a command's study; return True to reuse its finished cases.

    A folder of the same command with the same options is resumed (its finished cases are the
    answer); one with other options is replaced only with ``--overwrite``, never silently.
    """
    import shutil
    import tomllib

    if not folder.exists() or not any(folder.iterdir()):
        return False
    marker = folder / "study.json"
    if not marker.is_file():
        raise InputError("-o/--output", f"{folder} is not empty.", "choose a new or empty folder.")
    held = json.loads(marker.read_text()).get("name")
    if held != command.name:
        raise InputError(
            "-o/--output",
            f"{folder} holds the results of {held!r}.",
            "choose another folder (a command reuses only its own results).",
        )
    stored = folder / "study.toml"
    same = stored.is_file() and tomllib.loads(stored.read_text()) == tomllib.loads(command.text())
    if same:
        return True
    if not overwrite:
        raise InputError(
            "-o/--output",
            f"{folder} holds the results of an earlier {held!r} with other options.",
            "choose another folder, or add --overwrite to replace them.",
        )
    shutil.rmtree(folder)
    return False


def _run(study, command: CommandStudy, output: Path | None, dpi: int, overwrite: bool = False):
    """Run every case; return the analyses with their records and the report path (None without -o)."""
    from ..progress import shown
    from ..study.kind import CaseRecord
    from ..study.outputs import in_memory, read_study
    from ..study.report import write_report
    from ..study.run import case_progress, execute, make_task, run_study

    terminal = sys.stderr.isatty()  # progress bars (of the cases, and of a long case's steps) only there
    try:
        with shown(terminal):
            if output is None:
                records: dict[str, list] = {}
                with case_progress(len(study.cases), terminal and len(study.cases) > 1) as bar:
                    for case in study.cases:
                        record, _ = execute(make_task(study, case, raise_errors=True))
                        records.setdefault(case.analysis, []).append(CaseRecord(record, Path.cwd()))
                        bar.update()
                return in_memory(study, records), None
            folder = output.expanduser().resolve()
            resume = _output_folder(folder, command, overwrite)
            summary = run_study(study, folder, resume=resume, progress=terminal, raise_errors=True)
            if summary.recomputed_note:
                print(f"roughcontact: note: {summary.recomputed_note}", file=sys.stderr)
        report = write_report(folder, dpi=dpi)
        return read_study(folder)[1], report
    except InputError as error:
        raise command.input_error(error) from None


def run_command(command: CommandStudy, args) -> int:
    """Validate and run a command's study, then print its summary (or ``--json``); return the exit status.

    Parameters
    ----------
    command : CommandStudy
        The study the command built from its options.
    args : argparse.Namespace
        The command's options (``output``, ``json``, ``dpi``).
    """
    from ..study.outputs import produce, warning_lines

    study = command.build()
    for note in study.notes:
        print(f"roughcontact: note: {command.translate(note)}", file=sys.stderr)
    if not args.json:
        from ..study.report import preparation_line

        for name, prepared in study.prepared.items():
            print(command.translate(preparation_line(name, prepared)))
    output = getattr(args, "output", None)
    analyses, report = _run(
        study, command, output, getattr(args, "dpi", 150), getattr(args, "overwrite", False)
    )
    tables, problems = produce(analyses, "table")
    if args.json:  # the document on stdout; its warnings said on stderr too, where a person sees them
        for analysis in analyses:
            for line in warning_lines(analysis):
                print(f"roughcontact: warning: {line}", file=sys.stderr)
        document = {
            "command": study.name,
            "topographies": study.prepared,
            "analyses": [_analysis_document(analysis, tables) for analysis in analyses],
            "output": None if output is None else str(output.expanduser().resolve()),
        }
        print(json.dumps(json_ready(document), indent=2))
        return 0
    for analysis in analyses:
        print("\n".join(summary_lines(analysis, study.analysis(analysis.name).kind)))
        for line in warning_lines(analysis):
            print(f"roughcontact: warning: {line}", file=sys.stderr)
        for name, rows in ((n, r) for a, n, r in tables if a == analysis.name):
            print(f"  table {name}:")
            print("\n".join(table_lines(rows, indent="    ")))
    for problem in problems:
        print(f"roughcontact: table not made: {problem}", file=sys.stderr)
    if report is not None:
        print(f"wrote {report.parent}: results.csv, cases/, tables/, figures/ and {report.name}")
    return 0


def _analysis_document(analysis, tables) -> dict[str, Any]:
    return {
        "name": analysis.name,
        "model": analysis.kind.name,
        "units": dict(analysis.kind.units),
        "cases": [
            {
                "case": record["case"],
                "status": record["status"],
                "axes": record.data.get("axes") or {},
                "parameters": record.parameters,
                "scalars": record.scalars,
                "warnings": record.data.get("warnings") or [],
            }
            for record in analysis.records
            if record is not None
        ],
        "tables": {name: rows for a, name, rows in tables if a == analysis.name},
    }


def summary_lines(analysis, kind) -> list[str]:
    """Return an analysis' finished cases as lines: every scalar of one, or a table of the headline ones.

    Numbers in engineering units (:mod:`roughcontact.study.display`): beside the value for one
    case, in the column header for several.
    """
    from ..study.outputs import headline_rows

    records = [r for r in analysis.records if r is not None]
    units = dict(kind.units)
    lines = [f"{analysis.name} ({kind.name}): {kind.summary}"]
    if len(records) == 1:
        width = max(len(name) for name in records[0].scalars) if records[0].scalars else 0
        lines += [
            f"  {name:<{width}}  {shown(value, units.get(name))}"
            for name, value in records[0].scalars.items()
        ]
        return lines
    rows = headline_rows(analysis)
    if len({row["status"] for row in rows}) == 1:
        rows = [{k: v for k, v in row.items() if k != "status"} for row in rows]
    return lines + table_lines(rows, indent="  ")


def table_lines(rows: list[dict[str, Any]], indent: str = "") -> list[str]:
    """Rows as aligned text columns in engineering units (:func:`roughcontact.study.display.columns`)."""
    return text_table(*columns(rows), indent=indent) if rows else []
