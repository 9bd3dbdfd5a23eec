"""The report's methods section: software, surfaces, materials as used, and every combined quantity."""

import math

import pytest

from roughcontact.study import load_study, run_study
from roughcontact.study.methods import methods_paragraph
from roughcontact.study.outputs import read_study
from roughcontact.study.report import write_report
from study_documents import ADHESION_CYCLE, adhesive_ball

STUDY = (
    adhesive_ball("methods")
    + ADHESION_CYCLE
    + """counter_body = "SiO2"
steps = 6
[[analysis]]
name = "pressed"
model = "normal"
topography = "ball"
material = "film"
counter_body = "SiO2"
force = "1 uN"
"""
)


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    folder = tmp_path_factory.mktemp("methods")
    path = folder / "study.toml"
    path.write_text(STUDY)
    run_study(load_study(path), folder / "out")
    return folder / "out"


def test_the_methods_section_says_how_each_quantity_was_combined(finished):
    import json

    from roughcontact.study.methods import methods_paragraph

    provenance = json.loads((finished / "provenance.json").read_text())
    paragraphs = methods_paragraph(read_study(finished)[1], provenance, [])
    text = "\n".join(paragraphs)
    assert paragraphs[0].startswith("Computed with roughcontact") and "numpy" in paragraphs[0]
    assert "film (E = 4 GPa, ν = 0.3, γ = 25 mJ/m²)" in text
    assert "SiO2 (E = 70 GPa, ν = 0.17, γ = 72 mJ/m²)" in text
    work = 2 * math.sqrt(25e-3 * 72e-3)  # Girifalco-Good, 84.85 mJ/m^2
    assert f"2 √(γ₁ γ₂) (Girifalco and Good 1957) = {work * 1e3:.3g} mJ/m²" in text
    assert "25 mJ/m² (film's surface energy), 72 mJ/m² (SiO2's surface energy)" in text
    modulus = 1 / ((1 - 0.3**2) / 4e9 + (1 - 0.17**2) / 70e9)
    assert f"E* = {modulus / 1e9:.4g} GPa from 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ of film and SiO2" in text


def test_the_report_has_the_methods_section(finished):
    page = write_report(finished, redraw=False).read_text()
    assert "<h2>Methods</h2>" in page and "Girifalco and Good 1957" in page


def test_keys_swept_over_one_value_are_no_sweep(tmp_path):
    from roughcontact.study.methods import varied_axes

    path = tmp_path / "study.toml"
    path.write_text(
        STUDY.split("[[analysis]]")[0]
        + '[[analysis]]\nname = "pressed"\nmodel = "normal"\ntopography = "ball"\nmaterial = "film"\n'
        + 'force = "1 uN"\n[analysis.sweep]\ntolerance = [1e-8]\nforce = ["1 uN", "2 uN"]\n'
    )
    run_study(load_study(path), tmp_path / "out")
    (analysis,) = read_study(tmp_path / "out")[1]
    assert len(analysis.sweep_axes) == 2
    assert varied_axes(analysis) == ["force"]
    page = write_report(tmp_path / "out", redraw=False).read_text()
    assert "swept: force<" in page
    assert "2 cases over force." in page  # the methods paragraph names the same keys


def test_the_rule_stated_is_the_one_that_gives_the_case_its_value():
    from roughcontact.study.kind import CaseRecord
    from roughcontact.study.methods import _work_of_adhesion

    materials = {"a": {"material": "a", "surface_energy [J/m^2]": 50e-3}, "b": {"material": "b"}}

    def record(value):
        data = {
            "parameters": {"material": "a", "counter_body": "b", "counter_surface_energy": 72e-3},
            "scalars": {"work_of_adhesion": value},
        }
        return CaseRecord(data, None)

    root = math.sqrt(50e-3 * 72e-3)
    assert "2 √(γ₁ γ₂) (Girifalco and Good 1957) = 120 mJ/m²" in _work_of_adhesion(
        record(2 * root), materials
    )
    assert "√(γ₁ γ₂) (paper 000 as printed) = 60 mJ/m²" in _work_of_adhesion(record(root), materials)
    assert _work_of_adhesion(record(0.1), materials) == "Work of adhesion Δγ = 100 mJ/m²."  # no rule gives it


REALISATIONS = """
[study]
name = "realisations in words"
seed = 3

[topographies.scan]
generate = "self_affine"
shape = 32
size = "2 um"
hurst = 0.8
rms_height = "5 nm"

[[analysis]]
name = "contact"
model = "normal"
topography = "scan"
material = "polysilicon"
realisations = 2

[analysis.sweep]
mean_pressure = ["10 MPa", "40 MPa", "80 MPa"]
"""


@pytest.fixture(scope="module")
def realised(tmp_path_factory):
    from roughcontact.study import answer

    folder = tmp_path_factory.mktemp("realised")
    path = folder / "study.toml"
    path.write_text(REALISATIONS)
    return answer(load_study(path), folder / "out")


def test_a_case_is_one_realisation_of_one_setting(realised):
    import html
    import json

    provenance = json.loads((realised.folder / "provenance.json").read_text())
    (text,) = methods_paragraph(realised.analyses, provenance, [])[2:]
    words = "3 settings, each on 2 realisations (one case per realisation)."
    assert f"6 cases over mean pressure, replicate: {words}" in text
    assert "each on 2 realisations of" not in text  # the old words: 6 cases, each on 2 realisations
    page = html.unescape(realised.report.read_text())
    assert "3 settings, each on 2 realisations (one case per realisation)" in page
    assert (
        "Each setting ran on 2 realisations of the generated surface(s) scan, one case per realisation"
        in page
    )
    lines = "\n".join(realised.text_lines())
    assert "Each setting ran on 2 realisations" in lines and "Each case ran on" not in lines


def test_a_setting_short_of_its_realisations_is_said(realised):
    from dataclasses import replace

    from roughcontact.study.methods import _realisations

    (analysis,) = realised.analyses
    assert _realisations(analysis) == "3 settings, each on 2 realisations (one case per realisation)"
    partial = replace(analysis, records=(None, *analysis.records[1:]))  # one case not stored yet
    assert (
        _realisations(partial)
        == "3 settings, each on 1 to 2 of the 2 planned realisations (one case per realisation)"
    )
    one = replace(analysis, records=analysis.records[:2])
    assert _realisations(one) == "one setting on 2 realisations (one case per realisation)"


def test_the_report_marks_an_interval_cut_at_its_bound_and_says_why_under_the_table(realised):
    import csv

    with (realised.folder / "tables" / "contact_spread.csv").open() as handle:
        stored = list(csv.DictReader(handle))
    cut = [row for row in stored if row["note"]]
    assert cut, "two realisations of a positive quantity: Student's interval (t = 12.7) reaches below 0"
    assert all(
        float(row["ci95_low"]) >= 0
        for row in stored
        if row["quantity"] in ("contact_area", "contact_fraction")
    )
    assert all(row["note"].startswith("95 % interval cut at ") for row in cut)
    page = realised.report.read_text()
    section = page[page.index("<h3>spread</h3>") :]
    section = section[: section.index("<h3>", 4) if "<h3>" in section[4:] else len(section)]
    assert '<td class="text ">[1]</td>' in section and '<th class="text">note</th>' in section
    assert '<p class="note">[1] 95 % interval cut at ' in section
    assert section.count("95 % interval cut at") == len({row["note"] for row in cut})  # each reason once
    lines = realised.text_lines()
    assert any(line.startswith("    note: [1] 95 % interval cut at ") for line in lines)
