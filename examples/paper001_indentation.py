"""Write examples/paper001_indentation_hdpe.csv: a SYNTHETIC nanoindentation curve for paper 001's HDPE.

Paper 001 (section 4, Fig. 7, Table 2) indents its HDPE ball with a Berkovich tip at 10 mN, a
(un)loading rate of 20 mN/min and a 60 s hold, and reports E = 0.98 GPa (nu = 0.5, diamond
1141 GPa / 0.07) from Oliver-Pharr with the viscous hold correction (eqs. 5-8). The measured curve
is only drawn (Fig. 7), not tabulated, so this script synthesises one with
:func:`roughcontact.experiment.nanoindentation.synthetic_indentation_curve` from the paper's
parameters and the modulus 0.98 GPa. Not in the paper, and assumed here: the hardness (60 MPa,
which sets the depth, about 3 um), the creep at the end of the hold (1 nm/s, on the t^(1/3) hold
law), 10 samples per second, Gaussian noise of 1 nm and 1 uN.

Reading the file back (``roughcontact nanoindent examples/paper001_indentation_hdpe.csv``) gives
about 0.97 GPa: the power law fitted to 20-95 % of F_max does not follow the creep-bent top of the
unloading curve exactly (see docs/nanoindentation.md); the plain Oliver-Pharr value is about
1.02 GPa.

Run: ``.venv/bin/python examples/paper001_indentation.py``.
"""

from __future__ import annotations

from pathlib import Path

from roughcontact.experiment.nanoindentation import (
    oliver_pharr,
    synthetic_indentation_curve,
    write_indentation_csv,
)

OUTPUT = Path(__file__).with_name("paper001_indentation_hdpe.csv")
PARAMETERS = {
    "youngs_modulus": 0.98e9,  # paper 001, Table 2 (HDPE)
    "poissons_ratio": 0.5,  # paper 001, text of eq. 8
    "max_force": 10e-3,  # 10 mN
    "loading_rate": 20e-3 / 60.0,  # 20 mN/min, loading and unloading
    "hold_time": 60.0,  # s
    "hardness": 60e6,  # assumed (HDPE-like), sets the depth
    "creep_rate": 1e-9,  # assumed, m/s at the end of the hold
    "sampling_rate": 10.0,  # assumed, 1/s
    "depth_noise": 1e-9,  # assumed, m
    "load_noise": 1e-6,  # assumed, N
    "seed": 1,
}

COMMENTS = (
    "SYNTHETIC DATA, NOT MEASURED. Paper 001 shows its HDPE curve only as Fig. 7.",
    "Built by examples/paper001_indentation.py with roughcontact.experiment.nanoindentation."
    "synthetic_indentation_curve:",
    "E = 0.98 GPa, nu = 0.5, diamond Berkovich 1141 GPa / 0.07, ideal area 24.5 d_c^2, epsilon 0.75;",
    "10 mN, 20 mN/min loading and unloading, 60 s hold (paper 001); assumed: hardness 60 MPa, creep",
    "1 nm/s at the end of the hold (d = d0 + a t^(1/3)), 10 Hz sampling, noise 1 nm and 1 uN (seed 1).",
)


def main() -> None:
    """Write the CSV and print the modulus it reads back."""
    curve = synthetic_indentation_curve(**PARAMETERS)
    write_indentation_csv(OUTPUT, curve, comments=COMMENTS, digits=7)
    result = oliver_pharr(curve)
    print(
        f"wrote {OUTPUT}: E = {result.youngs_modulus / 1e9:.3f} GPa corrected, "
        f"{result.uncorrected_youngs_modulus / 1e9:.3f} GPa plain Oliver-Pharr (input 0.98 GPa)"
    )


if __name__ == "__main__":
    main()
