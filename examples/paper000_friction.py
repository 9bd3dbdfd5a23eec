"""Paper 000's validation case at reduced cost: simulated vs (synthetic) measured mu, Figs. 8-9, crossover.

A 2 um SiO2 sphere on LPCVD polysilicon (Ra 1.45, 1.49, 1.7 nm; seven synthetic scans per sample,
256^2 at 20 nm; 10 uN; polysilicon surface energy 50 mJ/m^2 assumed) compared with
``paper000_measured_mu.csv`` (SYNTHETIC values, see its header), then friction vs load and the
adhesive-mechanical crossover for one Ra 1.7 nm scan. Pass scans of your own through
:func:`roughcontact.papers.paper000.paper000_simulation` (``scans=``, ``tip=``) or the CLI
(``roughcontact friction-compare MEASURED.csv --sample NAME=a.di,b.di --tip tip.di``).

Run: ``.venv/bin/python examples/paper000_friction.py [OUTPUT_FOLDER]`` (default paper000-output).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from roughcontact.experiment import compare, read_measured
from roughcontact.materials import get_material
from roughcontact.papers.paper000 import (
    paper000_options,
    paper000_scans,
    paper000_simulation,
    paper000_tip,
)
from roughcontact.plotting import plot_friction_vs_load, plot_mu_boxes, plot_mu_means
from roughcontact.winkler_lj import winkler_lj_model


def main(output: Path) -> None:
    """Run the comparison and the load sweep; write three figures and print the numbers."""
    output.mkdir(parents=True, exist_ok=True)
    comparison = compare(
        paper000_simulation(), read_measured(Path(__file__).with_name("paper000_measured_mu.csv"))
    )
    for row in comparison.table():
        print(
            f"{row['sample']}: simulated {row['simulated_mean']:.4g} +- {row['simulated_std']:.2g}, "
            f"measured {row['measured_mean']:.4g} +- {row['measured_std']:.2g}, p = {row['p_value']:.3g}"
        )
    print(f"Pearson r of the means: {comparison.pearson_r:.3f}")
    plot_mu_boxes(comparison)[0].savefig(output / "fig9_mu_boxes.png", dpi=150)
    plot_mu_means(comparison)[0].savefig(output / "fig8_mu_means.png", dpi=150)

    model = winkler_lj_model(
        paper000_scans(1.7e-9, count=1, seed=200)[0],
        get_material("polysilicon"),
        get_material("SiO2"),
        options=paper000_options(),
        counter_topography=paper000_tip(),
    )
    crossover = model.crossover_load()
    sweep = model.sweep(np.geomspace(1e-6, 1e-3, 30))
    plot_friction_vs_load(sweep, crossover=crossover)[0].savefig(output / "friction_vs_load.png", dpi=150)
    print(
        f"Ra 1.7 nm: mechanical friction overtakes adhesive friction at {crossover * 1e6:.4g} uN "
        "(paper: ~600 uN)"
    )
    print(f"wrote {output}")


if __name__ == "__main__":
    main(Path(sys.argv[1] if len(sys.argv) > 1 else "paper000-output"))
