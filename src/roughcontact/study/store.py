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

    OUT/.lock                            while a run writes into OUT: its pid, host and start

Every file is written to a temporary name in the same folder and renamed into place, so a killed
run leaves either the whole file or none; a case counts as finished only when its ``.json`` record
exists, and that is written after its ``.nc``.

Each record is sealed (:func:`sealed`): it holds the SHA-256 and size of its ``.nc`` file's bytes
and, under ``checksum``, the SHA-256 of its own content (canonical JSON of everything but the
checksum). :func:`stored_case` verifies both before a case is used, so a hand-edited record, a
truncated, overwritten or missing ``.nc`` and a record copied over another case's are never
reused or drawn as if they were what the run wrote; it says what did not match.

One run at a time writes into a folder: :func:`locked` holds ``OUT/.lock`` (created with
``O_EXCL``) and refuses a second run naming the process that holds it. A lock whose process is
no longer running on this host (a killed run) is taken over, with a note.
"""

from __future__ import annotations

import contextlib
import csv
import hashlib
import io
import json
import os
import socket
import sys
import threading
import time
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from .._files import not_a_folder, replacing
from .._json import json_ready
from ..errors import InputError
from .kind import CaseRecord

CASES = "cases"
LOCK = ".lock"
"""Name of the lock file a run holds in its output folder (:func:`locked`)."""
CHECKSUM = "checksum"
"""Key of a record's own checksum (:func:`sealed`)."""
UNSEALED = (
    "it was stored without a checksum (by a roughcontact before checksums, or the checksum was removed)"
)
"""Why a record without a checksum is not verified (:attr:`StoredCase.unsealed`)."""


def write_atomically(path: Path, data: bytes | str) -> None:
    """Write ``data`` to ``path`` through a temporary file and a rename (never half a file)."""
    with replacing(path) as temporary, temporary.open("wb") as stream:
        stream.write(data.encode() if isinstance(data, str) else data)
        stream.flush()
        os.fsync(stream.fileno())


