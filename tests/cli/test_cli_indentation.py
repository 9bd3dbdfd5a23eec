"""roughcontact nanoindent: table, JSON, units, rate sign, plot and clear errors."""

import json
from pathlib import Path

import pytest

from roughcontact.cli import EXIT_INPUT_ERROR, main

EXAMPLE = Path(__file__).parents[2] / "examples" / "paper001_indentation_hdpe.csv"


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_json_reads_the_example_back(capsys):
    status, out, _ = run(capsys, "nanoindent", EXAMPLE, "--json")
    assert status == 0
    document = json.loads(out)
    assert document["youngs_modulus"] == pytest.approx(0.98e9, rel=0.02)
    assert document["rate_sign"] == "magnitude" and document["indenter"] == "diamond Berkovich"
    assert document["uncorrected_youngs_modulus"] > document["youngs_modulus"]


def test_table_and_plot(capsys, tmp_path):
    status, out, _ = run(capsys, "nanoindent", EXAMPLE, "--plot", tmp_path / "ni.png")
    assert status == 0
    assert "E sample (eq. 8)" in out and "S_e (eq. 5)" in out and "MPa" in out
    assert (tmp_path / "ni.png").stat().st_size > 0


def test_printed_rate_sign_raises_the_modulus(capsys):
    _, out, _ = run(capsys, "nanoindent", EXAMPLE, "--json")
    _, printed, _ = run(capsys, "nanoindent", EXAMPLE, "--json", "--rate-sign", "printed")
    assert json.loads(printed)["youngs_modulus"] > json.loads(out)["uncorrected_youngs_modulus"]


def test_unit_options_override_the_header(capsys, tmp_path):
    lines = EXAMPLE.read_text().splitlines()
    header = next(i for i, line in enumerate(lines) if not line.startswith("#"))
    lines[header] = "t,h,P"
    bare = tmp_path / "bare.csv"
    bare.write_text("\n".join(lines) + "\n")
    status, _, err = run(capsys, "nanoindent", bare, "--json")
    assert status == EXIT_INPUT_ERROR and "depth_unit" in err and "--depth-unit" in err
    status, out, _ = run(
        capsys, "nanoindent", bare, "--json", "--depth-unit", "nm", "--load-unit", "mN", "--time-unit", "s"
    )
    assert status == 0
    assert json.loads(out)["youngs_modulus"] == pytest.approx(0.98e9, rel=0.02)


def test_bad_file_and_indenter_are_input_errors(capsys, tmp_path):
    status, _, err = run(capsys, "nanoindent", tmp_path / "missing.csv")
    assert status == EXIT_INPUT_ERROR and "not found" in err
    status, _, err = run(capsys, "nanoindent", EXAMPLE, "--indenter", "unobtainium")
    assert status == EXIT_INPUT_ERROR
