"""Surface statistics, side by side with SurfaceTopography: wall time and agreement.

For periodic self-affine surfaces of 256^2, 1024^2 and 2048^2 points (H = 0.8, Sq = 10 nm, 10 um
period) it times, best of N,

* psd: ours ``psd_radial`` vs SurfaceTopography ``power_spectrum_from_area``;
* scalars: ours ``spectral_moments`` + ``summary`` vs SurfaceTopography ``rms_height_from_area``
  + ``rms_gradient`` + ``rms_curvature_from_area``;

and checks that the values agree: Sq, the rms gradient (theirs uses forward differences: compared
with our default ``derivative="forward"``; the central/forward ratio is shown too), the rms mean
curvature (both centred three-point stencils), and the radial PSDs (median |log ratio| of ours,
interpolated in log-log, at their wavevectors; the bins differ: ours linear, theirs logarithmic).

Prints a table, then one JSON line. Run: ``.venv/bin/python benchmarks/surface_statistics.py``.
"""

from __future__ import annotations

import json
import os
import platform

import numpy as np
import SurfaceTopography

from _timing import best_of
from roughcontact.topography import generate, statistics

SIZES = {256: 7, 1024: 3, 2048: 3}  # grid side -> repeats (best of N)


def ours_scalars(topography):
    return statistics.spectral_moments(topography), statistics.summary(topography)


def theirs_scalars(peer):
    return peer.rms_height_from_area(), peer.rms_gradient(), peer.rms_curvature_from_area()


def psd_disagreement(ours, theirs) -> float:
    q_ours, c_ours = ours
    q_theirs, c_theirs = (np.ma.filled(np.ma.asarray(a, dtype=float), np.nan) for a in theirs)
    usable = np.isfinite(c_theirs) & (c_theirs > 0) & (q_theirs >= q_ours[0]) & (q_theirs <= q_ours[-1])
    interpolated = np.interp(np.log(q_theirs[usable]), np.log(q_ours), np.log(c_ours))
    return float(np.median(np.abs(interpolated - np.log(c_theirs[usable]))))


def run(n: int, repeats: int) -> dict:
    topography = generate.self_affine((n, n), 1e-5, hurst=0.8, rms_height=1e-8, seed=n)
    peer = SurfaceTopography.Topography(np.asarray(topography.heights), topography.size, periodic=True)
    t_psd_ours, psd_ours = best_of(lambda: statistics.psd_radial(topography), repeats)
    t_psd_theirs, psd_theirs = best_of(peer.power_spectrum_from_area, repeats)
    t_sc_ours, (_, summary) = best_of(lambda: ours_scalars(topography), repeats)
    t_sc_theirs, (sq, gradient, curvature) = best_of(lambda: theirs_scalars(peer), repeats)
    central_slope = statistics.rms_slope(topography, derivative="central")
    return {
        "n": n,
        "repeats": repeats,
        "psd_ours_s": t_psd_ours,
        "psd_theirs_s": t_psd_theirs,
        "psd_ratio": t_psd_ours / t_psd_theirs,
        "scalars_ours_s": t_sc_ours,
        "scalars_theirs_s": t_sc_theirs,
        "scalars_ratio": t_sc_ours / t_sc_theirs,
        "sq_rel_diff": abs(summary["Sq"] / sq - 1),
        "slope_rel_diff": abs(summary["rms_slope"] / gradient - 1),
        "slope_central_vs_forward": central_slope / gradient,
        "curvature_rel_diff": abs(summary["rms_curvature"] / curvature - 1),
        "psd_median_abs_log_ratio": psd_disagreement(psd_ours, psd_theirs),
    }


def main() -> None:
    rows = [run(n, repeats) for n, repeats in SIZES.items()]
    header = (
        f"{'grid':>10} {'psd ours':>9} {'psd ST':>9} {'ratio':>6} {'scal ours':>9} {'scal ST':>9} "
        f"{'ratio':>6} {'dSq':>8} {'dslope':>8} {'dcurv':>8} {'PSD |ln|':>8} {'cen/fwd':>7}"
    )
    print(
        f"roughcontact statistics vs SurfaceTopography {SurfaceTopography.__version__}, "
        f"{os.cpu_count()} CPUs, {platform.processor() or platform.machine()}; times in s, best of N"
    )
    print(header)
    for r in rows:
        print(
            f"{r['n']:>5}^2 x{r['repeats']} {r['psd_ours_s']:9.4f} {r['psd_theirs_s']:9.4f} "
            f"{r['psd_ratio']:6.2f} {r['scalars_ours_s']:9.4f} {r['scalars_theirs_s']:9.4f} "
            f"{r['scalars_ratio']:6.2f} {r['sq_rel_diff']:8.1e} {r['slope_rel_diff']:8.1e} "
            f"{r['curvature_rel_diff']:8.1e} {r['psd_median_abs_log_ratio']:8.3f} "
            f"{r['slope_central_vs_forward']:7.4f}"
        )
    print(
        json.dumps(
            {
                "benchmark": "statistics",
                "peer": f"SurfaceTopography {SurfaceTopography.__version__}",
                "rows": rows,
            }
        )
    )


if __name__ == "__main__":
    main()
