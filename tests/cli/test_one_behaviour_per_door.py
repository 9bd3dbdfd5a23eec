"""One behaviour per door (issue 45, parts 4-5): one levelling, the same numbers and doubts in every door.

``read_topography`` levels a measured scan as the commands do and says so in the result; an
implausible scan is said to be one by every door that reads it (a note, a study's note, a
``PlausibilityWarning``); no command lets a numpy ``RuntimeWarning`` through on the issue's inputs.
"""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import numpy as np
import pytest

import roughcontact as rc
from roughcontact.cli import main
from roughcontact.errors import InputError
from roughcontact.topography.plausible import PlausibilityWarning

ROOT = Path(__file__).resolve().parents[2]
TOP = ROOT / "src" / "roughcontact" / "data" / "top-1.top"
POLY = ("--material", "polysilicon", "--counter-body", "SiO2")


def _run(capsys, argv):
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # one reaching a command is an internal error
        status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    assert "internal error" not in captured.err and "Traceback" not in captured.err, captured.err
    return status, captured.out, captured.err


def _contact(topography):
    return rc.solve_normal(
        topography,
        rc.get_material("polysilicon"),
        counter_body=rc.get_material("SiO2"),
        mean_pressure=rc.quantity("20 MPa", "pressure"),
    )


# --- levelling: Python as the commands ---------------------------------------------------------------


def test_the_python_door_levels_top_1_as_the_contact_command_and_says_so(capsys):
    status, out, _ = _run(capsys, ["contact", TOP, *POLY, "--pressure", "20 MPa", "--json"])
    assert status == 0
    command = json.loads(out)["analyses"][0]["cases"][0]["scalars"]
    scan = rc.read_topography(TOP)  # as the README's Python section reads it
    assert scan.info["detrend"] == "plane"
    python = _contact(scan).scalars()
    assert python["approach"] == pytest.approx(5.45e-9, abs=0.005e-9)  # the README's numbers
    assert python["number_of_patches"] == 3 and python["levelling"] == "plane"
    assert python["approach"] == pytest.approx(command["approach"], rel=1e-12)
    assert python["number_of_patches"] == command["number_of_patches"]
    assert python["contact_area"] == pytest.approx(command["contact_area"], rel=1e-12)
    assert command["levelling"] == "plane"


def test_an_unlevelled_scan_is_asked_for_and_its_result_says_it(capsys):
    raw = rc.read_topography(TOP, detrend="none")
    contact = _contact(raw)
    assert contact.scalars()["levelling"] == "none"
    assert contact.approach == pytest.approx(4.42e-9, abs=0.005e-9) and contact.number_of_patches == 5
    status, out, _ = _run(
        capsys, ["contact", TOP, *POLY, "--pressure", "20 MPa", "--detrend", "none", "--json"]
    )
    scalars = json.loads(out)["analyses"][0]["cases"][0]["scalars"]
    assert status == 0 and scalars["levelling"] == "none"
    assert scalars["approach"] == pytest.approx(contact.approach, rel=1e-12)
    assert "levelling" in contact._repr_html_()  # a notebook shows it with the scalars


def test_a_periodic_read_is_levelled_by_its_mean_and_a_plane_on_it_is_refused():
    periodic = rc.read_topography(TOP, periodic=True)
    assert periodic.periodic and periodic.info["detrend"] == "mean"
    assert periodic.heights.mean() == pytest.approx(0.0, abs=1e-20)
    with pytest.raises(InputError) as refused:
        rc.read_topography(TOP, periodic=True, detrend="plane")
    assert refused.value.field == "detrend" and "detrend='mean'" in str(refused.value)
    with pytest.raises(InputError, match="unknown levelling 'tilt'"):
        rc.read_topography(TOP, detrend="tilt")
    with pytest.raises(InputError, match="expected True or False"):
        rc.read_topography(TOP, periodic="yes")


def test_a_generated_surface_has_no_levelling_to_say():
    surface = rc.generate.self_affine((32, 32), 1e-6, hurst=0.8, rms_height=1e-9, seed=1)
    assert "levelling" not in _contact(surface).scalars()


# --- doubts at every door -----------------------------------------------------------------------------


@pytest.fixture(scope="module")
def scans(tmp_path_factory):
    folder = tmp_path_factory.mktemp("doubts")
    heights = rc.generate.self_affine((32, 32), 1e-6, hurst=0.8, rms_height=3e-8, seed=2).heights * 1e9
    files = {"wide": folder / "wide.txt", "flat": folder / "flat.txt"}
    np.savetxt(files["wide"], heights)
    np.savetxt(files["flat"], np.full((32, 32), 3.0))
    for name, size in (("wide", "160 m"), ("flat", "1 um")):
        study = folder / f"{name}.toml"
        study.write_text(
            f'[study]\nname = "{name}"\n\n[topographies.a]\nfile = "{name}.txt"\nsize = "{size}"\n'
            'height_unit = "nm"\n\n[[analysis]]\nname = "stats"\nmodel = "statistics"\ntopography = "a"\n'
        )
        files[f"{name}.toml"] = study
    files["folder"] = folder
    return files


