"""Plain-text heights read strictly (issue 32): a damaged table is refused at its line, never shifted."""

import gzip

import numpy as np
import pytest

from roughcontact.errors import UnsupportedFormatError
from roughcontact.topography.io import read_topography
from roughcontact.topography.text import TextFormatError, decode_text, parse_table

HEIGHTS = np.random.default_rng(4).normal(size=(7, 9))


def lines(separator=" ", decimal="."):
    return [separator.join(f"{v:.8f}".replace(".", decimal) for v in row) for row in HEIGHTS]


@pytest.mark.parametrize(
    ("separator", "decimal", "layout"),
    [
        (" ", ".", "whitespace-separated"),
        ("\t", ".", "whitespace-separated"),
        (",", ".", "comma-separated"),
        (";", ".", "semicolon-separated"),
        (";", ",", "semicolon-separated, decimal comma"),
        ("\t", ",", "whitespace-separated, decimal comma"),
    ],
)
def test_every_layout_reads_the_same_numbers(separator, decimal, layout):
    table = parse_table("\n".join(lines(separator, decimal)))
    assert table.layout == layout
    np.testing.assert_allclose(table.values, np.round(HEIGHTS, 8), rtol=0, atol=1e-12)


def test_header_comments_trailing_separators_and_undefined_markers():
    text = ["# Width: 5 um", "# Value units: nm", *[line + "," for line in lines(",")], "# end"]
    text[4] = text[4].replace(text[4].split(",")[2], "NaN", 1)
    table = parse_table("\n".join(text))
    assert (
        table.shape == (7, 9)
        and table.first_line == 3
        and table.header == ("# Width: 5 um", "# Value units: nm")
    )
    assert np.isnan(table.values[2, 2]) and np.count_nonzero(np.isnan(table.values)) == 1


@pytest.mark.parametrize(
    ("edit", "line", "words"),
    [
        (
            lambda t: t.__setitem__(3, t[3].replace(t[3].split()[4], "x", 1)),
            4,
            "value 5, 'x', is not a number",
        ),
        (
            lambda t: t.__setitem__(0, t[0].replace(t[0].split()[1], "1.2.3", 1)),
            1,
            "stands right before the data",
        ),
        (lambda t: t.__setitem__(6, " ".join(t[6].split()[:8])), 7, "8 values, where the data"),
        (lambda t: t.append("the end"), 8, "text after the data"),
        (lambda t: t.insert(3, "# a second block"), 4, "a comment between data lines"),
        (lambda t: t.__setitem__(2, t[2] + " 1.0"), 3, "10 values"),
    ],
    ids=["token", "first row", "short row", "trailing text", "comment inside", "long row"],
)
def test_a_damaged_table_is_refused_at_its_line(edit, line, words):
    text = lines()
    edit(text)
    with pytest.raises(TextFormatError) as caught:
        parse_table("\n".join(text))
    assert caught.value.line == line and words in caught.value.problem


def test_a_count_line_before_columns_is_header_but_not_before_a_matrix():
    assert parse_table("µm µm\n3\n0, 1\n1, 2\n2, 4\n").shape == (3, 2)  # Gwyddion's x y export
    with pytest.raises(TextFormatError, match="5 values"):
        parse_table("\n".join(["1 2 3 4 5", *lines()]))


def test_no_numbers_at_all():
    with pytest.raises(TextFormatError) as caught:
        parse_table("This is nonsense.\nSo is this.\n")
    assert caught.value.line is None


def test_text_or_binary():
    assert decode_text("1 2\n3 4\n".encode("utf-16")) == "1 2\n3 4\n"
    assert decode_text(b"\xb5m 1.0\n") == "µm 1.0\n"  # Latin-1 of an old Windows export
    assert decode_text(b"\x00\x01\x02\x03") is None


# --- through read_topography ---------------------------------------------------------------------


def _write(path, text):
    path.write_text(text)
    return path


def test_comma_and_semicolon_matrices_read_like_the_blank_separated_one(tmp_path):
    plain = read_topography(
        _write(tmp_path / "m.txt", "\n".join(lines())), size="9 um x 7 um", height_unit="nm", detrend="none"
    )
    for name, text in [("m.csv", "\n".join(lines(","))), ("m.dat", "\n".join(lines(";", ",")))]:
        other = read_topography(
            _write(tmp_path / name, text), size="9 um x 7 um", height_unit="nm", detrend="none"
        )
        np.testing.assert_array_equal(other.heights, plain.heights)
    np.testing.assert_allclose(plain.heights, np.round(HEIGHTS, 8).T * 1e-9, rtol=1e-15)  # rows are y


def test_a_header_gives_size_and_unit_to_a_comma_separated_matrix(tmp_path):
    header = "# Width: 9 um\n# Height: 7 um\n# Value units: nm\n"
    topography = read_topography(_write(tmp_path / "m.csv", header + "\n".join(lines(","))), detrend="none")
    assert topography.size == pytest.approx((9e-6, 7e-6), rel=1e-12)
    np.testing.assert_allclose(topography.heights, np.round(HEIGHTS, 8).T * 1e-9, rtol=1e-12)


def test_a_matrix_with_a_bad_token_is_refused_not_shifted(tmp_path):
    text = lines()
    text[4] = text[4].replace(text[4].split()[6], "abc", 1)
    path = _write(tmp_path / "m.txt", "\n".join(text))
    with pytest.raises(UnsupportedFormatError) as caught:
        read_topography(path, size="5 um", height_unit="nm")
    assert caught.value.field == str(path)
    assert "line 5: value 7, 'abc', is not a number" in caught.value.problem
    assert "Plain text" in caught.value.problem  # what SurfaceTopography alone would have done


def test_a_gzipped_damaged_matrix_is_refused_too(tmp_path):
    text = lines()
    text[2] = " ".join(text[2].split()[:5])
    path = tmp_path / "m.txt.gz"
    path.write_bytes(gzip.compress("\n".join(text).encode()))
    with pytest.raises(UnsupportedFormatError, match="line 3"):
        read_topography(path, size="5 um", height_unit="nm")


def test_a_small_ragged_file_is_not_an_elevation_tile(tmp_path):
    path = _write(tmp_path / "r.txt", "1 2 3\n4 5\n6 7 8 9\n")  # 18 bytes: NASA SRTM by size alone
    with pytest.raises(UnsupportedFormatError) as caught:
        read_topography(path, size="5 um", height_unit="nm")
    assert "line" in caught.value.problem and "NASA SRTM" in caught.value.problem


def test_a_binary_file_taken_only_by_its_size_is_refused_unless_named_hgt(tmp_path):
    content = np.arange(9, dtype=">i2").tobytes()  # 18 bytes: 3 x 3 points of 2 bytes
    path = tmp_path / "tile.bin"
    path.write_bytes(content)
    with pytest.raises(UnsupportedFormatError, match="by its size alone"):
        read_topography(path)
