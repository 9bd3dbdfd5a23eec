"""The ``inspect`` and ``plot`` commands: what a topography file holds, and its height map and PSD.

``plot`` given a study's output folder re-draws the study's figures instead (:mod:`.study`).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from .._files import not_a_folder
from .._json import json_ready
from ..errors import InputError
from ..topography import Topography
from ..topography.io import MAX_FILLED, channel_of, channel_words, max_filled_allowing
from ..topography.plausible import doubts, is_flat, size_doubt
from ..topography.process import LEVELLING, SPECK
from ..units import format_si
from .options import dpi_argument, new_command, read_file, refuse_unused

COMMANDS = {
    "inspect": "print channels, grid, physical size, units and statistics of a file",
    "plot": "draw the height map and PSD of a file, or re-draw a study's figures (plot OUT/)",
}
"""This module's commands and their lines in ``roughcontact --help``."""


FILLED_AS_READ = "inspect and plot describe the heights as read (filled points included)"
"""Why ``--exclude-filled`` (which acts in the contact models) is refused by ``inspect`` and ``plot``."""


def describe(topography: Topography, undefined=None) -> dict:
    """Return grid, size, units and statistics of a topography as a JSON-ready dictionary (SI).

    ``statistics`` holds the numbers in SI and ``statistics_units`` the SI unit of each (``"m"``,
    ``"1/m^2"``; ``""`` for a dimensionless one), so every statistic carries its unit while
    ``statistics`` stays a mapping of names to numbers. With ``undefined`` (the file's points
    without a height, not filled) the statistics are left out (they need every point) and the
    undefined points are described instead: how many, the fraction, their bounding box [m] and
    how many separate regions they form. ``flat`` says whether the surface is flat
    (:func:`~roughcontact.topography.plausible.is_flat`) and ``notes`` what is implausible about it
    (:func:`~roughcontact.topography.plausible.doubts`, in the options' words), as printed.
    """
    from scipy import ndimage

    from ..topography.statistics import SUMMARY, summary

    description = {
        "name": topography.info.get("name") or topography.info.get("source"),
        "channel": channel_of(topography.info),
        "grid": list(topography.shape),
        "size_m": list(topography.size),
        "spacing_m": list(topography.spacing),
        "periodic": topography.periodic,
        "height_unit_in_file": topography.info.get("height_unit"),
        "undefined_points_filled": topography.info.get("undefined_points_filled", 0),
        "specks": 0 if topography.specks is None else int(np.count_nonzero(topography.specks)),
        "specks_removed": topography.info.get("specks_removed", 0),
        "flat": undefined is None and is_flat(topography.heights),
        "notes": _doubts(topography, undefined),
    }
    if undefined is None:
        statistics = summary(topography)
        units = {key: SUMMARY[key][0] for key in statistics}
        return description | {"statistics": statistics, "statistics_units": units}
    where = np.nonzero(undefined)
    description["undefined"] = {
        "count": int(np.count_nonzero(undefined)),
        "fraction": float(np.count_nonzero(undefined) / undefined.size),
        "regions": int(ndimage.label(undefined)[1]),
        "from_m": [float(index.min() * step) for index, step in zip(where, topography.spacing, strict=True)],
        "to_m": [
            float((index.max() + 1) * step) for index, step in zip(where, topography.spacing, strict=True)
        ],
    }
    return description


def format_description(description: dict) -> str:
    """Render :func:`describe` output as an aligned text table with SI-prefixed units."""
    from ..study.display import shown
    from ..topography.statistics import SUMMARY

    size = " x ".join(format_si(s, "m") for s in description["size_m"])
    spacing = " x ".join(format_si(s, "m") for s in description["spacing_m"])
    lines = [f"surface        {description['name']}"]
    if description.get("channel"):
        lines.append(f"channel        {channel_words(description['channel'])}")
    lines += [
        f"grid           {' x '.join(str(n) for n in description['grid'])} points",
        f"physical size  {size}  (pixel {spacing})",
        f"periodic       {description['periodic']}",
    ]
    if description["height_unit_in_file"]:
        lines.append(f"height unit    {description['height_unit_in_file']} in the file, metres here")
    total = int(np.prod(description["grid"]))
    if description["undefined_points_filled"]:
        filled = description["undefined_points_filled"]
        lines.append(f"undefined      {filled} points ({100 * filled / total:.3g} %) filled by interpolation")
    undefined = description.get("undefined")
    if undefined:
        box = " x ".join(
            f"{format_si(a, 'm')}-{format_si(b, 'm')}"
            for a, b in zip(undefined["from_m"], undefined["to_m"], strict=True)
        )
        lines += [
            f"undefined      {undefined['count']} of {total} points ({100 * undefined['fraction']:.3g} %) in "
            f"{undefined['regions']} region(s) within {box}",
            "statistics     need every point: add --fill-undefined"
            + (
                f" --max-filled {max_filled_allowing(undefined['fraction']):g}"
                if undefined["fraction"] > MAX_FILLED
                else ""
            )
            + " to fill them, or see where they are with: roughcontact plot FILE -o FIGURE.png",
        ]
    if description.get("specks"):
        lines.append(
            f"specks         {description['specks']} measured points in groups of fewer than {SPECK} amid "
            "undefined ones (often outliers; a contact on them is flagged): --remove-specks makes them "
            "undefined before filling"
        )
    if description.get("specks_removed"):
        lines.append(
            f"specks         {description['specks_removed']} removed (made undefined before filling)"
        )
    if "detrend" in description:
        lines.append(f"levelling      {LEVELLING[description['detrend']]}")
    if description.get("flat"):
        lines.append(
            "flat           yes: no roughness (statistics 0, no summits); a contact is the flat punch's"
        )
    if "statistics" in description:
        lines.append("statistics")
    for key, value in description.get("statistics", {}).items():
        unit, meaning = SUMMARY.get(key, ("", ""))
        lines.append(f"  {key:<18} {shown(value, unit):<16} {meaning}")
    return "\n".join(lines)


