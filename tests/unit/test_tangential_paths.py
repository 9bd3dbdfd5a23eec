"""Tangential loading programmes: the builders, the reversal rule and reading a user's path file."""

import numpy as np
import pytest

from roughcontact.contact.paths import read_path_csv, read_programme_csv, reversals, stroke_path
from roughcontact.errors import InputError, UnitError


def _write(tmp_path, text, name="path.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_lengths_prescribe_the_displacement_in_metres(tmp_path):
    path = _write(tmp_path, "# a cycle\nstep,x [um],y [nm]\n1,0.5,0\n2,1.0,250\n3,0.25,-250\n")
    programme, control = read_path_csv(path)
    assert control == "displacement"
    np.testing.assert_allclose(programme, [[0.5e-6, 0.0], [1e-6, 250e-9], [0.25e-6, -250e-9]], rtol=1e-15)


def test_forces_prescribe_the_force_and_a_single_column_is_along_x(tmp_path):
    path = _write(tmp_path, "t [s]\tQ_x [mN]\n0.1\t1\n0.2\t2.5\n")
    programme, control = read_path_csv(path)
    assert control == "force"
    np.testing.assert_allclose(programme, [[1e-3, 0.0], [2.5e-3, 0.0]], rtol=1e-15)


def test_the_same_programme_in_other_units_reads_the_same(tmp_path):
    in_um, _ = read_path_csv(_write(tmp_path, "x [um]  y [um]\n1.5 0\n-0.25 1\n", "um.csv"))  # whitespace
    in_nm, _ = read_path_csv(_write(tmp_path, "x [nm];y [nm]\n1500;0\n-250;1000\n", "nm.csv"))
    np.testing.assert_allclose(in_um, in_nm, rtol=1e-15)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("0.5,0\n1.0,0\n", "no header"),
        ("x,y [um]\n1,2\n", "'x' has no unit"),
        ("x [um],Q [mN]\n1,2\n", "of the same kind"),
        ("p [MPa]\n1\n", "neither a length nor a force"),
        ("x [um],y [um],w [um]\n1,2,3\n", "3 tangential displacement or force column"),
        ("x [um]\n1\nabc\n", "data row 2"),
        ("x [um]\n1\nnan\n", "step 1 is not a finite number"),
        ("x [um]\n", "no steps"),
    ],
)
def test_bad_path_files_are_refused_with_the_fix(tmp_path, text, message):
    with pytest.raises(InputError, match=message) as error:
        read_path_csv(_write(tmp_path, text))
    assert "Fix" in str(error.value)


def test_an_unknown_unit_is_a_unit_error(tmp_path):
    with pytest.raises(UnitError, match="furlong"):
        read_path_csv(_write(tmp_path, "x [furlong]\n1\n"))


def test_a_missing_path_file_is_refused(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        read_path_csv(tmp_path / "missing.csv")


def test_reversals_of_the_stroke_path_and_holds():
    path = stroke_path(1.0, cycles=2, steps_per_stroke=3)  # up 3, down 3, up 3, down 3
    assert reversals(path).tolist() == [2, 5, 8]
    assert reversals([1.0, 2.0, 2.0, 1.0]).tolist() == [2]  # a hold is no reversal; its last step is
    assert reversals([1.0, 2.0, 3.0]).size == 0
    held = 2.0 + np.array([0.0, 4e-16, -4e-16, 4e-16])  # a force held under force control, with round-off
    assert reversals(np.concatenate([[1.0], held, [1.0]])).tolist() == [4]


def test_a_normal_column_makes_a_combined_programme(tmp_path):
    text = "step,x [um],F_n [mN]\n1,0,5\n2,0.5,20\n3,1,20\n"
    programme = read_programme_csv(_write(tmp_path, text, "combined.csv"))
    assert programme.control == "displacement" and programme.normal_control == "force"
    np.testing.assert_allclose(programme.tangential[:, 0], [0, 0.5e-6, 1e-6])
    np.testing.assert_allclose(programme.normal, [5e-3, 20e-3, 20e-3])
    approach = read_programme_csv(_write(tmp_path, "Q_x [mN],z [nm]\n1,10\n", "approach.csv"))
    assert approach.control == "force" and approach.normal_control == "approach"
    np.testing.assert_allclose(approach.normal, [10e-9])


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("x [um],F_n [mN]\n0,5\n0,0\n", "contact is lost"),
        ("x [um],F_n [mN],z [um]\n0,5,1\n", "at most one"),
        ("x [um],Q_y [mN],F_n [mN]\n0,1,5\n", "mixed controls"),
        ("x [um],F_n [mN]\n0,nan\n", "not a finite"),
    ],
)
def test_bad_combined_programmes_name_the_problem(tmp_path, text, words):
    with pytest.raises(InputError) as error:
        read_programme_csv(_write(tmp_path, text, "bad.csv"))
    assert words in str(error.value)


def test_a_tangential_reader_refuses_a_combined_programme(tmp_path):
    with pytest.raises(InputError, match="solve_frictional"):
        read_path_csv(_write(tmp_path, "x [um],F_n [mN]\n0,5\n", "combined.csv"))
