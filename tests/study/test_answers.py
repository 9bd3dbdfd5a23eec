"""One entry point runs a study in memory or into a folder, with the same answer either way."""

import tomllib

import pytest

from roughcontact.errors import InputError
from roughcontact.study import StudyAnswer, answer
from roughcontact.study.answers import reusable
from roughcontact.study.config import build_study
from study_documents import NORMAL_CONTACT, rough_scan

STUDY = (
    rough_scan("answers")
    + NORMAL_CONTACT
    + """
[analysis.sweep]
mean_pressure = ["10 MPa", "40 MPa"]
"""
)


def _study(tmp_path, text=STUDY):
    return build_study(tomllib.loads(text), folder=tmp_path, text=text, source="answers")


def test_in_memory_and_on_disk_give_the_same_answer(tmp_path):
    memory = answer(_study(tmp_path))
    disk = answer(_study(tmp_path), tmp_path / "out")
    assert isinstance(memory, StudyAnswer) and memory.folder is None and memory.report is None
    assert disk.report == tmp_path / "out" / "report.html" and disk.summary.done == 2
    scalars = [[r.scalars for r in a.records] for a in (memory.analyses[0], disk.analyses[0])]
    assert scalars[0] == scalars[1]
    assert memory.text_lines() == disk.text_lines()
    document = memory.document()
    assert document["output"] is None and len(document["analyses"][0]["cases"]) == 2


def test_a_run_on_dask_needs_a_folder(tmp_path):
    with pytest.raises(InputError, match="needs an output folder"):
        answer(_study(tmp_path), workers=2)


def test_a_commands_folder_is_resumed_only_for_the_same_study(tmp_path):
    folder = tmp_path / "out"
    assert reusable(folder, _study(tmp_path)) is False
    answer(_study(tmp_path), folder)
    assert reusable(folder, _study(tmp_path)) is True
    other = _study(tmp_path, STUDY.replace('"40 MPa"', '"50 MPa"'))
    with pytest.raises(InputError, match="other options"):
        reusable(folder, other)
    assert reusable(folder, other, replace=True) is False and not folder.exists()


def test_provenance_and_report_state_materials_and_every_dependency(tmp_path):
    """What a methods section needs: each material's properties as used, every dependency's version."""
    import json

    result = answer(_study(tmp_path), tmp_path / "out")
    provenance = json.loads((tmp_path / "out" / "provenance.json").read_text())
    assert {"numpy", "SurfaceTopography", "matplotlib", "numba", "pyFFTW", "dask"} <= set(
        provenance["packages"]
    )
    (material,) = provenance["materials"]
    assert material["material"] == "polysilicon" and material["youngs_modulus [Pa]"] == 110e9
    assert material["poissons_ratio"] == 0.22
    report = result.report.read_text()
    assert "Materials as used" in report and "youngs_modulus (GPa)" in report
