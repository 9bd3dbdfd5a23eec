r"""One entry point that runs a study, in memory or into an output folder, and the answer it gives.

Every command that computes (``roughcontact contact``, ``friction``, ..., ``run``) is a study; this
is where it is run, whatever asked for it::

    from roughcontact.study import load_study, answer
    result = answer(load_study("examples/demo.toml"))          # in memory: nothing written
    result = answer(study, "demo-out", resume=True)             # results.csv, figures, report.html
    print("\n".join(result.text_lines())); result.document()    # what the commands print, or --json

In memory each case runs in this process and its record stays in memory; into a folder the runner
(:func:`~roughcontact.study.run.run_study`) stores each case as it finishes and the report is
written after. Both give the same :class:`StudyAnswer`: the analyses with their records, the
derived tables, the warnings of the cases and, on disk, the folder, the report and the run's
summary. The commands only parse options and print what it says.
"""

from __future__ import annotations

import html
import json
import shutil
import tomllib
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Any

from ..errors import InputError
from ..messages import Door, render
from .config import Study
from .display import columns, missing_text, shown, text_table
from .kind import CaseRecord
from .outputs import (
    StoredAnalysis,
    footnoted,
    headline_rows,
    in_memory,
    produce,
    read_study,
    realisation_lines,
    warning_lines,
)
from .run import RunSummary, case_progress, execute, make_task, run_study
from .store import LOCK, locked, notes_of, refuse_if_in_use


@dataclass(frozen=True)
class StudyAnswer:
    """What a study gave: its analyses with their records, and where it was written.

    Attributes
    ----------
    study : Study
        The study that ran.
    analyses : list of StoredAnalysis
        Its analyses with their records (None for a case not stored: interrupted).
    folder : Path or None
        The output folder; None for a study run in memory.
    report : Path or None
        ``report.html`` in ``folder``.
    summary : RunSummary or None
        Counts and times of the run into ``folder``.
    """

    study: Study
    analyses: list[StoredAnalysis]
    folder: Path | None = None
    report: Path | None = None
    summary: RunSummary | None = None

    @cached_property
    def tables(self) -> tuple[list[tuple[str, str, Any]], list[str]]:
        """The analyses' derived tables as (analysis, name, rows), and the tables that could not be made."""
        return produce(self.analyses, "table")

    def problems(self) -> list[str]:
        """Return the tables and figures that could not be made (a requested product that failed).

        The tables' from :attr:`tables`; the figures' from the last drawing into the folder
        (``figures/.drawn.json``), none in memory, where no figure is drawn.
        """
        problems = list(self.tables[1])
        if self.folder is not None:
            from .outputs import DRAWN

            drawn = self.folder / DRAWN
            if drawn.is_file():
                problems += [
                    p for p in json.loads(drawn.read_text()).get("problems", []) if p not in problems
                ]
        return problems

    def warnings(self) -> list[tuple[str, str]]:
        """Return (analysis, warning) for every model-range and trust warning of the cases."""
        return [(analysis.name, line) for analysis in self.analyses for line in warning_lines(analysis)]

    def text_lines(self, say=None) -> list[str]:
        """Return the answer as a command prints it: each analysis' summary and its tables.

        One case shows every scalar; several a table of the headline ones (engineering units,
        :mod:`roughcontact.study.display`). ``say`` renders the sentences' marked keys in a door's
        words (a command passes its own; default Python's, for a notebook or a script).
        """
        say = say or (lambda text: render(text, Door.PYTHON))
        tables, _ = self.tables
        lines: list[str] = []
        for analysis in self.analyses:
            lines += summary_lines(analysis, analysis.kind)
            for name, rows in ((n, r) for a, n, r in tables if a == analysis.name):
                if name == "spread":
                    headline = set(analysis.kind.headline)
                    rows = footnoted([row for row in rows if row["quantity"] in headline] or rows)
                    name = f"spread over {analysis.realisations} realisations (headline quantities)"
                lines.append(f"  table {name}:")
                lines += table_lines(rows, indent="    ", missing=analysis.kind.missing)
                lines += [f"    note: {say(note)}" for note in notes_of(rows)]
            lines += [f"  {say(line)}" for line in realisation_lines(analysis)]
        return lines

    def _repr_html_(self) -> str:
        where = "in memory" if self.folder is None else f"in {self.folder}"
        head = f"<p><strong>{html.escape(self.study.name)}</strong> ({html.escape(where)})</p>"
        return f"<div>{head}{''.join(analysis._repr_html_() for analysis in self.analyses)}</div>"

    def document(self, say=None) -> dict[str, Any]:
        """Return the answer as one JSON-ready document (``--json``): parameters, scalars, tables.

        ``say`` renders the cases' warnings in the door's words (a command passes its own,
        :meth:`roughcontact.cli.options.CommandStudy.render`); default the study file's.
        """
        tables, _ = self.tables
        say = say or (lambda text: render(text, Door.STUDY))
        return {
            "command": self.study.name,
            "topographies": self.study.prepared,
            "analyses": [analysis_document(analysis, tables, say) for analysis in self.analyses],
            "output": None if self.folder is None else str(self.folder),
        }


