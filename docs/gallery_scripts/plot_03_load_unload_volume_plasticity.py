"""
Load and unload a sphere with plasticity in the volume
======================================================

Press a smooth elastic-perfectly-plastic sphere on a rigid flat to 8 times its critical load and
unload it, with von Mises (J2) plasticity below the surface (the eigenstrain method,
:doc:`/volume_plasticity`). Unloading leaves a residual interference and a residual stress,
which the surface model (pressure capped at the hardness) cannot show: paper 002's Figs. 7 and
9e. The loading branch is compared with Kogut and Etsion's finite-element fit (2002) and the
residual interference with that of Etsion, Kligerman and Kadin (2005). The grid is coarse (32 x 32
pixels, 16 layers) so that the example runs in seconds.
"""

import numpy as np
from matplotlib.figure import Figure

import roughcontact as rc
from roughcontact.asperity import (
    critical_interference,
    critical_load,
    kogut_etsion_load,
    residual_interference_ratio,
)
from roughcontact.contact import VolumePlasticity
from roughcontact.units import format_si, prefixed_scale, shown

# %%
# The sphere and its critical interference
# ----------------------------------------
# Kogut and Etsion's scales: the hardness H = 2.8 Y, omega_c = (pi K H / (2 E*))^2 R with
# K = 0.454 + 0.41 nu (paper 002 eqs. 6 and 8), P_c the Hertz load at omega_c and a_c its contact
# radius.

youngs_modulus, poissons_ratio, yield_strength = 200e9, 0.3, 1e9  # [Pa], [-], [Pa]
radius = rc.quantity("1 mm", "length")  # 1e-3 m
steel = rc.Material(youngs_modulus, poissons_ratio, yield_strength=yield_strength)
e_star = youngs_modulus / (1 - poissons_ratio**2)  # against a rigid flat [Pa]
scales = {"hardness": 2.8 * yield_strength, "poissons_ratio": poissons_ratio, "contact_modulus": e_star}
omega_c = critical_interference(radius=radius, **scales)
p_c = critical_load(radius=radius, **scales)
a_c = np.sqrt(radius * omega_c)
print(f"omega_c = {format_si(omega_c, 'm')}, P_c = {format_si(p_c, 'N')}, a_c = {format_si(a_c, 'm')}")

# %%
# Load and unload
# ---------------
# A free window 10 a_c wide on 32 x 32 pixels (a_c spans about 3 pixels); the plastic strain lives
# in 16 cell layers down to 4 a_c. Force control: up to 8 P_c and back to zero. (At 12 P_c the
# plastic zone would reach the bottom layer of this volume: the solver refuses such a step and
# names a deeper volume to give.)

n = 32
ball = rc.generate.sphere((n, n), (10 * a_c, 10 * a_c), radius=radius, kind="paraboloid")
path = rc.load_unload(
    ball,
    steel,
    forces=p_c * np.array([0.5, 1, 2, 4, 8]),
    unloading_forces=p_c * np.array([4, 2, 1, 0]),
    plasticity=VolumePlasticity(depth=4 * a_c, layers=16),
)
for name, value in path.scalars().items():
    print(f"{name:<24} {shown(value, path.UNITS.get(name))}")  # labels (levelling) as they are
for warning in path.range_warnings() or ["none"]:
    print("warning:", warning)

# %%
# Against the finite-element fits
# -------------------------------
# Kogut-Etsion's P/P_c at each loading interference, and the residual interference after
# unloading from the peak against Etsion-Kligerman-Kadin's omega_res / omega_max.

curve = path.curve()
loading = np.asarray(curve["branch"]) == "loading"
w_star, load = curve["approach"][loading] / omega_c, curve["force"][loading] / p_c
for w, p in zip(w_star, load, strict=True):
    print(f"omega/omega_c = {w:5.2f}: P/P_c = {p:5.2f} here, {kogut_etsion_load(w):5.2f} Kogut-Etsion")
peak = path.scalars()["peak_interference"]
ratio = path.residual_interference / peak
print(
    f"omega_res/omega_max = {ratio:.3f} here, {residual_interference_ratio(peak / omega_c):.3f} "
    f"Etsion-Kligerman-Kadin (residual interference {format_si(path.residual_interference, 'm')})"
)

# %%
# Force against interference
# --------------------------
# Left: the path in physical units, the interference counted from the first touch. Right: the
# same in Kogut and Etsion's scales, with their loading fit (grey) and the residual interference
# of Etsion-Kligerman-Kadin (cross). Unloading starts at the peak.

approach, force = np.asarray(curve["approach"]), np.asarray(curve["force"])
top = int(np.flatnonzero(loading)[-1])
branches = {"loading": slice(0, top + 1), "unloading": slice(top, None)}
length_scale, length_unit = prefixed_scale(approach.max(), "m")
force_scale, force_unit = prefixed_scale(force.max(), "N")
fig = Figure(figsize=(10.0, 4.2), layout="constrained")
left, right = fig.subplots(1, 2)
for (name, part), style in zip(branches.items(), ("-o", "--s"), strict=True):
    left.plot(approach[part] / length_scale, force[part] / force_scale, style, ms=3, label=name)
    right.plot(approach[part] / omega_c, force[part] / p_c, style, ms=3, label=name)
left.set_xlabel(f"interference ({length_unit})")
left.set_ylabel(f"force ({force_unit})")
left.set_title("J2 volume plasticity, 32 x 32 pixels, 16 layers")
fit = np.linspace(0.0, w_star.max(), 200)
right.plot(fit, kogut_etsion_load(fit), color="0.5", lw=1.0, label="Kogut-Etsion 2002 (loading)")
residual_fit = residual_interference_ratio(peak / omega_c) * peak / omega_c
right.plot(residual_fit, 0.0, "kx", ms=8, label="Etsion-Kligerman-Kadin 2005 residual")
right.set_xlabel(f"interference ω/ω_c (ω_c = {format_si(omega_c, 'm', digits=3)})")
right.set_ylabel(f"force P/P_c (P_c = {format_si(p_c, 'N', digits=3)})")
right.set_title("in Kogut-Etsion's scales")
for ax in (left, right):
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
