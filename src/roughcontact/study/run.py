"""Run a study: every case once, in-process or on a Dask cluster, restartable, with provenance.

The runner turns each pending :class:`~roughcontact.study.config.Case` into a picklable
:class:`Task`, runs it with :func:`execute` (the same function in-process and on a Dask worker),
and stores what comes back (:mod:`roughcontact.study.store`) as soon as it comes back. So:

* a rerun with ``resume=True`` skips every case whose record is stored with the same key (same
  model, parameters, inputs and seeds) and verifies against its checksums, and redoes failed,
  interrupted and changed ones, and those whose stored files do not match what was written (a
  line per case says what did not match);
* one run at a time writes into a folder (``OUT/.lock``, :func:`~roughcontact.study.store.locked`);
  a stopped run's table and ``provenance.json`` count the cases stored on disk, not those computed;
* Ctrl-C or a killed process loses no finished case, and leaves no half-written file (each is
  renamed into place when complete); the table written on the way out marks what is pending;
* a case that raises is recorded with its error (``status = "failed"``) and the others go on;
* on a Dask cluster, a case whose worker dies is rerun by the scheduler on another worker and is
  stored once, when its result reaches the client.

Scale-out uses Dask's own machinery: ``workers=N`` starts a ``distributed.LocalCluster`` of N
single-threaded worker processes on loopback; ``scheduler="tcp://host:8786"`` connects to a
running cluster (its workers need roughcontact installed; they get the topographies read here, so
they need no access to the input files). ``worker_storage=PATH`` makes the workers write the
cases' fields there (a path they share, e.g. a cluster file system) and send back only scalars.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import logging
import os
import platform
import socket
import sys
import time
import traceback
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from .._files import not_a_folder
from ..errors import InputError
from ..references import cited
from .config import Case, Study
from .inputs import CaseInputs
from .kind import CaseParameters, CaseRecord
from .schema import FileTopography, MaterialSpec, unit_of
from .store import (
    LOCK,
    clean_partial_files,
    dumps,
    fields_path,
    json_ready,
    locked,
    record_path,
    sealed,
    stored_case,
    write_atomically,
    write_dataset,
)

MARKER = "study.json"


@dataclass(frozen=True)
class Task:
    """Everything a worker needs to run one case (picklable)."""

    study: str
    analysis: str
    case_id: str
    key: str
    kind: str
    parameters: CaseParameters
    inputs: CaseInputs
    axes: dict[str, Any]
    axes_si: dict[str, Any]
    axes_units: dict[str, str | None]
    seeds: dict[str, int]
    worker_storage: str | None = None
    raise_errors: bool = False


def _version() -> str:
    from .._version import __version__

    return __version__


def _code() -> dict[str, Any]:
    from .._version import code_identity

    return code_identity()


def failed_record(task: Task, error: str | None) -> dict[str, Any]:
    """Return the record of a case that has not (yet) succeeded: its inputs, no scalars, the error."""
    return {
        "analysis": task.analysis,
        "case": task.case_id,
        "key": task.key,
        "model": task.kind,
        "status": "failed",
        "axes": task.axes,
        "axes_si": task.axes_si,
        "axes_units": task.axes_units,
        "parameters": task.parameters.model_dump(mode="json"),
        "seeds": task.seeds,
        "scalars": {},
        "fields": None,
        "fields_sha256": None,
        "fields_bytes": None,
        "error": error,
        "version": _version(),
        "code": _code(),
        "seconds": None,
    }


def execute(task: Task) -> tuple[dict[str, Any], Any]:
    """Run one case and return its record and its dataset (None if it has none or it went to storage).

    Errors of the case itself are caught and recorded (``status = "failed"`` with the message and
    the last lines of the traceback), unless the task says ``raise_errors`` (a command's cases:
    the error reaches the user at once); interruptions (KeyboardInterrupt, SystemExit) propagate.
    """
    from .kinds import get_kind

    record = failed_record(task, None)
    record |= {"host": socket.gethostname(), "pid": os.getpid()}
    record["started"] = datetime.now(UTC).isoformat(timespec="seconds")
    start = time.perf_counter()
    dataset = None
    try:
        output = get_kind(task.kind).run(task.parameters, task.inputs)
        record["scalars"] = json_ready(output.scalars)
        if output.warnings:
            record["warnings"] = list(output.warnings)
        dataset = output.dataset
        record["status"] = "done"
    except Exception as error:  # recorded, the study goes on
        if task.raise_errors:
            raise
        # a user's problem reads as the message; anything else is a bug and is named as such
        record["error"] = str(error) if isinstance(error, InputError) else f"{type(error).__name__}: {error}"
        record["traceback"] = traceback.format_exc(limit=-4)
    record["seconds"] = time.perf_counter() - start
    if dataset is not None and task.worker_storage is not None:
        path = Path(task.worker_storage) / task.study / task.analysis / f"{task.case_id}.nc"
        record["fields_sha256"], record["fields_bytes"] = write_dataset(path, dataset)
        record["fields"] = str(path.resolve())
        dataset = None
    return record, dataset


def store(folder: Path, record: dict[str, Any], dataset) -> None:
    """Store a case: its NetCDF file first (if any), then its record, the mark of a finished case.

    The record is sealed (:func:`~roughcontact.study.store.sealed`): it holds the checksum of the
    NetCDF file's bytes and of its own content, which a later run verifies before reusing it.
    """
    if dataset is not None:
        path = fields_path(folder, record["analysis"], record["case"])
        record["fields_sha256"], record["fields_bytes"] = write_dataset(path, dataset)
        record["fields"] = str(path.relative_to(folder))
    write_atomically(record_path(folder, record["analysis"], record["case"]), dumps(sealed(record)))


def _axes_si(case: Case) -> tuple[dict[str, Any], dict[str, str | None]]:
    """Return the swept values of a case in SI, and their SI units (None for plain numbers and labels)."""
    values, units = {}, {}
    for axis in case.axes:
        section, _, rest = axis.partition(".")
        table, _, key = rest.partition(".")
        if section == "topographies" and key:
            spec = case.topographies.get(table)
            values[axis] = getattr(spec, key, None)
            units[axis] = None if spec is None else unit_of(type(spec), key)
        elif section == "materials" and key:
            values[axis] = getattr(case.materials.get(table), key, None)
            units[axis] = unit_of(MaterialSpec, key)
        else:
            values[axis] = getattr(case.parameters, axis)
            units[axis] = unit_of(type(case.parameters), axis)
    return json_ready(values), units


def make_task(
    study: Study, case: Case, worker_storage: str | None = None, *, raise_errors: bool = False
) -> Task:
    """Build the picklable task of a case (file topographies travel as the arrays read in validation)."""
    files = {
        name: study.loaded[spec.model_dump_json()]
        for name, spec in case.topographies.items()
        if isinstance(spec, FileTopography)
    }
    inputs = CaseInputs(dict(case.topographies), files, dict(case.materials), study.device)
    axes_si, axes_units = _axes_si(case)
    return Task(
        study=study.name,
        analysis=case.analysis,
        case_id=case.case_id,
        key=case.key,
        kind=study.analysis(case.analysis).kind.name,
        parameters=case.parameters,
        inputs=inputs,
        axes=dict(case.axes),
        axes_si=axes_si,
        axes_units=axes_units,
        seeds=case.seeds,
        worker_storage=worker_storage,
        raise_errors=raise_errors,
    )


def is_finished(folder: Path, case: Case) -> bool:
    """Return True when ``case`` is stored as done with the same key, by the running code.

    Done means: the same key (inputs), the same code fingerprint
    (:func:`roughcontact._version.code_identity`), and its record and fields file, if any, as
    they were written (their checksums, :func:`~roughcontact.study.store.stored_case`).
    """
    return finished_state(folder, case) == "finished"


def finished_state(folder: Path, case: Case) -> str | None:
    """Return the state of a case's stored files; see :func:`case_state`, which also says why."""
    return case_state(folder, case)[0]


