"""Nanoindentation input: CSV columns and units, segments, and errors that name the field and the fix."""

import numpy as np
import pytest

from roughcontact._text_table import split_header
from roughcontact.errors import InputError, UnitError
from roughcontact.experiment.nanoindentation import (
    IndentationCurve,
    IndentationResult,
    berkovich_area,
    detect_segments,
    oliver_pharr,
    read_indentation_csv,
    synthetic_indentation_curve,
)
from roughcontact.results import SCALAR_NAME, Result
from roughcontact.units import prefixed_scale


@pytest.fixture(scope="module")
def curve():
    return synthetic_indentation_curve(0.98e9, creep_rate=1e-9, sampling_rate=2.0)


def _write(tmp_path, text, name="c.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_header_names_and_units_are_detected(tmp_path):
    path = _write(
        tmp_path,
        "# comment\nTime [s];Displacement [nm];Force [mN]\n"
        + "".join(f"{i};{i * 10};{i * 0.1}\n" for i in range(12)),
    )
    read = read_indentation_csv(path)
    np.testing.assert_allclose(read.depth[:3], [0, 1e-8, 2e-8], rtol=1e-12, atol=0)
    np.testing.assert_allclose(read.load[:3], [0, 1e-4, 2e-4], rtol=1e-12, atol=0)
    np.testing.assert_allclose(read.time[:3], [0, 1, 2], rtol=0, atol=0)


def test_overrides_name_columns_and_units(tmp_path):
    path = _write(tmp_path, "Pd,Pn,extra\n" + "".join(f"{i},{i},{i}\n" for i in range(12)))
    read = read_indentation_csv(path, depth_unit="um", load_unit="uN")
    assert read.time is None and read.depth[1] == pytest.approx(1e-6) and read.load[1] == pytest.approx(1e-6)
    other = read_indentation_csv(path, depth_column="extra", depth_unit="nm", load_unit="N")
    assert other.depth[1] == pytest.approx(1e-9)


@pytest.mark.parametrize(
    ("text", "kwargs", "field"),
    [
        ("depth,load\n" + "1,1\n" * 12, {}, "depth_unit"),
        ("depth (nm),load (mN)\n" + "1,1\n" * 12, {"load_unit": "nm"}, "load_unit"),
        ("depth (nm),weight (mN)\n" + "1,1\n" * 12, {}, "load_column"),
        ("depth (nm),load (mN)\n" + "1,1\n" * 12, {"depth_column": "height"}, "depth_column"),
    ],
)
def test_csv_errors_name_the_option(tmp_path, text, kwargs, field):
    with pytest.raises(InputError) as error:
        read_indentation_csv(_write(tmp_path, text), **kwargs)
    assert error.value.field == field and error.value.fix


def test_unit_of_wrong_dimension_is_a_unit_error(tmp_path):
    with pytest.raises(UnitError):
        read_indentation_csv(_write(tmp_path, "depth (mN),load (mN)\n" + "1,1\n" * 12))


def test_text_cell_and_missing_file(tmp_path):
    with pytest.raises(InputError, match="not a number"):
        read_indentation_csv(_write(tmp_path, "depth (nm),load (mN)\n1,1\nabc,2\n"))
    with pytest.raises(InputError, match="not found"):
        read_indentation_csv(tmp_path / "nothing.csv")


def test_nan_values_name_the_column(curve):
    depth = curve.depth.copy()
    depth[5] = np.nan
    with pytest.raises(InputError, match="NaN") as error:
        IndentationCurve(depth, curve.load, curve.time)
    assert error.value.field == "depth" and "remove" in error.value.fix


def test_too_few_points_and_mismatched_lengths():
    with pytest.raises(InputError, match="at least") as error:
        IndentationCurve(np.arange(5.0), np.arange(5.0))
    assert error.value.field == "depth"
    with pytest.raises(InputError) as error:
        IndentationCurve(np.arange(12.0), np.arange(11.0))
    assert error.value.field == "load"


def test_time_must_increase(curve):
    time = curve.time.copy()
    time[10] = time[9]
    with pytest.raises(InputError) as error:
        IndentationCurve(curve.depth, curve.load, time)
    assert error.value.field == "time"


def test_no_unloading_segment_is_refused(curve):
    stop = detect_segments(curve).unloading.start + 1
    cut = IndentationCurve(curve.depth[:stop], curve.load[:stop], curve.time[:stop])
    with pytest.raises(InputError, match="no unloading") as error:
        oliver_pharr(cut)
    assert error.value.field == "unloading"


def test_depth_that_does_not_fall_with_the_load_is_refused(curve):
    rng = np.random.default_rng(0)
    shuffled = curve.depth.copy()
    un = detect_segments(curve).unloading
    shuffled[un] = rng.permutation(shuffled[un])
    with pytest.raises(InputError, match="does not fall") as error:
        oliver_pharr(IndentationCurve(shuffled, curve.load, curve.time))
    assert error.value.field == "unloading"


def test_negative_depth_sign_is_refused(curve):
    with pytest.raises(InputError, match="multiply") as error:
        oliver_pharr(IndentationCurve(-curve.depth, curve.load, curve.time))
    assert error.value.field == "depth"


def test_no_hold_with_correction_asks_for_creep_fit_none():
    curve = synthetic_indentation_curve(0.98e9, hold_time=0.1, sampling_rate=5.0)
    with pytest.raises(InputError, match="creep_fit='none'") as error:
        oliver_pharr(curve)
    assert error.value.field == "hold"
    assert oliver_pharr(curve, creep_fit="none").youngs_modulus == pytest.approx(0.98e9, rel=1e-3)


def test_bad_options(curve):
    with pytest.raises(InputError) as error:
        oliver_pharr(curve, rate_sign="signed")
    assert error.value.field == "rate_sign"
    with pytest.raises(InputError) as error:
        oliver_pharr(curve, fit_range=(0.9, 0.2))
    assert error.value.field == "fit_range"
    with pytest.raises(InputError) as error:
        oliver_pharr(curve, creep_fit="log")
    assert error.value.field == "creep_fit"


def test_printed_sign_overcorrecting_to_negative_compliance_is_refused():
    curve = synthetic_indentation_curve(0.98e9, creep_rate=12e-9, hold_time=10.0, sampling_rate=5.0)
    with pytest.raises(InputError, match="compliance") as error:
        oliver_pharr(curve, rate_sign="printed", fit_range=(0.8, 1.0))
    assert error.value.field == "rate_sign"


def test_scalars_are_flat_and_area_function_and_beta_enter(curve):
    result = oliver_pharr(curve)
    scalars = result.scalars()
    assert all(isinstance(v, float | int | str) for v in scalars.values())
    assert scalars["rate_sign"] == "magnitude" and scalars["indenter"] == "diamond Berkovich"
    assert result.contact_area == pytest.approx(berkovich_area(result.contact_depth))
    doubled = oliver_pharr(curve, area_function=lambda d: 4 * berkovich_area(d))
    assert doubled.reduced_modulus == pytest.approx(result.reduced_modulus / 2)
    assert oliver_pharr(curve, beta=1.034).reduced_modulus == pytest.approx(result.reduced_modulus / 1.034)


@pytest.mark.parametrize(
    "header, separator",
    [
        ("time/s,depth/nm,load/mN", ","),
        ("time/s depth/nm load/mN", " "),
        ('Time (s); "Indentation_Depth [nm]"; "Normal-Load (mN)"', ";"),
    ],
)
def test_unit_after_a_slash_and_other_header_forms_read_through_the_text_table(tmp_path, header, separator):
    rows = "".join(separator.join((str(i), str(i * 10), str(i * 0.1))) + "\n" for i in range(12))
    read = read_indentation_csv(_write(tmp_path, f"# comment\n{header}\n{rows}"))
    np.testing.assert_allclose(read.time[:3], [0, 1, 2], rtol=0, atol=0)
    np.testing.assert_allclose(read.depth[:3], [0, 1e-8, 2e-8], rtol=1e-12, atol=0)
    np.testing.assert_allclose(read.load[:3], [0, 1e-4, 2e-4], rtol=1e-12, atol=0)


def test_split_header_forms():
    assert split_header("time/s") == ("time", "s")
    assert split_header("Load [mN]") == ("load", "mN")
    assert split_header(" depth (nm) ") == ("depth", "nm")
    assert split_header("stiffness/N/m") == ("stiffness", "N/m")
    assert split_header("load (corrected) [mN]") == ("load (corrected)", "mN")
    assert split_header("step") == ("step", None) and split_header("depth ()") == ("depth", None)
    assert split_header("/s") == ("/s", None)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("depth load\n" + "1 1\n" * 12, "no unit"),
        ("indentation depth (nm) load (mN)\n" + "1 1\n" * 12, "join the words"),
        ("1,2\n" * 12, "no header line"),
        ("# only a comment\n", "no header and data rows"),
        ("depth (nm),load (mN)\n", "no header and data rows"),
        ("depth\n" + "1\n" * 12, "single column"),
    ],
)
def test_table_shape_errors(tmp_path, text, message):
    with pytest.raises(InputError, match=message):
        read_indentation_csv(_write(tmp_path, text))


