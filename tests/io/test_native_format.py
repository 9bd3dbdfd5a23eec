"""roughcontact's own NetCDF format: exact round trips, atomic writes, clear refusals."""

import numpy as np
import pytest
import xarray as xr

from roughcontact.errors import InputError, UnsupportedFormatError
from roughcontact.topography import Topography
from roughcontact.topography.io import list_channels, read_topography
from roughcontact.topography.native import NATIVE_FORMAT, load_topography, save_topography
from roughcontact.topography.plausible import PlausibilityWarning

INFO = {
    "name": "test",
    "history": ("generated", "detrended"),
    "nested": {"list": [1, 2.5, None], "flag": True},
    "tuple_in_list": [(1, "a")],
}


def _topography(shape, periodic):
    heights = np.random.default_rng(3).normal(scale=1e-7, size=shape)
    size = (2e-6, 3e-6)[: len(shape)]
    return Topography(heights, size, periodic=periodic, info=INFO)


def _files(folder):
    return sorted(p.name for p in folder.iterdir())


@pytest.mark.parametrize("shape", [(17,), (8, 5)])
@pytest.mark.parametrize("periodic", [False, True])
def test_round_trip_is_exact(tmp_path, shape, periodic):
    topography = _topography(shape, periodic)
    path = tmp_path / "surface.nc"
    save_topography(topography, path)
    loaded = load_topography(path)
    assert np.array_equal(loaded.heights, topography.heights)  # bit for bit
    assert loaded.size == topography.size
    assert loaded.periodic is periodic
    assert dict(loaded.info) == dict(topography.info)  # tuples stay tuples, lists stay lists
    assert isinstance(loaded.info["history"], tuple) and isinstance(loaded.info["nested"]["list"], list)
    assert loaded == topography
    assert _files(tmp_path) == ["surface.nc"]  # no temporary left behind


def test_file_layout(tmp_path):
    topography = _topography((8, 5), periodic=False)
    save_topography(topography, tmp_path / "s.nc")
    with xr.open_dataset(tmp_path / "s.nc", engine="h5netcdf") as dataset:
        assert dataset.attrs["format"] == NATIVE_FORMAT
        assert int(dataset.attrs["format_version"]) == 1
        assert dataset["heights"].dtype == np.float64
        assert dataset["heights"].dims == ("x", "y")
        assert dataset["heights"].attrs["units"] == dataset["x"].attrs["units"] == "m"
        np.testing.assert_array_equal(dataset["x"].values, topography.coordinates()[0])
        np.testing.assert_array_equal(dataset["y"].values, topography.coordinates()[1])


def test_nan_in_info_survives(tmp_path):
    topography = Topography(np.arange(4.0), 1e-6, info={"nan": float("nan")})
    save_topography(topography, tmp_path / "s.nc")
    assert np.isnan(load_topography(tmp_path / "s.nc").info["nan"])


def test_instrument_file_round_trip(shared_topographies, tmp_path):
    original = read_topography(shared_topographies / "di-3.di")
    save_topography(original, tmp_path / "di.nc")
    assert load_topography(tmp_path / "di.nc") == original  # info from the reader is JSON-ready
    assert load_topography(tmp_path / "di.nc").info["instrument"]["vendor"] == "Bruker"


def _levelled_none(topography):
    """``topography`` as ``read_topography(..., detrend="none")`` returns it: with its levelling recorded."""
    return topography.with_heights(topography.heights, info={**topography.info, "detrend": "none"})


