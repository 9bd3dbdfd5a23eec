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
    linked = page.replace('<a href="https://doi.org/', "")  # the references' DOIs are links, not fetched
    assert "http://" not in linked and "https://" not in linked  # nothing fetched from elsewhere
    assert "Provenance" in page


def _html_tables(page: str) -> list[list[list[str]]]:
    """Every table of a page as rows of cell texts (header row first)."""
    from html.parser import HTMLParser

    class Tables(HTMLParser):
        def __init__(self):
            super().__init__()
            self.tables, self.cell = [], None

        def handle_starttag(self, tag, attrs):
            if tag == "table":
                self.tables.append([])
            elif tag == "tr":
                self.tables[-1].append([])
            elif tag in ("td", "th"):
                self.cell = ""

        def handle_data(self, data):
            if self.cell is not None:
                self.cell += data

        def handle_endtag(self, tag):
            if tag in ("td", "th"):
                self.tables[-1][-1].append(self.cell)
                self.cell = None

    parser = Tables()
    parser.feed(page)
    return parser.tables


def test_report_tables_are_in_engineering_units_with_the_unit_beside_the_number(finished, cli):
    cli("report", finished)
    page = (finished / "report.html").read_text()
    tables = _html_tables(page)
    listed = [table for table in tables if table[0][:2] == ["quantity", "unit"]]
    quantities = {row[0]: row[1:] for table in listed for row in table[1:]}
    assert quantities["Sq"] == ["nm", "1"]  # generated to 1 nm exactly
    assert quantities["size_x"] == ["µm", "2"]
    assert quantities["max_von_mises_depth"] == ["nm", "10", "10"]
    unit, *pressures = quantities["mean_pressure"]
    assert unit == "MPa" and [float(v) for v in pressures] == pytest.approx([10, 40], rel=1e-6)
    dimensional = [v for unit, *values in quantities.values() if unit for v in values]
    assert len(dimensional) > 20 and not [v for v in dimensional if "e" in v]  # 2.81 (um), not 2.805e-06


def test_report_captions_say_what_each_figure_shows(finished, cli):
    cli("report", finished)
    page = (finished / "report.html").read_text()
    assert "the real contact area (red) on the nominal area" in page
    assert page.count("<figcaption><b>") == 6


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


def test_figures_drawn_from_the_same_inputs_are_kept_not_redrawn(tmp_path):
    from roughcontact.study.outputs import draw_figures

    path = tmp_path / "study.toml"
    path.write_text(textwrap.dedent(STUDY))
    out = tmp_path / "out"
    run_study(load_study(path), out)
    first, problems = draw_figures(out)
    assert first and not problems
    stamps = {p: p.stat().st_mtime_ns for p in first}
    again, _ = draw_figures(out)
    assert again == first and all(p.stat().st_mtime_ns == stamps[p] for p in again)  # kept
    redrawn, _ = draw_figures(out, dpi=80)  # another resolution: drawn anew
    assert all(p.stat().st_mtime_ns != stamps[p] for p in redrawn)
    first[0].unlink()  # a figure gone: drawn anew
    assert draw_figures(out, dpi=80)[0][0].is_file()
    # a record changed (a case rerun): drawn anew
    record = next((out / "cases").rglob("*.json"))
    stamps = {p: p.stat().st_mtime_ns for p in redrawn}
    data = json.loads(record.read_text())
    data["seconds"] = (data.get("seconds") or 0) + 1.0
    record.write_text(json.dumps(data))
    assert any(p.stat().st_mtime_ns != stamps[p] for p in draw_figures(out, dpi=80)[0])


# --- the spread over realisations keeps to the range its quantity can take ---------------------------


def _realisations(kind_name, scalars_per_realisation, tmp_path):
    """A stored analysis of one setting whose cases are realisations with the given scalars (no solving)."""
    from roughcontact.study.kind import CaseRecord
    from roughcontact.study.kinds import get_kind
    from roughcontact.study.outputs import StoredAnalysis

    records = tuple(
        CaseRecord(
            {
                "case": f"case{r}",
                "status": "done",
                "parameters": {"sample": "", "replicate": r},
                "axes": {"replicate": r},
                "scalars": scalars,
            },
            tmp_path,
        )
        for r, scalars in enumerate(scalars_per_realisation)
    )
    kind = get_kind(kind_name)
    cases = tuple(r["case"] for r in records)
    return StoredAnalysis("a", kind, kind.summary, (), None, (), cases, records, len(records), ("s",))


