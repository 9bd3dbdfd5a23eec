"""What the commands share: their parsers, a file's options and its reading, materials, outputs.

A command that computes is a *view* of a study model (:mod:`roughcontact.study.kinds`): it turns
its options into the document a study file would hold (:class:`~.command_study.CommandStudy`,
in :mod:`.command_study`), which is validated by the same schemas and run by the same code as
``roughcontact run``. So a model's parameters, checks, results, tables and figures exist once.
Every option typed is read or refused (:mod:`.recorded`). The commands import all three from here.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from ..errors import InputError, UndefinedPointsError
from ..topography.io import MAX_FILLED
from ..topography.process import LEVELLING
from .command_study import FLAG_ALIASES, flag_of
from .command_study import CommandStudy as CommandStudy  # served here to the commands
from .command_study import options as options
from .recorded import RecordedOptions as RecordedOptions
from .recorded import given_options as given_options
from .recorded import option_strings as option_strings
from .recorded import refuse_unused as refuse_unused

EXIT_INPUT_ERROR = 2
EXIT_NOT_CONVERGED = 3
EXIT_CASES_FAILED = 4
EXIT_INTERNAL_ERROR = 70
"""A bug of roughcontact (EX_SOFTWARE of sysexits.h), said in one line; ``-vv`` shows the traceback."""
EXIT_INTERRUPTED = 130


def size_argument(text: str) -> tuple[str, ...]:
    """Split ``"10 um"``, ``"10 um x 20 um"`` or ``"10um,20um"`` into one string per axis."""
    parts = [p.strip() for p in text.replace(",", " x ").split(" x ") if p.strip()]
    if not 1 <= len(parts) <= 2:
        raise argparse.ArgumentTypeError(f"cannot read size {text!r}; write '10 um' or '10 um x 20 um'")
    return tuple(parts)


def fraction_argument(text: str) -> float:
    """Return a fraction from 0 to 1 (``--max-filled``)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number. Fix: a fraction, e.g. 0.3.") from None
    if not 0.0 <= value <= 1.0:
        raise argparse.ArgumentTypeError(f"{value:g} is not a fraction from 0 to 1. Fix: e.g. 0.3 for 30 %.")
    return value


def channel_argument(text: str) -> int | str:
    """Return a channel by index (digits) or by name."""
    return int(text) if text.isdigit() else text


FILE_OPTIONS = (
    "channel",
    "treat_as_height",
    "size",
    "height_unit",
    "position_unit",
    "override_file_values",
    "fill_undefined",
    "max_filled",
    "crop",
    "remove_specks",
    "exclude_filled",
    "periodic",
    "detrend",
)
"""The options that say how to read FILE (:func:`file_options`): unused where a command reads no file."""


def file_options(*, required: bool = True, periodic: bool = True) -> argparse.ArgumentParser:
    """Return a parent parser with FILE and the options that say how to read it.

    ``periodic`` adds ``--periodic`` (the surface repeats); a command that solves with a
    ``--boundary`` option leaves it out, so that the boundary has one spelling.
    """
    parent = argparse.ArgumentParser(add_help=False)
    group = parent.add_argument_group("reading the file")
    group.add_argument(
        "file",
        type=Path,
        nargs=None if required else "?",
        help="instrument file (any format SurfaceTopography reads) or .nc",
    )
    group.add_argument("--channel", type=channel_argument, help="channel name or index (default: the file's)")
    group.add_argument(
        "--treat-as-height",
        action="store_true",
        help="read a channel whose name says it holds no heights (phase, amplitude, error...) as heights",
    )
    group.add_argument(
        "--size",
        type=size_argument,
        help="physical scan size where the file lacks it, e.g. '5 um' or '5 um x 10 um'",
    )
    group.add_argument("--height-unit", help="unit of the stored heights where the file lacks it, e.g. nm")
    group.add_argument(
        "--position-unit",
        help="unit of the x (y) positions of a text file of points where its header lacks it, e.g. um "
        "(the positions give the size: no --size beside them)",
    )
    group.add_argument(
        "--override-file-values",
        action="store_true",
        help="use --size/--height-unit where the file stores other values (its metadata are wrong)",
    )
    group.add_argument(
        "--fill-undefined",
        action="store_true",
        help="interpolate undefined (missing) points instead of refusing the file",
    )
    group.add_argument(
        "--max-filled",
        type=fraction_argument,
        metavar="FRACTION",
        help=f"largest fraction of the points --fill-undefined may fill (default {MAX_FILLED:g})",
    )
    group.add_argument(
        "--crop",
        nargs="+",
        metavar="EDGE",
        help="read a window only: x0 x1 [y0 y1] with units, e.g. --crop '0 mm' '20 mm' '22 mm' '50 mm'",
    )
    group.add_argument(
        "--remove-specks",
        action="store_true",
        help="make measured points standing alone amid undefined ones undefined before filling",
    )
    group.add_argument(
        "--exclude-filled",
        action="store_true",
        help="keep the filled points out of contact (lowered below every measured point)",
    )
    if periodic:
        group.add_argument("--periodic", action="store_true", help="treat the surface as periodic")
    group.add_argument(
        "--detrend",
        choices=LEVELLING,
        help="background removed from the scan before use (default plane, its tilt; mean for a periodic "
        "surface; none keeps it)",
    )
    return parent


