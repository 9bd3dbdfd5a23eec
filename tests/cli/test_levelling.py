"""Measured scans are levelled before contact and statistics unless the user says otherwise (issue 15).

A raw scan's tilt is an artefact of mounting; left in, it decides where a flat touches. These tests
pin that every command and study levels a file with a plane by default, that the choice is said
in the summary, the ``--json`` document, the provenance and the report, and that ``--detrend none``
keeps the tilt.
"""

import json

import numpy as np
import pytest

from roughcontact.errors import InputError
from roughcontact.study import load_study, run_study
from roughcontact.study.report import write_report
from roughcontact.topography import Topography, level, save_topography
from roughcontact.topography.generate import self_affine
from roughcontact.topography.statistics import rq

SHARED = "../shared/data/topographies"


@pytest.fixture(scope="module")
def twins(tmp_path_factory):
    """A measured-like scan (64^2, 2 um, Sq 2 nm, not periodic) and its twin tilted by 20 nm per um."""
    folder = tmp_path_factory.mktemp("twins")
    flat = self_affine((64, 64), 2e-6, hurst=0.8, rms_height=2e-9, seed=7)
    x, y = flat.meshgrid()
    level_file, tilted_file = folder / "level.nc", folder / "tilted.nc"
    save_topography(Topography(flat.heights, flat.size), level_file)
    save_topography(Topography(flat.heights + 0.02 * x - 0.01 * y, flat.size), tilted_file)
    return level_file, tilted_file


def _contact(run, scalars, file, *extra):
    status, out, err = run(
        "contact", file, "--material", "polysilicon", "--pressure", "50 MPa", "--json", *extra
    )
    assert status == 0, err
    return json.loads(out), scalars(out)


def test_a_tilted_scan_touches_like_its_levelled_twin(run, scalars, twins):
    level_file, tilted_file = twins
    _, levelled = _contact(run, scalars, level_file)
    document, tilted = _contact(run, scalars, tilted_file)
    assert tilted["contact_fraction"] == pytest.approx(levelled["contact_fraction"], rel=1e-9, abs=1e-9)
    assert tilted["number_of_patches"] == levelled["number_of_patches"]
    assert tilted["approach"] == pytest.approx(levelled["approach"], rel=1e-6)
    assert document["topographies"]["surface"]["detrend"] == "plane"


def test_detrend_none_keeps_the_tilt_and_says_so(run, scalars, twins):
    level_file, tilted_file = twins
    _, levelled = _contact(run, scalars, level_file)
    document, raw = _contact(run, scalars, tilted_file, "--detrend", "none")
    assert document["topographies"]["surface"]["detrend"] == "none"
    # the tilt (40 nm across the scan, 20x the roughness) puts the contact on one corner
    assert raw["contact_fraction"] < 0.5 * levelled["contact_fraction"]
    status, out, _ = run(
        "contact", tilted_file, "--material", "polysilicon", "--pressure", "50 MPa", "--detrend", "none"
    )
    assert status == 0
    assert "tilted.nc" in out and "not levelled" in out and "tilt of the scan is kept" in out


def test_summary_says_the_scan_was_levelled(run, twins):
    status, out, _ = run("contact", twins[1], "--material", "polysilicon", "--pressure", "50 MPa")
    assert status == 0
    assert "surface: tilted.nc, 64 x 64 points" in out and "least-squares plane subtracted" in out


def test_inspect_reports_the_levelled_statistics_by_default(run, twins):
    status, out, _ = run("inspect", twins[1], "--json")
    assert status == 0
    levelled = json.loads(out)
    status, out, _ = run("inspect", twins[1], "--json", "--detrend", "none")
    raw = json.loads(out)
    assert levelled["detrend"] == "plane" and raw["detrend"] == "none"
    assert raw["statistics"]["Sq"] > 3 * levelled["statistics"]["Sq"]


