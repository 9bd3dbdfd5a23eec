"""roughcontact presliding and loop-analysis: outputs, JSON, units and clear errors (small grids)."""

from pathlib import Path

import numpy as np
import pytest

from roughcontact.cli import EXIT_INPUT_ERROR, main
from roughcontact.materials import get_material
from roughcontact.papers import paper001
from roughcontact.spread import realisation_seed
from roughcontact.study.store import read_table
from roughcontact.topography import generate
from roughcontact.topography.native import save_topography

MEASURED = Path(__file__).parents[2] / "examples" / "paper001_measured_loop.csv"
BALL_OPTIONS = (
    "--material",
    "POM",
    "--counter-body",
    "silicon wafer",
    "--normal-force",
    "5 mN",
    "--mu",
    "0.1",
)


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


def test_presliding_on_a_file_writes_loops_table_and_figures(capsys, tmp_path, ball_file, scalars):
    out = tmp_path / "out"
    status, stdout, err = run(
        capsys,
        "presliding",
        ball_file,
        *BALL_OPTIONS,
        "--stroke",
        "0.4 um",
        "--cycles",
        "2",
        "--steps-per-stroke",
        "10",
        "--measured",
        MEASURED,
        "-o",
        out,
        "--json",
    )
    assert status == 0, err
    row = scalars(stdout)
    assert row["friction_coefficient"] == 0.1 and row["normal_force"] == pytest.approx(5e-3)
    assert row["mu_from_loop"] == pytest.approx(0.1, rel=1e-3)  # the loop slides at mu F0
    assert 0 < row["K_L_C"] < row["K_L_B"] < row["K_L_A"]
    assert row["K_L_A_mindlin_printed"] == pytest.approx(4 * row["K_L_A_mindlin_johnson"])
    for name in ("loops", "stick_slip", "lateral_stiffness"):
        assert (out / "figures" / f"presliding_{name}.png").stat().st_size > 0
    assert (out / "tables" / "presliding_measured_loop.csv").stat().st_size > 0


def test_presliding_errors_name_the_option(capsys, tmp_path, ball_file):
    status, _, err = run(
        capsys, "presliding", ball_file, "--material", "POM", "--normal-force", "5 mN", "--stroke", "1 um"
    )
    assert status == EXIT_INPUT_ERROR and "--friction-coefficient" in err
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


def test_loop_analysis_of_the_measured_example(capsys, tmp_path, scalars):
    status, out, _ = run(capsys, "loop-analysis", MEASURED, "--normal-force", "25 mN", "--json")
    assert status == 0
    assert scalars(out)["mu"] == pytest.approx(0.153, rel=0.005)
    status, out, _ = run(capsys, "loop-analysis", MEASURED, "--normal-force", "25 mN", "-o", tmp_path / "out")
    assert "K_L_A" in out and "stroke" in out and "mN/µm" in out  # K_L in the figures' unit (issue 35)
    assert (tmp_path / "out" / "figures" / "loop_loop.png").stat().st_size > 0


def _steps(folder):
    """The per-step series of the one case of a command's output folder (from the unloaded start)."""
    import xarray as xr

    (stored,) = (folder / "cases" / "presliding").glob("*.nc")
    return xr.load_dataset(stored)


def test_a_path_file_reproduces_the_stroke_programme(capsys, tmp_path, ball_file, scalars):
    """The same steps written in a CSV (in um) give the --stroke run's forces, to round-off."""
    from roughcontact.contact.paths import stroke_path

    steps = stroke_path(0.4e-6, cycles=2, steps_per_stroke=10, spacing="quadratic")
    path = tmp_path / "path.csv"
    path.write_text("x [um]\n" + "\n".join(repr(float(1e6 * d)) for d in steps) + "\n")
    common = (ball_file, *BALL_OPTIONS)
    stroke = ("--stroke", "0.4 um", "--cycles", "2", "--steps-per-stroke", "10")
    status, _, err = run(capsys, "presliding", *common, *stroke, "-o", tmp_path / "stroke")
    assert status == 0, err
    status, out, err = run(capsys, "presliding", *common, "--path", path, "-o", tmp_path / "path", "--json")
    assert status == 0, err
    row = scalars(out)
    assert row["control"] == "displacement" and row["steps"] == len(steps) + row["inserted_steps"]
    expected, found = _steps(tmp_path / "stroke"), _steps(tmp_path / "path")
    for column in ("delta_x", "force_x", "stick_area"):
        np.testing.assert_allclose(found[column], expected[column], rtol=1e-9, atol=1e-18)
    assert row["mu_from_loop"] == pytest.approx(0.1, rel=1e-3)
    assert row["loops"] == 1 and row["energy_last_loop"] > 0
    for name in ("loops", "stick_slip"):
        assert (tmp_path / "path" / "figures" / f"presliding_{name}.png").stat().st_size > 0


