"""FFT backend: FFTW (pyFFTW) against scipy.fft (pocketfft) in the surface compliance operator.

Per grid and backend: one operator application (rfft2, multiply by the kernel, irfft2, copy
out: what the contact solver calls about three times per iteration), the planning time paid
by the first application in a process (FFTW plans; the wisdom makes later operators of the
same grid free), and one periodic self-affine ``solve_normal`` as in ``periodic_case`` of
``benchmarks/normal_contact.py`` (mean pressure 5e6 Pa, E* 1e9 Pa, tolerance 1e-10), operator
construction included, planning not (it is paid once, above). Solve times are the best of
``--repeats`` runs. Ratios are FFTW over scipy. Ends with one JSON line. FFTW's wisdom file
(:mod:`roughcontact._fftw_wisdom`) is off in this benchmark, which times the planning itself,
unless ``ROUGHCONTACT_FFTW_WISDOM`` is set (then it times plans found in that file).

    python benchmarks/fft_backend.py [--sizes 256 512 1024] [--repeats 2] [--no-solve]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import time

import numpy as np

from roughcontact import _fftw_wisdom
from roughcontact._backend import ENVIRONMENT_VARIABLE, RealFFT2, fft_backend
from roughcontact.contact import solve_normal
from roughcontact.contact.normal import compliance_for
from roughcontact.topography.generate import self_affine

CONTACT_MODULUS = 1e9
RMS_SLOPE = 0.1
BACKENDS = ("scipy", "fftw")


def operator_seconds(n: int, repeats: int = 15) -> dict:
    """Return {backend: (planning + first application, best application)} [s] of one n x n convolution."""
    field = np.random.default_rng(0).random((n, n))
    pairs = {b: RealFFT2((n, n), backend=b) for b in BACKENDS}
    kernel = np.random.default_rng(1).random(pairs["fftw"].spectrum_shape)
    first, best = {}, dict.fromkeys(BACKENDS, np.inf)
    for backend, pair in pairs.items():
        start = time.perf_counter()
        pair.convolve(field, kernel)
        first[backend] = time.perf_counter() - start
    for _ in range(repeats):
        for backend, pair in pairs.items():
            start = time.perf_counter()
            pair.convolve(field, kernel)
            best[backend] = min(best[backend], time.perf_counter() - start)
    return {b: (first[b], best[b]) for b in BACKENDS}


def solve_seconds(n: int, tolerance: float, repeats: int) -> dict:
    """Time ``solve_normal`` on the self-affine surface of ``periodic_case`` with each backend.

    The backends alternate (scipy, fftw, scipy, ...) so that a change of load on the machine
    does not favour one of them.
    """
    surface = self_affine((n, n), (1e-4, 1e-4), hurst=0.8, rms_slope=RMS_SLOPE, seed=n)
    load = {"mean_pressure": 0.05 * CONTACT_MODULUS * RMS_SLOPE, "tolerance": tolerance}
    solves = {b: {"times": []} for b in BACKENDS}
    for _ in range(repeats):
        for backend in BACKENDS:
            os.environ[ENVIRONMENT_VARIABLE] = backend
            start = time.perf_counter()
            operator = compliance_for(surface, CONTACT_MODULUS)
            result = solve_normal(surface, compliance=operator, **load)
            solves[backend]["times"].append(time.perf_counter() - start)
            solves[backend].update(best=min(solves[backend]["times"]), iterations=result.iterations)
            solves[backend]["pressure"] = result.pressure
    return solves


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[256, 512, 1024])
    parser.add_argument("--tolerance", type=float, default=1e-10)
    parser.add_argument("--repeats", type=int, default=2, help="solves per case (best is kept)")
    parser.add_argument("--no-solve", action="store_true", help="time the operator only")
    args = parser.parse_args()
    os.environ.setdefault(_fftw_wisdom.ENVIRONMENT_VARIABLE, "off")  # time the planning (docstring)
    fft_backend("fftw")  # fail early without pyFFTW
    print(
        f"FFT backend, {os.cpu_count()} CPUs, {platform.processor() or platform.machine()}; "
        "op = one operator application [ms], plan = first application [s], solve [s]",
        flush=True,
    )
    print(
        f"{'n':>5} {'op scipy':>9} {'op fftw':>8} {'ratio':>6} {'plan':>6} {'planner':>9} "
        f"{'solve scipy':>11} {'fftw':>7} {'ratio':>6} {'iter':>9} {'max dp/p':>9}",
        flush=True,
    )
    rows = []
    previous = os.environ.get(ENVIRONMENT_VARIABLE)
    try:
        for n in args.sizes:
            row = {"n": n, "planner": RealFFT2((n, n), backend="fftw").planner}
            for backend, (first, best) in operator_seconds(n).items():
                row[f"operator_seconds_{backend}"] = best
                row[f"first_operator_seconds_{backend}"] = first
            row["operator_ratio"] = row["operator_seconds_fftw"] / row["operator_seconds_scipy"]
            op_scipy, op_fftw = row["operator_seconds_scipy"] * 1e3, row["operator_seconds_fftw"] * 1e3
            text = (
                f"{n:5d} {op_scipy:9.2f} {op_fftw:8.2f} {row['operator_ratio']:6.2f} "
                f"{row['first_operator_seconds_fftw']:6.2f} {row['planner'][5:]:>9}"
            )
            if not args.no_solve:
                solves = solve_seconds(n, args.tolerance, args.repeats)
                pressure = solves["scipy"].pop("pressure")
                difference = np.max(np.abs(solves["fftw"].pop("pressure") - pressure)) / pressure.max()
                row["solve"] = solves
                row["solve_ratio"] = solves["fftw"]["best"] / solves["scipy"]["best"]
                row["max_pressure_difference"] = float(difference)
                iterations = f"{solves['scipy']['iterations']}/{solves['fftw']['iterations']}"
                text += (
                    f" {solves['scipy']['best']:11.3f} {solves['fftw']['best']:7.3f} "
                    f"{row['solve_ratio']:6.2f} {iterations:>9} {difference:9.1e}"
                )
            print(text, flush=True)
            rows.append(row)
    finally:
        if previous is None:
            os.environ.pop(ENVIRONMENT_VARIABLE, None)
        else:
            os.environ[ENVIRONMENT_VARIABLE] = previous
    print(json.dumps({"benchmark": "fft_backend", "tolerance": args.tolerance, "rows": rows}))


if __name__ == "__main__":
    main()
