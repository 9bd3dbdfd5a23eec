"""generate.matched_moments against seed paper 002's printed spectral moments (eqs. 1-3), measured back.

A surface made for paper 002's m0, m2, m4 on its 25 um square is measured back with
statistics.spectral_moments (the paper's finite-difference averages), over an ensemble of seeds.
"""

import numpy as np
import pytest

from roughcontact.papers.paper002 import ISLAND_SIDE, MOMENTS
from roughcontact.topography import generate, statistics

SEEDS = 200
"""One realisation scatters by 12 % (m0), 5 % (m2) and 3.5 % (m4) about the expected moments (the few
modes near the roll-off carry m0): 200 seeds leave 0.8 %, 0.4 % and 0.25 % on the means."""


@pytest.fixture(scope="module")
def measured():
    """Mean moments of 200 realisations on 512^2 (22 pixels per shortest wavelength)."""
    moments = [
        statistics.spectral_moments(generate.matched_moments((512, 512), ISLAND_SIDE, **MOMENTS, seed=seed))
        for seed in range(SEEDS)
    ]
    return {key: np.mean([getattr(m, key) for m in moments]) for key in ("m0", "m2", "m4")}


@pytest.mark.parametrize("key", ["m0", "m2", "m4"])
def test_mean_moments_of_the_ensemble_are_paper002s(measured, key):
    # expected: m0 and m2 exact on the period's lattice, m4 +0.03 % (one shell of modes); the finite
    # differences read m2 0.15 % and m4 0.6 % low on this grid; measured +0.43 %, +0.35 %, -0.73 %
    assert measured[key] == pytest.approx(MOMENTS[key], rel=0.02, abs=0)


def test_bandwidth_of_the_ensemble_is_paper002s(measured):
    # alpha = m0 m4 / m2^2 = 6.894 printed; of the mean moments measured -1.0 % (per realisation
    # averaged: -1.2 %, a ratio's bias)
    alpha = measured["m0"] * measured["m4"] / measured["m2"] ** 2
    assert alpha == pytest.approx(MOMENTS["m0"] * MOMENTS["m4"] / MOMENTS["m2"] ** 2, rel=0.02, abs=0)
