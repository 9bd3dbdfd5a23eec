"""The ``adhesion`` study kind on a small adhesive sphere.

* the kind's case is :func:`solve_adhesive` on the same surface, law and programme (same numbers);
* the work of adhesion from the surface energies by either combining rule;
* the smooth sphere's closed forms beside a generated sphere's result;
* bad input refused before anything runs (naming the key), or by the case (naming the key).

The command is tested in tests/cli/test_cli_adhesion.py.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from roughcontact.analytic.adhesion import maugis_dugdale_pull_off, maugis_parameter
from roughcontact.contact.adhesive import solve_adhesive
from roughcontact.contact.interaction import MaugisDugdale
from roughcontact.materials import Material, get_material
from roughcontact.study import load_study
from roughcontact.study.config import StudyError
from roughcontact.study.run import execute, make_task
from roughcontact.study.store import read_table
from roughcontact.topography.generate import sphere
from study_documents import ADHESION_CYCLE, adhesive_ball

FILM = Material(4e9, 0.3, name="film")
EXAMPLE_SCAN = Path(__file__).resolve().parents[2] / "src" / "roughcontact" / "data" / "top-1.top"
BALL = {"shape": (32, 32), "size": 200e-9, "radius": 1e-6}

STUDY = adhesive_ball("adhesive ball", "{gamma}") + ADHESION_CYCLE + "steps = 10\n{extra}\n"


def _study(tmp_path, *, gamma="25 mJ/m^2", extra='work_of_adhesion = "50 mJ/m^2"'):
    path = tmp_path / "adhesion.toml"
    path.write_text(STUDY.format(gamma=gamma, extra=extra))
    return load_study(path)


def _case(tmp_path, **options):
    study = _study(tmp_path, **options)
    record, dataset = execute(make_task(study, study.cases[0]))
    assert record["status"] == "done", record["error"]
    return record, dataset


def test_a_case_is_solve_adhesive_on_the_same_surface_law_and_programme(tmp_path):
    record, dataset = _case(tmp_path)
    programme = np.concatenate([np.linspace(-9.5e-9, 1e-9, 11), np.linspace(-9.5e-9, 1e-9, 11)[-2::-1]])
    direct = solve_adhesive(sphere(**BALL), FILM, MaugisDugdale(0.05, 1.9e-9), approach=programme)
    scalars = record["scalars"]
    assert scalars["pull_off_force"] == pytest.approx(direct.pull_off_force, rel=1e-12)
    assert scalars["dissipated_energy"] == pytest.approx(direct.dissipated_energy, rel=1e-9)
    np.testing.assert_allclose(dataset["force"], direct.force, rtol=1e-12, atol=0)
    assert set(dataset["state"].values) == {"peak", "pull_off", "end"}
    assert dataset["pressure"].attrs["units"] == "Pa" and dataset["approach"].attrs["units"] == "m"


def test_the_smooth_sphere_closed_forms_stand_beside_a_generated_sphere(tmp_path):
    scalars = _case(tmp_path)[0]["scalars"]
    contact_modulus = FILM.youngs_modulus / (1 - FILM.poissons_ratio**2)
    lam = maugis_parameter(0.05, 1e-6, contact_modulus, 0.05 / 1.9e-9)
    assert scalars["maugis_parameter"] == pytest.approx(lam, rel=1e-12)
    reference = maugis_dugdale_pull_off(lam) * math.pi * 0.05 * 1e-6
    assert scalars["maugis_dugdale_pull_off"] == pytest.approx(reference, rel=1e-12)
    assert scalars["jkr_pull_off"] == pytest.approx(1.5 * math.pi * 0.05e-6)
    assert scalars["dmt_pull_off"] == pytest.approx(2.0 * math.pi * 0.05e-6)
    # lambda = 0.3, a cohesive zone of ~40 pixels: the coarse cycle is within 5 % of Maugis (1992)
    assert scalars["pull_off_to_maugis_dugdale"] == pytest.approx(1.0, abs=0.05)


@pytest.mark.parametrize(("rule", "factor"), [(None, 2.0), ("girifalco_good", 2.0), ("printed", 1.0)])
def test_the_work_of_adhesion_comes_from_the_surface_energies_by_the_combining_rule(tmp_path, rule, factor):
    extra = 'counter_body = "SiO2"' + (f'\ncombining_rule = "{rule}"' if rule else "")
    scalars = _case(tmp_path, gamma="25 mJ/m^2", extra=extra)[0]["scalars"]
    gamma_sio2 = get_material("SiO2").surface_energy
    assert scalars["work_of_adhesion"] == pytest.approx(factor * math.sqrt(0.025 * gamma_sio2), rel=1e-12)


def test_a_rigid_flat_without_a_surface_energy_is_refused_naming_the_key(tmp_path):
    # known before anything runs: validation refuses it (issue 32)
    with pytest.raises(StudyError, match=r"\(cycle\)\.counter_surface_energy: no surface energy") as caught:
        _study(tmp_path, extra="")
    assert 'counter_surface_energy = "72 mJ/m^2"' in str(caught.value)


@pytest.mark.parametrize(
    ("extra", "words"),
    [
        ('work_of_adhesion = "-50 mJ/m^2"', "work_of_adhesion must be positive"),
        ('work_of_adhesion = "50 mJ/m^2"\nstart = "2 nm"', "start must lie below max_approach"),
        ('work_of_adhesion = "50 mJ/m^2"\nwinkler = true', 'law = "lennard_jones"'),
        ('work_of_adhesion = "50 mJ/m^2"\nlaw = "morse"', "law"),
        ('work_of_adhesion = "50"', "unit"),
    ],
)
def test_bad_keys_are_refused_before_anything_runs(tmp_path, extra, words):
    with pytest.raises(StudyError) as caught:
        _study(tmp_path, extra=extra)
    assert words in str(caught.value)


REDUCED = {
    "shape = 128": "shape = 64",  # 6.25 nm pixels over the same 400 nm
    "steps = 120": "steps = 20",
    'range = "1 nm"\nmax_approach = "2 nm"': 'range = "1 nm"\nmax_approach = "2 nm"\nsteps = 10',
    'max_approach = "3 nm"': 'max_approach = "1 nm"\nsteps = 8',  # the AFM scan: a short cycle
}


def test_the_example_study_runs_with_its_figures_and_tables(tmp_path, shrunk, cli):
    """examples/adhesion.toml reduced (the AFM file as it is): every case, figure and table."""
    study = shrunk("adhesion.toml", tmp_path, REDUCED)
    text = study.read_text().replace("../src/roughcontact/data/top-1.top", str(EXAMPLE_SCAN))
    study.write_text(text)
    output = tmp_path / "out"
    status, out, err = cli("run", study, "-o", output, "--no-progress")
    assert status == 0, err
    assert "7 cases run, 0 reused, 0 failed" in out
    for analysis in ("maugis", "laws", "afm"):
        assert (output / "tables" / f"{analysis}_adhesion.csv").exists()
        assert (output / "figures" / f"{analysis}_force_approach.png").stat().st_size > 0
        assert (output / "figures" / f"{analysis}_maps.png").stat().st_size > 0
    assert (output / "figures" / "maugis_pull_off.png").exists()
    rows = {row["case"]: row for row in read_table(output / "tables" / "maugis_adhesion.csv")}
    ratios = sorted(float(row["bem / maugis_dugdale pull-off"]) for row in rows.values())
    assert 0.9 < ratios[0] and ratios[-1] < 1.2  # coarse; the example's own grid: 0.98-1.09