def test_a_force_path_file_runs_under_force_control(capsys, tmp_path, ball_file, scalars):
    """Q_x in mN (+-0.5 mu F0 cycles): the applied forces are met; the loop dissipates energy."""
    amplitude = 0.5 * 0.1 * 5.0  # mN
    up = np.linspace(0, amplitude, 6)[1:]
    down = np.linspace(amplitude, -amplitude, 11)[1:]
    steps = np.concatenate([up, down, down[::-1][1:], [amplitude]])
    path = tmp_path / "force.csv"
    path.write_text("Q_x [mN],Q_y [mN]\n" + "\n".join(f"{float(q)!r},0" for q in steps) + "\n")
    out = tmp_path / "out"
    status, stdout, err = run(
        capsys, "presliding", ball_file, *BALL_OPTIONS, "--path", path, "-o", out, "--json"
    )
    assert status == 0, err
    row = scalars(stdout)
    assert row["control"] == "force"
    stored = _steps(out)
    forces = stored["force_x"].values[1:]  # step 0 is the unloaded start
    point = stored["programme_point"].values[1:]  # the step control may insert steps between rows
    at_rows = np.append(point[1:] != point[:-1], True)
    assert row["steps"] == len(steps) + row["inserted_steps"] and at_rows.sum() == len(steps)
    np.testing.assert_allclose(forces[at_rows], 1e-3 * steps, rtol=1e-9, atol=1e-15)
    assert row["last_stick_fraction"] > 0  # below mu F0 part of the contact sticks
    assert row["mu_from_loop"] is None and row["K_L_A"] is None  # no sliding plateau to analyse (NaN)
    energies = _steps(out)["loop_energy"].values
    assert row["loops"] == energies.size == 1 and energies[0] > 0 and row["energy_last_loop"] == energies[0]


def test_a_loop_too_coarse_for_the_eq9_fit_keeps_its_results_and_says_why(
    capsys, tmp_path, ball_file, scalars
):
    """Two steps per stroke slide at once: no pre-sliding samples to fit, yet the run and its loop stand.

    The step control (on by default) fills the pre-sliding parts, and the same programme is analysed.
    """
    path = tmp_path / "coarse.csv"
    path.write_text("x [um]\n0.4\n0\n-0.4\n0\n0.4\n0\n-0.4\n0\n0.4\n")
    out = tmp_path / "out"
    common = ("presliding", ball_file, *BALL_OPTIONS, "--path", path, "--json")
    status, stdout, err = run(capsys, *common, "--max-stick-change", "none", "-o", out)
    assert status == 0, err
    row = scalars(stdout)
    assert row["analysis_note"].startswith("last loop not analysed") and row["K_L_A"] is None
    assert row["inserted_steps"] == 0
    energies = _steps(out)["loop_energy"].values
    assert row["loops"] == energies.size == 2 and energies.min() > 0
    status, stdout, err = run(capsys, *common, "-o", tmp_path / "refined")
    assert status == 0, err
    row = scalars(stdout)
    assert row["analysis_note"] == "" and row["K_L_A"] > row["K_L_B"] > row["K_L_C"] > 0
    assert row["inserted_steps"] >= 4 * 10  # ten or more after each of the four reversals


def test_path_and_stroke_together_are_refused(capsys, tmp_path, ball_file):
    path = tmp_path / "path.csv"
    path.write_text("x [um]\n0.1\n")
    status, _, err = run(capsys, "presliding", ball_file, *BALL_OPTIONS, "--stroke", "1 um", "--path", path)
    assert status == EXIT_INPUT_ERROR and "--path" in err
    path.write_text("x\n0.1\n")
    status, _, err = run(capsys, "presliding", ball_file, *BALL_OPTIONS, "--path", path)
    assert status == EXIT_INPUT_ERROR and "has no unit" in err