def answer(
    study: Study,
    output: str | Path | None = None,
    *,
    resume: bool = False,
    progress: bool = False,
    raise_errors: bool = False,
    dpi: int = 150,
    workers: int | None = None,
    scheduler: str | None = None,
    worker_storage: str | Path | None = None,
) -> StudyAnswer:
    """Run every case of ``study``: in memory (``output`` None) or into the folder ``output``.

    Parameters
    ----------
    study : Study
        From :func:`~roughcontact.study.config.load_study` or a command's options.
    output : str or Path, optional
        The output folder (results, figures, report); None keeps everything in memory.
    resume : bool
        Keep the finished cases of an earlier run in ``output`` (same keys).
    progress : bool
        Progress bars on standard error.
    raise_errors : bool
        Stop at the first case that fails and raise its error (a command's cases), instead of
        recording it and going on.
    dpi : int
        Resolution of the figures written into ``output``.
    workers, scheduler, worker_storage
        Run the cases on Dask (:func:`~roughcontact.study.run.run_study`; into a folder only).

    Returns
    -------
    StudyAnswer
    """
    from ..progress import shown
    from .report import write_report

    if output is None:
        if workers is not None or scheduler is not None:
            raise InputError("-o/--output", "a run on Dask needs an output folder.", "add -o OUT.")
        records: dict[str, list[CaseRecord]] = {}
        with shown(progress), case_progress(len(study.cases), progress and len(study.cases) > 1) as bar:
            for case in study.cases:
                record, _ = execute(make_task(study, case, raise_errors=raise_errors))
                records.setdefault(case.analysis, []).append(CaseRecord(record, Path.cwd()))
                bar.update()
        return StudyAnswer(study, in_memory(study, records))
    folder = Path(output).expanduser().resolve()
    with locked(folder) as lock_note:  # the run, its report and what is read back: one writer at a time
        with shown(progress):
            summary = run_study(
                study,
                folder,
                resume=resume,
                progress=progress,
                raise_errors=raise_errors,
                workers=workers,
                scheduler=scheduler,
                worker_storage=worker_storage,
            )
        summary.lock_note = summary.lock_note or lock_note
        report = write_report(folder, dpi=dpi)
        analyses = read_study(folder)[1]
    return StudyAnswer(study, analyses, folder, report, summary)


def reusable(folder: str | Path, study: Study, *, replace: bool = False) -> bool:
    """Check ``folder`` for a command's study; return True where it holds this very study (resume it).

    A folder written by the same command with the same options is resumed (its finished cases are
    the answer, each verified against its checksums before it is reused); one with other options is
    emptied only with ``replace``, never silently; a folder of something else, or one another run
    is writing into, is refused.

    Raises
    ------
    InputError
        Field ``-o/--output``: the folder holds other files, another command's results, or this
        command's with other options (without ``replace``), or another running process holds it.
    """
    folder = Path(folder).expanduser().resolve()
    if not folder.is_dir() or not any(path.name != LOCK for path in folder.iterdir()):
        return False
    refuse_if_in_use(folder)
    marker = folder / "study.json"
    if not marker.is_file():
        raise InputError("-o/--output", f"{folder} is not empty.", "choose a new or empty folder.")
    held = json.loads(marker.read_text()).get("name")
    if held != study.name:
        raise InputError(
            "-o/--output",
            f"{folder} holds the results of {held!r}.",
            "choose another folder (a command reuses only its own results).",
        )
    stored = folder / "study.toml"
    if stored.is_file() and tomllib.loads(stored.read_text()) == tomllib.loads(study.text):
        return True
    if not replace:
        raise InputError(
            "-o/--output",
            f"{folder} holds the results of an earlier {held!r} with other options.",
            "choose another folder, or add --overwrite to replace them.",
        )
    shutil.rmtree(folder)
    return False


def analysis_document(analysis, tables, say=lambda text: text) -> dict[str, Any]:
    """Return an analysis as JSON-ready data: its cases' parameters, scalars and warnings, its tables."""
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
                "warnings": [say(line) for line in record.data.get("warnings") or []],
            }
            for record in analysis.records
            if record is not None
        ],
        "tables": {name: rows for a, name, rows in tables if a == analysis.name},
        "table_notes": {
            name: list(notes_of(rows)) for a, name, rows in tables if a == analysis.name and notes_of(rows)
        },
    }


def summary_lines(analysis, kind) -> list[str]:
    """Return an analysis' finished cases as lines: every scalar of one, or a table of the headline ones.

    Numbers in engineering units (:mod:`roughcontact.study.display`): beside the value for one
    case, in the column header for several.
    """
    records = [r for r in analysis.records if r is not None]
    units = dict(kind.units)
    lines = [f"{analysis.name} ({kind.name}): {kind.summary}"]
    if len(records) == 1:
        width = max(len(name) for name in records[0].scalars) if records[0].scalars else 0
        lines += [
            f"  {name:<{width}}  {shown(value, units.get(name), missing_text(kind.missing.get(name)))}"
            for name, value in records[0].scalars.items()
        ]
        return lines
    rows = headline_rows(analysis)
    if len({row["status"] for row in rows}) == 1:
        rows = [{k: v for k, v in row.items() if k != "status"} for row in rows]
    return lines + table_lines(rows, indent="  ", missing=kind.missing)


def table_lines(rows: list[dict[str, Any]], indent: str = "", missing=None) -> list[str]:
    """Rows as aligned text columns in engineering units (:func:`roughcontact.study.display.columns`).

    ``missing``: column name -> why a row may have no value there (:attr:`Kind.missing`).
    """
    return text_table(*columns(rows, missing=missing), indent=indent) if rows else []
