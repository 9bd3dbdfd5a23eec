"""The ``friction`` study kind (paper 000) and its example study examples/paper000.toml.

* end to end: the example through the CLI at a reduced size (32^2 scans of the paper's 20 nm
  pixels, three scans per sample, three loads), its table, comparison, figures and report, the
  statistics recomputed here from the stored values with scipy;
* the kind's scalars against a direct ``winkler_lj_model(...).solve(load)`` on surfaces built here
  from the same generators and seeds (the same numbers, readings and hold time included);
* validation errors (a bad reading, an unknown reading name, a missing load) before anything runs;
* the same physics written in nm and in m gives the same mu.
"""

from __future__ import annotations

import ast
import math
from dataclasses import replace

import numpy as np
import pytest
import xarray as xr
from scipy import stats

from roughcontact.experiment.compare import read_measured
from roughcontact.materials import get_material
from roughcontact.study import load_study, run_study
from roughcontact.study.config import StudyError
from roughcontact.study.kinds import get_kind
from roughcontact.study.run import execute, make_task
from roughcontact.study.store import read_table
from roughcontact.topography.generate import self_affine, sphere_with_roughness
from roughcontact.topography.statistics import ra
from roughcontact.winkler_lj import PAPER, PronySeries, Readings, WinklerLJOptions, winkler_lj_model
from study_documents import FRICTION_OVER_TWO_LOADS, SCAN_AND_TIP

SAMPLES = ["Ra 1.45 nm", "Ra 1.49 nm", "Ra 1.7 nm"]
REDUCED = {
    "shape = 250": "shape = 32",  # the paper's 20 nm pixels over 0.64 um instead of 5 um
    "stop = 6, step = 1": "stop = 2, step = 1",  # three scans per sample instead of seven
    "num = 13": "num = 3",  # three loads in the load sweep
}


def _rows(output, analysis):
    return [row for row in read_table(output / "results.csv") if row["analysis"] == analysis]


def test_paper000_example_end_to_end(tmp_path, shrunk, cli):
    """examples/paper000.toml reduced, through ``roughcontact run``: table, comparison, figures, report."""
    study = shrunk("paper000.toml", tmp_path, REDUCED, copy=("paper000_reported_mu.csv",))
    output = tmp_path / "out"
    status, out, err = cli("run", study, "-o", output, "--no-progress")
    assert status == 0, err
    # validation 9, claims 45 (five readings), two load sweeps of 27 (three scans each), 1 + 2
    assert "111 cases run, 0 reused, 0 failed" in out
    _check_results_table(output)
    _check_comparison(output, study)
    _check_claims(output)
    _check_figures_and_report(output)
    _check_no_agreement_verdict(output, out)


def _check_results_table(output):
    rows = _rows(output, "validation")
    assert len(rows) == 3 * 3
    assert {row["status"] for row in rows} == {"done"}
    for column in (
        "mu",
        "friction [N]",
        "adhesive_friction [N]",
        "mechanical_friction [N]",
        "normal_force [N]",
    ):
        assert column in rows[0], column
    assert "crossover_load [N]" in rows[0] and "topographies.scan.sample" in rows[0]
    for row in rows:
        mu, friction, load = float(row["mu"]), float(row["friction [N]"]), float(row["normal_force [N]"])
        assert load == pytest.approx(10e-6, rel=1e-12)
        assert mu > 0 and friction / load == pytest.approx(mu, rel=1e-12)
        parts = float(row["adhesive_friction [N]"]) + float(row["mechanical_friction [N]"])
        assert parts == pytest.approx(friction, rel=1e-12)
        assert float(row["crossover_load [N]"]) > 0
    assert sorted({row["sample"] for row in rows}) == sorted(SAMPLES)
    assert all(row["topographies.scan.sample"] == row["sample"] for row in rows)  # each scan its sample's Ra
    # every scan has its own derived seed: no two cases of the validation give the same mu
    assert len({row["mu"] for row in rows}) == len(rows)
    sweep = _rows(output, "load_sweep")
    assert len(sweep) == 3 * 3 * 3 and {row["status"] for row in sweep} == {"done"}
    assert sorted({float(row["normal_force [N]"]) for row in sweep}) == pytest.approx(
        [1e-6, math.sqrt(1e-9), 1e-3]
    )
    paper = _rows(output, "load_sweep_paper")  # reading = "paper": the preset's readings, three scans a load
    assert len(paper) == 3 * 3 * 3 and {row["status"] for row in paper} == {"done"}
    assert all("base=half_sphere" in row["readings"] for row in paper)


