"""The ``presliding`` and ``loop-analysis`` subcommands (paper 001: partial slip, loops, K_L).

``presliding`` runs a tangential loading programme on a measured or generated ball (or paper
001's case with ``--paper001``) and writes the loops, the last-loop analysis, stick/slip maps at
points A, B, C and K_L against Mindlin; ``loop-analysis`` analyses a measured loop (CSV). Unit
strings are converted here, once, through :mod:`roughcontact.units`.
"""

from __future__ import annotations

import argparse
import csv
import json
from pathlib import Path

import numpy as np

from ._json import json_ready
from .cli import _add_material_options, _material, _read, _read_options
from .errors import InputError
from .units import format_si, quantity


def _write_loop(path: Path, result) -> None:
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(
            [
                "step",
                "delta_x [m]",
                "delta_y [m]",
                "F_x [N]",
                "F_y [N]",
                "stick_area [m^2]",
                "slip_area [m^2]",
                "iterations",
            ]
        )
        for k in range(result.steps):
            writer.writerow(
                [
                    k,
                    *result.displacement[k],
                    *result.force[k],
                    result.stick_area[k],
                    result.slip_area[k],
                    result.iterations[k],
                ]
            )


def _maps(case_label: str, result, point_steps: dict[str, int]) -> dict[str, np.ndarray]:
    return {
        f"{case_label}, {point}": result.states[step].normalised_shear.T
        for point, step in point_steps.items()
    }


def _extent(topography) -> tuple[float, float, float, float]:
    return (0.0, topography.size[0], 0.0, topography.size[1])


def _contact_box(cases, margin: float = 0.1) -> tuple[float, float, float, float]:
    """Bounding box [m] of every case's contact, widened by ``margin`` of its size (the paper's zoom)."""
    boxes = []
    for case in cases:
        normal = case.result.normal
        x, y = normal.topography.meshgrid()
        contact = normal.pressure > 0
        boxes.append((x[contact].min(), x[contact].max(), y[contact].min(), y[contact].max()))
    x0, x1 = min(b[0] for b in boxes), max(b[1] for b in boxes)
    y0, y1 = min(b[2] for b in boxes), max(b[3] for b in boxes)
    pad = margin * max(x1 - x0, y1 - y0)
    return (x0 - pad, x1 + pad, y0 - pad, y1 + pad)


def _figures(out: Path, cases: list, measured) -> list[str]:
    import matplotlib

    matplotlib.use("Agg")
    from .plotting.presliding import plot_hysteresis_loops, plot_lateral_stiffness, plot_stick_slip_maps

    written = []
    loops = [(*case.loop(), case.label) for case in cases]
    figure = plot_hysteresis_loops(loops, measured)
    figure.savefig(out / "loops.png", dpi=150)
    written.append("loops.png")
    maps, extents = {}, {}
    for case in cases:
        for label, field in _maps(case.label, case.result, case.point_steps).items():
            maps[label], extents[label] = field, _extent(case.result.normal.topography)
    figure = plot_stick_slip_maps(maps, extents, zoom=_contact_box(cases))
    figure.savefig(out / "stick_slip.png", dpi=150)
    written.append("stick_slip.png")
    by_ball: dict[str, list] = {}
    for case in cases:
        by_ball.setdefault(case.ball, []).append(case)
    for ball, group in by_ball.items():
        loads = [c.normal_force for c in group]
        points = group[0].analysis.point_names
        simulated = {p: [c.analysis.lateral_stiffness[p] for c in group] for p in points}
        mindlin = {r: {p: [c.mindlin[r][p] for c in group] for p in points} for r in group[0].mindlin}
        figure = plot_lateral_stiffness(loads, simulated, mindlin=mindlin, title=ball)
        name = f"lateral_stiffness_{ball}.png".replace(" ", "_")
        figure.savefig(out / name, dpi=150)
        written.append(name)
    return written


def _report(cases: list, out: Path, measured, json_output: bool) -> int:
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for case in cases:
        slug = case.label.replace(" ", "_").replace(",", "")
        _write_loop(out / f"loop_{slug}.csv", case.result)
        rows.append(case.scalars())
    (out / "presliding.json").write_text(json.dumps(json_ready(rows), indent=2))
    figures = _figures(out, cases, measured)
    if json_output:
        print(json.dumps(json_ready(rows)))
        return 0
    header = ("case", "mu", "stroke", "K_L A", "K_L B", "K_L C", "Mindlin A (Johnson)")
    print(f"{header[0]:<18} {header[1]:>6} {header[2]:>10} " + " ".join(f"{h:>12}" for h in header[3:]))
    for case in cases:
        k = case.analysis.lateral_stiffness
        values = [k["A"], k["B"], k["C"], case.mindlin["johnson"]["A"]]
        print(
            f"{case.label:<18} {case.friction_coefficient:>6.3f} {format_si(case.stroke, 'm'):>10} "
            + " ".join(f"{format_si(v, 'N/m'):>12}" for v in values)
        )
    print(f"wrote {out}/presliding.json, loop_*.csv, {', '.join(figures)}")
    return 0


