"""Frictional normal loading and coupled programmes: what the coupling costs and what it changes (issue 20).

What is compared (one run, same machine, side by side)
------------------------------------------------------
Case 1, paper 001's HDPE loop: the generated HDPE ball (``paper001.roughness("HDPE", pixels=512)``,
2.15 um pixels) cut to its central ``--size`` x ``--size`` window (default 256), HDPE on the silicon
wafer (Dundurs beta = -0.003), F0 = 75 mN, Table 1's stroke and mu, ``--cycles`` cycles of
``--steps-per-stroke`` steps (paper: 4 x 2 x 25 = 200 steps; the frictional start adds 10 loading
steps), through
:func:`roughcontact.contact.presliding.presliding` without step control (the same steps in every run):

* ``goodman``: ``coupling=False`` (no normal-tangential coupling, frictionless normal loading);
* ``coupled, frictionless start``: coupling on, F0 applied without friction (the previous default);
* ``coupled, frictional start``: coupling on, F0 applied in 10 steps with friction
  (the default now for dissimilar materials).

Reported: the time of the loop's steps (ms per step) and of the loading, the coupled/goodman ratio
per step (target <= 2), and K_L at the points A, B, C of the last loop with their relative
differences from the Goodman run (the effect of the coupling and of the frictional start).

Case 2, a 35-step frictional normal loading of the same window to F0 at a held tangential
displacement (``solve_frictional``), against 35 frictionless normal solves of the same loads
(``solve_normal`` warm-started along ``load_path``): time per step, their ratio, and the locked-in
stick fraction and rms shear.

    python benchmarks/frictional.py [--size 256] [--cycles 4] [--steps-per-stroke 25] [--quick]

``--quick``: a 128^2 window of a 256-pixel scan, one cycle of 10 steps per stroke, a 10-step ramp.
Ends with one JSON line.
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np

from roughcontact.contact import load_path, solve_frictional
from roughcontact.contact.presliding import POINT_NAMES, presliding
from roughcontact.materials import get_material
from roughcontact.papers import paper001

FORCE = 75e-3


def _window(size: int, pixels: int):
    return paper001.central_window(paper001.roughness("HDPE", pixels=pixels), size)


def _loop(window, cycles, steps_per_stroke, **variant):
    stroke, mu = paper001.table1("HDPE", FORCE)
    start = time.perf_counter()
    case = presliding(
        window,
        get_material("HDPE"),
        get_material("silicon wafer"),
        normal_force=FORCE,
        friction_coefficient=mu,
        stroke=stroke,
        cycles=cycles,
        steps_per_stroke=steps_per_stroke,
        radius=paper001.RADIUS,
        max_stick_change=None,
        **variant,
    )
    total = time.perf_counter() - start
    result = case.result
    loading = result.loading
    scalars = case.scalars()
    return {
        "seconds": total,
        "steps": result.steps,
        "loading_steps": 0 if loading is None else loading.steps,
        "iterations_per_step": float(result.iterations.mean()),
        "passes_per_step": float(result.coupling_iterations.mean()),
        "K_L": [scalars[f"K_L_{p}"] for p in POINT_NAMES],
        "locked_in_stick_fraction": scalars["locked_in_stick_fraction"],
    }


def _timed_steps(window, cycles, steps_per_stroke, variant):
    """Run the loop; split its time into the loading and the loop's steps by a loading-only run."""
    run = _loop(window, cycles, steps_per_stroke, **variant)
    loading_seconds = 0.0
    if run["loading_steps"]:
        start = time.perf_counter()
        _normal_loading(window, run["loading_steps"])
        loading_seconds = time.perf_counter() - start
    run["loading_seconds"] = loading_seconds
    run["ms_per_step"] = 1e3 * (run["seconds"] - loading_seconds) / run["steps"]
    return run