def _check_comparison(output, study):
    rows = _rows(output, "validation")
    simulated = {s: [float(r["mu"]) for r in rows if r["sample"] == s] for s in SAMPLES}
    measured = read_measured(study.parent / "paper000_reported_mu.csv")
    table = read_table(output / "tables" / "validation_comparison.csv")
    assert [row["sample"] for row in table] == SAMPLES
    for row in table:
        sample = row["sample"]
        test = stats.ttest_ind(simulated[sample], measured[sample], equal_var=False)
        assert float(row["p_value"]) == pytest.approx(test.pvalue, rel=1e-12)
        assert float(row["t_statistic"]) == pytest.approx(test.statistic, rel=1e-12)
        assert (int(row["n_simulated"]), int(row["n_reconstructed"])) == (3, 7)
        assert row["verdict"].startswith("by construction: no verdict") and row["test"] == "welch"
        assert "measured_mean" not in row and float(row["reconstructed_mean"]) == pytest.approx(
            np.mean(measured[sample]), rel=1e-12
        )
        assert float(row["alpha"]) == 0.1
    means = [(np.mean(simulated[s]), np.mean(measured[s])) for s in SAMPLES]
    pearson = stats.pearsonr(*zip(*means, strict=True))
    assert float(table[0]["pearson_r"]) == pytest.approx(pearson.statistic, rel=1e-12)
    assert float(table[0]["pearson_p"]) == pytest.approx(pearson.pvalue, rel=1e-9)
    by_sample = read_table(output / "tables" / "validation_by_sample.csv")
    for row in by_sample:
        values = simulated[row["sample"]]
        assert int(row["n"]) == 3
        assert float(row["mu_mean"]) == pytest.approx(np.mean(values), rel=1e-12)
        assert float(row["mu_std"]) == pytest.approx(np.std(values, ddof=1), rel=1e-12)


def _check_claims(output):
    """The claims table: five readings, each claim's verdict named by its interval, and what none keeps."""
    table = read_table(output / "tables" / "claims_claims.csv")
    readings = [row["reading"] for row in table]
    assert readings == [
        "default",
        "default but adhesive_range=all_springs, base=half_sphere",
        "default but mechanical_height=printed_separation, base=half_sphere",
        "paper",
        "paper but base=lowest_point",
    ]
    rows = _rows(output, "claims")
    for row in table:
        cases = [r for r in rows if _label(r) == row["reading"]]
        ratios = [float(r["adhesive_to_mechanical"]) for r in cases]
        assert int(row["adhesive_to_mechanical n"]) == len(ratios) == 9
        assert float(row["adhesive_to_mechanical mean"]) == pytest.approx(np.mean(ratios), rel=1e-12)
        low, high = (
            float(row["adhesive_to_mechanical 95% prediction low"]),
            float(row["adhesive_to_mechanical 95% prediction high"]),
        )
        half = stats.t.ppf(0.975, 8) * np.std(ratios, ddof=1) * math.sqrt(1 + 1 / 9)
        assert (low, high) == pytest.approx((np.mean(ratios) - half, np.mean(ratios) + half), rel=1e-9)
        inside = 40 / 1.5 <= low and high <= 40 * 1.5
        outside = high < 40 / 1.5 or low > 40 * 1.5
        verdict = "kept" if inside else "not kept" if outside else "not established"
        assert row["paper sec. 5: adhesive / mechanical about 40"] == verdict
        assert float(row["adhesive_to_mechanical factor from paper"]) == pytest.approx(
            max(40 / low, high / 40), rel=1e-9
        )
        assert row["paper sec. 5: p > 0.1"] == "no verdict: the values were built from this model"
    default = table[0]
    assert float(default["adhesive_to_mechanical mean"]) < 1  # mechanical dominates under the defaults
    assert default["paper sec. 5: adhesive / mechanical about 40"] == "not kept"
    notes = read_table(output / "tables" / "claims_claims.csv").notes
    assert any("cannot be tested" in note for note in notes)
    assert any(note.startswith("No reading keeps every claim") for note in notes)


