"""The ``asperity`` command: asperity parameters, the statistical KKE load-unload, paper 002's island.

A view of the study models ``asperity`` (:mod:`roughcontact.study.kinds.asperity`) and, with
``--bem``, ``load_unload`` (:mod:`roughcontact.study.kinds.load_unload`). ``--paper002`` fills in
the paper's printed moments, materials and loads (:mod:`roughcontact.papers.paper002`) and adds
the table of section IV (printed values against ours, in both readings of eq. 7).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from ..errors import InputError
from .command_study import flag_of
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
    "asperity": "statistical elastic-plastic asperity model (GW/McCool, CEB, Kogut-Etsion, KKE) and "
    "paper 002",
}
"""This module's commands and their lines in ``roughcontact --help``."""


def _surface(command: CommandStudy, args: argparse.Namespace) -> dict:
    """Return the keys that say which surface: a FILE or --moments (else --paper002 fills the moments in)."""
    if args.file is not None and args.moments is not None:
        raise InputError("--moments", "both a FILE and --moments were given.", "give one of them.")
    if args.file is not None:
        return {"topography": (command.topography_file("surface", args), "FILE")}
    if args.moments is not None:
        return {
            name: (value, f"--moments {name}")
            for name, value in zip(("m0", "m2", "m4"), args.moments, strict=True)
        }
    if args.paper002:
        return {}
    raise InputError("FILE", "no surface given.", "pass a topography FILE, --moments M0 M2 M4 or --paper002.")


def _asperity(args: argparse.Namespace) -> int:
    """Build the ``asperity`` analysis; ``paper002 = true`` fills in what the options leave out."""
    paper = args.paper002
    if args.file is None:
        args.taking("without FILE no file is read", "give a topography FILE", options=FILE_OPTIONS)
    if not args.bem:
        args.taking(
            "without --bem there is no boundary-element compression",
            "add --bem",
            options=("grid", "seed", "substrate", "film_thickness", "plasticity")
            + ("hardening_modulus", "depth", "layers"),
        )
    elif args.file is not None:
        args.taking(
            "with FILE the island is the file", "leave out FILE for paper 002's", options=("grid", "seed")
        )
    command = CommandStudy("roughcontact asperity", "asperity parameters and the statistical load-unload")
    material = command.material("material", args, required=not paper)
    index = command.analysis(
        "asperity",
        "asperity",
        _surface(command, args)
        | {
            "paper002": (paper or None, "--paper002"),
            "material": (material, "--material"),
            "counter_body": (command.material("counter_body", args), "--counter-body"),
            "max_force": (args.max_force, "--max-force"),
            "nominal_area": (args.area if paper or args.max_force is not None else None, "--area"),
            "reference_force": (args.reference_force, "--reference-force"),
        }
        | options(args, "hardness", "yield_strength", "modulus_form", "law", "distribution", "steps"),
    )
    if args.realisations is not None and not (args.bem and args.paper002 and args.file is None):
        raise InputError(
            "--realisations", "draws paper 002's synthetic island only.", "add --bem --paper002 (no FILE)."
        )
    if args.bem:
        index = _island(command, args, material)
    if args.measured is not None:
        command.compare(index, {"measured_curve": (str(args.measured.resolve()), "--measured")})
    return run_command(command, args)


def _island(command: CommandStudy, args: argparse.Namespace, material: str | None) -> int:
    """Add the BEM compression of the island (FILE, or paper 002's synthetic one): model ``load_unload``."""
    if args.file is not None:
        topography = "surface"
    elif args.paper002:
        topography = command.topography(
            "island", {"generate": "paper002_island", "shape": args.grid}, "--grid"
        )
    else:
        raise InputError("--bem", "needs a topography FILE or --paper002.", "add one, or leave out --bem.")
    if args.max_force is None and not args.paper002:
        raise InputError("--bem", "needs --max-force (and --reference-force).", "add them (or --paper002).")
    index = command.analysis(
        "bem",
        "load_unload",
        {
            "topography": (topography, "FILE"),
            "paper002": (args.paper002 or None, "--paper002"),
            "material": (material, "--material"),
            "substrate": (args.substrate, "--substrate"),
            "film_thickness": (args.film_thickness, "--film-thickness"),
            "max_force": (args.max_force, "--max-force"),
            "reference_force": (args.reference_force, "--reference-force"),
            "hardness": (args.hardness, "--hardness"),
            "plasticity": (args.plasticity, "--plasticity"),
        }
        | _volume_options(args),
    )
    if topography == "island":
        command.set(("study", "seed"), args.seed, "--seed")
        command.realisations(index, args, topography)
    return index


