"""One self-contained HTML page of a study: status, tables, figures, failures and provenance.

Figures are embedded as base64 PNG and the styles inline, so ``report.html`` reads offline and
can be mailed or archived on its own.
"""

from __future__ import annotations

import base64
import html
import json
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from ..messages import Door, render
from ..references import Reference
from ..topography.io import channel_words
from ..topography.process import LEVELLING
from ..units import format_si
from .display import column_cells, columns, missing_text, number
from .kind import figure_caption
from .methods import methods_paragraph, varied_axes
from .outputs import (
    StoredAnalysis,
    draw_figures,
    footnoted,
    headline_rows,
    read_study,
    realisation_lines,
    result_rows,
    warning_lines,
    write_results_table,
    write_tables,
)
from .store import notes_of, read_table, write_atomically

_STYLE = """
body { font-family: system-ui, sans-serif; margin: 2em auto; max-width: 75em; color: #222; }
h1 { margin-bottom: 0.2em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: 0.2em; margin-top: 2em; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.85em; }
th, td { border: 1px solid #ddd; padding: 0.25em 0.5em; text-align: right; }
th { background: #f3f3f3; } td.text, th.text { text-align: left; } td:not(.text) { white-space: nowrap; }
.failed { color: #a00; } .pending { color: #a60; } .done { color: #070; }
figure { margin: 1em 0; } figure img { max-width: 100%; border: 1px solid #eee; }
pre { background: #f7f7f7; padding: 0.8em; overflow-x: auto; font-size: 0.85em; }
.scroll { overflow-x: auto; }
"""


TRANSPOSED_UP_TO = 8
"""Analyses of up to this many cases list every quantity as a row, one column per case."""
WIDE = 6
"""A table of one row and more columns than this is shown as a column of (quantity, value)."""


def _html_table(titles: list[str], cells: list[list[str]], text_columns: set[int] = frozenset()) -> str:
    head = "".join(
        f'<th class="text">{html.escape(t)}</th>' if i in text_columns else f"<th>{html.escape(t)}</th>"
        for i, t in enumerate(titles)
    )
    body = "".join(
        "<tr>"
        + "".join(
            f'<td class="text {html.escape(c) if titles[i] == "status" else ""}">{html.escape(c)}</td>'
            if i in text_columns or titles[i] == "status"
            else f"<td>{html.escape(c)}</td>"
            for i, c in enumerate(row)
        )
        + "</tr>"
        for row in cells
    )
    return f'<div class="scroll"><table><tr>{head}</tr>{body}</table></div>'


def _table(
    rows: list[dict[str, Any]], drop: tuple[str, ...] = (), missing: dict[str, str] | None = None
) -> str:
    """Rows (SI under stored headers) as an HTML table in engineering units, units in the headers.

    ``missing``: column name -> why a row may have no value there (:attr:`Kind.missing`).
    """
    if not rows:
        return "<p>(no rows)</p>"
    titles, cells = columns(
        [{k: v for k, v in row.items() if k not in drop} for row in rows], missing=missing
    )
    if len(cells) == 1 and len(titles) > WIDE:  # one long row: read down, not across
        pairs = [[title, cell] for title, cell in zip(titles, cells[0], strict=True)]
        return _html_table(["quantity", "value"], pairs, {0})
    text = {i for i, t in enumerate(titles) if not any(number(row[i]) is not None for row in cells)}
    return _html_table(titles, cells, text)


def _quantities(records: list, units: dict[str, str], caption: str, missing: dict[str, str]) -> str:
    """Every scalar of up to a few cases as rows, in engineering units per row (unit in its own column).

    A row whose values span too many decades for one prefix has no unit: each cell carries its
    own; a missing value reads ``none`` and why, where ``missing`` (:attr:`Kind.missing`) says.
    """
    names = list(dict.fromkeys(name for record in records for name in record.scalars))
    titles = ["quantity", "unit"] + (["value"] if len(records) == 1 else [r.label for r in records])
    rows = []
    for name in names:
        values = [record.scalars.get(name) for record in records]
        label, shown = column_cells(values, units.get(name), missing_text(missing.get(name)))
        rows.append([name, label, *shown])
    return f"<p>{html.escape(caption)}</p>" + _html_table(titles, rows, {0, 1})


def _image(path: Path, caption: str) -> str:
    data = base64.b64encode(path.read_bytes()).decode()
    name = html.escape(path.stem.replace("_", " "))
    image = f'<img alt="{name}" src="data:image/png;base64,{data}">'
    words = f"<b>{html.escape(path.name)}</b>. {html.escape(caption)}" if caption else f"<b>{name}</b>"
    return f"<figure>{image}<figcaption>{words}</figcaption></figure>"