def case_state(folder: Path, case: Case) -> tuple[str | None, str | None]:
    """Return the state of a case's stored files and, where they cannot be trusted, what did not match.

    States: ``"finished"`` (done with the same key by the running code, verified), ``"failed"``
    (stored as failed with the same key), ``"other code"`` (done with the same key by another
    version or source tree), ``"unsealed"`` (done with the same key but stored without a checksum,
    by a roughcontact before checksums), ``"damaged"`` (a record or fields file that does not match
    its checksum, or cannot be read: the second item says how), or None (not stored, or stored
    with another key: the study changed).
    """
    stored = stored_case(folder, case.analysis, case.case_id)
    if stored.problem is not None:
        return "damaged", stored.problem
    record = stored.record
    if record is None or record["key"] != case.key:
        return None, None
    if not record.done:
        return ("failed" if record["status"] == "failed" else None), None
    if stored.unsealed:
        return "unsealed", None
    fingerprint = (record.data.get("code") or {}).get("fingerprint")
    return ("finished" if fingerprint == _code()["fingerprint"] else "other code"), None


def case_words(case: Case, folder: Path) -> str:
    """Name a case for a line a user reads: ``case ID (analysis: its swept values or surface and load)``."""
    shown = {"case": case.case_id, "axes": case.axes, "parameters": case.parameters.model_dump(mode="json")}
    return f"case {case.case_id} ({case.analysis}: {CaseRecord(shown, folder).label})"


