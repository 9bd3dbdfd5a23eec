"""Study runner overhead: a 100-case sweep of small normal contacts, through the runner and directly.

The sweep: periodic self-affine surfaces (H = 0.8, Rq = 1 nm, 5 um, ``--size`` points a side) in
polysilicon against a rigid flat, 10 mean pressures (2 to 50 MPa, log-spaced) x 10 replicates
(each its own derived seed). Timed, each best of ``--repeats``, alternately:

* (a) the solves alone: ``solve_normal`` called in a loop on the same surfaces (built beforehand,
  from the cases' own specifications and seeds) and loads, in the same order;
* (b) the study: ``load_study`` (validation, case building) + ``run_study`` in-process into a new
  folder (each case's NetCDF file and JSON record, the results table, the provenance; no figures
  or report: ``run_study`` draws none, and the analysis sets ``figures = []``);
* (c) unless ``--no-dask``: ``run_study`` on a local Dask cluster of 2 single-threaded worker
  processes (started and warmed up beforehand; its start is printed separately).

The runner's overhead is (b - a) / a. Runs of (b) are instrumented: every function a case passes
through in the runner is wrapped with a timer (a microsecond per call): surface generation,
``solve_normal``, the kind's post-processing, ``execute``, NetCDF and JSON writes, ``fsync``, task
building, table and provenance. So the overhead is also given within one run, against that run's
own solves, which is robust to a machine whose load drifts between runs (a shared one: compare
the best-of-N lines only on a quiet machine). ``--profile`` adds cProfile's top entries of one more
run. The direct and the runner's results are checked to be equal, bitwise. Ends with one JSON line.

    python benchmarks/study_runner.py [--size 256] [--repeats 3] [--no-dask] [--profile]
"""

from __future__ import annotations

import argparse
import contextlib
import cProfile
import io
import json
import os
import platform
import pstats
import shutil
import statistics
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

STUDY = """
[study]
name = "runner overhead"
seed = 1

[topographies.rough]
generate = "self_affine"
shape = {size}
size = "5 um"
hurst = 0.8
rms_height = "1 nm"

[[analysis]]
name = "contact"
model = "normal"
topography = "rough"
material = "polysilicon"
mean_pressure = "1 MPa"
tolerance = {tolerance}
figures = []
[analysis.sweep]
mean_pressure = {{start = "2 MPa", stop = "50 MPa", num = {pressures}, spacing = "log"}}
replicate = {{start = 0, stop = {last_replicate}, step = 1}}
"""


def write_study(folder: Path, size: int, tolerance: float, pressures: int = 10, replicates: int = 10) -> Path:
    path = folder / f"study-{size}-{pressures}x{replicates}.toml"
    path.write_text(
        STUDY.format(size=size, tolerance=tolerance, pressures=pressures, last_replicate=replicates - 1)
    )
    return path


def direct_solves(study):
    """Time (a): solve_normal on the cases' surfaces and loads, in order.

    Returns the seconds of the solves, their scalars, and the seconds of building the surfaces.
    """
    from roughcontact.contact import solve_normal
    from roughcontact.study.inputs import build_topography

    start = time.perf_counter()
    problems = [
        (
            build_topography(case.topographies[case.parameters.topography], None),
            case.materials[case.parameters.material],
            case.parameters,
        )
        for case in study.cases
    ]
    build = time.perf_counter() - start
    seconds, scalars = 0.0, []
    for surface, material, parameters in problems:
        start = time.perf_counter()
        result = solve_normal(
            surface, material, mean_pressure=parameters.mean_pressure, tolerance=parameters.tolerance
        )
        seconds += time.perf_counter() - start
        scalars.append(result.scalars())
    return seconds, scalars, build


def through_runner(study_path: Path, folder: Path, **options) -> tuple[float, object]:
    """Time load_study + run_study into a new folder; return (seconds, summary)."""
    from roughcontact.study import load_study, run_study

    shutil.rmtree(folder, ignore_errors=True)
    start = time.perf_counter()
    summary = run_study(load_study(study_path), folder, **options)
    return time.perf_counter() - start, summary


class Timers:
    """Accumulated seconds of wrapped functions."""

    def __init__(self):
        self.seconds: dict[str, float] = defaultdict(float)

    def wrap(self, name: str, function):
        def timed(*args, **kwargs):
            start = time.perf_counter()
            try:
                return function(*args, **kwargs)
            finally:
                self.seconds[name] += time.perf_counter() - start

        return timed


