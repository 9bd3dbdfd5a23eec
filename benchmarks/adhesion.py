"""Adhesive contact (issue 17): roughcontact against tamaas and ContactMechanics + Adhesion, side by side.

The problem, the same for every solver (conventions: ``benchmarks/peers.py``, ``ADHESIVE``): a rigid
surface against an elastic half-space, E* = 1 GPa (a glassy polymer), a hard wall g >= 0 plus an
exponential attraction phi(g) = -w exp(-g / rho), w = 50 mJ/m^2, rho = 1 nm (peak tension w / rho =
50 MPa), periodic cell, approach control (the approach from first touch, zero-mean displacement), each
step started from the previous one, loading then unloading. Cases:

* ``sphere``: a paraboloid R = 3 um in a periodic 0.8 um cell (Tabor parameter (R w^2 / (E*^2 rho^3))^(1/3)
  = 1.96; JKR units: lateral (pi w R^2 / K)^(1/3) = 102 nm, vertical z = (pi^2 w^2 R / K^2)^(1/3) = 3.47 nm,
  force pi w R, K = 4 E* / 3). The cell is 7.8 lateral units, 4.3 x the JKR zero-load contact radius (185 nm):
  periodic images interact a little, the same for everyone (tamaas solves adhesion
  periodic only, see peers.py). Programme: approach 0 to 1.0 z in steps of 0.05 z, back down to
  -0.6 z: past the most tensile force (about -0.15 z) and before the jump-out (about -0.85 z).
* ``rough``: a periodic self-affine surface (H = 0.8, rms height 6 nm, short cutoff 8 pixels of the 256^2
  grid, long cutoff a quarter of the cell, flat roll-off, seed 17) in the same 0.8 um cell. Programme:
  0 to 12 nm in steps of 0.5 nm, back down to -3 nm. Checked at 64^2 (contactmechanics): tensile at first
  touch, pull-off 2.8e-8 N against 4.2e-6 N and 11 % contact at 12 nm: adhesion sets the pull-off but the
  surfaces do not stick everywhere. At rms 2 nm they did (the force stayed tensile up to 22 % contact);
  between the two is untried.

Grids: the cell is fixed, so 256^2 has 3.1 nm pixels and 512^2 1.6 nm; the cohesive-zone length
(pi / 4) E* w / (w / rho)^2 = 15.7 nm spans 5 and 10 pixels; rho / pixel = 0.32 and 0.64 (rho is a gap,
the pixel a lateral length: the cohesive zone is what the grid must resolve).

Why the unloading stops before detachment: out of contact tamaas' error is undefined and every step runs
to its iteration cap (10 000: 63 % of its iterations on a 128^2 sphere). ``--to-detachment`` extends every
programme's last stroke to -1.5 z (sphere) / -8 nm (rough): then tamaas stops at the first step with no
point at the wall, contactmechanics too, and ours continues until nothing touches (``until_detached``).

Reported per case, size and solver: the time of the solve calls (ours: the whole ``solve_adhesive`` call,
set-up included; the peers: solve calls only), the pull-off force (the most tensile force of the
programme's own steps: ours' inserted steps are left out so that every solver samples the same
approaches; ours' own parabola-refined ``pull_off_force`` is in the JSON), its difference from ours (%),
iterations (ours: its CG iterations; tamaas: Polonsky-Keer iterations; contactmechanics: L-BFGS-B
iterations) and the time ratio ours / peer (< 1: ours faster). Target (issue 17): the same pull-off
within 1 % and faster than both. A 32^2 warm-up compiles the numba kernels first. Ends with one JSON line.

    python benchmarks/adhesion.py [--sizes 256 512] [--cases sphere rough] [--peers tamaas contactmechanics]
        [--no-peers] [--tolerance 1e-6] [--to-detachment] [--quick]

``--quick``: 64^2 and 128^2. ``tolerance`` (default 1e-6) is handed to everyone: ours and
contactmechanics read it as the largest force imbalance of a pixel over the peak tension, tamaas as its
own error; 1e-8 stalls ours (ConvergenceError at 64^2, residual 1.1e-8).

Threads: OpenBLAS (numpy's ``vdot``, scipy's L-BFGS-B) runs on ``OPENBLAS_NUM_THREADS`` threads, set to 1
here unless given: on a loaded 2-core machine its spinning threads made one ``np.vdot`` of 128^2 doubles
take 0.2-18 ms instead of 3-50 us, which made ours (then on ``np.vdot``) 100 x slower per iteration at
128^2 than at 64^2 and contactmechanics (L-BFGS-B) 320 s instead of 6.5 s at 128^2
(``benchmarks/results/adhesion_2026-11-24.md``). tamaas's wheel is serial; ours keeps its default FFT
threads.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # before numpy's first import, see Threads above

import argparse
import json
import platform
import time

import numpy as np

import peers
from roughcontact.topography import Topography
from roughcontact.topography.generate import self_affine, sphere

CONTACT_MODULUS = 1e9
WORK_OF_ADHESION = 0.05
LENGTH = 1e-9
RADIUS = 3e-6
CELL = 0.8e-6
ROUGH_RMS_HEIGHT = 6e-9


def jkr_height_unit() -> float:
    """(pi^2 w^2 R / K^2)^(1/3) [m], K = 4 E* / 3."""
    k = 4.0 / 3.0 * CONTACT_MODULUS
    return (np.pi**2 * WORK_OF_ADHESION**2 * RADIUS / k**2) ** (1.0 / 3.0)


def _stroke(start: float, stop: float, step: float) -> np.ndarray:
    count = int(round(abs(stop - start) / step))
    return start + np.sign(stop - start) * step * np.arange(1, count + 1)


def programme(case: str, to_detachment: bool) -> np.ndarray:
    """The approach programme [m]: loading from first touch, then unloading."""
    if case == "sphere":
        z = jkr_height_unit()
        top, bottom, step = 1.0 * z, (-1.5 if to_detachment else -0.6) * z, 0.05 * z
    else:
        top, bottom, step = 12e-9, -8e-9 if to_detachment else -3e-9, 0.5e-9
    loading = np.concatenate([[0.0], _stroke(0.0, top, step)])
    return np.concatenate([loading, _stroke(top, bottom, step)])


def topography(case: str, n: int) -> Topography:
    if case == "sphere":
        return sphere((n, n), (CELL, CELL), radius=RADIUS, kind="paraboloid", periodic=True)
    return self_affine(
        (n, n),
        (CELL, CELL),
        hurst=0.8,
        rms_height=ROUGH_RMS_HEIGHT,
        short_cutoff=8 * CELL / 256,
        long_cutoff=CELL / 4,
        rolloff=1.0,
        seed=17,
    )


def solve_ours(surface: Topography, approaches: np.ndarray, tolerance: float, to_detachment: bool) -> dict:
    from roughcontact.contact.adhesive import solve_adhesive
    from roughcontact.contact.interaction import Exponential

    law = Exponential(work_of_adhesion=WORK_OF_ADHESION, length=LENGTH)
    start = time.perf_counter()
    result = solve_adhesive(
        surface,
        CONTACT_MODULUS,
        law,
        approach=approaches,
        boundary="periodic",
        tolerance=tolerance,
        until_detached=to_detachment,
    )
    seconds = time.perf_counter() - start
    requested = np.asarray(result.requested, dtype=bool)
    force = np.asarray(result.force)
    steps = min(int(requested.sum()), approaches.size)
    return {
        "seconds": seconds,
        "pull_off_force": float(-force[requested].min()),
        "refined_pull_off_force": float(result.pull_off_force),
        "iterations": int(np.sum(result.iterations)),
        "converged": bool(result.converged),
        "steps": int(force.size),
        "inserted_steps": int((~requested).sum()),
        # approach (zero-mean convention) against the programme on the requested steps
        "approach_offset_max": float(
            np.max(np.abs(np.asarray(result.approach)[requested][:steps] - approaches[:steps]))
        ),
        "force": force[requested].tolist(),
    }


def run_case(case: str, n: int, tolerance: float, peer_solvers: dict, to_detachment: bool) -> list[dict]:
    surface = topography(case, n)
    approaches = programme(case, to_detachment)
    rows = []
    ours = solve_ours(surface, approaches, tolerance, to_detachment)
    rows.append({"case": case, "n": n, "solver": "roughcontact", **ours})
    for name, solve in peer_solvers.items():
        theirs = solve(
            surface.heights,
            surface.size,
            CONTACT_MODULUS,
            WORK_OF_ADHESION,
            LENGTH,
            approaches,
            tolerance,
            until_detached=to_detachment,
        )
        rows.append(
            {
                "case": case,
                "n": n,
                "solver": name,
                "seconds": theirs["seconds"],
                "pull_off_force": theirs["pull_off_force"],
                "iterations": theirs["iterations"],
                "converged": theirs["converged"],
                "steps": theirs["steps"],
                "detached": theirs["detached"],
                "pull_off_difference_percent": 100.0
                * (theirs["pull_off_force"] / ours["pull_off_force"] - 1.0),
                "time_ratio": ours["seconds"] / theirs["seconds"],
                "force": theirs["force"].tolist(),
            }
        )
    return rows


def _print_row(r: dict) -> None:
    diff = f"{r['pull_off_difference_percent']:+9.4f}" if "pull_off_difference_percent" in r else f"{'':>9}"
    ratio = f"{r['time_ratio']:7.3f}" if "time_ratio" in r else f"{'':>7}"
    print(
        f"{r['case']:<7} {r['n']:>5} {r['solver']:<17} {r['seconds']:9.2f} {r['pull_off_force']:12.5e} "
        f"{diff} {r['iterations']:>8} {ratio}  steps {r['steps']} converged {r['converged']}",
        flush=True,
    )


def warm_up() -> float:
    """A 32^2 sphere once, so that numba's compilation is not timed in the first case."""
    start = time.perf_counter()
    surface = sphere((32, 32), (CELL, CELL), radius=RADIUS, kind="paraboloid", periodic=True)
    solve_ours(surface, programme("sphere", False)[::4], 1e-6, False)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[256, 512])
    parser.add_argument("--cases", nargs="+", default=["sphere", "rough"], choices=["sphere", "rough"])
    parser.add_argument("--peers", nargs="+", help="only these peers (tamaas, contactmechanics)")
    parser.add_argument("--no-peers", action="store_true")
    parser.add_argument("--tolerance", type=float, default=1e-6)
    parser.add_argument("--to-detachment", action="store_true", help="unload until the surfaces are apart")
    parser.add_argument("--quick", action="store_true", help="64^2 and 128^2")
    args = parser.parse_args()
    sizes = [64, 128] if args.quick else args.sizes
    peer_solvers = {} if args.no_peers else peers.adhesive_solvers(args.peers)
    warm_up_seconds = warm_up()
    z = jkr_height_unit()
    print(
        f"adhesive contact, tolerance {args.tolerance:g}, {os.cpu_count()} CPUs, "
        f"{platform.processor() or platform.machine()}; warm-up (JIT) {warm_up_seconds:.2f} s; "
        f"E* {CONTACT_MODULUS:g} Pa, w {WORK_OF_ADHESION:g} J/m^2, rho {LENGTH:g} m, sphere R {RADIUS:g} m "
        f"(JKR height unit {z:.3g} m), cell {CELL:g} m; "
        f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS')}",
        flush=True,
    )
    print(
        f"{'case':<7} {'size':>5} {'solver':<17} {'time (s)':>9} {'pull-off (N)':>12} {'diff (%)':>9} "
        f"{'iter':>8} {'ours/it':>7}",
        flush=True,
    )
    rows = []
    for case in args.cases:
        for n in sizes:
            for row in run_case(case, n, args.tolerance, peer_solvers, args.to_detachment):
                _print_row(row)
                rows.append(row)
    print(
        json.dumps(
            {
                "benchmark": "adhesion",
                "tolerance": args.tolerance,
                "to_detachment": args.to_detachment,
                "openblas_num_threads": os.environ.get("OPENBLAS_NUM_THREADS"),
                "warm_up_seconds": warm_up_seconds,
                "contact_modulus": CONTACT_MODULUS,
                "work_of_adhesion": WORK_OF_ADHESION,
                "length": LENGTH,
                "radius": RADIUS,
                "cell": CELL,
                "rows": rows,
            }
        )
    )


if __name__ == "__main__":
    main()
