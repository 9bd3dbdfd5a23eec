"""The ``presliding`` and ``loop-analysis`` commands (paper 001: partial slip, friction loops, K_L).

``presliding`` is a view of the study model ``presliding`` (:mod:`roughcontact.study.kinds.presliding`):
a ball FILE under paper 001's programme (``--stroke``) or your own (``--path`` CSV), or the paper's
own cases with ``--paper001`` (generated stand-in balls of Table 2's roughness, Table 1 loads,
strokes and mu, :mod:`roughcontact.papers.paper001`; each case solved on the central window that
holds its contact, ``--window auto``). ``loop-analysis`` is a view of the model ``loop_analysis``:
a friction loop's stroke, mu, eq. 9 fit and K_L at A, B, C.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from ..errors import InputError
from ..units import quantity, written
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
    "presliding": "partial-slip friction loops of a rough ball on a flat, K_L vs Mindlin (paper 001)",
    "loop-analysis": "stroke, mu, eq. 9 fit and K_L at A, B, C of a friction loop (paper 001)",
}
"""This module's commands and their lines in ``roughcontact --help``."""


def _paper001(command: CommandStudy, args: argparse.Namespace) -> tuple[dict, dict]:
    """Paper 001's balls (generator ``paper001_ball``) at Table 1's loads: keys and zipped axes.

    ``paper001 = true`` fills in each case's material, flat, radius, stroke and mu
    (:func:`roughcontact.papers.paper001.presliding_keys`).
    """
    from ..papers import paper001

    if args.file is not None:
        raise InputError("FILE", "--paper001 generates the balls.", "drop FILE, or drop --paper001.")
    zipped: dict[str, list] = {"sample": [], "topography": [], "normal_force": []}
    for ball in args.ball:
        try:
            name = paper001.ball_name(ball)
        except InputError as error:
            raise InputError("--ball", error.problem, error.fix) from None
        spec = {"generate": "paper001_ball", "ball": name, "shape": args.pixels, "seed": args.seed}
        command.topography(name.lower(), spec, "--ball")
        for load in args.normal_forces or [written(force, "N") for force in paper001.TABLE1[name]]:
            try:
                paper001.table1(name, quantity(load, "force", field="--normal-forces", require_unit=True))
            except InputError as error:
                raise InputError("--normal-forces", error.problem, error.fix) from None
            zipped["sample"].append(name)
            zipped["topography"].append(name.lower())
            zipped["normal_force"].append(load)
    keys = {
        "paper001": (True, "--paper001"),
        "topography": (zipped["topography"][0], None),
        "sample": (zipped["sample"][0], None),
        "normal_force": (zipped["normal_force"][0], None),
        "window": (args.window or "auto", "--window"),
    }
    flags = {"normal_force": "--normal-forces"}
    return keys, {key: (values, flags.get(key, "--ball")) for key, values in zipped.items()}


def _ball(command: CommandStudy, args: argparse.Namespace) -> dict:
    """Return the model's keys of a ball FILE under the programme of --stroke or --path."""
    if args.file is None:
        raise InputError("FILE", "no ball topography given.", "pass a FILE, or --paper001.")
    if args.path is not None and args.stroke is not None:
        raise InputError(
            "--path",
            "give --stroke (paper 001's cycles) or --path (your programme), not both.",
            "leave out --stroke to follow your programme, or --path for paper 001's cycles.",
        )
    if args.path is None and args.stroke is None:
        raise InputError(
            "--stroke", "missing.", "give --stroke (paper 001's cycles) or --path (your programme)."
        )
    return {
        "topography": (command.topography_file("ball", args), "FILE"),
        "sample": (args.file.stem, None),
        "material": (command.material("material", args, required=True), "--material"),
        "counter_body": (command.material("counter_body", args), "--counter-body"),
        "path": (None if args.path is None else str(args.path.resolve()), "--path"),
    } | options(args, "normal_force", "friction_coefficient", "stroke", "maps", "window")


def _window_option(args: argparse.Namespace) -> None:
    """Read --window (pixels or 'auto') in place."""
    if args.window is not None:
        args.window = _window(args.window)


def _window(text: str) -> int | str:
    """Return --window as a number of pixels, or ``"auto"`` (the study checks the range)."""
    if text.strip().lower() == "auto":
        return "auto"
    try:
        return int(text)
    except ValueError:
        raise InputError(
            "--window", f"got {text!r}.", "give a number of pixels such as 160, or 'auto'."
        ) from None


