"""Reading the real instrument files in shared/data/topographies (see its README.md).

The expected grids, physical sizes and height units are the README table, which lists what
SurfaceTopography 1.27 reports. Sizes there are printed with 3-5 significant digits, so they
are compared with a relative tolerance of 1e-3 (the rounding of a 4-digit value is at most
5e-4 relative), except where a file's entry needs more (said at the entry).
"""

import gzip
import json
import shutil

import numpy as np
import pytest

from roughcontact.errors import InputError, UnitError, UnsupportedFormatError
from roughcontact.topography.io import list_channels, read_topography
from roughcontact.topography.plausible import PlausibilityWarning
from roughcontact.units import length_unit_factor

UM, MM, NM = 1e-6, 1e-3, 1e-9

# file -> (grid, size [m], height unit, options, relative tolerance on size)
READABLE = {
    "di-3.di": ((256, 256), (10 * UM, 10 * UM), "nm", {}, 1e-3),
    "spot_1-1000nm.ibw": ((256, 256), (20.08 * UM, 20.08 * UM), "m", {}, 1e-3),
    "nid-1.nid": ((256, 256), (20 * UM, 20 * UM), "m", {}, 1e-3),
    "top-1.top": ((256, 256), (600 * NM, 600 * NM), "nm", {}, 1e-3),
    "plu-1.plu": ((768, 576), (1274.9 * UM, 956.2 * UM), "um", {}, 1e-3),
    # README prints 3 digits: "1.69 mm" stands for 1.6863 mm (2.2e-3 off)
    "sur-2.sur": ((563, 484), (1.96 * MM, 1.69 * MM), "mm", {"undefined": "interpolate"}, 3e-3),
    "x3p-2.x3p": ((650, 650), (83.0 * UM, 204.5 * UM), "m", {}, 1e-3),
    "al3d-1.al3d": ((200, 296), (87.6 * UM, 129.7 * UM), "m", {}, 1e-3),
    "tmd-1.tmd": ((300, 300), (18.96 * MM, 18.96 * MM), "mm", {}, 1e-3),
    "opdx-3.opdx": ((3001,), (49.98 * UM,), "um", {}, 1e-3),
    # README gives the x range of the 9600 (non-uniform) positions; our size counts 9600 pixels
    "dektak-1.csv": ((9600,), (1499.8 * UM * 9600 / 9599,), "um", {}, 1e-3),
    "gwyddion-export-english.txt": ((3, 4), (12.34 * UM, 5.68 * UM), "m", {}, 1e-3),
    # no units in the file: the user gives the positions' unit and the heights', and they come back exactly
    "xyz-1.txt": ((4, 4), (4 * UM, 4 * UM), "um", {"position_unit": "um", "height_unit": "um"}, 1e-12),
    "afm-slippy.txt": ((512, 512), (5 * UM, 5 * UM), "nm", {"size": "5 um", "height_unit": "nm"}, 1e-12),
    # header: h=305 w=75, pixel size 3.69862e-7 m, heights in rad with a factor to m
    "matrix-4.txt.gz": ((75, 305), (75 * 0.369862 * UM, 305 * 0.369862 * UM), "m", {}, 1e-12),
}
BROKEN = ["di_corrupted.di", "nonsense_txt_file.txt", "wrongnpyfile.npy"]


def rms(heights):
    return np.sqrt(np.mean((heights - heights.mean()) ** 2))


def test_every_file_in_the_readme_is_covered(shared_topographies):
    readme = (shared_topographies / "README.md").read_text(encoding="utf-8")
    listed = {line.split("|")[1].strip() for line in readme.splitlines() if line.startswith("| ")}
    named = {n.strip() for entry in listed for n in entry.split(",")} - {"file"}
    assert named == set(READABLE) | set(BROKEN)


@pytest.mark.parametrize("name", sorted(READABLE))
def test_reads_grid_size_and_unit(shared_topographies, name):
    grid, size, unit, options, rel = READABLE[name]
    if name == "gwyddion-export-english.txt":  # a test file: heights of metres, said as implausible
        with pytest.warns(PlausibilityWarning, match="11.52 m"):
            topography = read_topography(shared_topographies / name, **options)
    else:
        topography = read_topography(shared_topographies / name, **options)
    assert topography.shape == grid
    assert topography.size == pytest.approx(size, rel=rel, abs=0)
    assert length_unit_factor(topography.info["height_unit"]) == length_unit_factor(unit)
    assert np.all(np.isfinite(topography.heights))
    assert np.ptp(topography.heights) > 0
    assert topography.info["source"] == str(shared_topographies / name)
    assert topography.info["history"][0].startswith(f"read {name}")
    assert not topography.periodic
    json.dumps(dict(topography.info))  # info stays JSON-serialisable