def _row(rows, quantity):
    (row,) = [r for r in rows if r["quantity"] == quantity]
    return row


def test_a_fraction_near_1_over_three_realisations_keeps_its_interval_below_1(tmp_path):
    from roughcontact.spread import spread
    from roughcontact.study.outputs import spread_rows

    values = [0.99, 1.0, 1.0]  # Student's interval of the mean: 0.9967 +- 0.0143, up to 1.011
    assert spread(values).ci95_high > 1.01
    analysis = _realisations("normal", [{"contact_fraction": v} for v in values], tmp_path)
    row = _row(spread_rows(analysis), "contact_fraction")
    assert row["n"] == 3 and row["mean"] == pytest.approx(0.99667, rel=1e-4)
    assert row["ci95_high"] == 1.0 and row["ci95_low"] == pytest.approx(0.99667 - 0.01434, rel=1e-3)
    assert "cut at 1" in row["note"] and "[0, 1]" in row["note"]


def test_a_positive_quantity_over_two_realisations_keeps_its_interval_above_0(tmp_path):
    from roughcontact.study.outputs import spread_rows

    # n = 2: t_{0.975, 1} = 12.71, so the interval of the mean reaches 12.7 std below it
    records = [{"contact_area": 1e-12, "approach": -1e-9}, {"contact_area": 3e-12, "approach": 1e-9}]
    rows = spread_rows(_realisations("normal", records, tmp_path))
    area = _row(rows, "contact_area")
    assert area["ci95_low"] == 0.0 and area["ci95_high"] == pytest.approx(2e-12 + 12.706 * 1e-12, rel=1e-4)
    assert "cut at 0" in area["note"] and "2 values" in area["note"]
    approach = _row(rows, "approach")  # an approach may be negative (a pulled flat): not cut
    assert approach["ci95_low"] == pytest.approx(-12.706e-9, rel=1e-4) and approach["note"] == ""


def test_a_kind_names_the_bounds_its_names_do_not_tell(tmp_path):
    from roughcontact.study.kinds import get_kind
    from roughcontact.study.outputs import spread_rows

    kind = get_kind("nanoindentation")
    assert kind.bounds_of("youngs_modulus") == (0.0, float("inf"))  # by the kind: a modulus is positive
    assert kind.bounds_of("contact_area") == (0.0, float("inf"))  # natural: an area
    assert kind.bounds_of("unloading_rate") is None  # negative on unloading
    assert get_kind("normal").bounds_of("approach") is None  # an approach may be negative (adhesion)
    rows = spread_rows(_realisations("nanoindentation", [{"hardness": 50e6}, {"hardness": 70e6}], tmp_path))
    assert _row(rows, "hardness")["ci95_low"] == 0.0 and "cut at 0" in _row(rows, "hardness")["note"]


def test_the_report_and_the_terminal_mark_a_cut_interval_and_say_why_once(tmp_path):
    from roughcontact.study.outputs import footnoted, spread_rows

    records = [
        {"contact_fraction": f, "contact_area": a, "number_of_patches": n, "one_pixel_patches": n}
        for f, a, n in ((0.99, 2.0e-12, 1), (1.0, 2.1e-12, 3), (1.0, 2.2e-12, 2))
    ]
    rows = spread_rows(_realisations("normal", records, tmp_path))
    shown = footnoted(rows)
    assert [r["note"] for r in shown] == ["[1]", "", "[2]", "[2]"]  # the same reason, the same mark
    assert shown.notes == (f"[1] {rows[0]['note']}", f"[2] {rows[2]['note']}")
    assert "cut at 1" in rows[0]["note"] and "cut at 0" in rows[2]["note"]  # the stored rows keep theirs
    assert footnoted(rows[1:2]) == rows[1:2] and not footnoted(rows[1:2]).notes
