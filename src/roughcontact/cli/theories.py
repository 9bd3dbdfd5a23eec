"""The ``theories`` command: Persson, Bush-Gibson-Thomas and Greenwood-Williamson beside the BEM.

A view of the study model ``theories`` (:mod:`roughcontact.study.kinds.theories`): a load sweep on
a scan (FILE, one realisation) or on a generated self-affine surface (without FILE; five
realisations by default, so that every deviation of a theory from the BEM mean comes with its 95 %
confidence interval), the BEM's raw and perimeter-corrected areas, its kappa, and the tables and
figures of the model.
"""

from __future__ import annotations

import argparse

from ..errors import InputError
from .options import (
    FILE_OPTIONS,
    CommandStudy,
    add_material_options,
    add_output_options,
    add_realisations,
    new_command,
    options,
)
from .output import run_command

COMMANDS = {
    "theories": "which theory predicts my surface: Persson, Bush-Gibson-Thomas and Greenwood-Williamson "
    "beside the BEM",
}
"""This module's commands and their lines in ``roughcontact --help``."""

GENERATED = (
    "grid",
    "size",
    "hurst",
    "rms_slope",
    "short_cutoff",
    "long_cutoff",
    "rolloff",
    "seed",
    "realisations",
)
"""The options of the generated surface (read without FILE only)."""

DEFAULT_SIZE = "10 um"
"""Side of the generated surface without --size (--size is FILE's physical size otherwise)."""

SHORT_CUTOFF_PIXELS, LONG_CUTOFF_PARTS = 32, 4
"""Default cutoffs of the generated surface: its size over 32 (8 pixels on 256^2) and over 4."""


def _generated(command: CommandStudy, args: argparse.Namespace) -> str:
    """Add the generated self-affine surface (per wavevector: one surface per seed); return its name."""
    from ..units import quantity, written

    sides = list(args.size) if args.size is not None else [DEFAULT_SIZE]
    size = max(quantity(side, "length", field="--size", require_unit=True) for side in sides)
    table = {
        "generate": "self_affine",
        "shape": args.grid,
        "size": sides[0] if len(sides) == 1 else sides,
        "hurst": args.hurst,
        "rms_slope": args.rms_slope,
        "short_cutoff": args.short_cutoff or written(size / SHORT_CUTOFF_PIXELS, "m"),
        "long_cutoff": args.long_cutoff or written(size / LONG_CUTOFF_PARTS, "m"),
        "rolloff": args.rolloff,
        "modes": "wavevector",
    }
    name = command.topography("surface", table, "--grid")
    for key in ("size", "hurst", "rms_slope", "short_cutoff", "long_cutoff", "rolloff"):
        if getattr(args, key) is not None:
            command.name_flag(("topographies", name, key), f"--{key.replace('_', '-')}")
    return name


def _theories(args: argparse.Namespace) -> int:
    if args.file is None:
        file_only = tuple(key for key in FILE_OPTIONS if key != "size")  # --size is the generated side too
        args.taking("without FILE the surface is generated", "give a topography FILE", options=file_only)
        args.taking(
            "without FILE the surface is generated and periodic", "give a FILE", options=("boundary",)
        )
    else:
        args.taking("FILE is the surface", "leave FILE out for a generated one", options=GENERATED)
    if args.loads is not None and args.pressures is not None:
        raise InputError("--loads", "both --loads and --pressures were given.", "give one of them.")
    command = CommandStudy(
        "roughcontact theories",
        "Persson, Bush-Gibson-Thomas and Greenwood-Williamson beside the BEM over a load sweep",
    )
    topography = (
        command.topography_file("surface", args) if args.file is not None else _generated(command, args)
    )
    index = command.analysis(
        "theories",
        "theories",
        {
            "topography": (topography, "FILE" if args.file is not None else "--grid"),
            "material": (command.material("material", args, required=True), "--material"),
            "counter_body": (command.material("counter_body", args), "--counter-body"),
        }
        | options(args, "tolerance", "gamma", "kappa_max_fraction")
        | ({"boundary": (args.boundary, "--boundary")} if args.file is not None else {}),
    )
    if args.pressures is not None:
        command.sweep(index, "mean_pressure", list(args.pressures), "--pressures")
    else:
        from ..theory.comparison import REDUCED_PRESSURES

        command.sweep(index, "reduced_pressure", list(args.loads or REDUCED_PRESSURES), "--loads")
    if args.file is None:
        command.set(("study", "seed"), args.seed, "--seed")
        command.realisations(index, args, topography)
    return run_command(command, args)


def add_commands(commands) -> None:
    """Add ``theories`` to the subparsers ``commands``."""
    parser = new_command(
        commands,
        "theories",
        _theories,
        COMMANDS["theories"],
        "Sweep the load on a scan (FILE) or on a generated self-affine surface (without FILE, on "
        "--realisations draws) with the boundary-element method and set Persson's theory, "
        "Bush-Gibson-Thomas and Greenwood-Williamson beside it, each from the surface's own spectrum: "
        "the contact area (the BEM's pixel count and its perimeter-corrected area), the mean gap, the "
        "distribution of contact pressures, the small-load slope kappa; a table of each theory's "
        "deviation from the BEM mean with its 95 % interval (study model 'theories'). Loads as "
        "p0/(E* g) (--loads) or with units (--pressures). -o writes the tables, figures and a report.",
        file=False,
        boundary=True,
    )
    add_material_options(parser, "material", "the surface's body", "polysilicon, SU-8")
    add_material_options(parser, "counter_body", "the flat (default: rigid)", "'diamond flat tip'")
    parser.add_argument(
        "--loads",
        nargs="+",
        type=float,
        metavar="P_REDUCED",
        help="loads as p0/(E* g), g the surface's rms gradient (default 0.005 0.01 0.02 0.05 0.1 0.2 0.4)",
    )
    parser.add_argument(
        "--pressures", nargs="+", metavar="PRESSURE", help="loads with units, e.g. '5 MPa' '20 MPa'"
    )
    parser.add_argument("--tolerance", type=float, default=1e-8, help="scale-free residual (default 1e-8)")
    parser.add_argument(
        "--gamma", type=float, default=0.4, help="Persson's (2007) gamma of the mean separation (default 0.4)"
    )
    parser.add_argument(
        "--kappa-max-fraction",
        type=float,
        default=0.1,
        help="largest corrected A/A0 of a load in the small-load fit of kappa (default 0.1)",
    )
    generated = parser.add_argument_group(
        f"the generated surface (without FILE): self-affine, periodic, of side --size ({DEFAULT_SIZE!r})"
    )
    generated.add_argument("--grid", type=int, default=256, help="grid points per side (default 256)")
    generated.add_argument("--hurst", type=float, default=0.8, help="Hurst exponent (default 0.8)")
    generated.add_argument("--rms-slope", type=float, default=0.1, help="rms gradient g (default 0.1)")
    generated.add_argument(
        "--short-cutoff", help=f"shortest wavelength (default the size / {SHORT_CUTOFF_PIXELS})"
    )
    generated.add_argument(
        "--long-cutoff", help=f"longest self-affine wavelength (default the size / {LONG_CUTOFF_PARTS})"
    )
    generated.add_argument(
        "--rolloff",
        type=float,
        default=1.0,
        help="plateau below the long cutoff, a fraction of C (default 1)",
    )
    generated.add_argument("--seed", type=int, default=0, help="seed the realisations' seeds derive from")
    add_realisations(generated, "the generated surface", default=5)
    add_output_options(parser)
