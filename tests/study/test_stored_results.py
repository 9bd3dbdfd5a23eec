"""Stored results are verified before they are used (issue 45, part 3).

Each case record carries the SHA-256 of its own content and of its ``.nc`` file; a case whose
files do not match is computed again on ``--resume`` with a line saying what did not match, and
``plot`` / ``report`` leave it out with a warning. ``provenance.json`` counts the cases on disk
(also after a full disk stopped the run), and one run at a time writes into a folder (``OUT/.lock``;
a killed run's lock is taken over). Every study here is three 32^2 normal-contact cases.
"""

from __future__ import annotations

import errno
import json
import os
import shutil
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from roughcontact.errors import InputError
from roughcontact.study import load_study, run_study
from roughcontact.study.store import LOCK, locked, read_table, record_path, sealed

STUDY = """
[study]
name = "stored"

[topographies.surface]
generate = "self_affine"
shape = 32
size = "1 um"
hurst = 0.8
rms_height = "1 nm"
seed = 1

[[analysis]]
name = "contact"
model = "normal"
topography = "surface"
material = "polysilicon"
figures = []
sweep.mean_pressure = ["5 MPa", "20 MPa", "40 MPa"]
"""

WHEN = ("seconds", "started", "pid", "host", "checksum")
"""Entries of a record that differ between two runs of the same case (the checksum covers them)."""


def cases(folder: Path) -> list[str]:
    """The case ids of the study in ``folder``, in study order."""
    (entry,) = json.loads((folder / "study.json").read_text())["analyses"]
    return entry["cases"]


def record(folder: Path, case: str) -> dict:
    return json.loads(record_path(folder, "contact", case).read_text())


def fields(folder: Path, case: str) -> Path:
    return folder / "cases" / "contact" / f"{case}.nc"


def provenance(folder: Path) -> dict:
    return json.loads((folder / "provenance.json").read_text())


def results_rows(folder: Path) -> dict[str, dict]:
    return {row["case"]: row for row in read_table(folder / "results.csv")}


def assert_same_as_clean(clean: Path, folder: Path) -> None:
    """``folder`` holds every case of the clean run, done, with equal records, fields and table rows."""
    import xarray as xr

    for case in cases(clean):
        want, got = record(clean, case), record(folder, case)
        assert got["status"] == "done"
        assert {k: v for k, v in got.items() if k not in WHEN} == {
            k: v for k, v in want.items() if k not in WHEN
        }
        a, b = xr.load_dataset(fields(clean, case)), xr.load_dataset(fields(folder, case))
        for name in [*a.data_vars, *a.coords]:
            np.testing.assert_array_equal(b[name].values, a[name].values)
    strip = lambda rows: {c: {k: v for k, v in r.items() if k != "seconds"} for c, r in rows.items()}  # noqa: E731
    assert strip(results_rows(folder)) == strip(results_rows(clean))
    assert provenance(folder)["complete"] is True
    assert not (folder / LOCK).exists()


@pytest.fixture(scope="module")
def clean(tmp_path_factory):
    """The study file and its output folder, run once without interference."""
    folder = tmp_path_factory.mktemp("clean")
    study = folder / "study.toml"
    study.write_text(STUDY)
    summary = run_study(load_study(study), folder / "out")
    assert (summary.done, summary.failed) == (3, 0)
    return study, folder / "out"


@pytest.fixture
def copy(clean, tmp_path):
    """A copy of the clean output folder to damage, and the study file."""
    study, output = clean
    shutil.copytree(output, tmp_path / "out")
    return study, tmp_path / "out"


# --- a case whose stored files do not match is computed again, with a line -----------------------


def test_a_hand_edited_record_is_recomputed_and_results_csv_holds_the_computed_value(clean, copy, cli):
    study, output = copy
    case = cases(output)[0]
    edited = record(output, case)
    true_fraction = edited["scalars"]["contact_fraction"]
    edited["scalars"]["contact_fraction"] = 0.5
    record_path(output, "contact", case).write_text(json.dumps(edited, indent=2))

    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 0, err
    assert "1 case run, 2 reused, 0 failed" in out
    assert (
        f"roughcontact: note: case {case} (contact: mean pressure 5 MPa): its record was changed after it "
        "was written (checksum mismatch); computed again.\n"
    ) in err
    assert float(results_rows(output)[case]["contact_fraction"]) == true_fraction != 0.5
    assert_same_as_clean(clean[1], output)