def _label(row):
    """The reading of a results row in the claims table's words."""
    from roughcontact.study.kinds.friction import reading_label

    readings = ast.literal_eval(row["readings"]) if row["readings"].startswith("{") else {}
    return reading_label({"reading": row["reading"] or None, "readings": readings})


def _check_no_agreement_verdict(output, printed):
    """Nothing the paper 000 example writes or prints calls the reconstructed mu measured or agreeing."""
    report = (output / "report.html").read_text()
    tables = [path.read_text() for path in (output / "tables").glob("*.csv")]
    for text in [printed, report, *tables]:
        assert "agrees" not in text and "measured_mean" not in text
    for text in tables:  # the study file's comments in the report may say what the paper did not measure
        assert "measured values" not in text and "n_measured" not in text
    assert "by construction" in report
    assert "Compared with values reconstructed from reported statistics." in report


def _check_figures_and_report(output):
    figures = output / "figures"
    drawn = {path.name for path in figures.glob("*.png")}
    assert {"validation_mu_boxes.png", "validation_mu_means.png", "load_sweep_friction_vs_load.png"} <= drawn
    assert "load_sweep_paper_friction_vs_load.png" in drawn
    assert "validation_friction_vs_load.png" not in drawn  # one load: nothing to draw against load
    assert all((figures / name).stat().st_size > 10_000 for name in drawn)
    report = (output / "report.html").read_text()
    assert "Figures that could not be drawn" not in report
    for text in ("validation", "load_sweep", "comparison", "by sample", "data:image/png;base64"):
        assert text in report, text
    fields = sorted((output / "cases" / "validation").glob("*.nc"))
    assert len(fields) == 9
    assert "lateral_force" in xr.load_dataset(fields[0])


# --- the kind against the model called directly -------------------------------------------------

DIRECT = """
[study]
name = "direct"

[topographies.scan]
generate = "self_affine"
shape = 32
size = "0.64 um"
hurst = 0.8
rms_height = "1 nm"
ra = "1.7 nm"
seed = 11

[topographies.tip]
generate = "sphere_with_roughness"
shape = 32
size = "0.64 um"
radius = "1 um"
rms_height = "0.3 nm"
seed = 5

[[analysis]]
name = "friction"
model = "friction"
topography = "scan"
counter_topography = "tip"
material = "polysilicon"
counter_body = "SiO2"
normal_force = "{load}"
layer_thickness = "40 nm"
epsilon = "1.5 nm"
surface_energy = "45 mJ/m^2"
crossover = true
{extra}
"""


def _direct_surfaces():
    scan = self_affine((32, 32), 0.64e-6, hurst=0.8, rms_height=1e-9, seed=11)
    scan = scan.with_heights(scan.heights * (1.7e-9 / ra(scan)))
    tip = sphere_with_roughness((32, 32), 0.64e-6, radius=1e-6, rms_height=0.3e-9, seed=5)
    return scan, tip


