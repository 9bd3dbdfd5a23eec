"""The ``friction`` and ``friction-compare`` subcommands (paper 000's Winkler-Lennard-Jones model).

Added to the parser of :mod:`roughcontact.cli` by :func:`add_friction_commands`; unit strings are
converted here, once, through :mod:`roughcontact.units`.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from ._json import json_ready
from .cli import _add_material_options, _material, _read, _read_options, _size_argument
from .friction.winkler_lj import WinklerLJResult
from .units import format_si, quantity


def _model_options(args: argparse.Namespace) -> dict:
    from .friction import Readings
    from .friction.viscoelastic import standard_linear_solid

    options = {
        "layer_thickness": quantity(args.layer_thickness, "length", field="--layer-thickness"),
        "epsilon": quantity(args.epsilon, "length", field="--epsilon"),
        "readings": Readings.from_strings(args.reading),
        "resample": args.resample,
    }
    for name in ("surface_energy", "counter_surface_energy"):
        value = getattr(args, name)
        if value is not None:
            options[name] = quantity(value, "surface_energy", field=f"--{name.replace('_', '-')}")
    if args.relaxed_modulus is not None:
        relaxed = quantity(args.relaxed_modulus, "pressure", field="--relaxed-modulus")
        tau = quantity(args.relaxation_time, "time", field="--relaxation-time")
        material = _material(args, "material", required=True)
        options["relaxation"] = standard_linear_solid(material.youngs_modulus, relaxed, tau)
        options["hold_time"] = quantity(args.hold_time, "time", field="--hold-time")
    return options


def _print_scalars(title: str, scalars: dict) -> None:
    print(title)
    for key, value in scalars.items():
        unit = WinklerLJResult.UNITS.get(key, "")
        shown = format_si(value, unit) if unit else f"{value:.6g}"
        print(f"  {key:<24} {shown}")


def _friction(args: argparse.Namespace) -> int:
    from .friction import winkler_lj_model
    from .topography.io import read_topography

    material = _material(args, "material", required=True)
    counter = _material(args, "counter")
    counter_surface = None
    if args.counter_file is not None:
        size = args.size if args.size is None or len(args.size) > 1 else args.size[0]
        counter_surface = read_topography(args.counter_file, size=size, height_unit=args.height_unit)
    model = winkler_lj_model(
        _read(args), material, counter, counter_surface=counter_surface, **_model_options(args)
    )
    loads = [quantity(text, "force", field="--loads") for text in args.loads or [args.load]]
    result = model.solve(loads[0])
    document = {"scalars": result.scalars(), "parameters": result.parameters | {"readings": None}}
    document["readings"] = vars(model.readings)
    sweep = model.sweep(loads) if len(loads) > 1 else None
    crossover = model.crossover_load() if args.crossover else None
    if sweep is not None:
        document["sweep"] = {
            k: getattr(sweep, k).tolist()
            for k in ("load", "friction", "adhesive_friction", "mechanical_friction", "mu")
        }
    if args.crossover:
        document["crossover_load"] = crossover
    if args.output is not None:
        args.output.mkdir(parents=True, exist_ok=True)
        result.to_xarray().to_netcdf(args.output / "friction.nc", engine="h5netcdf")
        if sweep is not None:
            from .plotting import plot_friction_vs_load

            sweep.to_xarray().to_netcdf(args.output / "friction_sweep.nc", engine="h5netcdf")
            figure, _ = plot_friction_vs_load(sweep, crossover=crossover)
            figure.savefig(args.output / "friction_vs_load.png", dpi=args.dpi)
    if args.json:
        print(json.dumps(json_ready(document), indent=2))
        return 0
    changed = model.readings.changed()
    _print_scalars(
        f"friction of {args.file} against {args.counter_file or 'a flat'} "
        f"({material.name} / {counter.name if counter else 'rigid'}; readings: {changed or 'defaults'})",
        result.scalars(),
    )
    if sweep is not None:
        print(f"  {'load':>12} {'mu':>10} {'adhesive':>12} {'mechanical':>12}")
        for load, mu, adhesive, mechanical in zip(
            sweep.load, sweep.mu, sweep.adhesive_friction, sweep.mechanical_friction, strict=True
        ):
            print(
                f"  {format_si(load, 'N'):>12} {mu:>10.4g} {format_si(adhesive, 'N'):>12} "
                f"{format_si(mechanical, 'N'):>12}"
            )
    if args.crossover:
        shown = "none in the load range the layer carries" if crossover is None else format_si(crossover, "N")
        print(f"  crossover load (mechanical = adhesive friction): {shown}")
    if args.output is not None:
        print(f"wrote {args.output}")
    return 0


def _sample_argument(text: str) -> tuple[str, list[Path]]:
    name, separator, files = text.partition("=")
    if not separator or not files:
        raise argparse.ArgumentTypeError(f"cannot read {text!r}; write NAME=scan1.di,scan2.di,...")
    return name.strip(), [Path(f) for f in files.split(",") if f]


def _friction_compare(args: argparse.Namespace) -> int:
    from .experiment import compare, paper000_model_options, paper000_simulation, read_measured, simulate_mu
    from .friction import Readings
    from .materials import get_material
    from .topography.io import read_topography

    readings = Readings.from_strings(args.reading)
    load = quantity(args.load, "force", field="--load")
    energy = quantity(args.surface_energy, "surface_energy", field="--surface-energy")
    measured = read_measured(args.measured)
    if args.sample:
        size = args.size if args.size is None or len(args.size) > 1 else args.size[0]

        def read(path: Path):
            return read_topography(path, size=size, height_unit=args.height_unit)

        scans = {name: [read(p) for p in files] for name, files in args.sample}
        tip = read(args.tip) if args.tip is not None else None
        simulated = simulate_mu(
            scans,
            get_material(args.material),
            get_material(args.counter),
            load=load,
            counter_surface=tip,
            **paper000_model_options(surface_energy=energy, readings=readings),
        )
    else:
        simulated = paper000_simulation(load=load, surface_energy=energy, readings=readings, seed=args.seed)
    comparison = compare(simulated, measured, alpha=args.alpha, equal_var=args.equal_var)
    if args.output is not None:
        from .plotting import plot_mu_boxes, plot_mu_means

        args.output.mkdir(parents=True, exist_ok=True)
        plot_mu_boxes(comparison)[0].savefig(args.output / "mu_boxes.png", dpi=args.dpi)
        plot_mu_means(comparison)[0].savefig(args.output / "mu_means.png", dpi=args.dpi)
    if args.json:
        document = {
            "samples": comparison.table(),
            "pearson_r": comparison.pearson_r,
            "pearson_p": comparison.pearson_p,
            "alpha": comparison.alpha,
        }
        print(json.dumps(json_ready(document), indent=2))
        return 0
    source = "measured scans" if args.sample else "synthetic scans (paper 000 case, seeded)"
    print(f"simulated ({source}) vs measured ({args.measured}), t-test threshold p > {args.alpha}")
    print(f"  {'sample':<14} {'sim mean':>9} {'sim sd':>8} {'meas mean':>9} {'meas sd':>8} {'p':>7}  agrees")
    for row in comparison.table():
        print(
            f"  {row['sample']:<14} {row['simulated_mean']:>9.4g} {row['simulated_std']:>8.2g} "
            f"{row['measured_mean']:>9.4g} {row['measured_std']:>8.2g} {row['p_value']:>7.3g}  "
            f"{row['agrees']}"
        )
    print(f"  Pearson r of the means: {comparison.pearson_r:.3f} (p = {comparison.pearson_p:.3g})")
    if args.output is not None:
        print(f"wrote {args.output / 'mu_boxes.png'} and mu_means.png")
    return 0


def _common_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--reading",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="reading of a disputed equation of paper 000, e.g. contact=zero_gap (see docs/winkler_lj.md)",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON document (SI)")
    parser.add_argument("-o", "--output", type=Path, help="folder for the results and figures")
    parser.add_argument("--dpi", type=int, default=150)


def add_friction_commands(commands) -> None:
    """Add ``friction`` and ``friction-compare`` to the subparsers ``commands`` of the CLI."""
    friction = commands.add_parser(
        "friction",
        parents=[_read_options()],
        help="adhesive + mechanical friction of a surface (Winkler layer + Lennard-Jones, paper 000)",
        description="Friction of FILE (merged with COUNTER_FILE if given) against a flat at --load, or over "
        "--loads, with the adhesive and mechanical parts and mu = F / N.",
    )
    friction.add_argument("counter_file", nargs="?", type=Path, help="topography of the counter-body (tip)")
    _add_material_options(
        friction, "the surface's body", "the counter-body (default: rigid)", "polysilicon, SiO2"
    )
    friction.add_argument("--surface-energy", help="surface energy of the surface, e.g. '50 mJ/m^2'")
    friction.add_argument(
        "--counter-surface-energy", help="surface energy of the counter-body (default: the library's)"
    )
    friction.add_argument("--load", default="10 uN", help="normal load (default 10 uN)")
    friction.add_argument("--loads", nargs="+", help="several loads: a sweep, e.g. '1 uN' '10 uN' '100 uN'")
    friction.add_argument(
        "--crossover",
        action="store_true",
        help="find the load where mechanical friction overtakes adhesive friction",
    )
    friction.add_argument(
        "--resample",
        action="store_true",
        help="bring two grids of different pixel size onto a common grid instead of refusing them",
    )
    friction.add_argument(
        "--hold-time", default="0 s", help="time held in contact before sliding, e.g. '10 s'"
    )
    friction.add_argument(
        "--relaxed-modulus",
        help="long-time Young's modulus of the surface's body (standard "
        "linear solid from its modulus to this one), e.g. '90 GPa'",
    )
    friction.add_argument(
        "--relaxation-time", default="1 s", help="relaxation time of the standard linear solid"
    )
    friction.add_argument("--layer-thickness", default="50 nm", help="Winkler layer height h (default 50 nm)")
    friction.add_argument(
        "--epsilon", default="2 nm", help="Lennard-Jones equilibrium distance (default 2 nm)"
    )
    _common_arguments(friction)
    friction.set_defaults(handler=_friction)

    comparison = commands.add_parser(
        "friction-compare",
        help="simulated vs measured mu per sample: t-tests and Pearson r (paper 000's validation)",
        description="Simulate mu for every scan of every sample (--sample NAME=a.di,b.di ...; without "
        "--sample: paper 000's case with synthetic seeded scans) and compare with MEASURED (CSV sample,mu). "
        "The model uses paper 000's 50 nm layer and 2 nm epsilon.",
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
    comparison.add_argument("--size", type=_size_argument, help="scan size if the files lack it, e.g. '5 um'")
    comparison.add_argument("--height-unit", help="height unit if the files lack it")
    comparison.add_argument("--material", default="polysilicon", help="library material of the samples")
    comparison.add_argument("--counter", default="SiO2", help="library material of the tip")
    comparison.add_argument(
        "--surface-energy",
        default="50 mJ/m^2",
        help="surface energy of the samples (paper 000 does not give it; default 50 mJ/m^2)",
    )
    comparison.add_argument("--load", default="10 uN", help="normal load (default 10 uN)")
    comparison.add_argument("--alpha", type=float, default=0.1, help="t-test threshold (paper: 0.1)")
    comparison.add_argument(
        "--equal-var", action="store_true", help="Student's pooled t-test instead of Welch's"
    )
    comparison.add_argument("--seed", type=int, default=0, help="seed of the synthetic scans")
    _common_arguments(comparison)
    comparison.set_defaults(handler=_friction_compare)
