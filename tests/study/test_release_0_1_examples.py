"""The example study files of release 0.1 still validate, and build exactly today's cases.

They spell keys the old way (``surface``, ``counter``, ``counter_surface``, the friction ``load``,
``model = "tangential_path"``): each is accepted with a note saying what to write instead, and each
of their cases gets the same key (model, parameters, inputs and seeds) as the case of today's example, so it
computes the same numbers and a ``--resume`` of an old output folder reuses them.
"""

import shutil
from pathlib import Path

import pytest

from roughcontact.study import load_study

ROOT = Path(__file__).resolve().parents[2]
RELEASE = ROOT / "tests" / "data" / "release_0_1"
DATA = {
    "demo.toml": [ROOT / "src" / "roughcontact" / "data" / "top-1.top"],
    "paper000.toml": [ROOT / "examples" / "paper000_reported_mu.csv"],
    "paper001.toml": [ROOT / "examples" / "paper001_measured_loop.csv"],
    "paper002.toml": [],
    "tangential_path.toml": [
        ROOT / "examples" / "tangential_path_displacement.csv",
        ROOT / "examples" / "tangential_path_force.csv",
    ],
}
TODAY = {name: ROOT / "examples" / name for name in DATA}


@pytest.mark.parametrize("name", list(DATA))
def test_an_old_example_builds_todays_cases(tmp_path, name):
    for path in [RELEASE / name, *DATA[name]]:
        shutil.copy(path, tmp_path / path.name)
    shutil.copy(TODAY[name], tmp_path / f"today_{name}")  # beside the same files: keys hold their paths
    old = load_study(tmp_path / name)
    today = load_study(tmp_path / f"today_{name}")
    # today's examples may have grown analyses since (paper002: bem_volume); the old ones are unchanged
    names = {case.analysis for case in old.cases}
    assert [case.key for case in old.cases] == [case.key for case in today.cases if case.analysis in names]
    assert old.notes and all("is now called" in note for note in old.notes)
    assert not today.notes  # today's examples use today's spellings
