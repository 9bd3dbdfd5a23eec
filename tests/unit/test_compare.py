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
    assert EXAMPLE.read_text().splitlines()[0] == "# origin: synthetic"
    assert values.origin.word == "synthetic" and values.origin.by_construction
    bad = tmp_path / "bad.csv"
    bad.write_text("sample,mu\na,0.3\na,high\n")
    with pytest.raises(InputError, match="row 2"):
        read_measured(bad)
    bad.write_text("name,value\na,1\n")
    with pytest.raises(InputError, match="columns"):
        read_measured(bad)
    with pytest.raises(InputError, match="does not exist"):
        read_measured(tmp_path / "missing.csv")
    bad.write_text("sample,mu\na,0.3\na,-0.2\n")
    with pytest.raises(InputError, match="row 2: mu -0.2 is negative") as refused:
        read_measured(bad)
    assert refused.value.field == "measured" and "half difference" in refused.value.fix
    bad.write_text("# origin: simulated by hand\nsample,mu\na,0.3\na,0.2\n")
    with pytest.raises(InputError, match="origin: simulated by hand") as refused:
        read_measured(bad)
    assert "'# origin: synthetic'" in refused.value.fix


def _values(tmp_path, header: str):
    path = tmp_path / "mu.csv"
    path.write_text(header + "sample,mu\na,0.30\na,0.32\na,0.31\nb,0.40\nb,0.42\nb,0.43\n")
    return read_measured(path)


@pytest.mark.parametrize(
    ("header", "word", "built"),
    [
        ("", "measured", None),
        ("# friction loops, AFM, 2026-10-01\n", "measured", None),
        ("# origin: measured\n# a synthetic tip was not used\n", "measured", None),
        ("# origin: Synthetic\n", "synthetic", None),
        ("# made with a synthetic surface generator\n", "synthetic", None),
        (
            "# Origin: reconstructed\n# By construction: our simulation, seed 3\n",
            "reconstructed",
            "our simulation, seed 3",
        ),
    ],
)
def test_the_origin_comes_from_the_header(tmp_path, header, word, built):
    origin = _values(tmp_path, header).origin
    assert origin.word == word and origin.by_construction == built
    assert origin.declared == ("origin:" in header.lower())


def test_a_comparison_names_its_data_and_gives_no_verdict_by_construction(tmp_path):
    simulated = {"a": [0.30, 0.31, 0.33], "b": [0.41, 0.40, 0.44]}
    measured = compare(simulated, _values(tmp_path, ""))
    assert [row["verdict"] for row in measured.table()] == [
        "agrees: p > 0.1" if s.p_value > 0.1 else "differs: p <= 0.1" for s in measured.samples
    ]
    assert "measured_mean" in measured.table()[0] and measured.notes() == ["Compared with measured values."]
    synthetic = compare(simulated, _values(tmp_path, "# origin: synthetic\n"))
    row = synthetic.table()[0]
    assert "synthetic_mean" in row and "n_synthetic" in row and "measured_mean" not in row
    assert synthetic.samples[0].agrees in (True, False)
    assert "validates nothing" in " ".join(synthetic.notes())
    built = compare(simulated, _values(tmp_path, "# origin: reconstructed\n# by construction: ours\n"))
    assert built.by_construction and all(s.agrees is None for s in built.samples)
    assert all(row["verdict"].startswith("by construction: no verdict") for row in built.table())
    assert "reconstructed_mean" in built.table()[0]
    notes = " ".join(built.notes())
    assert "values reconstructed from reported statistics" in notes and "not a validation" in notes
    fig, ax = plot_mu_boxes(built)
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        "simulated",
        "reconstructed from reported statistics (built from this model)",
    ]
    assert "by construction" in ax.get_title() and "measured" not in ax.get_title()
    fig, ax = plot_mu_means(synthetic)
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["simulated", "synthetic"]


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
    from roughcontact.papers.paper000 import paper000_options
    from roughcontact.winkler_lj import winkler_lj_model

    model = winkler_lj_model(
        paper000_scans(1.7e-9, count=1, shape=48)[0],
        get_material("polysilicon"),
        get_material("SiO2"),
        options=paper000_options(),
        counter_topography=paper000_tip(shape=48),
    )
    sweep = model.sweep([1e-6, 1e-5, 1e-4])
    fig, ax = plot_friction_vs_load(sweep, crossover=model.crossover_load())
    assert len(ax.get_lines()) == 4