@dataclass
class RunSummary:
    """What a run did: counts, times and the executor."""

    total: int
    skipped: int = 0
    other_code: int = 0
    """Cases stored as done by other code (another version or source of roughcontact): recomputed."""

    damaged: list[str] = field(default_factory=list)
    """A line per case whose stored files did not match their checksums: what did not, and that it is
    computed again."""
    unsealed: int = 0
    """Cases stored as done without a checksum (by a roughcontact before checksums): recomputed."""
    lock_note: str | None = None
    """Says that a lock left by a killed run was taken over (None when there was none)."""

    @property
    def recomputed_note(self) -> str | None:
        """The line that says cases stored by other code were recomputed (None when none were)."""
        if not self.other_code:
            return None
        many = self.other_code != 1
        return (
            f"{self.other_code} case{'s' if many else ''} stored by other code (another version of "
            f"roughcontact, or changed sources) {'were' if many else 'was'} recomputed, not reused."
        )

    @property
    def notes(self) -> list[str]:
        """Every line a user should read about the stored cases: a lock taken over, cases not reused."""
        lines = [self.lock_note] if self.lock_note else []
        lines += self.damaged
        if self.unsealed:
            many = self.unsealed != 1
            lines.append(
                f"{self.unsealed} case{'s' if many else ''} stored without a checksum (by a roughcontact "
                f"before checksums) {'were' if many else 'was'} recomputed, not reused."
            )
        if self.recomputed_note:
            lines.append(self.recomputed_note)
        return lines

    done: int = 0
    failed: int = 0
    interrupted: bool = False
    executor: str = "in-process"
    wall_seconds: float = 0.0
    case_seconds: float = 0.0
    failures: list[str] = field(default_factory=list)
    reused: set[str] = field(default_factory=set)
    """Ids of the cases reused (stored, verified, by the running code)."""
    store_error: str | None = None
    """Why the run stopped storing cases (a full disk), where it did: the case and the system's words."""

    @property
    def pending(self) -> int:
        """Cases neither finished nor failed (after an interruption)."""
        return self.total - self.skipped - self.done - self.failed


def _in_process(tasks: list[Task]) -> Iterator[tuple[dict, Any]]:
    for task in tasks:
        yield execute(task)


