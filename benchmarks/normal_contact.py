"""Normal contact solver: roughcontact against its peers on the same surfaces, side by side.

Periodic self-affine surfaces (H = 0.8, rms slope 0.1) at a mean pressure giving a few percent
of contact, and a free-boundary Hertz case. Per case: wall time of the solve, iterations, our
time over each peer's, our time per iteration over one rfft2 + irfft2 pair of the same grid and
FFT backend (measured in this run), our peak traced memory (from a second, untimed solve: tracing
slows every allocation), and the largest pressure difference to each peer relative to the peak
pressure. As for the peers, operator set-up (kernel, FFT plans) is not in the solve time; ours is
printed beside it. A 32^2 warm-up solve first compiles the numba kernels (cached on disk after
the first run of an install). Ends with one JSON line.

    python benchmarks/normal_contact.py [--sizes 256 512 1024] [--tolerance 1e-10] [--no-peers]
        [--peers aspher] [--peers-up-to 2048] [--no-hertz]

Peers (``pip install .[bench]``) are called through ``benchmarks/peers.py`` when it is present;
aspher twice, with its Fourier preconditioner and coarse-to-fine ("aspher nested", its fastest).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import time
import tracemalloc
from pathlib import Path

import numpy as np

from roughcontact._backend import RealFFT2
from roughcontact.contact import solve_normal
from roughcontact.contact.normal import compliance_for
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


def periodic_case(n: int, tolerance: float, peers, peer_names=None) -> dict:
    surface = self_affine((n, n), (1e-4, 1e-4), hurst=0.8, rms_slope=RMS_SLOPE, seed=n)
    mean_pressure = 0.05 * CONTACT_MODULUS * RMS_SLOPE  # ~ 5-10 % contact
    operator = compliance_for(surface, CONTACT_MODULUS)
    start = time.perf_counter()
    operator.plan()  # operator set-up: the FFT plans (FFTW: measured from 2^20 points)
    setup = time.perf_counter() - start
    start = time.perf_counter()
    ours = solve_normal(surface, mean_pressure=mean_pressure, tolerance=tolerance, compliance=operator)
    seconds = time.perf_counter() - start
    tracemalloc.start()  # a second, traced solve: tracing slows every allocation, so it is not timed
    solve_normal(surface, mean_pressure=mean_pressure, tolerance=tolerance, compliance=operator)
    peak_memory = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    pair = fft_pair_seconds((n, n))
    row = {
        "case": f"periodic {n}^2",
        "n": n,
        "seconds": seconds,
        "setup_seconds": setup,
        "iterations": ours.iterations,
        "contact_fraction": ours.contact_fraction,
        "per_iteration_in_fft_pairs": seconds / max(ours.iterations, 1) / pair,
        "peak_memory_mb": peak_memory / 2**20,
        "peers": {},
    }
    if peers is not None:
        for name, solve in peers.solvers("periodic", peer_names).items():
            theirs = solve(surface.heights, surface.size, CONTACT_MODULUS, mean_pressure, tolerance)
            difference = np.max(np.abs(theirs["pressure"] - ours.pressure)) / ours.pressure.max()
            row["peers"][name] = {
                "seconds": theirs["seconds"],
                "iterations": theirs["iterations"],
                "time_ratio": seconds / theirs["seconds"],
                "max_pressure_difference": float(difference),
            }
    return row


def hertz_case(n: int, tolerance: float, peers, peer_names=None) -> dict:
    radius, force = 1e-3, 1e-3
    surface = sphere((n, n), (40e-6, 40e-6), radius=radius, kind="paraboloid")
    start = time.perf_counter()
    ours = solve_normal(surface, CONTACT_MODULUS, force=force, tolerance=tolerance)
    seconds = time.perf_counter() - start
    row = {
        "case": f"free Hertz {n}^2",
        "n": n,
        "seconds": seconds,
        "iterations": ours.iterations,
        "per_iteration_in_fft_pairs": seconds / max(ours.iterations, 1) / fft_pair_seconds((2 * n, 2 * n)),
        "peers": {},
    }
    if peers is not None:
        for name, solve in peers.solvers("free_hertz", peer_names).items():
            theirs = solve(surface.heights, surface.size, CONTACT_MODULUS, force, tolerance)
            difference = np.max(np.abs(theirs["pressure"] - ours.pressure)) / ours.pressure.max()
            row["peers"][name] = {
                "seconds": theirs["seconds"],
                "iterations": theirs["iterations"],
                "time_ratio": seconds / theirs["seconds"],
                "max_pressure_difference": float(difference),
            }
    return row


def _print_row(r: dict) -> None:
    peer_text = "  ".join(
        f"{k}: {v['seconds']:.3g}s it {v['iterations']} ratio {v['time_ratio']:.2f} "
        f"dp {v['max_pressure_difference']:.1e}"
        for k, v in r["peers"].items()
    )
    memory = f"{r['peak_memory_mb']:7.0f}" if "peak_memory_mb" in r else f"{'':>7}"
    setup = f"{r['setup_seconds']:6.2f}" if "setup_seconds" in r else f"{'':>6}"
    print(
        f"{r['case']:<18} {r['seconds']:8.3f} {setup} {r['iterations']:5d} "
        f"{r['per_iteration_in_fft_pairs']:10.2f} {memory}  {peer_text}",
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
    parser.add_argument("--no-hertz", action="store_true", help="skip the free-boundary Hertz case")
    args = parser.parse_args()
    peers = None if args.no_peers else _peers()
    warm_up_seconds = warm_up()
    print(
        f"normal contact, tolerance {args.tolerance:g}, {os.cpu_count()} CPUs, "
        f"{platform.processor() or platform.machine()}; times in s; warm-up (JIT) {warm_up_seconds:.2f} s",
        flush=True,
    )
    print(
        f"{'case':<18} {'ours s':>8} {'setup':>6} {'iter':>5} {'it/FFTpair':>10} {'MB':>7}  "
        "peers (time ratio ours/theirs, max dp/p)",
        flush=True,
    )
    rows = []
    for n in args.sizes:
        rows.append(periodic_case(n, args.tolerance, peers if n <= args.peers_up_to else None, args.peers))
        _print_row(rows[-1])
    if not args.no_hertz:
        rows.append(hertz_case(256, args.tolerance, peers, args.peers))
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
