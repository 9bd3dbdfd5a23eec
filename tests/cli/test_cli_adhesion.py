"""The ``adhesion`` command end to end: text, JSON, figures, table and report; errors naming options."""

import pytest

from roughcontact.cli import EXIT_INPUT_ERROR
from roughcontact.topography.generate import sphere
from roughcontact.topography.native import save_topography

BALL = {"shape": (32, 32), "size": 200e-9, "radius": 1e-6}


@pytest.fixture(scope="module")
def ball_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("adhesion") / "ball.nc"
    save_topography(sphere(**BALL), path)
    return path


COMMAND = ["--material-youngs-modulus", "4 GPa", "--material-poissons-ratio", "0.3", "--max-approach", "1 nm"]


def test_the_command_prints_writes_figures_a_table_and_a_report(run, ball_file, tmp_path, cases, table):
    folder = tmp_path / "out"
    argv = ["adhesion", ball_file, *COMMAND, "--work-of-adhesion", "50 mJ/m^2", "--steps", "8"]
    status, out, err = run(*argv, "--ranges", "1.9 nm", "5 nm", "-o", folder)
    assert status == 0, err
    assert "pull_off_force" in out and "nN" in out
    for figure in ("force_approach", "maps", "pull_off"):
        assert (folder / "figures" / f"adhesion_{figure}.png").stat().st_size > 0
    assert (folder / "tables" / "adhesion_adhesion.csv").exists()
    assert "pull_off" in (folder / "report.html").read_text()
    status, out, err = run(*argv, "--ranges", "1.9 nm", "5 nm", "-o", folder, "--json")
    assert status == 0, err
    found = cases(out)
    assert [c["scalars"]["interaction_length"] for c in found] == pytest.approx([1.9e-9, 5e-9])
    rows = table(out, "adhesion")
    assert rows[0]["law"] == "Maugis-Dugdale" and rows[0]["pull_off_force [N]"] > 0


def test_the_command_names_the_option_of_a_problem(run, ball_file, capsys):
    status, _, err = run("adhesion", ball_file, *COMMAND)
    assert status == EXIT_INPUT_ERROR and "--surface-energy" in err and "--work-of-adhesion" in err
    assert "the material has none" in err
    with pytest.raises(SystemExit) as stopped:
        run("adhesion", ball_file, *COMMAND, "--work-of-adhesion", "50 mJ/m^2", "--law", "morse")
    assert stopped.value.code == EXIT_INPUT_ERROR
    assert "unknown law 'morse'; use one of md (maugis_dugdale)" in capsys.readouterr().err
    status, _, err = run("adhesion", ball_file, *COMMAND, "--work-of-adhesion", "-5 mJ/m^2")
    assert status == EXIT_INPUT_ERROR and "--work-of-adhesion" in err
