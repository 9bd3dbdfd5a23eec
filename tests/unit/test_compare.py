"""Simulated vs measured friction: t-tests, Pearson r, the CSV reader, the paper-000 case and figures."""

from pathlib import Path

import numpy as np
import pytest
from scipy import stats

from roughcontact.errors import InputError
from roughcontact.experiment import compare, read_measured
from roughcontact.papers.paper000 import paper000_scans, paper000_simulation, paper000_tip
from roughcontact.plotting import plot_friction_vs_load, plot_mu_boxes, plot_mu_means
from roughcontact.topography.statistics import ra

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "paper000_measured_mu.csv"

SIMULATED = {"a": [0.30, 0.32, 0.31, 0.29], "b": [0.40, 0.41, 0.43, 0.39], "c": [0.50, 0.52, 0.49, 0.51]}
MEASURED = {"a": [0.31, 0.33, 0.30, 0.28], "b": [0.45, 0.47, 0.44, 0.46], "c": [0.50, 0.53, 0.48, 0.52]}


def test_compare_matches_scipy():
    result = compare(SIMULATED, MEASURED)
    for row in result.samples:
        expected = stats.ttest_ind(SIMULATED[row.sample], MEASURED[row.sample], equal_var=False)
        assert row.p_value == pytest.approx(expected.pvalue, rel=1e-12)
        assert row.agrees == (row.p_value > 0.1)
    means = np.array([[np.mean(SIMULATED[k]), np.mean(MEASURED[k])] for k in SIMULATED])
    assert result.pearson_r == pytest.approx(stats.pearsonr(means[:, 0], means[:, 1]).statistic, rel=1e-12)
    student = compare(SIMULATED, MEASURED, equal_var=True)
    assert student.samples[1].p_value == pytest.approx(
        stats.ttest_ind(SIMULATED["b"], MEASURED["b"]).pvalue, rel=1e-12
    )
    assert [row["sample"] for row in result.table()] == ["a", "b", "c"]


def test_compare_refuses_mismatched_or_short_samples():
    with pytest.raises(InputError, match="measured"):
        compare(SIMULATED, {"a": [0.3, 0.3]})
    with pytest.raises(InputError, match="simulated"):
        compare({"a": [0.3]}, {"a": [0.3, 0.4]})


def test_identical_constant_samples_agree_without_nan():
    result = compare({"a": [0.3, 0.3]}, {"a": [0.3, 0.3]})
    assert result.samples[0].p_value == 1.0 and result.pearson_r == 0.0


def test_read_measured_skips_comments_and_refuses_bad_rows(tmp_path):
    values = read_measured(EXAMPLE)
    assert list(values) == ["Ra 1.45 nm", "Ra 1.49 nm", "Ra 1.7 nm"]
    assert all(len(v) == 7 for v in values.values())
    assert "SYNTHETIC" in EXAMPLE.read_text().splitlines()[0]
    bad = tmp_path / "bad.csv"
    bad.write_text("sample,mu\na,0.3\na,high\n")
    with pytest.raises(InputError, match="row 2"):
        read_measured(bad)
    bad.write_text("name,value\na,1\n")
    with pytest.raises(InputError, match="columns"):
        read_measured(bad)
    with pytest.raises(InputError, match="does not exist"):
        read_measured(tmp_path / "missing.csv")


def test_paper000_case_inputs():
    scans = paper000_scans(1.7e-9, count=2, shape=32, seed=4)
    assert len(scans) == 2 and scans[0].spacing == pytest.approx((20e-9, 20e-9), rel=1e-12)
    assert ra(scans[1]) == pytest.approx(1.7e-9, rel=1e-12)
    assert paper000_tip(shape=32).heights.max() <= 5e-9


def test_paper000_simulation_and_figures():
    simulated = paper000_simulation(count=3, shape=48)
    assert list(simulated) == ["Ra 1.45 nm", "Ra 1.49 nm", "Ra 1.7 nm"]
    assert all(np.all(np.isfinite(v)) and v.size == 3 for v in simulated.values())
    comparison = compare(simulated, {k: v * 1.01 for k, v in simulated.items()})
    for plot in (plot_mu_boxes, plot_mu_means):
        fig, ax = plot(comparison)
        assert ax.get_ylabel()
    from roughcontact.materials import get_material
    from roughcontact.papers.paper000 import paper000_model_options
    from roughcontact.winkler_lj import winkler_lj_model

    model = winkler_lj_model(
        paper000_scans(1.7e-9, count=1, shape=48)[0],
        get_material("polysilicon"),
        get_material("SiO2"),
        counter_topography=paper000_tip(shape=48),
        **paper000_model_options(),
    )
    sweep = model.sweep([1e-6, 1e-5, 1e-4])
    fig, ax = plot_friction_vs_load(sweep, crossover=model.crossover_load())
    assert len(ax.get_lines()) == 4
