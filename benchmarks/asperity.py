"""Asperity models and the paper 002 island: wall time of the statistical and the BEM load-unload.

* statistical: ``statistical_load_unload`` of paper 002's Gaussian summits (printed moments, Table I,
  1000 uN peak, zero at 25 uN, 4001 height classes, 40 points per branch), per loading law, best of N;
* bem: ``compress_island`` of the synthetic SU-8 island on silicon (force-controlled, 22 steps at
  0, 25, 100, ..., 1000 uN and back), per grid, one run each; reports the peak and residual
  interference in omega_c, the peak contact fraction and the plastic fraction.

Prints a table, then one JSON line. Run: ``.venv/bin/python benchmarks/asperity.py [--grids 64 128]``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import time

import numpy as np

from _timing import best_of
from roughcontact.asperity import LOADING_LAWS
from roughcontact.materials import get_material
from roughcontact.papers import paper002
from roughcontact.papers.paper002 import compress_island, paper002_island

SU8, SILICON = get_material("SU-8"), get_material("silicon wafer")
PARAMETERS = paper002.parameters()


def statistical(law: str, repeats: int) -> dict:
    best, result = best_of(lambda: paper002.statistical_curve(law), repeats)
    omega_c = result.critical_interference
    return {
        "case": f"statistical {law}",
        "seconds": best,
        "peak_interference_ratio": float(result.approach[result.branch == "loading"][-1] / omega_c),
        "return_interference_ratio": result.interference_at_return_force / omega_c,
    }


def bem(grid: int) -> dict:
    island = paper002_island(grid)
    start = time.perf_counter()
    result = compress_island(island, SU8, substrate=SILICON)
    seconds = time.perf_counter() - start
    omega_c = PARAMETERS.critical_interference
    peak = result.steps[int(np.sum(result.branch == "loading")) - 1]
    return {
        "case": f"bem {grid}x{grid}",
        "seconds": seconds,
        "peak_interference_ratio": float(result.interference[result.branch == "loading"][-1] / omega_c),
        "return_interference_ratio": result.interference_at_return_force / omega_c,
        "peak_contact_fraction": peak.contact_fraction,
        "peak_plastic_fraction": float(peak.plastic_mask.mean()),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", type=int, nargs="+", default=[64, 128])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    rows = [statistical(law, args.repeats) for law in LOADING_LAWS]
    print(f"{'case':<28} {'time (s)':>9} {'w_peak/w_c':>11} {'w_25uN/w_c':>10}")
    for row in rows:
        print(
            f"{row['case']:<28} {row['seconds']:>9.3f} {row['peak_interference_ratio']:>11.3f} "
            f"{row['return_interference_ratio']:>10.3f}",
            flush=True,
        )
    for grid in args.grids:
        row = bem(grid)
        rows.append(row)
        print(
            f"{row['case']:<28} {row['seconds']:>9.3f} {row['peak_interference_ratio']:>11.3f} "
            f"{row['return_interference_ratio']:>10.3f}  "
            f"contact {100 * row['peak_contact_fraction']:.2f} %, "
            f"plastic {100 * row['peak_plastic_fraction']:.3f} %",
            flush=True,
        )
    print(
        json.dumps(
            {
                "benchmark": "asperity",
                "cpus": os.cpu_count(),
                "python": platform.python_version(),
                "omega_c_m": PARAMETERS.critical_interference,
                "rows": rows,
            }
        )
    )


if __name__ == "__main__":
    main()
