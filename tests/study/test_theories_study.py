"""The ``theories`` study kind and command: each load and realisation a case, the theories beside the BEM.

* a study of a generated surface (three loads on three realisations) and of the shipped AFM scan (a
  free window, two loads): its scalars, the area, gap and kappa tables with their intervals and
  verdicts, and every figure read as a reviewer would (:func:`test_figures_read.figure_problems`);
* the kind's scalars are the Python function's on the same surface and load (one call);
* the command on a FILE and on a generated surface, and what it refuses;
* validation errors naming the key.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from test_figures_read import figure_problems

from roughcontact.study import load_study, run_study
from roughcontact.study.config import StudyError
from roughcontact.study.outputs import produce, read_study
from roughcontact.study.store import notes_of

TOP = Path(__file__).resolve().parents[2] / "src" / "roughcontact" / "data" / "top-1.top"

STUDY = f"""
[study]
name = "theories"
seed = 3

[topographies.rough]
generate = "self_affine"
shape = 64
size = "2 um"
hurst = 0.8
rms_slope = 0.1
short_cutoff = "250 nm"
long_cutoff = "1 um"
rolloff = 1.0
modes = "wavevector"

[topographies.afm]
file = "{TOP.as_posix()}"

[[analysis]]
name = "generated"
model = "theories"
topography = "rough"
material = "polysilicon"
realisations = 3
[analysis.sweep]
reduced_pressure = [0.01, 0.03, 0.1]

