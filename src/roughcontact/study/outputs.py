"""What a study's output folder shows: results table, derived tables and figures, from stored records only.

Everything here reads ``OUT/study.json`` and the case records, never the study file or the solvers,
so ``roughcontact plot OUT/`` and ``roughcontact report OUT/`` work on a finished (or partly
finished) study, also on another machine.
"""

from __future__ import annotations

import json
import logging
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..display_html import html_table
from ..errors import InputError
from .display import columns, header
from .kind import CaseRecord, FigureContext, Kind
from .schema import STORED
from .store import Table, notes_of, replacing, stored_case, write_table

log = logging.getLogger(__name__)

CASES_SHOWN = 50
"""Cases a notebook shows of an analysis (its table says how many more there are)."""


@dataclass(frozen=True)
class StoredAnalysis:
    """One analysis of a stored study: its kind, its records (None for cases not yet stored), options."""

    name: str
    kind: Kind
    summary: str
    figures: tuple[str, ...]
    compare: Any
    sweep_axes: tuple[str, ...]
    cases: tuple[str, ...]
    records: tuple[CaseRecord | None, ...]
    realisations: int = 1
    """Realisations of its generated surfaces per case (the replicates of :mod:`.spread`)."""
    redrawn: tuple[str, ...] = ()
    """Its generated random topographies drawn anew for each realisation."""
    drawn_once: tuple[str, ...] = ()
    """Its generated random topographies drawn once (one seed for every case)."""
    damaged: tuple[tuple[str, str], ...] = ()
    """(case id, what did not match) of each case whose stored files do not match their checksums:
    not used (its record is None, shown as pending), named by ``plot`` and ``report``."""
    unsealed: tuple[str, ...] = ()
    """Ids of the cases stored without a checksum (by a roughcontact before checksums): used
    unverified, said by ``plot`` and ``report``."""

    @property
    def finished(self) -> list[CaseRecord]:
        """Records of the cases that finished."""
        return [r for r in self.records if r is not None and r.done]

    def _repr_html_(self) -> str:
        rows = case_rows(self)
        titles, cells = columns(rows[:CASES_SHOWN], missing=self.kind.missing)
        table = html_table(titles, cells, title=self.name, caption=f"({self.kind.name}): {self.summary}")
        more = len(rows) - CASES_SHOWN
        return table + (f"<p>… {more} more cases</p>" if more > 0 else "")


def context(analysis: StoredAnalysis, analyses: list[StoredAnalysis]) -> FigureContext:
    """Return what the figure and table functions of ``analysis`` get besides its records."""
    others = {a.name: (a.kind.name, a.finished) for a in analyses if a.name != analysis.name}
    return FigureContext(analysis.name, analysis.compare, others)


def _current(record: CaseRecord | None, case_id: str) -> CaseRecord | None:
    """Return the record if it is this case's (key starts with the id), else None (pending)."""
    if record is None or not str(record.data.get("key", "")).startswith(case_id):
        return None
    return record


def read_study(folder: str | Path) -> tuple[dict[str, Any], list[StoredAnalysis]]:
    """Read ``OUT/study.json`` and every stored record of the study in ``folder``, verified.

    A record or fields file that does not match its checksum is not used: the case reads as not
    stored (pending) and :attr:`StoredAnalysis.damaged` says what did not match. A record stored
    without a checksum (an earlier roughcontact) is used and listed in :attr:`StoredAnalysis.unsealed`.
    """
    from .kinds import get_kind

    folder = Path(folder).expanduser().resolve()
    marker = folder / "study.json"
    if not marker.is_file():
        raise InputError(
            "OUT",
            f"{folder} holds no study results (no study.json).",
            "give the folder 'roughcontact run' wrote.",
        )
    document = json.loads(marker.read_text())
    analyses = []
    for entry in document["analyses"]:
        kind = get_kind(entry["model"])
        compare = entry.get("compare")
        if compare is not None and kind.compare is not None:
            compare = kind.compare.model_validate(compare, context=STORED)  # written in SI by the runner
            kept = {k: folder / v for k, v in compare if isinstance(v, Path) and not v.is_absolute()}
            compare = compare.model_copy(update=kept)  # measured data kept in OUT/inputs/
        stored = {case: stored_case(folder, entry["name"], case) for case in entry["cases"]}
        records = tuple(_current(stored[case].record, case) for case in entry["cases"])
        damaged = tuple((case, s.problem) for case, s in stored.items() if s.problem is not None)
        unsealed = tuple(
            case for (case, s), record in zip(stored.items(), records, strict=True) if s.unsealed and record
        )
        analyses.append(
            StoredAnalysis(
                entry["name"],
                kind,
                entry.get("summary", kind.summary),
                tuple(entry["figures"]),
                compare,
                tuple(entry.get("sweep_axes", ())),
                tuple(entry["cases"]),
                records,
                entry.get("realisations", 1),
                tuple(entry.get("redrawn", ())),
                tuple(entry.get("drawn_once", ())),
                damaged,
                unsealed,
            )
        )
    return document, analyses