@pytest.mark.parametrize(
    ("extra", "options"),
    [
        ("", {}),
        (
            'readings = {contact = "zero_gap", shear_poisson = "surface", adhesive_cutoff = "20 nm"}',
            {"readings": Readings(contact="zero_gap", shear_poisson="surface", adhesive_cutoff=20e-9)},
        ),
        (
            'relaxed_modulus = "80 GPa"\nrelaxation_time = "5 s"\nhold_time = "3 s"',
            {"relaxation": PronySeries(80e9, (110e9 - 80e9,), (5.0,)), "hold_time": 3.0},
        ),
        (  # the preset, changed by the table; the tip's radius comes from its generator
            'reading = "paper"\nreadings = {adhesive_range = "maugis_dugdale"}',
            {"readings": replace(PAPER, adhesive_range="maugis_dugdale")},
        ),
    ],
    ids=["defaults", "readings", "hold", "paper"],
)
def test_scalars_are_those_of_the_model_called_directly(tmp_path, extra, options):
    path = tmp_path / "direct.toml"
    path.write_text(DIRECT.format(load="7 uN", extra=extra))
    study = load_study(path)
    (case,) = study.cases
    task = make_task(study, case)
    output = get_kind("friction").run(task.parameters, task.inputs)

    scan, tip = _direct_surfaces()
    model = winkler_lj_model(
        scan,
        get_material("polysilicon"),
        get_material("SiO2"),
        options=WinklerLJOptions(
            layer_thickness=40e-9,
            epsilon=1.5e-9,
            surface_energy=0.045,
            counter_surface_energy=None,  # the SiO2 library value, 72 mJ/m^2
            **options,
        ),
        counter_topography=tip,
    )
    result = model.solve(7e-6)
    for name, value in result.scalars().items():
        assert output.scalars[name] == pytest.approx(value, rel=1e-12, abs=0.0), name
    assert output.scalars["crossover_load"] == pytest.approx(model.crossover_load(), rel=1e-12)
    assert output.scalars["load_capacity"] == pytest.approx(model.load_capacity(), rel=1e-12)
    assert output.scalars["contact_modulus"] == pytest.approx(model.contact_modulus, rel=1e-12)
    assert output.scalars["work_of_adhesion"] == pytest.approx(model.work_of_adhesion, rel=1e-12)
    # the stored fields are cropped to the springs that carry friction: nothing of Q is lost
    lateral = output.dataset["lateral_force"]
    assert lateral.size < result.lateral_force.size
    assert float(lateral.sum()) == pytest.approx(result.friction, rel=1e-12)


def test_a_case_runs_through_the_runner_with_the_same_numbers(tmp_path):
    path = tmp_path / "direct.toml"
    path.write_text(DIRECT.format(load="7 uN", extra=""))
    study = load_study(path)
    record, dataset = execute(make_task(study, study.cases[0]))
    assert record["status"] == "done", record["error"]
    scan, tip = _direct_surfaces()
    mu = (
        winkler_lj_model(
            scan,
            get_material("polysilicon"),
            get_material("SiO2"),
            options=WinklerLJOptions(layer_thickness=40e-9, epsilon=1.5e-9, surface_energy=0.045),
            counter_topography=tip,
        )
        .solve(7e-6)
        .mu
    )
    assert record["scalars"]["mu"] == pytest.approx(mu, rel=1e-12)
    assert dataset is not None and "bonded" in dataset


# --- validation errors ---------------------------------------------------------------------------


def _problems(tmp_path, text):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(StudyError) as caught:
        load_study(path)
    return caught.value.problems, str(caught.value)


def test_a_bad_reading_value_is_refused_with_its_name_and_the_choices(tmp_path):
    problems, message = _problems(
        tmp_path, DIRECT.format(load="7 uN", extra='readings = {contact = "touch"}')
    )
    assert len(problems) == 1
    field, problem, fix = problems[0]
    assert field.endswith(".readings")
    assert "'contact'" in problem and "touch" in problem
    assert "epsilon" in fix and "zero_gap" in fix
    assert "contact" in message


def test_an_unknown_preset_is_refused_with_the_presets(tmp_path):
    problems, _ = _problems(tmp_path, DIRECT.format(load="7 uN", extra='reading = "papers"'))
    (field, problem, fix), *_ = problems
    assert field.endswith(".reading") and "papers" in problem
    assert "'paper'" in fix and "default" in fix and "printed" in fix


def test_an_unknown_reading_name_is_refused_with_a_suggestion(tmp_path):
    problems, _ = _problems(
        tmp_path, DIRECT.format(load="7 uN", extra='readings = {adhesive_rang = "all_springs"}')
    )
    (field, problem, fix), *_ = problems
    assert "adhesive_rang" in problem and "adhesive_range" in fix


def test_a_bad_cutoff_unit_is_refused(tmp_path):
    problems, _ = _problems(
        tmp_path, DIRECT.format(load="7 uN", extra='readings = {adhesive_cutoff = "2 s"}')
    )
    assert "adhesive_cutoff" in problems[0][1]


def test_a_missing_load_is_refused_before_anything_runs(tmp_path):
    text = DIRECT.format(load="7 uN", extra="").replace('normal_force = "7 uN"\n', "")
    problems, _ = _problems(tmp_path, text)
    assert [(f.rsplit(".", 1)[-1], p) for f, p, _ in problems] == [
        ("normal_force", "is required but missing.")
    ]


