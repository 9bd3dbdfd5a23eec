"""Tables of docs/winkler_lj.md: how the paper-000 case moves under each reading of the paper.

Case: one synthetic polysilicon scan (Ra 1.7 nm, 256^2 at 20 nm, seed 0) merged with the synthetic
2 um SiO2 tip, 10 uN, 50 nm layer, epsilon 2 nm, polysilicon surface energy 50 mJ/m^2 (assumed),
72 mJ/m^2 for the tip. Each row changes one reading from the default (last row: every equation as
printed). Second table: mu at 10 uN for the three samples (seven scans each) under the default
and under the earlier default (``adhesive_range="all_springs"``).

Run: ``.venv/bin/python docs/scripts/winkler_lj_readings.py`` (prints Markdown, about a minute).
"""

from __future__ import annotations

from dataclasses import replace

from roughcontact.errors import InputError
from roughcontact.winkler_lj import PRINTED, Readings
from roughcontact.winkler_lj.readings import CHOICES
from roughcontact.papers.paper000 import paper000_model, paper000_scans, paper000_simulation, paper000_tip
from roughcontact.units import format_si


def row(label: str, readings: Readings, scan, tip) -> str:
    """Return one Markdown row: mu, adhesive/mechanical ratio, mechanical springs, crossover."""
    model = paper000_model(scan, tip, readings=readings)
    try:
        result = model.solve(10e-6)
    except InputError as error:
        return f"| {label} | refused: {error.problem} | | | |"
    ratio = (
        result.adhesive_friction / result.mechanical_friction if result.mechanical_friction else float("inf")
    )
    try:
        crossover = model.crossover_load()
        shown = "none below capacity" if crossover is None else format_si(crossover, "N")
    except InputError as error:
        shown = f"refused ({error.field})"
    return f"| {label} | {result.mu:.4g} | {ratio:.3g} | {int(result.mechanical.sum())} | {shown} |"


def main() -> None:
    """Print both tables."""
    scan = paper000_scans(1.7e-9, count=1, shape=256, seed=200)[0]
    tip = paper000_tip(shape=256, seed=0)
    print("| reading | mu at 10 uN | adhesive / mechanical friction | mechanical springs | crossover load |")
    print("|---|---|---|---|---|")
    print(row("default", Readings(), scan, tip))
    for name, allowed in CHOICES.items():
        for value in allowed[1:]:
            print(row(f"`{name}={value}`", Readings(**{name: value}), scan, tip))
    for cutoff in (20e-9, 100e-9):
        print(row(f"`adhesive_cutoff={cutoff:g}`", Readings(adhesive_cutoff=cutoff), scan, tip))
        label = f"`adhesive_range=all_springs`, `adhesive_cutoff={cutoff:g}`"
        print(row(label, Readings(adhesive_range="all_springs", adhesive_cutoff=cutoff), scan, tip))
    paper_mechanical = Readings(mechanical_height="printed_separation", mechanical_energy="eq16_signed")
    print(row("eqs. 16-17 as printed (both)", paper_mechanical, scan, tip))
    every = replace(paper_mechanical, adhesive_range="all_springs")
    print(row("eqs. 16-17 as printed, `adhesive_range=all_springs`", every, scan, tip))
    print(row("all printed but eq. 2 in forces", replace(PRINTED, balance_terms="forces"), scan, tip))
    print(row("all printed (`PRINTED`)", PRINTED, scan, tip))
    print()
    print("| sample | mean mu at 10 uN | s.d. (7 scans) | `adhesive_range=all_springs`: mean | s.d. |")
    print("|---|---|---|---|---|")
    earlier = paper000_simulation(readings=Readings(adhesive_range="all_springs"))
    for name, values in paper000_simulation().items():
        cells = [f"{values.mean():.4g}", f"{values.std(ddof=1):.2g}"]
        cells += [f"{earlier[name].mean():.4g}", f"{earlier[name].std(ddof=1):.2g}"]
        print(f"| {name} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