def _truncate_fields(output: Path, case: str, other: str) -> str:
    path = fields(output, case)
    size = path.stat().st_size
    path.write_bytes(path.read_bytes()[: size // 2])
    return f"its fields file cases/contact/{case}.nc has {size // 2} bytes, {size} were written (truncated)"


def _overwrite_fields(output: Path, case: str, other: str) -> str:
    shutil.copyfile(fields(output, other), fields(output, case))  # another case's file, the same size
    assert fields(output, case).stat().st_size == record(output, case)["fields_bytes"]
    return (
        f"its fields file cases/contact/{case}.nc is not the one written with it "
        "(checksum mismatch: overwritten or changed)"
    )


def _remove_fields(output: Path, case: str, other: str) -> str:
    fields(output, case).unlink()
    return f"its fields file cases/contact/{case}.nc is missing"


def _truncate_record(output: Path, case: str, other: str) -> str:
    path = record_path(output, "contact", case)
    path.write_text(path.read_text()[:200])
    return "its record cannot be read (not a complete JSON record: truncated or damaged)"


def _copy_record_over(output: Path, case: str, other: str) -> str:
    shutil.copyfile(record_path(output, "contact", other), record_path(output, "contact", case))
    return f"its record file holds another case (contact/{other}): copied over it"


@pytest.mark.parametrize(
    "damage", [_truncate_fields, _overwrite_fields, _remove_fields, _truncate_record, _copy_record_over]
)
def test_damaged_stored_files_are_recomputed_with_a_line_saying_what_did_not_match(clean, copy, cli, damage):
    study, output = copy
    case, other = cases(output)[2], cases(output)[0]
    problem = damage(output, case, other)
    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 0, err
    assert "1 case run, 2 reused, 0 failed" in out
    assert (
        f"roughcontact: note: case {case} (contact: mean pressure 40 MPa): {problem}; computed again.\n"
        in err
    )
    assert err.count("roughcontact: note:") == 1
    assert_same_as_clean(clean[1], output)


def test_report_and_plot_leave_a_damaged_case_out_and_say_so(clean, copy, cli):
    study, output = copy
    first, second, third = cases(output)
    edited = record(output, first)
    edited["scalars"]["contact_fraction"] = 0.5
    record_path(output, "contact", first).write_text(json.dumps(edited))
    problem = _truncate_fields(output, third, first)

    status, out, err = cli("report", output)
    assert status == 0 and f"wrote {output}/report.html" in out
    assert (
        f"roughcontact: warning: case {first} (contact): its record was changed after it was written "
        "(checksum mismatch); left out of the tables, figures and report (pending in results.csv). Fix: "
        "rerun the study into this folder with --resume to compute it again.\n"
    ) in err
    assert f"roughcontact: warning: case {third} (contact): {problem}; left out" in err
    rows = results_rows(output)
    assert [rows[c]["status"] for c in (first, second, third)] == ["pending", "done", "pending"]
    assert rows[first]["error"] == "not used: its record was changed after it was written (checksum mismatch)"
    assert rows[first]["contact_fraction"] == ""  # the edited 0.5 is nowhere
    assert "0.5" not in (output / "results.csv").read_text().split(first)[1].split("\n")[0]

    status, out, err = cli("plot", output)
    assert f"roughcontact: warning: case {first} (contact): its record was changed" in err
    assert f"roughcontact: warning: case {third} (contact): {problem}" in err

    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 0 and "2 cases run, 1 reused, 0 failed" in out
    assert_same_as_clean(clean[1], output)


def test_a_record_without_a_checksum_is_recomputed_on_resume_and_used_with_a_warning_by_report(
    clean, copy, cli
):
    # what a roughcontact before checksums wrote: the same record, without the three entries
    study, output = copy
    case = cases(output)[1]
    old = {
        k: v
        for k, v in record(output, case).items()
        if k not in ("checksum", "fields_sha256", "fields_bytes")
    }
    record_path(output, "contact", case).write_text(json.dumps(old))

    status, out, err = cli("report", output)
    assert status == 0
    assert "roughcontact: warning: contact: 1 case stored without a checksum by a roughcontact before" in err
    assert f"cases/contact/{case}.json): used as stored, not verified. Fix: rerun the study" in err
    assert results_rows(output)[case]["status"] == "done"

    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 0 and "1 case run, 2 reused, 0 failed" in out
    assert (
        "roughcontact: note: 1 case stored without a checksum (by a roughcontact before checksums) was "
        "recomputed, not reused.\n"
    ) in err
    assert "checksum" in record(output, case)
    assert_same_as_clean(clean[1], output)


# --- provenance counts what is on disk ------------------------------------------------------------


def _disk_full_after(monkeypatch, stored: int, *, summary_too: bool = False):
    """Make every case record written after ``stored`` of them fail as a full disk does.

    With ``summary_too`` the results table and provenance written after the cases fail too.
    """
    import roughcontact.study.run as run_module
    import roughcontact.study.store as store_module

    written = []
    original = store_module.write_atomically

    def write(path: Path, data) -> None:
        is_case = "cases" in Path(path).parts
        summary = Path(path).name in ("results.csv", "provenance.json")
        if (is_case and len(written) >= stored) or (summary_too and summary):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))
        if is_case:
            written.append(path)
        original(path, data)

    monkeypatch.setattr(run_module, "write_atomically", write)
    monkeypatch.setattr(store_module, "write_atomically", write)