@contextlib.contextmanager
def dask_client(workers: int | None = None, scheduler: str | None = None):
    """Yield a Dask ``Client`` on a new local cluster of ``workers`` processes, or on ``scheduler``."""
    try:
        from distributed import Client, LocalCluster
    except ImportError as error:  # pragma: no cover - distributed is a dependency
        raise InputError(
            "--workers", f"Dask distributed does not import ({error}).", "pip install distributed"
        ) from None
    if scheduler is not None:
        try:
            client = Client(scheduler, timeout="20s")
        except OSError as error:
            raise InputError(
                "--scheduler",
                f"cannot reach a Dask scheduler at {scheduler!r} ({error}).",
                "start one (dask scheduler) or check the address, e.g. tcp://10.0.0.5:8786.",
            ) from None
        with client:
            yield client
        return
    with (
        LocalCluster(
            n_workers=workers,
            threads_per_worker=1,
            processes=True,
            host="127.0.0.1",
            dashboard_address=":0",  # any free port: never clash with a running cluster
            # Dask's own log lines stay off the terminal up to ERROR: at shutdown a worker's heartbeat
            # can race the scheduler's close and log "Failed to communicate with scheduler during
            # heartbeat" at ERROR (the likely Dask line that once failed the test of our terminal;
            # it was not kept). What matters reaches the user as our own lines: a case that raises,
            # or whose workers keep dying, is a failed record.
            silence_logs=logging.CRITICAL,
            env=_worker_threads(workers),
        ) as cluster,
        Client(cluster) as client,
    ):
        yield client


