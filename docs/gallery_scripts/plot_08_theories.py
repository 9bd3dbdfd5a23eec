"""
Which theory predicts the island? Persson, BGT and GW beside the BEM (paper 002)
================================================================================

Paper 002 asks whether a statistical model predicts the deterministic contact of its measured
island. Here the question goes to the theories the field uses: Persson's, Bush-Gibson-Thomas's and
Greenwood-Williamson's, each evaluated from the spectrum of the surface itself, beside the
boundary-element solution of the same surface, at the paper's loads (25 to 1000 uN on the 25 um
square top: 0.04 to 1.6 MPa) and on three realisations of the island's roughness (the paper's
printed spectral moments; its scan is not published), so that each theory's deviation from the BEM
mean comes with its 95 % confidence interval. The BEM's area is given both as the pixel count and
corrected for its pixelated perimeter (Yastrebov et al. 2017). Theory: :doc:`/theories`.
"""

import numpy as np

from roughcontact.materials import get_material
from roughcontact.papers import paper002
from roughcontact.plotting import as_cases
from roughcontact.plotting.theories import theories_area_figure, theories_kappa_figure
from roughcontact.theory import against_bem, compare_theories
from roughcontact.units import format_si

# %%
# Three islands, five loads
# -------------------------
# The roughness of the island's top, periodic over its side (the island's step is left out: the
# theories are of an infinite rough surface), SU-8 under the flat diamond tip.

film, tip = get_material(paper002.MATERIAL), get_material(paper002.PUNCH)
pressures = paper002.island_pressures(5)
results = [
    compare_theories(
        paper002.island_roughness(256, seed=seed), film, counter_body=tip, mean_pressures=pressures
    )
    for seed in (1, 2, 3)
]
first = results[0]
print(
    f"E* = {format_si(first.contact_modulus, 'Pa')}, rms gradient g = {first.rms_gradient:.4f}, "
    f"loads p0 / (E* g) = {', '.join(f'{x:.2g}' for x in first.reduced_pressure)}"
)

# %%
# Each theory against the BEM
# ---------------------------
# The deviation theory / BEM - 1 on each island, its mean and the 95 % confidence interval of the
# mean over the three: "over-predicts" or "under-predicts" where the interval lies above or below 0.

bem = np.array([r.contact_fraction_corrected for r in results])
theories = {
    key: np.array([getattr(r, f"{key}_fraction") for r in results]) for key in ("persson", "bgt", "gw")
}
print(f"{'theory':<34} {'load':>8} {'theory':>9} {'BEM mean [95 % CI]':>28} {'deviation [95 % CI]':>26}")
for row in against_bem(theories, bem, quantity="contact_fraction", mean_pressure=np.array([pressures] * 3)):
    r = row.row()
    print(
        f"{r['theory']:<34} {format_si(r['mean_pressure'], 'Pa'):>8} {r['theory_value']:9.2e} "
        f"{r['bem_mean']:9.2e} [{r['bem_ci95_low']:.2e}, {r['bem_ci95_high']:.2e}] "
        f"{r['deviation']:+7.2f} [{r['deviation_ci95_low']:+.2f}, {r['deviation_ci95_high']:+.2f}] "
        f"{r['verdict']}"
    )

# %%
# Contact area against load
# -------------------------
# At the paper's loads the island touches on less than 1 % of its top, where the area is linear in
# the load: the BEM lies above Persson's and GW's areas and below BGT's small-load law.

figure = theories_area_figure(as_cases(results, samples=["paper 002 island"] * 3))

# %%
# The area-load slope
# -------------------
# A/A0 over p0/(E* g) at each load, the BEM's with its 95 % interval, beside Persson's sqrt(8/pi)
# and BGT's sqrt(2 pi).

figure = theories_kappa_figure(as_cases(results, samples=["paper 002 island"] * 3))
