"""Table of docs/winkler_lj.md, "The paper's own reading": how each printed choice moves the figures.

Case: paper 000's scenario, one synthetic polysilicon scan (Ra 1.7 nm, 256^2 at 20 nm, seed 200)
merged with the synthetic 2 um SiO2 tip (a paraboloid of radius 1 um, Rq 0.3 nm), 10 uN, 50 nm
layer, epsilon 2 nm, polysilicon surface energy 50 mJ/m^2 (assumed), 72 mJ/m^2 for the tip. Rows:
the preset ``reading = "paper"`` (:data:`~roughcontact.winkler_lj.readings.PAPER`), each of its
choices put back to the default one at a time, the printed forms it does not take, the default;
then the window study (central crops of 2, 2.56 and 5.12 um around the tip's apex).

Run: ``.venv/bin/python docs/scripts/winkler_lj_paper_reading.py`` (prints Markdown, about 10 s).
"""

from __future__ import annotations

from dataclasses import replace

from roughcontact.errors import InputError
from roughcontact.winkler_lj import PAPER, Readings
from roughcontact.papers.paper000 import paper000_model, paper000_scans, paper000_tip
from roughcontact.topography import Topography
from roughcontact.units import format_si

SHAPE = 256


def central(topography: Topography, points: int) -> Topography:
    """Return the central ``points``^2 window (the tip's apex stays at its middle)."""
    start = SHAPE // 2 - points // 2
    window = topography.heights[start : start + points, start : start + points]
    return Topography(window, points * topography.spacing[0], info=topography.info)


def figures(readings: Readings, scan, tip) -> tuple[str, str, str]:
    """Return mu and adhesive / mechanical friction at 10 uN and the crossover load, as text."""
    model = paper000_model(scan, tip, readings=readings)
    try:
        result = model.solve(10e-6)
        crossover = model.crossover_load()
    except InputError as error:
        return f"refused ({error.field})", "", ""
    ratio = result.adhesive_friction / result.mechanical_friction
    shown = "none below capacity" if crossover is None else format_si(crossover, "N")
    return f"{result.mu:.4g}", f"{ratio:.3g}", shown


def main() -> None:
    """Print both tables."""
    scan = paper000_scans(1.7e-9, count=1, shape=SHAPE, seed=200)[0]
    tip = paper000_tip(shape=SHAPE, seed=0)
    default = Readings()
    rows = [('`reading = "paper"`', PAPER)]
    for name in PAPER.changed():
        back = getattr(default, name)
        rows.append((f"paper, but `{name}={back}` (default)", replace(PAPER, **{name: back})))
    for name, value in (
        ("cuboid_height", "printed"),
        ("mechanical_energy", "eq16_signed"),
        ("adhesion_sign", "printed"),
        ("energy_area", "printed"),
        ("balance_terms", "pressures_printed"),
    ):
        rows.append((f"paper, but `{name}={value}` (printed)", replace(PAPER, **{name: value})))
    rows.append(("default readings", default))
    print("| readings | mu at 10 uN | adhesive / mechanical at 10 uN | crossover load |")
    print("|---|---|---|---|")
    for label, readings in rows:
        print(f"| {label} | " + " | ".join(figures(readings, scan, tip)) + " |")
    print()
    print("| window | paper: ratio at 10 uN | crossover | paper, `base=lowest_point`: ratio | crossover |")
    print("|---|---|---|---|---|")
    lowest = replace(PAPER, base="lowest_point")
    for points in (100, 128, 256):
        cells = figures(PAPER, central(scan, points), central(tip, points))[1:]
        cells += figures(lowest, central(scan, points), central(tip, points))[1:]
        print(f"| {points * 20e-3:.2f} um ({points}^2) | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