def _inspect(args: argparse.Namespace) -> int:
    from ..topography.io import list_channels

    channels = list_channels(args.file)
    topography, undefined = read_file(args)
    as_json = args.json
    args.taking(FILLED_AS_READ, "use it with a contact command", options=("exclude_filled",))
    refuse_unused(args)
    description = describe(topography, undefined)
    _notes(description["notes"], args.file)
    description["file"] = str(args.file)
    description["detrend"] = topography.info["detrend"]
    description["format"] = topography.info.get("file_format")
    description["channels"] = [
        {
            "index": c.index,
            "name": c.name,
            "grid": list(c.shape),
            "size_m": None if c.size is None else list(c.size),
            "height_unit": c.height_unit,
            "default": c.is_default,
            "holds_heights": c.is_height,
            "holds": c.holds or "heights",
        }
        for c in channels
    ]
    if as_json:
        print(json.dumps(json_ready(description), indent=2))
        return 0
    print(f"file           {args.file}  ({description['format']})")
    print("channels")
    for c in channels:
        size = "size not in file" if c.size is None else " x ".join(format_si(s, "m") for s in c.size)
        marker = "*" if c.is_default else " "
        grid = " x ".join(str(n) for n in c.shape)
        holds = f"heights in {c.height_unit or '?'}" if c.is_height else f"not heights: {c.holds}"
        print(f" {marker}{c.index:>2}  {c.name:<24} {grid:<12} {size:<24} {holds}")
    print(format_description(description))
    return 0


def _doubts(topography: Topography, undefined) -> list[str]:
    """Return what is implausible about FILE's surface, in the options' words (with ``undefined``: its size).

    With undefined points left unfilled the heights hold placeholders, so only the size is judged.
    """
    found = doubts(topography) if undefined is None else (size_doubt(topography.size),)
    return [doubt.said("cli") for doubt in found if doubt is not None]


def _notes(notes: list[str], file: Path) -> None:
    """Print what is implausible about FILE's surface, one note a line on stderr (as the models' commands)."""
    for note in notes:
        print(f"roughcontact: note: {file.name}: {note}", file=sys.stderr)


def _check_figure_file(path: Path, overwrite: bool) -> None:
    """Refuse, before drawing, a figure file matplotlib cannot write or one that would be replaced."""
    from matplotlib.backend_bases import FigureCanvasBase

    formats = FigureCanvasBase.get_supported_filetypes()
    suffix = path.suffix.lower().lstrip(".")
    if suffix not in formats:
        said = f"ends in .{suffix}, which is not a figure format" if suffix else "has no file extension"
        raise InputError(
            "-o/--output",
            f"{path} {said}.",
            "name the figure file with one of "
            + ", ".join(f".{f}" for f in ("png", "pdf", "svg", "eps", "tif"))
            + f" (all: {', '.join(sorted(formats))}).",
        )
    if path.is_dir():
        raise InputError("-o/--output", f"{path} is a folder.", "give a figure file, e.g. -o scan.png.")
    if path.exists() and not overwrite:
        raise InputError("-o/--output", f"{path} exists.", "choose another name, or add --overwrite.")
    problem = not_a_folder(path.parent)
    if problem:
        raise InputError("-o/--output", problem, "give the figure file a path in a folder.")


def _plot(args: argparse.Namespace) -> int:
    from ..plotting import plot_overview

    if args.file.is_dir():
        from .study import plot_study

        args.taking("a study's folder is redrawn as its study file says", "give a topography file instead")
        refuse_unused(args)
        return plot_study(args.file)
    if args.output is None:
        raise InputError("-o/--output", "no figure file given.", "add -o FIGURE.png.")
    _check_figure_file(args.output, args.overwrite)
    topography, undefined = read_file(args)
    dpi = args.dpi
    args.taking(FILLED_AS_READ, "use it with a contact command", options=("exclude_filled",))
    refuse_unused(args)
    _notes(_doubts(topography, undefined), args.file)
    figure = plot_overview(topography, undefined=undefined)
    args.output.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(args.output, dpi=dpi)
    print(f"wrote {args.output}")
    return 0


def add_commands(commands) -> None:
    """Add ``inspect`` and ``plot`` to the subparsers ``commands``."""
    inspect = new_command(
        commands,
        "inspect",
        _inspect,
        COMMANDS["inspect"],
        file=True,
    )
    inspect.add_argument("--json", action="store_true", help="print one JSON document (SI units)")

    plot = new_command(
        commands,
        "plot",
        _plot,
        COMMANDS["plot"],
        "FILE a topography: draw its height map and PSD into -o. FILE a study's output "
        "folder: re-draw its figures and tables from the stored results (nothing is solved again).",
        file=True,
    )
    plot.add_argument("-o", "--output", type=Path, help="figure file (.png, .pdf, .svg) for a topography")
    plot.add_argument("--dpi", type=dpi_argument, default=150, help="resolution of the figure (default 150)")
    plot.add_argument("--overwrite", action="store_true", help="replace an existing figure file")
