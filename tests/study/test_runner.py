"""The study runner's promises: resume, failures, Dask (also with a worker killed), Ctrl-C, provenance.

Every study here is small and real: generated self-affine surfaces solved by the ``normal`` kind
(64^2: a few ms per case) and the ``statistics`` of a topography file written in the test. Results
are compared bitwise (floats by their hex form, fields by their bytes); only the timing and host
entries of a record (``seconds``, ``started``, ``pid``, ``host``) may differ between runs.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import shutil
import signal
import time
from pathlib import Path

import numpy as np
import pytest

import roughcontact
from roughcontact.cli import EXIT_CASES_FAILED, EXIT_INPUT_ERROR, EXIT_INTERRUPTED
from roughcontact.cli.study import run_and_report
from roughcontact.errors import ConvergenceError
from roughcontact.study import load_study, run_study
from roughcontact.study.outputs import write_results_table
from roughcontact.study.store import read_table, record_path

TIMING = ("seconds", "started", "pid", "host", "checksum")
"""Entries of a case record that say when, where and how long, not what: excluded from comparisons
(with the record's checksum, which covers them; the fields file's checksum is compared)."""

STUDY = """
[study]
name = "runner test"
seed = 11
{topography_file}
[topographies.rough]
generate = "self_affine"
shape = {shape}
size = "5 um"
hurst = 0.8
rms_height = "1 nm"
{statistics}
[[analysis]]
name = "contact"
model = "normal"
surface = "rough"
material = "polysilicon"
mean_pressure = "1 MPa"
figures = []
{extra}
[analysis.sweep]
mean_pressure = {pressures}
replicate = {replicates}
"""

STATISTICS = """
[[analysis]]
name = "stats"
model = "statistics"
surface = "scan"
figures = []
"""

PRESSURES = ("5 MPa", "10 MPa", "20 MPa")


def write_study(
    folder: Path,
    *,
    scan: Path | None = None,
    pressures=PRESSURES,
    replicates=(0, 1),
    shape: int = 64,
    extra: str = "",
    name: str = "study.toml",
) -> Path:
    """Write a study: ``normal`` contact over pressures x replicates, and the statistics of ``scan``."""
    text = STUDY.format(
        topography_file=f'\n[topographies.scan]\nfile = "{scan}"\n' if scan else "",
        statistics=STATISTICS if scan else "",
        shape=shape,
        extra=extra,
        pressures=json.dumps(list(pressures)),
        replicates=json.dumps(list(replicates)),
    )
    path = folder / name
    path.write_text(text)
    return path


def stop_after(count: int):
    """An ``on_record`` callback that raises KeyboardInterrupt (Ctrl-C) after ``count`` stored cases."""
    seen = []

    def on_record(record):
        seen.append(record["case"])
        if len(seen) == count:
            raise KeyboardInterrupt

    return on_record


def case_ids(folder: Path) -> dict[str, list[str]]:
    """Analysis -> its case ids, as the output folder's study.json lists them."""
    document = json.loads((folder / "study.json").read_text())
    return {entry["name"]: entry["cases"] for entry in document["analyses"]}


def hexed(value):
    """``value`` with every float as its hex form, so that == is a bitwise comparison."""
    if isinstance(value, float):
        return value.hex()
    if isinstance(value, dict):
        return {k: hexed(v) for k, v in value.items()}
    if isinstance(value, list):
        return [hexed(v) for v in value]
    return value


def stored_fields(path: Path) -> dict:
    """Every variable and coordinate of a case's NetCDF file as (dims, dtype, bytes)."""
    import xarray as xr

    data = xr.load_dataset(path)
    return {
        name: (data[name].dims, str(data[name].dtype), np.ascontiguousarray(data[name].values).tobytes())
        for name in [*data.data_vars, *data.coords]
    }


def results(folder: Path) -> dict[str, tuple[dict, dict | None]]:
    """``analysis/case`` -> (record without timing, fields) of every case study.json lists.

    Fails if a listed case has no record: call it on finished studies.
    """
    found = {}
    for analysis, cases in case_ids(folder).items():
        for case in cases:
            record = json.loads(record_path(folder, analysis, case).read_text())
            fields = None if record["fields"] is None else stored_fields(folder / record["fields"])
            found[f"{analysis}/{case}"] = ({k: v for k, v in record.items() if k not in TIMING}, fields)
    return found