def test_inspect_of_a_real_afm_scan_is_levelled(run):
    """WSxM ``top-1.top``: Rq 3.15 nm as stored (tilted), 1.6 nm levelled (issue 15's example)."""
    status, out, _ = run("inspect", f"{SHARED}/top-1.top", "--json")
    assert status == 0
    assert json.loads(out)["statistics"]["Sq"] == pytest.approx(1.61e-9, rel=0.01)
    status, out, _ = run("inspect", f"{SHARED}/top-1.top", "--json", "--detrend", "none")
    assert json.loads(out)["statistics"]["Sq"] == pytest.approx(3.15e-9, rel=0.01)


def test_a_study_levels_its_files_and_keeps_the_choice(tmp_path, twins):
    level_file, tilted_file = twins
    (tmp_path / "study.toml").write_text(
        f"""
[study]
name = "levelling"

[topographies.tilted]
file = "{tilted_file}"

[topographies.raw]
file = "{tilted_file}"
detrend = "none"

[topographies.level]
file = "{level_file}"

[[analysis]]
name = "contact"
model = "normal"
material = "polysilicon"
mean_pressure = "50 MPa"
sweep = {{ topography = ["tilted", "raw", "level"] }}
"""
    )
    study = load_study(tmp_path / "study.toml")
    assert {name: p["detrend"] for name, p in study.prepared.items()} == {
        "tilted": "plane",
        "raw": "none",
        "level": "plane",
    }
    run_study(study, tmp_path / "out")
    provenance = json.loads((tmp_path / "out" / "provenance.json").read_text())
    assert provenance["topographies"]["raw"]["detrend"] == "none"
    report = write_report(tmp_path / "out").read_text()
    assert "least-squares plane subtracted" in report and "tilt of the scan is kept" in report


@pytest.mark.parametrize(
    ("mode", "tolerance"), [("mean", 1e-9), ("plane", 1e-9), ("curvature", 1e-9), ("sphere", 1e-3)]
)
def test_level_twice_changes_nothing(mode, tolerance):
    """Levelling again leaves a levelled surface alone (relative to its Sq).

    The linear fits are least-squares projections (exact to rounding); the sphere is a nonlinear
    fit whose second pass finds a cap of almost no curvature (measured: 7e-5 of Sq).
    """
    x = np.linspace(-1e-6, 1e-6, 48)
    ball = Topography(
        -(x[:, None] ** 2 + x[None, :] ** 2) / (2 * 20e-6) + 1e-9 * np.sin(7e6 * x[:, None]), 2e-6
    )
    once = level(ball, mode)
    again = level(once, mode)
    assert np.max(np.abs(again.heights - once.heights)) <= tolerance * rq(once)


def test_level_none_is_the_identity_and_unknown_modes_are_refused():
    surface = self_affine((16, 16), 1e-6, hurst=0.8, rms_height=1e-9, seed=1)
    kept = level(surface, "none")
    assert np.array_equal(kept.heights, surface.heights) and kept.size == surface.size and kept.periodic
    assert kept.info == {**surface.info, "detrend": "none"}  # the levelling is recorded, "none" too
    assert level(surface, "plane").info["detrend"] == "plane"
    with pytest.raises(InputError, match="detrend.*choose one of none, mean, plane, curvature, sphere"):
        level(surface, "tilt")


def test_every_file_of_a_command_gets_the_units_and_the_levelling():
    """A second file (friction's tip) takes --size, --height-unit and --detrend as FILE does."""
    import argparse

    from roughcontact.cli.options import CommandStudy

    args = argparse.Namespace(
        file="scan.txt", size=("5 um",), height_unit="nm", channel=None, max_filled=None,
        fill_undefined=False, periodic=False, detrend="plane",
    )  # fmt: skip
    command = CommandStudy("roughcontact friction")
    command.topography_file("surface", args)
    command.topography_file("tip", args, file="tip.txt")
    tables = command.document["topographies"]
    for name in ("surface", "tip"):
        assert tables[name]["size"] == "5 um" and tables[name]["height_unit"] == "nm"
        assert tables[name]["detrend"] == "plane"