def axis_columns(record: CaseRecord, units: dict[str, str]) -> dict[str, Any]:
    """Return the swept values of a case (SI) under their stored headers; sample and replicate left out."""
    axis_units = record.data.get("axes_units") or {}
    return {
        header(axis, axis_units.get(axis) or units.get(axis)): value
        for axis, value in (record.data.get("axes_si") or {}).items()
        if axis not in ("sample", "replicate")
    }


def case_rows(analysis: StoredAnalysis) -> list[dict[str, Any]]:
    """Return one row per case of an analysis as a notebook shows it: :func:`result_rows` less bookkeeping.

    Its analysis, model and time are left out, so is the replicate where none is repeated and the
    status where every case is done.
    """
    rows = result_rows([analysis])
    dropped = {"analysis", "model", "seconds"}
    if not any(row.get("replicate") for row in rows):
        dropped.add("replicate")
    if all(row["status"] == "done" for row in rows):
        dropped.add("status")
    return [{key: value for key, value in row.items() if key not in dropped} for row in rows]


def result_rows(analyses: list[StoredAnalysis]) -> list[dict[str, Any]]:
    """One row per case of every analysis: status, swept values (SI), scalars (SI), time, error."""
    rows = []
    for analysis in analyses:
        units = dict(analysis.kind.units)
        damaged = dict(analysis.damaged)
        for case_id, record in zip(analysis.cases, analysis.records, strict=True):
            row: dict[str, Any] = {"analysis": analysis.name, "model": analysis.kind.name, "case": case_id}
            if record is None:
                why = damaged.get(case_id)
                rows.append(row | {"status": "pending"} | ({"error": f"not used: {why}"} if why else {}))
                continue
            row["status"] = record["status"]
            row["sample"] = record.parameters.get("sample", "")
            row["replicate"] = record.parameters.get("replicate", 0)
            row |= axis_columns(record, units)
            for name, value in record.scalars.items():
                title = header(name, units.get(name))
                if title in row:  # a swept key that is also a result (mean_pressure): keep both
                    title = header(f"{name} (result)", units.get(name))
                row[title] = value
            row["seconds"] = record.data.get("seconds")
            row["error"] = record.data.get("error") or ""
            rows.append(row)
    return rows


def headline_rows(analysis: StoredAnalysis) -> list[dict[str, Any]]:
    """One row per case for a reader: its sample, swept values, the kind's headline scalars, status.

    SI values under stored headers (:func:`~roughcontact.study.display.header`), to be shown
    through :func:`~roughcontact.study.display.columns`. A headline quantity that is also swept
    (the mean pressure of a pressure sweep) shows the solved value. Cases not yet run are
    ``pending``, failed ones have no values.
    """
    units = dict(analysis.kind.units)
    present = {n for r in analysis.records if r is not None for n in r.scalars}
    headline = [n for n in analysis.kind.headline if n in present]
    replicated = any(r is not None and r.parameters.get("replicate") for r in analysis.records)
    rows = []
    for record in analysis.records:
        if record is None:
            rows.append({"status": "pending"})
            continue
        row: dict[str, Any] = {}
        if record.parameters.get("sample"):
            row["sample"] = record.parameters["sample"]
        if replicated:
            row["replicate"] = record.parameters.get("replicate", 0)
        row |= axis_columns(record, units)
        row |= {header(name, units.get(name)): record.scalars.get(name) for name in headline}
        rows.append(row | {"status": record["status"]})
    return rows