def add_device(parser: argparse.ArgumentParser) -> None:
    """Add ``--device cpu|gpu``: where the normal contact solves run (a study's ``[study] device``)."""
    parser.add_argument(
        "--device",
        choices=("cpu", "gpu"),
        help="run the normal contact solver on the CPU (default) or a CUDA GPU (needs roughcontact[gpu])",
    )


def new_command(
    commands,
    name: str,
    handler,
    summary: str,
    description: str = "",
    *,
    file: bool | None = None,
    boundary: bool = False,
):
    """Add the command ``name`` to the subparsers ``commands``, run by ``handler(args)``; return its parser.

    ``summary`` is its line in ``roughcontact --help``, ``description`` its ``--help`` text; ``file``
    adds FILE and the options that say how to read it (True: required, False: optional);
    ``boundary`` adds ``--boundary periodic|free`` in place of ``--periodic``.
    """
    parents = [] if file is None else [file_options(required=file, periodic=not boundary)]
    parser = commands.add_parser(name, parents=parents, help=summary, description=description or None)
    parser.set_defaults(handler=handler)
    if boundary:
        parser.add_argument(
            "--boundary",
            choices=("periodic", "free"),
            help="periodic (the scan repeated) or free (a window of a larger surface); default free for "
            "a map, periodic for a line scan",
        )
    return parser


def levelling(args: argparse.Namespace, periodic: bool | None = None) -> str:
    """Return the levelling of FILE: ``--detrend``, else plane (mean for a periodic surface).

    ``periodic``: whether the surface as read is periodic (``--periodic``, or a file that says so);
    default ``--periodic``. The default is :func:`~roughcontact.topography.process.default_levelling`'s,
    as ``read_topography``'s and a study file's.

    Raises
    ------
    InputError
        ``--periodic`` with a levelling that would make the surface non-periodic.
    """
    from ..topography.process import default_levelling

    if periodic is None:
        periodic = getattr(args, "periodic", False)
    if args.detrend is None:
        return default_levelling(periodic)
    periodic = getattr(args, "periodic", False)
    if periodic and args.detrend not in ("none", "mean"):
        raise InputError(
            "--detrend",
            f"{args.detrend} removes a background from a --periodic surface, which then no longer repeats.",
            "use --detrend mean (or none) for a periodic surface, or leave --periodic out.",
        )
    return args.detrend


def read_file(args: argparse.Namespace):
    """Read and level FILE as the file options say (for the commands that describe a file, not a model).

    ``--exclude-filled`` is left to the models: the statistics and figures of a file describe
    its heights as filled.

    Returns
    -------
    topography : Topography
        The levelled surface. For a file with undefined points read without --fill-undefined,
        those points hold the mean height (a placeholder: what needs every point is refused);
        its ``specks`` are marked.
    undefined : ndarray of bool or None
        Where the file holds no height (None when every point is defined or was filled).
    """
    import numpy as np

    from ..topography import Topography
    from ..topography.io import Scan, crop_metres, read_scan
    from ..topography.process import crop, find_specks, level
    from ..units import quantity

    levelling(args)  # a --detrend that --periodic refuses, before the file is read
    for part in args.size or ():  # a unit is required here, as in a study file ('--size 5' is not 5 m)
        quantity(part, "length", field="--size", require_unit=True)
    size = args.size if args.size is None or len(args.size) > 1 else args.size[0]
    try:
        scan = read_scan(
            args.file,
            channel=args.channel,
            size=size,
            height_unit=args.height_unit,
            position_unit=args.position_unit,
            periodic=getattr(args, "periodic", False),
            treat_as_height=args.treat_as_height,
            override_file_values=args.override_file_values,
        )
        if args.crop:
            for edge in args.crop:
                quantity(edge, "length", field="--crop", require_unit=True)
            window = crop_metres(args.crop, len(scan.size))
            scan = scan.cropped(*window) if isinstance(scan, Scan) else crop(scan, *window)
    except InputError as error:
        if error.field in ("crop", "x", "y"):
            raise InputError("--crop", error.problem, error.fix) from None
        if error.field == str(args.file) and "cli" in error.fixes:  # the file itself, in the options' words
            raise InputError(error.field, error.problem, error.fix_in("cli")) from None
        if "cli" in error.fixes or error.field in ("size", "height_unit", "position_unit", "channel"):
            raise InputError(flag_of(error.field), error.problem, error.fix_in("cli")) from None
        raise
    undefined = None
    if not isinstance(scan, Scan):
        topography = scan
    elif args.fill_undefined or not scan.undefined.any():
        try:
            topography = scan.topography(
                undefined="interpolate",
                max_filled=MAX_FILLED if args.max_filled is None else args.max_filled,
                remove_specks=args.remove_specks,
            )
        except UndefinedPointsError as error:
            fix = f"if that is acceptable, allow it: --max-filled {error.allowing:g}; or crop them away."
            raise InputError("--max-filled", error.problem, fix) from None
    else:
        undefined = scan.undefined
        placeholder = np.where(undefined, np.nanmean(scan.heights), scan.heights)
        topography = Topography(
            placeholder, scan.size, periodic=scan.periodic, info=scan.info, specks=find_specks(undefined)
        )
    try:
        return level(topography, levelling(args, topography.periodic)), undefined
    except InputError as error:
        raise InputError("--detrend", error.problem, error.fix) from None


