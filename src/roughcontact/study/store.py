"""The output folder of a study: where each case, the table, the provenance and the figures go.

Layout::

    OUT/study.toml                       the study file as written
    OUT/study.json                       name, analyses, figures and comparisons (for plot / report)
    OUT/provenance.json                  versions, input hashes, seeds, timings, executor, completeness
    OUT/cases/ANALYSIS/CASE.json         one record per case: parameters, swept values, scalars, status
    OUT/cases/ANALYSIS/CASE.nc           its fields and curves (xarray / NetCDF), when it has any
    OUT/results.csv                      one row per case: status, swept values, scalars (SI units)
    OUT/tables/ANALYSIS_TABLE.csv        derived tables (comparisons with measured data, ...)
    OUT/figures/ANALYSIS_FIGURE.png      figures
    OUT/report.html                      everything above on one page, readable offline

Every file is written to a temporary name in the same folder and renamed into place, so a killed
run leaves either the whole file or none; a case counts as finished only when its ``.json`` record
exists, and that is written after its ``.nc``.
"""

from __future__ import annotations

import csv
import io
import json
import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from .._files import replacing
from .._json import json_ready
from .kind import CaseRecord

CASES = "cases"


def write_atomically(path: Path, data: bytes | str) -> None:
    """Write ``data`` to ``path`` through a temporary file and a rename (never half a file)."""
    with replacing(path) as temporary, temporary.open("wb") as stream:
        stream.write(data.encode() if isinstance(data, str) else data)
        stream.flush()
        os.fsync(stream.fileno())


def write_dataset(path: Path, dataset) -> None:
    """Write an ``xarray.Dataset`` to ``path`` as NetCDF, atomically.

    NetCDF3 (64-bit offset, through scipy) where the data fits it: writing a small case takes about
    2 ms that way against 20-40 ms through HDF5 (h5netcdf), which would dominate a sweep of small
    solves. Data NetCDF3 cannot hold (64-bit integers beyond 32 bits, say) goes to NetCDF4 through
    h5netcdf. ``xarray.open_dataset`` reads either.
    """
    import dask

    # xarray takes a Dask lock for writing, from the scheduler when a distributed client is
    # active: a round trip per file, and an error once the client is closed. The data are numpy
    # arrays written by one thread, so the local, synchronous scheduler's lock is the right one.
    with replacing(path) as temporary, dask.config.set(scheduler="synchronous"):
        try:
            dataset.to_netcdf(temporary, engine="scipy")
        except (ValueError, TypeError, OverflowError):
            dataset.to_netcdf(temporary, engine="h5netcdf")


def dumps(value: Any) -> str:
    """JSON text of ``value`` (see :func:`json_ready`), indented."""
    return json.dumps(json_ready(value), indent=2, sort_keys=False)


def clean_partial_files(folder: Path) -> int:
    """Remove temporary files an interrupted run left behind; return how many."""
    count = 0
    if folder.exists():
        for path in folder.rglob(".*.part"):
            path.unlink(missing_ok=True)
            count += 1
    return count


def record_path(folder: Path, analysis: str, case_id: str) -> Path:
    """Path of a case's JSON record."""
    return folder / CASES / analysis / f"{case_id}.json"


def fields_path(folder: Path, analysis: str, case_id: str) -> Path:
    """Path of a case's NetCDF file in the output folder."""
    return folder / CASES / analysis / f"{case_id}.nc"


def read_record(folder: Path, analysis: str, case_id: str) -> CaseRecord | None:
    """Return the stored record of a case, or None where there is none (or it cannot be read)."""
    path = record_path(folder, analysis, case_id)
    try:
        return CaseRecord.read(path, folder)
    except (OSError, ValueError):
        return None


class Table(list):
    """The rows (dicts) of a derived table with the sentences that must be read with them.

    A table function returns one where its numbers need words to be read right: what the
    compared data are ("reconstructed from reported statistics: agreement by construction"),
    which interval a verdict rests on. The notes go wherever the rows go: above the CSV's header
    as ``#`` lines, under the report's table, after the command's table lines and into ``--json``.

    Parameters
    ----------
    rows : iterable of dict
        The rows.
    notes : iterable of str
        Whole sentences.
    """

    def __init__(self, rows: Iterable[dict[str, Any]] = (), notes: Iterable[str] = ()) -> None:
        super().__init__(rows)
        self.notes = tuple(notes)


def notes_of(rows: Iterable[dict[str, Any]]) -> tuple[str, ...]:
    """Return the notes of a :class:`Table` (none for plain rows)."""
    return tuple(getattr(rows, "notes", ()))


def write_table(path: Path, rows: Iterable[dict[str, Any]]) -> None:
    """Write rows (dicts) as CSV with the union of their keys as columns, in first-seen order.

    The notes of a :class:`Table` come first, one ``# `` line each.
    """
    notes = notes_of(rows)
    rows = list(rows)
    columns: dict[str, None] = {}
    for row in rows:
        columns.update(dict.fromkeys(row))
    buffer = io.StringIO()
    for note in notes:
        buffer.write(f"# {note}\n")
    writer = csv.DictWriter(buffer, fieldnames=list(columns), lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: _cell(v) for k, v in row.items()})
    write_atomically(path, buffer.getvalue())


def _cell(value: Any) -> Any:
    value = json_ready(value)
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, list | dict):
        return json.dumps(value)
    return "" if value is None else value


def read_table(path: Path) -> Table:
    """Read a CSV written by :func:`write_table` (values as strings), with its notes."""
    lines = path.read_text().splitlines(keepends=True)
    count = next((i for i, line in enumerate(lines) if not line.startswith("# ")), len(lines))
    notes = [line[2:].rstrip("\r\n") for line in lines[:count]]
    return Table(csv.DictReader(lines[count:]), notes)
