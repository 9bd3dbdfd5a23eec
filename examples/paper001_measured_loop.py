"""Write examples/paper001_measured_loop.csv: a SYNTHETIC friction loop for paper 001 (not measured).

Paper 001 does not publish its measured loops (Figs. 3, 13, 14 only). This script builds one for
the HDPE ball on the silicon wafer at F0 = 25 mN with the paper's Table 1 inputs (mu = 0.153,
stroke d_s = 2.805 um) and Table 2 moduli (HDPE 0.98 GPa / 0.5, silicon 130 GPa / 0.28), 10 mm
ball, from the Mindlin-Deresiewicz Masing rule (:func:`roughcontact.analytic.mindlin.masing_force`)
with Johnson's G*. The contact is in series with a setup spring K_s (paper 001 Fig. 3(b); its
value is not given, 5 kN/m is assumed): the XY stage moves 0 -> S -> 0 four times at 0.1 um/s
(the paper's path, Fig. 6), and the capacitive sensor reads the ball-wafer displacement
x_cs = x_stage - F / K_s, whose range in the converged loop is the stroke 2.805 um. Samples are
uniform in time (10 Hz); small Gaussian noise is added (1 nm on x_cs, 0.01 mN on F; seed 1).

It exists to exercise :mod:`roughcontact.experiment.friction_loop`; it is not a measurement and
has no roughness or visco-elasticity (the paper's curved corners are absent). Its header's first
line, ``# origin: synthetic`` (:mod:`roughcontact.origin`), travels with the loop
(:func:`~roughcontact.experiment.friction_loop.read_loop_csv`), so the tables, legends and report
of a study that compares with it call it synthetic, never measured. The file name keeps
"measured" only because it fills the place of the paper's measured loop (``[analysis.compare]``'s
``measured_loop``).

Run: ``.venv/bin/python examples/paper001_measured_loop.py``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from roughcontact.analytic.mindlin import masing_force
from roughcontact.materials import Material
from roughcontact.papers.paper001 import paper001_mindlin

OUTPUT = Path(__file__).with_name("paper001_measured_loop.csv")

HDPE = Material(0.98e9, 0.50, "HDPE ball", source="seed paper 001, Table 2")
SILICON = Material(130e9, 0.28, "silicon wafer", source="seed paper 001, Table 2")
NORMAL_FORCE = 25e-3  # N, Table 1
MU = 0.153  # Table 1, HDPE at 25 mN
STROKE = 2.805e-6  # m, Table 1, range of the sensor displacement in the last loop
BALL_RADIUS = 5e-3  # m (10 mm ball)
SETUP_STIFFNESS = 5e3  # N/m, assumed (not given in the paper)
STAGE_SPEED = 0.1e-6  # m/s (paper sec. 3)
SAMPLE_RATE = 10.0  # Hz
CYCLES = 4
DISPLACEMENT_NOISE = 1e-9  # m (1 nm)
FORCE_NOISE = 1e-5  # N (0.01 mN)
SEED = 1


def synthetic_loop(seed: int = SEED, noise: bool = True) -> dict[str, np.ndarray]:
    """Return time [s], stage and sensor displacement [m] and friction force [N] of the loop."""
    mindlin = paper001_mindlin(
        friction_coefficient=MU,
        normal_force=NORMAL_FORCE,
        radius=BALL_RADIUS,
        material=HDPE,
        counter_body=SILICON,
    )
    slip = MU * NORMAL_FORCE / SETUP_STIFFNESS  # setup deflection while sliding
    # sensor displacement turns at x_hi (stage at S) and x_lo (stage at 0, after the first stroke)
    x_lo, x_hi = slip, slip + STROKE
    corners = [0.0] + [x_hi, x_lo] * CYCLES
    points = 20001
    legs = [np.linspace(a, b, points) for a, b in zip(corners[:-1], corners[1:], strict=True)]
    x_cs = np.concatenate([legs[0]] + [leg[1:] for leg in legs[1:]])
    force = masing_force(
        x_cs,
        mindlin.friction_coefficient,
        mindlin.normal_force,
        mindlin.contact_radius,
        mindlin.shear_modulus,
    )
    x_stage = x_cs + force / SETUP_STIFFNESS
    # resample each leg uniformly in time: the stage moves at constant speed
    t0, times, stage, sensor, friction = 0.0, [], [], [], []
    for k in range(len(legs)):
        leg = slice(k * (points - 1), (k + 1) * (points - 1) + 1)
        s, x, f = x_stage[leg], x_cs[leg], force[leg]
        if s[-1] < s[0]:  # np.interp needs increasing abscissae
            s, x, f, sign = s[::-1], x[::-1], f[::-1], -1.0
        else:
            sign = 1.0
        duration = (s[-1] - s[0]) / STAGE_SPEED
        t = np.arange(0.0 if k == 0 else 1.0 / SAMPLE_RATE, duration + 1e-9, 1.0 / SAMPLE_RATE)
        s_t = (s[0] + STAGE_SPEED * t) if sign > 0 else (s[-1] - STAGE_SPEED * t)
        times.append(t0 + t)
        stage.append(s_t)
        sensor.append(np.interp(s_t, s, x))
        friction.append(np.interp(s_t, s, f))
        t0 += duration
    out = {
        "time": np.concatenate(times),
        "stage_displacement": np.concatenate(stage),
        "displacement": np.concatenate(sensor),
        "force": np.concatenate(friction),
    }
    if noise:
        rng = np.random.default_rng(seed)
        out["displacement"] = out["displacement"] + DISPLACEMENT_NOISE * rng.standard_normal(out["time"].size)
        out["force"] = out["force"] + FORCE_NOISE * rng.standard_normal(out["time"].size)
    return out


def main() -> None:
    """Write the CSV (um and mN, as the capacitive sensor and force hinge would report)."""
    mindlin = paper001_mindlin(
        friction_coefficient=MU,
        normal_force=NORMAL_FORCE,
        radius=BALL_RADIUS,
        material=HDPE,
        counter_body=SILICON,
    )
    data = synthetic_loop()
    header = [
        "origin: synthetic",
        "SYNTHETIC DATA, NOT MEASURED. Paper 001 does not publish its measured loops.",
        "Built by examples/paper001_measured_loop.py: Mindlin-Deresiewicz Masing rule (Johnson 1985,",
        "sec. 7.4) for a 10 mm ball, HDPE 0.98 GPa / 0.5 on silicon 130 GPa / 0.28 (paper 001 Table 2),",
        f"F0 = 25 mN, mu = {MU} (Table 1), Hertz radius a = {mindlin.contact_radius * 1e6:.3f} um,",
        f"Johnson G* = {mindlin.shear_modulus / 1e9:.4f} GPa, "
        f"delta_0 = {mindlin.sliding_distance * 1e9:.1f} nm,",
        f"in series with an assumed setup spring K_s = {SETUP_STIFFNESS:g} N/m; stage path 0 -> S -> 0,",
        f"{CYCLES} cycles at 0.1 um/s, sampled at {SAMPLE_RATE:g} Hz; displacement = capacitive sensor",
        f"(ball vs wafer, x_stage - F/K_s), stroke of the last loop {STROKE * 1e6:g} um (Table 1).",
        f"Noise: {DISPLACEMENT_NOISE * 1e9:g} nm on displacement, {FORCE_NOISE * 1e3:g} mN on force, "
        f"seed {SEED}.",
    ]
    rows = np.column_stack(
        [
            data["time"],
            data["stage_displacement"] * 1e6,
            data["displacement"] * 1e6,
            data["force"] * 1e3,
        ]
    )
    with OUTPUT.open("w") as handle:
        handle.writelines(f"# {line}\n" for line in header)
        handle.write("time [s],stage_displacement [um],displacement [um],force [mN]\n")
        for row in rows:
            handle.write(f"{row[0]:.1f},{row[1]:.5f},{row[2]:.5f},{row[3]:.5f}\n")
    print(f"wrote {OUTPUT} ({rows.shape[0]} rows)")


if __name__ == "__main__":
    main()
