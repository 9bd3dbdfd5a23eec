"""The friction and friction-compare subcommands end to end, on small generated grids."""

import json
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


def test_friction_text_json_and_outputs(capsys, files, tmp_path):
    status, out, err = run(capsys, "friction", files["scan"], files["tip"], *COMMON, "--load", "10 uN")
    assert status == 0, err
    assert "mu" in out and "adhesive_friction" in out and "readings: defaults" in out
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
        tmp_path,
    )
    assert status == 0
    document = json.loads(out)
    assert document["readings"]["contact"] == "zero_gap"
    assert len(document["sweep"]["mu"]) == 3 and document["scalars"]["load"] == pytest.approx(1e-6, rel=1e-12)
    assert "crossover_load" in document
    assert (tmp_path / "friction.nc").is_file() and (tmp_path / "friction_sweep.nc").is_file()
    assert (tmp_path / "friction_vs_load.png").read_bytes()[:8] == PNG_MAGIC


def test_friction_hold_time_changes_mu(capsys, files):
    _, out, _ = run(capsys, "friction", files["scan"], files["tip"], *COMMON, "--json")
    fresh = json.loads(out)["scalars"]["mu"]
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
    assert json.loads(out)["scalars"]["mu"] != fresh


@pytest.mark.parametrize(
    "extra, field",
    [
        (["--surface-energy", "-5 mJ/m^2"], "surface_energy"),
        (["--epsilon", "0 nm"], "epsilon"),
        (["--load", "1 N"], "load"),
        (["--reading", "contact=glued"], "readings.contact"),
    ],
)
def test_friction_bad_input_exits_with_the_field(capsys, files, extra, field):
    status, _, err = run(capsys, "friction", files["scan"], files["tip"], *COMMON, *extra)
    assert status == EXIT_INPUT_ERROR
    assert field in err


def test_friction_mismatched_grids_refused_then_resampled(capsys, files):
    status, _, err = run(capsys, "friction", files["scan"], files["coarse"], *COMMON)
    assert status == EXIT_INPUT_ERROR and "--resample" in err
    status, out, err = run(capsys, "friction", files["scan"], files["coarse"], *COMMON, "--resample")
    assert status == 0, err


def test_friction_compare_with_scans_and_synthetic(capsys, files, tmp_path):
    measured = tmp_path / "measured.csv"
    measured.write_text("# test values\nsample,mu\nA,3.0\nA,3.2\nB,3.1\nB,3.3\nC,2.9\nC,3.0\n")
    samples = [f"{name}={files['scan']},{files['scan2']}" for name in "ABC"]
    argv = ["friction-compare", measured, "--tip", files["tip"], "--json", "-o", tmp_path]
    for sample in samples:
        argv += ["--sample", sample]
    status, out, err = run(capsys, *argv)
    assert status == 0, err
    document = json.loads(out)
    assert [row["sample"] for row in document["samples"]] == ["A", "B", "C"]
    assert (tmp_path / "mu_boxes.png").read_bytes()[:8] == PNG_MAGIC


def test_friction_compare_paper000_synthetic_case_runs(capsys):
    status, out, err = run(capsys, "friction-compare", EXAMPLE)
    assert status == 0, err
    assert "Pearson r" in out and "Ra 1.7 nm" in out
