"""roughcontact nanoindent: table, JSON, units, rate sign, plot and clear errors."""

from pathlib import Path

import pytest

from roughcontact.cli import EXIT_INPUT_ERROR, main

EXAMPLE = Path(__file__).parents[2] / "examples" / "paper001_indentation_hdpe.csv"


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_json_reads_the_example_back(capsys, scalars):
    status, out, _ = run(capsys, "nanoindent", EXAMPLE, "--json")
    assert status == 0
    document = scalars(out)
    assert document["youngs_modulus"] == pytest.approx(0.98e9, rel=0.02)
    assert document["rate_sign"] == "magnitude" and document["indenter"] == "diamond Berkovich"
    assert document["uncorrected_youngs_modulus"] > document["youngs_modulus"]


def test_table_and_figure(capsys, tmp_path):
    status, out, _ = run(capsys, "nanoindent", EXAMPLE, "-o", tmp_path / "out")
    assert status == 0
    assert "youngs_modulus" in out and "corrected_stiffness" in out and "MPa" in out
    assert (tmp_path / "out" / "figures" / "indentation_indentation.png").stat().st_size > 0


def test_the_command_prints_the_hardness(capsys, tmp_path, scalars):
    status, out, _ = run(capsys, "nanoindent", EXAMPLE, "-o", tmp_path / "out")
    assert status == 0
    lines = {line.split()[0]: line.split()[1:] for line in out.splitlines() if line.startswith("  ")}
    assert lines["hardness"] == ["60.33", "MPa"]  # built with an assumed 60 MPa (the file's header)
    assert lines["uncorrected_hardness"][1] == "MPa"
    report = (tmp_path / "out" / "report.html").read_text()
    assert ">hardness<" in report and "60.33" in report
    _, document, _ = run(capsys, "nanoindent", EXAMPLE, "--json")
    found = scalars(document)
    assert found["hardness"] == pytest.approx(found["max_load"] / (24.5 * found["contact_depth"] ** 2))
    assert found["hardness"] == pytest.approx(60.3e6, rel=2e-3)


def test_printed_rate_sign_raises_the_modulus(capsys, scalars):
    _, out, _ = run(capsys, "nanoindent", EXAMPLE, "--json")
    _, printed, _ = run(capsys, "nanoindent", EXAMPLE, "--json", "--rate-sign", "printed")
    assert scalars(printed)["youngs_modulus"] > scalars(out)["uncorrected_youngs_modulus"]


def test_unit_options_override_the_header(capsys, tmp_path, scalars):
    lines = EXAMPLE.read_text().splitlines()
    header = next(i for i, line in enumerate(lines) if not line.startswith("#"))
    lines[header] = "t,h,P"
    bare = tmp_path / "bare.csv"
    bare.write_text("\n".join(lines) + "\n")
    status, _, err = run(capsys, "nanoindent", bare, "--json")
    assert status == EXIT_INPUT_ERROR and "--depth-unit" in err
    status, out, _ = run(
        capsys, "nanoindent", bare, "--json", "--depth-unit", "nm", "--load-unit", "mN", "--time-unit", "s"
    )
    assert status == 0
    assert scalars(out)["youngs_modulus"] == pytest.approx(0.98e9, rel=0.02)


def test_bad_file_and_indenter_are_input_errors(capsys, tmp_path):
    status, _, err = run(capsys, "nanoindent", tmp_path / "missing.csv")
    assert status == EXIT_INPUT_ERROR and "not found" in err
    status, _, err = run(capsys, "nanoindent", EXAMPLE, "--indenter", "unobtainium")
    assert status == EXIT_INPUT_ERROR and "--indenter" in err
