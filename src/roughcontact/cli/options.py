"""What the commands share: reading a file's options, materials, outputs, and a command as a study.

A command that computes is a *view* of a study model (:mod:`roughcontact.study.kinds`): it turns
its options into the document a study file would hold (:class:`CommandStudy`), which is validated
by the same schemas and run by the same code as ``roughcontact run``. So a model's parameters,
checks, results, tables and figures exist once. :class:`CommandStudy` remembers which option set
each value, so a problem is reported in the user's own terms: the option and the value as typed
(``--material-youngs-modulus: '-70 GPa' ...``), not a study key and an SI float.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from ..errors import InputError, UndefinedPointsError
from ..messages import Door, render
from ..topography.io import MAX_FILLED
from ..topography.process import LEVELLING

EXIT_INPUT_ERROR = 2
EXIT_NOT_CONVERGED = 3
EXIT_CASES_FAILED = 4
EXIT_INTERNAL_ERROR = 70
"""A bug of roughcontact (EX_SOFTWARE of sysexits.h), said in one line; ``-vv`` shows the traceback."""
EXIT_INTERRUPTED = 130


class RecordedOptions:
    """A command's parsed options that remember which of them the command read.

    :func:`roughcontact.cli.main` hands every handler its options wrapped in one: reading an
    option (``args.path``, ``getattr(args, "stroke", None)``) marks it used. Before a command
    computes anything it calls :func:`refuse_unused`, which refuses every option the user typed
    that the path the command took never read: ``presliding --paper001 --path my.csv`` runs the
    paper's own programme, so ``--path`` would be dropped without a word. One mechanism for
    every command and path; a handler names what decided its path with :meth:`taking`.

    Parameters
    ----------
    namespace : argparse.Namespace
        The parsed options.
    given : dict of str to str
        The options the user typed: destination -> the option string as typed (``--path``).
    """

    def __init__(
        self,
        namespace: argparse.Namespace,
        given: Mapping[str, str],
        options: Mapping[str, str] | None = None,
    ):
        object.__setattr__(self, "_namespace", namespace)
        object.__setattr__(self, "_given", dict(given))
        object.__setattr__(self, "_options", dict(options or {}))
        object.__setattr__(self, "_read", set())
        object.__setattr__(self, "_path", [])

    def __getattr__(self, name: str) -> Any:
        value = getattr(object.__getattribute__(self, "_namespace"), name)
        object.__getattribute__(self, "_read").add(name)
        return value

    def __setattr__(self, name: str, value: Any) -> None:
        setattr(object.__getattribute__(self, "_namespace"), name, value)

    def taking(self, reason: str, other: str, *, options: Iterable[str] | None = None) -> None:
        """Say what decided the command's path and how to take the other one.

        ``reason``: ``"--paper001 runs the paper's own programme"``; ``other``: ``"leave out
        --paper001 to run your own"``; ``options``: the destinations it explains (default every
        unused one). :func:`refuse_unused` gives both when it refuses an option this path does
        not read.
        """
        dests = None if options is None else frozenset(options)
        object.__getattribute__(self, "_path").append((reason, other, dests))

    def option_for(self, dest: str) -> str | None:
        """Return the option string of destination ``dest`` in this command (None if it has none)."""
        return object.__getattribute__(self, "_options").get(dest)

    def unused_options(self) -> dict[str, str]:
        """Return the options typed but never read: destination -> the option as typed."""
        read = object.__getattribute__(self, "_read")
        return {
            dest: option
            for dest, option in object.__getattribute__(self, "_given").items()
            if dest not in read
        }

    def reasons_for(self, dest: str) -> list[tuple[str, str]]:
        """Return what decided the path for option ``dest`` and how to take the other (:meth:`taking`)."""
        return [(r, o) for r, o, d in object.__getattribute__(self, "_path") if d is None or dest in d]


def option_strings(parser: argparse.ArgumentParser) -> dict[str, str]:
    """Return each destination of ``parser``'s options and its first long option string (``--pressure``)."""
    found = {}
    for action in parser._actions:
        if action.option_strings:
            long = [text for text in action.option_strings if text.startswith("--")]
            found.setdefault(action.dest, (long or action.option_strings)[0])
        elif action.dest not in ("handler",):
            found.setdefault(action.dest, action.dest.upper())
    return found


