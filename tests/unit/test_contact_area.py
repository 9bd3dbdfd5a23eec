"""The perimeter-corrected contact area (roughcontact.contact.area) and where results report it."""

import math

import numpy as np
import pytest

from roughcontact.contact import solve_normal
from roughcontact.contact.area import PERIMETER_CORRECTION, corrected_contact_count, perimeter_switches
from roughcontact.errors import InputError
from roughcontact.topography.generate import self_affine, sinusoid


def test_the_constant_is_yastrebovs():
    assert PERIMETER_CORRECTION == pytest.approx((math.pi - 1 + math.log(2)) / 24)
    assert PERIMETER_CORRECTION == pytest.approx(0.11811, abs=5e-6)


def test_switches_count_both_grid_directions_and_the_period_when_periodic():
    mask = np.zeros((6, 6), dtype=bool)
    mask[2, 3] = True  # one pixel: four switches whatever the boundary
    assert perimeter_switches(mask, periodic=True) == perimeter_switches(mask, periodic=False) == 4
    mask[:] = False
    mask[0, 1:3] = True  # two pixels on the first row: 2 along x at the wrap and below, 2 along y
    assert perimeter_switches(mask, periodic=False) == 2 + 2  # row edge: nothing beyond the window
    assert perimeter_switches(mask, periodic=True) == 2 + 2 + 2  # row 0 against row 5 too
    full = np.ones((4, 4), dtype=bool)
    assert perimeter_switches(full, periodic=True) == perimeter_switches(full, periodic=False) == 0


def test_the_corrected_count_removes_c_per_switch_and_never_a_whole_pixel():
    mask = np.zeros((8, 8), dtype=bool)
    mask[2:5, 2:6] = True  # 12 pixels, perimeter 14 switches
    assert corrected_contact_count(mask, periodic=True) == pytest.approx(12 - PERIMETER_CORRECTION * 14)
    speck = np.zeros((8, 8), dtype=bool)
    speck[::2, ::2] = True  # isolated pixels: the largest correction, 4 c of each
    assert corrected_contact_count(speck, periodic=True) == pytest.approx(16 * (1 - 4 * PERIMETER_CORRECTION))
    with pytest.raises(InputError, match="map"):
        perimeter_switches(np.ones(8, dtype=bool), periodic=True)


def test_normal_contact_reports_the_corrected_area_beside_the_raw_one():
    surface = self_affine((64, 64), 1e-6, hurst=0.8, rms_slope=0.1, seed=2)
    result = solve_normal(surface, 1e9, mean_pressure=5e6)
    scalars = result.scalars()
    mask = result.contact_mask
    assert scalars["perimeter_switches"] == perimeter_switches(mask, periodic=True) > 0
    expected = corrected_contact_count(mask, periodic=True) / mask.size
    assert scalars["contact_fraction_corrected"] == pytest.approx(expected)
    assert scalars["contact_area_corrected"] == pytest.approx(expected * surface.area)
    assert scalars["contact_area_corrected"] < scalars["contact_area"]
    assert type(result).UNITS["contact_area_corrected"] == "m^2"
    assert result.to_xarray().attrs["contact_area_corrected"] == pytest.approx(
        scalars["contact_area_corrected"]
    )


def test_a_line_contact_reports_no_corrected_area():
    profile = sinusoid(64, 1e-6, amplitude=1e-8, wavelength=1e-6)
    scalars = solve_normal(profile, 1e9, mean_pressure=1e6).scalars()
    assert "contact_length" in scalars and "contact_area_corrected" not in scalars


def test_the_adhesive_result_corrects_its_areas_too():
    from roughcontact.contact.adhesive import solve_adhesive
    from roughcontact.contact.interaction import Exponential
    from roughcontact.topography.generate import sphere

    ball = sphere((32, 32), (1.2, 1.2), radius=1.0, kind="paraboloid")
    result = solve_adhesive(ball, 1.0, Exponential(1e-3, 0.02), approach=[0.02, -0.02])
    scalars = result.scalars()
    assert 0 < scalars["max_contact_area_corrected"] < scalars["max_contact_area"]
    assert result.to_xarray()["contact_area_corrected"].attrs["units"] == "m^2"
