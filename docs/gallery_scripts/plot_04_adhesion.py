"""
Adhesive approach and retraction of a sphere
============================================

Bring a smooth elastic sphere to a rigid flat and pull it off again through an exponential
adhesive law (w = 50 mJ/m^2, decay length 0.5 nm), solved by boundary elements as an energy
minimisation at each approach (:doc:`/adhesive_contact`). The pull-off force is compared with
the closed forms of JKR (1.5 pi w R), DMT (2 pi w R) and Maugis-Dugdale (Maugis 1992) for the
Dugdale law of the same work of adhesion and peak tension.
"""

import numpy as np

import roughcontact as rc
from roughcontact import analytic
from roughcontact.contact import Exponential
from roughcontact.plotting import as_cases
from roughcontact.plotting.adhesion import force_approach_figure
from roughcontact.units import format_si

# %%
# The sphere, the body and the law
# --------------------------------
# A paraboloid of radius 5 um on a free window of 600 nm, 96 x 96 pixels of 6.25 nm; a stiff
# polymer (E = 4 GPa, nu = 0.3) against a rigid flat.

radius = rc.quantity("5 um", "length")  # 5e-6 m
ball = rc.generate.sphere((96, 96), rc.quantity("600 nm", "length"), radius=radius)
polymer = rc.Material(4e9, 0.3)  # E [Pa], nu [-]
work_of_adhesion = rc.quantity("50 mJ/m^2")  # 0.05 J/m^2
law = Exponential(work_of_adhesion, rc.quantity("0.5 nm", "length"))  # peak tension w / rho = 100 MPa

# %%
# The cycle
# ---------
# The flat's approach, from the first touch of the undeformed sphere (negative: apart), goes from
# -2.5 nm to 3 nm and back; the solver inserts steps where the state changes fast, brackets the
# jumps into and out of contact, and continues the last stroke until the surfaces let go. The
# cohesive zone, (pi/4) E* w / sigma0^2, must span a few pixels: for this smooth law the result
# warns below 2.

stroke = np.linspace(-2.5e-9, 3e-9, 23)  # [m]
result = rc.solve_adhesive(ball, polymer, law, approach=np.r_[stroke, stroke[::-1][1:]])
scalars = result.scalars()
headline = ["pull_off_force", "pull_off_approach", "max_force", "jump_in_approach", "jump_out_approach"]
headline += ["dissipated_energy", "max_contact_area", "contact_area_at_pull_off", "cohesive_zone_length"]
for name in headline:
    print(f"{name:<26} {format_si(scalars[name], result.UNITS[name])}")
print(f"cohesive zone {scalars['cohesive_zone_pixels']:.3g} pixels")
imbalance = scalars["residual"]  # largest force imbalance of a pixel over the law's peak tension
print(f"{scalars['steps']} steps ({scalars['inserted_steps']} inserted), largest imbalance {imbalance:.2g}")
for warning in result.range_warnings() or ["none"]:
    print("warning:", warning)

# %%
# Pull-off against the closed forms
# ---------------------------------
# The Maugis parameter lambda of the Dugdale law with the same w and peak tension sigma0 = w/rho
# places this sphere between the DMT (lambda -> 0) and JKR (lambda -> infinity) limits; the
# exponential law is not the Dugdale law, so a few per cent between the two are expected
# (Greenwood 1997).

lam = analytic.maugis_parameter(work_of_adhesion, radius, result.contact_modulus, law.peak_tension)
closed_forms = {
    "Maugis-Dugdale": analytic.maugis_dugdale_pull_off(lam) * np.pi * work_of_adhesion * radius,
    "JKR": analytic.jkr_pull_off(work_of_adhesion, radius),
    "DMT": analytic.dmt_pull_off(work_of_adhesion, radius),
}
print(f"Maugis parameter lambda = {lam:.3g}")
print(f"pull-off, boundary elements: {format_si(result.pull_off_force, 'N')}")
for name, value in closed_forms.items():
    ratio = result.pull_off_force / value
    print(f"pull-off, {name:<15} {format_si(value, 'N')}  (boundary elements / closed form = {ratio:.3f})")

# %%
# Force against approach
# ----------------------
# The library's figure of the cycle (that of ``roughcontact adhesion``): loading solid, unloading
# dash-dotted, the jumps dotted, the pull-off marked; right, the part near the pull-off. The area
# inside the loop is the energy the cycle dissipates.

fig = force_approach_figure(as_cases([result], labels=["sphere R = 5 µm"]))
