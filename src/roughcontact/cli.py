"""Command line: ``roughcontact inspect | plot | contact | demo | friction | asperity | presliding | ...``.

The edges of the program live here: unit strings from the user are converted once
(through :mod:`roughcontact.units`), errors are turned into one readable line and an exit
status, and logging is configured (only here).
"""

from __future__ import annotations

import argparse
import json
import logging
import sys
from collections.abc import Sequence
from pathlib import Path

from . import __version__
from ._json import json_ready
from .errors import ConvergenceError, InputError
from .topography import Topography
from .units import format_si

log = logging.getLogger("roughcontact")

EXIT_INPUT_ERROR = 2
EXIT_NOT_CONVERGED = 3

# statistic -> (SI unit for display, description)
_STATISTICS = {
    "Ra": ("m", "arithmetic mean deviation"),
    "Rq": ("m", "root mean square height"),
    "Rsk": ("", "skewness"),
    "Rku": ("", "kurtosis"),
    "Rz": ("m", "peak-to-valley height"),
    "rms_slope": ("", "rms slope"),
    "rms_curvature": ("1/m", "rms curvature"),
    "m0": ("m^2", "spectral moment m0 (paper 002 eq. 1)"),
    "m2": ("", "spectral moment m2 (eq. 2)"),
    "m4": ("1/m^2", "spectral moment m4 (eq. 3)"),
    "bandwidth": ("", "bandwidth parameter alpha = m0 m4 / m2^2"),
    "summit_density": ("1/m^2", "summit density eta (McCool)"),
    "summit_radius": ("m", "summit radius R_asp (eq. 4)"),
    "summit_height_std": ("m", "summit height deviation sigma_s (eq. 5)"),
}


def _size_argument(text: str) -> tuple[str, ...]:
    """Split ``"10 um"``, ``"10 um x 20 um"`` or ``"10um,20um"`` into one string per axis."""
    parts = [p.strip() for p in text.replace(",", " x ").split(" x ") if p.strip()]
    if not 1 <= len(parts) <= 2:
        raise argparse.ArgumentTypeError(f"cannot read size {text!r}; write '10 um' or '10 um x 20 um'")
    return tuple(parts)


def _channel_argument(text: str) -> int | str:
    return int(text) if text.isdigit() else text


def _read_options(file_required: bool = True) -> argparse.ArgumentParser:
    parent = argparse.ArgumentParser(add_help=False)
    group = parent.add_argument_group("reading the file")
    group.add_argument(
        "file",
        type=Path,
        nargs=None if file_required else "?",
        help="instrument file (any format SurfaceTopography reads) or .nc",
    )
    group.add_argument(
        "--channel", type=_channel_argument, help="channel name or index (default: the file's)"
    )
    group.add_argument(
        "--size",
        type=_size_argument,
        help="physical scan size where the file lacks it, e.g. '5 um' or '5 um x 10 um'",
    )
    group.add_argument("--height-unit", help="unit of the stored heights where the file lacks it, e.g. nm")
    group.add_argument(
        "--fill-undefined",
        action="store_true",
        help="interpolate undefined (missing) points instead of refusing the file",
    )
    group.add_argument("--periodic", action="store_true", help="treat the surface as periodic")
    return parent


def _read(args: argparse.Namespace) -> Topography:
    from .topography.io import read_topography

    size = args.size if args.size is None or len(args.size) > 1 else args.size[0]
    return read_topography(
        args.file,
        channel=args.channel,
        size=size,
        height_unit=args.height_unit,
        undefined="interpolate" if args.fill_undefined else "refuse",
        periodic=args.periodic,
    )


def describe(topography: Topography) -> dict:
    """Return grid, size, units and statistics of a topography as a JSON-ready dictionary (SI)."""
    from .topography.statistics import summary

    return {
        "name": topography.info.get("name") or topography.info.get("source"),
        "grid": list(topography.shape),
        "size_m": list(topography.size),
        "spacing_m": list(topography.spacing),
        "periodic": topography.periodic,
        "height_unit_in_file": topography.info.get("height_unit"),
        "undefined_points_filled": topography.info.get("undefined_points_filled", 0),
        "statistics": summary(topography),
    }


def format_description(description: dict) -> str:
    """Render :func:`describe` output as an aligned text table with SI-prefixed units."""
    size = " x ".join(format_si(s, "m") for s in description["size_m"])
    spacing = " x ".join(format_si(s, "m") for s in description["spacing_m"])
    lines = [
        f"surface        {description['name']}",
        f"grid           {' x '.join(str(n) for n in description['grid'])} points",
        f"physical size  {size}  (pixel {spacing})",
        f"periodic       {description['periodic']}",
    ]
    if description["height_unit_in_file"]:
        lines.append(f"height unit    {description['height_unit_in_file']} in the file, metres here")
    if description["undefined_points_filled"]:
        lines.append(
            f"undefined      {description['undefined_points_filled']} points filled by interpolation"
        )
    lines.append("statistics")
    for key, value in description["statistics"].items():
        unit, meaning = _STATISTICS.get(key, ("", ""))
        shown = format_si(value, unit) if unit in ("m",) else f"{value:.4g} {unit}".rstrip()
        lines.append(f"  {key:<18} {shown:<16} {meaning}")
    return "\n".join(lines)


