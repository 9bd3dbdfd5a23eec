"""The command line end to end, on real instrument files and small grids."""

import json
import subprocess
import sys

import pytest

from roughcontact.cli import EXIT_INPUT_ERROR, main

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_inspect_lists_channels_units_and_statistics(capsys, shared_topographies):
    status, out, err = run(capsys, "inspect", shared_topographies / "di-3.di")
    assert status == 0, err
    assert "ZSensor" in out and "*" in out  # default channel marked
    assert "256 x 256 points" in out
    assert "10 µm x 10 µm" in out
    assert "Sq" in out and "Rq" in out and "summit_radius" in out


def test_inspect_json_is_si(capsys, shared_topographies):
    status, out, _ = run(capsys, "inspect", shared_topographies / "top-1.top", "--json", "--detrend", "none")
    assert status == 0
    doc = json.loads(out)
    assert doc["grid"] == [256, 256]
    assert doc["size_m"] == pytest.approx([600e-9, 600e-9], rel=1e-9, abs=0)
    # README: rms 3.15 nm as stored (SurfaceTopography's figure, tilt included; levelled it is
    # 1.61 nm, tests/cli/test_levelling.py); 1e-2 relative covers the README's 3-digit rounding.
    assert doc["statistics"]["Sq"] == pytest.approx(3.15e-9, rel=1e-2, abs=0)
    # issue 35: every statistic has its SI unit beside it ("" for a dimensionless one)
    units = doc["statistics_units"]
    assert set(units) == set(doc["statistics"])
    assert (units["Sq"], units["m0"], units["m4"], units["rms_curvature"], units["Ssk"]) == (
        "m",
        "m^2",
        "1/m^2",
        "1/m",
        "",
    )


def test_inspect_selects_channel_by_name_and_index(capsys, shared_topographies):
    path = shared_topographies / "di-3.di"
    status, out, err = run(capsys, "inspect", path, "--json", "--channel", "3")
    assert status == 0, err
    by_index = json.loads(out)
    name = next(c["name"] for c in by_index["channels"] if c["index"] == 3)
    assert name == "Height"
    status, out, err = run(capsys, "inspect", path, "--json", "--channel", name)
    assert status == 0, err
    by_name = json.loads(out)
    assert by_name["statistics"] == by_index["statistics"]
    status, out, _ = run(capsys, "inspect", path, "--json")
    default = json.loads(out)
    assert default["statistics"]["Sq"] != by_index["statistics"]["Sq"]  # ZSensor is another channel


def test_non_height_channel_is_refused(capsys, shared_topographies):
    status, _, err = run(capsys, "inspect", shared_topographies / "di-3.di", "--channel", "Phase")
    assert status == EXIT_INPUT_ERROR
    assert "Phase" in err


def test_missing_size_says_how_to_pass_it(capsys, shared_topographies):
    status, _, err = run(capsys, "inspect", shared_topographies / "afm-slippy.txt")
    assert status == EXIT_INPUT_ERROR
    assert "--size" in err
    assert "afm-slippy.txt" in err
    status, out, err = run(
        capsys,
        "inspect",
        shared_topographies / "afm-slippy.txt",
        "--size",
        "5 um",
        "--height-unit",
        "nm",
        "--json",
    )
    assert status == 0, err
    assert json.loads(out)["size_m"] == pytest.approx([5e-6, 5e-6], rel=1e-12, abs=0)


def test_undefined_points_need_an_explicit_choice(capsys, shared_topographies):
    """inspect describes the file anyway (tests/cli/test_undefined_points.py); a solve refuses it."""
    status, _, err = run(
        capsys, "contact", shared_topographies / "sur-2.sur", "--material", "SU-8", "--pressure", "1 MPa"
    )
    assert status == EXIT_INPUT_ERROR
    assert "undefined" in err and "--fill-undefined" in err
    status, out, err = run(capsys, "inspect", shared_topographies / "sur-2.sur", "--fill-undefined", "--json")
    assert status == 0, err
    assert json.loads(out)["undefined_points_filled"] > 0


