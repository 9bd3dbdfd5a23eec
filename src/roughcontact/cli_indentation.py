"""The ``nanoindent`` subcommand: Oliver-Pharr modulus with the viscous hold correction (paper 001 eqs. 5-8).

Added to the parser of :mod:`roughcontact.cli` by :func:`add_indentation_commands`; unit strings
are converted here and in :func:`~roughcontact.experiment.nanoindentation.read_indentation_csv`,
once, through :mod:`roughcontact.units`.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from ._json import json_ready
from .errors import InputError
from .units import format_si

# (key of IndentationResult.scalars(), label, SI unit for format_si)
_ROWS = (
    ("max_load", "F_max", "N"),
    ("max_depth", "d_max", "m"),
    ("stiffness", "S (apparent, power-law fit)", "N/m"),
    ("creep_rate", "creep rate at end of hold", "m/s"),
    ("unloading_rate", "unloading rate", "N/s"),
    ("corrected_stiffness", "S_e (eq. 5)", "N/m"),
    ("contact_depth", "d_c (eq. 7)", "m"),
    ("contact_area", "A_c", "m^2"),
    ("reduced_modulus", "E_r (eq. 6)", "Pa"),
    ("uncorrected_youngs_modulus", "E sample, uncorrected", "Pa"),
    ("youngs_modulus", "E sample (eq. 8)", "Pa"),
)


def _nanoindent(args: argparse.Namespace) -> int:
    from .experiment.nanoindentation import oliver_pharr, read_indentation_csv
    from .materials import get_material

    low, high = args.fit_range
    if not 0.0 <= low < high <= 1.0:
        raise InputError(
            "--fit-range", f"{low} {high} is not 0 <= LOW < HIGH <= 1.", "e.g. --fit-range 0.2 0.95."
        )
    curve = read_indentation_csv(
        args.file,
        depth_column=args.depth_column,
        load_column=args.load_column,
        time_column=args.time_column,
        depth_unit=args.depth_unit,
        load_unit=args.load_unit,
        time_unit=args.time_unit,
    )
    result = oliver_pharr(
        curve,
        indenter=get_material(args.indenter),
        poissons_ratio=args.poisson,
        epsilon=args.epsilon,
        beta=args.beta,
        fit_range=(low, high),
        rate_sign=args.rate_sign,
        creep_fit=args.creep_fit,
    )
    scalars = result.scalars()
    if args.plot is not None:
        from .plotting.indentation import plot_indentation

        fig, _ = plot_indentation(result)
        args.plot.parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(args.plot, dpi=args.dpi)
    if args.json:
        document = {"file": str(args.file), **scalars}
        if args.plot is not None:
            document["plot"] = str(args.plot)
        print(json.dumps(json_ready(document), indent=2))
        return 0
    per = "s" if result.time_basis == "time" else "sample"
    units = {"creep_rate": f"m/{per}", "unloading_rate": f"N/{per}"}
    print(
        f"{args.file}: Oliver-Pharr with viscous correction (paper 001 eqs. 5-8), rate sign "
        f"{args.rate_sign}, creep fit {args.creep_fit}, indenter {scalars['indenter']}, nu {args.poisson}"
    )
    width = max(len(label) for _, label, _ in _ROWS)
    for key, label, unit in _ROWS:
        value = scalars[key]
        if key == "contact_area":
            text = f"{value * 1e12:.4g} µm^2"
        elif key in units:
            text = format_si(value, units[key]) if per == "s" else f"{value:.4g} {units[key]}"
        else:
            text = format_si(value, unit)
        print(f"  {label:<{width}}  {text}")
    print(
        f"  {'power law alpha (d - d_f)^m':<{width}}  m = {result.unloading_fit.exponent:.3f}, "
        f"d_f = {format_si(result.unloading_fit.final_depth, 'm')}, fitted on {low:.0%}-{high:.0%} of F_max "
        f"({result.unloading_fit.points} points)"
    )
    if args.plot is not None:
        print(f"wrote {args.plot}")
    return 0


def add_indentation_commands(commands) -> None:
    """Add the ``nanoindent`` subcommand to the CLI's subparsers."""
    from .experiment.nanoindentation import CREEP_FITS, RATE_SIGNS

    nanoindent = commands.add_parser(
        "nanoindent",
        help="sample modulus from a load-displacement CSV: Oliver-Pharr with the hold-creep correction",
        description="Oliver-Pharr analysis with Tang-Ngan's viscous correction as in seed paper 001 "
        "eqs. 5-8: power law fitted to the upper unloading curve, creep rate from the hold at maximum "
        "load, unloading rate from the onset of unloading, ideal Berkovich area 24.5 d_c^2. Columns are "
        "found by name (depth/displacement, load/force, time) with units in the header, e.g. "
        "'depth (nm)', or given with the options.",
    )
    nanoindent.add_argument("file", type=Path, help="CSV with depth, load and (optional) time columns")
    nanoindent.add_argument("--depth-column", help="header of the depth column (default: auto-detect)")
    nanoindent.add_argument("--load-column", help="header of the load column (default: auto-detect)")
    nanoindent.add_argument("--time-column", help="header of the time column (default: auto-detect)")
    nanoindent.add_argument("--depth-unit", help="unit of the depth column, e.g. nm (overrides the header)")
    nanoindent.add_argument("--load-unit", help="unit of the load column, e.g. mN (overrides the header)")
    nanoindent.add_argument("--time-unit", help="unit of the time column, e.g. s (overrides the header)")
    nanoindent.add_argument(
        "--indenter",
        default="diamond berkovich",
        help="library material of the tip (default: 1141 GPa, 0.07)",
    )
    nanoindent.add_argument("--poisson", type=float, default=0.5, help="sample Poisson's ratio (default 0.5)")
    nanoindent.add_argument("--epsilon", type=float, default=0.75, help="eq. 7's geometric constant")
    nanoindent.add_argument("--beta", type=float, default=1.0, help="tip-shape factor of eq. 6 (default 1)")
    nanoindent.add_argument(
        "--fit-range", type=float, nargs=2, default=(0.2, 0.95), metavar=("LOW", "HIGH"),
        help="fractions of F_max between which the unloading power law is fitted (default 0.2 0.95)",
    )  # fmt: skip
    nanoindent.add_argument(
        "--rate-sign", choices=RATE_SIGNS, default="magnitude",
        help="eq. 5 with |F_dot| (default) or the paper's printed signed F_dot (raises the modulus)",
    )  # fmt: skip
    nanoindent.add_argument(
        "--creep-fit", choices=CREEP_FITS, default="tang_ngan",
        help="end-of-hold creep rate: t^(1/3) hold law (default), a line on the last 20%%, or none",
    )  # fmt: skip
    nanoindent.add_argument(
        "--plot", type=Path, help="figure of the curve, fit and tangent (.png, .pdf, .svg)"
    )
    nanoindent.add_argument("--dpi", type=int, default=150)
    nanoindent.add_argument("--json", action="store_true", help="print one JSON document (SI)")
    nanoindent.set_defaults(handler=_nanoindent)