def _worker_threads(workers: int) -> dict[str, str]:
    """Environment of the local cluster's worker processes: the machine's cores shared among them.

    Each worker's FFTs would otherwise take every core (measured: paper 001's 1024-pixel study took
    10 min 19 s on two workers against 9 min 49 s in-process, 4.9 min of it system time), and BLAS and
    OpenMP pools likewise.
    """
    from .._backend import THREADS_VARIABLE

    share = str(max((os.cpu_count() or 1) // max(workers, 1), 1))
    return {THREADS_VARIABLE: share, "OMP_NUM_THREADS": share, "OPENBLAS_NUM_THREADS": share}


def _on_dask(client, tasks: list[Task]) -> Iterator[tuple[dict, Any]]:
    from distributed import as_completed

    futures = {
        client.submit(execute, task, key=f"roughcontact-{task.analysis}-{task.case_id}", pure=False): task
        for task in tasks
    }
    try:
        for future in as_completed(futures):
            try:
                yield future.result()
            except Exception as error:  # the task could not run at all (e.g. its workers kept dying)
                yield failed_record(futures[future], f"{type(error).__name__}: {error}"), None
    finally:
        client.cancel(list(futures))


def case_progress(total: int, enabled: bool):
    """Return a progress bar of ``total`` cases on standard error (a silent one unless ``enabled``)."""
    from tqdm.auto import tqdm

    return tqdm(total=total, disable=not enabled, unit="case", desc="cases", file=sys.stderr, leave=False)


def check_output(folder: Path, resume: bool) -> None:
    """Refuse a folder that is a file, and to mix a new study into one that holds another one's results."""
    problem = not_a_folder(folder)
    if problem:
        raise InputError("-o/--output", problem, "give a folder for the results (a new one is made).")
    if resume or not folder.exists() or not any(path.name != LOCK for path in folder.iterdir()):
        return
    if (folder / MARKER).exists():
        raise InputError(
            "-o/--output",
            f"{folder} already holds a study's results.",
            "pass --resume to continue it (finished cases are kept), or choose another folder.",
        )
    raise InputError("-o/--output", f"{folder} is not empty.", "choose a new or empty folder.")


def run_study(
    study: Study,
    output: str | Path,
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    resume: bool = False,
    worker_storage: str | Path | None = None,
    progress: bool = False,
    on_record: Callable[[dict], None] | None = None,
    raise_errors: bool = False,
) -> RunSummary:
    """Run every pending case of ``study`` into ``output`` and write the table and provenance.

    Parameters
    ----------
    study : Study
        From :func:`roughcontact.study.config.load_study`.
    output : str or Path
        The output folder (layout in :mod:`roughcontact.study.store`).
    workers : int, optional
        Run on a local Dask cluster of this many worker processes (default: in-process).
    scheduler : str, optional
        Address of a running Dask scheduler to send the cases to.
    resume : bool
        Continue a study in a folder that holds results: finished cases with the same key are kept.
    worker_storage : str or Path, optional
        Folder (shared with the workers) where they write the fields; only scalars come back.
    progress : bool
        Show a progress bar on standard error.
    on_record : callable, optional
        Called with each case's record as it is handed to storage (for tests and logging).
    raise_errors : bool
        Stop at the first case that fails and raise its error (in-process only; a command's
        cases), instead of recording it and going on. Finished cases are stored either way.

    Returns
    -------
    RunSummary
        Counts of skipped, done, failed and pending cases; ``interrupted`` after Ctrl-C (the
        KeyboardInterrupt is re-raised after the table and provenance are written).
    """
    if not isinstance(study, Study):
        fix = "load it first: run_study(load_study('study.toml'), 'out')."
        raise InputError("study", f"expected a Study, got {type(study).__name__}.", fix)
    if not isinstance(output, str | Path):
        raise InputError("output", f"expected a folder path, got {type(output).__name__}.", "e.g. 'out'.")
    if workers is not None and scheduler is not None:
        raise InputError("--workers", "both --workers and --scheduler were given.", "give one of them.")
    if workers is not None and workers < 1:
        raise InputError("--workers", f"need at least 1 worker, got {workers}.", "e.g. --workers 2.")
    folder = Path(output).expanduser().resolve()
    with locked(folder) as lock_note:
        summary = _run_locked(
            study, folder, resume, workers, scheduler, worker_storage, progress, on_record, raise_errors
        )
    if lock_note:
        summary.lock_note = lock_note
    return summary


def _run_locked(
    study: Study,
    folder: Path,
    resume: bool,
    workers: int | None,
    scheduler: str | None,
    worker_storage: str | Path | None,
    progress: bool,
    on_record: Callable[[dict], None] | None,
    raise_errors: bool,
) -> RunSummary:
    """:func:`run_study` in a folder whose lock this process holds."""
    check_output(folder, resume)
    clean_partial_files(folder)
    write_atomically(folder / "study.toml", study.text)
    write_atomically(folder / MARKER, dumps(study_document(study, folder)))

    cases = study.cases
    states = [case_state(folder, case) if resume else (None, None) for case in cases]
    pending = [case for case, (state, _) in zip(cases, states, strict=True) if state != "finished"]
    summary = RunSummary(total=len(cases), skipped=len(cases) - len(pending))
    summary.reused = {
        case.case_id for case, (state, _) in zip(cases, states, strict=True) if state == "finished"
    }
    summary.other_code = sum(state == "other code" for state, _ in states)
    summary.unsealed = sum(state == "unsealed" for state, _ in states)
    summary.damaged = [
        f"{case_words(case, folder)}: {problem}; computed again."
        for case, (state, problem) in zip(cases, states, strict=True)
        if state == "damaged"
    ]
    storage = None if worker_storage is None else str(Path(worker_storage).expanduser().resolve())
    tasks = [make_task(study, case, storage, raise_errors=raise_errors) for case in pending]
    started = datetime.now(UTC)
    clock = time.perf_counter()
    bar = case_progress(len(tasks), progress)
    # Cases are stored on one background thread, in order, while the next case solves (the
    # solvers release the GIL): a small case's NetCDF and JSON writes would otherwise add ~5 % to
    # a sweep. Every write is waited for before the table is written, also after Ctrl-C. A write
    # that fails (a full disk) stops the run: the next case is not started.
    writer = ThreadPoolExecutor(max_workers=1, thread_name_prefix="roughcontact-store")
    writes = []
    unstored: list[tuple[dict[str, Any], OSError]] = []

    def store_case(record: dict[str, Any], dataset) -> None:
        try:
            store(folder, record, dataset)
        except OSError as error:
            unstored.append((record, error))
            raise

    try:
        with contextlib.ExitStack() as stack:
            if workers is not None or scheduler is not None:
                client = stack.enter_context(dask_client(workers, scheduler))
                summary.executor = (
                    f"dask scheduler {scheduler}" if scheduler else f"dask local cluster, {workers} workers"
                )
                results = _on_dask(client, tasks)
            else:
                results = _in_process(tasks)
            stack.callback(results.close)  # a run stopped early cancels what is left (Dask)
            for record, dataset in results:
                writes.append(writer.submit(store_case, record, dataset))
                summary.case_seconds += record.get("seconds") or 0.0
                if record["status"] == "done":
                    summary.done += 1
                else:
                    summary.failed += 1
                    label = CaseRecord(record, folder).label  # its swept values, not its hash
                    summary.failures.append(f"{record['analysis']} ({label}): {record['error']}")
                bar.update()
                if on_record is not None:
                    on_record(record)
                if unstored:
                    break
            writer.shutdown(wait=True)  # every case stored before the cluster goes
    except KeyboardInterrupt:
        summary.interrupted = True
        raise
    finally:
        writer.shutdown(wait=True)
        bar.close()
        summary.wall_seconds = time.perf_counter() - clock
        summary_error = None
        if unstored:
            record, error = unstored[0]
            summary.store_error = f"{record['analysis']}/{record['case']}: {error.strerror or error}"
        try:
            write_summary_files(study, folder, summary, started)
        except OSError as error:
            if not unstored:
                raise
            # the disk that refused a case refuses the table too: remove the earlier run's table and
            # provenance rather than leave them describing what is no longer so
            summary_error = error
            for name in ("results.csv", "provenance.json"):
                (folder / name).unlink(missing_ok=True)
    if unstored:
        record, error = unstored[0]
        counts = stored_counts(folder, study, summary)
        kept = counts["done"] + counts["reused"] + counts["failed"]
        said = (
            "provenance.json counts them"
            if summary_error is None
            else f"results.csv and provenance.json could not be written either ({summary_error.strerror}) "
            "and were removed"
        )
        label = CaseRecord(record, folder).label
        raise InputError(
            "-o/--output",
            f"could not store case {record['case']} ({record['analysis']}: {label}) "
            f"in {folder}: {error.strerror or error}. The run stopped with {kept} of {summary.total} cases "
            f"stored ({said}).",
            "free space (or give another folder) and rerun with --resume: the stored cases are kept.",
        ) from error
    for write in writes:
        write.result()  # a failed write (disk full, say) is an error of the run, not of a case
    return summary


def _kept_compare(analysis, folder: Path) -> dict[str, Any] | None:
    """Return the analysis' compare table with its files copied to ``OUT/inputs/`` (paths relative to OUT).

    The measured data then travel with the results: ``plot`` and ``report`` work on a moved or
    archived output folder.
    """
    if analysis.compare is None:
        return None
    document = analysis.compare.model_dump(mode="json")
    for name, value in analysis.compare:
        if isinstance(value, Path):
            kept = folder / "inputs" / analysis.name / value.name
            write_atomically(kept, value.read_bytes())
            document[name] = str(kept.relative_to(folder))
    return document


def study_document(study: Study, folder: Path) -> dict[str, Any]:
    """Return what ``plot`` and ``report`` need of the study: analyses, figures, comparisons, case ids."""
    return {
        "name": study.name,
        "description": study.description,
        "study_file": None if study.path is None else str(study.path),
        "analyses": [
            {
                "name": analysis.name,
                "model": analysis.kind.name,
                "summary": analysis.kind.summary,
                "figures": list(analysis.figures),
                "compare": _kept_compare(analysis, folder),
                "sweep_axes": list(analysis.sweep_axes),
                "realisations": analysis.realisations,
                "redrawn": list(analysis.redrawn),
                "drawn_once": list(analysis.drawn_once),
                "cases": [case.case_id for case in analysis.cases],
            }
            for analysis in study.analyses
        ],
    }


def materials_used(study: Study) -> list[dict[str, Any]]:
    """Return every material the study's cases use, as used: its study name and properties (SI).

    One row per distinct (name, properties): a sweep of a material's modulus gives one row per value.
    """
    rows: dict[str, dict[str, Any]] = {}
    for case in study.cases:
        for name, material in case.materials.items():
            row = {
                "material": name,
                "library entry": material.name,
                "youngs_modulus [Pa]": material.youngs_modulus,
                "poissons_ratio": material.poissons_ratio,
                "hardness [Pa]": material.hardness,
                "yield_strength [Pa]": material.yield_strength,
                "surface_energy [J/m^2]": material.surface_energy,
                "source": material.source,
            }
            rows.setdefault(json.dumps(row, sort_keys=True, default=str), row)
    return list(rows.values())


def references_used(study: Study) -> list[dict[str, Any]]:
    """Return the works the study's models implement (``Kind.references``), roughcontact first, each once."""
    keys = [key for analysis in study.analyses for key in analysis.kind.references]
    return [reference.to_dict() for reference in cited(keys)]


def dependency_versions() -> dict[str, str]:
    """Return the installed version of every dependency roughcontact declares (for a methods section).

    Read from the package's metadata (``pyproject.toml``'s ``dependencies``, optional extras left
    out), so a dependency added there is reported without a change here.
    """
    import re
    from importlib import metadata

    versions = {}
    for requirement in metadata.requires("roughcontact") or ():
        if "extra ==" in requirement:
            continue
        name = re.match(r"[A-Za-z0-9_.\-]+", requirement).group(0)
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = "not installed"
    return versions


def stored_counts(folder: Path, study: Study, summary: RunSummary) -> dict[str, int]:
    """Count the study's cases as they are stored in ``folder`` now, each verified (:func:`case_state`).

    ``done`` and ``reused`` are the cases stored as finished (done, same key, running code, matching
    their checksums), split into those this run computed and those it reused; ``failed`` those stored
    as failed with the same key; ``pending`` every other case: not stored, or stored in a way a
    ``--resume`` would compute again.
    """
    counts = {"total": len(study.cases), "reused": 0, "done": 0, "failed": 0, "pending": 0}
    for case in study.cases:
        state, _ = case_state(folder, case)
        if state == "finished":
            counts["reused" if case.case_id in summary.reused else "done"] += 1
        elif state == "failed":
            counts["failed"] += 1
        else:
            counts["pending"] += 1
    return counts


def write_summary_files(study: Study, folder: Path, summary: RunSummary, started: datetime) -> None:
    """Write ``results.csv`` (every case, pending ones marked) and ``provenance.json``.

    Both are written from the case records on disk, each verified against its checksums, not from
    what the run counted: after a run stopped by a full disk they say what was stored.
    """
    from .outputs import write_results_table

    write_results_table(folder)
    counts = stored_counts(folder, study, summary)
    document = {
        "roughcontact": _version(),
        "python": sys.version.split()[0],
        "platform": platform.platform(),
        "packages": dependency_versions(),
        "materials": materials_used(study),
        "references": references_used(study),
        "command": sys.argv,
        "study_file": None if study.path is None else str(study.path),
        "study_sha256": hashlib.sha256(study.text.encode()).hexdigest(),
        "input_files": study.files,
        "topographies": study.prepared,
        "study_seed": study.seed,
        "seeds": {f"{c.analysis}/{c.case_id}": c.seeds for c in study.cases if c.seeds},
        "executor": summary.executor,
        "started": started.isoformat(timespec="seconds"),
        "finished": datetime.now(UTC).isoformat(timespec="seconds"),
        "wall_seconds": summary.wall_seconds,
        "case_seconds": summary.case_seconds,
        "cases": counts,
        "cases_counted": "from the case records on disk, each verified against its checksums",
        "complete": counts["pending"] == 0 and not summary.interrupted and summary.store_error is None,
        "interrupted": summary.interrupted,
        "store_error": summary.store_error,
    }
    write_atomically(folder / "provenance.json", dumps(document))