def test_a_full_disk_stops_the_run_and_provenance_counts_the_cases_on_disk(clean, tmp_path, monkeypatch, cli):
    study, _ = clean
    output = tmp_path / "out"
    _disk_full_after(monkeypatch, 1)
    with pytest.raises(InputError) as raised:
        run_study(load_study(study), output)
    message = str(raised.value)
    assert "No space left on device" in message and "The run stopped with 1 of 3 cases stored" in message
    assert "rerun with --resume" in message and "provenance.json counts them" in message
    assert len(list((output / "cases").rglob("*.json"))) == 1
    document = provenance(output)
    assert document["cases"] == {"total": 3, "reused": 0, "done": 1, "failed": 0, "pending": 2}
    assert document["complete"] is False and "No space left on device" in document["store_error"]
    assert sorted(row["status"] for row in results_rows(output).values()) == ["done", "pending", "pending"]
    assert not (output / LOCK).exists()

    # the disk still full, now for the table and provenance too: the earlier ones are removed, not
    # left saying what is no longer so
    monkeypatch.undo()
    _disk_full_after(monkeypatch, 0, summary_too=True)
    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 2
    assert "could not store case" in err and "No space left on device" in err
    assert "results.csv and provenance.json could not be written either" in err
    assert not (output / "provenance.json").exists() and not (output / "results.csv").exists()

    monkeypatch.undo()
    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 0 and "2 cases run, 1 reused, 0 failed" in out
    assert provenance(output)["cases"] == {"total": 3, "reused": 1, "done": 2, "failed": 0, "pending": 0}
    assert_same_as_clean(clean[1], output)


def test_provenance_is_counted_from_disk_not_from_what_the_run_computed(copy, monkeypatch):
    # a case removed after the run reused it, before its table is written: provenance says it is gone
    import roughcontact.study.outputs as outputs

    study, output = copy
    gone = cases(output)[1]
    original = outputs.write_results_table

    def remove_then_write(folder):
        record_path(output, "contact", gone).unlink()
        return original(folder)

    monkeypatch.setattr(outputs, "write_results_table", remove_then_write)
    summary = run_study(load_study(study), output, resume=True)
    assert summary.skipped == 3
    document = provenance(output)
    assert document["cases"] == {"total": 3, "reused": 2, "done": 0, "failed": 0, "pending": 1}
    assert document["complete"] is False


# --- one run at a time ------------------------------------------------------------------------------