def _inspect(args: argparse.Namespace) -> int:
    from .topography.io import list_channels

    channels = list_channels(args.file)
    topography = _read(args)
    description = describe(topography)
    description["file"] = str(args.file)
    description["format"] = topography.info.get("file_format")
    description["channels"] = [
        {
            "index": c.index,
            "name": c.name,
            "grid": list(c.shape),
            "size_m": None if c.size is None else list(c.size),
            "height_unit": c.height_unit,
            "default": c.is_default,
        }
        for c in channels
    ]
    if args.json:
        print(json.dumps(json_ready(description), indent=2))
        return 0
    print(f"file           {args.file}  ({description['format']})")
    print("channels")
    for c in channels:
        size = "size not in file" if c.size is None else " x ".join(format_si(s, "m") for s in c.size)
        marker = "*" if c.is_default else " "
        grid = " x ".join(str(n) for n in c.shape)
        print(f" {marker}{c.index:>2}  {c.name:<24} {grid:<12} {size:<24} heights in {c.height_unit or '?'}")
    print(format_description(description))
    return 0


def _plot(args: argparse.Namespace) -> int:
    from .plotting import plot_overview

    if args.file.is_dir():
        from .cli_study import plot_study

        return plot_study(args.file)
    if args.output is None:
        raise InputError("-o/--output", "no figure file given.", "add -o FIGURE.png.")
    topography = _read(args)
    figure = plot_overview(topography)
    args.output.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(args.output, dpi=args.dpi)
    print(f"wrote {args.output}")
    return 0


def _add_material_options(parser: argparse.ArgumentParser, body: str, counter: str, names: str) -> None:
    """Add ``--material``/``--counter`` options: a library name, or Young's modulus and Poisson's ratio."""
    for prefix, what in (("material", body), ("counter", counter)):
        parser.add_argument(f"--{prefix}", help=f"library material of {what}, e.g. {names}")
        parser.add_argument(f"--{prefix}-youngs-modulus", help=f"Young's modulus of {what}, e.g. '70 GPa'")
        parser.add_argument(f"--{prefix}-poissons-ratio", type=float, help=f"Poisson's ratio of {what}")


def _material(args: argparse.Namespace, prefix: str, *, required: bool = False):
    """Return the material of ``--PREFIX`` (library name) or ``--PREFIX-youngs-modulus``, or None."""
    from .materials import Material, get_material

    name = getattr(args, prefix)
    modulus = getattr(args, f"{prefix}_youngs_modulus")
    if name is not None and modulus is not None:
        raise InputError(f"--{prefix}", "both a library name and a Young's modulus were given.", "give one.")
    if name is not None:
        return get_material(name)
    if modulus is None:
        if required:
            raise InputError(
                f"--{prefix}", "no material given.", f"pass --{prefix} NAME or --{prefix}-youngs-modulus."
            )
        return None
    ratio = getattr(args, f"{prefix}_poissons_ratio")
    if ratio is None:
        raise InputError(
            f"--{prefix}-poissons-ratio",
            "missing.",
            f"add --{prefix}-poissons-ratio with the Young's modulus.",
        )
    return Material.from_units(youngs_modulus=modulus, poissons_ratio=ratio, name=prefix)


def _contact(args: argparse.Namespace) -> int:
    from .contact import solve_normal
    from .plotting import plot_contact_overview
    from .units import quantity

    material = _material(args, "material", required=True)
    counter = _material(args, "counter")
    targets = {
        "mean_pressure": None
        if args.pressure is None
        else quantity(args.pressure, "pressure", field="--pressure"),
        "force": None if args.force is None else quantity(args.force, "force", field="--force"),
        "approach": None if args.approach is None else quantity(args.approach, "length", field="--approach"),
    }
    hardness = None if args.hardness is None else quantity(args.hardness, "pressure", field="--hardness")
    topography = _read(args)
    result = solve_normal(
        topography,
        material,
        counter_body=counter,
        hardness=hardness,
        boundary=args.boundary,
        tolerance=args.tolerance,
        **targets,
    )
    scalars = result.scalars()
    if args.output is not None:
        args.output.mkdir(parents=True, exist_ok=True)
        result.to_xarray().to_netcdf(args.output / "contact.nc", engine="h5netcdf")
        if topography.dim == 2:
            plot_contact_overview(result).savefig(args.output / "contact.png", dpi=args.dpi)
    if args.json:
        scalars["contact_modulus"] = result.contact_modulus
        print(json.dumps(json_ready(scalars), indent=2))
        return 0
    units = {"force": "N", "mean_pressure": "Pa", "approach": "m", "contact_area": "m^2", "mean_gap": "m"}
    units["max_pressure"] = "Pa"
    print(
        f"contact of {args.file} ({material.name} against {counter.name if counter else 'a rigid flat'}, "
        f"E* {format_si(result.contact_modulus, 'Pa')}, {result.boundary} boundary)"
    )
    for key, value in scalars.items():
        unit = units.get(key, "")
        shown = format_si(value, unit) if unit in ("m", "N", "Pa") else f"{value:.4g} {unit}".rstrip()
        print(f"  {key:<18} {shown}")
    if args.output is not None:
        print(f"wrote {args.output / 'contact.nc'}" + (" and contact.png" if topography.dim == 2 else ""))
    return 0