def _normal_loading(window, steps):
    loads = FORCE * (np.arange(1, steps + 1) / steps) ** 3
    mu = paper001.table1("HDPE", FORCE)[1]
    return solve_frictional(
        window,
        get_material("HDPE"),
        counter_body=get_material("silicon wafer"),
        friction_coefficient=mu,
        normal_force=loads,
        displacement=np.zeros(steps),
        fields_at="last",
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--cycles", type=int, default=4)
    parser.add_argument("--steps-per-stroke", type=int, default=25)
    parser.add_argument("--scan-pixels", type=int, default=512, help="pixels across the 1.1 mm scan")
    parser.add_argument("--ramp-steps", type=int, default=35)
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    if args.quick:
        args.size, args.scan_pixels, args.cycles, args.steps_per_stroke, args.ramp_steps = 128, 256, 1, 10, 10
    window = _window(args.size, args.scan_pixels)
    variants = {
        "goodman": {"coupling": False},
        "coupled, frictionless start": {"normal_loading": "frictionless"},
        "coupled, frictional start": {"normal_loading": "frictional"},
    }
    rows = {
        name: _timed_steps(window, args.cycles, args.steps_per_stroke, variant)
        for name, variant in variants.items()
    }
    reference = rows["goodman"]
    print(f"Case 1: HDPE on silicon at {FORCE * 1e3:g} mN, {args.size}^2, {reference['steps']} loop steps")
    print(
        f"{'variant':30s} {'ms/step':>9s} {'ratio':>6s} {'loading s':>10s} {'passes':>7s} {'iter':>7s} "
        f"{'K_L A, B, C (kN/m)':>26s} {'dK_L vs goodman':>24s}"
    )
    for name, row in rows.items():
        ratio = row["ms_per_step"] / reference["ms_per_step"]
        row["ratio_per_step"] = ratio
        row["K_L_difference"] = [k / g - 1 for k, g in zip(row["K_L"], reference["K_L"], strict=True)]
        stiffness = ", ".join(f"{k / 1e3:7.2f}" for k in row["K_L"])
        change = ", ".join(f"{d:+.1e}" for d in row["K_L_difference"])
        print(
            f"{name:30s} {row['ms_per_step']:9.1f} {ratio:6.2f} {row['loading_seconds']:10.2f} "
            f"{row['passes_per_step']:7.2f} {row['iterations_per_step']:7.1f} {stiffness:>26s} {change:>24s}"
        )

    loads = FORCE * (np.arange(1, args.ramp_steps + 1) / args.ramp_steps) ** 3
    start = time.perf_counter()
    ramp = _normal_loading(window, args.ramp_steps)
    frictional = time.perf_counter() - start
    start = time.perf_counter()
    list(load_path(window, get_material("HDPE"), counter_body=get_material("silicon wafer"), forces=loads))
    frictionless = time.perf_counter() - start
    final = ramp.states[ramp.steps - 1]
    stick_fraction = float(ramp.stick_area[-1] / ramp.contact_area[-1])
    shear_rms = float(np.sqrt(np.mean(np.hypot(final.shear_x, final.shear_y)[final.contact] ** 2)))
    print(
        f"\nCase 2: {args.ramp_steps}-step frictional normal loading to {FORCE * 1e3:g} mN at {args.size}^2"
    )
    print(f"{'solver':34s} {'s':>8s} {'ms/step':>9s} {'ratio':>6s}")
    print(
        f"{'solve_frictional (coupled)':34s} {frictional:8.2f} {1e3 * frictional / args.ramp_steps:9.1f} "
        f"{frictional / frictionless:6.2f}"
    )
    per_step = 1e3 * frictionless / args.ramp_steps
    print(f"{'load_path (frictionless normal)':34s} {frictionless:8.2f} {per_step:9.1f} {1.0:6.2f}")
    print(
        f"locked in: stick fraction {stick_fraction:.4f}, rms shear {shear_rms / 1e3:.3g} kPa "
        f"(beta = {ramp.parameters['dundurs_beta']:.4f})"
    )
    summary = {
        "benchmark": "frictional",
        "size": args.size,
        "loop": rows,
        "normal_loading": {
            "steps": args.ramp_steps,
            "frictional_s": frictional,
            "frictionless_s": frictionless,
            "ratio": frictional / frictionless,
            "stick_fraction": stick_fraction,
            "shear_rms_Pa": shear_rms,
        },
    }
    print(json.dumps(summary))


if __name__ == "__main__":
    main()