def assert_same_results(expected: Path, actual: Path) -> None:
    """Both output folders hold the same cases with bitwise equal records, fields and table rows."""
    want, got = results(expected), results(actual)
    assert list(got) == list(want)
    for name, (record, fields) in want.items():
        assert got[name][0]["status"] == "done"
        assert hexed(got[name][0]) == hexed(record), name
        assert got[name][1] == fields, name
    table = [{k: v for k, v in row.items() if k != "seconds"} for row in read_table(expected / "results.csv")]
    assert [
        {k: v for k, v in row.items() if k != "seconds"} for row in read_table(actual / "results.csv")
    ] == (table)


def assert_nothing_half_written(folder: Path) -> None:
    """No temporary files; every record is complete JSON and every fields file a readable NetCDF file."""
    assert not list(folder.rglob("*.part"))
    for path in (folder / "cases").rglob("*.json"):
        record = json.loads(path.read_text())
        assert record["status"] in ("done", "failed") and record["case"] == path.stem
    for path in (folder / "cases").rglob("*.nc"):
        assert stored_fields(path)


def file_identities(folder: Path) -> dict[str, tuple[int, int]]:
    """Path -> (inode, mtime in ns) of every stored case file: a rewritten file changes its inode."""
    return {
        str(path.relative_to(folder)): (path.stat().st_ino, path.stat().st_mtime_ns)
        for path in sorted((folder / "cases").rglob("*"))
        if path.is_file()
    }


def statuses(folder: Path) -> dict[str, str]:
    """``analysis/case`` -> status of every row of results.csv (which must hold each case once)."""
    rows = read_table(folder / "results.csv")
    names = [f"{row['analysis']}/{row['case']}" for row in rows]
    assert len(names) == len(set(names)), "a case appears twice in results.csv"
    return {name: row["status"] for name, row in zip(names, rows, strict=True)}


def provenance(folder: Path) -> dict:
    return json.loads((folder / "provenance.json").read_text())


# --- a reference study, run once, uninterrupted, in-process ---------------------------------------


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """(study file, output folder) of the study run once, uninterrupted, in-process (7 cases)."""
    from roughcontact.topography.generate import self_affine
    from roughcontact.topography.native import save_topography

    folder = tmp_path_factory.mktemp("reference")
    scan = folder / "scan.nc"
    save_topography(self_affine((32, 32), (2e-6, 2e-6), hurst=0.7, rms_height=2e-9, seed=5), scan)
    study = write_study(folder, scan=scan)
    output = folder / "A"
    summary = run_study(load_study(study), output)
    assert (summary.done, summary.failed, summary.total) == (7, 0, 7)
    return study, output


def test_provenance_and_table_of_a_finished_run(reference):
    study_path, output = reference
    study = load_study(study_path)
    document = provenance(output)
    assert document["roughcontact"] == roughcontact.__version__
    scan = str((study_path.parent / "scan.nc").resolve())
    assert document["input_files"] == {scan: hashlib.sha256(Path(scan).read_bytes()).hexdigest()}
    assert document["study_sha256"] == hashlib.sha256(study_path.read_text().encode()).hexdigest()
    assert document["study_seed"] == 11
    # seeds: one per generated topography per case, derived per (sample, replicate), as in the records
    seeds = {f"{c.analysis}/{c.case_id}": c.seeds for c in study.cases if c.seeds}
    assert document["seeds"] == seeds and len(seeds) == 6
    by_replicate = {c.parameters.replicate: c.seeds["rough"] for c in study.analysis("contact").cases}
    assert len(set(by_replicate.values())) == 2
    stored = results(output)
    for name, case_seeds in seeds.items():
        assert stored[name][0]["seeds"] == case_seeds
    assert document["executor"] == "in-process"
    assert document["cases"] == {"total": 7, "reused": 0, "done": 7, "failed": 0, "pending": 0}
    assert document["complete"] is True and document["interrupted"] is False
    assert document["wall_seconds"] >= document["case_seconds"] > 0
    records = [json.loads(p.read_text()) for p in (output / "cases").rglob("*.json")]
    assert document["case_seconds"] == pytest.approx(sum(r["seconds"] for r in records))
    assert document["started"] <= document["finished"]
    # results.csv: one row per case, in study order, scalars exactly as in the records, SI units
    rows = read_table(output / "results.csv")
    assert [f"{r['analysis']}/{r['case']}" for r in rows] == list(stored)
    assert {r["status"] for r in rows} == {"done"}
    for row in rows:
        record = stored[f"{row['analysis']}/{row['case']}"][0]
        if row["analysis"] == "contact":
            assert float(row["mean_pressure [Pa]"]) == record["axes_si"]["mean_pressure"]  # as asked
            assert float(row["mean_pressure (result) [Pa]"]) == record["scalars"]["mean_pressure"]  # solved
            assert float(row["contact_fraction"]) == record["scalars"]["contact_fraction"]
            assert row["replicate"] == str(record["parameters"]["replicate"])
        else:
            assert float(row["Sq [m]"]) == record["scalars"]["Sq"]