def preparation_line(name: str, prepared: dict[str, Any]) -> str:
    """One sentence on what was done to a measured file before use (levelling, filled points)."""
    grid = " x ".join(str(n) for n in prepared["grid"])
    size = " x ".join(format_si(s, "m") for s in prepared["size_m"])
    filled = prepared.get("undefined_points_filled", 0)
    undefined = (
        f"{100 * prepared['undefined_fraction_filled']:.3g} % of the points ({filled}) were undefined, "
        "filled by harmonic interpolation"
        if filled
        else "no undefined points"
    )
    if prepared.get("specks_removed"):
        undefined += f" (with {prepared['specks_removed']} specks, isolated measured points, removed first)"
    elif prepared.get("specks"):
        undefined += f"; {prepared['specks']} specks (isolated measured points amid them) kept"
    if prepared.get("filled_excluded_from_contact"):
        undefined += "; the filled points kept out of contact"
    words = LEVELLING.get(prepared["detrend"], prepared["detrend"])
    channel = prepared.get("channel")
    channel = f" channel {channel_words(channel)}" if isinstance(channel, dict) else ""
    return f"{name}: {prepared['file']}{channel}, {grid} points, {size}; {words}; {undefined}."


def _cases(analysis: StoredAnalysis, rows: list[dict]) -> list[str]:
    """Return the cases' table(s): every quantity of a few cases, or the headline ones, the rest folded."""
    units, missing = dict(analysis.kind.units), dict(analysis.kind.missing)
    finished = analysis.finished
    if finished and len(rows) <= TRANSPOSED_UP_TO:
        caption = "Every result of the case." if len(finished) == 1 else "Every result, one column per case."
        parts = [_quantities(finished, units, caption, missing)]
        if len(finished) < len(rows):
            parts.append(_table(headline_rows(analysis), missing=missing))
        return parts
    return [
        _table(headline_rows(analysis), missing=missing),
        "<details><summary>Every result of every case (as in results.csv)</summary>",
        _table(rows, drop=("analysis", "model", "error"), missing=missing),
        "</details>",
    ]


def _analysis_section(folder: Path, analysis: StoredAnalysis, rows: list[dict]) -> str:
    counts: dict[str, int] = {}
    for row in rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    parts = [
        f"<h2>{html.escape(analysis.name)} <small>({html.escape(analysis.kind.name)})</small></h2>",
        f"<p>{html.escape(analysis.summary)}. Cases: "
        + ", ".join(f'<span class="{s}">{n} {s}</span>' for s, n in counts.items())
        + (f"; swept: {html.escape(', '.join(varied))}" if (varied := varied_axes(analysis)) else "")
        + "</p>",
        *_cases(analysis, rows),
    ]
    own = {*analysis.kind.tables, "spread"}  # not those of another analysis whose name starts alike
    for path in sorted((folder / "tables").glob(f"{analysis.name}_*.csv")):
        if path.stem.removeprefix(analysis.name + "_") not in own:
            continue
        parts.append(f"<h3>{html.escape(path.stem.removeprefix(analysis.name + '_').replace('_', ' '))}</h3>")
        table = read_table(path)
        if path.stem == f"{analysis.name}_spread":
            table = footnoted(table)  # a cut interval's note once, under the table
        parts.append(_table(table, missing=dict(analysis.kind.missing)))
        parts += [f'<p class="note">{html.escape(render(note, Door.STUDY))}</p>' for note in notes_of(table)]
    for name in analysis.figures:
        path = folder / "figures" / f"{analysis.name}_{name}.png"
        if path.exists():
            parts.append(_image(path, figure_caption(analysis.kind.figures[name])))
    parts += [f"<p>{html.escape(render(line, Door.STUDY))}</p>" for line in realisation_lines(analysis)]
    warnings = warning_lines(analysis)
    if warnings:
        parts.append("<h3>Outside the model's range</h3><ul>")
        parts += [f'<li class="pending">{html.escape(render(line, Door.STUDY))}</li>' for line in warnings]
        parts.append("</ul>")
    failed = [r for r in analysis.records if r is not None and r["status"] == "failed"]
    if failed:
        parts.append("<h3>Failed cases</h3><ul>")
        parts += [
            f'<li class="failed">{html.escape(r.label)}: {html.escape(str(r.data.get("error", "")))}</li>'
            for r in failed
        ]
        parts.append("</ul>")
    return "\n".join(parts)