def _report_programme(case, out: Path, measured, json_output: bool) -> int:
    """Write and print a user programme's results: per-step CSV, JSON row, loop and stick/slip figures."""
    import matplotlib

    matplotlib.use("Agg")
    from .plotting.presliding import plot_hysteresis_loops, plot_stick_slip_maps

    out.mkdir(parents=True, exist_ok=True)
    _write_loop(out / "path_result.csv", case.result)
    row = case.scalars()
    (out / "presliding.json").write_text(json.dumps(json_ready(row), indent=2))
    plot_hysteresis_loops([(*case.loop(), case.label)], measured).savefig(out / "loops.png", dpi=150)
    maps = _maps(case.label, case.result, case.map_steps)
    extent = _extent(case.result.normal.topography)
    figure = plot_stick_slip_maps(maps, dict.fromkeys(maps, extent), zoom=_contact_box([case]))
    figure.savefig(out / "stick_slip.png", dpi=150)
    if json_output:
        print(json.dumps(json_ready(row)))
        return 0
    result, stick = case.result, 100 * row["last_stick_fraction"]
    print(
        f"{case.label}: {result.steps} steps under {case.control} control, mu {case.friction_coefficient:g}; "
        f"last step delta_x {format_si(result.displacement[-1, 0], 'm')}, "
        f"F_x {format_si(result.force[-1, 0], 'N')}, stick {stick:.1f} % of the contact"
    )
    for k, energy in enumerate(row["energy_per_loop [J]"], 1):
        print(f"loop {k}: dissipated energy {format_si(energy, 'J')}")
    if case.note:
        print(case.note)
    if case.analysis is not None:
        stiffness = ", ".join(
            f"{p} {format_si(v, 'N/m')}" for p, v in case.analysis.lateral_stiffness.items()
        )
        stroke = format_si(case.analysis.stroke, "m")
        print(f"last loop: stroke {stroke}, mu {case.analysis.mu:.4f}, K_L {stiffness}")
    print(f"wrote {out}/presliding.json, path_result.csv, loops.png, stick_slip.png")
    return 0


def _measured(args) -> list | None:
    if args.measured is None:
        return None
    from .experiment.friction_loop import read_loop_csv

    loop = read_loop_csv(args.measured, args.measured_displacement_unit, args.measured_force_unit)
    return [(loop.displacement, loop.force, f"measured ({Path(args.measured).name})")]


def _presliding(args: argparse.Namespace) -> int:
    from .contact.paths import read_path_csv
    from .models import paper001

    common = dict(
        cycles=args.cycles,
        steps_per_stroke=args.steps_per_stroke,
        coupling=not args.no_coupling,
        tolerance=args.tolerance,
    )
    cases = []
    if args.paper001:
        if args.file is not None:
            raise InputError("FILE", "--paper001 generates the balls.", "drop FILE, or drop --paper001.")
        loads = [
            quantity(text, "force", field="--loads") for text in (args.loads or ["25 mN", "50 mN", "75 mN"])
        ]
        for ball in args.ball:
            for load in loads:
                cases.append(
                    paper001.run_case(
                        ball, load, window=args.window or 160, pixels=args.pixels, seed=args.seed, **common
                    )
                )
    else:
        if args.file is None:
            raise InputError("FILE", "no ball topography given.", "pass a FILE, or --paper001.")
        if args.path is not None and args.stroke is not None:
            raise InputError("--path", "give --stroke (paper 001's cycles) or --path, not both.", None)
        for name in ("force", "mu") + (() if args.path is not None else ("stroke",)):
            if getattr(args, name) is None:
                raise InputError(f"--{name}", "missing.", f"give --{name} (or use --paper001).")
        programme = None if args.path is None else read_path_csv(args.path)
        scan = _read(args)
        material = _material(args, "material", required=True)
        counter = _material(args, "counter")
        load = quantity(args.force, "force", field="--force")
        if args.window is not None:
            scan = paper001.central_window(scan, args.window)
        if programme is not None:
            case = paper001.programme_case(
                scan,
                material,
                counter,
                load,
                path=programme[0],
                control=programme[1],
                friction_coefficient=args.mu,
                label=f"{Path(args.file).stem} {load * 1e3:g} mN",
                coupling=not args.no_coupling,
                tolerance=args.tolerance,
            )
            return _report_programme(case, args.output, _measured(args), args.json)
        cases.append(
            paper001.presliding_case(
                scan,
                material,
                counter,
                load,
                stroke=quantity(args.stroke, "length", field="--stroke"),
                friction_coefficient=args.mu,
                radius=quantity(args.radius, "length", field="--radius"),
                label=f"{Path(args.file).stem} {load * 1e3:g} mN",
                ball=Path(args.file).stem,
                **common,
            )
        )
    return _report(cases, args.output, _measured(args), args.json)