def _demo(args: argparse.Namespace) -> int:
    from .cli_study import demo_study, run_and_report
    from .study import load_study

    path = demo_study()
    study = load_study(path)
    print(f"demo study {study.name!r}: {len(study.cases)} cases ({path})")
    return run_and_report(study, args.output, progress=sys.stderr.isatty(), resume=True)


def build_parser() -> argparse.ArgumentParser:
    """Return the argument parser of the ``roughcontact`` command."""
    parser = argparse.ArgumentParser(
        prog="roughcontact",
        description="Contact mechanics of rough surfaces from measured topographies.",
    )
    parser.add_argument("--version", action="version", version=f"roughcontact {__version__}")
    parser.add_argument("-v", "--verbose", action="count", default=0, help="more log output (-vv for debug)")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    inspect = commands.add_parser(
        "inspect",
        parents=[_read_options()],
        help="print channels, grid, physical size, units and statistics of a file",
    )
    inspect.add_argument("--json", action="store_true", help="print one JSON document (SI units)")
    inspect.set_defaults(handler=_inspect)

    plot = commands.add_parser(
        "plot",
        parents=[_read_options()],
        help="draw the height map and PSD of a file, or re-draw a study's figures (plot OUT/)",
        description="FILE a topography: draw its height map and PSD into -o. FILE a study's output "
        "folder: re-draw its figures and tables from the stored results (nothing is solved again).",
    )
    plot.add_argument("-o", "--output", type=Path, help="figure file (.png, .pdf, .svg) for a topography")
    plot.add_argument("--dpi", type=int, default=150)
    plot.set_defaults(handler=_plot)

    contact = commands.add_parser(
        "contact",
        parents=[_read_options()],
        help="solve the normal contact of a file's surface against a flat",
        description="Elastic (or elastic-perfectly-plastic with --hardness) normal contact of the surface "
        "against a flat. Give exactly one of --pressure, --force, --approach, with units.",
    )
    _add_material_options(
        contact, "the surface's body", "the flat (default: rigid)", "SU-8, polysilicon, SiO2"
    )
    contact.add_argument("--pressure", help="nominal mean pressure, e.g. '20 MPa'")
    contact.add_argument("--force", help="total force, e.g. '10 uN'")
    contact.add_argument("--approach", help="rigid approach from the first touch, e.g. '5 nm'")
    contact.add_argument("--hardness", help="cap the pressure (elastic-perfectly-plastic), e.g. '0.46 GPa'")
    contact.add_argument("--boundary", choices=("periodic", "free"), help="default: free unless --periodic")
    contact.add_argument("--tolerance", type=float, default=1e-8, help="scale-free residual (default 1e-8)")
    contact.add_argument("-o", "--output", type=Path, help="folder for contact.nc and contact.png")
    contact.add_argument("--dpi", type=int, default=150)
    contact.add_argument("--json", action="store_true", help="print the scalars as JSON (SI)")
    contact.set_defaults(handler=_contact)

    demo = commands.add_parser(
        "demo", help="run the embedded demo study (examples/demo.toml) and write its report"
    )
    demo.add_argument("-o", "--output", type=Path, default=Path("demo-output"), help="output folder")
    demo.set_defaults(handler=_demo)

    from .cli_study import add_study_commands

    add_study_commands(commands)
    from .cli_friction import add_friction_commands

    add_friction_commands(commands)
    from .cli_asperity import add_asperity_commands

    add_asperity_commands(commands)
    from .cli_indentation import add_indentation_commands

    add_indentation_commands(commands)
    from .cli_presliding import add_presliding_commands

    add_presliding_commands(commands)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the ``roughcontact`` command; return its exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    level = (logging.WARNING, logging.INFO, logging.DEBUG)[min(args.verbose, 2)]
    logging.basicConfig(level=level, format="%(levelname)s %(name)s: %(message)s")
    try:
        return args.handler(args)
    except InputError as error:
        print(f"roughcontact: error: {error}", file=sys.stderr)
        return EXIT_INPUT_ERROR
    except ConvergenceError as error:
        print(f"roughcontact: error: {error}", file=sys.stderr)
        return EXIT_NOT_CONVERGED


if __name__ == "__main__":
    sys.exit(main())