def spread_rows(analysis: StoredAnalysis) -> list[dict[str, Any]]:
    """One row per group of realisations and scalar: its spread over the realisations (SI).

    A group is the cases whose parameters differ only in their realisation (``replicate``:
    :func:`roughcontact.cases.realisations_of`), so measured spots of one sample (files
    zipped with ``replicate``) are its realisations too; a row names the group by its sample and
    the swept values its cases share. Each numeric scalar of the group's finished cases is
    summarised by :func:`roughcontact.spread.spread` (n, mean, std, 95 % interval of the mean,
    min, max, note), with its SI ``unit``. The interval stays within the range the quantity can
    take (:meth:`~roughcontact.study.kind.Kind.bounds_of`: a fraction in [0, 1], an area or a
    stiffness not below 0), and the row's ``note`` says where Student's interval was cut there
    (two realisations of a positive quantity, a stick fraction near 1). A scalar equal in every
    realisation to 1e-6 relative (an input such as the force of a force-controlled case, reached
    to its solver's tolerance, or a material constant) does not depend on the draw and is left
    out. Empty for an analysis of one realisation.
    """
    from ..cases import realisations_of
    from ..spread import spread

    if analysis.realisations < 2:
        return []
    units = dict(analysis.kind.units)
    groups = []
    for records in realisations_of(analysis.finished).values():
        axes = [axis_columns(record, units) for record in records]
        shared = {k: v for k, v in axes[0].items() if all(a.get(k) == v for a in axes)}
        groups.append(({"sample": records[0].parameters.get("sample", "")} | shared, records))
    rows = []
    for where, records in groups:
        names = dict.fromkeys(n for r in records for n, v in r.scalars.items() if _numeric(v))
        for name in names:
            summary = spread(
                (r.scalars[name] for r in records if _numeric(r.scalars.get(name))),
                bounds=analysis.kind.bounds_of(name),
            )
            if summary.n > 1 and summary.max - summary.min <= 1e-6 * max(abs(summary.max), abs(summary.min)):
                continue
            rows.append(where | {"quantity": name, "unit": units.get(name) or ""} | summary.row())
    return rows


def footnoted(rows: list[dict[str, Any]]) -> Table:
    """Return a spread table as a reader sees it: each row's ``note`` as a mark, the notes under the table.

    The stored table (``tables/*_spread.csv``) keeps the whole sentence in every row, for a
    program; a report or a terminal shows ``[1]`` in the row and ``[1] 95 % interval cut at 0:
    ...`` once among the table's notes, so a cut interval is flagged without a column of
    repeated sentences. Rows without a note stay blank there (the column is left out where no
    row has one).
    """
    marks: dict[str, str] = {}
    shown = []
    for row in rows:
        note = row.get("note") or ""
        if note:
            mark = marks.setdefault(note, f"[{len(marks) + 1}]")
            row = row | {"note": mark}
        shown.append(row)
    return Table(shown, [*notes_of(rows), *(f"{mark} {note}" for note, mark in marks.items())])


