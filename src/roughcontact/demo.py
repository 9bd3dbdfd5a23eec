"""The embedded demo run by ``roughcontact demo`` and ``make demo``.

It needs no file from the user: it reads the AFM scan shipped in ``roughcontact/data``,
generates two self-affine surfaces and their composite, solves its normal contact (with the
subsurface stress) and its Winkler-layer Lennard-Jones friction (seed paper 000), runs the
pre-sliding loops of a small rough ball (seed paper 001), reproduces
the asperity parameters of seed paper 002 from its printed spectral moments with its
statistical load-unload, and writes figures and the lossless NetCDF form of each surface into
the output folder.
"""

from __future__ import annotations

from collections.abc import Callable
from importlib.resources import as_file, files
from pathlib import Path

from .materials import get_material
from .topography import Topography
from .topography.generate import self_affine
from .topography.io import load_topography, read_topography, save_topography
from .topography.process import combine


def _demo_scan() -> Topography:
    with as_file(files("roughcontact") / "data" / "top-1.top") as path:
        scan = read_topography(path)
    return scan


def _paper_002(report: Callable[[str], None]) -> None:
    """Report paper 002's asperity numbers and its statistical (Kogut-Etsion) load-unload."""
    from .models import asperity_report, paper002
    from .units import format_si

    report("\n== seed paper 002: asperity parameters from the printed spectral moments ==")
    report(asperity_report.format_comparison(paper002.comparison()))
    curve = paper002.statistical_curve()
    omega_c = paper002.parameters().critical_interference
    peak, residual = curve.approach.max() / omega_c, curve.residual_interference / omega_c
    report(
        "statistical load-unload (Kogut-Etsion loading, eq. 11 unloading), "
        f"{format_si(paper002.PEAK_FORCE, 'N')} on the {format_si(paper002.ISLAND_SIDE, 'm')} island: "
        f"peak interference {peak:.2f} omega_c, residual {residual:.2f} omega_c"
    )


def _paper_000(report: Callable[[str], None]) -> None:
    """Report paper 000's case: the SiO2 sphere tip on one synthetic polysilicon scan per sample, 10 uN."""
    from .experiment.paper000 import PAPER000_SAMPLES, paper000_simulation

    report("\n== seed paper 000: Winkler-layer Lennard-Jones friction, SiO2 tip on polysilicon, 10 uN ==")
    mu = paper000_simulation(count=1)
    for sample in PAPER000_SAMPLES:
        report(f"  {sample:<12} mu {mu[sample][0]:.3g}")
    report("  (synthetic scans, default readings, polysilicon surface energy 50 mJ/m^2 assumed;")
    report("   the readings and their effect: docs/winkler_lj.md)")


def _paper_001(output: Path, report: Callable[[str], None]) -> None:
    """Report a small paper 001 case: a rough POM-like ball on silicon, two stroke cycles, K_L vs Mindlin."""
    import matplotlib

    matplotlib.use("Agg")
    from .models.paper001 import presliding_case
    from .plotting.presliding import plot_hysteresis_loops
    from .topography.generate import sphere_with_roughness
    from .units import format_si

    report("\n== seed paper 001: pre-sliding loops of a rough ball (R 5 mm, 0.05 um rms) on silicon, 5 mN ==")
    ball = sphere_with_roughness((64, 64), (64 * 2.148e-6,) * 2, radius=5e-3, rms_height=5e-8, seed=3)
    case = presliding_case(
        ball,
        get_material("POM"),
        get_material("silicon wafer"),
        5e-3,
        stroke=0.4e-6,
        friction_coefficient=0.1,
        cycles=2,
        steps_per_stroke=10,
        label="POM-like ball, 5 mN",
    )
    analysis = case.analysis
    report(
        f"  last loop: stroke {format_si(analysis.stroke, 'm')}, sliding force / F0 {analysis.mu:.3f}, "
        f"energy {format_si(analysis.energy, 'J')}"
    )
    for point, value in analysis.lateral_stiffness.items():
        mindlin = case.mindlin["johnson"][point]
        report(
            f"  K_L at {point}: {format_si(value, 'N/m')} (smooth ball, Mindlin: {format_si(mindlin, 'N/m')})"
        )
    figure = plot_hysteresis_loops([(*case.loop(), case.label)])
    figure.savefig(output / "presliding_loop.png", dpi=150)
    report(
        f"  wrote {output / 'presliding_loop.png'}; the paper's full case: roughcontact presliding --paper001"
    )


