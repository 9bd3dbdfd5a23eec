"""Verdicts at the level of the claim and intervals that respect their quantity (roughcontact.spread)."""

import math

import pytest
from scipy import stats

from roughcontact.spread import natural_bounds, spread


def test_a_claim_about_one_specimen_is_judged_with_the_prediction_interval():
    values = [0.80, 0.85, 0.90, 0.95, 1.00]  # the mean's interval lies below 1.05, one ball's does not
    s = spread(values)
    mean = s.verdict(1.05, of="mean")
    one = s.verdict(1.05, of="one")
    assert mean.word == "below" and mean.established
    assert one.word == "not established" and not one.established
    half = stats.t.ppf(0.975, 4) * s.std * math.sqrt(1 + 1 / 5)
    assert one.interval == pytest.approx((0.9 - half, 0.9 + half), rel=1e-12)
    assert one.mean_interval == (s.ci95_low, s.ci95_high) and one.n == 5
    assert one.interval_name == "95 % prediction interval of one realisation"
    assert "not established: the 95 % prediction interval of one realisation" in one.describe()
    assert s.verdict(0.5, of="one").word == "above" and s.verdict(2.0, of="one").word == "below"
    assert spread([1.0]).verdict(2.0).word == "one realisation"
    with pytest.raises(ValueError, match="of must be"):
        s.verdict(1.0, of="ball")


def test_a_printed_value_with_a_tolerance_is_inside_outside_or_not_established():
    s = spread([19.0, 19.5, 20.0, 20.5, 21.0])
    assert s.within(40 / 1.5, 40 * 1.5) == "outside"
    assert s.within(20 / 1.5, 20 * 1.5) == "inside"
    assert s.within(20.0, 30.0) == "not established"
    assert spread([20.0]).within(10, 30) == "one realisation"


def test_intervals_of_bounded_quantities_stop_at_their_bounds_and_say_why():
    fraction = spread([0.99, 1.0, 0.995], bounds=(0.0, 1.0))
    assert fraction.ci95_high == 1.0 and fraction.ci95_low < 1.0
    assert "cut at 1" in fraction.note and "[0, 1]" in fraction.note
    assert fraction.prediction()[1] == 1.0
    positive = spread([1.0, 9.0], bounds=(0.0, math.inf))  # n = 2: Student's interval reaches far below 0
    assert positive.ci95_low == 0.0 and "cut at 0" in positive.note
    free = spread([1.0, 9.0])
    assert free.ci95_low < 0 and free.note == ""
    assert "note" in positive.row() and "bounds" not in positive.row()


@pytest.mark.parametrize(
    ("name", "unit", "bounds"),
    [
        ("last_stick_fraction", "", (0.0, 1.0)),
        ("contact_fraction", None, (0.0, 1.0)),
        ("K_L_A", "N/m", (0.0, math.inf)),
        ("mu", None, (0.0, math.inf)),
        ("peak_contact_area", "m^2", (0.0, math.inf)),
        ("adhesive_to_mechanical", None, (0.0, math.inf)),
        ("crossover_load", "N", (0.0, math.inf)),
        ("number_of_patches", None, (0.0, math.inf)),
        ("plastic_fraction_at_peak", None, (0.0, 1.0)),
        ("mean_gap", "m", (0.0, math.inf)),
        ("max_pressure", "Pa", (0.0, math.inf)),
        ("iterations", None, (0.0, math.inf)),
        ("rq", "m", (0.0, math.inf)),
        ("approach", "m", None),
        ("pull_off_force", "N", None),
    ],
)
def test_natural_bounds(name, unit, bounds):
    assert natural_bounds(name, unit) == bounds
