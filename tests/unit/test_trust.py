"""How much of a contact rests on invented points, specks, a window's edge or a few pixels (issue 32)."""

import numpy as np
import pytest

from roughcontact.contact import solve_normal
from roughcontact.contact.trust import (
    EDGE_PIXELS,
    area_resolution,
    contact_shares,
    edge_band,
    one_pixel_patches,
    patch_resolution,
    share_warnings,
)
from roughcontact.errors import InputError
from roughcontact.materials import get_material
from roughcontact.messages import render
from roughcontact.topography import Topography
from roughcontact.topography.channels import classify_channel
from roughcontact.topography.generate import self_affine
from roughcontact.topography.process import (
    combine,
    crop,
    detrend,
    exclude_filled,
    find_specks,
    measured_points,
    resample,
)

POLY = get_material("polysilicon")


def _surface(filled=None, specks=None, shape=(32, 32)):
    heights = self_affine(shape, 1e-6, hurst=0.8, rms_height=1e-9, seed=3).heights
    return Topography(heights, 1e-6, info={"name": "s"}, filled=filled, specks=specks)


# --- the shares ------------------------------------------------------------------------------------


def test_shares_of_load_and_area_on_each_mask():
    filled = np.zeros((32, 32), bool)
    filled[10:20, 10:20] = True
    specks = np.zeros((32, 32), bool)
    specks[5, 5] = True
    pressure = np.zeros((32, 32))
    pressure[12, 12], pressure[5, 5], pressure[16, 25] = 3.0, 1.0, 4.0
    shares = contact_shares(pressure, _surface(filled, specks), "periodic")
    assert shares == {
        "filled_load_share": 3 / 8,
        "filled_area_share": 1 / 3,
        "speck_load_share": 1 / 8,
        "speck_area_share": 1 / 3,
    }
    free = contact_shares(pressure, _surface(), "free")
    assert set(free) == {"edge_load_share", "edge_area_share"} and free["edge_load_share"] == 0.0
    pressure[0, 7] = 8.0
    assert contact_shares(pressure, _surface(), "free")["edge_load_share"] == pytest.approx(0.5)
    assert contact_shares(-pressure, _surface(), "free")["edge_load_share"] == 0.0  # tension carries no load


def test_the_edge_band_and_the_rim_of_excluded_points():
    band = edge_band(_surface(), "free")
    assert band.sum() == 32 * 32 - (32 - 2 * EDGE_PIXELS) ** 2
    assert edge_band(_surface(), "periodic") is None
    filled = np.zeros((32, 32), bool)
    filled[10:20, 10:20] = True
    excluded = exclude_filled(_surface(filled))
    rim = edge_band(excluded, "periodic")
    assert not rim[filled].any() and rim[9, 15] and rim[7, 15] and not rim[6, 15]
    profile = Topography(np.zeros(20), 1e-6)
    assert edge_band(profile, "free").sum() == 2 * EDGE_PIXELS


def test_warnings_say_the_share_and_the_fix():
    filled = np.zeros((32, 32), bool)
    filled[:16] = True
    surface = _surface(filled, filled & (np.arange(32)[None, :] == 3))
    shares = {
        "filled_load_share": 0.4,
        "filled_area_share": 0.3,
        "speck_load_share": 0.2,
        "speck_area_share": 0.1,
    }
    filled_warning, speck_warning = (render(w, "cli") for w in share_warnings(shares, surface, "periodic"))
    assert "40 % of the load" in filled_warning and "--exclude-filled" in filled_warning
    assert "20 % of the load" in speck_warning and "--remove-specks" in speck_warning
    assert share_warnings({"filled_load_share": 0.04, "filled_area_share": 0.04}, surface, "periodic") == []
    # concentrated at the edge (a punch edge): 13 % of the load on 3 % of the contact
    (edge,) = share_warnings({"edge_load_share": 0.13, "edge_area_share": 0.03}, _surface(), "free")
    edge = render(edge, "cli")  # each door names the keys in its words (roughcontact.messages)
    assert "13 % of the load" in edge and "concentrated" in edge and "--boundary periodic" in edge
    # most of the load at the edge, whatever its pressure: decided beyond the scan
    (edge,) = share_warnings({"edge_load_share": 0.84, "edge_area_share": 0.67}, _surface(), "free")
    assert "decided at the edge" in edge
    # a patch that merely lies near the edge
    assert share_warnings({"edge_load_share": 0.105, "edge_area_share": 0.093}, _surface(), "free") == []


def test_resolution_warnings():
    (few,) = area_resolution("the contact area", 3e-18, 1e-18)
    assert "3 pixels" in few and "not resolved" in few
    assert area_resolution("the contact area", 10e-18, 1e-18) == []
    assert area_resolution("the contact area", 0.0, 1e-18) == []
    assert "1 pixel " in area_resolution("the contact length", 1e-9, 1e-9, 1)[0]
    mask = np.zeros((10, 10), bool)
    mask[::3, ::3] = True
    mask[0, 1] = True
    assert one_pixel_patches(mask) == (16, 15)
    (patches,) = patch_resolution(16, 15)
    assert "15 of the 16 contact patches" in patches
    assert patch_resolution(16, 8) == [] and patch_resolution(3, 3) == []


def test_a_normal_contact_reports_its_shares_and_warns():
    filled = np.zeros((32, 32), bool)
    surface = _surface()
    peak = np.unravel_index(np.argmax(surface.heights), surface.shape)
    filled[peak] = True
    result = solve_normal(_surface(filled), POLY, mean_pressure=2e6, boundary="periodic")
    scalars = result.scalars()
    assert scalars["filled_load_share"] > 0.05 and "edge_load_share" not in scalars
    assert any("rests on filled points" in w for w in result.range_warnings())
    excluded = solve_normal(exclude_filled(_surface(filled)), POLY, mean_pressure=2e6, boundary="periodic")
    assert excluded.scalars()["filled_load_share"] == 0.0 and excluded.pressure[peak] == 0.0
    assert "edge_load_share" in excluded.scalars()  # the rim of the excluded points is an edge