# --- interruption and resume ---------------------------------------------------------------------


def test_resume_after_interruptions_reproduces_the_uninterrupted_run(reference, tmp_path, monkeypatch, cli):
    study_path, expected = reference
    output = tmp_path / "B"
    total = 7

    # 1. Ctrl-C after two stored cases
    with pytest.raises(KeyboardInterrupt):
        run_study(load_study(study_path), output, on_record=stop_after(2))
    table = statuses(output)
    assert len(table) == total
    assert sorted(table.values()) == ["done"] * 2 + ["pending"] * 5
    document = provenance(output)
    assert document["complete"] is False and document["interrupted"] is True
    assert document["cases"] == {"total": 7, "reused": 0, "done": 2, "failed": 0, "pending": 5}
    assert_nothing_half_written(output)

    # 2. a real SIGINT that arrives in the middle of the next case's solve (resumed run)
    from roughcontact.contact import _constrained_cg

    solve, calls = _constrained_cg.solve, []

    def solve_then_interrupt(*args, **kwargs):
        calls.append(1)
        if len(calls) == 2:  # the second case of this run: its surface is built, its solve starts
            os.kill(os.getpid(), signal.SIGINT)
        return solve(*args, **kwargs)

    monkeypatch.setattr(_constrained_cg, "solve", solve_then_interrupt)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt):
            run_study(load_study(study_path), output, resume=True)
    finally:
        signal.signal(signal.SIGINT, previous)
    monkeypatch.undo()
    assert len(calls) == 2
    table = statuses(output)
    assert sorted(table.values()) == ["done"] * 3 + ["pending"] * 4
    document = provenance(output)
    assert document["complete"] is False and document["interrupted"] is True
    assert document["cases"] == {"total": 7, "reused": 2, "done": 1, "failed": 0, "pending": 4}
    assert_nothing_half_written(output)

    # 3. what a killed process (SIGKILL: no clean-up) leaves: a half-written NetCDF file under its
    #    temporary name, and a stale record with another key (status done, wrong numbers)
    pending = [name.split("/") for name, status in table.items() if status == "pending"]
    (analysis, half), (stale_analysis, stale) = pending[0], pending[1]
    partial = output / "cases" / analysis / f".{half}.nc.x1y2z3.part"
    partial.write_bytes(b"\x89HDF\r\n\x1a\n" + b"\0" * 100)
    old = json.loads(record_path(expected, stale_analysis, stale).read_text())
    old |= {"key": "0" * 64, "scalars": {k: 1.0 for k in old["scalars"]}}
    record_path(output, stale_analysis, stale).parent.mkdir(parents=True, exist_ok=True)
    record_path(output, stale_analysis, stale).write_text(json.dumps(old))

    status, out, err = cli("run", study_path, "-o", output, "--resume", "--no-progress")
    assert status == 0, err
    assert "4 cases run, 3 reused, 0 failed" in out
    assert not partial.exists()
    assert_nothing_half_written(output)
    for name, cases in case_ids(output).items():  # each case once, nothing else
        assert sorted(p.stem for p in (output / "cases" / name).glob("*.json")) == sorted(cases)
    assert set(statuses(output).values()) == {"done"}
    assert_same_results(expected, output)
    document = provenance(output)
    assert document["complete"] is True and document["interrupted"] is False
    assert document["cases"] == {"total": 7, "reused": 3, "done": 4, "failed": 0, "pending": 0}


