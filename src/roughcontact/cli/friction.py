"""The ``friction`` and ``friction-compare`` commands: paper 000's Winkler-Lennard-Jones friction.

Both are views of the study model ``friction`` (:mod:`roughcontact.study.kinds.friction`):
``friction`` runs one surface (merged with a counter-surface) at one load or a sweep of loads;
``friction-compare`` runs every scan of every sample at one load and compares the simulated mu
with measured values (paper 000's validation: t-tests and the Pearson r of the means). Without
scans it runs paper 000's own case on synthetic scans (:mod:`roughcontact.papers.paper000`).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from ..errors import InputError
from .options import (
    CommandStudy,
    add_output_options,
    add_realisations,
    add_two_bodies,
    new_command,
    options,
    size_argument,
)
from .output import run_command

COMMANDS = {
    "friction": "adhesive + mechanical friction of a surface (Winkler layer + Lennard-Jones, paper 000)",
    "friction-compare": "simulated vs measured mu per sample: t-tests and Pearson r (paper 000's validation)",
}
"""This module's commands and their lines in ``roughcontact --help``."""


def _readings(texts: list[str]) -> tuple[str | None, dict[str, str]]:
    """Return ``--reading`` (repeated) as a study's ``reading`` preset and ``readings`` table.

    ``--reading PRESET`` (no ``=``, at most one: default, paper, printed) names the preset;
    ``--reading NAME=VALUE`` changes one of its fields. Both are checked by the study model.
    """
    preset, readings = None, {}
    for text in texts:
        name, separator, value = text.partition("=")
        if not separator and name.strip() and preset is None:
            preset = name.strip()
            continue
        if not separator or not name.strip() or not value.strip():
            raise InputError(
                "--reading",
                f"cannot read {text!r}" + (f" beside the preset {preset!r}." if preset else "."),
                "write NAME=VALUE, e.g. contact=zero_gap, or one preset name: default, paper, printed.",
            )
        readings[name.strip()] = value.strip()
    return preset, readings


def _model_keys(args: argparse.Namespace) -> dict:
    """Return the model's keys the two commands share, with the option of each."""
    keys = options(args, "surface_energy", "counter_surface_energy", "layer_thickness", "epsilon")
    preset, readings = _readings(args.reading)
    return keys | {
        "reading": (preset, "--reading"),
        "readings": (readings or None, "--reading"),
        **options(args, "tip_radius"),
        "gap_model": (args.gap_model, "--gap-model"),
    }


def _friction(args: argparse.Namespace) -> int:
    command = CommandStudy("roughcontact friction", f"friction of {args.file.name} (paper 000's model)")
    if args.normal_forces:
        args.taking("--normal-forces gives the loads", "leave out --normal-forces", options=("normal_force",))
    if not args.relaxed_modulus:
        args.taking(
            "without --relaxed-modulus the modulus does not relax",
            "add --relaxed-modulus",
            options=("hold_time", "relaxation_time"),
        )
    forces = args.normal_forces or [args.normal_force]
    index = command.analysis(
        "friction",
        "friction",
        command.two_bodies(args)
        | {
            "normal_force": (forces[0], "--normal-forces" if args.normal_forces else "--normal-force"),
            "crossover": (args.crossover or None, "--crossover"),
            **options(args, "relaxed_modulus"),
            **(options(args, "relaxation_time", "hold_time") if args.relaxed_modulus else {}),
            **_model_keys(args),
        },
    )
    if len(forces) > 1:
        command.sweep(index, "normal_force", forces, "--normal-forces")
    return run_command(command, args)


def _sample_argument(text: str) -> tuple[str, list[Path]]:
    name, separator, files = text.partition("=")
    if not separator or not files:
        raise argparse.ArgumentTypeError(f"cannot read {text!r}; write NAME=scan1.di,scan2.di,...")
    return name.strip(), [Path(f) for f in files.split(",") if f]