def test_a_line_contact_speaks_per_length():
    profile = Topography(self_affine(256, 1e-6, hurst=0.8, rms_height=1e-9, seed=1).heights, 1e-6)
    result = solve_normal(profile, POLY, mean_pressure=2e7)
    scalars = result.scalars()
    assert "force" not in scalars and "contact_area" not in scalars
    assert scalars["force_per_length"] == pytest.approx(2e7 * 1e-6)
    assert scalars["contact_length"] == pytest.approx(result.contact_fraction * 1e-6)
    with pytest.raises(InputError) as caught:
        solve_normal(profile, POLY, mean_pressure=2e7, boundary="free")
    assert "--boundary periodic" in caught.value.text("cli")


def test_a_load_the_scan_cannot_carry_is_refused_before_solving():
    with pytest.raises(InputError) as caught:
        solve_normal(_surface(), POLY, force=100.0)
    assert caught.value.field == "force" and "times the contact modulus" in caught.value.problem
    assert "1 µm x 1 µm" in caught.value.problem
    with pytest.raises(InputError, match="hardness 15 MPa"):
        solve_normal(_surface(), POLY, mean_pressure=2e7, hardness=1.5e7)


# --- the masks through processing ----------------------------------------------------------------


def test_specks_are_small_measured_islands_amid_undefined_points():
    undefined = np.zeros((20, 20), bool)
    undefined[:, 10:] = True
    undefined[5, 15] = undefined[5, 16] = False  # a speck of two points
    undefined[12:16, 12:16] = False  # 16 points: a region, not a speck
    specks = find_specks(undefined)
    assert specks.sum() == 2 and specks[5, 15] and specks[5, 16]
    assert not find_specks(np.zeros((5, 5), bool)).any()


def test_backgrounds_are_fitted_to_measured_points_only():
    x = np.linspace(0, 1, 32)
    tilt = np.add.outer(x, 2 * x) * 1e-8
    filled = np.zeros((32, 32), bool)
    filled[:8] = True
    heights = np.where(filled, 5e-7, tilt)  # nonsense where filled
    levelled = detrend(Topography(heights, 1e-6, filled=filled), "plane")
    np.testing.assert_allclose(levelled.heights[~filled], 0.0, atol=1e-20)
    assert np.array_equal(measured_points(levelled), ~filled)


def test_masks_follow_crop_resample_combine_and_mismatched_shapes_are_refused():
    filled = np.zeros((32, 32), bool)
    filled[4:8, 4:8] = True
    surface = _surface(filled)
    cropped = crop(surface, x=(0.0, 0.5e-6))
    assert cropped.filled.shape == (16, 32) and cropped.filled.sum() == 16
    finer = resample(surface, 0.5e-6 / 32)
    assert finer.filled.shape == finer.shape and finer.filled[10, 10] and not finer.filled[40, 40]
    both = combine(surface, _surface(specks=filled.T))
    assert both.filled.sum() == 16 and both.specks.sum() == 16
    assert _surface(np.zeros((32, 32), bool)).filled is None  # all False: none
    with pytest.raises(InputError, match="filled"):
        Topography(np.zeros((4, 4)), 1e-6, filled=np.zeros((3, 3), bool))


# --- channels ----------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "unit", "length", "kind", "height", "words"),
    [
        ("ZSensor", "nm", True, "HEIGHT", True, ""),
        ("HeightRetrace", "m", True, "HEIGHT", True, ""),
        ("Scan forward (Z-Axis)", "m", True, "HEIGHT", True, ""),
        ("Default", None, None, None, True, ""),
        ("AmplitudeTrace", "m", True, "HEIGHT", False, "oscillation amplitude"),
        ("AmplitudeError", None, None, "HEIGHT", False, "error"),
        ("PeakForceError", "nm", True, "HEIGHT", False, "error"),
        ("Phase", None, None, "HEIGHT", False, "phase"),
        ("PhaseTrace", "deg", False, "PHASE", False, "'deg'"),
        ("NapPotentialTrace", "V", False, "VOLTAGE", False, "'V'"),
        ("Friction", "V", False, "FRICTION", False, "'V'"),
        ("Deflection", "nm", True, "HEIGHT", False, "deflection"),
        ("Surface", "m", True, "VOLTAGE", False, "voltage"),
    ],
)
def test_channels_are_classified_by_name_unit_and_kind(name, unit, length, kind, height, words):
    classified = classify_channel(name, unit, length, kind)
    assert classified.is_height is height
    assert words in classified.reason


def test_an_adhesive_line_contact_speaks_per_length():
    from roughcontact.contact import solve_adhesive
    from roughcontact.contact.adhesive_result import LINE_NAMES
    from roughcontact.contact.interaction import Exponential

    profile = Topography(self_affine(128, 1e-6, hurst=0.8, rms_height=0.3e-9, seed=2).heights, 1e-6)
    result = solve_adhesive(profile, POLY, Exponential(0.1, 1e-9), approach=np.linspace(-4e-9, 1e-9, 12))
    scalars = result.scalars()
    for area_name, line_name in LINE_NAMES.items():
        assert area_name not in scalars and line_name in scalars
        assert line_name in type(result).UNITS
    assert type(result).UNITS["pull_off_force_per_length"] == "N/m"
    assert result.to_xarray()["force"].attrs["units"] == "N/m"