@pytest.mark.parametrize(
    "name", ["di_corrupted.di", "nonsense_txt_file.txt", "wrongnpyfile.npy", "no-such-file.di"]
)
def test_broken_files_give_one_clear_line(capsys, shared_topographies, name):
    status, out, err = run(capsys, "inspect", shared_topographies / name)
    assert status == EXIT_INPUT_ERROR
    assert name in err
    assert "Traceback" not in err
    assert len(err.strip().splitlines()) <= 3


def test_plot_writes_a_png(capsys, shared_topographies, tmp_path):
    target = tmp_path / "figs" / "top.png"
    status, out, err = run(capsys, "plot", shared_topographies / "top-1.top", "-o", target)
    assert status == 0, err
    assert target.read_bytes().startswith(PNG_MAGIC)


def test_plot_a_line_scan(capsys, shared_topographies, tmp_path):
    target = tmp_path / "profile.png"
    status, _, err = run(capsys, "plot", shared_topographies / "opdx-3.opdx", "-o", target)
    assert status == 0, err
    assert target.read_bytes().startswith(PNG_MAGIC)


def test_bad_size_argument_is_refused(capsys, shared_topographies):
    status, _, err = run(
        capsys, "inspect", shared_topographies / "afm-slippy.txt", "--size", "5 GPa", "--height-unit", "nm"
    )
    assert status == EXIT_INPUT_ERROR
    assert "expected a length" in err


