"""Theories beside the BEM (issue 47): wall time of ``compare_theories`` and of its parts.

* ``generated``: a periodic self-affine surface (H = 0.8, g = 0.1, shortest wavelength 8 pixels,
  plateau below a quarter of the side, per wavevector) at 256^2 and 512^2, the seven default loads
  p0/(E* g) = 0.005 to 0.4 warm-started on one operator; and the same seven loads solved cold, one
  call each, as the study runs them (one case per load);
* ``scan``: the shipped ``top-1.top`` (256^2, free window), the seven loads;
* ``persson_mean_separation`` alone on the 512^2 spectrum (the sum over its 262 143 modes per load).

Issue 47's target: the comparison at 256^2 on five realisations and seven loads in under a minute on
two cores. Best of N; ends with one JSON line.

    python benchmarks/theories.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from _timing import best_of
from roughcontact.materials import get_material
from roughcontact.theory import REDUCED_PRESSURES, compare_theories, persson_mean_separation, surface_spectrum
from roughcontact.topography import read_topography
from roughcontact.topography.generate import self_affine

SIDE = 10e-6
TOP = Path(__file__).resolve().parents[1] / "src" / "roughcontact" / "data" / "top-1.top"


def _surface(n: int):
    return self_affine(
        (n, n),
        SIDE,
        hurst=0.8,
        rms_slope=0.1,
        short_cutoff=SIDE * 8 / n,
        long_cutoff=SIDE / 4,
        rolloff=1.0,
        seed=1,
        modes="wavevector",
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    material = get_material("polysilicon")
    compare_theories(_surface(64), material, reduced_pressures=[0.05])  # compiles the numba kernels
    found = {}
    for n in (256, 512):
        surface = _surface(n)
        swept, _ = best_of(lambda s=surface: compare_theories(s, material), args.repeats)
        cold, _ = best_of(
            lambda s=surface: [
                compare_theories(s, material, reduced_pressures=[x]) for x in REDUCED_PRESSURES
            ],
            args.repeats,
        )
        found[f"generated_{n}"] = {"swept_s": swept, "one_load_per_call_s": cold}
        print(f"generated {n}^2: 7 loads warm-started {swept:.2f} s, one call per load {cold:.2f} s")
    scan = read_topography(TOP)
    seconds, result = best_of(lambda: compare_theories(scan, material), args.repeats)
    found["scan_256"] = {"swept_s": seconds, "kappa": result.kappa[0]}
    print(f"top-1.top (free window): 7 loads {seconds:.2f} s, kappa {result.kappa[0]:.3f}")
    spectrum = surface_spectrum(_surface(512))
    pressures = [x * result.contact_modulus * spectrum.rms_gradient for x in REDUCED_PRESSURES]
    seconds, _ = best_of(
        lambda: persson_mean_separation(pressures, contact_modulus=result.contact_modulus, spectrum=spectrum),
        args.repeats,
    )
    found["persson_mean_separation_512"] = seconds
    print(f"persson_mean_separation, 512^2 modes, 7 loads: {seconds:.3f} s")
    print(json.dumps(found))


if __name__ == "__main__":
    main()
