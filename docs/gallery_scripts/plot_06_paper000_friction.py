"""
Adhesive and mechanical friction of a nanoscale contact (paper 000)
===================================================================

Paper 000's Winkler-layer model with the Lennard-Jones law (its eqs. 1-17): a 2 um SiO2 sphere
(a rough AFM tip) on polysilicon of Ra 1.7 nm at 10 uN, the friction split into an adhesive part
(bonds broken by sliding) and a mechanical one (contacts sheared off), and their crossover with
the load. The paper reports adhesive friction about 40 times the mechanical part at 10 uN and a
crossover near 600 uN. Its scans are not published: the polysilicon scans here are synthetic
(self-affine, scaled to the sample's Ra, seven per sample as the paper scanned seven spots), and
the polysilicon surface energy (50 mJ/m^2) is an assumption. Both the library's default reading
of the disputed equations and the paper's own reading (:doc:`/winkler_lj`) are shown.
"""

import numpy as np
from matplotlib.figure import Figure

import roughcontact as rc
from roughcontact.papers import paper000
from roughcontact.plotting import plot_friction_vs_load
from roughcontact.spread import realisation_seed, spread
from roughcontact.units import format_si, prefixed_scale, shown
from roughcontact.winkler_lj import Readings

# %%
# One scan at the paper's load
# ----------------------------
# Pixels of 20 nm as in the paper, each a spring of the 50 nm Winkler layer, but 128 x 128 of them
# (2.56 um) instead of the paper's 5 um scans: the window holds the whole contact, the ring of
# bonds around it and the half-sphere tip, beyond which neither reading changes with the window
# (:doc:`/winkler_lj`). The tip is a paraboloid of radius 1 um with 0.3 nm rms roughness
# (assumed), merged with the scan into one composite surface against a rigid flat.

sample, ra = "Ra 1.7 nm", paper000.PAPER000_SAMPLES["Ra 1.7 nm"]  # Ra [m]
pixels = 128
tip = paper000.paper000_tip(shape=pixels)
seeds = [realisation_seed(0, "scan", sample, i) for i in range(7)]
scans = [paper000.paper000_scan(ra, shape=pixels, seed=seed) for seed in seeds]
polysilicon, oxide = rc.get_material("polysilicon"), rc.get_material("SiO2")
load = rc.quantity("10 uN", "force")  # 1e-5 N

result = rc.solve_winkler_lj(
    scans[0],
    polysilicon,
    oxide,
    normal_force=load,
    options=paper000.paper000_options(),
    counter_topography=tip,
)
for name, value in result.scalars().items():
    print(f"{name:<24} {shown(value, result.UNITS.get(name))}")  # labels (levelling) as they are

# %%
# Seven scans, two readings
# -------------------------
# mu at 10 uN, the adhesive / mechanical ratio and the crossover load, as mean +- standard
# deviation over the seven synthetic scans. The default reading counts adhesive friction in the
# Dugdale zone of eq. 7 (bonds within 1.97 epsilon); the paper's reading sums eq. 15 over every
# spring under the half-sphere tip and divides eq. 17 by the distance to its equator, which is
# what produces the paper's figures.

readings = {"default reading": None, "paper's reading": Readings.preset("paper")}
models = {}
for label, reading in readings.items():
    models[label] = [paper000.paper000_model(scan, tip, readings=reading) for scan in scans]
    solved = [model.solve(load) for model in models[label]]
    mu = spread([r.mu for r in solved])
    ratio = spread([r.adhesive_friction / r.mechanical_friction for r in solved])
    crossover = spread([model.crossover_load() for model in models[label]])
    print(
        f"{label}: mu at 10 uN {mu.mean:.3f} +- {mu.std:.3f}, adhesive / mechanical {ratio.mean:.3g} "
        f"+- {ratio.std:.2g}, crossover {format_si(crossover.mean, 'N', digits=3)} "
        f"+- {format_si(crossover.std, 'N', digits=2)} (7 scans)"
    )

# %%
# Friction against load
# ---------------------
# Friction and its two parts from 100 nN to 1 mN on the first scan (one synthetic realisation;
# the other six give the spread printed above), the crossover marked (grey) and the paper's load
# of 10 uN dotted.

loads = np.geomspace(1e-7, 1e-3, 25)  # [N]
scale, _ = prefixed_scale(loads.max(), "N")  # the unit plot_friction_vs_load writes on its axes
fig = Figure(figsize=(10.5, 4.2), layout="constrained")
for ax, (label, group) in zip(fig.subplots(1, 2), models.items(), strict=True):
    model = group[0]
    plot_friction_vs_load(model.sweep(loads), ax, crossover=model.crossover_load())
    ax.axvline(load / scale, color="0.3", ls=":", lw=1.0)
    ax.set_title(f"{label}, {sample}, first synthetic scan")
