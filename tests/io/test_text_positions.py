"""Text files of points (x z or x y z columns): their positions give the size, in the unit they carry.

SurfaceTopography's example files (tests/data, from its test/file_format_examples): ``csv-1.csv``
has the header ``X_(microns),y1`` and 8 points at 0.0386 um (rounded, so not quite uniform);
``csv-2.csv`` and ``csv-3.csv`` are UTF-16 with ``x in µm,y in µm`` (``csv-2`` with an index column
first). The size of n points is n times their spacing (n pixels), not the range (n - 1 spacings):
for ``csv-1.csv`` 8 x 0.03861 um = 0.3089 um, not 0.2703 um. A size beside a file's own positions
is refused; positions without a unit take ``position_unit``, never a size.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from roughcontact.errors import InputError, MissingMetadataError
from roughcontact.topography.io import list_channels, read_scan

DATA = Path(__file__).resolve().parents[1] / "data"
CSV1 = DATA / "csv-1.csv"
CSV1_X = np.array([0.0386, 0.0772, 0.1158, 0.1544, 0.1931, 0.2317, 0.2703, 0.3089])
CSV1_SIZE = 8 * (CSV1_X[-1] - CSV1_X[0]) / 7  # n spacings: 0.30891 um


def _unit_less(tmp_path: Path, header: str | None = "x,z") -> Path:
    """csv-1.csv with another header line (None: none), so that its positions carry no unit."""
    rows = CSV1.read_text().splitlines()[1:]
    path = tmp_path / "points.csv"
    path.write_text("\n".join(([header] if header is not None else []) + rows) + "\n")
    return path


def test_csv1_size_is_its_points_times_their_spacing_in_the_unit_of_its_header():
    scan = read_scan(CSV1, height_unit="um")
    assert scan.size == pytest.approx((CSV1_SIZE * 1e-6,), rel=1e-12, abs=0)
    assert scan.size[0] == pytest.approx(0.30891e-6, rel=1e-4)  # not the range, 0.2703 um
    assert scan.info["size_from"] == "positions"
    assert (scan.info["position_unit"], scan.info["position_unit_from"]) == ("microns", "file")
    (channel,) = list_channels(CSV1)
    assert channel.size == pytest.approx((CSV1_SIZE * 1e-6,), rel=1e-12, abs=0)
    assert channel.size_unit == "microns" and channel.height_unit is None  # 'y1' gives none


def test_csv1_heights_need_their_unit_and_only_that():
    with pytest.raises(MissingMetadataError) as caught:
        read_scan(CSV1)
    assert caught.value.field == "height_unit" and set(caught.value.missing) == {"height_unit"}
    assert "--height-unit nm" in caught.value.fix_in("cli") and "--size" not in caught.value.fix_in("cli")


def test_a_size_beside_positions_with_a_unit_is_refused_naming_the_header_cell():
    with pytest.raises(InputError) as caught:
        read_scan(CSV1, size="0.2703 um", height_unit="um")
    error = caught.value
    assert error.field == "size"
    assert "its header cell 'X_(microns)'" in error.problem
    assert "8 points 38.61 nm apart: a size of 8 x 38.61 nm = 308.9 nm" in error.problem
    assert error.fix_in("cli") == "leave --size out: the positions give the size, 308.9 nm."
    assert error.fix_in("study").startswith("remove size:")
    # even the size the positions make is refused: the file gives it
    with pytest.raises(InputError, match="a size beside them is refused"):
        read_scan(CSV1, size=f"{CSV1_SIZE} um", height_unit="um")
    with pytest.raises(InputError, match="a size beside them is refused"):
        read_scan(CSV1, size="1 um", height_unit="um", override_file_values=True)


def test_a_position_unit_that_contradicts_the_header_is_refused_unless_overridden():
    with pytest.raises(InputError) as caught:
        read_scan(CSV1, position_unit="nm", height_unit="um")
    assert caught.value.field == "position_unit"
    assert "'microns' (its header cell 'X_(microns)')" in caught.value.problem
    assert "'nm' was given" in caught.value.problem
    assert "--override-file-values" in caught.value.fix_in("cli")
    assert (
        read_scan(CSV1, position_unit="um", height_unit="um").size == read_scan(CSV1, height_unit="um").size
    )
    overridden = read_scan(CSV1, position_unit="nm", height_unit="um", override_file_values=True)
    assert overridden.size == pytest.approx((CSV1_SIZE * 1e-9,), rel=1e-12, abs=0)
    assert overridden.info["position_unit_from"] == "user"


@pytest.mark.parametrize("header", ["x,z", None])
def test_positions_without_a_unit_ask_for_it_with_the_size_they_make(tmp_path, header):
    path = _unit_less(tmp_path, header)
    with pytest.raises(MissingMetadataError) as caught:
        read_scan(path, height_unit="um")
    error = caught.value
    assert error.field == "position_unit" and error.missing == {"position_unit": "um"}
    assert "8 points 0.03861 apart: a size of 8 x 0.03861 = 0.3089 in a unit the file does not name" in (
        error.problem
    )
    assert error.fix_in("cli").startswith("give the real values, e.g. --position-unit um;")
    assert "positions in um make a size of 308.9 nm" in error.fix_in("cli")
    # the hint followed: the size is the one it said
    scan = read_scan(path, height_unit="um", position_unit="um")
    assert scan.size == pytest.approx((CSV1_SIZE * 1e-6,), rel=1e-12, abs=0)
    assert scan.info["position_unit_from"] == "user"


def test_a_size_beside_positions_without_a_unit_is_refused_asking_for_their_unit(tmp_path):
    path = _unit_less(tmp_path)
    with pytest.raises(InputError) as caught:
        read_scan(path, size="0.2703 um", height_unit="um")
    error = caught.value
    assert error.field == "size" and "without a unit" in error.problem and "they need a unit" in error.problem
    assert error.fix_in("cli") == (
        "leave --size out and give the positions' unit: --position-unit um (if they are micrometres, the "
        "size is then 308.9 nm)."
    )


@pytest.mark.parametrize("name", ["csv-2.csv", "csv-3.csv"])
def test_utf16_points_with_units_written_in_words_need_nothing_more(name):
    """``x in µm,y in µm`` (csv-2: after an index column): 8 points 1/12 um apart make 2/3 um."""
    scan = read_scan(DATA / name)
    assert scan.size == pytest.approx((8 / 12 * 1e-6,), rel=1e-9, abs=0)
    assert scan.info["position_unit"] == "µm" and scan.info["height_unit"] == "µm"
    np.testing.assert_allclose(scan.heights, -1.42743285743491e-6, rtol=1e-12)


def test_a_grid_of_points_takes_the_units_of_its_header_cells(tmp_path):
    rows = [f"{0.5 * i},{0.25 * j},{i * j + i}" for j in range(3) for i in range(4)]
    path = tmp_path / "grid.csv"
    path.write_text("\n".join(["x [um],y [um],z [nm]", *rows]) + "\n")
    scan = read_scan(path)
    assert scan.heights.shape == (4, 3)
    assert scan.size == pytest.approx((2e-6, 0.75e-6), rel=1e-12, abs=0)  # 4 x 0.5 um, 3 x 0.25 um
    assert scan.info["height_unit"] == "nm"
    with pytest.raises(InputError) as caught:
        read_scan(path, size="2 um")
    assert "its header cells 'x [um]' and 'y [um]'" in caught.value.problem
    assert "4 x 3 points 500 nm x 250 nm apart: a size of 2 µm x 750 nm" in caught.value.problem
    path.write_text("\n".join(["x [um],y [nm],z [nm]", *rows]) + "\n")
    with pytest.raises(InputError, match=r"give \[um\] and \[nm\]: a grid of points has one unit"):
        read_scan(path)
    path.write_text("\n".join(["x [s],y [s],z [nm]", *rows]) + "\n")
    with pytest.raises(InputError, match=r"'x \[s\]' of grid.csv gives \[s\], not a length"):
        read_scan(path)


@pytest.mark.parametrize("name", ["txt_example.txt", "single_column.txt"])
def test_a_position_unit_for_a_file_without_positions_is_refused(name):
    with pytest.raises(InputError) as caught:
        read_scan(DATA / name, position_unit="um", size="1 um", height_unit="nm")
    assert caught.value.field == "position_unit" and "holds a grid of heights" in caught.value.problem
    assert caught.value.fix_in("cli").startswith("leave --position-unit out")


def test_a_position_unit_for_a_native_file_is_refused(tmp_path):
    from roughcontact.topography import Topography
    from roughcontact.topography.native import save_topography

    path = tmp_path / "flat.nc"
    save_topography(Topography(np.arange(16.0).reshape(4, 4) * 1e-9, 1e-6), path)
    with pytest.raises(InputError) as caught:
        read_scan(path, position_unit="um")
    assert caught.value.field == "position_unit" and "roughcontact height grid" in caught.value.problem


def test_a_matrix_without_a_size_still_asks_for_one(tmp_path):
    scan = read_scan(DATA / "txt_example.txt")  # '# Width: 1.0e-6 m', '# Height: 0.5e-6 m'
    assert scan.size == pytest.approx((1e-6, 0.5e-6), rel=1e-12, abs=0)
    with pytest.raises(MissingMetadataError) as caught:
        read_scan(DATA / "single_column.txt")
    assert set(caught.value.missing) == {"size", "height_unit"}
