import numpy as np
import pytest

from roughcontact.errors import InputError
from roughcontact.topography import Topography


def test_geometry_of_a_map():
    t = Topography(np.zeros((4, 8)), (2e-6, 4e-6))
    assert t.dim == 2
    assert t.shape == (4, 8)
    assert t.spacing == (0.5e-6, 0.5e-6)
    assert t.pixel_area == pytest.approx(0.25e-12, rel=1e-15, abs=0)
    assert t.area == pytest.approx(8e-12, rel=1e-15, abs=0)
    x, y = t.coordinates()
    assert x[1] == 0.5e-6 and len(y) == 8
    xx, yy = t.meshgrid()
    assert xx.shape == (4, 8) and yy[0, 3] == 1.5e-6


def test_profile_and_scalar_size():
    t = Topography(np.arange(5.0), 5e-6)
    assert t.dim == 1 and t.size == (5e-6,) and t.spacing == pytest.approx((1e-6,), rel=1e-15, abs=0)
    square = Topography(np.zeros((3, 3)), 3e-6)
    assert square.size == (3e-6, 3e-6)


def test_is_immutable_and_copies_input():
    heights = np.zeros((3, 3))
    t = Topography(heights, (1.0, 1.0))
    heights[0, 0] = 5.0
    assert t.heights[0, 0] == 0.0
    with pytest.raises(ValueError):
        t.heights[0, 0] = 1.0
    with pytest.raises(AttributeError):
        t.periodic = True
    with pytest.raises(TypeError):
        t.info["name"] = "x"


@pytest.mark.parametrize(
    ("heights", "size", "field", "fragment"),
    [
        (np.array([[0.0, np.nan], [0.0, 0.0]]), (1.0, 1.0), "heights", "1 of 4 heights are NaN or infinite"),
        (np.array([[0.0, np.inf], [0.0, 0.0]]), (1.0, 1.0), "heights", "NaN or infinite"),
        (np.zeros((2, 2)), (0.0, 1.0), "size", "must be positive"),
        (np.zeros((2, 2)), (-1.0, 1.0), "size", "must be positive"),
        (np.zeros((2, 2)), (np.nan, 1.0), "size", "must be positive"),
        (np.zeros((2, 2)), (1.0, 1.0, 1.0), "size", "got 3 values for a 2D"),
        (np.zeros((2, 2, 2)), (1.0, 1.0), "heights", "3 dimensions"),
        (np.zeros((1, 5)), (1.0, 1.0), "heights", "fewer than 2 points"),
        (np.zeros(0), (1.0,), "heights", "fewer than 2 points"),
    ],
)
def test_bad_input_names_field_and_fix(heights, size, field, fragment):
    with pytest.raises(InputError) as info:
        Topography(heights, size)
    assert info.value.field == field
    assert fragment in str(info.value)
    assert info.value.fix


def test_with_heights_records_history_and_checks_shape():
    t = Topography(np.zeros((3, 3)), (1.0, 1.0), info={"name": "a"})
    u = t.with_heights(np.ones((3, 3)), step="offset")
    v = u.with_heights(np.ones((3, 3)) * 2, step="double")
    assert v.info["history"] == ("offset", "double")
    assert t.info == {"name": "a"}
    with pytest.raises(InputError, match="does not match the grid"):
        t.with_heights(np.ones((2, 3)))


def test_equality_by_value():
    a = Topography(np.ones((3, 3)), (1.0, 1.0))
    assert a == Topography(np.ones((3, 3)), (1.0, 1.0))
    assert a != Topography(np.ones((3, 3)), (1.0, 2.0))
    assert "3 x 3 points" in repr(a)