def test_demo_runs_the_embedded_study_and_writes_its_report(capsys, tmp_path):
    import csv

    status, out, err = run(capsys, "demo", "-o", tmp_path)
    assert status == 0, err
    assert "demo study 'roughcontact demo'" in out and "0 failed" in out
    with (tmp_path / "results.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    analyses = {row["analysis"] for row in rows}
    assert {"afm_scan", "contact"} <= analyses
    assert all(row["status"] == "done" for row in rows)
    contact = [row for row in rows if row["analysis"] == "contact"]
    fractions = [float(row["contact_fraction"]) for row in contact]
    assert len(contact) == 5 and fractions == sorted(fractions)  # the area grows with the load
    afm = next(row for row in rows if row["analysis"] == "afm_scan")
    assert float(afm["size_x [m]"]) == pytest.approx(600e-9)  # the scan's size, from its file
    friction = [row for row in rows if row["analysis"] == "paper000_friction"]
    samples = ["Ra 1.45 nm", "Ra 1.49 nm", "Ra 1.7 nm"]  # five realisations of each: mu with its spread
    assert [row["sample"] for row in friction] == samples * 5
    assert sorted({row["replicate"] for row in friction}) == ["0", "1", "2", "3", "4"]
    assert (tmp_path / "tables" / "paper000_friction_spread.csv").exists()
    assert all(0 < float(row["mu"]) < 5 for row in friction)
    with (tmp_path / "tables" / "paper002_kke_paper002.csv").open() as handle:
        paper002 = {row["quantity"]: row for row in csv.DictReader(handle)}
    for quantity in ("summit_radius", "summit_height_std", "critical_interference", "plasticity_index"):
        assert abs(float(paper002[quantity]["relative_deviation"])) < 5e-3  # paper 002's printed values
    (loop,) = [row for row in rows if row["analysis"] == "paper001_presliding"]
    assert float(loop["mu_from_loop"]) == pytest.approx(0.1, rel=1e-3)  # the sliding plateau is mu F0
    assert 0 < float(loop["K_L_C [N/m]"]) < float(loop["K_L_B [N/m]"]) < float(loop["K_L_A [N/m]"])
    for name in ("contact_contact", "contact_von_mises", "contact_area_load", "afm_scan_psd"):
        assert (tmp_path / "figures" / f"{name}.png").read_bytes().startswith(PNG_MAGIC)
    report = (tmp_path / "report.html").read_text()
    assert "roughcontact demo" in report and report.count("data:image/png;base64,") >= 4
    status, out, _ = run(capsys, "demo", "-o", tmp_path)  # a second run reuses every case
    assert status == 0 and "0 cases run" in out
    assert f"sample AFM scan for your first commands: {tmp_path / 'top-1.top'}" in out
    status, out, err = run(capsys, "validate", tmp_path / "study.toml")  # reruns from its own folder
    assert status == 0, err
    status, out, err = run(capsys, "inspect", tmp_path / "top-1.top")
    assert status == 0 and "600 nm x 600 nm" in out


def test_console_script_runs_as_module():
    done = subprocess.run(
        [sys.executable, "-m", "roughcontact", "--version"], capture_output=True, text=True, check=False
    )
    assert done.returncode == 0
    assert done.stdout.startswith("roughcontact ")


def test_contact_solves_a_real_scan_and_writes_results(capsys, shared_topographies, tmp_path, scalars):
    import xarray as xr

    out = tmp_path / "out"
    status, stdout, err = run(
        capsys,
        "contact",
        shared_topographies / "top-1.top",
        "--material",
        "polysilicon",
        "--counter-body",
        "SiO2",
        "--pressure",
        "50 MPa",
        "-o",
        out,
        "--json",
    )
    assert status == 0, err
    values = scalars(stdout)
    assert values["mean_pressure"] == pytest.approx(50e6, rel=1e-12, abs=0)
    assert 0 < values["contact_fraction"] < 1
    assert values["residual"] <= 1e-8
    assert (out / "figures" / "contact_contact.png").read_bytes().startswith(PNG_MAGIC)
    assert (out / "report.html").is_file() and (out / "results.csv").is_file()
    (stored,) = (out / "cases" / "contact").glob("*.nc")
    with xr.open_dataset(stored) as data:
        assert data["pressure"].attrs["units"] == "Pa"
        assert float(data["pressure"].mean()) == pytest.approx(50e6, rel=1e-12, abs=0)
    # the command's study, written beside its results, reruns as a study file
    status, stdout, err = run(capsys, "validate", out / "study.toml")
    assert status == 0, err


def test_contact_with_user_material_and_bad_inputs(capsys, shared_topographies):
    path = shared_topographies / "top-1.top"
    status, out, err = run(
        capsys, "contact", path, "--material-youngs-modulus", "70 GPa", "--material-poissons-ratio", "0.17",
        "--force", "10 uN",
    )  # fmt: skip
    assert status == 0, err
    assert "force" in out and "10 µN" in out
    status, _, err = run(capsys, "contact", path, "--pressure", "1 MPa")
    assert status == EXIT_INPUT_ERROR and "--material" in err
    status, _, err = run(
        capsys, "contact", path, "--material", "SU-8", "--pressure", "1 MPa", "--force", "1 N"
    )
    assert status == EXIT_INPUT_ERROR and "exactly one" in err
    status, _, err = run(capsys, "contact", path, "--material", "SU-8", "--pressure", "1 nm")
    assert status == EXIT_INPUT_ERROR and "--pressure" in err
    status, _, err = run(
        capsys, "contact", path, "--material-youngs-modulus", "70 GPa", "--pressure", "1 MPa"
    )
    assert status == EXIT_INPUT_ERROR and "poissons-ratio" in err


def test_models_lists_each_key_description_whole():
    from roughcontact.cli.study import _attribute_notes, describe_kind
    from roughcontact.study.kinds import get_kind, kind_names

    for name in kind_names():
        kind = get_kind(name)
        for key, note in _attribute_notes(kind.parameters).items():
            assert note.rstrip().endswith((".", ")", ":")), f"{name}.{key}: {note!r} reads cut"
        assert all(len(line) <= 160 for line in describe_kind(kind)[2:]), name