@pytest.mark.parametrize("timed", [True, False])
def test_to_xarray_holds_the_curve_fit_and_scalars_with_units(curve, timed, tmp_path):
    import xarray as xr

    curve = curve if timed else IndentationCurve(curve.depth, curve.load)
    result = oliver_pharr(curve)
    data = result.to_xarray()
    size = curve.depth.size
    expected = {"depth": "m", "load": "N", "segment": "1", "fit_load": "N", "in_fit_range": "1"}
    if timed:
        expected["time"] = "s"
        np.testing.assert_array_equal(data["time"], curve.time)
    assert {name: data[name].attrs["units"] for name in data.data_vars} == expected
    assert all(data[name].dims == ("sample",) and data[name].size == size for name in data.data_vars)
    np.testing.assert_array_equal(data["depth"], curve.depth)
    np.testing.assert_array_equal(data["load"], curve.load)
    segments = result.segments
    labels = data["segment"].values
    assert set(labels) == {"loading", "hold", "unloading"}
    assert (labels[: segments.hold.start] == "loading").all()
    assert (labels[segments.hold.start : segments.unloading.start] == "hold").all()
    assert (labels[segments.unloading] == "unloading").all()
    unloading = labels == "unloading"
    np.testing.assert_allclose(
        data["fit_load"].values[unloading],
        result.unloading_fit.load(curve.depth[unloading]),
        rtol=1e-15,
        atol=0,
    )
    assert np.isnan(data["fit_load"].values[~unloading]).all()
    assert int(data["in_fit_range"].sum()) == result.unloading_fit.points
    assert data.attrs == result.scalars()
    # the scalars survive a netCDF file
    path = tmp_path / "indentation.nc"
    data.to_netcdf(path)
    with xr.open_dataset(path) as back:
        assert set(back.attrs) == set(result.scalars())
        for name, value in result.scalars().items():
            assert back.attrs[name] == (
                pytest.approx(value, rel=1e-15) if isinstance(value, float) else value
            )
        assert list(back["segment"].values) == list(labels)