def test_a_path_with_a_normal_column_runs_a_combined_programme(capsys, tmp_path, ball_file, scalars):
    """Oblique loading then normal-load cycling at a held displacement (issue 20), from the unloaded state."""
    rows = [(0.0, 5 * (k / 5) ** 3) for k in range(1, 6)]
    rows += [(0.05 * k, 5 + k) for k in range(1, 6)] + [(0.25, 6.0), (0.25, 10.0)]
    path = tmp_path / "combined.csv"
    path.write_text("x [um],F_n [mN]\n" + "\n".join(f"{x!r},{f!r}" for x, f in rows) + "\n")
    options = [o for o in BALL_OPTIONS]
    at = options.index("--normal-force")
    del options[at : at + 2]
    out = tmp_path / "out"
    status, stdout, err = run(capsys, "presliding", ball_file, *options, "--path", path, "-o", out, "--json")
    assert status == 0, err
    row = scalars(stdout)
    assert row["normal_loading"] == "frictional" and row["normal_force"] == pytest.approx(10e-3)
    stored = _steps(out)
    point = stored["programme_point"].values[1:]
    at_rows = np.append(point[1:] != point[:-1], True)
    np.testing.assert_allclose(
        stored["normal_force"].values[1:][at_rows], 1e-3 * np.array(rows)[:, 1], rtol=1e-8
    )
    # F_n falls at a held displacement: the contact slides back to (nearly) mu F_n; reloading holds it
    # (to the coupling of beta = -0.004)
    force = stored["force_x"].values[1:][at_rows]
    mu = float(row["friction_coefficient"])
    assert force[-2] == pytest.approx(mu * 6e-3, rel=1e-3) and force[-1] == pytest.approx(force[-2], rel=1e-3)
    assert "sliding" not in err
    assert (out / "figures" / "presliding_path.png").stat().st_size > 10_000


def test_a_normal_column_and_a_normal_force_are_refused_together(capsys, tmp_path, ball_file):
    path = tmp_path / "combined.csv"
    path.write_text("x [um],F_n [mN]\n0,5\n")
    status, _, err = run(capsys, "presliding", ball_file, *BALL_OPTIONS, "--path", path)
    assert status == EXIT_INPUT_ERROR
    assert "normal column" in err and "normal_force" in err.replace("--normal-force", "normal_force")


def test_the_frictional_loading_is_chosen_and_sized_from_the_command_line(
    capsys, tmp_path, ball_file, scalars
):
    """POM on silicon is coupled (beta = -0.004): F0 is applied with friction unless asked otherwise."""
    common = ("presliding", ball_file, *BALL_OPTIONS, "--stroke", "0.2 um", "--cycles", "1", "--json")
    status, stdout, err = run(capsys, *common, "--loading-steps", "4", "-o", tmp_path / "a")
    assert status == 0, err
    row = scalars(stdout)
    assert row["normal_loading"] == "frictional" and row["loading_steps"] == 4
    assert 0.9 < row["locked_in_stick_fraction"] <= 1 and row["locked_in_shear_rms"] > 0
    status, stdout, err = run(capsys, *common, "--normal-loading", "frictionless", "-o", tmp_path / "b")
    assert status == 0, err
    row = scalars(stdout)
    assert row["normal_loading"] == "frictionless" and row["loading_steps"] == 0
    assert row["locked_in_stick_fraction"] is None  # NaN: no frictional loading


def test_paper001_on_realisations_of_the_ball(capsys, tmp_path):
    """--realisations N draws N balls per load (seeds from --seed) and tables K_L's spread against Mindlin."""
    status, stdout, err = run(
        capsys,
        "presliding",
        "--paper001",
        "--ball",
        "POM",
        "--normal-forces",
        "25 mN",
        "--pixels",
        "128",
        "--window",
        "40",
        "--steps-per-stroke",
        "6",
        "--cycles",
        "2",
        "--realisations",
        "3",
        "-o",
        tmp_path / "out",
    )
    assert status == 0, err
    assert "spread over 3 realisations" in stdout and "Each setting ran on 3 realisations" in stdout
    spread = read_table(tmp_path / "out" / "tables" / "presliding_lateral_stiffness_spread.csv")
    assert len(spread) == 3 and all(row["n"] == "3" for row in spread)  # points A, B, C at 25 mN
    assert {row["rough vs smooth, one ball (johnson)"] for row in spread} <= VERDICTS
    assert any("prediction interval" in note for note in spread.notes)
    assert (tmp_path / "out" / "figures" / "presliding_lateral_stiffness.png").exists()


