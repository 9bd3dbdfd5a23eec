"""The friction and friction-compare subcommands end to end, on small generated grids."""

from pathlib import Path

import pytest

from roughcontact.cli import EXIT_INPUT_ERROR, main
from roughcontact.topography.generate import self_affine, sphere_with_roughness
from roughcontact.topography.native import save_topography

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "paper000_measured_mu.csv"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
COMMON = ["--material", "polysilicon", "--counter", "SiO2", "--surface-energy", "50 mJ/m^2"]


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("friction")
    n = 32
    paths = {
        "scan": self_affine((n, n), n * 20e-9, hurst=0.8, rms_height=1.8e-9, seed=1),
        "scan2": self_affine((n, n), n * 20e-9, hurst=0.8, rms_height=1.8e-9, seed=3),
        "tip": sphere_with_roughness((n, n), n * 20e-9, radius=1e-6, rms_height=0.3e-9, seed=2),
        "coarse": sphere_with_roughness((16, 16), n * 20e-9, radius=1e-6, rms_height=0.3e-9, seed=2),
    }
    for name, topography in paths.items():
        save_topography(topography, folder / f"{name}.nc")
    return {name: folder / f"{name}.nc" for name in paths}


def test_friction_text_json_and_outputs(capsys, files, tmp_path, cases):
    status, out, err = run(capsys, "friction", files["scan"], files["tip"], *COMMON, "--load", "10 uN")
    assert status == 0, err
    assert "mu" in out and "adhesive_friction" in out and "readings" in out and "defaults" in out
    folder = tmp_path / "out"
    status, out, _ = run(
        capsys,
        "friction",
        files["scan"],
        files["tip"],
        *COMMON,
        "--json",
        "--reading",
        "contact=zero_gap",
        "--loads",
        "1 uN",
        "10 uN",
        "100 uN",
        "--crossover",
        "-o",
        folder,
    )
    assert status == 0
    found = cases(out)
    assert found[0]["parameters"]["readings"]["contact"] == "zero_gap"
    assert found[0]["scalars"]["readings"] == "contact=zero_gap"
    assert len(found) == 3 and found[0]["scalars"]["normal_force"] == pytest.approx(1e-6, rel=1e-12)
    assert all("crossover_load" in case["scalars"] for case in found)
    assert len(list((folder / "cases" / "friction").glob("*.nc"))) == 3
    assert (folder / "figures" / "friction_friction_vs_load.png").read_bytes()[:8] == PNG_MAGIC


def test_friction_paper_preset_changed_by_a_reading(capsys, files, cases):
    argv = ["friction", files["scan"], files["tip"], *COMMON, "--json", "--reading", "paper"]
    status, out, err = run(capsys, *argv, "--reading", "contact=zero_gap", "--tip-radius", "1 um")
    assert status == 0, err
    (case,) = cases(out)
    assert case["parameters"]["reading"] == "paper"
    assert case["parameters"]["readings"] == {"contact": "zero_gap"}
    changed = case["scalars"]["readings"]
    assert "base=half_sphere" in changed and "contact=zero_gap" in changed and "all_springs" in changed


def test_friction_hold_time_changes_mu(capsys, files, scalars):
    _, out, _ = run(capsys, "friction", files["scan"], files["tip"], *COMMON, "--json")
    fresh = scalars(out)["mu"]
    _, out, _ = run(
        capsys,
        "friction",
        files["scan"],
        files["tip"],
        *COMMON,
        "--json",
        "--relaxed-modulus",
        "60 GPa",
        "--relaxation-time",
        "1 s",
        "--hold-time",
        "100 s",
    )
    assert scalars(out)["mu"] != fresh


@pytest.mark.parametrize(
    "extra, option",
    [
        (["--surface-energy", "-5 mJ/m^2"], "--surface-energy"),
        (["--epsilon", "0 nm"], "--epsilon"),
        (["--load", "1 N"], "--normal-force"),
        (["--reading", "contact=glued"], "--reading"),
        (["--reading", "papers"], "--reading"),
        (["--reading", "paper", "--reading", "printed"], "--reading"),
        (["--reading", "paper", "--tip-radius", "-1 um"], "--tip-radius"),
    ],
)
def test_friction_bad_input_exits_naming_the_option(capsys, files, extra, option):
    status, _, err = run(capsys, "friction", files["scan"], files["tip"], *COMMON, *extra)
    assert status == EXIT_INPUT_ERROR
    assert f"error: {option}" in err, err


def test_friction_mismatched_grids_refused_then_resampled(capsys, files):
    status, _, err = run(capsys, "friction", files["scan"], files["coarse"], *COMMON)
    assert status == EXIT_INPUT_ERROR and "--resample" in err
    status, out, err = run(capsys, "friction", files["scan"], files["coarse"], *COMMON, "--resample")
    assert status == 0, err


def test_friction_compare_with_scans_and_synthetic(capsys, files, tmp_path, table):
    measured = tmp_path / "measured.csv"
    measured.write_text("# test values\nsample,mu\nA,3.0\nA,3.2\nB,3.1\nB,3.3\nC,2.9\nC,3.0\n")
    samples = [f"{name}={files['scan']},{files['scan2']}" for name in "ABC"]
    folder = tmp_path / "out"
    argv = ["friction-compare", measured, "--tip", files["tip"], "--json", "-o", folder]
    for sample in samples:
        argv += ["--sample", sample]
    status, out, err = run(capsys, *argv)
    assert status == 0, err
    assert [row["sample"] for row in table(out, "comparison")] == ["A", "B", "C"]
    assert (folder / "figures" / "friction_mu_boxes.png").read_bytes()[:8] == PNG_MAGIC


def test_friction_compare_paper000_synthetic_case_runs(capsys):
    status, out, err = run(capsys, "friction-compare", EXAMPLE, "--grid", "64")
    assert status == 0, err
    assert "pearson_r" in out and "Ra 1.7 nm" in out


def test_friction_compare_gives_the_example_csvs_stated_p_values(capsys, table):
    """One realisation set: the command's scans are paper000_simulation()'s, the CSV was built on them."""
    import numpy as np

    from roughcontact.papers.paper000 import paper000_simulation

    status, out, err = run(capsys, "friction-compare", EXAMPLE, "--json")
    assert status == 0, err
    rows = {row["sample"]: row for row in table(out, "comparison")}
    header = EXAMPLE.read_text()
    assert "0.13, 0.12, 0.79" in header
    for sample, p_value in {"Ra 1.45 nm": 0.13, "Ra 1.49 nm": 0.12, "Ra 1.7 nm": 0.79}.items():
        assert rows[sample]["p_value"] == pytest.approx(p_value, abs=1e-4)  # the CSV keeps 6 decimals of mu
    simulated = paper000_simulation()
    for sample, values in simulated.items():
        assert rows[sample]["simulated_mean"] == pytest.approx(float(np.mean(values)), rel=1e-12)
    (trend,) = table(out, "ra_trend")
    assert trend["n"] == 21 and trend["trend"] == "within the scatter"  # synthetic scans: mu flat in Ra
