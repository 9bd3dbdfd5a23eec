"""
Normal contact of a measured scan
=================================

Press the levelled AFM scan shipped with roughcontact against a flat at a nominal mean pressure
of 20 MPa (polysilicon against SiO2, the pair of paper 000) and read the real contact area, the
contact patches and what the result rests on. The contact is the elastic half-space problem of
paper 001, eq. 4 (p >= 0, g >= 0, p g = 0), solved by constrained conjugate gradients with a free
boundary, since a scan is a window cut from a larger surface.
"""

import importlib.resources

import numpy as np
from matplotlib.figure import Figure
from scipy import ndimage

import roughcontact as rc
from roughcontact.plotting import plot_contact_overview, plot_pressure
from roughcontact.spread import spread
from roughcontact.topography import level
from roughcontact.topography.generate import matched_psd
from roughcontact.units import format_si, prefixed_scale, shown

path = importlib.resources.files("roughcontact") / "data" / "top-1.top"
scan = level(rc.read_topography(path), "plane")
polysilicon, oxide = rc.get_material("polysilicon"), rc.get_material("SiO2")
pressure = rc.quantity("20 MPa", "pressure")  # 2e7 Pa

# %%
# Solve
# -----
# Two elastic bodies are reduced to their composite surface against a rigid flat with the contact
# modulus 1/E* = sum (1 - nu_i^2)/E_i. Every result returns its scalars in SI (``scalars()``) with
# the unit of each dimensional one in ``UNITS``.

result = rc.solve_normal(scan, polysilicon, counter_body=oxide, mean_pressure=pressure)
print(f"boundary: {result.boundary}, E* = {format_si(result.contact_modulus, 'Pa')}")
for name, value in result.scalars().items():
    print(f"{name:<20} {shown(value, result.UNITS.get(name))}")  # labels (levelling) as they are
print(
    f"contact: {100 * result.contact_fraction:.3g} % of the nominal area, {result.number_of_patches} patches"
)

# %%
# What the result rests on
# ------------------------
# ``range_warnings()`` says where the solution leaves its model's range: a peak pressure of the
# order of E* (local slopes beyond small-slope elasticity), full contact, a contact resolved on
# fewer than ten pixels, or a large share of the load on filled points, specks or the window's
# edge (``edge_load_share`` above: a patch near the edge carries about a tenth of the load on a
# tenth of the contact, which is not flagged).

for warning in result.range_warnings() or ["none"]:
    print("warning:", warning)

# %%
# Pressure and gap
# ----------------
# The pressure map (left) and the gap between the deformed surface and the flat (right).

fig = plot_contact_overview(result)

# %%
# The most loaded patch, enlarged
# -------------------------------
# Under 1 % contact the patches are a few pixels each and vanish in a map of the whole scan; here
# the patch that carries the largest load is drawn again on its own, the edge of the contact
# outlined (black inside it is a pressure near zero, outside no contact).

labels, count = ndimage.label(result.contact_mask)
loads = ndimage.sum(result.pressure, labels, index=np.arange(1, count + 1))  # [Pa], times pixel area = N
rows, columns = np.nonzero(labels == 1 + int(np.argmax(loads)))
share = loads.max() / loads.sum()
print(f"most loaded patch: {rows.size} pixels, {100 * share:.3g} % of the load")
scale, _ = prefixed_scale(max(scan.size), "m")  # the unit plot_pressure writes on its axes
margin = 15  # pixels around the patch
zoom = Figure(figsize=(5.0, 4.2), layout="constrained")
ax = zoom.subplots()
plot_pressure(result, ax)
ax.set_xlim((rows.min() - margin) * scan.spacing[0] / scale, (rows.max() + margin) * scan.spacing[0] / scale)
ax.set_ylim(
    (columns.min() - margin) * scan.spacing[1] / scale, (columns.max() + margin) * scan.spacing[1] / scale
)
x, y = (coordinate / scale for coordinate in scan.coordinates())
ax.contour(x, y, result.contact_mask.T.astype(float), levels=[0.5], colors="0.6", linewidths=0.6)
ax.set_title(f"most loaded patch: {100 * share:.2g} % of the load\n(grey line: edge of the contact)")

# %%
# One scan is one spot
# --------------------
# A generated surface with the scan's radially averaged PSD
# (:func:`~roughcontact.topography.generate.matched_psd`: isotropic, Gaussian heights, periodic)
# stands in for more spots of the same sample. Five of them carry the same pressure on a contact
# spread over many more patches: the scan's load sits on a few tall particles (skewness 2.7),
# which a Gaussian surface with the same spectrum does not have.

fractions, patches = [], []
for seed in range(5):
    stand_in = rc.solve_normal(
        matched_psd(scan, seed=seed), polysilicon, counter_body=oxide, mean_pressure=pressure
    )
    fractions.append(stand_in.contact_fraction)
    patches.append(stand_in.number_of_patches)
fraction = spread(fractions)
print(
    f"5 PSD-matched surfaces: contact {100 * fraction.mean:.3g} % +- {100 * fraction.std:.2g} % (1 s.d.), "
    f"{min(patches)}-{max(patches)} patches; the scan: {100 * result.contact_fraction:.3g} %, "
    f"{result.number_of_patches} patches"
)