def _paper000_scans(command: CommandStudy, args: argparse.Namespace) -> dict:
    """Paper 000's synthetic scans and tip (generators ``paper000_scan``, ``paper000_tip``): their keys."""
    from ..papers import paper000

    first = next(iter(paper000.PAPER000_SAMPLES))
    command.topography("scan", {"generate": "paper000_scan", "shape": args.grid, "sample": first}, "--grid")
    command.topography("tip", {"generate": "paper000_tip", "shape": args.grid, "seed": args.seed}, "--grid")
    command.set(("study", "seed"), args.seed, "--seed")
    return {"topography": ("scan", None), "counter_topography": ("tip", None)}


def _friction_compare(args: argparse.Namespace) -> int:
    from ..papers import paper000

    command = CommandStudy(
        "roughcontact friction-compare", f"simulated mu against the values of {args.measured.name}"
    )
    if args.sample:
        args.taking(
            "--sample gives the scans",
            "leave out --sample for paper 000's",
            options=("grid", "seed", "realisations"),
        )
    else:
        args.taking(
            "without --sample the scans and the tip are paper 000's synthetic ones",
            "give your scans with --sample",
            options=("tip", "size", "height_unit"),
        )
    if args.sample:
        names, samples, replicates = [], [], []
        for sample, files in args.sample:
            for number, path in enumerate(files):
                names.append(command.topography_file(f"{sample}_{number}", args, file=path))
                samples.append(sample)
                replicates.append(number)
        tip = None if args.tip is None else command.topography_file("tip", args, file=args.tip)
        surfaces = {"topography": (names[0], None), "counter_topography": (tip, "--tip")}
    else:
        surfaces = _paper000_scans(command, args)
    index = command.analysis(
        "friction",
        "friction",
        surfaces
        | {
            "paper000": (True, None),  # paper 000's bodies, load, layer and energies unless given
            "material": (args.material, "--material"),
            "counter_body": (args.counter_body, "--counter-body"),
            "normal_force": (args.normal_force, "--normal-force"),
            **_model_keys(args),
        },
    )
    if args.sample:
        command.zipped(
            index,
            {
                "sample": (samples, "--sample"),
                "replicate": (replicates, "--sample"),
                "topography": (names, "--sample"),
            },
        )
    else:
        command.sweep(index, "replicate", list(range(args.realisations)), "--realisations")
        samples = list(paper000.PAPER000_SAMPLES)
        command.zipped(
            index, {"sample": (samples, "--seed"), "topographies.scan.sample": (samples, "--seed")}
        )
    command.compare(
        index,
        {
            "measured": (str(args.measured.resolve()), "MEASURED"),
            "alpha": (args.alpha, "--alpha"),
            "equal_var": (args.equal_var, "--equal-var"),
        },
    )
    return run_command(command, args)


def _shared_options(parser: argparse.ArgumentParser, *, paper: bool) -> None:
    """Add the model's options; ``paper``: their defaults are paper 000's (``friction-compare``)."""
    from ..papers import paper000

    keys = paper000.friction_keys()
    parser.add_argument(
        "--surface-energy",
        help="surface energy of the surface, e.g. '50 mJ/m^2'"
        + (f" (paper 000 does not give it; default {keys['surface_energy']})" if paper else ""),
    )
    parser.add_argument(
        "--counter-surface-energy",
        help="surface energy of the counter-body (default: "
        + (f"{keys['counter_surface_energy']}, paper 000's SiO2)" if paper else "the library's)"),
    )
    parser.add_argument(
        "--layer-thickness", help=f"Winkler layer height h (default {keys['layer_thickness']}, paper 000's)"
    )
    parser.add_argument(
        "--epsilon", help=f"Lennard-Jones equilibrium distance (default {keys['epsilon']}, paper 000's)"
    )
    parser.add_argument(
        "--reading",
        action="append",
        default=[],
        metavar="NAME=VALUE|PRESET",
        help="reading of a disputed equation of paper 000, e.g. contact=zero_gap, or a preset they change: "
        "default, paper (the paper's own reading: its headline results), printed (see the documentation's "
        "Winkler-layer page)",
    )
    parser.add_argument(
        "--tip-radius",
        help="radius of the half-sphere tip (reading base=half_sphere, in the preset paper), e.g. '1 um'; "
        "default: the generated tip's",
    )
    parser.add_argument(
        "--gap-model",
        choices=("winkler", "bem"),
        help="gap field of the friction sums: winkler (default, paper 000's springs) or bem (the adhesive "
        "boundary-element solution at the same load; the documentation's Winkler-layer page)",
    )
    add_output_options(parser)


