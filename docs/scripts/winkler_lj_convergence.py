"""Convergence tables of docs/winkler_lj.md: mu against the modelled area under each adhesive range.

Sphere: one synthetic polysilicon scan (Ra 1.7 nm, seed 200) and the synthetic SiO2 tip (paraboloid
of radius R with 0.3 nm roughness, seed 0), both generated on 512^2 pixels of 20 nm; the composite
is cropped to the central n^2 window (apex in the middle), so every column models *the same*
surface, only more of it. 10 uN, 50 nm layer, epsilon 2 nm, polysilicon 50 mJ/m^2 (assumed).
Flat: a flat face 100 nm below a 2 x 2 pillar that carries the load, n^2 pixels of 20 nm.

Run: ``.venv/bin/python docs/scripts/winkler_lj_convergence.py`` (prints Markdown, about 20 s).
"""

from __future__ import annotations

import numpy as np

from roughcontact.winkler_lj import Readings, winkler_lj_model
from roughcontact.materials import get_material
from roughcontact.papers.paper000 import paper000_model_options, paper000_scans
from roughcontact.topography import Topography
from roughcontact.topography.generate import sphere_with_roughness

PIXEL, FULL, LOAD = 20e-9, 512, 10e-6
SIZES = (16, 32, 64, 128, 256, 512)
CASES = {
    "`maugis_dugdale` (default)": Readings(),
    "`all_springs` (earlier default)": Readings(adhesive_range="all_springs"),
    "`all_springs`, `adhesive_cutoff=1e-07`": Readings(adhesive_range="all_springs", adhesive_cutoff=100e-9),
    "`all_springs`, `adhesive_cutoff=2e-08`": Readings(adhesive_range="all_springs", adhesive_cutoff=20e-9),
    "`all_springs`, `adhesive_cutoff=6e-09`": Readings(adhesive_range="all_springs", adhesive_cutoff=6e-9),
}
MATERIALS = get_material("polysilicon"), get_material("SiO2")


def composite(radius: float) -> np.ndarray:
    """Heights [m] of the 512^2 scan plus a tip of radius ``radius``, apex at pixel (256, 256)."""
    scan = paper000_scans(1.7e-9, count=1, shape=FULL, seed=200)[0]
    tip = sphere_with_roughness((FULL, FULL), FULL * PIXEL, radius=radius, rms_height=0.3e-9, seed=0)
    return scan.heights + tip.heights


def crop(heights: np.ndarray, n: int) -> Topography:
    """Central n^2 window of ``heights`` as a Topography of 20 nm pixels."""
    start = (heights.shape[0] - n) // 2
    return Topography(heights[start : start + n, start : start + n].copy(), (n * PIXEL, n * PIXEL))


def solve(surface: Topography, readings: Readings):
    """Solve the paper-000 model of ``surface`` against a flat at 10 uN."""
    options = paper000_model_options(readings=readings)
    return winkler_lj_model(surface, *MATERIALS, **options).solve(LOAD)


def main() -> None:
    """Print the three tables."""
    heights = composite(1e-6)
    print("| adhesive range | " + " | ".join(f"{n}^2 ({n * PIXEL * 1e6:.2f} um)" for n in SIZES) + " |")
    print("|---|" + "---|" * len(SIZES))
    for label, readings in CASES.items():
        values = [solve(crop(heights, n), readings).mu for n in SIZES]
        print(f"| {label} | " + " | ".join(f"{mu:.4g}" for mu in values) + " |")
    result = solve(crop(heights, 256), Readings())
    print(
        f"\ndefault at 256^2: {int(result.mechanical.sum())} mechanical, {int(result.bonded.sum())} bonded "
        f"and {int(result.adhesive.sum())} attracted springs; adhesive / mechanical friction "
        f"{result.adhesive_friction / result.mechanical_friction:.3g}\n"
    )

    columns = [
        "default 256^2",
        "default 512^2",
        "change",
        "`all_springs` 256^2",
        "`all_springs` 512^2",
        "change",
    ]
    print("| tip radius | " + " | ".join(columns) + " |")
    print("|---|---|---|---|---|---|---|")
    for radius in (0.5e-6, 1e-6, 2e-6, 5e-6):
        heights = composite(radius)
        cells = []
        for readings in (Readings(), Readings(adhesive_range="all_springs")):
            small, large = (solve(crop(heights, n), readings).mu for n in (256, 512))
            cells += [f"{small:.4g}", f"{large:.4g}", f"{large / small - 1:+.2%}"]
        print(f"| {radius * 1e6:g} um | " + " | ".join(cells) + " |")

    print("\n| flat face 100 nm away, scan | adhesive friction, default [N] | `all_springs` [N] |")
    print("|---|---|---|")
    for n in (32, 64, 128, 256):
        heights = np.full((n, n), -100e-9)
        heights[n // 2 : n // 2 + 2, n // 2 : n // 2 + 2] = 0.0
        surface = Topography(heights, (n * PIXEL, n * PIXEL))
        ranges = (Readings(), Readings(adhesive_range="all_springs"))
        cells = [f"{solve(surface, readings).adhesive_friction:.4g}" for readings in ranges]
        print(f"| {n}^2 | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