def _references(provenance: dict[str, Any]) -> list[str]:
    """Return the report's list of the works its models implement (``provenance.json``), DOIs as links."""
    items = []
    for entry in provenance.get("references") or []:
        reference = Reference.from_dict(entry)
        doi = html.escape(reference.doi or "")
        link = f' <a href="https://doi.org/{doi}">doi:{doi}</a>' if doi else ""
        items.append(f"<li>{html.escape(reference.citation())}{link}</li>")
    if not items:
        return []
    intro = (
        "The works this study's models implement (<code>roughcontact cite OUT/</code> writes their BibTeX):"
    )
    return ["<h2>References</h2>", f"<p>{intro}</p><ul>", *items, "</ul>"]


def _run_line(provenance: dict[str, Any]) -> str:
    wall, cases = (float(provenance.get(k) or 0.0) for k in ("wall_seconds", "case_seconds"))
    return (
        f"roughcontact {provenance.get('roughcontact', '?')}, {provenance.get('executor', '?')}, "
        f"finished {provenance.get('finished', '?')}, wall time {wall:.1f} s (cases {cases:.1f} s)."
    )


def write_report(folder: str | Path, *, redraw: bool = True, dpi: int = 150) -> Path:
    """Write ``OUT/report.html`` for the study in ``folder`` (tables and figures re-drawn first).

    Parameters
    ----------
    folder : str or Path
        A study's output folder.
    redraw : bool
        Re-write the results table, derived tables and figures from the records before the page.
    dpi : int
        Resolution of the re-drawn figures.

    Returns
    -------
    Path
        The report file.
    """
    folder = Path(folder).expanduser().resolve()
    problems: list[str] = []
    if redraw:
        write_results_table(folder)
        problems = write_tables(folder)[1] + draw_figures(folder, dpi=dpi)[1]
    document, analyses = read_study(folder)
    rows = result_rows(analyses)
    provenance_path = folder / "provenance.json"
    provenance = json.loads(provenance_path.read_text()) if provenance_path.exists() else {}
    status = "complete" if provenance.get("complete") else "incomplete: rerun with --resume to finish it"
    title = html.escape(document["name"])
    parts = [
        f"<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>{title}</title>",
        f"<style>{_STYLE}</style></head><body>",
        f"<h1>{title}</h1>",
        f"<p>{html.escape(document.get('description', ''))}</p>",
        f"<p>Study {html.escape(status)}. {html.escape(_run_line(provenance))} "
        "Each quantity is shown in one engineering unit, named in its column header or beside it; "
        "results.csv holds the same values in SI.</p>",
    ]
    if problems:
        parts.append(
            "<p class='failed'>Tables and figures that could not be made: "
            + html.escape("; ".join(problems))
            + "</p>"
        )
    prepared = provenance.get("topographies") or {}
    if prepared:
        parts.append("<h2>Measured topographies</h2><ul>")
        parts += [f"<li>{html.escape(preparation_line(n, p))}</li>" for n, p in prepared.items()]
        parts.append("</ul>")
    materials = provenance.get("materials") or []
    if materials:
        parts.append("<h2>Materials as used</h2>")
        parts.append(_table(materials))
    surfaces = [preparation_line(n, p) for n, p in prepared.items()]
    parts.append("<h2>Methods</h2>")
    parts += [f"<p>{html.escape(text)}</p>" for text in methods_paragraph(analyses, provenance, surfaces)]
    parts += _references(provenance)
    for analysis in analyses:
        parts.append(_analysis_section(folder, analysis, [r for r in rows if r["analysis"] == analysis.name]))
    parts.append("<h2>Provenance</h2>")
    inputs = provenance.get("input_files", {})
    if inputs:
        parts.append(_table([{"file": path, "sha256": digest} for path, digest in inputs.items()]))
    shown = {
        k: v for k, v in provenance.items() if k not in ("input_files", "seeds", "materials", "references")
    }
    parts.append(f"<pre>{html.escape(json.dumps(shown, indent=2))}</pre>")
    study_file = folder / "study.toml"
    if study_file.exists():
        parts.append(f"<h3>Study file</h3><pre>{html.escape(study_file.read_text())}</pre>")
    parts.append(
        f"<p><small>Written {datetime.now(UTC).isoformat(timespec='seconds')} by roughcontact report."
        "</small></p>"
    )
    parts.append("</body></html>")
    path = folder / "report.html"
    write_atomically(path, "\n".join(parts))
    return path