@pytest.mark.parametrize("name", sorted(READABLE))
def test_list_channels_agrees_with_read(shared_topographies, name):
    grid, size, _, options, rel = READABLE[name]
    channels = list_channels(shared_topographies / name)
    default = [c for c in channels if c.is_default]
    assert len(default) == 1
    assert default[0].shape == grid
    if "size" not in options and "position_unit" not in options:  # else the file has no size to list
        assert default[0].size == pytest.approx(size, rel=rel, abs=0)


def test_periodic_flag_is_passed_on(shared_topographies):
    assert read_topography(shared_topographies / "top-1.top", periodic=True).periodic


def test_line_scans_are_1d(shared_topographies):
    for name in ("opdx-3.opdx", "dektak-1.csv"):
        assert read_topography(shared_topographies / name).dim == 1


def test_plausible_magnitudes(shared_topographies):
    # README gives 226 nm and 3.15 nm (the heights as stored, about their mean): half a unit in the last digit
    di = read_topography(shared_topographies / "di-3.di", detrend="mean")
    top = read_topography(shared_topographies / "top-1.top", detrend="mean")
    assert rms(di.heights) == pytest.approx(226 * NM, abs=0.5 * NM)
    assert rms(top.heights) == pytest.approx(3.15 * NM, abs=0.005 * NM)


def test_gzip_matrix_heights_are_the_matrix_times_its_factor(shared_topographies):
    text = gzip.decompress((shared_topographies / "matrix-4.txt.gz").read_bytes()).decode()
    matrix = np.loadtxt(text.splitlines()[4:])  # 305 rows (y) of 75 values (x) after a 4-line header
    topography = read_topography(shared_topographies / "matrix-4.txt.gz", detrend="none")
    # only float rounding separates the two products
    np.testing.assert_allclose(topography.heights, matrix.T * 2.91818e-8, rtol=1e-12)


def test_any_gzip_compressed_file_reads_like_the_original(shared_topographies, tmp_path):
    packed = tmp_path / "top-1.top.gz"
    packed.write_bytes(gzip.compress((shared_topographies / "top-1.top").read_bytes()))
    original = read_topography(shared_topographies / "top-1.top")
    assert np.array_equal(read_topography(packed).heights, original.heights)


# --- channels ------------------------------------------------------------------------------------

MULTI_CHANNEL = {
    # file -> (number of channels, default name, another height channel by name)
    "di-3.di": (4, "ZSensor", "Height"),
    "spot_1-1000nm.ibw": (8, "HeightTrace", "HeightRetrace"),
    "nid-1.nid": (4, "Scan forward (Z-Axis)", "Scan backward (Z-Axis)"),
}


@pytest.mark.parametrize("name", sorted(MULTI_CHANNEL))
def test_multi_channel_files(shared_topographies, name):
    count, default_name, other = MULTI_CHANNEL[name]
    path = shared_topographies / name
    channels = list_channels(path)
    assert len(channels) == count
    assert [c.index for c in channels] == list(range(count))
    assert [c.name for c in channels if c.is_default] == [default_name]
    default = read_topography(path)
    assert default.info["channel"] == default_name
    index = next(c.index for c in channels if c.name == other)
    by_name, by_index = read_topography(path, channel=other), read_topography(path, channel=index)
    assert by_name.info["channel"] == by_index.info["channel"] == other
    assert np.array_equal(by_name.heights, by_index.heights)
    assert not np.array_equal(by_name.heights, default.heights)


def test_di_channel_sizes_and_units(shared_topographies):
    channels = list_channels(shared_topographies / "di-3.di")
    zsensor = channels[0]
    assert zsensor.size == pytest.approx((10 * UM, 10 * UM), rel=1e-12, abs=0)  # 10000 nm exactly in the file
    assert (zsensor.height_unit, zsensor.size_unit) == ("nm", "nm")
    assert channels[2].height_unit is None  # Phase: the file gives no unit for its values


