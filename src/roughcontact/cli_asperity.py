"""The ``asperity`` subcommand: statistical elastic-plastic asperity model and paper 002's island.

Added to the parser of :mod:`roughcontact.cli` by :func:`add_asperity_commands`; unit strings are
converted here, once, through :mod:`roughcontact.units`.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from ._json import json_ready
from .cli import _add_material_options, _material, _read, _read_options
from .errors import InputError
from .units import format_si, quantity


def _area(text: str) -> float:
    """Nominal area from '625 um^2' or a rectangle '25 um x 25 um'."""
    parts = [p.strip() for p in text.split(" x ")]
    if len(parts) == 2:
        return quantity(parts[0], "length", field="--area") * quantity(parts[1], "length", field="--area")
    return quantity(text, "area", field="--area")


def _inputs(args: argparse.Namespace) -> dict:
    """Moments, materials and loads from the arguments (paper 002's where --paper002 and not overridden)."""
    from .materials import get_material
    from .models import paper002
    from .topography.statistics import spectral_moments

    sources = sum([args.file is not None, args.moments is not None, args.paper002 and args.moments is None])
    if args.file is not None and args.moments is not None:
        raise InputError("--moments", "both a FILE and --moments were given.", "give one of them.")
    if sources == 0:
        raise InputError(
            "FILE", "no surface given.", "pass a topography FILE, --moments M0 M2 M4 or --paper002."
        )
    topography = None
    if args.file is not None:
        topography = _read(args)
        found = spectral_moments(topography)
        moments = {"m0": found.m0, "m2": found.m2, "m4": found.m4}
    elif args.moments is not None:
        dimensions = ("area", "dimensionless", "inverse_area")
        moments = {
            name: quantity(text, dimension, field=f"--moments {name}")
            for name, text, dimension in zip(("m0", "m2", "m4"), args.moments, dimensions, strict=True)
        }
    else:
        moments = dict(paper002.MOMENTS)
    sample = _material(args, "material", required=not args.paper002) or get_material("SU-8")
    counter = _material(args, "counter")
    if args.paper002:
        counter = counter or get_material("diamond flat tip")

    def si(value, dimension, field, default=None):
        return default if value is None else quantity(value, dimension, field=field)

    paper = args.paper002
    return {
        "topography": topography,
        "moments": moments,
        "sample": sample,
        "counter": counter,
        "hardness": si(args.hardness, "pressure", "--hardness"),
        "yield_strength": si(args.yield_strength, "pressure", "--yield-strength", sample.yield_strength),
        "max_force": si(args.max_force, "force", "--max-force", paper002.PEAK_FORCE if paper else None),
        "nominal_area": _area(args.area) if args.area else (paper002.ISLAND_SIDE**2 if paper else None),
        "reference_force": si(
            args.reference_force, "force", "--reference-force", paper002.REFERENCE_FORCE if paper else None
        ),
    }


def _asperity(args: argparse.Namespace) -> int:
    from .asperity import statistical_load_unload
    from .asperity.greenwood_williamson import summits_of
    from .asperity.parameters import asperity_parameters
    from .models import asperity_report, paper002
    from .topography.statistics import mccool_parameters

    inputs = _inputs(args)
    sample, counter, moments = inputs["sample"], inputs["counter"], inputs["moments"]
    parameters = asperity_parameters(
        **moments,
        sample=sample,
        counter_body=counter,
        hardness=inputs["hardness"],
        modulus_form=args.modulus_form,
    )
    document = {"parameters": parameters.to_dict(), "modulus_form": args.modulus_form}
    if args.paper002:
        document["paper002_comparison"] = asperity_report.comparison_records(paper002.comparison())
    curves, statistical = {}, None
    if inputs["max_force"] is not None:
        if inputs["nominal_area"] is None:
            raise InputError(
                "--area", "a load-unload curve needs the nominal area.", "e.g. --area '25 um x 25 um'."
            )
        if args.distribution == "measured" and inputs["topography"] is None:
            raise InputError(
                "--distribution", "'measured' needs a topography FILE.", "pass FILE or 'gaussian'."
            )
        summits = summits_of(mccool_parameters(**moments), args.distribution, inputs["topography"])
        statistical = statistical_load_unload(
            summits,
            contact_modulus=parameters.contact_modulus,
            hardness=inputs["hardness"] or sample.hardness,
            poissons_ratio=sample.poissons_ratio,
            max_force=inputs["max_force"],
            nominal_area=inputs["nominal_area"],
            law=args.law,
            yield_strength=inputs["yield_strength"],
            reference_force=inputs["reference_force"],
            steps=args.steps,
        )
        curves[f"statistical ({args.law})"] = statistical.curve()
        document["statistical"] = {
            "law": args.law,
            "peak_interference": float(statistical.approach[statistical.peak]),
            "residual_interference": statistical.residual_interference,
        }
    compression = _island(args, inputs, sample) if args.bem else None
    if compression is not None:
        curves["BEM island"] = compression.curve()
        document["bem"] = {
            "grid": list(compression.steps[0].topography.shape),
            "peak_interference": float(compression.interference[compression.branch == "loading"][-1]),
            "residual_interference": compression.residual_interference,
        }
    measured = asperity_report.read_measured_curve(args.measured) if args.measured else None
    if args.output is not None:
        document["files"] = _write(args, curves, compression, measured, parameters, document)
    if args.json:
        print(json.dumps(json_ready(document), indent=2))
        return 0
    print(
        f"asperity parameters ({sample.name} against {counter.name if counter else 'a rigid flat'}, "
        f"E' form: {args.modulus_form})"
    )
    print(asperity_report.format_parameters(parameters))
    if args.paper002:
        print("paper 002, section IV: paper vs ours")
        print(asperity_report.format_comparison(paper002.comparison()))
    for name in ("statistical", "bem"):
        if name in document:
            values = document[name]
            print(
                f"{name}: peak interference {format_si(values['peak_interference'], 'm')}, residual "
                f"{format_si(values['residual_interference'], 'm')} "
                f"({values['peak_interference'] / parameters.critical_interference:.3g} and "
                f"{values['residual_interference'] / parameters.critical_interference:.3g} omega_c)"
            )
    for path in document.get("files", []):
        print(f"wrote {path}")
    return 0


def _island(args: argparse.Namespace, inputs: dict, sample):
    from .materials import get_material
    from .models.thin_film_island import compress_island, paper002_island

    topography = inputs["topography"] or (paper002_island(args.grid) if args.paper002 else None)
    if topography is None:
        raise InputError("--bem", "needs a topography FILE or --paper002.", "add one, or leave out --bem.")
    if inputs["max_force"] is None or inputs["reference_force"] is None:
        raise InputError("--bem", "needs --max-force and --reference-force.", "add them (or --paper002).")
    substrate = get_material(args.substrate) if args.substrate else None
    if args.paper002 and args.substrate is None:
        substrate = get_material("silicon wafer")
    return compress_island(
        topography,
        sample,
        peak_force=inputs["max_force"],
        substrate=substrate,
        film_thickness=quantity(args.film_thickness, "length", field="--film-thickness"),
        hardness=inputs["hardness"],
        reference_force=inputs["reference_force"],
    )


def _write(args, curves, compression, measured, parameters, document) -> list[str]:
    from .models import asperity_report
    from .plotting import plot_area_load, plot_load_interference, plot_von_mises_maps

    out = args.output
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for label, curve in curves.items():
        name = "bem_island" if label == "BEM island" else "load_unload"
        asperity_report.write_curve_csv(out / f"{name}.csv", curve)
        written.append(str(out / f"{name}.csv"))
    if curves:
        labels = {label: ("bem" if label == "BEM island" else "statistical") for label in curves}
        dataset = asperity_report.curves_dataset(
            {labels[label]: curve for label, curve in curves.items()},
            {"critical_interference_m": parameters.critical_interference, "modulus_form": args.modulus_form},
        )
        dataset.to_netcdf(out / "load_unload.nc", engine="h5netcdf")
        fig, _ = plot_load_interference(curves, parameters.critical_interference, measured=measured)
        fig.savefig(out / "fig7_load_interference.png", dpi=args.dpi)
        fig, _ = plot_area_load(curves)
        fig.savefig(out / "contact_area.png", dpi=args.dpi)
        written += [
            str(out / n) for n in ("load_unload.nc", "fig7_load_interference.png", "contact_area.png")
        ]
    if compression is not None:
        forces = compression.curve()["force"]
        wanted = [i for i, f in enumerate(forces) if round(f * 1e6) % 200 == 0]
        fig, _ = plot_von_mises_maps(compression, wanted)
        fig.savefig(out / "von_mises.png", dpi=args.dpi)
        written.append(str(out / "von_mises.png"))
    (out / "asperity.json").write_text(json.dumps(json_ready(document), indent=2))
    return [*written, str(out / "asperity.json")]


def add_asperity_commands(commands) -> None:
    """Add the ``asperity`` subcommand to the CLI's subparsers."""
    from .asperity import LOADING_LAWS

    asperity = commands.add_parser(
        "asperity",
        parents=[_read_options(file_required=False)],
        help="statistical elastic-plastic asperity model (GW/McCool, CEB, Kogut-Etsion, KKE) and paper 002",
        description="Asperity parameters (R_asp, sigma_s, E', K, omega_c, psi) from a topography FILE or "
        "--moments, the statistical load-unload curve with --max-force and --area, and the BEM island "
        "compression with --bem. --paper002 fills in the paper's moments, materials and loads and prints "
        "the paper-vs-ours table.",
    )
    asperity.add_argument(
        "--moments", nargs=3, metavar=("M0", "M2", "M4"), help="e.g. '0.00213 um^2' 0.0023 '0.0171 1/um^2'"
    )
    asperity.add_argument(
        "--paper002", action="store_true", help="seed paper 002's moments, materials, loads"
    )
    _add_material_options(asperity, "the rough body", "the flat (default: rigid)", "SU-8, 'diamond flat tip'")
    asperity.add_argument(
        "--hardness", help="hardness of the rough body, e.g. '0.462 GPa' (default: material's)"
    )
    asperity.add_argument("--yield-strength", help="yield strength for --law jackson_green, e.g. '0.165 GPa'")
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
    asperity.add_argument("--substrate", help="substrate of the film for --bem (paper 002: silicon wafer)")
    asperity.add_argument(
        "--film-thickness", default="6.3 um", help="film thickness for --bem with --substrate"
    )
    asperity.add_argument("--measured", type=Path, help="CSV of a measured curve: interference_m,force_N")
    asperity.add_argument("-o", "--output", type=Path, help="folder for CSV, NetCDF, figures and JSON")
    asperity.add_argument("--dpi", type=int, default=150)
    asperity.add_argument("--json", action="store_true", help="print one JSON document (SI)")
    asperity.set_defaults(handler=_asperity)