@contextlib.contextmanager
def instrumented(timers: Timers):
    """Wrap the functions a case passes through in the runner with timers (restored on exit)."""
    import roughcontact.contact
    import roughcontact.study.inputs as inputs
    import roughcontact.study.run as run

    targets = [
        (run, "run_study"),
        (run, "make_task"),
        (run, "execute"),
        (inputs, "build_topography"),
        (roughcontact.contact, "solve_normal"),  # the normal kind imports it at call time
        (run, "store"),
        (run, "write_dataset"),
        (run, "write_summary_files"),
        (os, "fsync"),  # store.write_atomically's
    ]
    saved = [(module, name, getattr(module, name)) for module, name in targets]
    try:
        for module, name in targets:
            setattr(module, name, timers.wrap(name, getattr(module, name)))
        yield
    finally:
        for module, name, function in saved:
            setattr(module, name, function)


def instrumented_run(study_path: Path, folder: Path) -> tuple[float, dict[str, float]]:
    """Time (b) with the timers on; return (seconds, part -> seconds)."""
    import roughcontact.study.run as run
    from roughcontact.study.config import load_study

    timers, kind = Timers(), []
    with instrumented(timers):
        shutil.rmtree(folder, ignore_errors=True)
        start = time.perf_counter()
        study = timers.wrap("load_study", load_study)(study_path)
        run.run_study(study, folder, on_record=lambda record: kind.append(record["seconds"]))
        total = time.perf_counter() - start
    s = timers.seconds
    inside_run = s["execute"] + s["store"] + s["make_task"] + s["write_summary_files"]
    parts = {
        "solve_normal (inside the cases)": s["solve_normal"],
        "surface generation (inside the cases)": s["build_topography"],
        "kind post-processing: scalars, to_xarray": sum(kind) - s["solve_normal"] - s["build_topography"],
        "execute around the kind (record, timing)": s["execute"] - sum(kind),
        "per-case NetCDF writes": s["write_dataset"],
        "per-case JSON records (dump, write, fsync, rename)": s["store"] - s["write_dataset"],
        "  of which fsync (with the summary files')": s["fsync"],
        "task building (make_task)": s["make_task"],
        "validation and case building (load_study)": s["load_study"],
        "results table and provenance": s["write_summary_files"],
        "run_study rest (folder, study.json, loop)": s["run_study"] - inside_run,
        "total": total,
        "  case work besides solve_normal (in execute)": s["execute"] - s["solve_normal"],
        "  runner proper (all but execute)": total - s["execute"],
    }
    return total, parts


def profile_run(study_path: Path, folder: Path, entries: int = 25) -> str:
    """cProfile one more run of (b); return the top entries by own time."""
    profiler = cProfile.Profile()
    profiler.enable()
    through_runner(study_path, folder)
    profiler.disable()
    stream = io.StringIO()
    pstats.Stats(profiler, stream=stream).sort_stats("tottime").print_stats(entries)
    return stream.getvalue()


def same_results(folder: Path, scalars: list[dict]) -> bool:
    """True when the runner's stored scalars equal the direct solves' (floats bitwise, in case order)."""
    from roughcontact.study.store import json_ready

    document = json.loads((folder / "study.json").read_text())
    stored = [
        json.loads((folder / "cases" / "contact" / f"{case}.json").read_text())["scalars"]
        for case in document["analyses"][0]["cases"]
    ]
    return json.dumps(stored) == json.dumps(json_ready(scalars))


def warm_up(folder: Path, tolerance: float) -> float:
    """One small study run (imports, numba's cached kernels, the NetCDF writer); return its seconds."""
    start = time.perf_counter()
    through_runner(write_study(folder, 32, tolerance, pressures=2, replicates=1), folder / "warm-up")
    return time.perf_counter() - start


