"""Partial-slip increment solvers side by side: conjugate gradients (method="cg") against accelerated
projected gradients (method="apg"), one run each.

Cases
-----
1. Cattaneo-Mindlin, nu = 0: a smooth sphere (paraboloid, R = 10 mm, E* = 1 GPa) on a flat of the
   same material, P = 0.5 N, then Q = 0.5 mu P (mu = 0.3) in one force-controlled step from the
   virgin state; free n x n grid over a 4a window (n = 64, 128). The set-up of
   benchmarks/tangential.py, problem [A].
2. The same with nu = 0.5 on a rigid flat (problem [B]), the slow case of the conjugate gradients.
3. Paper 001's HDPE ball at 25 mN: ``models.paper001.run_case("HDPE", 0.025, pixels=256,
   window=64, seed=2, cycles=2, steps_per_stroke=12)`` (coupled to silicon, displacement path,
   last-loop analysis), with ``solve_tangential``'s method set through a wrapper.

``--large`` adds paper 001's default window (``pixels=512, window=160``, 2 cycles of 10 steps per
stroke; 68 s with cg in docs/tangential_contact.md) and the rough-ball loop of
benchmarks/tangential.py problem [P] at 128^2 (HDPE, nu = 0.5 on a rigid flat, 19 % contact) on a
one-cycle path of 6 steps per stroke.

Reported per run: iterations (per step for loops: mean, max; cg's count includes the 500 plain
iterations spent before a preconditioned retry under precondition="auto"), wall seconds of the
tangential solve (normal contact solved beforehand, not timed; for case 3 the whole run_case call),
and the agreement of the two answers. Iterations are not comparable one to one: a cg iteration
applies the operator twice (four with the preconditioner), an apg iteration once. The load average
(``os.getloadavg``) is printed before and after each case: this is a shared 2-core machine.

    python benchmarks/tangential_apg.py [--sizes 64 128] [--tolerance 1e-8] [--large]
"""

from __future__ import annotations

import argparse
import functools
import json
import os
import sys
import time
from pathlib import Path
from unittest import mock

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from roughcontact.analytic import mindlin  # noqa: E402
from roughcontact.contact import (
    ShearSolver,
    solve_normal,  # noqa: E402
)
from roughcontact.contact.paths import stroke_path  # noqa: E402
from roughcontact.contact.tangential import solve_tangential  # noqa: E402
from roughcontact.materials import Material, contact_modulus  # noqa: E402
from roughcontact.papers import paper001  # noqa: E402
from roughcontact.topography import generate  # noqa: E402
from tangential import FORCE, MU, Cattaneo  # noqa: E402

METHODS = ("cg", "apg")


def _load(values) -> str:
    return " ".join(f"{v:.2f}" for v in values)


def load() -> str:
    return "load " + _load(os.getloadavg())


def cattaneo(n: int, problem: str, tolerance: float) -> dict:
    case = Cattaneo(n, problem)
    normal = solve_normal(
        case.topography, case.material, counter_body=case.counter, force=FORCE, tolerance=1e-10
    )
    p0 = 3 * FORCE / (2 * np.pi * case.a**2)
    row = {"case": f"Cattaneo nu = {case.poisson:g} {n}^2", "load_before": os.getloadavg()}
    states = {}
    for method in METHODS:
        start = time.perf_counter()
        result = solve_tangential(
            normal,
            case.material,
            counter_body=case.counter,
            friction_coefficient=MU,
            force=[case.q],
            fields_at="last",
            solver=ShearSolver(tolerance=tolerance, method=method),
        )
        seconds = time.perf_counter() - start
        states[method] = result.states[0]
        c = np.sqrt(result.stick_area[0] / np.pi) / case.a
        row[method] = {
            "iterations": int(result.iterations[0]),
            "seconds": seconds,
            "c_over_a_error": float(c - case.expected),
            "delta": float(result.displacement[0, 0]),
            "residual": float(result.residual[0]),
        }
    first, second = states["cg"], states["apg"]
    row["max_dq_over_mu_p0"] = float(
        np.max(np.hypot(first.shear_x - second.shear_x, first.shear_y - second.shear_y)) / (MU * p0)
    )
    row["delta_relative_difference"] = abs(row["apg"]["delta"] / row["cg"]["delta"] - 1)
    row["load_after"] = os.getloadavg()
    return row


def paper001_case(tolerance: float, **arguments) -> dict:
    row = {
        "case": "paper001 run_case(HDPE, 25 mN, " + ", ".join(f"{k}={v}" for k, v in arguments.items()) + ")"
    }
    row["load_before"] = os.getloadavg()
    forces = {}
    for method in METHODS:
        wrapped = functools.partial(solve_tangential, method=method)
        start = time.perf_counter()
        with mock.patch.object(paper001, "solve_tangential", wrapped):
            case = paper001.run_case("HDPE", 0.025, tolerance=tolerance, **arguments)
        seconds = time.perf_counter() - start
        result = case.result
        forces[method] = result.force
        row[method] = {
            "seconds": seconds,
            "steps": int(result.steps),
            "iterations_per_step": float(np.mean(result.iterations)),
            "max_iterations_step": int(np.max(result.iterations)),
            "iterations_per_pass": float(np.sum(result.iterations) / np.sum(result.coupling_iterations)),
            "coupling_passes_per_step": float(np.mean(result.coupling_iterations)),
            "contact_fraction": float(result.normal.contact_fraction),
            "mu_from_loop": float(case.analysis.mu),
            "K_L": {k: float(v) for k, v in case.analysis.lateral_stiffness.items()},
        }
        sliding = case.friction_coefficient * case.normal_force
    row["max_dF_over_mu_F0"] = float(np.max(np.abs(forces["cg"] - forces["apg"])) / sliding)
    row["K_L_relative_difference"] = {
        k: abs(row["apg"]["K_L"][k] / row["cg"]["K_L"][k] - 1) for k in row["cg"]["K_L"]
    }
    row["mu_relative_difference"] = abs(row["apg"]["mu_from_loop"] / row["cg"]["mu_from_loop"] - 1)
    row["load_after"] = os.getloadavg()
    return row


