"""The ``nanoindent`` command: sample modulus and hardness from a load-depth CSV (paper 001 equations 5-8).

A view of the study model ``nanoindentation`` (:mod:`roughcontact.study.kinds.nanoindentation`).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .options import CommandStudy, add_output_options, new_command, options
from .output import run_command

COMMANDS = {
    "nanoindent": "sample modulus and hardness from a load-displacement CSV: Oliver-Pharr with the "
    "hold-creep correction",
}
"""This module's commands and their lines in ``roughcontact --help``."""


def _nanoindent(args: argparse.Namespace) -> int:
    command = CommandStudy("roughcontact nanoindent", f"Oliver-Pharr analysis of {args.file.name}")
    keys = {"curve": (str(args.file.resolve()), "FILE"), "fit_range": (list(args.fit_range), "--fit-range")}
    names = ("depth_column", "load_column", "time_column", "depth_unit", "load_unit", "time_unit")
    names += ("indenter", "poissons_ratio", "epsilon", "beta", "rate_sign", "creep_fit")
    command.analysis("indentation", "nanoindentation", keys | options(args, *names))
    return run_command(command, args)


def add_commands(commands) -> None:
    """Add ``nanoindent`` to the subparsers ``commands``."""
    from ..experiment.nanoindentation import CREEP_FITS, RATE_SIGNS

    nanoindent = new_command(
        commands,
        "nanoindent",
        _nanoindent,
        COMMANDS["nanoindent"],
        "Oliver-Pharr analysis with Tang-Ngan's viscous correction as in seed paper 001 "
        "eqs. 5-8 (study model 'nanoindentation'): power law fitted to the upper unloading curve, creep "
        "rate from the hold at maximum load, unloading rate from the onset of unloading, ideal Berkovich "
        "area 24.5 d_c^2; the hardness H = F_max / A_c(d_c) on the same contact area (Oliver and Pharr "
        "2004). Columns are found by name (depth/displacement, load/force, time) with units in "
        "the header, e.g. 'depth (nm)', or given with the options.",
    )
    nanoindent.add_argument("file", type=Path, help="CSV with depth, load and (optional) time columns")
    nanoindent.add_argument("--depth-column", help="header of the depth column (default: auto-detect)")
    nanoindent.add_argument("--load-column", help="header of the load column (default: auto-detect)")
    nanoindent.add_argument("--time-column", help="header of the time column (default: auto-detect)")
    nanoindent.add_argument("--depth-unit", help="unit of the depth column, e.g. nm (overrides the header)")
    nanoindent.add_argument("--load-unit", help="unit of the load column, e.g. mN (overrides the header)")
    nanoindent.add_argument("--time-unit", help="unit of the time column, e.g. s (overrides the header)")
    nanoindent.add_argument(
        "--indenter",
        default="diamond berkovich",
        help="library material of the tip (default: 1141 GPa, 0.07)",
    )
    nanoindent.add_argument(
        "--poissons-ratio", "--poisson", dest="poissons_ratio", type=float, default=0.5,
        help="sample Poisson's ratio (default 0.5)",
    )  # fmt: skip
    nanoindent.add_argument("--epsilon", type=float, default=0.75, help="eq. 7's geometric constant")
    nanoindent.add_argument("--beta", type=float, default=1.0, help="tip-shape factor of eq. 6 (default 1)")
    nanoindent.add_argument(
        "--fit-range", type=float, nargs=2, default=(0.2, 0.95), metavar=("LOW", "HIGH"),
        help="fractions of F_max between which the unloading power law is fitted (default 0.2 0.95)",
    )  # fmt: skip
    nanoindent.add_argument(
        "--rate-sign", choices=RATE_SIGNS, default="magnitude",
        help="eq. 5 with |F_dot| (default) or the paper's printed signed F_dot (raises the modulus)",
    )  # fmt: skip
    nanoindent.add_argument(
        "--creep-fit", choices=CREEP_FITS, default="tang_ngan",
        help="end-of-hold creep rate: t^(1/3) hold law (default), a line on the last 20%%, or none",
    )  # fmt: skip
    add_output_options(nanoindent)