def test_unknown_channel_lists_the_available_ones(shared_topographies):
    with pytest.raises(InputError) as caught:
        read_topography(shared_topographies / "di-3.di", channel="Topography")
    assert caught.value.field == "channel"
    assert all(name in caught.value.fix for name in ("ZSensor", "AmplitudeError", "Phase", "Height"))
    with pytest.raises(InputError, match="ZSensor"):
        read_topography(shared_topographies / "di-3.di", channel=9)


def test_channel_without_heights_is_refused(shared_topographies):
    with pytest.raises(InputError, match="deg") as caught:
        read_topography(shared_topographies / "spot_1-1000nm.ibw", channel="PhaseTrace")
    assert caught.value.field == "channel"
    assert "HeightTrace" in caught.value.fix


# --- metadata missing from the file ---------------------------------------------------------------


def test_missing_size_says_how_to_give_it(shared_topographies):
    path = shared_topographies / "afm-slippy.txt"
    with pytest.raises(InputError) as caught:
        read_topography(path)
    message = str(caught.value)
    assert caught.value.field == "size"
    assert "afm-slippy.txt" in message
    assert 'size="5 um"' in message and '--size "5 um"' in message and "--height-unit nm" in message
    with pytest.raises(InputError, match="height_unit") as caught:
        read_topography(path, size="5 um")
    assert caught.value.field == "height_unit"
    topography = read_topography(path, size="5 um", height_unit="nm")
    assert topography.size == (5e-6, 5e-6)
    assert topography.info["size_from"] == "user"


def test_unit_less_xyz_needs_the_unit_of_its_positions(shared_topographies):
    with pytest.raises(InputError, match="without a unit") as caught:
        read_topography(shared_topographies / "xyz-1.txt", height_unit="um")
    assert caught.value.field == "position_unit"


def test_a_size_beside_the_files_own_is_refused_unless_overridden(shared_topographies):
    path = shared_topographies / "di-3.di"
    with pytest.raises(InputError) as caught:
        read_topography(path, size=("20 um", 30e-6))
    assert caught.value.field == "size"
    assert "10 µm x 10 µm" in caught.value.problem and "20 µm x 30 µm" in caught.value.problem
    assert "override_file_values=True" in str(caught.value)
    assert "--override-file-values" in caught.value.text("cli")
    assert read_topography(path, size="10 um").size == read_topography(path).size  # same value: no clash
    topography = read_topography(path, size=("20 um", 30e-6), override_file_values=True, detrend="none")
    assert topography.size == (20e-6, 30e-6)
    assert topography.info["size_in_file"] == pytest.approx((10 * UM, 10 * UM), rel=1e-12, abs=0)
    assert np.array_equal(topography.heights, read_topography(path, detrend="none").heights)


def test_height_unit_must_agree_with_the_file(shared_topographies):
    path = shared_topographies / "di-3.di"
    with pytest.raises(InputError, match="'nm'") as caught:
        read_topography(path, height_unit="um")
    assert caught.value.field == "height_unit" and "'um'" in caught.value.problem
    overridden = read_topography(path, height_unit="um", override_file_values=True, detrend="none")
    np.testing.assert_allclose(
        overridden.heights, read_topography(path, detrend="none").heights * 1000, rtol=1e-14
    )
    assert np.array_equal(read_topography(path, height_unit="nm").heights, read_topography(path).heights)


def test_bad_options(shared_topographies):
    path = shared_topographies / "afm-slippy.txt"
    with pytest.raises(UnitError):
        read_topography(path, size="5 um", height_unit="nN")
    with pytest.raises(UnitError):
        read_topography(path, size="5 Pa", height_unit="nm")
    with pytest.raises(InputError, match="3 values"):
        read_topography(path, size=("1 um", "2 um", "3 um"), height_unit="nm")
    with pytest.raises(InputError) as caught:
        read_topography(path, size="5 um", height_unit="nm", undefined="zero")
    assert caught.value.field == "undefined"


# --- undefined points ------------------------------------------------------------------------------


def test_undefined_points_are_refused_by_default(shared_topographies):
    with pytest.raises(InputError) as caught:
        read_topography(shared_topographies / "sur-2.sur")
    message = str(caught.value)
    assert "117" in message and "undefined" in message
    assert "undefined='interpolate'" in message and "--fill-undefined" not in message  # Python's words
    assert "--fill-undefined" in caught.value.text("cli") and "fill_undefined = true" in caught.value.text(
        "study"
    )