def _volume_options(args: argparse.Namespace) -> dict:
    """Return the keys of ``--plasticity volume`` (--yield-strength is shared with --law jackson_green)."""
    from ..contact.load_unload import PLASTICITY_KEYS

    flags = {flag_of(key): key for key in PLASTICITY_KEYS["volume"]}
    given = {key: (getattr(args, key), flag) for flag, key in flags.items() if getattr(args, key) is not None}
    if args.plasticity != "volume":
        extra = [flag for flag, key in flags.items() if key in given and key != "yield_strength"]
        if extra:
            raise InputError(extra[0], "applies to --plasticity volume only.", "add --plasticity volume.")
        return {}
    return given


def add_commands(commands) -> None:
    """Add ``asperity`` to the subparsers ``commands``."""
    from ..asperity import LOADING_LAWS

    asperity = new_command(
        commands,
        "asperity",
        _asperity,
        COMMANDS["asperity"],
        "Asperity parameters (R_asp, sigma_s, E', K, omega_c, psi) from a topography FILE or "
        "--moments, the statistical load-unload curve with --max-force and --area (study model "
        "'asperity'), and the BEM island compression with --bem (model 'load_unload'). --paper002 fills in "
        "the paper's moments, materials and loads and adds its section IV table (paper vs ours).",
        file=False,
    )
    asperity.add_argument(
        "--moments", nargs=3, metavar=("M0", "M2", "M4"), help="e.g. '0.00213 um^2' 0.0023 '0.0171 1/um^2'"
    )
    asperity.add_argument(
        "--paper002", action="store_true", help="seed paper 002's moments, materials, loads"
    )
    add_material_options(asperity, "material", "the rough body", "SU-8")
    add_material_options(asperity, "counter_body", "the flat (default: rigid)", "'diamond flat tip'")
    asperity.add_argument(
        "--hardness", help="hardness of the rough body, e.g. '0.462 GPa' (default: material's)"
    )
    asperity.add_argument(
        "--yield-strength",
        help="yield strength for --law jackson_green and --plasticity volume, e.g. '0.165 GPa'",
    )
    asperity.add_argument(
        "--modulus-form", choices=("standard", "paper002_eq7_printed"), default="standard", help="E' of eq. 7"
    )
    asperity.add_argument(
        "--law", choices=LOADING_LAWS, default="kogut_etsion", help="single-asperity loading"
    )
    asperity.add_argument("--distribution", choices=("gaussian", "measured"), default="gaussian")
    asperity.add_argument("--max-force", help="peak load, e.g. '1000 uN'")
    asperity.add_argument("--area", help="nominal area, e.g. '25 um x 25 um' or '625 um^2'")
    asperity.add_argument(
        "--reference-force",
        help="load of zero interference, e.g. '25 uN' (default: interference = minus the separation "
        "from the summits' mean plane)",
    )
    asperity.add_argument("--steps", type=int, default=40, help="points per branch of the statistical curve")
    asperity.add_argument("--bem", action="store_true", help="also run the BEM island compression")
    asperity.add_argument("--grid", type=int, default=128, help="grid of paper 002's synthetic island")
    asperity.add_argument("--seed", type=int, default=0, help="seed of paper 002's synthetic island")
    add_realisations(asperity, "paper 002's synthetic island (--bem --paper002)")
    from ..papers import paper002

    paper = paper002.load_unload_keys()
    asperity.add_argument(
        "--substrate", help=f"substrate of the film for --bem (paper 002: {paper['substrate']})"
    )
    asperity.add_argument(
        "--film-thickness",
        help=f"film thickness for --bem with --substrate (paper 002: {paper['film_thickness']})",
    )
    asperity.add_argument(
        "--plasticity",
        choices=("surface", "volume"),
        default="surface",
        help="--bem plastic model: pressure cap at the hardness (surface) or J2 plasticity below it (volume)",
    )
    asperity.add_argument("--hardening-modulus", help="--plasticity volume: hardening slope, e.g. '0 GPa'")
    asperity.add_argument("--depth", help="--plasticity volume: depth of the plastic volume, e.g. '2 um'")
    asperity.add_argument("--layers", type=int, help="--plasticity volume: cells through the depth (16)")
    asperity.add_argument(
        "--measured", type=Path, help="CSV of a measured load-interference curve: interference_m,force_N"
    )
    add_output_options(asperity)
