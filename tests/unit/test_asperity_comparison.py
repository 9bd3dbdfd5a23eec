"""KKE against the BEM's realisations at the level of paper 002's claim: one island, the mean beside it.

``asperity.comparison.against_realisations`` and the ``against_statistical`` table of the
``load_unload`` kind built from stored-like records (no solve): the verdict for one island rests on
the prediction interval of one realisation, the mean's on its confidence interval; the ratio
KKE / BEM carries each interval through x -> KKE / x, so it holds 1 exactly where the verdict is
"not established"; paper 002's words stand beside it; an earlier store is said, not misread.
"""

import math
from types import SimpleNamespace

import numpy as np
import pytest
from scipy import stats

from roughcontact.asperity.comparison import against_realisations
from roughcontact.papers.paper002 import STATISTICAL_WORDS
from roughcontact.study.kinds.load_unload import _against_statistical
from roughcontact.study.store import notes_of

# Five islands' peak interferences [m] and a statistical peak above their mean's interval but
# inside the prediction interval of one more island (the case of paper002.toml's run).
BEM = [30e-9, 45e-9, 39e-9, 50e-9, 31e-9]
KKE = 56.4e-9
ONE, MEAN = "one island (prediction interval)", "the mean (confidence interval)"


def _student(values, factor):
    values = np.asarray(values)
    t = stats.t.ppf(0.975, values.size - 1)
    half = t * values.std(ddof=1) * factor
    return values.mean() - half, values.mean() + half


def test_one_island_is_judged_with_the_prediction_interval_and_the_mean_with_its_own():
    found = against_realisations(KKE, BEM, quantity="peak_interference")
    low, high = _student(BEM, math.sqrt(1 + 1 / 5))
    assert found.one.interval == pytest.approx((low, high), rel=1e-12)
    assert low < KKE < high
    assert found.one.word == "not established" and found.model_words("one") == "not established"
    mean_low, mean_high = _student(BEM, math.sqrt(1 / 5))
    assert found.mean.interval == pytest.approx((mean_low, mean_high), rel=1e-12)
    assert mean_high < KKE
    assert found.mean.word == "below" and found.model_words("mean") == "over-predicts"
    assert found.claim("one") == "that KKE over-predicts one island is not established"
    assert found.claim("mean") == "KKE over-predicts the mean"


def test_ratio_is_kke_over_the_bem_mean_with_each_interval_carried_through():
    found = against_realisations(KKE, BEM, quantity="peak_interference")
    assert found.ratio == pytest.approx(KKE / np.mean(BEM), rel=1e-12)
    for of in ("one", "mean"):
        low, high = found.verdict(of).interval
        assert found.ratio_interval(of) == pytest.approx((KKE / high, KKE / low), rel=1e-12)
    # the ratio's interval holds 1 exactly where the verdict is "not established"
    assert found.ratio_interval("one")[0] < 1 < found.ratio_interval("one")[1]
    assert found.ratio_interval("mean")[0] > 1


@pytest.mark.parametrize(
    ("statistical", "one", "mean"),
    [
        (80e-9, "over-predicts", "over-predicts"),  # above both intervals
        (40e-9, "not established", "not established"),  # inside both
        (5e-9, "under-predicts", "under-predicts"),  # below both
    ],
)
def test_the_verdict_follows_where_the_statistical_value_lies(statistical, one, mean):
    found = against_realisations(statistical, BEM, quantity="peak_interference")
    assert (found.model_words("one"), found.model_words("mean")) == (one, mean)
    for of in ("one", "mean"):
        low, high = found.ratio_interval(of)
        assert (low <= 1 <= high) == (found.verdict(of).word == "not established")


def test_intervals_of_a_positive_quantity_stop_at_zero_and_the_ratio_becomes_unbounded():
    found = against_realisations(20e-9, [1e-9, 30e-9], quantity="peak_interference")  # wide: n = 2
    assert found.one.interval[0] == 0.0 and found.mean.interval[0] == 0.0
    assert found.deterministic.note  # says the interval was cut
    assert found.ratio_interval("one")[1] == math.inf
    assert found.model_words("one") == "not established"


def test_sentence_says_both_levels_the_ratio_and_the_papers_words():
    found = against_realisations(KKE, BEM, quantity="peak_interference")
    text = found.sentence(lambda v: f"{v * 1e9:.3g} nm", words=STATISTICAL_WORDS)
    assert "KKE's peak interference 56.4 nm is 1.45 times the BEM mean 39 nm (n = 5)" in text
    assert "inside the 95 % prediction interval of one island" in text
    assert "that KKE over-predicts one island is not established" in text
    assert "above the 95 % confidence interval of the mean" in text
    assert 'Paper 002\'s words: "KKE slightly over-predicts".' in text


