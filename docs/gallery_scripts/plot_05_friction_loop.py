"""
Friction loop and lateral stiffness of a rough ball (paper 001)
===============================================================

Paper 001's case at a small size: a rough POM ball (R = 5 mm) pressed on a silicon wafer at
25 mN, then moved 0 -> d_s -> 0 twice under the local Coulomb law of its eq. 3. The last loop is
analysed as the paper does (stroke, mu, the eq. 9 fit and the lateral stiffness K_L at the points
A, B, C where the force has changed by 25, 50 and 75 % of its pre-sliding span), and K_L is
compared with Mindlin's smooth ball (eqs. 10-12, Johnson's reading). The paper's scans are not
published: the ball is a generated rough sphere, so the numbers are given over three draws of it.
"""

import numpy as np
from matplotlib.figure import Figure

import roughcontact as rc
from roughcontact.papers import paper001
from roughcontact.plotting.presliding import POINT_COLOURS, plot_hysteresis_loops
from roughcontact.spread import spread
from roughcontact.units import format_si

# %%
# Three draws of the ball
# -----------------------
# :func:`~roughcontact.papers.paper001.run_case` generates the ball (a paraboloid of R = 5 mm with
# self-affine roughness of Table 2's 0.67 um rms after sphere removal, on the paper's 1.1 mm field),
# here on 256 pixels (4.3 um) instead of the paper's 1024, and solves the central 64 x 64 pixels
# (275 um, a free window; the contact must not reach its border). Table 1 gives the stroke and
# mu_f at 25 mN; two cycles of 12 steps per stroke, refined where the stick area changes fast.

normal_force = rc.quantity("25 mN", "force")  # 0.025 N
cases = [
    paper001.run_case("POM", normal_force, pixels=256, window=64, seed=seed, cycles=2, steps_per_stroke=12)
    for seed in (1, 2, 3)
]
case = cases[0]
scalars = case.scalars()
for name in ("stroke", "friction_coefficient", "contact_area", "max_pressure", "stroke_from_loop"):
    print(f"{name:<24} {format_si(scalars[name], case.UNITS.get(name, ''))}")
print(f"{'patches':<24} {scalars['patches']}")
print(f"{'mu_from_loop':<24} {scalars['mu_from_loop']:.4f}")
print(f"{'presliding_distance':<24} {format_si(scalars['presliding_distance'], 'm')}")
print(f"{'steps':<24} {scalars['steps']} ({scalars['inserted_steps']} inserted)")

# %%
# K_L at A, B, C against Mindlin
# ------------------------------
# Mindlin's K_L = 8 a G* (1 - f)^(1/3) at the force fraction f of the span, with the Hertz radius
# a of the smooth ball and Johnson's composite shear modulus G*. Paper 001 prints its eq. 12 with a
# modulus four times Johnson's, so its printed Mindlin values are 4 times these.

for point in ("A", "B", "C"):
    values = spread([c.scalars()[f"K_L_{point}"] for c in cases])
    mindlin = scalars[f"K_L_{point}_mindlin_johnson"]
    print(
        f"K_L at {point}: {format_si(values.mean, 'N/m')} +- {format_si(values.std, 'N/m', digits=2)} "
        f"(mean +- s.d. of 3 draws), Mindlin {format_si(mindlin, 'N/m')}, ratio {values.mean / mindlin:.2f}"
    )

# %%
# The loop and its pre-sliding part
# ---------------------------------
# Left: the analysed last loop of the first draw (paper 001 Figs. 13-14). Right: the branch that
# starts at the reversal at delta = 0, as the change of force against the distance from the
# reversal, beside Mindlin and Deresiewicz's branch of the smooth ball, 2 Q(x / 2) (Masing's
# rule), and the points A, B, C of the analysis (coloured as in paper 001 Fig. 15).

displacement, force = case.loop()
last = case.analysis.loop
branch = case.analysis.branch
reference = paper001.paper001_mindlin(
    friction_coefficient=case.friction_coefficient,
    normal_force=normal_force,
    radius=case.radius,
    material=rc.get_material("POM"),
    counter_body=rc.get_material("silicon wafer"),
)
part = slice(branch.start, branch.stop + 1)
distance = np.abs(displacement[part] - branch.reversal_displacement)
change = np.abs(force[part] - branch.reversal_force)
shown = distance <= 2.5 * branch.sliding_distance
smooth = np.linspace(0.0, distance[shown].max(), 200)

fig = Figure(figsize=(10.5, 4.4), layout="constrained")
left, right = fig.subplots(1, 2)
plot_hysteresis_loops([(displacement[last], force[last], "last loop, first draw")], ax=left)
left.set_title(f"μ = {case.analysis.mu:.3f}, stroke {format_si(case.analysis.stroke, 'm', digits=3)}")
right.plot(
    distance[shown] * 1e9, change[shown] * 1e3, "-o", ms=3, color="tab:orange", label="rough ball, first draw"
)
right.plot(
    smooth * 1e9, 2 * reference.force(smooth / 2) * 1e3, "--", color="0.4", label="Mindlin (smooth ball)"
)
for name, x, f, k in zip("ABC", branch.point_distance, branch.fractions, branch.point_stiffness, strict=True):
    label = f"{name}: K_L = {format_si(k, 'N/m', digits=3)}"
    right.plot(x * 1e9, f * branch.span * 1e3, "o", ms=7, color=POINT_COLOURS[name], label=label)
right.set_xlabel("distance from the reversal |δ - δ_r| (nm)")
right.set_ylabel("force change |F - F_r| (mN)")
right.set_title("pre-sliding after the reversal at δ = 0")
right.grid(True, alpha=0.3)
right.legend(fontsize="small", loc="lower right")
