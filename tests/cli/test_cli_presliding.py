"""roughcontact presliding and loop-analysis: outputs, JSON, units and clear errors (small grids)."""

import json
from pathlib import Path

import pytest

from roughcontact.cli import EXIT_INPUT_ERROR, main
from roughcontact.materials import get_material
from roughcontact.models import paper001
from roughcontact.topography import generate
from roughcontact.topography.io import save_topography

MEASURED = Path(__file__).parents[2] / "examples" / "paper001_measured_loop.csv"


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


@pytest.fixture(scope="module")
def ball_file(tmp_path_factory):
    """A 64^2 window of a rough POM-like ball (sphere R = 5 mm, 0.05 um rms, 2.15 um pixels)."""
    scan = generate.sphere_with_roughness(
        (64, 64), (64 * 2.148e-6,) * 2, radius=5e-3, rms_height=5e-8, seed=3
    )
    path = tmp_path_factory.mktemp("ball") / "ball.nc"
    save_topography(scan, path)
    return path


def test_presliding_on_a_file_writes_loops_table_and_figures(capsys, tmp_path, ball_file):
    status, out, err = run(
        capsys,
        "presliding",
        ball_file,
        "--material",
        "POM",
        "--counter",
        "silicon wafer",
        "--force",
        "5 mN",
        "--mu",
        "0.1",
        "--stroke",
        "0.4 um",
        "--cycles",
        "2",
        "--steps-per-stroke",
        "10",
        "--measured",
        MEASURED,
        "-o",
        tmp_path,
        "--json",
    )
    assert status == 0, err
    (row,) = json.loads(out)
    assert row["mu"] == 0.1 and row["F0 [N]"] == pytest.approx(5e-3)
    assert row["mu_from_loop"] == pytest.approx(0.1, rel=1e-3)  # the loop slides at mu F0
    assert 0 < row["K_L_C [N/m]"] < row["K_L_B [N/m]"] < row["K_L_A [N/m]"]
    assert row["K_L_A_mindlin_printed [N/m]"] == pytest.approx(4 * row["K_L_A_mindlin_johnson [N/m]"])
    for name in ("presliding.json", "loops.png", "stick_slip.png", "loop_ball_5_mN.csv"):
        assert (tmp_path / name).stat().st_size > 0


def test_presliding_errors_name_the_field(capsys, tmp_path, ball_file):
    status, _, err = run(
        capsys, "presliding", ball_file, "--material", "POM", "--force", "5 mN", "-o", tmp_path
    )
    assert status == EXIT_INPUT_ERROR and "--mu" in err
    status, _, err = run(
        capsys,
        "presliding",
        ball_file,
        "--material",
        "POM",
        "--force",
        "5 mN",
        "--mu",
        "0.1",
        "--stroke",
        "1 kg",
        "-o",
        tmp_path,
    )
    assert status == EXIT_INPUT_ERROR and "--stroke" in err
    status, _, err = run(capsys, "presliding", "-o", tmp_path)
    assert status == EXIT_INPUT_ERROR and "FILE" in err


def test_paper001_window_too_small_is_refused():
    """HDPE at 75 mN touches the border of a 0.1 mm window: refused, not cut off silently."""
    with pytest.raises(Exception, match="border of the solved window"):
        paper001.run_case("HDPE", 0.075, window=48, pixels=512, cycles=1, steps_per_stroke=2)


def test_paper001_case_uses_table_1_and_2():
    assert paper001.TABLE1["POM"][0.050] == (3.370e-6, 0.104)
    assert get_material("HDPE").youngs_modulus == 0.98e9
    with pytest.raises(Exception, match="not in Table 1"):
        paper001.run_case("POM", 0.03)


def test_loop_analysis_of_the_measured_example(capsys):
    status, out, _ = run(capsys, "loop-analysis", MEASURED, "--normal-force", "25 mN", "--json")
    assert status == 0
    scalars = json.loads(out)
    assert scalars["mu"] == pytest.approx(0.153, rel=0.005)
    status, out, _ = run(capsys, "loop-analysis", MEASURED, "--normal-force", "25 mN")
    assert "K_L at A" in out and "stroke" in out
