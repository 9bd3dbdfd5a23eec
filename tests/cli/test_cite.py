"""``roughcontact cite``: the BibTeX of the works a study's models implement, from its provenance."""

import json

import pytest

from roughcontact.cli import EXIT_INPUT_ERROR
from roughcontact.references import ROUGHCONTACT, bibtex, references_of
from roughcontact.study.kinds import get_kind
from study_documents import NORMAL_CONTACT, rough_scan

STUDY = (
    rough_scan("cite")
    + """
[[analysis]]
name = "roughness"
model = "statistics"
topography = "scan"
figures = []
"""
    + NORMAL_CONTACT
    + "figures = []\n"
)


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    """The output folder of a small study of two models (statistics, normal)."""
    from roughcontact.study import load_study, run_study
    from roughcontact.study.report import write_report

    folder = tmp_path_factory.mktemp("cite")
    (folder / "study.toml").write_text(STUDY)
    run_study(load_study(folder / "study.toml"), folder / "out")
    write_report(folder / "out", redraw=False)
    return folder / "out"


def _expected():
    keys = get_kind("statistics").references + get_kind("normal").references
    return [ROUGHCONTACT, *references_of(keys)]


def test_provenance_lists_roughcontact_and_each_models_works_once(finished):
    listed = json.loads((finished / "provenance.json").read_text())["references"]
    assert [entry["key"] for entry in listed] == [r.key for r in _expected()]
    polonsky = next(entry for entry in listed if entry["key"] == "polonsky1999")
    assert polonsky["authors"] == ["Polonsky, I. A.", "Keer, L. M."] and polonsky["year"] == 1999
    assert polonsky["doi"] == "10.1016/S0043-1648(99)00113-1" and polonsky["title"]


def test_the_report_lists_the_references_with_doi_links(finished):
    page = (finished / "report.html").read_text()
    assert "<h2>References</h2>" in page
    assert '<a href="https://doi.org/10.1115/1.2833523">doi:10.1115/1.2833523</a>' in page
    assert page.count("<li>Polonsky, I. A. and Keer, L. M. (1999).") == 1


def test_cite_prints_the_bibtex_of_a_study_folder(run, finished):
    status, out, err = run("cite", finished)
    assert status == 0, err
    assert out == bibtex(_expected())
    assert "@software{roughcontact," in out and "doi = {10.1016/S0043-1648(99)00113-1}," in out


def test_cite_prints_one_models_references(run):
    status, out, err = run("cite", "--model", "presliding")
    assert status == 0, err
    assert out == bibtex([ROUGHCONTACT, *references_of(get_kind("presliding").references)])
    assert "@article{paper001," in out and "doi = {10.1115/1.4045900}," in out
    assert "@article{cattaneo1938," in out and "@article{mindlin1953," in out


def test_a_folder_without_provenance_is_refused_in_one_line_with_the_fix(run, tmp_path):
    status, out, err = run("cite", tmp_path)
    assert status == EXIT_INPUT_ERROR and not out
    (line,) = err.strip().splitlines()
    assert str(tmp_path) in line and "provenance.json" in line and "Fix: give the folder" in line


def test_a_provenance_of_an_older_roughcontact_says_how_to_rewrite_it(run, tmp_path):
    (tmp_path / "provenance.json").write_text(json.dumps({"roughcontact": "0.1.0"}))
    status, _, err = run("cite", tmp_path)
    assert status == EXIT_INPUT_ERROR and "lists no references" in err and "--resume" in err


@pytest.mark.parametrize(
    ("argv", "said"),
    [([], "give a study's output folder or --model"), (["--model", "normall"], "unknown model 'normall'")],
)
def test_cite_needs_a_folder_or_a_known_model(run, argv, said):
    status, _, err = run("cite", *argv)
    assert status == EXIT_INPUT_ERROR and said in err
