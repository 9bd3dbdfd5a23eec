"""Files with undefined (missing) points: described always, filled only when asked (issue 15)."""

import json

import numpy as np
import pytest

from roughcontact.study import load_study, run_study
from roughcontact.study.config import StudyError

SHARED = "../shared/data/topographies"


@pytest.fixture(scope="module")
def holes(tmp_path_factory):
    """A 32 x 32 height matrix (text, nm) whose first 10 rows are undefined: 31.25 % of the points."""
    path = tmp_path_factory.mktemp("holes") / "holes.txt"
    heights = np.random.default_rng(1).normal(size=(32, 32))
    heights[:10, :] = np.nan
    np.savetxt(path, heights)
    return path


READ = ("--size", "1 um", "--height-unit", "nm")


def test_inspect_describes_a_file_with_undefined_points(run):
    """SurfaceTopography's sur-2.sur: 117 of 563 x 484 points undefined."""
    status, out, err = run("inspect", f"{SHARED}/sur-2.sur")
    assert status == 0, err
    assert "undefined      117 of 272492 points (0.0429 %)" in out
    assert "need every point: add --fill-undefined" in out
    status, out, _ = run("inspect", f"{SHARED}/sur-2.sur", "--json")
    document = json.loads(out)
    assert document["undefined"]["count"] == 117 and "statistics" not in document


def test_inspect_fills_a_few_points_when_asked_and_says_how_many(run):
    status, out, _ = run("inspect", f"{SHARED}/sur-2.sur", "--fill-undefined")
    assert status == 0
    assert "117 points (0.0429 %) filled by interpolation" in out and "Sq" in out


def test_filling_more_than_5_percent_needs_max_filled(run, holes):
    status, _, err = run("inspect", holes, *READ, "--fill-undefined")
    assert status == 2
    assert "--max-filled: holes.txt: 31.2 % of the points are undefined" in err
    assert "--max-filled 0.32" in err
    status, out, _ = run("inspect", holes, *READ, "--fill-undefined", "--max-filled", "0.32")
    assert status == 0 and "320 points (31.2 %) filled by interpolation" in out


def test_plot_draws_where_the_points_are_missing(run, holes, tmp_path):
    status, out, _ = run("plot", holes, *READ, "-o", tmp_path / "holes.png")
    assert status == 0 and (tmp_path / "holes.png").stat().st_size > 0


def test_a_command_reports_the_filled_fraction(run, holes):
    argv = ("contact", holes, *READ, "--material", "SU-8", "--pressure", "1 MPa", "--fill-undefined")
    status, _, err = run(*argv)
    assert status == 2 and "--max-filled" in err and "31.2 %" in err
    status, out, _ = run(*argv, "--max-filled", "0.32")
    assert status == 0
    assert "31.2 % of the points (320) were undefined, filled by harmonic interpolation" in out


def test_a_study_needs_max_filled_and_keeps_the_fraction(tmp_path, holes):
    text = f"""
[study]
name = "holes"

[topographies.scan]
file = "{holes}"
size = "1 um"
height_unit = "nm"
fill_undefined = true
{{max_filled}}

[[analysis]]
name = "contact"
model = "normal"
topography = "scan"
material = "SU-8"
mean_pressure = "1 MPa"
"""
    (tmp_path / "study.toml").write_text(text.replace("{max_filled}", ""))
    with pytest.raises(StudyError) as caught:
        load_study(tmp_path / "study.toml")
    (problem,) = caught.value.problems
    assert problem.field == "topographies.scan (max_filled)" and "max_filled = 0.32" in problem.fix
    (tmp_path / "study.toml").write_text(text.replace("{max_filled}", "max_filled = 0.32"))
    run_study(load_study(tmp_path / "study.toml"), tmp_path / "out")
    provenance = json.loads((tmp_path / "out" / "provenance.json").read_text())
    assert provenance["topographies"]["scan"]["undefined_points_filled"] == 320
    assert provenance["topographies"]["scan"]["undefined_fraction_filled"] == pytest.approx(0.3125)