def test_results_table_marks_a_stale_record_pending(reference, tmp_path):
    study_path, expected = reference
    output = tmp_path / "B"
    with pytest.raises(KeyboardInterrupt):
        run_study(load_study(study_path), output, on_record=stop_after(1))
    analysis, case = next(name for name, s in statuses(output).items() if s == "pending").split("/")
    old = json.loads(record_path(expected, analysis, case).read_text())
    record_path(output, analysis, case).parent.mkdir(parents=True, exist_ok=True)
    old |= {"key": "0" * 64, "scalars": {k: 1.0 for k in old["scalars"]}}
    record_path(output, analysis, case).write_text(json.dumps(old))
    write_results_table(output)
    assert statuses(output)[f"{analysis}/{case}"] == "pending"


def test_resume_reruns_nothing_or_only_changed_cases_and_a_plain_rerun_is_refused(reference, tmp_path, cli):
    study_path, expected = reference
    output = tmp_path / "A"
    shutil.copytree(expected, output)
    before = file_identities(output)

    status, out, err = cli("run", study_path, "-o", output, "--resume", "--no-progress")
    assert status == 0, err
    assert "0 cases run, 7 reused, 0 failed" in out
    assert file_identities(output) == before  # finished cases are not touched
    assert provenance(output)["cases"] == {"total": 7, "reused": 7, "done": 0, "failed": 0, "pending": 0}

    # change one swept value: only its cases (both replicates) get new keys and run
    changed = write_study(
        tmp_path, scan=study_path.parent / "scan.nc", pressures=("5 MPa", "12 MPa", "20 MPa"), name="c.toml"
    )
    old_cases, new_cases = load_study(study_path).cases, load_study(changed).cases
    different = [new.case_id for old, new in zip(old_cases, new_cases, strict=True) if old.key != new.key]
    assert len(different) == 2
    ran = []
    summary = run_study(load_study(changed), output, resume=True, on_record=lambda r: ran.append(r["case"]))
    assert sorted(ran) == sorted(different)
    assert (summary.skipped, summary.done, summary.failed) == (5, 2, 0)
    after = file_identities(output)
    assert {k: v for k, v in after.items() if k in before} == before  # nothing rewritten, old kept
    assert sorted(set(after) - set(before)) == sorted(
        f"cases/contact/{case}.{suffix}" for case in different for suffix in ("json", "nc")
    )
    rows = {r["case"]: r for r in read_table(output / "results.csv")}
    # the swept value, as asked (the solved one is in "mean_pressure (result) [Pa]")
    assert [float(rows[c]["mean_pressure [Pa]"]) for c in different] == pytest.approx([12e6, 12e6], rel=1e-12)

    # without --resume the folder is refused, with the documented message, and nothing changes
    status, out, err = cli("run", study_path, "-o", output, "--no-progress")
    assert status == 2
    assert "already holds a study's results" in err and "pass --resume to continue it" in err
    assert file_identities(output) == after


def test_extending_a_sweep_reuses_every_unchanged_case(reference, tmp_path):
    study_path, expected = reference
    output = tmp_path / "A"
    shutil.copytree(expected, output)
    more = write_study(tmp_path, scan=study_path.parent / "scan.nc", replicates=(0, 1, 2), name="more.toml")
    old_keys = {case.key for case in load_study(study_path).cases}
    new = [case for case in load_study(more).cases if case.key not in old_keys]
    assert len(new) == 3  # one new replicate per pressure; the 7 old cases keep their keys
    ran = []
    summary = run_study(load_study(more), output, resume=True, on_record=lambda r: ran.append(r["case"]))
    assert sorted(ran) == sorted(case.case_id for case in new)
    assert (summary.skipped, summary.done) == (7, 3)