def rough_loop_128(tolerance: float) -> dict:
    """benchmarks/tangential.py Case 2 [P] at 128^2 on a short path (1 cycle, 6 steps per stroke)."""
    hdpe = Material(0.98e9, 0.5, "HDPE")
    modulus = contact_modulus(hdpe, None)
    a = mindlin.hertz_contact_radius(1.0, 5e-3, modulus)
    size = 4.0 * a
    topography = generate.sphere_with_roughness(
        (128, 128), (size, size), radius=5e-3, rms_height=0.2e-6, seed=1
    )
    normal = solve_normal(topography, hdpe, force=1.0, tolerance=tolerance)
    path = stroke_path(3e-6, cycles=1, steps_per_stroke=6)
    row = {"case": "rough-ball loop 128^2, HDPE nu = 0.5 on rigid, 12 steps", "load_before": os.getloadavg()}
    forces = {}
    for method in METHODS:
        start = time.perf_counter()
        result = solve_tangential(
            normal,
            hdpe,
            friction_coefficient=0.15,
            displacement=path,
            fields_at="none",
            solver=ShearSolver(tolerance=tolerance, method=method),
        )
        seconds = time.perf_counter() - start
        forces[method] = result.force
        row[method] = {
            "seconds": seconds,
            "steps": int(result.steps),
            "iterations_per_step": float(np.mean(result.iterations)),
            "max_iterations_step": int(np.max(result.iterations)),
            "contact_fraction": float(normal.contact_fraction),
        }
    row["max_dF_over_mu_F0"] = float(np.max(np.abs(forces["cg"] - forces["apg"])) / 0.15)
    row["load_after"] = os.getloadavg()
    return row


def print_single(row: dict) -> None:
    print(f"\n{row['case']}  (load {_load(row['load_before'])} -> {_load(row['load_after'])})")
    for method in METHODS:
        r = row[method]
        print(
            f"  {method:<4} {r['iterations']:6d} it  {r['seconds']:8.3f} s  "
            f"c/a err {r['c_over_a_error']:+.4f}  residual {r['residual']:.1e}"
        )
    print(
        f"  cg/apg time {row['cg']['seconds'] / row['apg']['seconds']:.2f}; max |q_cg - q_apg| / mu p0 "
        f"{row['max_dq_over_mu_p0']:.1e}; delta differs by {row['delta_relative_difference']:.1e}",
        flush=True,
    )


def print_loop(row: dict) -> None:
    print(f"\n{row['case']}  (load {_load(row['load_before'])} -> {_load(row['load_after'])})")
    for method in METHODS:
        r = row[method]
        extra = ""
        if "K_L" in r:
            extra = (
                f"  passes/step {r['coupling_passes_per_step']:.2f}  mu {r['mu_from_loop']:.5f}  K_L A/B/C "
                + " / ".join(f"{v / 1e3:.3f}" for v in r["K_L"].values())
                + " kN/m"
            )
        print(
            f"  {method:<4} {r['steps']} steps  {r['seconds']:8.2f} s  "
            f"{r['iterations_per_step']:7.1f} it/step (max {r['max_iterations_step']}){extra}"
        )
    text = f"  cg/apg time {row['cg']['seconds'] / row['apg']['seconds']:.2f}; max |F_cg - F_apg| / mu F0 "
    text += f"{row['max_dF_over_mu_F0']:.1e}"
    if "K_L_relative_difference" in row:
        text += "; K_L differ by " + " / ".join(f"{v:.1e}" for v in row["K_L_relative_difference"].values())
        text += f"; mu by {row['mu_relative_difference']:.1e}"
    print(text, flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[64, 128])
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--large", action="store_true", help="paper 001's default window and a 128^2 loop")
    parser.add_argument("--skip-cattaneo", action="store_true")
    args = parser.parse_args()
    start = time.perf_counter()
    for problem in "AB":  # numba compilation, not timed below
        for method in METHODS:
            case = Cattaneo(32, problem)
            normal = solve_normal(case.topography, case.material, counter_body=case.counter, force=FORCE)
            solve_tangential(
                normal,
                case.material,
                counter_body=case.counter,
                friction_coefficient=MU,
                force=[case.q],
                solver=ShearSolver(method=method),
            )
    print(
        f"cg vs apg, {os.cpu_count()} CPUs, tolerance {args.tolerance:g}, "
        f"warm-up {time.perf_counter() - start:.1f} s, {load()}",
        flush=True,
    )
    rows = []
    if not args.skip_cattaneo:
        for problem in "AB":
            for n in args.sizes:
                rows.append(cattaneo(n, problem, args.tolerance))
                print_single(rows[-1])
    rows.append(paper001_case(args.tolerance, pixels=256, window=64, seed=2, cycles=2, steps_per_stroke=12))
    print_loop(rows[-1])
    if args.large:
        rows.append(paper001_case(args.tolerance, cycles=2, steps_per_stroke=10))
        print_loop(rows[-1])
        rows.append(rough_loop_128(args.tolerance))
        print_loop(rows[-1])
    print(json.dumps({"benchmark": "tangential_apg", "tolerance": args.tolerance, "rows": rows}))


if __name__ == "__main__":
    main()
