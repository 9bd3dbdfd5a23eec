"""The ``adhesion`` command: an adhesive load-unload cycle of a file's surface (study model ``adhesion``).

A view of :mod:`roughcontact.study.kinds.adhesion`: FILE (merged with COUNTER_FILE when given)
approaches a flat to ``--max-approach`` and withdraws until it lets go, with a Maugis-Dugdale,
exponential or Lennard-Jones interaction; it prints the pull-off force, the jumps and the
hysteresis, and with ``-o`` writes the cycle, its figures and a report. ``--winkler`` puts paper
000's Winkler-layer springs beside the boundary elements on the same surface.
"""

from __future__ import annotations

import argparse

from .options import CommandStudy, add_output_options, add_two_bodies, new_command, options
from .output import run_command

COMMANDS = {
    "adhesion": "adhesive load-unload cycle of a surface against a flat: pull-off, jumps, hysteresis",
}
"""This module's commands and their lines in ``roughcontact --help``."""

LAW_NAMES = {"md": "maugis_dugdale", "exp": "exponential", "lj": "lennard_jones"}
"""Short spellings of ``--law`` -> the model's law names (which are accepted as well)."""


def _law(text: str) -> str:
    name = LAW_NAMES.get(text, text)
    if name not in LAW_NAMES.values():
        known = ", ".join(f"{short} ({long})" for short, long in LAW_NAMES.items())
        raise argparse.ArgumentTypeError(f"unknown law {text!r}; use one of {known}")
    return name


def _adhesion(args: argparse.Namespace) -> int:
    command = CommandStudy("roughcontact adhesion", f"adhesive load-unload cycle of {args.file.name}")
    ranges = args.ranges or [args.range]
    index = command.analysis(
        "adhesion",
        "adhesion",
        command.two_bodies(args)
        | {
            "law": (args.law, "--law"),
            "interaction_range": (ranges[0], "--ranges" if args.ranges else "--range"),
            "winkler": (args.winkler or None, "--winkler"),
            "reading": (args.reading, "--reading"),
        }
        | options(
            args,
            "work_of_adhesion",
            "surface_energy",
            "counter_surface_energy",
            "combining_rule",
            "max_approach",
            "start",
            "steps",
            "jump_resolution",
            "boundary",
            "film_thickness",
            "layer_thickness",
            "tolerance",
        ),
    )
    if len(ranges) > 1:
        command.sweep(index, "interaction_range", ranges, "--ranges")
    return run_command(command, args)


def add_commands(commands) -> None:
    """Add ``adhesion`` to the subparsers ``commands``."""
    parser = new_command(
        commands,
        "adhesion",
        _adhesion,
        COMMANDS["adhesion"],
        "Boundary-element adhesive contact of FILE (merged with COUNTER_FILE if given) with a flat: "
        "the flat approaches from --start to --max-approach and withdraws until the surfaces let go "
        "(study model 'adhesion'). The work of adhesion is --work-of-adhesion or comes from the surface "
        "energies by --combining-rule. --winkler adds paper 000's Winkler-layer springs beside it.",
        file=True,
        boundary=True,
    )
    add_two_bodies(parser, "the flat or tip (default: rigid)")
    parser.add_argument(
        "--law",
        type=_law,
        default="maugis_dugdale",
        help="interaction law: md (Maugis-Dugdale, default), exp (exponential), lj (Lennard-Jones 9-3, "
        "paper 000 eq. 7)",
    )
    parser.add_argument(
        "--range", default="1 nm", help="interaction range: rho (md, exp) or eps (lj), e.g. '1 nm' (default)"
    )
    parser.add_argument("--ranges", nargs="+", help="several ranges: a sweep, e.g. '0.5 nm' '1 nm' '2 nm'")
    parser.add_argument("--work-of-adhesion", help="work of adhesion, e.g. '100 mJ/m^2'")
    parser.add_argument(
        "--surface-energy", help="surface energy of the surface's body (default: the material's)"
    )
    parser.add_argument(
        "--counter-surface-energy", help="surface energy of the counter-body (default: the material's)"
    )
    parser.add_argument(
        "--combining-rule",
        choices=("girifalco_good", "printed"),
        help="work of adhesion from the surface energies: girifalco_good 2 sqrt(g1 g2) (default) or "
        "printed sqrt(g1 g2) (paper 000 below eq. 7)",
    )
    parser.add_argument(
        "--max-approach", required=True, help="deepest approach from the first touch, e.g. '3 nm'"
    )
    parser.add_argument("--start", help="first approach, negative: apart (default: five ranges apart)")
    parser.add_argument("--steps", type=int, help="equal steps each way (default 40)")
    parser.add_argument("--jump-resolution", help="width jumps are bracketed to (default: a quarter range)")
    parser.add_argument("--film-thickness", help="the body is a film of this thickness on a rigid base")
    parser.add_argument(
        "--winkler", action="store_true", help="paper 000's Winkler-layer springs beside it (needs --law lj)"
    )
    parser.add_argument(
        "--layer-thickness", help="height of the Winkler layer with --winkler (default 50 nm)"
    )
    parser.add_argument(
        "--reading",
        choices=("default", "paper", "printed"),
        help="preset of paper 000's readings for the springs with --winkler (default: default)",
    )
    parser.add_argument(
        "--tolerance", type=float, help="force imbalance per pixel / peak tension (default 1e-6)"
    )
    add_output_options(parser)