VERDICTS = {"below", "above", "not established"}
"""One ball's verdict against Mindlin where the balls give an interval."""


def test_the_readme_paper001_command_runs_to_a_report(capsys, tmp_path):
    """README: ``roughcontact presliding --paper001 --realisations 5 -o out/``, at a reduced size.

    Both balls at Table 1's three loads on three stand-in balls each (128 px, two cycles of six
    steps): every case runs (the window each solves is chosen to hold its contact and stated), and
    the report judges one ball against Mindlin in both readings of eq. 12.
    """
    out = tmp_path / "out"
    status, stdout, err = run(
        capsys,
        "presliding",
        "--paper001",
        "--realisations",
        "3",
        "--pixels",
        "128",
        "--cycles",
        "2",
        "--steps-per-stroke",
        "6",
        "-o",
        out,
    )
    assert status == 0, err
    assert 'window = "auto"' in (out / "study.toml").read_text()
    rows = read_table(out / "results.csv")
    assert len(rows) == 18 and {row["status"] for row in rows} == {"done"}
    for row in rows:  # the window of each case is stated: its pixels and how it was chosen
        assert row["window_choice"].startswith(f"auto: {row['window_pixels']} px (")
        assert 3 <= int(row["window_pixels"]) <= 128
    assert "Solved windows, chosen per case (--window auto): HDPE " in stdout
    spread = read_table(out / "tables" / "presliding_lateral_stiffness_spread.csv")
    assert len(spread) == 18
    for row in spread:
        johnson = row["rough vs smooth, one ball (johnson)"]
        printed = row["rough vs smooth, one ball (printed)"]
        assert johnson in VERDICTS and printed.split(" (")[0] in VERDICTS
        # the printed reading's K_L is 4x Johnson's: where the verdicts differ, the cell says why
        if not printed.startswith(johnson):
            assert printed.endswith(
                f"(decided by eq. 12's printed factor 4: with Johnson's Mindlin {johnson})"
            )
        low, high = (float(row[f"K_L / mindlin_johnson one ball 95% {end}"]) for end in ("low", "high"))
        assert (johnson == "not established") == (low <= 1 <= high)
    report = (out / "report.html").read_text()
    assert "rough vs smooth, one ball" in report and "stand-in balls" in report


def test_the_help_calls_paper001s_realisations_stand_in_balls(capsys):
    with pytest.raises(SystemExit):
        main(["presliding", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "stand-in balls generated with Table 2's roughness" in text
    assert "not the five spots on the wafer" in text and "measured five spots" not in text
    assert "'# origin:' header line" in text  # --measured: the loop is called what its file says


def test_a_case_that_fails_names_its_sample_replicate_and_seed(capsys, tmp_path):
    """A stand-in ball whose contact reaches the border of a given window: the error names which."""
    status, _, err = run(
        capsys,
        "presliding",
        "--paper001",
        "--ball",
        "HDPE",
        "--normal-forces",
        "25 mN",
        "--pixels",
        "128",
        "--window",
        "8",
        "--realisations",
        "2",
        "--cycles",
        "1",
        "--steps-per-stroke",
        "4",
        "-o",
        tmp_path / "out",
    )
    assert status == EXIT_INPUT_ERROR
    seed = realisation_seed(1, "hdpe", "HDPE", 0)
    assert f"--window: HDPE at 25 mN (sample HDPE, replicate 0, seed {seed} of topography 'hdpe'): " in err
    assert "reaches the border of the solved window (8 x 8 px)" in err and "--window auto" in err


def test_realisations_of_a_measured_ball_are_refused(capsys, ball_file):
    status, _, err = run(
        capsys, "presliding", ball_file, *BALL_OPTIONS, "--stroke", "1 um", "--realisations", "3"
    )
    assert status == EXIT_INPUT_ERROR
    assert "--realisations" in err and "realisations need a generated surface" in err