# --- failures ------------------------------------------------------------------------------------


def test_a_load_the_scan_cannot_carry_fails_validation_with_the_case_named(tmp_path, cli):
    # hardness 15 MPa caps the pressure: a mean pressure of 20 MPa is more than the surface can carry,
    # known before anything runs (issue 32: validate runs every check run runs)
    study_path = write_study(tmp_path, replicates=(0,), extra='hardness = "15 MPa"')
    for command in ("validate", "run"):
        arguments = (study_path,) if command == "validate" else (study_path, "-o", tmp_path / "out")
        status, out, err = cli(command, *arguments)
        assert status == EXIT_INPUT_ERROR
        assert "sweep.mean_pressure" in err and "20 MPa" in err and "hardness 15 MPa" in err
        assert "Traceback" not in err
    assert not (tmp_path / "out").exists()


def test_a_failing_case_is_recorded_the_others_finish_and_resume_retries_only_it(tmp_path, cli, monkeypatch):
    # a solver that does not converge at 20 MPa (what validation cannot know): that case fails
    import roughcontact.contact as contact

    original = contact.solve_normal

    def stalls_above_15_mpa(*args, **kwargs):
        if (kwargs.get("mean_pressure") or 0) > 15e6:
            raise ConvergenceError("solve_normal", 1e-3, 10_000, 1e-8)
        return original(*args, **kwargs)

    monkeypatch.setattr(contact, "solve_normal", stalls_above_15_mpa)
    study_path = write_study(tmp_path, replicates=(0,))
    output = tmp_path / "out"
    status, out, err = cli("run", study_path, "-o", output, "--no-progress")
    assert status == EXIT_CASES_FAILED
    assert "2 cases run, 0 reused, 1 failed" in out
    (failed,) = [c for c in load_study(study_path).cases if c.parameters.mean_pressure > 15e6]
    label = ", ".join(
        f"{axis.rsplit('.', 1)[-1].replace('_', ' ')} {value}" for axis, value in failed.axes.items()
    )
    assert f"failed: contact ({label}): ConvergenceError: solve_normal did not converge" in err
    assert failed.case_id not in err

    rows = {r["case"]: r for r in read_table(output / "results.csv")}
    assert len(rows) == 3
    assert [r["status"] for r in rows.values()] == ["done", "done", "failed"]
    assert "residual" in rows[failed.case_id]["error"] and not rows[failed.case_id].get("contact_fraction")
    assert all(r["error"] == "" and float(r["contact_fraction"]) > 0 for r in list(rows.values())[:2])
    record = json.loads(record_path(output, "contact", failed.case_id).read_text())
    assert record["status"] == "failed" and record["scalars"] == {} and record["fields"] is None
    assert "solve_normal did not converge" in record["error"]
    assert "stalls_above_15_mpa" in record["traceback"]
    assert provenance(output)["cases"] == {"total": 3, "reused": 0, "done": 2, "failed": 1, "pending": 0}

    before = file_identities(output)
    status, out, err = cli("run", study_path, "-o", output, "--resume", "--no-progress")
    assert status == EXIT_CASES_FAILED
    assert "0 cases run, 2 reused, 1 failed" in out
    after = file_identities(output)
    retried = f"cases/contact/{failed.case_id}.json"
    assert after[retried] != before[retried]  # rewritten: a new file renamed into place
    assert {k: v for k, v in after.items() if k != retried} == {
        k: v for k, v in before.items() if k != retried
    }
    assert provenance(output)["cases"] == {"total": 3, "reused": 2, "done": 0, "failed": 1, "pending": 0}


# --- Ctrl-C through the command line -------------------------------------------------------------


def test_ctrl_c_exits_130_with_the_resume_hint(reference, tmp_path, capsys, monkeypatch):
    import roughcontact.study.answers as answer_module

    study_path, _ = reference
    output = tmp_path / "C"
    stopping = functools.partial(answer_module.run_study, on_record=stop_after(1))
    monkeypatch.setattr(answer_module, "run_study", stopping)  # Ctrl-C after the first case
    status = run_and_report(load_study(study_path), output, progress=False)
    captured = capsys.readouterr()
    assert status == EXIT_INTERRUPTED == 130
    assert "interrupted: finished cases are kept in" in captured.err
    assert "rerun the same command with --resume" in captured.err
    assert sorted(statuses(output).values()) == ["done"] + ["pending"] * 6
    assert provenance(output)["interrupted"] is True