def given_options(parser: argparse.ArgumentParser, argv: Iterable[str]) -> dict[str, str]:
    """Return the options of ``parser`` that ``argv`` types: destination -> the option string typed.

    Read from the words themselves, so an option typed with its default value counts as given.
    Abbreviations argparse accepts (``--pres`` for ``--pressure``) count under their option.
    """
    actions = parser._option_string_actions  # argparse's own table of option strings
    given: dict[str, str] = {}
    for word in argv:
        if word == "--":
            break
        if not word.startswith("-") or word in ("-", "-v", "-vv", "--verbose"):
            continue
        option = word.split("=", 1)[0]
        action = actions.get(option)
        if action is None and option.startswith("--"):
            matches = [a for text, a in actions.items() if text.startswith(option)]
            action = matches[0] if len({id(a) for a in matches}) == 1 else None
        if action is not None and action.dest not in ("help",):
            given.setdefault(action.dest, option)
    return given


def refuse_unused(args) -> None:
    """Refuse every option the user typed that the command's path did not read (see :class:`RecordedOptions`).

    Raises
    ------
    InputError
        Naming each unused option and why: the options that chose the path, or that the command
        does not use it in this combination.
    """
    if not isinstance(args, RecordedOptions):
        return
    unused = args.unused_options()
    if not unused:
        return
    groups: dict[tuple, list[str]] = {}
    for dest, option in sorted(unused.items(), key=lambda item: item[1]):
        groups.setdefault(tuple(args.reasons_for(dest)), []).append(option)
    found = []
    for path, options in groups.items():
        because = "; ".join(reason for reason, _ in path) or "the command does not use it with these options"
        them = "it" if len(options) == 1 else "them"
        fix = f"leave {them} out" + "".join(f", or {other}" for _, other in path) + "."
        found.append(
            (", ".join(options), f"{'is' if len(options) == 1 else 'are'} not used: {because}.", fix)
        )
    if len(found) == 1:
        raise InputError(*found[0])
    lines = [f"{option}: {problem} Fix: {fix}" for option, problem, fix in found]
    raise InputError(", ".join(sorted(unused.values())), "not used:\n  " + "\n  ".join(lines))


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
            raise InputError(_flag(error.field), error.problem, error.fix_in("cli")) from None
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
    aliases = [f"--{alias}" for alias in _FLAG_ALIASES.get(prefix, ())]
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


_FLAG_ALIASES = {"counter_body": ("counter",)}
"""Option spellings of release 0.1 still accepted (``--counter`` for ``--counter-body``)."""


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


def _flag(name: str) -> str:
    return f"--{name.replace('_', '-')}"


def options(
    args: argparse.Namespace, *names: str, spelled: Mapping[str, str] | None = None
) -> dict[str, tuple[Any, str]]:
    """Return model keys as (value, option), the values read from ``args``.

    ``names`` are keys whose option is spelled like them (``stress_depths``: ``--stress-depths``);
    each ``key: "--option"`` of ``spelled`` is a key that an option of another name sets.
    """
    keys = {name: (getattr(args, name), _flag(name)) for name in names}
    for key, option in (spelled or {}).items():
        keys[key] = (getattr(args, option.lstrip("-").replace("-", "_")), option)
    return keys