def _fraction(text: str) -> float:
    """Return --max-stick-change as a number (the study checks its range; 0 turns it off)."""
    try:
        return float(text)
    except ValueError:
        raise InputError(
            "--max-stick-change", f"got {text!r}.", "give a fraction such as 0.1, or 'none'."
        ) from None


def _presliding(args: argparse.Namespace) -> int:
    command = CommandStudy(
        "roughcontact presliding", "partial-slip friction loops of a rough ball (paper 001)"
    )
    zipped = {}
    _window_option(args)
    if args.paper001:
        args.taking(
            "--paper001 runs the paper's own scenario (its balls and their materials, Table 1's loads, "
            "strokes and mu, the programme of Fig. 6)",
            "leave out --paper001 to run your own ball FILE",
            options=("material", "material_youngs_modulus", "material_poissons_ratio", "path", "stroke")
            + ("counter_body", "counter_body_youngs_modulus", "counter_body_poissons_ratio")
            + ("friction_coefficient", "normal_force", "maps", *FILE_OPTIONS),
        )
        keys, zipped = _paper001(command, args)
    else:
        args.taking(
            "without --paper001 the ball is FILE",
            "add --paper001 for the paper's generated balls",
            options=("ball", "pixels", "seed", "realisations", "normal_forces"),
        )
        keys = _ball(command, args)
    keys |= options(args, "radius", "cycles", "steps_per_stroke", "tolerance")
    keys["coupling"] = (False if args.no_coupling else None, "--no-coupling")
    keys |= options(args, "normal_loading", "loading_steps")
    if args.max_stick_change is not None:
        text = args.max_stick_change.strip().lower()
        keys["max_stick_change"] = (0.0 if text == "none" else _fraction(text), "--max-stick-change")
    index = command.analysis("presliding", "presliding", keys)
    if zipped:
        command.zipped(index, zipped)
    command.realisations(index, args, *dict.fromkeys(zipped.get("topography", ([], None))[0]))
    if args.measured is None:
        args.taking(
            "without --measured there is no loop to compare",
            "add --measured LOOP.csv",
            options=("measured_displacement_unit", "measured_force_unit", "measured_normal_force"),
        )
    else:
        command.compare(
            index,
            {"measured_loop": (str(args.measured.resolve()), "--measured")}
            | options(
                args,
                spelled={
                    "displacement_unit": "--measured-displacement-unit",
                    "force_unit": "--measured-force-unit",
                },
            )
            | {
                "normal_force": (
                    args.measured_normal_force or keys["normal_force"][0],
                    "--measured-normal-force",
                )
            },
        )
    return run_command(command, args)


def _loop_analysis(args: argparse.Namespace) -> int:
    command = CommandStudy("roughcontact loop-analysis", f"analysis of the friction loop {args.file.name}")
    command.analysis(
        "loop",
        "loop_analysis",
        {"loop": (str(args.file.resolve()), "FILE")}
        | options(args, "displacement_unit", "force_unit", "normal_force", "branch"),
    )
    return run_command(command, args)


