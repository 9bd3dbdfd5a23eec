"""What a user waits for: whole ``roughcontact`` processes, timed end to end, beside the solver's own time.

Each command runs ``--repeats`` times as a new process (interpreter start, imports, reading the
file, solving, writing; the operating system's file cache warm after the first run), and the
table gives min / median / max wall time against issue 36's target. The processes keep their
converted copies of instrument files in a folder of their own (``ROUGHCONTACT_FILE_CACHE``), not
the user's; FFTW's wisdom file is the user's, as in use. The package's bytecode is compiled first,
as ``pip install`` does (an editable install under ``PYTHONDONTWRITEBYTECODE=1``, as on this
machine, would otherwise compile every changed module in every process: 0.2 s more per command).
Commands:

* ``roughcontact --help`` and ``--version``;
* ``inspect`` of the shipped AFM scan (``top-1.top``, 256 x 256);
* ``contact`` on it at 20 MPa: on a first read of the file (the converted-copy cache emptied
  before each run, :mod:`roughcontact.topography.file_cache`) and on a later read; with ``-o``
  into a new folder (the case, its figures and report written) and into the same folder again
  (everything reused); and on a 1024 x 1024 self-affine surface written once as a text matrix;
* ``demo`` into a new folder (a first run) and again into the same folder (every case reused);
* a 100-case study (``benchmarks/study_runner.py``'s: 10 mean pressures x 10 replicates of a
  64 x 64 self-affine surface), first run and rerun with every case reused.

Beside them: the normal solve alone (``solve_normal`` on the scan, in this process, after one
warm-up solve), and a twelve-line tamaas script solving the same heights, periodic, as a whole
process (tamaas is a benchmark extra: ``pip install .[bench]``; left out when it does not import).
Ends with one JSON line.

    python benchmarks/latency.py [--repeats 3] [--skip-large]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from study_runner import write_study  # noqa: E402  (the 100-case sweep its runner benchmark times)

ROOT = Path(__file__).resolve().parents[1]
SCAN = ROOT / "src" / "roughcontact" / "data" / "top-1.top"
CLI = [sys.executable, "-m", "roughcontact"]
MATERIALS = ["--material", "polysilicon", "--counter-body", "SiO2", "--pressure", "20 MPa"]

TARGETS = {  # issue 36's targets [s] (None: none stated)
    "--help": 0.3,
    "--version": 0.3,
    "inspect 256^2": None,
    "contact 256^2, first read of the file": None,
    "contact 256^2": 1.5,
    "contact 256^2 -o, new folder": 3.0,
    "contact 256^2 -o, again": None,
    "contact 1024^2": None,
    "demo, first run": 10.0,
    "demo, every case reused": 3.0,
    "100-case study, first run": None,
    "100-case study, reused": None,
}

TAMAAS = """
import time, numpy as np, tamaas as tm
h = np.load({heights!r})
start = time.perf_counter()
model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [{size}, {size}], list(h.shape))
model.E, model.nu = {modulus}, 0.0
solver = tm.PolonskyKeerRey(model, h, 1e-8)
solver.solve({pressure})
print(f"solve {{time.perf_counter() - start:.3f}}")
"""


ENVIRONMENT = dict(os.environ)
"""The commands' environment (``main`` points the file cache at a folder of the benchmark's)."""


def timed(command: list[str], repeats: int, *, before=None, cwd=None) -> list[float]:
    """Run ``command`` ``repeats`` times as a process (``before()`` ahead of each); return the wall times."""
    times = []
    for _ in range(repeats):
        if before is not None:
            before()
        start = time.perf_counter()
        done = subprocess.run(command, capture_output=True, text=True, cwd=cwd, env=ENVIRONMENT)
        times.append(time.perf_counter() - start)
        if done.returncode != 0:
            raise RuntimeError(f"{' '.join(command)} failed ({done.returncode}): {done.stderr[-800:]}")
    return times


def solver_alone() -> tuple[float, np.ndarray, tuple[float, float], float]:
    """Return the in-process solve time of the CLI's contact problem, the heights, size and E*."""
    from roughcontact.contact import solve_normal
    from roughcontact.materials import contact_modulus, get_material
    from roughcontact.topography import read_topography
    from roughcontact.topography.process import detrend

    surface = detrend(read_topography(SCAN), "plane")
    material, counter = get_material("polysilicon"), get_material("SiO2")
    solve_normal(surface, material, counter_body=counter, mean_pressure=20e6)  # compile, plan
    start = time.perf_counter()
    solve_normal(surface, material, counter_body=counter, mean_pressure=20e6)
    seconds = time.perf_counter() - start
    return seconds, surface.heights, surface.size, contact_modulus(material, counter)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--skip-large", action="store_true", help="leave out the 1024^2 contact")
    args = parser.parse_args()
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "src" / "roughcontact")], check=True)
    work = Path(tempfile.mkdtemp(prefix="latency-"))
    cache = work / "file-cache"
    ENVIRONMENT["ROUGHCONTACT_FILE_CACHE"] = str(cache)
    rows: dict[str, list[float]] = {}
    try:
        rows["--help"] = timed([*CLI, "--help"], args.repeats)
        rows["--version"] = timed([*CLI, "--version"], args.repeats)
        rows["inspect 256^2"] = timed([*CLI, "inspect", str(SCAN)], args.repeats)
        contact = [*CLI, "contact", str(SCAN), *MATERIALS]
        rows["contact 256^2, first read of the file"] = timed(
            contact, args.repeats, before=lambda: shutil.rmtree(cache, ignore_errors=True)
        )
        rows["contact 256^2"] = timed(contact, args.repeats)
        out = work / "contact-out"
        rows["contact 256^2 -o, new folder"] = timed(
            [*contact, "-o", str(out)], args.repeats, before=lambda: shutil.rmtree(out, ignore_errors=True)
        )
        rows["contact 256^2 -o, again"] = timed([*contact, "-o", str(out)], args.repeats)
        if not args.skip_large:
            from roughcontact.topography.generate import self_affine

            large = self_affine((1024, 1024), (10e-6, 10e-6), hurst=0.8, rms_height=1e-9, seed=1)
            text = work / "large.txt"
            np.savetxt(text, large.heights * 1e9, fmt="%.6g")
            rows["contact 1024^2"] = timed(
                [*CLI, "contact", str(text), "--size", "10 um", "--height-unit", "nm", *MATERIALS],
                args.repeats,
            )
        demo = work / "demo"
        rows["demo, first run"] = timed(
            [*CLI, "demo", "-o", str(demo)],
            args.repeats,
            before=lambda: shutil.rmtree(demo, ignore_errors=True),
        )
        rows["demo, every case reused"] = timed([*CLI, "demo", "-o", str(demo)], args.repeats)
        study = write_study(work, 64, 1e-8)  # benchmarks/study_runner.py's sweep, 64^2
        folder = work / "study-out"
        rows["100-case study, first run"] = timed(
            [*CLI, "run", str(study), "-o", str(folder), "--no-progress"],
            args.repeats,
            before=lambda: shutil.rmtree(folder, ignore_errors=True),
        )
        rows["100-case study, reused"] = timed(
            [*CLI, "run", str(study), "-o", str(folder), "--no-progress", "--resume"], args.repeats
        )
        solve, heights, size, modulus = solver_alone()
        reference = None
        try:
            import tamaas  # noqa: F401  (only whether it imports: the script runs it in its own process)

            np.save(work / "h.npy", np.ascontiguousarray(heights.max() - heights))
            script = work / "tamaas_script.py"
            script.write_text(
                textwrap.dedent(
                    TAMAAS.format(heights=str(work / "h.npy"), size=size[0], modulus=modulus, pressure=20e6)
                )
            )
            rows["tamaas twelve-line script 256^2 (periodic)"] = timed(
                [sys.executable, str(script)], args.repeats
            )
            reference = min(rows["tamaas twelve-line script 256^2 (periodic)"])
        except ImportError:
            pass
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"whole processes, {args.repeats} runs each, {os.cpu_count()} CPUs; times in s")
    print(f"{'command':<44} {'min':>7} {'median':>7} {'max':>7} {'target':>7}")
    for name, times in rows.items():
        target = TARGETS.get(name)
        print(
            f"{name:<44} {min(times):7.2f} {statistics.median(times):7.2f} {max(times):7.2f} "
            f"{'' if target is None else f'{target:7.2g}':>7}"
        )
    print(f"{'solve_normal alone (scan 256^2, in process)':<44} {solve:7.3f}")
    if reference is not None:
        ratio = min(rows["contact 256^2"]) / reference
        print(f"contact 256^2 over the tamaas script: {ratio:.1f} x (issue 36: at most 2)")
    summary = {
        name: {"min": min(t), "median": statistics.median(t), "max": max(t)} for name, t in rows.items()
    }
    print(
        json.dumps({"benchmark": "latency", "repeats": args.repeats, "rows": summary, "solve_seconds": solve})
    )


if __name__ == "__main__":
    main()