def _table(rows: list[tuple[str, ...]], header: tuple[str, ...]) -> str:
    widths = [max(len(r[i]) for r in [header, *rows]) for i in range(len(header))]
    lines = ["  ".join(cell.ljust(w) for cell, w in zip(row, widths, strict=True)) for row in [header, *rows]]
    return "\n".join(line.rstrip() for line in lines)


def _write(topography: Topography, name: str, output: Path, report: Callable[[str], None]) -> None:
    from .plotting import plot_overview

    figure_path = output / f"{name}.png"
    plot_overview(topography).savefig(figure_path, dpi=120)
    data_path = output / f"{name}.nc"
    save_topography(topography, data_path)
    reread = load_topography(data_path)
    if not (reread.heights == topography.heights).all():  # the demo shows the format is lossless
        raise RuntimeError(f"{data_path} did not read back identically")
    report(f"wrote {figure_path} and {data_path}")


def _rough_contact(surface: Topography, output: Path, report: Callable[[str], None]) -> None:
    """Solve and report the normal contact of the composite surface, polysilicon on SiO2 (paper 000)."""
    from .contact import solve_normal
    from .elasticity.stress import subsurface_stress
    from .plotting import plot_contact_overview, plot_von_mises
    from .units import format_si

    silicon, oxide = get_material("polysilicon"), get_material("SiO2")
    result = solve_normal(surface, silicon, counter_body=oxide, mean_pressure=20e6, tolerance=1e-8)
    report("\n== normal contact of the composite surface: polysilicon on SiO2, mean pressure 20 MPa ==")
    rows = [
        ("contact modulus E*", format_si(result.contact_modulus, "Pa")),
        ("force", format_si(result.force, "N")),
        ("real contact area", f"{100 * result.contact_fraction:.2f} % of nominal"),
        ("contact patches", str(result.number_of_patches)),
        ("largest pressure", format_si(float(result.pressure.max()), "Pa")),
        ("approach", format_si(result.approach, "m")),
        ("mean gap", format_si(result.mean_gap, "m")),
        ("iterations / residual", f"{result.iterations} / {result.residual:.1e}"),
    ]
    report(_table(rows, ("quantity", "value")))
    figure_path = output / "contact.png"
    plot_contact_overview(result).savefig(figure_path, dpi=120)
    depth = 20e-9
    stress = subsurface_stress(
        result.pressure, surface.size, [depth], poissons_ratio=silicon.poissons_ratio, boundary="periodic"
    )
    fig, _ = plot_von_mises(stress, 0)
    stress_path = output / "von_mises_20nm.png"
    fig.savefig(stress_path, dpi=120)
    peak, _ = stress.max_von_mises()
    report(f"largest von Mises stress at 20 nm depth: {format_si(peak, 'Pa')}")
    report(f"wrote {figure_path} and {stress_path}")


def run_demo(output: Path | str, report: Callable[[str], None] = print) -> None:
    """Run the demo, writing figures and surfaces into ``output`` and text through ``report``.

    Parameters
    ----------
    output : path
        Folder for the figures (PNG) and surfaces (NetCDF); created when missing.
    report : callable
        Receives each block of text (``print`` by default).
    """
    from .cli import describe, format_description

    output = Path(output)
    output.mkdir(parents=True, exist_ok=True)

    scan = _demo_scan()
    report("== measured AFM scan (embedded top-1.top, units from the file) ==")
    report(format_description(describe(scan)))
    _write(scan, "afm_scan", output, report)

    ball = self_affine((256, 256), (5e-6, 5e-6), hurst=0.8, rms_height=1.5e-9, seed=1)
    flat = self_affine((256, 256), (5e-6, 5e-6), hurst=0.7, rms_height=1.0e-9, seed=2)
    composite = combine(ball, flat)
    report("\n== composite of two generated self-affine surfaces (H 0.8 + 0.7, rms 1.5 nm + 1.0 nm) ==")
    report(format_description(describe(composite)))
    _write(composite, "composite", output, report)

    _rough_contact(composite, output, report)

    _paper_000(report)
    _paper_001(output, report)
    _paper_002(report)
