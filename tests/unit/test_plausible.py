"""Implausible numbers said at every door, flat surfaces flat, overflowing heights refused (issue 45, part 4).

The topography layer's one check (roughcontact.topography.plausible), the levelling of a flat or planar
scan, the statistics of a flat surface, a height whose square overflows, and the normal solver on flat,
tilted and absurdly scaled surfaces (the causes its failures used to hide behind a "noise" advice).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import roughcontact as rc
from roughcontact.errors import ConvergenceError, InputError
from roughcontact.topography import Topography
from roughcontact.topography.plausible import FLAT, PlausibilityWarning, doubts, is_flat, size_doubt
from roughcontact.topography.process import level
from roughcontact.topography.statistics import summary
from roughcontact.topography.surface import LARGEST

SIO2 = rc.get_material("SiO2")


def _ramp(n: int = 32) -> np.ndarray:
    x = np.arange(n)
    return np.add.outer(x * 1e-9, x * 0.5e-9) + 7e-6  # a tilted plane far from zero


# --- the check -----------------------------------------------------------------------------------------


def test_a_scan_of_160_m_is_doubted_in_each_doors_words():
    surface = Topography(np.random.default_rng(1).normal(size=(8, 8)) * 3e-8, 160.0)
    (doubt,) = doubts(surface)
    assert doubt.problem == "the scan is 160 m x 160 m, outside 1 nm to 1 m"
    assert "size= and height_unit=" in doubt.said("python")
    assert "size and height_unit here" in doubt.said("study")
    assert "--size and --height-unit" in doubt.said("cli")
    assert size_doubt((1e-6, 2e-6)) is None and size_doubt(2e-10) is not None


def test_heights_spanning_kilometres_or_attometres_are_doubted_a_rough_micrometre_scan_is_not():
    rough = np.random.default_rng(2).normal(size=(16, 16))
    assert doubts(Topography(rough * 1e-9, 1e-6)) == ()
    (high,) = doubts(Topography(rough * 1e3, 1e-6))
    assert "more than 1 m" in high.problem and "height unit" in high.said("cli")
    (low,) = doubts(Topography(rough * 1e-18, 1e-6))
    assert "less than 1 pm" in low.problem


def test_flat_is_round_off_of_the_heights_magnitude():
    assert is_flat(np.zeros((4, 4))) and is_flat(np.full(7, 3e-9))
    assert is_flat(3e-9 + np.array([0.0, 1e-25, -1e-25]))  # 3e-17 of the magnitude
    assert not is_flat(3e-9 + np.array([0.0, 1e-19, 0.0]))  # 3e-11: a roughness, however small
    assert not is_flat(_ramp())  # a tilted plane is not flat until levelled
    assert FLAT == 1e-12


# --- levelling and statistics of a flat surface --------------------------------------------------------


@pytest.mark.parametrize("mode", ["mean", "plane", "curvature"])
@pytest.mark.parametrize(
    "heights", [np.full((32, 32), 3e-9), _ramp(), np.arange(64) * 1e-9], ids=["flat", "ramp", "line"]
)
def test_levelling_a_flat_or_planar_scan_leaves_it_exactly_flat(heights, mode):
    surface = Topography(heights, 1e-6)
    if mode == "mean" and np.ptp(heights) > 0:
        assert not is_flat(level(surface, mode).heights)  # a tilt stays with the mean only
        return
    levelled = level(surface, mode)
    assert np.all(levelled.heights == 0) and levelled.info["detrend"] == mode
    assert levelled.info["history"][-1].startswith("flat: levelled heights are")


def test_levelling_a_rough_scan_is_not_touched_by_the_flat_rule():
    rough = rc.generate.self_affine((32, 32), 1e-6, hurst=0.8, rms_height=1e-12, seed=3)  # 1 pm rms
    levelled = level(rough, "plane")
    assert levelled.heights.std() > 0.5e-12 and not levelled.info["history"][-1].startswith("flat")


def test_a_flat_surface_has_zero_statistics_and_no_summits():
    flat = summary(Topography(np.full((16, 16), 3e-9) + 1e-25 * np.eye(16), 1e-6))
    assert flat["Sq"] == flat["Sa"] == flat["Sz"] == flat["m4"] == flat["rms_curvature"] == 0.0
    assert not {"summit_radius", "summit_density", "bandwidth", "Ssk", "Sku"} & set(flat)
    profile = summary(Topography(np.zeros(64), 1e-6))
    assert profile["Rq"] == 0.0 and "Sq" not in profile and "summit_radius" not in profile


def test_read_topography_reports_a_flat_file_as_flat(tmp_path):
    path = tmp_path / "flat.txt"
    np.savetxt(path, np.full((16, 16), 3.0))
    with pytest.warns(PlausibilityWarning, match="flat.txt: the surface is flat once levelled") as caught:
        surface = rc.read_topography(path, size="1 um", height_unit="nm")
    (said,) = [w for w in caught if w.category is PlausibilityWarning]
    assert np.all(surface.heights == 0) and said.message.doubt.problem.startswith("the surface is flat")
    assert said.filename == __file__  # the warning points at the caller's line


# --- overflow ------------------------------------------------------------------------------------------


def test_a_height_whose_square_overflows_is_refused_at_reading_naming_the_point(tmp_path):
    heights = np.random.default_rng(4).normal(size=(8, 8))
    heights[5, 2] = 1e300  # row 5 (y), column 2 (x) of the text
    path = tmp_path / "huge.txt"
    np.savetxt(path, heights)
    with pytest.raises(InputError) as refused:
        rc.read_topography(path, size="1 um", height_unit="nm")
    error = refused.value
    assert error.field == str(path)
    assert "x = 250 nm, y = 625 nm (grid point 2, 5)" in error.problem
    assert "1e+300 nm in the file, 1e+291 m" in error.problem and "overflow" in error.problem
    assert "undefined='interpolate'" in str(error) and "--fill-undefined" in error.text("cli")
    heights[5, 2] = np.nan  # the fix: the marker written as an undefined point, filled
    np.savetxt(path, heights)
    filled = rc.read_topography(path, size="1 um", height_unit="nm", undefined="interpolate")
    assert filled.info["undefined_points_filled"] == 1


def test_the_container_refuses_heights_and_sizes_beyond_the_largest():
    with pytest.raises(InputError, match=r"point \(1, 2\) is 1e\+200 m"):
        Topography(np.array([[0.0, 0, 0], [0, 0, 1e200]]), 1e-6)
    with pytest.raises(InputError, match="at most 1e\\+100 m"):
        Topography(np.zeros((4, 4)), 1e101)
    Topography(np.full((4, 4), LARGEST), 1e-6)  # the limit itself is a number roughcontact computes with


# --- the normal solver on flat, tilted and absurd surfaces ---------------------------------------------


@pytest.mark.parametrize("boundary", ["periodic", "free"])
def test_a_flat_against_a_flat_is_full_contact(boundary):
    flat = Topography(np.full((16, 16), 3e-9) + 1e-25 * np.eye(16), 1e-6)  # round-off of a constant
    contact = rc.solve_normal(flat, SIO2, mean_pressure=20e6, boundary=boundary)
    assert contact.contact_fraction == 1.0 and contact.mean_pressure == pytest.approx(20e6, rel=1e-12)
    if boundary == "periodic":  # uniform pressure: the exact answer, at once
        assert np.ptp(contact.pressure) == 0 and contact.iterations == 0
    else:  # a flat punch: carried at its edges
        assert contact.pressure[0, 8] > contact.pressure[8, 8]


def test_levelled_ramp_is_solved_as_the_flat_it_is():
    ramp = level(Topography(_ramp(), 1e-6), "plane")
    contact = rc.solve_normal(ramp, SIO2, mean_pressure=20e6, boundary="periodic")
    assert contact.contact_fraction == 1.0 and contact.approach == 0.0


def test_a_periodic_approach_beyond_the_mean_separation_is_refused_with_the_cause():
    line = Topography(np.arange(64) * 1e-12, 1e-6)  # a ramp profile: a sawtooth when repeated
    with pytest.raises(InputError) as refused:
        rc.solve_normal(line, SIO2, approach=1e-9)
    error = refused.value
    assert error.field == "approach" and "mean separation 31.5 pm" in error.problem
    options = {"mean_pressure": "--pressure"}.get
    assert "mean_pressure" in str(error) and "--pressure" in error.text("cli", options)
    below = rc.solve_normal(line, SIO2, approach=20e-12)  # below it: solved
    assert 0 < below.contact_fraction < 1
    flat = Topography(np.zeros((8, 8)), 1e-6, periodic=True)
    with pytest.raises(InputError, match="the surface is flat"):
        rc.solve_normal(flat, SIO2, approach=1e-9)
    assert rc.solve_normal(flat, SIO2, approach=0.0).force == 0.0  # the unloaded state


def test_a_solve_that_fails_at_an_absurd_scale_says_so_not_noise():
    scan = rc.generate.self_affine((64, 64), 1e-6, hurst=0.8, rms_height=3e-8, seed=5)
    absurd = Topography(scan.heights, 160.0)  # the size of nms-1.nms as read
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing printed by numpy on the way
        with pytest.raises(ConvergenceError) as failed:
            rc.solve_normal(absurd, SIO2, mean_pressure=20e6, boundary="free", max_iterations=300)
    message = str(failed.value)
    assert "the scan is 160 m x 160 m, outside 1 nm to 1 m (implausible)" in message
    assert "times its rms height" in message and "noise" not in message
    assert "check the scan's size and height unit" in failed.value.fix
