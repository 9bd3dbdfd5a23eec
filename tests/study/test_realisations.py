"""Realisations as an axis of a study: N independent draws per case, and the spread of every scalar."""

import csv
import math
import tomllib

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from roughcontact.spread import spread
from roughcontact.study import answer
from roughcontact.study.config import StudyError, build_study
from roughcontact.study.outputs import spread_rows

STUDY = """
[study]
name = "realisations"
seed = 3

[topographies.scan]
generate = "self_affine"
shape = 32
size = "2 um"
hurst = 0.8
rms_height = "5 nm"

[[analysis]]
name = "contact"
model = "normal"
topography = "scan"
material = "polysilicon"
realisations = 4

[analysis.sweep]
mean_pressure = ["10 MPa", "40 MPa"]
"""


def _study(tmp_path, text=STUDY):
    return build_study(tomllib.loads(text), folder=tmp_path, text=text, source="realisations")


# --- the summary of one quantity -------------------------------------------------------------------


def test_spread_of_a_known_sample():
    values = [1.0, 2.0, 3.0, 4.0, 5.0]
    s = spread(values)
    assert (s.n, s.mean, s.min, s.max) == (5, 3.0, 1.0, 5.0)
    assert s.std == pytest.approx(math.sqrt(2.5), rel=1e-14)
    # Student's t_{0.975, 4} = 2.7764451051977987 (tables)
    assert s.half_width == pytest.approx(2.7764451051977987 * math.sqrt(2.5) / math.sqrt(5), rel=1e-12)


def test_spread_interval_covers_the_true_mean_at_its_level():
    """Over many normal samples of 5, the 95 % interval of the mean holds the true mean 95 % of the time."""
    rng = np.random.default_rng(0)
    trials = 4000
    covered = sum(
        s.ci95_low <= 10.0 <= s.ci95_high for s in (spread(rng.normal(10.0, 2.0, 5)) for _ in range(trials))
    )
    assert covered / trials == pytest.approx(0.95, abs=3 * math.sqrt(0.95 * 0.05 / trials))


def test_spread_leaves_out_undefined_values_and_says_one_value_has_no_scatter():
    s = spread([2.0, math.nan, math.inf])
    assert s.n == 1 and s.mean == 2.0 and math.isnan(s.std) and math.isnan(s.ci95_low)
    assert spread([]).n == 0 and math.isnan(spread([]).mean)


@settings(max_examples=50, deadline=None)
@given(st.lists(st.floats(-1e6, 1e6, allow_nan=False), min_size=2, max_size=30))
def test_spread_is_ordered(values):
    s = spread(values)
    rounding = 1e-12 * max(abs(v) for v in values)  # the mean of equal values may round past them
    assert s.min - rounding <= s.mean <= s.max + rounding
    assert s.ci95_low - rounding <= s.mean <= s.ci95_high + rounding
    assert s.std >= 0


# --- the study key ----------------------------------------------------------------------------------


def test_realisations_make_cases_with_their_own_draws(tmp_path):
    study = _study(tmp_path)
    (analysis,) = study.analyses
    assert len(analysis.cases) == 8 and analysis.realisations == 4
    assert [c.parameters.replicate for c in analysis.cases] == [0, 1, 2, 3] * 2
    assert len({c.seeds["scan"] for c in analysis.cases}) == 4  # one draw per realisation ...
    assert analysis.cases[0].seeds == analysis.cases[4].seeds  # ... the same at every load
    assert analysis.redrawn == ("scan",) and analysis.drawn_once == ()
    assert analysis.sweep_axes == ("mean_pressure",)