def test_one_realisation_gives_no_verdict():
    found = against_realisations(KKE, [40e-9], quantity="peak_interference")
    assert found.one.word == "one realisation" and math.isnan(found.ratio_interval("one")[0])
    assert "no interval, no verdict" in found.sentence(str)


# --- the table of the load_unload kind --------------------------------------------------------------


def _bem(replicate, peak, back):
    scalars = {
        "peak_interference": peak,
        "interference_at_return_force": back,
        "residual_interference": -5e-9,
    }
    return SimpleNamespace(
        scalars=scalars,
        parameters={"replicate": replicate, "plasticity": "surface", "topography": "island"},
        label=f"replicate {replicate}",
    )


def _context(kke_scalars, paper002=True):
    kke = SimpleNamespace(
        scalars={"critical_interference": 12.5e-9, **kke_scalars},
        parameters={"law": "kogut_etsion", "paper002": paper002},
    )
    return SimpleNamespace(others={"kke": ("asperity", [kke])}, analysis="bem")


def test_table_judges_one_island_and_the_mean_with_ratio_and_the_papers_words():
    records = [_bem(i, peak, 0.3 * peak) for i, peak in enumerate(BEM)]
    context = _context({"peak_interference": KKE, "interference_at_return_force": 14e-9})
    table = _against_statistical(records, context)
    rows = {(row["quantity"], row["judged for"]): row for row in table}
    assert set(rows) == {
        (quantity, level)
        for quantity in ("peak_interference", "interference_at_return_force")
        for level in (ONE, MEAN)
    }
    one, mean = rows["peak_interference", ONE], rows["peak_interference", MEAN]
    found = against_realisations(KKE, BEM, quantity="peak_interference")
    assert one["statistical model"] == "not established" and mean["statistical model"] == "over-predicts"
    assert (one["bem 95% low [m]"], one["bem 95% high [m]"]) == pytest.approx(found.one.interval, rel=1e-12)
    assert (mean["bem 95% low [m]"], mean["bem 95% high [m]"]) == pytest.approx(
        found.mean.interval, rel=1e-12
    )
    assert one["statistical / bem"] == pytest.approx(KKE / np.mean(BEM), rel=1e-12)
    assert one["statistical / bem 95% low"] < 1 < one["statistical / bem 95% high"]
    assert mean["statistical / bem 95% low"] > 1
    assert one["statistical / omega_c"] == pytest.approx(KKE / 12.5e-9, rel=1e-12)
    assert all(row["paper's words"] == "slightly over-predicts" for row in table)
    assert all(row["n"] == 5 and row["bem"] == "bem (surface plasticity)" for row in table)
    # the return point: KKE's 14 nm against the BEM's at the same load (not its zero-load residual)
    back = rows["interference_at_return_force", MEAN]
    assert back["bem mean [m]"] == pytest.approx(0.3 * np.mean(BEM), rel=1e-12)
    notes = notes_of(table)
    assert len(notes) == 2 and "that KKE over-predicts one island is not established" in notes[0]


def test_papers_words_only_for_paper_002_cases():
    records = [_bem(i, peak, 0.3 * peak) for i, peak in enumerate(BEM)]
    context = _context({"peak_interference": KKE, "interference_at_return_force": 14e-9}, paper002=False)
    assert all(row["paper's words"] == "" for row in _against_statistical(records, context))


def test_an_earlier_store_is_said_not_compared_under_the_old_name():
    """Before the rename the statistical model's return point was stored as residual_interference."""
    records = [_bem(i, peak, 0.3 * peak) for i, peak in enumerate(BEM)]
    context = _context({"peak_interference": KKE, "residual_interference": 14e-9})
    table = _against_statistical(records, context)
    assert {row["quantity"] for row in table} == {"peak_interference"}
    assert any("stored by an earlier roughcontact" in note for note in notes_of(table))


def test_an_interval_reaching_zero_leaves_the_ratio_unbounded_not_negative():
    """The BEM's interference back at 25 uN scatters about a nanometre: its interval stops at 0."""
    records = [
        _bem(i, peak, back)
        for i, (peak, back) in enumerate(zip(BEM, [0.1e-9, 3e-9, 0.5e-9, 1e-9, 2e-9], strict=True))
    ]
    context = _context({"peak_interference": KKE, "interference_at_return_force": 14e-9})
    back = [
        row
        for row in _against_statistical(records, context)
        if row["quantity"] == "interference_at_return_force"
    ]
    assert [row["bem 95% low [m]"] for row in back] == [0.0, 0.0]
    assert all(row["statistical / bem 95% high"] is None for row in back)  # shown as unbounded, never inf
    assert all(
        row["statistical / bem 95% low"] > 1 and row["statistical model"] == "over-predicts" for row in back
    )