def test_a_load_that_is_not_a_force_is_refused(tmp_path):
    problems, _ = _problems(tmp_path, DIRECT.format(load="7 nm", extra=""))
    assert problems[0][0].endswith("normal_force")


def test_a_hold_time_without_relaxation_is_refused(tmp_path):
    problems, _ = _problems(tmp_path, DIRECT.format(load="7 uN", extra='hold_time = "3 s"'))
    assert "relaxed_modulus" in problems[0][1]


def test_cli_validate_names_the_bad_reading(tmp_path, cli):
    path = tmp_path / "bad.toml"
    path.write_text(DIRECT.format(load="7 uN", extra='readings = {mechanical_energy = "signed"}'))
    status, _, err = cli("validate", path)
    assert status != 0
    assert "mechanical_energy" in err and "eq16_signed" in err


# --- units ---------------------------------------------------------------------------------------

UNITS = """
[study]
name = "units"
seed = 4

[topographies.scan]
generate = "self_affine"
shape = 32
size = "{size}"
hurst = 0.8
rms_height = "{rms}"
ra = "{ra}"

[topographies.tip]
generate = "sphere_with_roughness"
shape = 32
size = "{size}"
radius = "{radius}"
rms_height = "{tip_rms}"
seed = 2

[[analysis]]
name = "friction"
model = "friction"
topography = "scan"
counter_topography = "tip"
material = "polysilicon"
counter_body = "SiO2"
normal_force = "{load}"
layer_thickness = "{layer}"
epsilon = "{epsilon}"
surface_energy = "{energy}"
readings = {{adhesive_cutoff = "{cutoff}"}}
figures = []
[analysis.sweep]
replicate = [0, 1]
[analysis.zip]
sample = ["a", "b"]
"topographies.scan.ra" = ["{ra}", "{ra_b}"]
"""

IN_NM = {
    "size": "640 nm",
    "rms": "1.5 nm",
    "ra": "1.45 nm",
    "ra_b": "1.7 nm",
    "radius": "1000 nm",
    "tip_rms": "0.3 nm",
    "load": "10000 nN",
    "layer": "50 nm",
    "epsilon": "2 nm",
    "energy": "50 mJ/m^2",
    "cutoff": "30 nm",
}
IN_M = {
    "size": "6.4e-7 m",
    "rms": "1.5e-9 m",
    "ra": "1.45e-9 m",
    "ra_b": "1.7e-9 m",
    "radius": "1e-6 m",
    "tip_rms": "3e-10 m",
    "load": "1e-5 N",
    "layer": "5e-8 m",
    "epsilon": "2e-9 m",
    "energy": "0.05 J/m^2",
    "cutoff": "3e-8 m",
}


def test_mu_does_not_depend_on_the_units_the_study_is_written_in(tmp_path):
    mu = {}
    for name, values in (("nm", IN_NM), ("m", IN_M)):
        path = tmp_path / f"{name}.toml"
        path.write_text(UNITS.format(**values))
        output = tmp_path / f"out-{name}"
        summary = run_study(load_study(path), output)
        assert summary.done == 4 and summary.failed == 0
        mu[name] = {
            (row["sample"], row["replicate"]): float(row["mu"]) for row in read_table(output / "results.csv")
        }
    assert mu["nm"].keys() == mu["m"].keys() and len(mu["nm"]) == 4
    for key, value in mu["nm"].items():
        assert value == pytest.approx(mu["m"][key], rel=1e-9, abs=0.0), key
    assert len(set(mu["nm"].values())) == 4  # four different scans, so the check compares four cases


def test_the_reported_csv_is_labelled_and_has_seven_values_per_sample(examples):
    text = (examples / "paper000_reported_mu.csv").read_text()
    assert text.startswith("# origin: reconstructed\n# by construction: ")
    measured = read_measured(examples / "paper000_reported_mu.csv")
    assert measured.origin.word == "reconstructed" and measured.origin.by_construction
    assert list(measured) == SAMPLES
    assert all(values.size == 7 for values in measured.values())


# --- comparison with a load sweep ------------------------------------------------------------------

SWEPT = (
    SCAN_AND_TIP
    + FRICTION_OVER_TWO_LOADS
    + """replicate = [0, 1, 2]
sample = ["a", "b"]
[analysis.compare]
measured = "measured.csv"
{load}
"""
)


