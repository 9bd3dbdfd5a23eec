"""Paper 001's verdict at the level of its claim: one rough ball against Mindlin's smooth ball (issue 44).

The claim (the rough ball is laterally softer than Mindlin's) is about one ball, so the table judges
the 95 % prediction interval of one more stand-in ball, the mean's interval beside it; a verdict
that eq. 12's printed factor 4 decides says so. Records with POM-like and HDPE-like ratios (those
the filer measured: POM 0.79-1.01 under Johnson's Mindlin, HDPE 0.47-0.64) make the table without
a solve.
"""

from dataclasses import dataclass, field
from typing import Any

import matplotlib
import pytest

from roughcontact.plotting.presliding import MeasuredLoop, lateral_stiffness_figure
from roughcontact.spread import spread
from roughcontact.study.kinds.presliding import KIND
from roughcontact.study.store import notes_of

matplotlib.use("Agg")

MINDLIN = 60e3
"""Johnson's Mindlin K_L of every record [N/m]; as printed it is 4x."""
POM = (0.80, 0.85, 0.90, 0.95, 1.00)
"""Johnson ratios of five POM stand-in balls: their mean's interval lies below 1, one ball's does not."""
HDPE = (0.47, 0.52, 0.55, 0.60, 0.64)
"""Johnson ratios of five HDPE stand-in balls: below 1 for one ball too."""
LOADS = (0.025, 0.05, 0.075)


@dataclass
class Record:
    """A stored case as the tables and figures read it."""

    scalars: dict[str, Any]
    parameters: dict[str, Any]
    label: str
    case: str
    data: dict[str, Any] = field(default_factory=dict)
    has_fields: bool = False

    def __getitem__(self, key: str) -> Any:
        return {"case": self.case}[key]

    def dataset(self):
        return None


def records(samples=(("POM", POM), ("HDPE", HDPE))) -> list[Record]:
    """Five stand-in balls per sample and load, K_L = ratio x Mindlin at A, B and C."""
    made = []
    for sample, ratios in samples:
        for force in LOADS:
            for replicate, ratio in enumerate(ratios):
                scalars = {"normal_force": force, "table2_rq": 1e-6, "window_pixels": 150 + replicate}
                scalars["window_choice"] = "auto: 150 px"
                for point in "ABC":
                    scalars[f"K_L_{point}"] = ratio * MINDLIN
                    scalars[f"K_L_{point}_mindlin_johnson"] = MINDLIN
                    scalars[f"K_L_{point}_mindlin_printed"] = 4 * MINDLIN
                label = f"sample {sample}, normal force {force * 1e3:g} mN, replicate {replicate}"
                parameters = {"sample": sample, "normal_force": force, "replicate": replicate}
                parameters |= {"material": sample, "counter_body": "silicon wafer", "radius": 5e-3}
                made.append(Record(scalars, parameters, label, f"{sample}{force}{replicate}"))
    return made


def test_one_ball_is_judged_by_the_prediction_interval_and_the_factor_4_is_named():
    table = KIND.tables["lateral_stiffness_spread"](records(), None)
    assert len(table) == 2 * len(LOADS) * 3
    pom = [row for row in table if row["sample"] == "POM"]
    hdpe = [row for row in table if row["sample"] == "HDPE"]
    expected = spread(POM, bounds=(0.0, float("inf")))
    for row in pom:
        # the mean's interval lies below 1, but one ball's prediction interval holds it
        assert row["K_L / mindlin_johnson mean 95% high"] < 1 < row["K_L / mindlin_johnson one ball 95% high"]
        assert (
            row["K_L / mindlin_johnson one ball 95% low"],
            row["K_L / mindlin_johnson one ball 95% high"],
        ) == (pytest.approx(expected.prediction()))
        assert row["K_L / mindlin_johnson mean 95% low"] == pytest.approx(expected.ci95_low)
        assert row["rough vs smooth, one ball (johnson)"] == "not established"
        assert row["rough vs smooth, one ball (printed)"] == (
            "below (decided by eq. 12's printed factor 4: with Johnson's Mindlin not established)"
        )
    for row in hdpe:  # roughness decides HDPE: below in both readings, no factor named
        assert row["K_L / mindlin_johnson one ball 95% high"] < 1
        assert row["rough vs smooth, one ball (johnson)"] == "below"
        assert row["rough vs smooth, one ball (printed)"] == "below"
    notes = " ".join(notes_of(table))
    assert "95 % prediction interval" in notes and "not one ball" in notes
    assert "stand-in balls" in notes and "not the paper's balls, nor its five spots" in notes
    assert (
        "POM, Johnson's Mindlin: mean K_L / Mindlin 0.90-0.90 over the loads and points; one ball " in notes
    )
    assert "not established at 9 of 9" in notes and "HDPE, Johnson's Mindlin" in notes
    assert "At 9 of 18 rows (POM) its verdict differs from Johnson's: the factor 4 decides it" in notes
    assert "HDPE 150-154 px" in notes  # the windows the cases solved


def test_one_realisation_gives_no_verdict_table():
    one = [r for r in records() if r.parameters["replicate"] == 0]
    assert KIND.tables["lateral_stiffness_spread"](one, None) is None


def test_the_figure_says_one_balls_verdict_and_names_a_synthetic_loop_so(examples):
    from roughcontact.experiment.friction_loop import analyse_loop, read_loop_csv

    loop = read_loop_csv(examples / "paper001_measured_loop.csv")
    measured = MeasuredLoop(
        loop, analyse_loop(loop, None, 0.025), "paper001_measured_loop.csv", 0.025, "HDPE", loop.origin
    )
    assert measured.legend == "synthetic loop (paper001_measured_loop.csv)"
    figure = lateral_stiffness_figure(records(), measured)
    titles = {ax.get_title() for ax in figure.axes}
    (pom,) = [t for t in titles if t.startswith("(a) POM")]
    assert "Johnson not established 9/9" in pom and "as printed below 9/9" in pom
    assert "9/9 as printed decided by eq. 12's printed factor 4" in pom
    (hdpe,) = [t for t in titles if t.startswith("(b) HDPE")]
    assert "Johnson below 9/9" in hdpe and "decided" not in hdpe
    legends = [
        text.get_text() for ax in figure.axes if ax.get_legend() for text in ax.get_legend().get_texts()
    ]
    assert "synthetic loop (paper001_measured_loop.csv)" in legends
    assert not any("measured" in text and "synthetic" not in text for text in legends)
    assert "mean ± 95 % CI (5 stand-in balls)" in legends and "one ball: 95 % prediction interval" in legends