WIDE = "the scan is 160 m x 160 m, outside 1 nm to 1 m"


def test_a_scan_of_160_m_is_doubted_by_inspect_plot_validate_run_contact_and_python(scans, capsys):
    typed = ("--size", "160 m", "--height-unit", "nm")
    for argv in (
        ["inspect", scans["wide"], *typed],
        ["inspect", scans["wide"], *typed, "--json"],
        ["plot", scans["wide"], *typed, "-o", scans["folder"] / "wide.png"],
    ):
        status, out, err = _run(capsys, argv)
        assert status == 0 and f"roughcontact: note: wide.txt: {WIDE}" in err, err
        assert "--size and --height-unit" in err
    assert WIDE in " ".join(
        json.loads(_run(capsys, ["inspect", scans["wide"], *typed, "--json"])[1])["notes"]
    )
    for argv in (["validate", scans["wide.toml"]], ["run", scans["wide.toml"], "-o", scans["folder"] / "w"]):
        status, _, err = _run(capsys, argv)
        assert status == 0 and f"roughcontact: note: topographies.a: {WIDE}" in err, err
        assert "size and height_unit, with override_file_values = true" in err
    status, _, err = _run(capsys, ["contact", scans["wide"], *typed, *POLY, "--pressure", "20 MPa"])
    assert f"roughcontact: note: topographies.surface: {WIDE}" in err and "--size and --height-unit" in err
    assert status == 3 and f"{WIDE} (implausible), and the load displaces the surface" in err, err
    with pytest.warns(PlausibilityWarning, match=f"wide.txt: {WIDE}; check its size and height unit"):
        rc.read_topography(scans["wide"], size="160 m", height_unit="nm")


def test_a_generated_scan_of_160_m_is_doubted_at_validation(tmp_path, capsys):
    study = tmp_path / "generated.toml"
    study.write_text(
        '[study]\nname = "wide"\n\n[topographies.a]\ngenerate = "self_affine"\nshape = 16\nsize = "160 m"\n'
        'hurst = 0.8\nrms_height = "30 nm"\nseed = 1\n\n[[analysis]]\nname = "stats"\nmodel = "statistics"\n'
        'topography = "a"\n'
    )
    status, _, err = _run(capsys, ["validate", study])
    assert status == 0 and f"roughcontact: note: topographies.a: {WIDE}; check size and its unit." in err, err


def test_a_flat_file_is_reported_flat_by_every_door(scans, capsys):
    typed = ("--size", "1 um", "--height-unit", "nm")
    status, out, err = _run(capsys, ["inspect", scans["flat"], *typed])
    assert status == 0 and "the surface is flat once levelled" in err
    assert "flat           yes" in out and "summit_radius" not in out and "Sq                 0 m" in out
    status, out, err = _run(capsys, ["inspect", scans["flat"], *typed, "--json"])
    described = json.loads(out)
    assert described["flat"] is True and described["statistics"]["Sq"] == 0.0
    status, _, err = _run(capsys, ["validate", scans["flat.toml"]])
    assert status == 0 and "topographies.a: the surface is flat" in err
    status, out, err = _run(
        capsys, ["contact", scans["flat"], *typed, *POLY, "--pressure", "20 MPa", "--json"]
    )
    scalars = json.loads(out)["analyses"][0]["cases"][0]["scalars"]
    assert status == 0 and scalars["contact_fraction"] == 1.0  # the flat punch: full contact
    assert "the surface is flat" in err


def test_the_issues_inputs_let_no_numpy_warning_through(scans, capsys, tmp_path):
    """The issue's inputs through each command, RuntimeWarnings as errors (``_run``)."""
    huge = np.random.default_rng(1).normal(size=(16, 16))
    huge[3, 4] = 1e300
    np.savetxt(tmp_path / "huge.txt", huge)
    typed = ("--size", "1 um", "--height-unit", "nm")
    for argv, expected in (
        (["inspect", tmp_path / "huge.txt", *typed], 2),
        (["contact", tmp_path / "huge.txt", *typed, *POLY, "--pressure", "20 MPa"], 2),
        (["inspect", scans["flat"], *typed], 0),
        (["plot", scans["flat"], *typed, "-o", tmp_path / "flat.png"], 0),
        (["contact", scans["flat"], *typed, *POLY, "--pressure", "20 MPa", "--boundary", "periodic"], 0),
        (["contact", scans["flat"], *typed, *POLY, "--pressure", "20 MPa", "--detrend", "none"], 0),
    ):
        status, _, err = _run(capsys, argv)
        assert status == expected, err
        assert "RuntimeWarning" not in err and "np.float64" not in err, err