def _numeric(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def write_results_table(folder: str | Path) -> Path:
    """Write ``OUT/results.csv`` from the stored records; return its path."""
    folder = Path(folder).expanduser().resolve()
    _, analyses = read_study(folder)
    path = folder / "results.csv"
    write_table(path, result_rows(analyses))
    return path


def produce(analyses: list[StoredAnalysis], what: str) -> tuple[list[tuple[str, str, Any]], list[str]]:
    """Call every analysis' table (``what="table"``) or chosen figure functions on its finished cases.

    Returns (analysis, name, product) for each product made, and the problems met: a function
    that fails (measured data that do not match the cases, say) is reported and the others still
    run. A function returns None where it has nothing to show (too few cases, say).
    """
    made, problems = [], []
    for analysis in analyses:
        records = analysis.finished
        if not records:
            continue
        kind = analysis.kind
        functions = kind.tables if what == "table" else {n: kind.figures[n] for n in analysis.figures}
        if what == "table" and analysis.realisations > 1:
            made.append((analysis.name, "spread", spread_rows(analysis)))
        for name, function in functions.items():
            try:
                product = function(records, context(analysis, analyses))
            except Exception as error:  # one failure must not lose the others; the caller says it
                kind_of = "" if isinstance(error, InputError) else f"{type(error).__name__}: "
                problems.append(f"{analysis.name}/{name}: {kind_of}{error}")
                log.info("%s %s of %s failed: %s", what, name, analysis.name, error)
                continue
            if product is not None and (what != "table" or product):
                made.append((analysis.name, name, product))
    return made, problems


def in_memory(study, records: dict[str, list[CaseRecord]]) -> list[StoredAnalysis]:
    """Return a study's analyses with records that were never stored (a command run without ``-o``)."""
    return [
        StoredAnalysis(
            analysis.name,
            analysis.kind,
            analysis.kind.summary,
            analysis.figures,
            analysis.compare,
            analysis.sweep_axes,
            tuple(case.case_id for case in analysis.cases),
            tuple(records.get(analysis.name, ())),
            analysis.realisations,
            analysis.redrawn,
            analysis.drawn_once,
        )
        for analysis in study.analyses
    ]


def write_tables(folder: str | Path) -> tuple[list[Path], list[str]]:
    """Write every analysis' derived tables to ``OUT/tables/ANALYSIS_TABLE.csv``.

    Returns the files written and the problems met (see :func:`produce`). Tables of an earlier
    write that this one did not make (their analysis changed, or their function failed this time)
    are removed, so that the report shows none as if it were current.
    """
    folder = Path(folder).expanduser().resolve()
    tables, problems = produce(read_study(folder)[1], "table")
    written = []
    for analysis, name, rows in tables:
        path = folder / "tables" / f"{analysis}_{name}.csv"
        write_table(path, rows)
        written.append(path)
    for stale in set((folder / "tables").glob("*.csv")) - set(written):
        stale.unlink()  # a table this run did not make (no longer applies, or failed): not shown as current
    return written, problems


DRAWN = "figures/.drawn.json"
"""What the last :func:`draw_figures` drew from: a stamp of its inputs, the files and the problems."""


def draw_figures(folder: str | Path, *, dpi: int = 150) -> tuple[list[Path], list[str]]:
    """Draw every analysis' figures into ``OUT/figures``; return the files and the problems met.

    Figures already drawn from the same inputs are kept, not redrawn: the inputs are the study,
    every case's record, the figures asked for, measured data files (size and modification time),
    the resolution and the code (:func:`roughcontact._version.code_fingerprint`). Drawing is most
    of the time of a rerun whose every case is reused (6 of the demo's 6.2 s), so such a rerun
    writes its report from the figures it has.
    """
    folder = Path(folder).expanduser().resolve()
    document, analyses = read_study(folder)
    stamp = _drawn_from(document, analyses, dpi)
    record = folder / DRAWN
    if record.is_file():
        previous = json.loads(record.read_text())
        files = [folder / name for name in previous.get("files", [])]
        if previous.get("stamp") == stamp and all(path.is_file() for path in files):
            return files, list(previous.get("problems", []))
    figures, problems = produce(analyses, "figure")  # Figure objects: saved without pyplot or a backend
    written = []
    for analysis, name, figure in figures:
        path = folder / "figures" / f"{analysis}_{name}.png"
        with replacing(path) as temporary:
            figure.savefig(temporary, dpi=dpi, bbox_inches="tight", format="png")
        written.append(path)
    drawn = {"stamp": stamp, "files": [str(p.relative_to(folder)) for p in written], "problems": problems}
    with replacing(record) as temporary:
        Path(temporary).write_text(json.dumps(drawn))
    return written, problems


def _drawn_from(document: dict[str, Any], analyses: list[StoredAnalysis], dpi: int) -> str:
    """Return a SHA-256 of everything the figures are drawn from (see :func:`draw_figures`)."""
    import hashlib

    from .._version import code_fingerprint

    state = {
        "study": document,
        "analyses": [
            [
                a.name,
                list(a.figures),
                [None if r is None else r.data for r in a.records],
                _files_of(a.compare),
            ]
            for a in analyses
        ],
        "dpi": dpi,
        "code": code_fingerprint(),
    }
    return hashlib.sha256(json.dumps(state, sort_keys=True, default=str).encode()).hexdigest()


def _files_of(compare) -> Any:
    """Return a comparison's settings, with each data file's size and modification time."""
    if compare is None:
        return None
    state = {}
    for key, value in compare:
        if isinstance(value, Path) and value.is_file():
            status = value.stat()
            state[key] = [str(value), status.st_size, status.st_mtime_ns]
        else:
            state[key] = repr(value)
    return state


def warning_lines(analysis) -> list[str]:
    """Return the model-range warnings of an analysis' cases, each once, with the cases it concerns."""
    cases: dict[str, list[str]] = {}
    records = [r for r in analysis.records if r is not None]
    for record in records:
        for warning in record.data.get("warnings") or ():
            cases.setdefault(warning, []).append(record.label)
    if len(records) == 1:
        return list(cases)
    return [f"{warning} ({'; '.join(labels)})" for warning, labels in cases.items()]


def realisation_lines(analysis: StoredAnalysis) -> list[str]:
    """Return what an analysis' numbers rest on, where they rest on random draws of generated surfaces."""
    lines = []
    if analysis.redrawn and analysis.realisations > 1:
        settings = max(1, len(analysis.cases) // analysis.realisations)
        lines.append(
            f"Each setting ran on {analysis.realisations} realisations of the generated surface(s) "
            f"{', '.join(analysis.redrawn)}, one case per realisation ({settings} setting"
            f"{'s' if settings != 1 else ''}, {len(analysis.cases)} cases); the spread table gives their "
            "mean, std and the 95 % interval of the mean over the realisations of each setting."
        )
    once = analysis.drawn_once if analysis.realisations > 1 else analysis.drawn_once + analysis.redrawn
    if once:
        lines.append(
            f"Every number rests on one realisation of the generated surface(s) {', '.join(once)}: "
            "another seed gives another answer. Add «realisations=N» and leave their seed out for the "
            "spread."
        )
    return lines