def dask_run(study_path: Path, folder: Path, tolerance: float, repeats: int) -> dict:
    """Time (c) on a local cluster of 2 single-threaded workers, started and warmed up first."""
    import logging

    from distributed import LocalCluster

    start = time.perf_counter()
    with LocalCluster(
        n_workers=2,
        threads_per_worker=1,
        processes=True,
        host="127.0.0.1",
        dashboard_address=":0",
        silence_logs=logging.CRITICAL,
    ) as cluster:
        started = time.perf_counter() - start
        address = cluster.scheduler_address
        small = write_study(folder, 32, tolerance, pressures=2, replicates=2)
        warm, _ = through_runner(small, folder / "dask-warm-up", scheduler=address)
        runs = [through_runner(study_path, folder / "dask", scheduler=address) for _ in range(repeats)]
    best, summary = min(runs, key=lambda pair: pair[0])
    return {
        "cluster_start_seconds": started,
        "warm_up_seconds": warm,
        "seconds": best,
        "all_seconds": [seconds for seconds, _ in runs],
        "case_seconds": summary.case_seconds,
        "done": summary.done,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=256, help="grid points a side (default 256)")
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--repeats", type=int, default=5, help="best of N for (a), (b) and (c)")
    parser.add_argument("--no-dask", action="store_true", help="skip (c)")
    parser.add_argument("--profile", action="store_true", help="cProfile one more run of (b)")
    parser.add_argument("--keep", type=Path, help="write the outputs here (default: a temporary folder)")
    args = parser.parse_args()

    from roughcontact.study import load_study

    with contextlib.ExitStack() as stack:
        folder = args.keep or Path(stack.enter_context(tempfile.TemporaryDirectory(prefix="study-runner-")))
        folder.mkdir(parents=True, exist_ok=True)
        warm_up_seconds = warm_up(folder, args.tolerance)
        study_path = write_study(folder, args.size, args.tolerance)
        study = load_study(study_path)
        cases = len(study.cases)
        solves, runs, build_seconds = [], [], 0.0
        for _ in range(args.repeats):  # alternate, so that drifting machine load hits both alike
            seconds, scalars, build_seconds = direct_solves(study)
            solves.append(seconds)
            runs.append(instrumented_run(study_path, folder / "in-process"))
        equal = same_results(folder / "in-process", scalars)
        profile_text = profile_run(study_path, folder / "profiled") if args.profile else ""
        dask = None if args.no_dask else dask_run(study_path, folder, args.tolerance, args.repeats)

    a = min(solves)
    b, parts = min(runs, key=lambda run: run[0])
    in_run = parts["solve_normal (inside the cases)"]
    overhead, overhead_in_run = 100 * (b - a) / a, 100 * (b - in_run) / in_run
    # each (b) ran right after its (a): the median of the paired ratios resists load that drifts
    paired = 100 * (statistics.median(r[0] / s for r, s in zip(runs, solves, strict=True)) - 1)
    print(
        f"study runner overhead: {cases} normal-contact cases of {args.size}^2, "
        f"tolerance {args.tolerance:g}, {os.cpu_count()} CPUs, "
        f"{platform.processor() or platform.machine()}; best of {args.repeats}; "
        f"warm-up {warm_up_seconds:.2f} s",
        flush=True,
    )
    print(f"{'measurement':<54} {'seconds':>8} {'per case ms':>11} {'% of (a)':>9} {'% in run':>9}")
    lines = [
        ("(a) solve_normal alone, in a loop", a),
        ("    (surfaces built beforehand, not in (a))", build_seconds),
        ("(b) load_study + run_study, in-process", b),
    ]
    if dask is not None:
        lines += [
            ("(c) run_study on a local Dask cluster (2 workers)", dask["seconds"]),
            ("    (cluster start, not in (c))", dask["cluster_start_seconds"]),
        ]
    for name, seconds in lines:
        print(f"{name:<54} {seconds:8.3f} {1e3 * seconds / cases:11.2f} {100 * seconds / a:9.1f}")
    print("where the best run of (b) goes ('% in run': of that run's own solve_normal time):")
    for name, seconds in parts.items():
        print(
            f"  {name:<52} {seconds:8.3f} {1e3 * seconds / cases:11.2f} "
            f"{100 * seconds / a:9.1f} {100 * seconds / in_run:9.1f}"
        )
    print(
        f"runner overhead (b - a) / a: {overhead:.1f} % between runs (best of {args.repeats}), "
        f"{paired:.1f} % median of the {args.repeats} paired runs, {overhead_in_run:.1f} % within the best "
        f"run; results equal the direct ones: {equal}"
    )
    if profile_text:
        print(profile_text, file=sys.stderr)
    print(
        json.dumps(
            {
                "benchmark": "study_runner",
                "cases": cases,
                "size": args.size,
                "tolerance": args.tolerance,
                "repeats": args.repeats,
                "cpus": os.cpu_count(),
                "solves_seconds": a,
                "surface_build_seconds": build_seconds,
                "runner_seconds": b,
                "overhead_percent": overhead,
                "overhead_percent_in_run": overhead_in_run,
                "overhead_percent_paired_median": paired,
                "results_equal": equal,
                "all_solves_seconds": solves,
                "all_runner_seconds": [seconds for seconds, _ in runs],
                "breakdown_seconds": parts,
                "dask": dask,
            }
        )
    )


if __name__ == "__main__":
    main()
