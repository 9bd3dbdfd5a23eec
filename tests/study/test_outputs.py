"""What a study writes: table with units, figures re-drawn from stored cases, report, worker storage."""

import csv
import json
import textwrap

import pytest
import xarray as xr

from roughcontact.study import load_study, run_study

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"

STUDY = """
[study]
name = "outputs"
seed = 2

[topographies.rough]
generate = "self_affine"
shape = 32
size = "2 um"
hurst = 0.8
rms_height = "1 nm"

[[analysis]]
name = "surface"
model = "statistics"
surface = "rough"

[[analysis]]
name = "contact"
model = "normal"
surface = "rough"
material = "polysilicon"
counter = "SiO2"
mean_pressure = "20 MPa"
stress_depths = ["10 nm"]
[analysis.sweep]
mean_pressure = ["10 MPa", "40 MPa"]
"""


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    path = folder / "study.toml"
    path.write_text(textwrap.dedent(STUDY))
    out = folder / "out"
    summary = run_study(load_study(path), out)
    assert summary.done == 3 and summary.failed == 0
    return out


def rows(out):
    with (out / "results.csv").open() as handle:
        return list(csv.DictReader(handle))


def test_the_table_has_one_row_per_case_with_units_in_the_headers(finished):
    table = rows(finished)
    assert [r["analysis"] for r in table] == ["surface", "contact", "contact"]
    contact = table[1]
    assert float(contact["mean_pressure [Pa]"]) == pytest.approx(10e6, rel=1e-9)
    assert float(contact["force [N]"]) == pytest.approx(10e6 * 4e-12, rel=1e-9)
    assert 0 < float(contact["contact_fraction"]) < 1
    assert float(contact["max_von_mises [Pa]"]) > 0
    assert float(table[0]["Sq [m]"]) == pytest.approx(1e-9, rel=1e-9)


def test_records_and_fields_are_stored_per_case(finished):
    records = [json.loads(p.read_text()) for p in (finished / "cases" / "contact").glob("*.json")]
    assert len(records) == 2
    (record,) = [r for r in records if r["axes"] == {"mean_pressure": "10 MPa"}]
    assert record["status"] == "done" and record["case"] == record["key"][:16]
    assert record["parameters"]["mean_pressure"] == 10e6
    assert record["seeds"]["rough"] > 0 and record["version"]
    fields = xr.load_dataset(finished / record["fields"])
    assert fields["pressure"].shape == (32, 32)
    assert float(fields["pressure"].sum()) * (2e-6 / 32) ** 2 == pytest.approx(
        record["scalars"]["force"], rel=1e-9
    )


def test_plot_redraws_the_figures_from_the_stored_cases(finished, cli):
    for png in (finished / "figures").glob("*.png"):
        png.unlink()
    status, out, err = cli("plot", finished)
    assert status == 0, err
    drawn = sorted(p.name for p in (finished / "figures").glob("*.png"))
    assert drawn == sorted(
        [
            "contact_contact.png",
            "contact_area_load.png",
            "contact_load_approach.png",
            "contact_von_mises.png",
            "surface_heights.png",
            "surface_psd.png",
        ]
    )
    assert all(p.read_bytes().startswith(PNG_MAGIC) for p in (finished / "figures").glob("*.png"))


def test_report_is_one_offline_page(finished, cli):
    status, out, err = cli("report", finished)
    assert status == 0, err
    page = (finished / "report.html").read_text()
    assert page.startswith("<!DOCTYPE html>") and "Study complete" in page
    assert page.count("data:image/png;base64,") == 6
    assert "http://" not in page and "https://" not in page  # nothing fetched from elsewhere
    assert "max_von_mises [Pa]" in page and "Provenance" in page


def test_plot_and_report_refuse_a_folder_without_a_study(tmp_path, cli):
    status, _, err = cli("report", tmp_path)
    assert status == 2 and "holds no study results" in err
    status, _, err = cli("plot", tmp_path)
    assert status == 2 and "holds no study results" in err


def test_worker_storage_keeps_the_fields_there(tmp_path):
    path = tmp_path / "study.toml"
    path.write_text(textwrap.dedent(STUDY))
    storage = tmp_path / "scratch"
    run_study(load_study(path), tmp_path / "out", worker_storage=storage)
    stored = sorted(storage.rglob("*.nc"))
    assert len(stored) == 3 and not list((tmp_path / "out" / "cases").rglob("*.nc"))
    record = json.loads(next((tmp_path / "out" / "cases" / "contact").glob("*.json")).read_text())
    assert record["fields"].startswith(str(storage.resolve()))
    from roughcontact.study.outputs import draw_figures

    figures, problems = draw_figures(tmp_path / "out")  # figures read the fields where they are
    assert not problems and len(figures) == 6
