"""roughcontact asperity: paper 002's table, moments with units, curves and figures, clear errors."""

import json

import numpy as np
import pytest
import xarray as xr

from roughcontact.cli import EXIT_INPUT_ERROR, main


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_paper002_json_reproduces_section_iv(capsys, scalars, table):
    status, out, _ = run(capsys, "asperity", "--paper002", "--json", "--steps", "10")
    assert status == 0
    parameters = scalars(out)
    assert parameters["summit_radius"] == pytest.approx(5.08e-6, rel=5e-3, abs=0)
    assert parameters["critical_interference"] == pytest.approx(0.0125e-6, rel=5e-3, abs=0)
    assert parameters["plasticity_index"] == pytest.approx(1.86, rel=5e-3, abs=0)
    rows = {row["quantity"]: row for row in table(out, "paper002")}
    assert rows["contact_modulus"]["printed_inputs_eq7_printed"] == pytest.approx(9.717e9, rel=1e-3, abs=0)
    # the statistical curve ran at the paper's 1000 uN peak, zero at 25 uN
    assert parameters["peak_force"] == pytest.approx(1e-3, rel=1e-9)
    # unloading ends back at 25 uN: KKE's interference there (not a residual at zero load)
    assert parameters["peak_interference"] > parameters["interference_at_return_force"] > 0
    assert (
        parameters["return_force"] == pytest.approx(25e-6, rel=1e-12)
        and "residual_interference" not in parameters
    )


def test_text_table_names_paper_and_both_readings(capsys):
    status, out, _ = run(capsys, "asperity", "--paper002", "--steps", "5")
    assert status == 0
    assert "table paper002" in out
    assert "8.31 GPa" in out and "7.973 GPa" in out and "9.717 GPa" in out


def test_moments_with_units_equal_the_paper_run(capsys, scalars):
    moments = ["0.00213279 um^2", "0.00230023", "0.0171036 1/um^2"]
    status, out, _ = run(
        capsys,
        "asperity",
        "--moments",
        *moments,
        "--material",
        "SU-8",
        "--counter-body",
        "diamond flat tip",
        "--json",
    )
    assert status == 0
    parameters = scalars(out)
    assert parameters["m4"] == pytest.approx(0.0171036e12, rel=1e-12, abs=0)
    assert parameters["summit_height_std"] == pytest.approx(0.0431e-6, rel=5e-3, abs=0)
    assert "peak_interference" not in parameters  # no --max-force: parameters only


def test_output_folder_gets_curves_and_figures(capsys, tmp_path):
    out = tmp_path / "out"
    status, _, err = run(
        capsys, "asperity", "--paper002", "--bem", "--grid", "24", "--steps", "6", "-o", out, "--dpi", "40"
    )
    assert status == 0, err
    for name in (
        "asperity_load_interference",
        "asperity_contact_area",
        "bem_load_interference",
        "bem_von_mises",
    ):
        assert (out / "figures" / f"{name}.png").stat().st_size > 0
    (curve,) = (out / "cases" / "asperity").glob("*.nc")
    with xr.open_dataset(curve) as data:
        force = np.asarray(data["force"])
        assert force.size == 11  # 6 loading + 5 unloading
        assert force[0] == pytest.approx(25e-6, rel=1e-8, abs=0)
        assert force[5] == pytest.approx(1e-3, rel=1e-8, abs=0)
    assert (out / "cases" / "bem").is_dir() and (out / "report.html").is_file()


def test_measured_curve_csv_is_drawn(capsys, tmp_path):
    measured = tmp_path / "measured.csv"
    measured.write_text("interference_m,force_N\n0,25e-6\n2e-8,3e-4\n5e-8,1e-3\n")
    out = tmp_path / "out"
    status, _, err = run(capsys, "asperity", "--paper002", "--steps", "4", "--measured", measured, "-o", out)
    assert status == 0, err
    assert (out / "figures" / "asperity_load_interference.png").exists()


def test_bad_input_gives_one_clear_line(capsys):
    # bandwidth alpha = 0.5 < 0.8968
    status, _, err = run(
        capsys, "asperity", "--moments", "1e-16 m^2", "1e-2", "0.5e12 1/m^2", "--material", "SU-8"
    )
    assert status == EXIT_INPUT_ERROR
    assert "m2" in err and "0.8968" in err
    status, _, err = run(capsys, "asperity", "--material", "SU-8")
    assert status == EXIT_INPUT_ERROR and "FILE" in err
    status, _, err = run(capsys, "asperity", "--paper002", "--distribution", "measured")
    assert status == EXIT_INPUT_ERROR and "--distribution" in err
    status, _, err = run(capsys, "asperity", "--paper002", "--max-force", "10 N")
    assert status == EXIT_INPUT_ERROR and "110" in err
    status, _, err = run(
        capsys,
        "asperity",
        "--paper002",
        "--material-youngs-modulus",
        "7 GPa",
        "--material-poissons-ratio",
        "0.6",
    )
    assert status == EXIT_INPUT_ERROR and "--material-poissons-ratio" in err
    status, _, err = run(
        capsys, "asperity", "--moments", "1 um", "0.002", "0.017 1/um^2", "--material", "SU-8"
    )
    assert status == EXIT_INPUT_ERROR and "--moments m0" in err


def test_file_with_measured_summit_heights(capsys, shared_topographies, scalars):
    argv = [
        "asperity",
        shared_topographies / "top-1.top",
        "--material",
        "SU-8",
        "--json",
        "--max-force",
        "10 uN",
    ]
    status, out, err = run(
        capsys,
        *argv,
        "--area",
        "10 um x 10 um",
        "--distribution",
        "measured",
        "--reference-force",
        "0.1 uN",
        "--steps",
        "5",
    )
    assert status == 0, err
    parameters = scalars(out)
    assert parameters["summit_radius"] > 0
    assert parameters["peak_interference"] > 0
    assert json.loads(out)["analyses"][0]["cases"][0]["parameters"]["nominal_area"] == pytest.approx(1e-10)


def test_bem_with_volume_plasticity_draws_the_section(capsys, tmp_path):
    out = tmp_path / "out"
    status, _, err = run(
        capsys, "asperity", "--paper002", "--bem", "--plasticity", "volume", "--layers", "6",
        "--grid", "24", "--steps", "4", "-o", out, "--dpi", "40",
    )  # fmt: skip
    assert status == 0, err
    for name in ("bem_load_interference", "bem_von_mises", "bem_von_mises_section"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 0


def test_volume_options_need_volume_plasticity(capsys):
    status, _, err = run(capsys, "asperity", "--paper002", "--bem", "--grid", "24", "--layers", "6")
    assert status == EXIT_INPUT_ERROR and "--layers" in err and "--plasticity volume" in err


def test_realisations_draw_paper002s_island_only(capsys):
    status, _, err = run(capsys, "asperity", "--paper002", "--realisations", "3")
    assert status == EXIT_INPUT_ERROR
    assert "--realisations" in err and "add --bem --paper002" in err
