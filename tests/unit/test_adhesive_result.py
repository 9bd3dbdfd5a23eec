"""AdhesiveResult's own judgement: the pull-off's parabola is an interpolation; a window too small is said."""

from dataclasses import replace

import numpy as np
import pytest

from roughcontact.contact.adhesive import solve_adhesive
from roughcontact.contact.interaction import MaugisDugdale
from roughcontact.topography.generate import sphere

BALL = sphere((32, 32), 240e-9, radius=1e-6)


@pytest.fixture(scope="module")
def cycle():
    programme = np.concatenate([np.linspace(-3e-9, 1e-9, 9), np.linspace(-3e-9, 1e-9, 9)[-2::-1]])
    return solve_adhesive(BALL, 4e9, MaugisDugdale(0.05, 1.9e-9), approach=programme)


def test_the_parabola_refines_a_smooth_minimum_and_never_extrapolates(cycle):
    # three points on y = (x - 0.1)^2 - 1: the vertex (0.1, -1) lies between them and close above
    smooth = replace(cycle, approach=np.array([-1.0, 0.0, 1.0]), force=np.array([0.21, -0.99, -0.19]))
    smooth = replace(smooth, jump=np.zeros(3, bool), map_steps={**cycle.map_steps, "pull_off": 1})
    assert smooth.pull_off_force == pytest.approx(1.0, rel=1e-12)
    # top-1.top's loading steps across contact onset: the parabola's vertex would be 3.4x below
    # the smallest force; the smallest force itself is kept
    uneven = replace(
        smooth, approach=np.array([-2e-9, 0.0, 0.25e-9]), force=np.array([0.0, -23.6e-9, 11.7e-9])
    )
    assert uneven.pull_off_force == pytest.approx(23.6e-9, rel=1e-12)


def test_an_interaction_reaching_the_window_edge_is_reported(cycle):
    assert not any("window's edge" in w for w in cycle.range_warnings())
    small = sphere((24, 24), 120e-9, radius=1e-6)
    wide = solve_adhesive(small, 4e9, MaugisDugdale(0.05, 6e-9), approach=[-12e-9, 1e-9, -12e-9])
    assert any("window's edge" in w and "underestimated" in w for w in wide.range_warnings())


def test_the_tail_of_a_law_far_from_the_contact_is_no_contact_in_the_edge_shares():
    """An exponential law leaves tractions of a fraction of a pascal tens of nanometres from the contact:
    a sphere in the middle of its window has none of its contact at the window's edge."""
    from roughcontact.contact.interaction import Exponential

    ball = sphere((64, 64), 600e-9, radius=5e-6)
    law = Exponential(0.05, 0.5e-9)
    programme = np.r_[np.linspace(-2.5e-9, 3e-9, 6), np.linspace(3e-9, -2.5e-9, 6)[1:]]
    result = solve_adhesive(ball, 4e9, law, approach=programme)
    pressure, gap = result.maps["peak"]
    assert np.count_nonzero((pressure > 0) & ~law.in_contact(gap))  # the tail: positive, no contact
    assert result.shares["edge_area_share"] == 0.0 and result.shares["edge_load_share"] == 0.0
