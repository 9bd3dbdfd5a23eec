"""Volume plasticity: a smooth sphere's load-unload beside tamaas' EPICSolver, and paper 002's island.

* sphere: an elastic-perfectly-plastic paraboloid (E = 210 GPa, nu = 0.3, Y = 1 GPa, R = 10 mm) pressed
  by a rigid flat, force-controlled, 10 steps up to 13 P_c (about 6 omega_c) and 10 down to zero, on a
  periodic 2.5 mm window (about 23 a_c; tamaas' volume models are periodic only), ``layers = n / 2``
  down to 1.25 mm. Ours: :func:`roughcontact.contact.volume_plastic.solve_elastic_plastic`; tamaas:
  ``EPICSolver`` (``peers.tamaas_elastic_plastic``; its depth grid is ``layers`` planes from 0 to the
  depth, ours ``layers`` cells). The approaches compare without the mean residual displacement
  (tamaas' periodic Mindlin displacement has zero mean; ours keeps the k = 0 mode), and the difference
  of the load-approach curves is the largest |delta_ours - delta_tamaas| over the steps, in units of
  the peak approach.
* island: paper 002's synthetic island in the film on silicon at the example's grid, 22 force steps
  (``compress_island(..., plasticity="volume")``), ours only (no peer has a film or a free window).

Prints a table, then one JSON line. Run:
``.venv/bin/python benchmarks/volume_plasticity.py [--grids 64 128] [--peers tamaas] [--island 128]``
(tamaas takes about 25 minutes at 64^2 here).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import time

import numpy as np

import peers
from roughcontact.asperity.elastic_plastic import critical_interference, critical_load
from roughcontact.contact.volume_plastic import solve_elastic_plastic
from roughcontact.materials import Material, get_material
from roughcontact.papers.paper002 import compress_island, paper002_island
from roughcontact.topography.generate import sphere

E, NU, Y, R = 210e9, 0.3, 1e9, 10e-3
SIZE, DEPTH = 2.5e-3, 1.25e-3
STEEL = Material(youngs_modulus=E, poissons_ratio=NU, yield_strength=Y)
E_STAR = E / (1 - NU**2)
OMEGA_C = critical_interference(hardness=2.8 * Y, poissons_ratio=NU, contact_modulus=E_STAR, radius=R)
P_C = critical_load(hardness=2.8 * Y, poissons_ratio=NU, contact_modulus=E_STAR, radius=R)
UP = np.linspace(0.0, 13.0 * P_C, 11)[1:]
FORCES = np.concatenate([UP, UP[::-1][1:], [0.0]])


def sphere_case(n: int, with_tamaas: bool) -> dict:
    ball = sphere((n, n), (SIZE, SIZE), radius=R, kind="paraboloid", periodic=True)
    start = time.perf_counter()
    ours = solve_elastic_plastic(ball, STEEL, forces=FORCES, depth=DEPTH, layers=n // 2)
    seconds = time.perf_counter() - start
    approach = ours.approach - ours.residual_displacement.mean(axis=(1, 2))
    peak = int(np.argmax(ours.force))
    row = {
        "case": f"sphere {n}x{n}x{n // 2}",
        "steps": int(FORCES.size),
        "seconds": seconds,
        "iterations": ours.iterations,
        "peak_ratio": float(approach[peak] / OMEGA_C),
        "residual_ratio": float(approach[-1] / approach[peak]),
    }
    if with_tamaas:
        peer = peers.tamaas_elastic_plastic(
            ball.heights, SIZE, depth=DEPTH, layers=n // 2, youngs_modulus=E, poissons_ratio=NU,
            yield_strength=Y, hardening_modulus=0.0, forces=FORCES,
        )  # fmt: skip
        theirs = np.asarray(peer["approach"])
        row |= {
            "tamaas_seconds": peer["total"],
            "time_ratio": seconds / peer["total"],
            "tamaas_peak_ratio": float(theirs[peak] / OMEGA_C),
            "tamaas_residual_ratio": float(theirs[-1] / theirs[peak]),
            "curve_difference": float(np.max(np.abs(approach - theirs)) / theirs[peak]),
        }
    return row


def island_case(n: int) -> dict:
    island = paper002_island(n)
    start = time.perf_counter()
    result = compress_island(
        island, get_material("SU-8"), substrate=get_material("silicon wafer"), plasticity="volume"
    )
    seconds = time.perf_counter() - start
    scalars = result.scalars()
    return {
        "case": f"island {n}x{n}x16 (film)",
        "steps": int(result.force.size),
        "seconds": seconds,
        "iterations": result.iterations,
        "peak_interference_nm": scalars["peak_interference"] * 1e9,
        "residual_interference_nm": scalars["residual_interference"] * 1e9,
        "residual_von_mises_MPa": scalars["max_residual_von_mises"] * 1e-6,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", type=int, nargs="+", default=[64, 128])
    parser.add_argument("--peers", nargs="*", default=[], choices=["tamaas"])
    parser.add_argument("--island", type=int, nargs="*", default=[128], help="island grids (none: skip)")
    args = parser.parse_args()
    rows = [sphere_case(n, "tamaas" in args.peers) for n in args.grids]
    rows += [island_case(n) for n in args.island]
    header = f"{'case':26s} {'steps':>5s} {'ours [s]':>9s} {'iters':>6s} {'tamaas [s]':>10s} {'ratio':>6s}"
    print(header + f" {'w_max/w_c':>16s} {'w_res/w_max':>16s} {'curve diff':>10s}")
    for row in rows:
        if row["case"].startswith("island"):
            print(
                f"{row['case']:26s} {row['steps']:5d} {row['seconds']:9.1f} {row['iterations']:6d}"
                f"   peak {row['peak_interference_nm']:.1f} nm,"
                f" residual {row['residual_interference_nm']:.2f} nm,"
                f" residual von Mises {row['residual_von_mises_MPa']:.0f} MPa"
            )
            continue
        theirs = "tamaas_seconds" in row
        peer_time = (
            f"{row['tamaas_seconds']:10.1f} {row['time_ratio']:6.2f}" if theirs else f"{'-':>10s} {'-':>6s}"
        )
        peaks = f"{row['peak_ratio']:.3f}" + (f" / {row['tamaas_peak_ratio']:.3f}" if theirs else "")
        residuals = f"{row['residual_ratio']:.4f}" + (
            f" / {row['tamaas_residual_ratio']:.4f}" if theirs else ""
        )
        difference = f"{row['curve_difference']:10.4f}" if theirs else f"{'-':>10s}"
        print(
            f"{row['case']:26s} {row['steps']:5d} {row['seconds']:9.1f} {row['iterations']:6d} {peer_time}"
            f" {peaks:>16s} {residuals:>16s} {difference}"
        )
    print(
        json.dumps(
            {
                "benchmark": "volume_plasticity",
                "machine": {"cores": os.cpu_count(), "python": platform.python_version()},
                "rows": rows,
            }
        )
    )


if __name__ == "__main__":
    main()