def test_result_protocol_units_name_every_dimensional_scalar(curve):
    result = oliver_pharr(curve)
    scalars = result.scalars()
    assert isinstance(result, Result)
    assert all(SCALAR_NAME.match(name) for name in scalars)
    assert set(IndentationResult.UNITS) <= set(scalars)
    dimensionless = {
        "time_basis", "fit_exponent", "fit_range_low", "fit_range_high", "fit_points", "creep_fit",
        "rate_sign", "epsilon", "beta", "poissons_ratio", "indenter", "indenter_poissons_ratio",
    }  # fmt: skip
    fractional = {"fit_alpha", "creep_fit_a"}  # units of fitted or fractional powers, documented
    assert set(scalars) == set(IndentationResult.UNITS) | dimensionless | fractional
    for unit in IndentationResult.UNITS.values():
        assert prefixed_scale(1.0, unit)  # every unit is one roughcontact.units can show


def _example_rows(depth_unit: str = "nm", load_unit: str = "mN") -> str:
    """The synthetic HDPE curve of examples/ as CSV text (depth in nm, load in mN), header units as given."""
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "examples" / "paper001_indentation_hdpe.csv").read_text()
    return text.replace("depth (nm)", f"depth ({depth_unit})").replace("load (mN)", f"load ({load_unit})")