def add_commands(commands) -> None:
    """Add ``presliding`` and ``loop-analysis`` to the subparsers ``commands``."""
    from ..papers import paper001

    presliding = new_command(
        commands,
        "presliding",
        _presliding,
        COMMANDS["presliding"],
        "Press the ball FILE (heights with its spherical shape) on a flat with --normal-force, "
        "move the flat 0 -> --stroke -> 0 for --cycles cycles, and analyse the last loop; or drive it along "
        "your own displacement or force programme (--path CSV); or run paper 001's HDPE/POM cases with "
        "--paper001 (generated stand-in balls of Table 2's roughness, Table 1 loads, strokes and mu; each "
        "case solved on the central window that holds its contact). Study model 'presliding'.",
        file=False,
    )
    add_material_options(presliding, "material", "the ball", "HDPE, POM")
    add_material_options(presliding, "counter_body", "the flat (default: rigid)", "'silicon wafer'")
    presliding.add_argument("--paper001", action="store_true", help="paper 001's balls and Table 1")
    presliding.add_argument(
        "--ball", nargs="+", default=["HDPE", "POM"], help="with --paper001: HDPE and/or POM"
    )
    presliding.add_argument(
        "--normal-forces",
        "--loads",
        dest="normal_forces",
        nargs="+",
        help="with --paper001: loads (default: Table 1's, "
        + ", ".join(written(force, "N") for force in paper001.TABLE1["HDPE"])
        + ")",
    )
    presliding.add_argument(
        "--normal-force", "--force", dest="normal_force", help="normal force F0, e.g. '25 mN'"
    )
    presliding.add_argument(
        "--friction-coefficient",
        "--mu",
        dest="friction_coefficient",
        type=float,
        help="friction coefficient mu_f",
    )
    presliding.add_argument("--stroke", help="stroke d_s of paper 001's programme, e.g. '2.8 um'")
    presliding.add_argument(
        "--path",
        type=Path,
        help="instead of --stroke: your programme, a CSV with one row per step and units in the header: "
        "'x [um]' or 'x [um],y [um]' (displacement control), 'Q_x [mN],Q_y [mN]' (force control); add "
        "a normal column 'F_n [mN]' (normal force) or 'z [um]' (approach) for a combined programme "
        "from the unloaded state (then no --normal-force)",
    )
    presliding.add_argument("--maps", type=int, help="with --path: shear maps kept (last reversals and step)")
    presliding.add_argument(
        "--radius",
        help=f"ball radius for Mindlin's K_L (default: paper 001's {written(paper001.RADIUS, 'm')})",
    )
    presliding.add_argument(
        "--cycles", type=int, default=4, help="with --stroke: cycles of the path (default 4, as Fig. 6)"
    )
    presliding.add_argument(
        "--steps-per-stroke", type=int, default=20, help="with --stroke: steps per branch (default 20)"
    )
    presliding.add_argument(
        "--window",
        help="pixels of the solved central window, or 'auto': per case, the smallest that holds every point "
        "of the ball that can touch at its load (default 'auto' with --paper001, else the whole scan)",
    )
    presliding.add_argument(
        "--pixels", type=int, default=512, help="with --paper001: pixels of the 1.1 mm scan"
    )
    presliding.add_argument("--seed", type=int, default=1, help="with --paper001: seed of the roughness")
    add_realisations(
        presliding,
        "the ball's roughness (--paper001: stand-in balls generated with Table 2's roughness; they are not "
        "the five spots on the wafer where the paper measured)",
    )
    presliding.add_argument("--no-coupling", action="store_true", help="uncoupled (Goodman) solution")
    presliding.add_argument(
        "--normal-loading",
        choices=("auto", "frictional", "frictionless"),
        help="how F0 is applied before the programme: with friction (locked-in shear; 'auto', the "
        "default, does so for dissimilar materials) or frictionless (Goodman's start)",
    )
    presliding.add_argument(
        "--loading-steps", type=int, help="steps of the frictional normal loading (default 10)"
    )
    presliding.add_argument(
        "--max-stick-change",
        help="step control: most the stick fraction may fall in one step (default 0.1, at least 10 "
        "steps from a reversal to full slip); 'none' or 0 solves the programme's points only",
    )
    presliding.add_argument("--tolerance", type=float, default=1e-8, help="solver tolerance (default 1e-8)")
    presliding.add_argument(
        "--measured",
        type=Path,
        help="a friction loop CSV to set beside the cases; its '# origin:' header line says whether it is "
        "measured or synthetic (examples/paper001_measured_loop.csv is synthetic), and tables and legends "
        "name it so",
    )
    presliding.add_argument(
        "--measured-displacement-unit",
        help="unit of the --measured loop's displacement where its header gives none",
    )
    presliding.add_argument(
        "--measured-force-unit", help="unit of the --measured loop's force where its header gives none"
    )
    presliding.add_argument("--measured-normal-force", help="F0 of the --measured loop (default: the cases')")
    add_output_options(presliding)

    analysis = new_command(
        commands,
        "loop-analysis",
        _loop_analysis,
        COMMANDS["loop-analysis"],
        "Analyse the last loop of a friction record (CSV of displacement and force) as paper 001 "
        "does (study model 'loop_analysis'); -o writes the figure of the loop, its fits and points.",
    )
    analysis.add_argument(
        "file",
        type=Path,
        help="CSV with displacement and force columns, units in the header ('displacement [um],force [mN]'); "
        "its '# origin:' line says whether it is measured or synthetic, and the outputs call it so",
    )
    analysis.add_argument("--normal-force", required=True, help="F0, e.g. '25 mN'")
    analysis.add_argument(
        "--displacement-unit",
        help="unit of the displacement column where its header gives none, e.g. um (no default)",
    )
    analysis.add_argument(
        "--force-unit", help="unit of the force column where its header gives none, e.g. mN (no default)"
    )
    analysis.add_argument(
        "--branch", choices=("increasing", "decreasing"), default="increasing", help="branch of the points"
    )
    add_output_options(analysis)