def test_spread_table_per_load_over_the_realisations(tmp_path):
    result = answer(_study(tmp_path), tmp_path / "out")
    rows = spread_rows(result.analyses[0])
    approach = [r for r in rows if r["quantity"] == "approach"]
    assert len(approach) == 2 and all(r["n"] == 4 and r["unit"] == "m" for r in approach)
    records = [r for r in result.analyses[0].records if r.parameters["mean_pressure"] == 10e6]
    expected = spread(r.scalars["approach"] for r in records)
    assert approach[0]["mean"] == expected.mean and approach[0]["ci95_high"] == expected.ci95_high
    assert not [r for r in rows if r["quantity"] == "force"]  # the control does not depend on the draw
    with (tmp_path / "out" / "tables" / "contact_spread.csv").open() as handle:
        stored = list(csv.DictReader(handle))
    assert len(stored) == len(rows)
    lines = "\n".join(result.text_lines())
    assert "spread over 4 realisations" in lines and "Each setting ran on 4 realisations" in lines
    assert "Each setting ran on 4 realisations" in (tmp_path / "out" / "report.html").read_text()


def test_a_partly_run_ensemble_resumes(tmp_path):
    answer(_study(tmp_path, STUDY.replace("realisations = 4", "realisations = 2")), tmp_path / "out")
    more = answer(_study(tmp_path), tmp_path / "out", resume=True)
    assert (more.summary.skipped, more.summary.done) == (4, 4)
    assert {r.parameters["replicate"] for r in more.analyses[0].records} == {0, 1, 2, 3}


def test_one_draw_says_so(tmp_path):
    result = answer(_study(tmp_path, STUDY.replace("realisations = 4", "")))
    assert not spread_rows(result.analyses[0])
    assert any(
        "rests on one realisation of the generated surface(s) scan" in line for line in result.text_lines()
    )


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ("realisations = 0", "expected a whole number >= 1"),
        ("realisations = 2.5", "expected a whole number >= 1"),
        ("realisations = 4\nsweep.replicate = [0, 1]", "replicate is swept"),
    ],
)
def test_realisations_refused(tmp_path, change, message):
    text = STUDY.replace("realisations = 4", change).replace(
        "[analysis.sweep]\nmean_pressure", "sweep.mean_pressure"
    )
    with pytest.raises(StudyError, match=message):
        _study(tmp_path, text)


def test_realisations_of_a_fixed_seed_are_refused(tmp_path):
    text = STUDY.replace('rms_height = "5 nm"', 'rms_height = "5 nm"\nseed = 7')
    with pytest.raises(
        StudyError, match="every realisation would draw the same surfaces.*scan have a fixed seed"
    ):
        _study(tmp_path, text)


# --- figures of realisations ------------------------------------------------------------------------


def test_cases_are_grouped_by_all_but_their_realisation():
    from roughcontact.cases import realisations_of
    from roughcontact.plotting.cases import ResultCase

    cases = [
        ResultCase(f"force 10 uN, replicate {r}", {}, None, {"force": 1e-5, "replicate": r}) for r in range(3)
    ] + [ResultCase("force 20 uN, replicate 0", {}, None, {"force": 2e-5, "replicate": 0})]
    groups = realisations_of(cases)
    assert list(groups) == ["force 10 uN", "force 20 uN"]
    assert [len(g) for g in groups.values()] == [3, 1]


def test_mean_load_interference_curve_and_its_range():
    from roughcontact.plotting.asperity import _mean_curve

    force = np.array([0.0, 1e-4, 2e-4, 1e-4, 0.0])
    branch = np.array(["loading"] * 3 + ["unloading"] * 2)
    curves = [
        {"force": force * (1 + 1e-7 * k), "branch": branch, "approach": np.arange(5.0) * (k + 1)}
        for k in range(3)
    ]
    mean = _mean_curve(curves)
    np.testing.assert_allclose(mean["approach"], np.arange(5.0) * 2)
    np.testing.assert_allclose(mean["approach_min"], np.arange(5.0))
    np.testing.assert_allclose(mean["approach_max"], np.arange(5.0) * 3)
    other = {"force": force[:4], "branch": branch[:4], "approach": np.arange(4.0)}
    assert _mean_curve([curves[0], other]) is curves[0]  # other programmes: no mean is made up