def test_a_unit_option_that_contradicts_the_header_is_refused_naming_the_cell(tmp_path):
    path = _write(tmp_path, _example_rows())
    with pytest.raises(InputError) as error:
        read_indentation_csv(path, depth_unit="um")
    assert error.value.field == "depth_unit"
    assert error.value.problem == "'um' contradicts the header cell 'depth (nm)' of c.csv, which gives [nm]."
    assert error.value.fix_in("cli").startswith("leave --depth-unit out: the column is read in nm")
    # the header's own unit, typed again, is no contradiction
    np.testing.assert_array_equal(
        read_indentation_csv(path, depth_unit="nm").depth, read_indentation_csv(path).depth
    )


@pytest.mark.parametrize(
    ("depth_unit", "load_unit", "column", "reached"),
    [
        ("m", "mN", "depth", "3.004 km"),  # nm labelled m: issue 45's 3 km and 967 pPa
        ("nm", "kN", "load", "10 kN"),
        ("fm", "mN", "depth", "3.004 pm"),
        ("nm", "fN", "load", "10 fN"),
    ],
)
def test_a_depth_or_load_no_indentation_reaches_is_refused(tmp_path, depth_unit, load_unit, column, reached):
    path = _write(tmp_path, _example_rows(depth_unit, load_unit))
    with pytest.raises(InputError) as error:
        read_indentation_csv(path)
    assert error.value.field == str(path)
    assert f"the {column} column of c.csv, read in the unit of its header cell" in error.value.problem
    assert f"reaches {reached}" in error.value.problem
    assert error.value.fix.startswith(f"check the unit of the {column} column: correct its header cell")


def test_a_wrong_unit_option_is_refused_as_implausible_naming_the_option(tmp_path):
    path = _write(tmp_path, _example_rows().replace("depth (nm)", "depth"))
    with pytest.raises(InputError) as error:
        read_indentation_csv(path, depth_unit="m")
    assert error.value.field == "depth_unit" and "read in 'm', reaches 3.004 km" in error.value.problem
    assert (
        error.value.fix_in("cli")
        == "check the unit of the depth column: give the unit its values are in, e.g. --depth-unit nm."
    )
    assert read_indentation_csv(path, depth_unit="nm").depth.max() == pytest.approx(3.004e-6, rel=1e-3)


def test_units_written_with_in_are_read(tmp_path):
    path = _write(
        tmp_path,
        "time in s,depth in nm,load in mN\n" + "".join(f"{i},{i * 10},{i * 0.1}\n" for i in range(12)),
    )
    read = read_indentation_csv(path)
    np.testing.assert_allclose(read.depth[:3], [0, 1e-8, 2e-8], rtol=1e-12, atol=0)
    np.testing.assert_allclose(read.load[:3], [0, 1e-4, 2e-4], rtol=1e-12, atol=0)
    assert split_header("time in contact") == ("time in contact", None)
    assert split_header("x in µm") == ("x", "µm") and split_header("X_(microns)") == ("x_", "microns")