[[analysis]]
name = "scan"
model = "theories"
topography = "afm"
material = "polysilicon"
[analysis.sweep]
reduced_pressure = [0.01, 0.1]
"""


@pytest.fixture(scope="module")
def answered(tmp_path_factory):
    folder = tmp_path_factory.mktemp("theories")
    path = folder / "theories.toml"
    path.write_text(STUDY)
    run_study(load_study(path), folder / "out")
    analyses = read_study(folder / "out")[1]
    return {a.name: a for a in analyses}, analyses


def _tables(analyses):
    tables, problems = produce(analyses, "table")
    assert not problems, problems
    return {(analysis, name): rows for analysis, name, rows in tables}


def test_each_load_and_realisation_is_a_case_with_every_theory_beside_the_bem(answered):
    by_name, _ = answered
    records = [r for r in by_name["generated"].records if r is not None]
    assert len(records) == 3 * 3 and all(r.done for r in records)
    at_one_load = [r.scalars for r in records if r.parameters["reduced_pressure"] == 0.01]
    assert len({s["rms_gradient"] for s in at_one_load}) == 3  # three draws, three surfaces
    for record in records:
        scalars = record.scalars
        x = scalars["reduced_pressure"]
        assert x == pytest.approx(record.parameters["reduced_pressure"])
        assert scalars["contact_fraction"] > scalars["contact_fraction_corrected"] > 0
        assert scalars["area_load_slope"] == pytest.approx(scalars["contact_fraction_corrected"] / x)
        assert scalars["persson_fraction"] == pytest.approx(math.erf(math.sqrt(2) * x), rel=1e-12)
        assert scalars["bgt_fraction"] == pytest.approx(math.sqrt(2 * math.pi) * x, rel=1e-12)
        # 8 pixels per shortest wavelength: forward differences read the spectral g to a few per cent
        assert scalars["rms_gradient_finite_differences"] == pytest.approx(scalars["rms_gradient"], rel=0.05)
        assert scalars["boundary"] == "periodic" and scalars["gap_compared"] is True
    scan = [r for r in by_name["scan"].records if r is not None]
    assert {r.scalars["boundary"] for r in scan} == {"free"}
    assert all(any("free window" in w for w in r.data["warnings"]) for r in scan)
    # large slopes are said, but the comparison is elastic and takes no hardness: none is advised
    said = [w for r in scan for w in r.data["warnings"]]
    assert any("small-slope elastic theory" in w for w in said)
    assert not any("hardness" in w for w in said)


def test_tables_judge_each_theory_with_an_interval_over_the_realisations(answered):
    _, analyses = answered
    tables = _tables(analyses)
    area = tables[("generated", "area")]
    assert {row["theory"] for row in area} == {
        "Persson",
        "Bush-Gibson-Thomas (small load)",
        "Greenwood-Williamson",
    }
    assert len(area) == 3 * 3  # three theories at three loads
    for row in area:
        assert row["n"] == 3
        assert row["bem_ci95_low"] <= row["bem_mean"] <= row["bem_ci95_high"]
        low, high = row["deviation_ci95_low"], row["deviation_ci95_high"]
        assert low <= row["deviation"] <= high
        expected = "over-predicts" if low > 0 else "under-predicts" if high < 0 else "not established"
        assert row["verdict"] == expected
    persson = [row for row in area if row["theory"] == "Persson"]
    assert all(row["deviation"] < 0 for row in persson)  # Persson's area lies below the BEM's
    assert any("confidence interval of the mean" in note for note in notes_of(area))
    gap = tables[("generated", "gap")]
    assert {row["theory"] for row in gap} == {"Persson", "Greenwood-Williamson"}
    assert all("bem_mean [m]" in row for row in gap)
    kappa = tables[("generated", "kappa")]
    assert [row["theory"] for row in kappa] == ["Persson", "Bush-Gibson-Thomas (small load)"]
    assert kappa[0]["theory_value"] < kappa[0]["bem_mean"] < kappa[1]["theory_value"]
    assert kappa[0]["bem_raw_mean"] > kappa[0]["bem_mean"]  # the pixel count's slope is steeper
    # the scan: one realisation, no interval; its mean gap (a free window) is not compared
    scan_area = tables[("scan", "area")]
    assert {row["verdict"] for row in scan_area} == {"one realisation: no interval"}
    # every row names its surfaces' origin: the scan is measured, the generated surfaces synthetic
    assert {row["surface_origin"] for row in scan_area} == {"measured"}
    assert {
        row["surface_origin"] for name in ("area", "gap", "kappa") for row in tables[("generated", name)]
    } == {"synthetic"}
    assert ("scan", "gap") not in tables


def test_every_figure_is_drawn_and_reads_as_a_reviewer_wants(answered):
    _, analyses = answered
    figures, problems = produce(analyses, "figure")
    assert not problems, problems
    drawn = {(analysis, name) for analysis, name, _ in figures}
    for analysis in ("generated", "scan"):
        assert {(analysis, n) for n in ("area", "gap", "pressure", "kappa", "magnification")} <= drawn
    names = {"rough", "afm", "generated", "scan", "polysilicon"}
    found = [f"{a}/{n}: {p}" for a, n, figure in figures for p in figure_problems(figure, names)]
    assert not found, "\n".join(found)
    area = next(figure for a, n, figure in figures if (a, n) == ("generated", "area"))
    assert "3 realisations" in area.axes[0].get_title()
    (bem,) = [line for line in area.axes[0].get_lines() if line.get_label() == "BEM, corrected area"]
    assert np.allclose(bem.get_xdata(), [0.01, 0.03, 0.1])


def test_the_kind_runs_the_python_function_once(answered):
    from roughcontact.materials import get_material
    from roughcontact.theory import compare_theories
    from roughcontact.topography import read_topography

    by_name, _ = answered
    scan = next(
        r for r in by_name["scan"].records if r is not None and r.parameters["reduced_pressure"] == 0.1
    )
    direct = compare_theories(read_topography(TOP), get_material("polysilicon"), reduced_pressures=[0.1])
    for key in (
        "contact_fraction_corrected",
        "mean_gap",
        "persson_mean_gap",
        "gw_fraction",
        "rms_gradient",
        "m4",
    ):
        assert scan.scalars[key] == pytest.approx(direct.scalars()[key], rel=1e-9), key
    assert np.allclose(scan.dataset()["bem_pressure_density"].values, direct.bem_pressure_density)


def test_validation_names_the_key(tmp_path):
    for bad, key in (
        ('reduced_pressure = 0.01\nmean_pressure = "5 MPa"', "mean_pressure"),
        ("reduced_pressure = -0.01", "reduced_pressure"),
        ("reduced_pressure = 0.01\ngamma = 1.5", "gamma"),
    ):
        text = STUDY.replace("[analysis.sweep]\nreduced_pressure = [0.01, 0.1]", bad)
        path = tmp_path / "bad.toml"
        path.write_text(text)
        with pytest.raises(StudyError) as error:
            load_study(path)
        assert key in str(error.value), (bad, str(error.value))


def test_the_command_on_a_generated_surface_and_on_a_file(cli, tmp_path):
    argv = [
        "theories",
        "--material",
        "polysilicon",
        "--grid",
        "64",
        "--realisations",
        "2",
        "--loads",
        "0.01",
        "0.1",
    ]
    status, out, err = cli(*argv, "--json")
    assert status == 0, err
    (analysis,) = json.loads(out)["analyses"]
    assert len(analysis["cases"]) == 2 * 2
    assert {"area", "gap", "kappa"} <= set(analysis["tables"])  # from the scalars: no -o needed
    status, out, err = cli(
        "theories", TOP, "--material", "polysilicon", "--loads", "0.01", "0.05", "-o", tmp_path / "o"
    )
    assert status == 0, err
    assert "table area" in out and "free window" in err
    assert (tmp_path / "o" / "figures" / "theories_area.png").exists()
    status, _, err = cli("theories", TOP, "--material", "polysilicon", "--hurst", "0.5")
    assert status == 2 and "--hurst" in err and "FILE is the surface" in err
    status, _, err = cli("theories", "--material", "polysilicon", "--boundary", "free")
    assert status == 2 and "--boundary" in err
    status, _, err = cli("theories", "--material", "polysilicon", "--loads", "0.01", "--pressures", "5 MPa")
    assert status == 2 and "--loads" in err
