"""Winkler-Lennard-Jones friction model (paper 000): wall time of one solve and of a load sweep.

Cases (a self-affine polysilicon scan, Ra ~1.5 nm, merged with a rough 1 um radius tip, 20 nm
pixels, the paper's materials, 50 mJ/m^2 assumed for polysilicon):

* ``single``: one load (10 uN) on 1024^2 springs, model preparation (merge of the two surfaces,
  one sort of the heights) and solve timed apart; target well under a second;
* ``sweep``: 30 loads from 1 uN to 1 mN, log-spaced, on 512^2; target seconds;
* ``crossover``: the load where mechanical friction overtakes adhesive friction on 512^2.

Best of N wall times. Prints a table, then one JSON line. Run:
``.venv/bin/python benchmarks/winkler_lj.py [--sizes 512 1024]``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform

import numpy as np

from _timing import best_of
from roughcontact.materials import get_material
from roughcontact.papers.paper000 import paper000_options, paper000_scans, paper000_tip
from roughcontact.winkler_lj import winkler_lj_model


def surfaces(n: int):
    return paper000_scans(1.5e-9, count=1, shape=n, seed=7)[0], paper000_tip(shape=n, seed=8)


def prepare(scan, tip):
    return winkler_lj_model(
        scan,
        get_material("polysilicon"),
        get_material("SiO2"),
        options=paper000_options(),
        counter_topography=tip,
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--single", type=int, default=1024, help="grid side of the single-load case")
    parser.add_argument("--sweep", type=int, default=512, help="grid side of the sweep and crossover cases")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    rows = []
    pair = surfaces(args.single)
    prep_time, model = best_of(lambda: prepare(*pair), args.repeats)
    solve_time, result = best_of(lambda: model.solve(10e-6), args.repeats)
    rows.append(("single", args.single, 1, prep_time, solve_time, result.mu))

    model = prepare(*surfaces(args.sweep))
    loads = np.geomspace(1e-6, 1e-3, 30)
    sweep_time, sweep = best_of(lambda: model.sweep(loads), max(1, args.repeats - 2))
    rows.append(("sweep", args.sweep, 30, 0.0, sweep_time, float(sweep.mu[9])))
    crossover_time, crossover = best_of(model.crossover_load, 1)
    rows.append(("crossover", args.sweep, 0, 0.0, crossover_time, crossover))

    print(f"{'case':<10} {'grid':>6} {'loads':>6} {'prepare s':>10} {'solve s':>9} {'value':>12}")
    for case, n, count, prep, solve, value in rows:
        print(f"{case:<10} {n:>5}^2 {count:>6} {prep:>10.3f} {solve:>9.3f} {value:>12.5g}")
    print("value: mu at 10 uN (single, sweep) or the crossover load [N]")
    print(
        json.dumps(
            {
                "benchmark": "winkler_lj",
                "machine": {"cpus": os.cpu_count(), "python": platform.python_version()},
                "single": {
                    "grid": args.single,
                    "prepare_s": rows[0][3],
                    "solve_s": rows[0][4],
                    "mu": rows[0][5],
                },
                "sweep": {"grid": args.sweep, "loads": 30, "seconds": rows[1][4]},
                "crossover": {"grid": args.sweep, "seconds": rows[2][4], "load_N": crossover},
            }
        )
    )


if __name__ == "__main__":
    main()