def test_read_topography_and_list_channels_recognise_native_files(tmp_path):
    topography = _topography((8, 5), periodic=True)
    path = tmp_path / "s.nc"
    save_topography(topography, path)
    assert read_topography(path, detrend="none") == _levelled_none(topography)
    [channel] = list_channels(path)
    assert (channel.shape, channel.size) == ((8, 5), (2e-6, 3e-6))
    assert (channel.height_unit, channel.is_default) == ("m", True)
    with pytest.raises(InputError, match="2 µm x 3 µm") as caught:
        read_topography(path, size="4 um")
    assert caught.value.field == "size" and "override_file_values=True" in caught.value.fix
    resized = read_topography(path, size="4 um", override_file_values=True)
    assert resized.size == (4e-6, 4e-6) and resized.info["size_in_file"] == (2e-6, 3e-6)
    own = read_topography(path, size=("2 um", "3 um"), detrend="none")  # the file's own size: no clash
    assert own == _levelled_none(topography)
    with pytest.raises(InputError, match="'m'"):
        read_topography(path, height_unit="nm")
    with pytest.warns(PlausibilityWarning, match="less than 1 pm"):  # metres read as nm: said
        in_nm = read_topography(path, height_unit="nm", override_file_values=True, detrend="none")
    np.testing.assert_array_equal(in_nm.heights, topography.heights * 1e-9)


def test_failed_write_leaves_nothing_and_keeps_the_old_file(tmp_path, monkeypatch):
    path = tmp_path / "s.nc"
    old = _topography((8, 5), periodic=False)
    save_topography(old, path)
    before = path.read_bytes()

    def half_write(self, target, *args, **kwargs):
        with open(target, "wb") as stream:
            stream.write(b"\x89HDF\r\n\x1a\npartial")
        raise RuntimeError("disk unplugged")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", half_write)
    with pytest.raises(RuntimeError, match="disk unplugged"):
        save_topography(_topography((17,), periodic=True), path)
    with pytest.raises(RuntimeError):
        save_topography(old, tmp_path / "new.nc")
    assert _files(tmp_path) == ["s.nc"]
    assert path.read_bytes() == before


def test_os_error_becomes_input_error(tmp_path, monkeypatch):
    def no_space(self, target, *args, **kwargs):
        open(target, "wb").close()
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", no_space)
    with pytest.raises(InputError, match="No space left") as caught:
        save_topography(_topography((17,), periodic=False), tmp_path / "s.nc")
    assert caught.value.field == "path"
    assert _files(tmp_path) == []


def test_refused_writes(tmp_path):
    topography = _topography((17,), periodic=False)
    with pytest.raises(InputError, match="does not exist"):
        save_topography(topography, tmp_path / "missing" / "s.nc")
    with pytest.raises(InputError, match="ndarray") as caught:
        save_topography(Topography(np.arange(4.0), 1e-6, info={"array": np.arange(3)}), tmp_path / "s.nc")
    assert caught.value.field == "topography.info"
    with pytest.raises(InputError, match="not a string"):
        save_topography(Topography(np.arange(4.0), 1e-6, info={"map": {1: "a"}}), tmp_path / "s.nc")
    with pytest.raises(InputError, match="Topography"):
        save_topography(np.arange(4.0), tmp_path / "s.nc")
    assert _files(tmp_path) == []


def test_foreign_netcdf_is_refused(tmp_path):
    path = tmp_path / "other.nc"
    xr.Dataset({"z": ("x", np.arange(3.0))}).to_netcdf(path, engine="h5netcdf")
    with pytest.raises(UnsupportedFormatError, match="not a roughcontact topography") as caught:
        load_topography(path)
    assert caught.value.field == str(path)
    with pytest.raises(UnsupportedFormatError):  # SurfaceTopography cannot make sense of it either
        read_topography(path)


def test_newer_version_and_non_netcdf_are_refused(tmp_path):
    newer = tmp_path / "newer.nc"
    xr.Dataset(
        {"heights": ("x", np.arange(3.0))}, attrs={"format": NATIVE_FORMAT, "format_version": 2}
    ).to_netcdf(newer, engine="h5netcdf")
    with pytest.raises(UnsupportedFormatError, match="version 2"):
        load_topography(newer)
    text = tmp_path / "text.nc"
    text.write_text("not netcdf")
    with pytest.raises(UnsupportedFormatError, match="NetCDF"):
        load_topography(text)