class CommandStudy:
    """The study a command builds from its options, and which option gave each value.

    Parameters
    ----------
    name : str
        The study's name (``"roughcontact contact"``): a later run of the same command into the
        same ``-o`` folder reuses its finished cases.
    description : str
        One line for the report.
    """

    def __init__(self, name: str, description: str = ""):
        self.name = name
        self.document: dict[str, Any] = {
            "study": {"name": name, "description": description, "seed": 0},
            "topographies": {},
            "materials": {},
            "analysis": [],
        }
        self.flags: dict[tuple, str] = {}
        self.words: dict[str, str] = {}
        self.table_words: dict[tuple, dict[str, str]] = {}
        self.options = None  # key -> the command's option of that name (RecordedOptions.option_for)

    # --- building the document ---------------------------------------------------------------

    def set(self, path: tuple, value: Any, flag: str | None = None) -> None:
        """Set ``value`` at ``path`` of the document; ``flag`` is the option the user typed it as."""
        node = self.document
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value
        if flag is not None:
            self.name_flag(path, flag)

    def name_flag(self, path: tuple, flag: str) -> None:
        """Say that the value at ``path`` (and a key of that name in messages) came from ``flag``."""
        self.flags[path] = flag
        key = str(path[-1])
        if key not in ("file", "material", "counter_body", "topography") or flag.startswith("-"):
            self.words.setdefault(key, flag)

    def topography_file(self, name: str, args: argparse.Namespace, *, file: Path | None = None) -> str:
        """Add FILE (or ``file``) as the topography ``name``, read as the file options say; return it."""
        table: dict[str, Any] = {"file": str(Path(file if file is not None else args.file).resolve())}
        where = ("topographies", name)
        self.document["topographies"][name] = table
        for key in (
            "size",
            "height_unit",
            "position_unit",
            "channel",
            "fill_undefined",
            "max_filled",
            "treat_as_height",
            "override_file_values",
            "remove_specks",
            "exclude_filled",
            "crop",
        ):
            self.words.setdefault(key, _flag(key))
        self.flags[(*where, "max_filled")] = "--max-filled"
        self.name_flag((*where, "file"), "FILE" if file is None else str(file))
        self.flags[where] = "FILE" if file is None else str(file)
        # FILE's own options; the file's units (--size, --height-unit) and --detrend hold for every file
        for key in (
            ("channel", "height_unit", "position_unit", "max_filled")
            if file is None
            else (
                "height_unit",
                "position_unit",
            )
        ):
            if getattr(args, key, None) is not None:
                self.set((*where, key), getattr(args, key), _flag(key))
        if getattr(args, "size", None) is not None:
            self.set((*where, "size"), list(args.size) if len(args.size) > 1 else args.size[0], "--size")
        if getattr(args, "crop", None):
            self.set((*where, "crop"), list(args.crop), "--crop")
        if getattr(args, "override_file_values", False):
            self.set((*where, "override_file_values"), True, "--override-file-values")
        flags = ("fill_undefined", "periodic", "treat_as_height", "remove_specks", "exclude_filled")
        for key in flags if file is None else ():
            if getattr(args, key, False):
                self.set((*where, key), True, _flag(key))
        if getattr(args, "detrend", None) is not None:
            self.set((*where, "detrend"), args.detrend, "--detrend")
        return name

    def two_bodies(self, args: argparse.Namespace) -> dict[str, tuple[Any, str]]:
        """Return the keys of FILE merged with COUNTER_FILE (when given) and their two materials.

        ``topography``, ``counter_topography``, ``material`` (required), ``counter_body`` and
        ``resample``, each with the option that gave it, for the commands of two rough bodies
        (friction, adhesion; their options from :func:`add_two_bodies`).
        """
        counter = None
        if args.counter_file is not None:
            counter = self.topography_file("counter_surface", args, file=args.counter_file)
        return {
            "topography": (self.topography_file("surface", args), "FILE"),
            "counter_topography": (counter, "COUNTER_FILE"),
            "material": (self.material("material", args, required=True), "--material"),
            "counter_body": (self.material("counter_body", args), "--counter-body"),
            "resample": (args.resample or None, "--resample"),
        }

    def topography(self, name: str, table: dict[str, Any], flag: str) -> str:
        """Add a generated topography (a ``generate = ...`` table); return ``name``."""
        self.document["topographies"][name] = table
        self.flags[("topographies", name)] = flag
        return name

    def realisations(self, index: int, args: argparse.Namespace, *redrawn: str) -> None:
        """Run analysis ``index`` on ``--realisations`` draws of the generated topographies ``redrawn``.

        With more than one, their fixed seed gives way to seeds derived from the study's seed
        (``--seed``), one per realisation.
        """
        count = args.realisations
        if count is None:
            return
        self.set(("analysis", index, "realisations"), count, "--realisations")
        if count > 1:
            for name in redrawn:
                self.document["topographies"][name].pop("seed", None)
            self.set(("study", "seed"), args.seed, "--seed")

    def material(self, prefix: str, args: argparse.Namespace, *, required: bool = False) -> str | None:
        """Return the study name of the material of ``--PREFIX`` options (None where none is given).

        A library name alone is used as it is; Young's modulus and Poisson's ratio make a
        ``[materials.PREFIX]`` table (overrides of the library entry when a name is also given).
        """
        name = getattr(args, prefix)
        overrides = {
            key: getattr(args, f"{prefix}_{key}")
            for key in ("youngs_modulus", "poissons_ratio")
            if getattr(args, f"{prefix}_{key}") is not None
        }
        flag = _flag(prefix)
        self.table_words[("materials", prefix)] = {"library": flag} | {
            key: f"{flag}-{key.replace('_', '-')}" for key in ("youngs_modulus", "poissons_ratio")
        }
        if name is None and not overrides:
            if required:
                raise InputError(flag, "no material given.", f"pass {flag} NAME or {flag}-youngs-modulus.")
            return None
        if not overrides:
            return name
        table = ({"library": name} if name is not None else {}) | overrides
        self.document["materials"][prefix] = table
        self.flags[("materials", prefix)] = flag
        for key in overrides:
            self.name_flag(("materials", prefix, key), f"{flag}-{key.replace('_', '-')}")
        self.words.setdefault("library", flag)
        return prefix

    def analysis(self, name: str, model: str, keys: dict[str, tuple[Any, str | None]]) -> int:
        """Add an analysis of ``model``; ``keys`` maps each key to (value, the option that gave it).

        A value of None is left out (the model's default). Returns the analysis' index.
        """
        index = len(self.document["analysis"])
        self.document["analysis"].append({"name": name, "model": model})
        self.flags[("analysis", index)] = name
        for key, (value, flag) in keys.items():
            if value is not None:
                self.set(("analysis", index, key), value, flag)
            elif flag is not None and flag.startswith("-"):
                self.words.setdefault(key, flag)  # named in messages even when not given
        return index

    def sweep(self, index: int, key: str, values: list, flag: str) -> None:
        """Sweep ``key`` of analysis ``index`` over ``values`` (one case each), given as ``flag``."""
        self.document["analysis"][index].setdefault("sweep", {})[key] = values
        self.name_flag(("analysis", index, "sweep", key), flag)
        self.name_flag(("analysis", index, key), flag)

    def zipped(self, index: int, axes: dict[str, tuple[list, str]]) -> None:
        """Take the lists of ``axes`` (key -> (values, option)) together: one case per position."""
        table = self.document["analysis"][index].setdefault("zip", {})
        for key, (values, flag) in axes.items():
            table[key] = values
            self.name_flag(("analysis", index, "zip", key), flag)
            self.name_flag(("analysis", index, key), flag)

    def compare(self, index: int, keys: dict[str, tuple[Any, str | None]]) -> None:
        """Add the ``[analysis.compare]`` table (measured data) to analysis ``index``."""
        table = self.document["analysis"][index].setdefault("compare", {})
        for key, (value, flag) in keys.items():
            if value is not None:
                table[key] = value
                if flag is not None:
                    self.name_flag(("analysis", index, "compare", key), flag)

    # --- validating and reporting problems in the command's terms ------------------------------

    def text(self) -> str:
        """Return the document as a study file (TOML), kept with the results (``run`` reruns it)."""
        import shlex

        import tomli_w

        document = {key: value for key, value in self.document.items() if value}
        return f"# written by: roughcontact {shlex.join(sys.argv[1:])}\n" + tomli_w.dumps(document)

    def build(self):
        """Validate the document and build its cases (:func:`roughcontact.study.config.build_study`).

        Raises
        ------
        InputError
            Every problem, each naming the option and the value as typed.
        """
        from ..study.config import StudyError, build_study

        try:
            return build_study(self.document, folder=Path.cwd(), text=self.text(), source=self.name)
        except StudyError as error:
            found = self.explain(error.problems)
            if len(found) == 1:
                raise InputError(*found[0]) from None
            lines = [
                f"{option}: {problem}" + (f" Fix: {fix}" if fix else "") for option, problem, fix in found
            ]
            raise InputError(self.name, f"{len(found)} problems:\n  " + "\n  ".join(lines)) from None

    def option_of(self, path: tuple) -> str | None:
        """Return the option that set the value at ``path``, else its key's option, else one above it.

        The key's option names a value that was not given (a missing ``--counter-surface-energy``).
        """
        if path in self.flags:
            return self.flags[path]
        if path and path[0] == "analysis" and str(path[-1]) in self.words:
            return self.words[str(path[-1])]
        for end in range(len(path) - 1, 0, -1):
            if path[:end] in self.flags:
                return self.flags[path[:end]]
        return None

    def name_of(self, key: str, path: tuple = ()) -> str | None:
        """Return the option that names ``key`` in this command's messages, None if it has none.

        The option the user typed it as (or the command gives it); at ``path`` (a problem's place)
        the words of its table first (a material's own options); else the command's option of
        that name (:meth:`RecordedOptions.option_for`). None: the command has no option for the
        key, and a message names it as the study key it is (:func:`roughcontact.messages.render`).
        """
        for end in range(len(path), 0, -1):
            if path[:end] in self.table_words and key in self.table_words[path[:end]]:
                return self.table_words[path[:end]][key]
        if key in self.words:
            return self.words[key]
        return self.options(key) if self.options is not None else None

    def render(self, text: str | None, path: tuple = ()) -> str | None:
        """Return a message with its marked keys named as this command's options (``--pressure``)."""
        return render(text, Door.CLI, lambda key: self.name_of(key, path))

    def explain(self, problems: Iterable) -> list[tuple[str, str, str | None]]:
        """Return (option, problem, fix) per problem, in the command's terms and the values as typed."""
        return [
            (
                self.option_of(p.path) or p.field,
                *p.said(Door.CLI, lambda key, path=p.path: self.name_of(key, path)),
            )
            for p in problems
        ]

    def input_error(self, error: InputError) -> InputError:
        """Return a model's refusal (named by its Python parameter) named by the option instead."""
        field, problem, fix = error.rendered(Door.CLI, self.name_of)
        return InputError(self.words.get(error.field, field), problem, fix)