# --- Dask ----------------------------------------------------------------------------------------


def test_local_dask_cluster_gives_the_in_process_numbers(reference, tmp_path, cli):
    study_path, expected = reference
    output = tmp_path / "D"
    status, out, err = cli("run", study_path, "-o", output, "--workers", "2", "--no-progress")
    assert status == 0, err
    assert "7 cases run, 0 reused, 0 failed" in out
    assert provenance(output)["executor"] == "dask local cluster, 2 workers"
    records = [json.loads(p.read_text()) for p in (output / "cases").rglob("*.json")]
    assert os.getpid() not in {r["pid"] for r in records}  # really solved elsewhere
    assert_same_results(expected, output)


def test_dask_says_nothing_of_its_own_on_the_terminal(reference, tmp_path):
    """A run on a local cluster prints our lines only: no log line of Dask's, from any process."""
    import subprocess
    import sys

    study_path, _ = reference
    command = [sys.executable, "-m", "roughcontact", "run", str(study_path), "-o", str(tmp_path / "E")]
    done = subprocess.run([*command, "--workers", "2"], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    lines = (done.stdout + done.stderr).splitlines()
    assert lines and not [line for line in lines if "distributed" in line or "dask." in line.lower()]


@pytest.fixture(scope="module")
def cluster():
    """A real local Dask cluster on loopback: 2 single-threaded worker processes, each under a nanny."""
    import logging

    from distributed import Client, LocalCluster

    with (
        LocalCluster(
            processes=True,
            host="127.0.0.1",
            n_workers=2,
            threads_per_worker=1,
            dashboard_address=":0",
            silence_logs=logging.CRITICAL,
        ) as local,
        Client(local) as client,
    ):
        yield local, client


def test_a_killed_dask_worker_loses_no_case_and_stores_each_once(cluster, tmp_path):
    local, client = cluster
    # 8 cases of 0.2-0.3 s (384^2): long enough for the kill to land in the middle of one
    study_path = write_study(tmp_path, pressures=("2 MPa", "5 MPa", "10 MPa", "20 MPa"), shape=384)
    expected = tmp_path / "in-process"
    run_study(load_study(study_path), expected)

    pids = client.run(os.getpid)  # worker address -> pid
    keys = []
    seen: list[str] = []
    suspicious: dict[str, int] = {}

    def on_record(record):
        seen.append(record["case"])
        if len(seen) == 1:
            # kill the worker that sent the first case: it has been given its next one; wait (by
            # polling the scheduler, bounded) until the scheduler lists it as processing there
            (address,) = [a for a, pid in pids.items() if pid == record["pid"]]
            deadline = time.monotonic() + 60
            while not (processing := client.processing(workers=[address])[address]):
                assert time.monotonic() < deadline, "the worker got no second case"
                time.sleep(0.005)
            keys.extend(processing)
            os.kill(record["pid"], signal.SIGKILL)
        if len(seen) == 8:  # all in: read how often the scheduler saw a task's worker die under it
            suspicious.update(
                client.run_on_scheduler(
                    lambda dask_scheduler: {
                        str(k): ts.suspicious for k, ts in dask_scheduler.tasks.items() if ts.suspicious
                    }
                )
            )

    output = tmp_path / "dask"
    summary = run_study(
        load_study(study_path), output, scheduler=local.scheduler_address, on_record=on_record
    )
    assert (summary.done, summary.failed, summary.pending) == (8, 0, 0)
    assert summary.executor == f"dask scheduler {local.scheduler_address}"
    assert keys and all(suspicious.get(k, 0) >= 1 for k in keys)  # the kill hit running cases
    assert sorted(seen) == sorted(case_ids(output)["contact"])  # each stored once
    assert len(list((output / "cases" / "contact").glob("*.json"))) == 8
    assert_nothing_half_written(output)
    assert_same_results(expected, output)
