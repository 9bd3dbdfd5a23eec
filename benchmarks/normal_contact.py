"""Normal contact solver: roughcontact against its peers on the same surfaces, side by side.

Periodic self-affine surfaces (H = 0.8, rms slope 0.1) at a mean pressure giving a few percent of
contact, and free-boundary cases: a Hertz paraboloid and a rough ball. Per case: wall time of the
solve (best of ``--repeats`` rounds that alternate the codes, so that the machine's drift hits all
alike), iterations, our time over each peer's, our time per iteration over one double-precision
rfft2 + irfft2 pair of the transform grid (zero-padded for the free surface) and FFT backend
(measured in this run), our peak traced memory (from one more, untimed solve, up to 2048^2:
tracing slows every allocation), the process's peak resident memory after our solve (surface
and operator included; the one memory figure at 4096^2), and the largest pressure difference
to each peer relative to the peak pressure. A case whose tolerance is below its round-off
floor (the solver stops as stalled, ``ConvergenceError.stalled_at``; 4096^2 at 1e-10) is solved,
ours and the peers alike, at twice the floor rounded up (``suggested_tolerance``), and the row
says so. As for the peers, operator set-up (kernel, FFT plans) is not in the solve time; ours is
printed beside it (after a first run on a machine FFTW's plans come from its wisdom file:
``ROUGHCONTACT_FFTW_WISDOM=off`` to time the planning itself). A solve builds its coarse-level
operators (and a free surface's box operators) on first use (``contact/_box.py``; cached on the
operator), so the first round's time ("first s") is printed too: with ``--repeats 1`` it is the
solve time. Iterations are those of the finest level (and of the box), not of the coarse levels,
whose time is in the solve time. A 32^2 warm-up solve first compiles the numba kernels (cached on
disk after the first run of an install). Ends with one JSON line.

    python benchmarks/normal_contact.py [--sizes 256 512 1024] [--tolerance 1e-10] [--no-peers]
        [--peers aspher] [--peers-up-to 2048] [--free-sizes 256 512 1024] [--repeats 3]

Peers (``pip install .[bench]``) are called through ``benchmarks/peers.py`` when it is present;
aspher twice, with its Fourier preconditioner and coarse-to-fine ("aspher nested", its fastest).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import sys
import time
import tracemalloc
from pathlib import Path

import numpy as np

from roughcontact._backend import RealFFT2
from roughcontact.contact import solve_normal
from roughcontact.contact.normal import compliance_for
from roughcontact.errors import ConvergenceError
from roughcontact.topography import Topography
from roughcontact.topography.generate import self_affine, sphere

CONTACT_MODULUS = 1e9
RMS_SLOPE = 0.1


def _peers():
    sys.path.insert(0, str(Path(__file__).parent))
    try:
        import peers
    except ImportError:
        return None
    return peers


def fft_pair_seconds(shape: tuple[int, int], repeats: int = 5) -> float:
    """Best time of one rfft2 + irfft2 pair on all cores, with the solver's FFT backend.

    One application of the operator's transform (``RealFFT2.convolve``: rfft2, multiply by a
    kernel, irfft2, copy out; FFTW unless ``ROUGHCONTACT_FFT=scipy``), planned before timing.
    """
    field = np.random.default_rng(0).random(shape)
    pair = RealFFT2(shape)
    kernel = np.ones(pair.spectrum_shape)
    pair.convolve(field, kernel)
    best = np.inf
    for _ in range(repeats):
        start = time.perf_counter()
        pair.convolve(field, kernel)
        best = min(best, time.perf_counter() - start)
    return best


def periodic_case(n: int, tolerance: float, peers, peer_names=None, repeats: int = 1) -> dict:
    """A periodic self-affine surface at a mean pressure giving ~5-10 % contact."""
    surface = self_affine((n, n), (1e-4, 1e-4), hurst=0.8, rms_slope=RMS_SLOPE, seed=n)
    mean_pressure = 0.05 * CONTACT_MODULUS * RMS_SLOPE
    solvers = peers.solvers("periodic", peer_names) if peers is not None else {}
    row = _race(surface, {"mean_pressure": mean_pressure}, mean_pressure, solvers, tolerance, repeats)
    return {"case": f"periodic {n}^2", "n": n, **row}


def free_case(n: int, tolerance: float, peers, peer_names=None, repeats: int = 1, rough=False) -> dict:
    """A paraboloid (R = 1 mm) on a free (zero-padded) 40 um window of n x n pixels at 1 mN.

    ``rough``: the paraboloid plus a self-affine roughness (H = 0.8, rms slope 0.05, rms height
    about 70 nm, comparable with the smooth ball's approach of 83 nm), a rough ball whose contact
    breaks up into patches (about 2.5 % of the window against 16 % for the smooth one). The
    peers' free-boundary solvers take any heights.
    """
    force = 1e-3
    surface = sphere((n, n), (40e-6, 40e-6), radius=1e-3, kind="paraboloid")
    if rough:
        roughness = self_affine((n, n), (40e-6, 40e-6), hurst=0.8, rms_slope=0.05, seed=n)
        surface = Topography(surface.heights + roughness.heights, surface.size)
    solvers = peers.solvers("free_hertz", peer_names) if peers is not None else {}
    row = _race(surface, {"force": force}, force, solvers, tolerance, repeats)
    return {"case": f"free {'rough ball' if rough else 'Hertz'} {n}^2", "n": n, **row}


def _race(surface, load: dict, peer_load: float, solvers: dict, tolerance: float, repeats: int) -> dict:
    """Solve ``surface`` with ours and each peer, ``repeats`` rounds alternating the codes.

    Times are the best of the rounds (the machine's noise only ever adds time). Our operator is
    built and planned first (its set-up is reported apart, as the peers' is left out); the peak
    traced memory comes from one more, untimed solve, up to 2048^2; above, only the process's
    peak resident memory, which also holds the surface and the operator, is reported.
    """
    operator = compliance_for(surface, CONTACT_MODULUS)
    start = time.perf_counter()
    operator.plan()  # operator set-up: the FFT plans (FFTW: measured from 2^20 points)
    setup = time.perf_counter() - start
    seconds, best, theirs, first = np.inf, {name: np.inf for name in solvers}, {}, None
    stalled_at = None
    for _ in range(repeats):
        start = time.perf_counter()
        try:
            ours = solve_normal(surface, tolerance=tolerance, compliance=operator, **load)
        except ConvergenceError as error:
            if error.stalled_at is None:
                raise
            stalled_at, tolerance = error.stalled_at, error.suggested_tolerance
            print(f"  stalled at {stalled_at:.2g} (round-off floor): solving at {tolerance:g}", flush=True)
            start = time.perf_counter()
            ours = solve_normal(surface, tolerance=tolerance, compliance=operator, **load)
        elapsed = time.perf_counter() - start
        seconds, first = min(seconds, elapsed), elapsed if first is None else first
        resident = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**10  # kB on Linux
        for name, solve in solvers.items():
            theirs[name] = solve(surface.heights, surface.size, CONTACT_MODULUS, peer_load, tolerance)
            best[name] = min(best[name], theirs[name]["seconds"])
    peak_memory = None
    if surface.heights.size <= 2048**2:
        tracemalloc.start()  # a traced solve: tracing slows every allocation, so it is not timed
        solve_normal(surface, tolerance=tolerance, compliance=operator, **load)
        peak_memory = tracemalloc.get_traced_memory()[1] / 2**20
        tracemalloc.stop()
    pair = fft_pair_seconds(operator.transform_shape)  # the transform grid: padded for a free surface
    row = {
        "tolerance": tolerance,
        "stalled_at": stalled_at,
        "seconds": seconds,
        "first_seconds": first,
        "setup_seconds": setup,
        "iterations": ours.iterations,
        "contact_fraction": ours.contact_fraction,
        "fft_pair_seconds": pair,
        "per_iteration_in_fft_pairs": seconds / max(ours.iterations, 1) / pair,
        "peak_memory_mb": peak_memory,
        "peak_resident_mb": resident,
        "repeats": repeats,
        "peers": {},
    }
    for name, result in theirs.items():
        difference = np.max(np.abs(result["pressure"] - ours.pressure)) / ours.pressure.max()
        row["peers"][name] = {
            "seconds": best[name],
            "iterations": result["iterations"],
            "time_ratio": seconds / best[name],
            "max_pressure_difference": float(difference),
        }
    return row


def _print_row(r: dict) -> None:
    peer_text = "  ".join(
        f"{k}: {v['seconds']:.3g}s it {v['iterations']} ratio {v['time_ratio']:.2f} "
        f"dp {v['max_pressure_difference']:.1e}"
        for k, v in r["peers"].items()
    )
    memory = f"{r['peak_memory_mb']:7.0f}" if r["peak_memory_mb"] is not None else f"{'':>7}"
    resident = f"{r['peak_resident_mb']:7.0f}"
    setup = f"{r['setup_seconds']:6.2f}"
    print(
        f"{r['case']:<24} {r['seconds']:8.3f} {r['first_seconds']:8.3f} {setup} {r['iterations']:5d} "
        f"{r['per_iteration_in_fft_pairs']:10.2f} {memory} {resident}  {peer_text}",
        flush=True,
    )


def warm_up() -> float:
    """Solve a 32^2 problem once so that numba's compilation (cached on disk after the first run of an
    install) is not timed as part of the first case; return its seconds."""
    start = time.perf_counter()
    surface = self_affine((32, 32), (1e-4, 1e-4), hurst=0.8, rms_slope=RMS_SLOPE, seed=0)
    solve_normal(surface, CONTACT_MODULUS, mean_pressure=0.05 * CONTACT_MODULUS * RMS_SLOPE)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[256, 512, 1024])
    parser.add_argument("--tolerance", type=float, default=1e-10)
    parser.add_argument("--no-peers", action="store_true")
    parser.add_argument("--peers-up-to", type=int, default=1024, help="largest grid the peers solve too")
    parser.add_argument("--peers", nargs="+", help="only these peers (tamaas, contactmechanics, aspher)")
    parser.add_argument(
        "--free-sizes", type=int, nargs="*", default=[256, 512, 1024], help="free Hertz and rough-ball grids"
    )
    parser.add_argument("--repeats", type=int, default=1, help="rounds per periodic case, best time kept")
    args = parser.parse_args()
    peers = None if args.no_peers else _peers()
    warm_up_seconds = warm_up()
    print(
        f"normal contact, tolerance {args.tolerance:g}, {os.cpu_count()} CPUs, "
        f"{platform.processor() or platform.machine()}; times in s; warm-up (JIT) {warm_up_seconds:.2f} s",
        flush=True,
    )
    print(
        f"{'case':<24} {'ours s':>8} {'first s':>8} {'setup':>6} {'iter':>5} {'it/FFTpair':>10} "
        f"{'MB':>7} {'RSS MB':>7}  "
        "peers (time ratio ours/theirs, max dp/p)",
        flush=True,
    )
    rows = []
    for n in args.sizes:
        case_peers = peers if n <= args.peers_up_to else None
        rows.append(periodic_case(n, args.tolerance, case_peers, args.peers, args.repeats))
        _print_row(rows[-1])
    for n in args.free_sizes:
        case_peers = peers if n <= args.peers_up_to else None
        for rough in (False, True):
            rows.append(free_case(n, args.tolerance, case_peers, args.peers, args.repeats, rough))
            _print_row(rows[-1])
    print(
        json.dumps(
            {
                "benchmark": "normal_contact",
                "tolerance": args.tolerance,
                "warm_up_seconds": warm_up_seconds,
                "rows": rows,
            }
        )
    )


if __name__ == "__main__":
    main()