def add_commands(commands) -> None:
    """Add ``friction`` and ``friction-compare`` to the subparsers ``commands``."""
    from ..papers import paper000

    friction = new_command(
        commands,
        "friction",
        _friction,
        COMMANDS["friction"],
        "Friction of FILE (merged with COUNTER_FILE if given) against a flat at --normal-force, "
        "or over --normal-forces, with the adhesive and mechanical parts and mu = F / N (study model "
        "'friction').",
        file=True,
    )
    add_two_bodies(friction, "the counter-body (default: rigid)")
    friction.add_argument(
        "--normal-force",
        "--load",
        dest="normal_force",
        default=paper000.friction_keys()["normal_force"],
        help="normal load (default: paper 000's %(default)s)",
    )
    friction.add_argument(
        "--normal-forces",
        "--loads",
        dest="normal_forces",
        nargs="+",
        help="several loads: a sweep, e.g. '1 uN' '10 uN' '100 uN'",
    )
    friction.add_argument(
        "--crossover",
        action="store_true",
        help="find the load where mechanical friction overtakes adhesive friction",
    )
    friction.add_argument(
        "--hold-time", default="0 s", help="time held in contact before sliding, e.g. '10 s'"
    )
    friction.add_argument(
        "--relaxed-modulus",
        help="long-time Young's modulus of the surface's body (standard linear solid from its modulus to "
        "this one), e.g. '90 GPa'",
    )
    friction.add_argument(
        "--relaxation-time", default="1 s", help="relaxation time of the standard linear solid"
    )
    _shared_options(friction, paper=False)

    comparison = new_command(
        commands,
        "friction-compare",
        _friction_compare,
        COMMANDS["friction-compare"],
        "Simulate mu for every scan of every sample (--sample NAME=a.di,b.di ...; without "
        "--sample: paper 000's case, seven synthetic seeded scans per sample) and compare with MEASURED "
        "(CSV sample,mu): per-sample t-tests and the Pearson r of the means.",
    )
    comparison.add_argument("measured", type=Path, help="CSV with columns sample,mu ('#' comments)")
    comparison.add_argument(
        "--sample",
        action="append",
        type=_sample_argument,
        metavar="NAME=FILES",
        help="scans of one sample, comma-separated; repeat per sample",
    )
    comparison.add_argument("--tip", type=Path, help="topography of the tip, on the scans' grid")
    comparison.add_argument("--size", type=size_argument, help="scan size if the files lack it, e.g. '5 um'")
    comparison.add_argument("--height-unit", help="height unit if the files lack it")
    comparison.add_argument(
        "--material", help=f"library material of the samples (default: paper 000's {paper000.MATERIAL})"
    )
    comparison.add_argument(
        "--counter-body",
        "--counter",
        dest="counter_body",
        help=f"library material of the tip (default: paper 000's {paper000.TIP_MATERIAL})",
    )
    comparison.add_argument(
        "--normal-force",
        "--load",
        dest="normal_force",
        help=f"normal load (default: paper 000's {paper000.friction_keys()['normal_force']})",
    )
    comparison.add_argument("--alpha", type=float, default=0.1, help="t-test threshold (paper: 0.1)")
    comparison.add_argument(
        "--equal-var", action="store_true", help="Student's pooled t-test instead of Welch's"
    )
    comparison.add_argument(
        "--seed", type=int, default=0, help="without --sample: seed of the synthetic scans"
    )
    comparison.add_argument(
        "--grid",
        type=int,
        default=paper000.SCAN_PIXELS,
        help=f"without --sample: points per side of the 20 nm-pixel scans (default {paper000.SCAN_PIXELS})",
    )
    add_realisations(
        comparison,
        "each sample's scan (without --sample; paper 000 scanned seven spots)",
        paper000.SCANS_PER_SAMPLE,
    )
    _shared_options(comparison, paper=True)