def test_interpolated_undefined_points_keep_the_measured_ones(shared_topographies):
    import SurfaceTopography

    path = shared_topographies / "sur-2.sur"
    topography = read_topography(path, undefined="interpolate", detrend="none")
    assert topography.info["undefined_points_filled"] == 117
    assert np.all(np.isfinite(topography.heights))
    measured = SurfaceTopography.open_topography(str(path)).topography().heights()  # masked, in mm
    defined = ~np.ma.getmaskarray(measured)
    # measured points are only converted mm -> m (one float product)
    np.testing.assert_allclose(topography.heights[defined], measured.data[defined] * MM, rtol=1e-15)
    filled = topography.heights[~defined]
    # harmonic interpolation creates no new extrema and never zeroes the holes
    assert filled.min() >= topography.heights[defined].min()
    assert filled.max() <= topography.heights[defined].max()


# --- broken inputs ---------------------------------------------------------------------------------


@pytest.mark.parametrize("name", BROKEN)
def test_broken_files(shared_topographies, name):
    path = shared_topographies / name
    for function in (read_topography, list_channels):
        with pytest.raises(UnsupportedFormatError) as caught:
            function(path)
        assert caught.value.field == str(path)
        assert caught.value.fix
        assert caught.value.__cause__ is not None


@pytest.mark.parametrize(
    ("name", "fraction"),
    [
        ("di-3.di", 0.5),
        ("sur-2.sur", 0.9),
        ("x3p-2.x3p", 0.5),
        ("top-1.top", 0.99),
        ("spot_1-1000nm.ibw", 0.5),
        ("matrix-4.txt.gz", 0.5),
        ("afm-slippy.txt", 0.5),
    ],
)
def test_truncated_copies(shared_topographies, tmp_path, name, fraction):
    content = (shared_topographies / name).read_bytes()
    path = tmp_path / name
    path.write_bytes(content[: int(len(content) * fraction)])
    with pytest.raises(UnsupportedFormatError) as caught:
        read_topography(path, **READABLE[name][3])
    assert caught.value.field == str(path)


def test_empty_missing_and_folder(shared_topographies, tmp_path):
    empty = tmp_path / "empty.sur"
    empty.write_bytes(b"")
    empty_gzip = tmp_path / "empty.txt.gz"
    empty_gzip.write_bytes(gzip.compress(b""))
    for path, words in [
        (empty, "empty"),
        (empty_gzip, "empty"),
        (tmp_path / "nothing.di", "no such file"),
        (tmp_path, "folder"),
    ]:
        with pytest.raises(UnsupportedFormatError, match=words) as caught:
            read_topography(path)
        assert caught.value.field == str(path)


# --- units -----------------------------------------------------------------------------------------


def _write_matrix(path, heights):
    np.savetxt(path, heights, fmt="%.17g")  # round-trip exact decimal text


@pytest.mark.parametrize(("unit", "factor"), [("nm", 1e-9), ("um", 1e-6), ("mm", 1e-3)])
def test_unit_invariance(tmp_path, unit, factor):
    heights = np.random.default_rng(7).normal(size=(6, 5))
    _write_matrix(tmp_path / "in_unit.txt", heights)
    _write_matrix(tmp_path / "in_metres.txt", heights * factor)
    in_unit = read_topography(
        tmp_path / "in_unit.txt", size=("3 um", "2.5 um"), height_unit=unit, detrend="none"
    )
    in_metres = read_topography(
        tmp_path / "in_metres.txt", size=(3e-6, 2.5e-6), height_unit="m", detrend="none"
    )
    assert in_unit.size == in_metres.size == (3e-6, 2.5e-6)
    # the two differ by float rounding of (h * factor) versus (h) * factor only
    np.testing.assert_allclose(in_unit.heights, in_metres.heights, rtol=1e-14)
    # text rows are y, columns x (SurfaceTopography's convention): heights come back transposed
    np.testing.assert_allclose(in_unit.heights, heights.T * factor, rtol=1e-15)


def test_copy_of_a_file_reads_the_same(shared_topographies, tmp_path):
    # the reader goes by content, not by name
    copy = tmp_path / "renamed.dat"
    shutil.copy(shared_topographies / "top-1.top", copy)
    original = read_topography(shared_topographies / "top-1.top")
    assert np.array_equal(read_topography(copy).heights, original.heights)