def test_a_load_sweep_is_compared_at_the_load_of_the_measurements(tmp_path, caplog):
    from roughcontact.study.outputs import draw_figures, write_tables

    (tmp_path / "measured.csv").write_text(
        "# test values\nsample,mu\n" + "".join(f"{s},{0.5 + 0.1 * k}\n" for s in "abc" for k in range(4))
    )
    path = tmp_path / "with.toml"
    path.write_text(SWEPT.format(load='normal_force = "10 uN"'))
    output = tmp_path / "with"
    assert run_study(load_study(path), output).done == 12
    with caplog.at_level("WARNING"):
        write_tables(output)
    assert "['c']" in caplog.text  # measured only: left out, and said
    table = read_table(output / "tables" / "friction_comparison.csv")
    assert [row["sample"] for row in table] == ["a", "b"]
    rows = read_table(output / "results.csv")
    measured = read_measured(tmp_path / "measured.csv")
    for row in table:
        at_10 = [
            float(r["mu"])
            for r in rows
            if r["sample"] == row["sample"]
            and math.isclose(float(r["normal_force [N]"]), 1e-5, rel_tol=1e-12)
        ]
        assert len(at_10) == int(row["n_simulated"]) == 3
        expected = stats.ttest_ind(at_10, measured[row["sample"]], equal_var=False).pvalue
        assert float(row["p_value"]) == pytest.approx(expected, rel=1e-12)
    by_sample = read_table(output / "tables" / "friction_by_sample.csv")
    assert [(r["sample"], float(r["normal_force [N]"]), int(r["n"])) for r in by_sample] == [
        ("a", 5e-6, 3),
        ("a", 1e-5, 3),
        ("b", 5e-6, 3),
        ("b", 1e-5, 3),
    ]

    path.write_text(SWEPT.format(load=""))  # two loads and no compare.normal_force: no comparison, said
    output = tmp_path / "without"
    run_study(load_study(path), output)
    _, problems = write_tables(output)
    assert not (output / "tables" / "friction_comparison.csv").exists()
    assert any("compare.normal_force" in problem for problem in problems)
    written, problems = draw_figures(output)
    assert {p.name for p in written} == {"friction_friction_vs_load.png"}
    assert len(problems) == 2 and all("compare.normal_force" in p for p in problems)
    stale = output / "tables" / "friction_comparison.csv"  # left by an earlier run of other settings
    stale.write_text("sample,p_value\na,0.5\n")
    write_tables(output)
    assert not stale.exists()  # a table this run could not make is not shown as if it were current


def test_tables_of_an_analysis_of_several_readings_keep_them_apart(tmp_path):
    from roughcontact.study.outputs import write_tables

    text = SCAN_AND_TIP + FRICTION_OVER_TWO_LOADS.replace("[analysis.sweep]", "[analysis.zip]")
    text += 'replicate = [0, 1, 0, 1]\nreading = ["default", "default", "paper", "paper"]\n'
    text = text.replace('normal_force = ["5 uN", "10 uN"]\n', "")
    path = tmp_path / "readings.toml"
    path.write_text(text)
    output = tmp_path / "out"
    assert run_study(load_study(path), output).done == 4
    write_tables(output)
    by_sample = read_table(output / "tables" / "friction_by_sample.csv")
    assert [(row["reading"], int(row["n"])) for row in by_sample] == [("default", 2), ("paper", 2)]
    mu = {row["reading"]: float(row["mu_mean"]) for row in by_sample}
    assert mu["paper"] > 1.2 * mu["default"]


def test_fields_beyond_the_size_limit_are_not_stored(tmp_path, monkeypatch):
    from roughcontact.study.kinds import friction

    path = tmp_path / "direct.toml"
    path.write_text(DIRECT.format(load="7 uN", extra=""))
    study = load_study(path)
    task = make_task(study, study.cases[0])
    stored = friction.run(task.parameters, task.inputs)
    points = stored.dataset.sizes["x"] * stored.dataset.sizes["y"]
    monkeypatch.setattr(friction, "FIELD_POINTS", points - 1)
    output = friction.run(task.parameters, task.inputs)
    assert output.dataset is None and output.scalars == stored.scalars