def _loop_analysis(args: argparse.Namespace) -> int:
    from .experiment.friction_loop import analyse_loop, read_loop_csv

    loop = read_loop_csv(args.file, args.displacement_unit, args.force_unit)
    normal_force = quantity(args.normal_force, "force", field="--normal-force")
    analysis = analyse_loop(loop.displacement, loop.force, normal_force)
    scalars = analysis.scalars()
    if args.json:
        print(json.dumps(json_ready(scalars)))
    else:
        print(f"stroke d_s      {format_si(analysis.stroke, 'm')}")
        print(f"friction mu     {analysis.mu:.4f}")
        print(f"energy per loop {format_si(analysis.energy, 'J')}")
        for point, value in analysis.lateral_stiffness.items():
            print(f"K_L at {point}        {format_si(value, 'N/m')}")
    if args.plot is not None:
        import matplotlib

        matplotlib.use("Agg")
        from .plotting.presliding import plot_hysteresis_loops

        plot_hysteresis_loops([], [(loop.displacement, loop.force, Path(args.file).stem)]).savefig(
            args.plot, dpi=150
        )
    return 0


def add_presliding_commands(commands) -> None:
    """Add ``presliding`` and ``loop-analysis`` to the subparsers ``commands`` of the CLI."""
    presliding = commands.add_parser(
        "presliding",
        parents=[_read_options(file_required=False)],
        help="partial-slip friction loops of a rough ball on a flat, K_L vs Mindlin (paper 001)",
        description="Press the ball FILE (heights with its spherical shape) on a flat with --force, move the "
        "flat 0 -> --stroke -> 0 for --cycles cycles, and analyse the last loop; or drive it along your own "
        "displacement or force programme (--path CSV); or run paper 001's HDPE/POM cases with --paper001 "
        "(generated balls, Table 1 loads, strokes and mu).",
    )
    _add_material_options(presliding, "the ball", "the flat (default: rigid)", "HDPE, POM, 'silicon wafer'")
    presliding.add_argument("--paper001", action="store_true", help="paper 001's balls and Table 1")
    presliding.add_argument(
        "--ball", nargs="+", default=["HDPE", "POM"], help="with --paper001: HDPE and/or POM"
    )
    presliding.add_argument("--loads", nargs="+", help="with --paper001: loads (default 25 mN 50 mN 75 mN)")
    presliding.add_argument("--force", help="normal force F0, e.g. '25 mN'")
    presliding.add_argument("--mu", type=float, help="friction coefficient mu_f")
    presliding.add_argument("--stroke", help="stroke d_s, e.g. '2.8 um'")
    presliding.add_argument(
        "--path",
        type=Path,
        help="instead of --stroke: your tangential programme, a CSV with one row per step and units "
        "in the header: 'x [um]' or 'x [um],y [um]' (displacement control), 'Q_x [mN],Q_y [mN]' "
        "(force control)",
    )
    presliding.add_argument("--radius", default="5 mm", help="ball radius for Mindlin's K_L (default 5 mm)")
    presliding.add_argument(
        "--cycles", type=int, default=4, help="with --stroke: cycles of the path (default 4, as Fig. 6)"
    )
    presliding.add_argument(
        "--steps-per-stroke", type=int, default=20, help="with --stroke: steps per branch (default 20)"
    )
    presliding.add_argument(
        "--window",
        type=int,
        help="pixels of the solved central window (default 160 with --paper001, else the whole scan)",
    )
    presliding.add_argument(
        "--pixels", type=int, default=512, help="with --paper001: pixels of the 1.1 mm scan"
    )
    presliding.add_argument("--seed", type=int, default=1, help="with --paper001: seed of the roughness")
    presliding.add_argument("--no-coupling", action="store_true", help="uncoupled (Goodman) solution")
    presliding.add_argument("--tolerance", type=float, default=1e-8, help="solver tolerance (default 1e-8)")
    presliding.add_argument("--measured", type=Path, help="a measured loop CSV to overlay")
    presliding.add_argument("--measured-displacement-unit", default="um")
    presliding.add_argument("--measured-force-unit", default="mN")
    presliding.add_argument(
        "-o", "--output", type=Path, default=Path("presliding-output"), help="output folder"
    )
    presliding.add_argument("--json", action="store_true", help="print the table as JSON")
    presliding.set_defaults(handler=_presliding)

    analysis = commands.add_parser(
        "loop-analysis",
        help="stroke, mu, eq. 9 fit and K_L at A, B, C of a measured friction loop (paper 001)",
        description="Analyse the last loop of a friction record (CSV of displacement and force).",
    )
    analysis.add_argument("file", type=Path, help="CSV with displacement and force columns")
    analysis.add_argument("--normal-force", required=True, help="F0, e.g. '25 mN'")
    analysis.add_argument("--displacement-unit", default="um")
    analysis.add_argument("--force-unit", default="mN")
    analysis.add_argument("--plot", type=Path, help="write the loop figure here")
    analysis.add_argument("--json", action="store_true")
    analysis.set_defaults(handler=_loop_analysis)