def add_two_bodies(parser: argparse.ArgumentParser, counter_body: str) -> None:
    """Add what the commands of two rough bodies share: COUNTER_FILE, both materials, ``--resample``.

    ``counter_body`` says what the counter-body is (``"the flat or tip (default: rigid)"``); the
    keys come back from :meth:`CommandStudy.two_bodies`.
    """
    parser.add_argument("counter_file", nargs="?", type=Path, help="topography of the counter-body (tip)")
    add_material_options(parser, "material", "the surface's body", "polysilicon, SiO2")
    add_material_options(parser, "counter_body", counter_body, "SiO2")
    parser.add_argument(
        "--resample",
        action="store_true",
        help="bring two grids of different pixel size onto a common grid instead of refusing them",
    )


def add_material_options(parser: argparse.ArgumentParser, prefix: str, what: str, names: str) -> None:
    """Add ``--PREFIX`` (a library material) and ``--PREFIX-youngs-modulus``/``--PREFIX-poissons-ratio``.

    With a library name the two are overrides of its values; without one they define the material.
    """
    flag = f"--{prefix.replace('_', '-')}"
    aliases = [f"--{alias}" for alias in FLAG_ALIASES.get(prefix, ())]
    parser.add_argument(flag, *aliases, dest=prefix, help=f"library material of {what}, e.g. {names}")
    parser.add_argument(
        f"{flag}-youngs-modulus",
        *[f"{a}-youngs-modulus" for a in aliases],
        dest=f"{prefix}_youngs_modulus",
        help=f"Young's modulus of {what}, e.g. '70 GPa'",
    )
    parser.add_argument(
        f"{flag}-poissons-ratio",
        *[f"{a}-poissons-ratio" for a in aliases],
        dest=f"{prefix}_poissons_ratio",
        type=float,
        help=f"Poisson's ratio of {what}",
    )


def output_folder(text: str) -> Path:
    """Return ``-o``'s folder; refuse (before anything is computed) a path that is a file or under one."""
    from .._files import not_a_folder

    path = Path(text).expanduser()
    problem = not_a_folder(path)
    if problem:
        raise argparse.ArgumentTypeError(f"{problem} Fix: give a folder for the results (a new one is made).")
    return path


def dpi_argument(text: str) -> int:
    """Return ``--dpi`` as an int from 10 to 2400 (dots per inch of the figures)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number. Fix: e.g. --dpi 300.") from None
    if not 10 <= value <= 2400:
        raise argparse.ArgumentTypeError(
            f"{value} dots per inch is outside 10 to 2400. Fix: 150 for the screen, 300 or 600 for print."
        )
    return value


def add_realisations(parser: argparse.ArgumentParser, what: str, default: int | None = None) -> None:
    """Add ``--realisations N``: each setting on N draws of ``what``, a case each (study key realisations)."""
    parser.add_argument(
        "--realisations",
        type=int,
        default=default,
        metavar="N",
        help=f"run each setting (load, sample) on N independent realisations of {what}, one case each, "
        "their seeds derived from --seed, "
        "and give every number's mean, std and 95 %% interval of the mean"
        + (f" (default {default})" if default else " (default: one draw)"),
    )


def add_output_options(parser: argparse.ArgumentParser, *, figures: bool = True) -> None:
    """Add ``-o/--output``, ``--json`` and (for commands that draw) ``--dpi``."""
    parser.add_argument(
        "-o",
        "--output",
        type=output_folder,
        help="folder for the results: each case, results.csv, tables, figures and report.html",
    )
    parser.add_argument(
        "--overwrite",
        action="store_true",
        help="replace the results an earlier run of this command with other options left in -o",
    )
    parser.add_argument("--json", action="store_true", help="print the results as one JSON document (SI)")
    if figures:
        parser.add_argument(
            "--dpi", type=dpi_argument, default=150, help="resolution of the figures (default 150)"
        )
