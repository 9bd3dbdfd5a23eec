"""The ``contact`` command: normal contact of a file's surface against a flat (study model ``normal``)."""

from __future__ import annotations

import argparse

from .options import CommandStudy, add_device, add_material_options, add_output_options, new_command, options
from .output import run_command

COMMANDS = {
    "contact": "solve the normal contact of a file's surface against a flat",
}
"""This module's commands and their lines in ``roughcontact --help``."""


def _contact(args: argparse.Namespace) -> int:
    command = CommandStudy("roughcontact contact", f"normal contact of {args.file.name} against a flat")
    topography = command.topography_file("surface", args)
    command.analysis(
        "contact",
        "normal",
        {
            "topography": (topography, "FILE"),
            "material": (command.material("material", args, required=True), "--material"),
            "counter_body": (command.material("counter_body", args), "--counter-body"),
        }
        | options(
            args,
            "force",
            "approach",
            "hardness",
            "boundary",
            "tolerance",
            "stress_depths",
            spelled={"mean_pressure": "--pressure"},
        ),
    )
    if args.device is not None:
        command.set(("study", "device"), args.device, "--device")
    return run_command(command, args)


def add_commands(commands) -> None:
    """Add ``contact`` to the subparsers ``commands``."""
    contact = new_command(
        commands,
        "contact",
        _contact,
        COMMANDS["contact"],
        "Elastic (or elastic-perfectly-plastic with --hardness) normal contact of the surface "
        "against a flat (study model 'normal'). Give exactly one of --pressure, --force, --approach, with "
        "units. -o writes the case, its figures and a report.",
        file=True,
        boundary=True,
    )
    add_material_options(contact, "material", "the surface's body", "SU-8, polysilicon, SiO2")
    add_material_options(contact, "counter_body", "the flat (default: rigid)", "SiO2")
    contact.add_argument("--pressure", help="nominal mean pressure, e.g. '20 MPa'")
    contact.add_argument("--force", help="total force, e.g. '10 uN'")
    contact.add_argument("--approach", help="rigid approach from the first touch, e.g. '5 nm'")
    contact.add_argument("--hardness", help="cap the pressure (elastic-perfectly-plastic), e.g. '0.46 GPa'")
    contact.add_argument("--tolerance", type=float, default=1e-8, help="scale-free residual (default 1e-8)")
    contact.add_argument(
        "--stress-depths", nargs="+", metavar="DEPTH", help="von Mises maps at these depths, e.g. '20 nm'"
    )
    add_device(contact)
    add_output_options(contact)