def write_dataset(path: Path, dataset) -> tuple[str, int]:
    """Write an ``xarray.Dataset`` to ``path`` as NetCDF, atomically; return its bytes' SHA-256 and size.

    NetCDF3 (64-bit offset, through scipy) where the data fits it: writing a small case takes about
    2 ms that way against 20-40 ms through HDF5 (h5netcdf), which would dominate a sweep of small
    solves. Data NetCDF3 cannot hold (64-bit integers beyond 32 bits, say) goes to NetCDF4 through
    h5netcdf. ``xarray.open_dataset`` reads either. The checksum is of the file as written, before
    it is renamed into place (a record stores it, :func:`sealed`).
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
        digest = _sha256(temporary), temporary.stat().st_size
    return digest


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


_DIGESTS: dict[tuple, tuple[str, int]] = {}
"""File identity (path, inode, size, modification and change times) -> (SHA-256, size), per process."""


def file_digest(path: Path) -> tuple[str, int]:
    """Return the SHA-256 (hex) of a file's bytes and its size.

    Remembered per file while its inode, size and modification and change times stay the same (a
    run reads a case's fields file to verify it up to three times: to resume, for the table and
    the report); any write, truncation or replacement changes one of them, and so reads it anew.
    """
    status = os.stat(path)
    identity = (str(path), status.st_ino, status.st_size, status.st_mtime_ns, status.st_ctime_ns)
    if identity not in _DIGESTS:
        _DIGESTS[identity] = (_sha256(path), status.st_size)
    return _DIGESTS[identity]


def _sha256(path: Path) -> str:
    sha = hashlib.sha256()
    with open(path, "rb") as stream:
        for block in iter(lambda: stream.read(1 << 20), b""):
            sha.update(block)
    return sha.hexdigest()


def _canonical(record: dict[str, Any]) -> dict[str, Any]:
    """Return ``record`` as it reads back from its JSON file (the form its checksum is of)."""
    return json.loads(json.dumps(json_ready(record)))


def record_checksum(record: dict[str, Any]) -> str:
    """Return the SHA-256 (hex) of a record's content: canonical JSON of all but its ``checksum``."""
    content = {k: v for k, v in _canonical(record).items() if k != CHECKSUM}
    text = json.dumps(content, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    return hashlib.sha256(text.encode()).hexdigest()


def sealed(record: dict[str, Any]) -> dict[str, Any]:
    """Return ``record`` (JSON-ready) with its ``checksum``: what :func:`stored_case` verifies.

    The record must already hold ``fields_sha256`` and ``fields_bytes`` of its ``.nc`` file (as
    :func:`write_dataset` returns them) where it has one, so that the checksum covers the fields too.
    """
    content = {k: v for k, v in _canonical(record).items() if k != CHECKSUM}
    return content | {CHECKSUM: record_checksum(content)}


@dataclass(frozen=True)
class StoredCase:
    """What a case's stored files hold, verified (:func:`stored_case`).

    Attributes
    ----------
    record : CaseRecord or None
        The record, where there is one that can be used; None where there is none, or where
        ``problem`` says why it cannot be trusted.
    problem : str or None
        What did not match (``"its record was changed after it was written (checksum
        mismatch)"``), in words that follow "case ID (analysis: label):".
    unsealed : bool
        The record has no checksum (an earlier roughcontact wrote it): its content cannot be
        verified. The runner recomputes such a case; ``plot`` and ``report`` use it with a warning.
    """

    record: CaseRecord | None
    problem: str | None = None
    unsealed: bool = False


def _shown(path: Path, folder: Path) -> str:
    """Return a fields file's path as a user finds it: relative to the output folder where it lies inside."""
    try:
        return str(path.relative_to(folder))
    except ValueError:
        return str(path)


def _fields_problem(record: CaseRecord, folder: Path) -> str | None:
    """Say how a record's fields file differs from the one written with it (None where it matches)."""
    path = record.fields_path
    if path is None:
        return None
    shown = _shown(path, folder)
    if not path.is_file():
        return f"its fields file {shown} is missing"
    written = record.data.get("fields_bytes")
    digest, size = file_digest(path)
    if written is not None and size != written:
        how = "truncated" if size < written else "overwritten or changed"
        return f"its fields file {shown} has {size} bytes, {written} were written ({how})"
    expected = record.data.get("fields_sha256")
    if expected is not None and digest != expected:
        return (
            f"its fields file {shown} is not the one written with it "
            "(checksum mismatch: overwritten or changed)"
        )
    return None


def stored_case(folder: Path, analysis: str, case_id: str) -> StoredCase:
    """Read a case's record and verify it and its fields file against the checksums it holds.

    A record file that cannot be read, whose content does not match its checksum, that names
    another case, or whose fields file is missing or differs from the one written with it gives
    no record and a ``problem``. A record without a checksum is returned ``unsealed`` (its fields
    file must still be there).
    """
    path = record_path(folder, analysis, case_id)
    if not path.exists():
        return StoredCase(None)
    try:
        record = CaseRecord.read(path, folder)
    except (OSError, ValueError):
        return StoredCase(
            None, "its record cannot be read (not a complete JSON record: truncated or damaged)"
        )
    if CHECKSUM not in record.data:
        return StoredCase(None if (problem := _fields_problem(record, folder)) else record, problem, True)
    if record.data[CHECKSUM] != record_checksum(record.data):
        return StoredCase(None, "its record was changed after it was written (checksum mismatch)")
    if (record.data.get("analysis"), record.data.get("case")) != (analysis, case_id):
        held = f"{record.data.get('analysis')}/{record.data.get('case')}"
        return StoredCase(None, f"its record file holds another case ({held}): copied over it")
    problem = _fields_problem(record, folder)
    return StoredCase(None, problem) if problem else StoredCase(record)


def read_record(folder: Path, analysis: str, case_id: str) -> CaseRecord | None:
    """Return the stored record of a case, or None where there is none or it does not verify.

    See :func:`stored_case`, which also says what did not match.
    """
    return stored_case(folder, analysis, case_id).record


# --- the lock of an output folder ----------------------------------------------------------------

_HELD: dict[Path, int] = {}
"""Output folders this process holds the lock of, with how many times it entered :func:`locked`."""
_HELD_GUARD = threading.Lock()


def _process_identity(pid: int) -> str | None:
    """Return what tells process ``pid`` from a later one with its number (Linux: boot id and start time).

    None where the system does not say (no ``/proc``), or where the process is gone or a zombie.
    """
    try:
        boot = Path("/proc/sys/kernel/random/boot_id").read_text().strip()
        fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    except (OSError, ValueError):
        return None
    if not fields or fields[0] in ("Z", "X"):
        return None
    return f"{boot}/{fields[19]}"


def _running(pid: int, identity: str | None) -> bool:
    """Whether process ``pid`` of this host is running (and is the one ``identity`` names, if given)."""
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process: running
        return True
    except OSError:
        return False
    if Path("/proc").is_dir():
        now = _process_identity(pid)
        if now is None:  # a zombie: dead, not yet reaped
            return False
        return identity is None or identity == now
    return True


def _holder(path: Path) -> dict[str, Any] | None:
    """Return the content of a lock file, or None where it cannot be read (being written, damaged)."""
    try:
        holder = json.loads(path.read_text())
    except (OSError, ValueError):
        return None
    if not isinstance(holder, dict) or not isinstance(holder.get("pid"), int):
        return None
    return holder


UNREADABLE_LOCK_SECONDS = 30.0
"""Age after which a lock file that cannot be read is taken to be left by a killed run."""


def _held_by_another(path: Path) -> tuple[bool, dict[str, Any] | None]:
    """Return (held, holder) of a lock file: held means a run that is still running holds it."""
    holder = _holder(path)
    if holder is None:
        try:
            age = time.time() - path.stat().st_mtime
        except OSError:
            return False, None
        return age < UNREADABLE_LOCK_SECONDS, None
    if holder.get("host") != socket.gethostname():
        return True, holder  # another machine's run: its process cannot be seen from here
    if holder["pid"] == os.getpid():
        return False, holder  # this process holds no lock here (see _HELD): left by an earlier one
    return _running(holder["pid"], holder.get("process")), holder


def _who(holder: dict[str, Any] | None) -> str:
    """Name the process of a lock file: pid, host, start and, cut short, its command."""
    if holder is None:
        return "a run whose lock file cannot be read yet"
    words = f"pid {holder['pid']} on {holder.get('host')}, started {holder.get('started')}"
    command = holder.get("command")
    if isinstance(command, list) and command:
        line = " ".join([Path(str(command[0])).name, *map(str, command[1:])])
        words += f": {line if len(line) <= 100 else line[:97] + '...'}"
    return words


def _wait_fix(field: str) -> str:
    """Return the fix of a folder in use: wait, or (for a run's output) write to another folder."""
    if field == "-o/--output":
        return "wait for it to finish, or write to another folder (-o)."
    return "wait for it to finish, then run this command again."


@contextlib.contextmanager
def _one_at_a_time(folder: Path) -> Iterator[None]:
    """Serialise taking the lock among this host's processes (``flock`` on the folder, where it works)."""
    try:
        import fcntl
    except ImportError:  # pragma: no cover - not on POSIX: O_EXCL alone
        yield
        return
    descriptor = os.open(folder, os.O_RDONLY)
    try:
        with contextlib.suppress(OSError):  # a file system without flock: O_EXCL alone
            fcntl.flock(descriptor, fcntl.LOCK_EX)
        yield
    finally:
        os.close(descriptor)  # releases the flock


def _take(folder: Path, field: str) -> str | None:
    """Create ``folder/.lock`` for this process; return a note where a killed run's lock was taken over."""
    path = folder / LOCK
    note = None
    with _one_at_a_time(folder):
        for _ in range(3):
            try:
                descriptor = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
            except FileExistsError:
                held, holder = _held_by_another(path)
                if held:
                    fix = _wait_fix(field)
                    if holder is None or holder.get("host") != socket.gethostname():
                        fix += f" If no run uses the folder any more, remove {path}."
                    raise InputError(
                        field, f"{folder} is in use by another roughcontact run ({_who(holder)}).", fix
                    ) from None
                path.unlink(missing_ok=True)
                note = (
                    f"took over {path}, left by a run that is no longer running ({_who(holder)}); "
                    "its stored cases are verified before they are reused."
                )
                continue
            mine = {
                "pid": os.getpid(),
                "host": socket.gethostname(),
                "started": datetime.now(UTC).isoformat(timespec="seconds"),
                "process": _process_identity(os.getpid()),
                "command": sys.argv,
            }
            with os.fdopen(descriptor, "w") as stream:
                stream.write(json.dumps(mine))
                stream.flush()
                os.fsync(stream.fileno())
            return note
    raise InputError(field, f"{folder}: could not take its lock {path}.", f"remove {path} if no run uses it.")


def _release(folder: Path) -> None:
    """Remove ``folder/.lock`` where it is still this process's."""
    path = folder / LOCK
    holder = _holder(path)
    if holder is not None and holder.get("pid") == os.getpid() and holder.get("host") == socket.gethostname():
        path.unlink(missing_ok=True)


@contextlib.contextmanager
def locked(folder: Path, *, field: str = "-o/--output", create: bool = True) -> Iterator[str | None]:
    """Hold the lock of an output folder while writing into it; yield a note where one was taken over.

    ``OUT/.lock`` is created with ``O_EXCL`` and holds this process's pid, host, start time and
    command. A folder another running process holds is refused; a lock left by a process no longer
    running on this host (a killed run) is taken over, and the yielded note says so. The lock is
    re-entrant within a process (a command's run holds it around the runner, which takes it too)
    and removed on the way out, also after an error or Ctrl-C.

    Parameters
    ----------
    folder : Path
        The output folder (made if missing and ``create``).
    field : str
        The option or argument that named the folder, for the error.
    create : bool
        Make a missing folder; without it a missing folder is not locked (the caller reports it).

    Raises
    ------
    InputError
        ``folder`` is a file, or another run holds it: the error names the folder, the process
        that holds it and the fix (wait, or write to another folder).
    """
    folder = Path(folder).expanduser().resolve()
    problem = not_a_folder(folder)
    if problem:
        raise InputError(field, problem, "give a folder for the results (a new one is made).")
    if not create and not folder.is_dir():
        yield None
        return
    with _HELD_GUARD:
        entered = _HELD.get(folder, 0)
        if not entered:
            folder.mkdir(parents=True, exist_ok=True)
            note = _take(folder, field)
        else:
            note = None
        _HELD[folder] = entered + 1
    try:
        yield note
    finally:
        with _HELD_GUARD:
            _HELD[folder] -= 1
            if not _HELD[folder]:
                del _HELD[folder]
                _release(folder)


def refuse_if_in_use(folder: Path, field: str = "-o/--output") -> None:
    """Raise the error of :func:`locked` where another running process holds ``folder`` (take nothing)."""
    folder = Path(folder).expanduser().resolve()
    path = folder / LOCK
    if folder in _HELD or not path.exists():
        return
    held, holder = _held_by_another(path)
    if held:
        raise InputError(
            field, f"{folder} is in use by another roughcontact run ({_who(holder)}).", _wait_fix(field)
        )


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
