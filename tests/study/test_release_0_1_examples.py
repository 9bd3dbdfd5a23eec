"""The example study files of release 0.1 still validate, and build exactly today's cases.

They spell keys the old way (``surface``, ``counter``, ``counter_surface``, the friction ``load``,
``model = "tangential_path"``): each is accepted with a note saying what to write instead, and each
of their cases gets the same key (model, parameters, inputs and seeds) as the case of today's example, so it
computes the same numbers and a ``--resume`` of an old output folder reuses them. The papers' examples
now take their scenarios from ``roughcontact.papers`` (``paperNNN = true``, the paper generators), so
their keys changed: their cases are checked to compute the same thing instead (the same surfaces to
1e-12, parameters, material constants and seeds).
"""

import shutil
from pathlib import Path

import numpy as np
import pytest

from roughcontact.study import load_study
from roughcontact.study.inputs import build_topography

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
FROM_PAPERS = {"paper000.toml", "paper001.toml", "paper002.toml"}
"""Examples whose scenario today comes from roughcontact.papers (other case keys, same computation)."""
CHANGED = {"paper001.toml": {"window": (64, 128)}}
"""Keys today's paper examples changed on purpose: paper001's five balls per load (issue 34) touch
beyond the old 64 px window, so the example solves 128 px."""
STAND_INS = {"paper001.toml": {"rms": "drawn"}, "paper002.toml": {"roughness": "gaussian"}}
"""The paper generators' options that give release 0.1's stand-ins: today's defaults match the papers
(issue 34: the ball's RMS after sphere removal is Table 2's, the island has all three moments)."""


@pytest.mark.parametrize("name", list(DATA))
def test_an_old_example_builds_todays_cases(tmp_path, name):
    for path in [RELEASE / name, *DATA[name]]:
        shutil.copy(path, tmp_path / path.name)
    shutil.copy(TODAY[name], tmp_path / f"today_{name}")  # beside the same files: keys hold their paths
    old = load_study(tmp_path / name)
    today = load_study(tmp_path / f"today_{name}")
    # today's examples may have grown analyses since (paper002: bem_volume); the old ones are unchanged
    names = {case.analysis for case in old.cases}
    kept = [case for case in today.cases if case.analysis in names]
    # today's examples may run more realisations (issue 34): the old cases are today's of their replicates
    replicates = {(case.analysis, case.parameters.replicate) for case in old.cases}
    kept = [case for case in kept if (case.analysis, case.parameters.replicate) in replicates]
    if name in FROM_PAPERS:
        assert len(old.cases) == len(kept)
        for before, now in zip(old.cases, kept, strict=True):
            _same_computation(before, now, CHANGED.get(name, {}), STAND_INS.get(name, {}))
    else:
        assert [case.key for case in old.cases] == [case.key for case in kept]
    assert old.notes and all("is now called" in note for note in old.notes)
    assert not today.notes  # today's examples use today's spellings


def _same_computation(before, now, changed: dict, stand_in: dict) -> None:
    """Assert that two cases solve the same problem: parameters, materials, seeds and surfaces.

    ``changed`` maps a key changed on purpose to its (old, new) value; ``stand_in`` the options of
    today's paper generators that draw the old surfaces.
    """
    assert before.seeds == now.seeds
    first, second = before.parameters.model_dump(), now.parameters.model_dump()
    for key, (old, new) in changed.items():
        assert (first.pop(key), second.pop(key)) == (old, new)
    for key in ("material", "counter_body", "substrate"):  # a study name for the library's entry
        if first.get(key) is not None:
            a, b = before.materials[first.pop(key)], now.materials[second.pop(key)]
            assert (a.youngs_modulus, a.poissons_ratio, a.hardness) == (
                b.youngs_modulus,
                b.poissons_ratio,
                b.hardness,
            )
    assert first.keys() == second.keys()
    for key, value in first.items():
        assert value == (
            pytest.approx(second[key], rel=1e-12) if isinstance(value, float) else second[key]
        ), key
    for name, spec in before.topographies.items():
        a, b = (
            build_topography(
                s.model_copy(update={k: v for k, v in stand_in.items() if k in type(s).model_fields}), None
            )
            for s in (spec, now.topographies[name])
        )  # an old file read today gets today's stand-in: both are built with the old one
        assert a.size == pytest.approx(b.size, rel=1e-12)
        np.testing.assert_allclose(a.heights, b.heights, rtol=1e-12, atol=1e-12 * np.ptp(a.heights))