def test_prediction_interval_of_one_more_realisation():
    s = spread([1.0, 2.0, 3.0, 4.0, 5.0])
    low, high = s.prediction()
    half = 2.7764451051977987 * math.sqrt(2.5) * math.sqrt(1 + 1 / 5)
    assert (low, high) == (pytest.approx(3.0 - half, rel=1e-12), pytest.approx(3.0 + half, rel=1e-12))
    assert all(math.isnan(v) for v in spread([1.0]).prediction())


def test_one_measured_loop_against_the_realisations_scatter():
    from roughcontact.study.kinds.presliding import _realisations_row

    simulated = [
        {"sample": "HDPE", "normal_force [N]": 0.025} | {f"K_L_{p} [N/m]": value for p in "ABC"}
        for value in (30e3, 35e3, 40e3, 45e3, 50e3)
    ]
    row = _realisations_row(simulated, {"A": 40e3, "B": 80e3, "C": 20e3})  # 40 +- 24.0 kN/m
    assert row["K_L_A [N/m]"] == pytest.approx(40e3) and row["K_L_B simulated / measured"] == pytest.approx(
        0.5
    )
    inside = "measured in the realisations' 95% prediction"
    assert (row[f"K_L_A {inside}"], row[f"K_L_B {inside}"], row[f"K_L_C {inside}"]) == (True, False, True)


def test_area_load_with_realisations_draws_means_and_intervals():
    from roughcontact.plotting.cases import ResultCase
    from roughcontact.plotting.contact import area_load_figure

    cases = [
        ResultCase(
            f"p={p}, replicate={r}",
            {"mean_pressure": p, "contact_fraction": 0.01 * p / 1e6 + 0.002 * r},
            None,
            {"mean_pressure": p, "replicate": r},
        )
        for p in (10e6, 40e6)
        for r in range(4)
    ]
    ax = area_load_figure(cases).axes[0]
    (label,) = [t.get_text() for t in ax.get_legend().get_texts()]
    assert label == "mean ± 95 % CI of 4 realisations"
    mean_line = ax.get_lines()[0]
    np.testing.assert_allclose(mean_line.get_ydata(), [10.3, 40.3])  # % of nominal: 0.1 + 0.003 mean


def test_measured_spots_of_one_sample_are_its_realisations(tmp_path):
    """Files zipped with replicate: one group per sample and load, its spread over the files."""
    from roughcontact.topography import generate
    from roughcontact.topography.native import save_topography

    for number in range(3):
        scan = generate.self_affine((32, 32), 2e-6, hurst=0.8, rms_height=5e-9, seed=10 + number)
        save_topography(scan, tmp_path / f"spot{number}.nc")
    text = STUDY.replace(
        'generate = "self_affine"\nshape = 32\nsize = "2 um"\nhurst = 0.8\nrms_height = "5 nm"',
        'file = "spot0.nc"\nperiodic = true',
    ).replace(
        "realisations = 4",
        "[analysis.zip]\nreplicate = [0, 1, 2]\n"
        '"topographies.scan.file" = ["spot0.nc", "spot1.nc", "spot2.nc"]',
    )
    result = answer(_study(tmp_path, text), tmp_path / "out")
    approach = [r for r in spread_rows(result.analyses[0]) if r["quantity"] == "approach"]
    assert len(approach) == 2 and all(r["n"] == 3 for r in approach)  # per load, over the three spots


def test_cases_on_different_grids_are_not_realisations_of_one_another():
    # a mesh study sweeps a topography key: the cases' parameters name the surface only, the grid
    # is in their swept values; merging them drew paper002_mesh.toml's 6 grids x 3 draws as "18 realisations"
    from roughcontact.cases import realisations_of
    from roughcontact.study.kind import CaseRecord

    def record(shape, replicate):
        axes = {"topographies.island.shape": shape, "replicate": replicate}
        return CaseRecord(
            {"axes": axes, "parameters": {"topography": "island", "replicate": replicate}}, None
        )

    groups = realisations_of([record(shape, r) for shape in (64, 96) for r in range(3)])
    assert list(groups) == ["shape 64", "shape 96"]
    assert [len(g) for g in groups.values()] == [3, 3]