HOLD = """
import sys, time
from pathlib import Path
from roughcontact.study.store import locked
with locked(Path(sys.argv[1])):
    print("held", flush=True)
    time.sleep(120)
"""


def test_a_second_run_is_refused_while_the_first_holds_the_folder_and_a_killed_run_leaves_no_lock(
    clean, copy, cli
):
    study, output = copy
    holder = subprocess.Popen([sys.executable, "-c", HOLD, str(output)], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        with pytest.raises(InputError) as raised:
            run_study(load_study(study), output, resume=True)
        message = str(raised.value)
        assert f"{output} is in use by another roughcontact run (pid {holder.pid} on" in message
        assert "wait for it to finish, or write to another folder (-o)" in message
        for argv in (("run", study, "-o", output, "--resume", "--no-progress"), ("report", output)):
            status, out, err = cli(*argv)
            assert status == 2 and f"is in use by another roughcontact run (pid {holder.pid} on" in err
        assert json.loads((output / LOCK).read_text())["pid"] == holder.pid  # untouched
    finally:
        holder.kill()  # SIGKILL: no clean-up, the lock file stays
        holder.wait()
    assert (output / LOCK).exists()
    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 0 and "0 cases run, 3 reused" in out
    assert (
        f"roughcontact: note: took over {output}/{LOCK}, left by a run that is no longer running (pid " in err
    )
    assert f"(pid {holder.pid} on" in err
    assert_same_as_clean(clean[1], output)


def _lock_of(pid: int, host: str | None = None) -> str:
    return json.dumps(
        {"pid": pid, "host": host or socket.gethostname(), "started": "2025-01-01T00:00:00+00:00"}
    )


def test_a_lock_written_with_a_live_pid_is_refused_and_one_with_a_dead_pid_taken_over(clean, copy, cli):
    study, output = copy
    sleeper = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(120)"])
    try:
        (output / LOCK).write_text(_lock_of(sleeper.pid))
        status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
        assert status == 2
        assert f"is in use by another roughcontact run (pid {sleeper.pid} on {socket.gethostname()}" in err
    finally:
        sleeper.kill()
        sleeper.wait()
    # the same pid, now dead (and reaped): the lock is taken over, with a note
    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 0 and "0 cases run, 3 reused" in out
    assert f"took over {output}/{LOCK}, left by a run that is no longer running (pid {sleeper.pid}" in err
    assert not (output / LOCK).exists()

    # another machine's lock: its process cannot be seen from here, so it is refused with the way out
    (output / LOCK).write_text(_lock_of(1, host="another-machine.example"))
    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 2 and "(pid 1 on another-machine.example" in err
    assert f"If no run uses the folder any more, remove {output}/{LOCK}." in err
    (output / LOCK).unlink()
    assert_same_as_clean(clean[1], output)


def test_the_lock_is_released_after_ctrl_c_and_an_error_and_is_held_once_per_process(copy):
    study, output = copy

    def interrupt(record):
        raise KeyboardInterrupt

    with pytest.raises(InputError, match="already holds a study's results"):
        run_study(load_study(study), output)  # refused inside the lock: released all the same
    assert not (output / LOCK).exists()
    fresh = output.parent / "fresh"
    with pytest.raises(KeyboardInterrupt):
        run_study(load_study(study), fresh, on_record=interrupt)
    assert not (fresh / LOCK).exists() and provenance(fresh)["interrupted"] is True
    with locked(fresh) as note:  # re-entrant: the runner inside a command's lock takes it again
        assert note is None and json.loads((fresh / LOCK).read_text())["pid"] == os.getpid()
        run_study(load_study(study), fresh, resume=True)
        assert (fresh / LOCK).exists()
    assert not (fresh / LOCK).exists()


def test_a_sealed_record_verifies_and_any_change_of_it_does_not(clean):
    _, output = clean
    case = cases(output)[0]
    stored = record(output, case)
    assert sealed(stored) == stored
    changed = stored | {"scalars": stored["scalars"] | {"contact_fraction": 0.5}}
    assert sealed(changed)["checksum"] != stored["checksum"]
