"""Messages as data (issue 46): marked keys said in each door's words, through every kind of message.

A message marks the keys it names (``«boundary=periodic»``, :mod:`roughcontact.messages`); Python,
a study file and the command line each render the marks in their own words, and nothing rewrites
prose after the fact. These tests render one message of every kind (an error of a model, a problem
of a study, a warning of a result, a note of an answer) through the three doors and find no study
key in the command line's words and no option in Python's.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

import roughcontact as rc
from roughcontact.cli import main
from roughcontact.errors import InputError
from roughcontact.messages import Door, Message, default_option, key, marked, render
from roughcontact.study import StudyError, load_study

ROOT = Path(__file__).resolve().parents[2]
TOP = ROOT / "src" / "roughcontact" / "data" / "top-1.top"
OPTION = re.compile(r"(?<![\w-])--[a-z][a-z-]+")


def _study_keys() -> set[str]:
    """Every key of every study model and table that has an underscore (so it cannot be prose)."""
    from roughcontact.study import schema
    from roughcontact.study.kinds import get_kind, kind_names

    keys = set()
    for name in kind_names():
        kind = get_kind(name)
        keys |= set(kind.parameters.model_fields)
        if kind.compare is not None:
            keys |= set(kind.compare.model_fields)
    for spec in (schema.FileTopography, schema.MaterialSpec):
        keys |= set(spec.model_fields)
    return {k for k in keys if "_" in k}


STUDY_KEYS = _study_keys()


def _no_study_key(text: str) -> None:
    """A command line's message names no study key (``mean_pressure``, ``film_thickness = ...``)."""
    assert "«" not in text and "»" not in text, text
    words = set(re.findall(r"(?<![\w./-])[a-z][a-z0-9]*(?:_[a-z0-9]+)+(?![\w-])", text))
    assert not (words & STUDY_KEYS), (words & STUDY_KEYS, text)


def _no_option(text: str) -> None:
    """A Python message names no command-line option."""
    assert "«" not in text and not OPTION.search(text), text


@pytest.mark.parametrize(
    ("marked_text", "python", "study", "cli"),
    [
        ("«exclude_filled»", "exclude_filled", "exclude_filled", "--exclude-filled"),
        ("«boundary=periodic»", "boundary='periodic'", 'boundary = "periodic"', "--boundary periodic"),
        ("«exclude_filled=true»", "exclude_filled=True", "exclude_filled = true", "--exclude-filled"),
        ("«max_filled=0.3»", "max_filled=0.3", "max_filled = 0.3", "--max-filled 0.3"),
        ("«max_force=10 uN»", "max_force=quantity('10 uN')", 'max_force = "10 uN"', "--max-force '10 uN'"),
        (
            "«friction_coefficient=...»",
            "friction_coefficient=...",
            "friction_coefficient = ...",
            "--friction-coefficient ...",
        ),
    ],
)
def test_each_door_says_a_key_in_its_words(marked_text, python, study, cli):
    assert render(marked_text, Door.PYTHON) == python
    assert render(marked_text, Door.STUDY) == study
    assert render(marked_text, Door.CLI) == cli
    peak = {"max_force": "--peak"}
    own = render(marked_text, "cli", lambda name: peak.get(name, default_option(name)))
    assert own == (cli if "max_force" not in marked_text else "--peak '10 uN'")
    assert key("max_filled", 0.3) == "«max_filled=0.3»" and key("resume", True) == "«resume=true»"


def test_a_key_the_command_has_no_option_for_is_named_as_the_study_key():
    assert (
        render("use «film_base=frictionless»", Door.CLI, lambda name: None)
        == 'use film_base = "frictionless" (a study key)'
    )


def test_a_message_prints_in_python_words_and_keeps_its_marks():
    message = Message("Use «boundary=periodic».")
    assert message == "Use boundary='periodic'." and marked(message) == "Use «boundary=periodic»."
    assert marked("plain") == "plain" and render(message, Door.CLI) == "Use --boundary periodic."
    error = InputError("boundary", "free is not «boundary=free».", "give «boundary=periodic».")
    assert str(error) == "boundary: free is not boundary='free'. Fix: give boundary='periodic'."
    assert error.text("cli") == "--boundary: free is not --boundary free. Fix: give --boundary periodic."
    assert error.text("study") == 'boundary: free is not boundary = "free". Fix: give boundary = "periodic".'


# --- every kind of message, through the three doors --------------------------------------------------


def _cli(capsys, *argv):
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_an_error_of_a_model_through_the_three_doors(capsys, tmp_path):
    line = rc.Topography(np.sin(np.linspace(0, 6.28, 64, endpoint=False)) * 1e-9, 1e-6)
    with pytest.raises(InputError) as refused:  # Python: a free line contact
        rc.solve_normal(line, rc.get_material("SiO2"), mean_pressure=1e6, boundary="free")
    _no_option(str(refused.value))
    assert "boundary='periodic'" in str(refused.value)
    profile = tmp_path / "line.txt"
    profile.write_text("\n".join(f"{1e9 * v:.4f}" for v in line.heights))
    study = tmp_path / "line.toml"
    study.write_text(
        f'[study]\nname = "line"\n[topographies.line]\nfile = "{profile}"\nsize = "1 um"\n'
        'height_unit = "nm"\n[[analysis]]\nname = "n"\nmodel = "normal"\ntopography = "line"\n'
        'material = "SiO2"\nmean_pressure = "1 MPa"\nboundary = "free"\n'
    )
    with pytest.raises(StudyError) as study_error:  # a study file
        load_study(study)
    assert 'boundary = "periodic"' in str(study_error.value) and not OPTION.search(str(study_error.value))
    status, _, err = _cli(  # the command line
        capsys,
        "contact",
        profile,
        "--size",
        "1 um",
        "--height-unit",
        "nm",
        "--material",
        "SiO2",
        "--pressure",
        "1 MPa",
        "--boundary",
        "free",
    )
    assert status == 2 and "--boundary periodic" in err
    _no_study_key(err)


def test_a_problem_of_a_study_through_the_doors(capsys, tmp_path):
    study = tmp_path / "two.toml"
    study.write_text(
        f'[study]\nname = "two"\n[topographies.scan]\nfile = "{TOP}"\n[[analysis]]\nname = "n"\n'
        'model = "normal"\ntopography = "scan"\nmaterial = "SiO2"\nforce = "1 uN"\napproach = "1 nm"\n'
    )
    status, _, err = _cli(capsys, "validate", study)
    assert status == 2 and 'mean_pressure = "20 MPa"' in err and not OPTION.search(err)
    status, _, err = _cli(
        capsys, "contact", TOP, "--material", "SiO2", "--force", "1 uN", "--approach", "1 nm"
    )
    assert status == 2 and "--pressure" in err and "--force" in err
    _no_study_key(err)


def test_a_warning_of_a_result_through_the_three_doors(capsys, tmp_path):
    sphere = rc.generate.sphere((64, 64), 2e-6, radius=5e-6)  # its apex moved to the window's edge
    ball = rc.Topography(np.roll(sphere.heights, 30, axis=0), sphere.size)
    result = rc.solve_normal(ball, rc.get_material("SiO2"), mean_pressure=2e8, boundary="free")
    said = " ".join(result.range_warnings())
    assert "boundary='periodic'" in said and "hardness" in said
    _no_option(said)
    rc.save_topography(ball, tmp_path / "ball.nc")
    contact = [
        "contact",
        tmp_path / "ball.nc",
        "--material",
        "SiO2",
        "--pressure",
        "200 MPa",
        "--boundary",
        "free",
    ]
    status, out, err = _cli(capsys, *contact, "-o", tmp_path / "out")
    assert status == 0 and "--boundary periodic" in err and "--hardness" in err, err
    _no_study_key(err)
    report = (tmp_path / "out" / "report.html").read_text().split("Study file")[0]
    assert "boundary = &quot;periodic&quot;" in report and not OPTION.search(report)
    status, out, err = _cli(capsys, *contact, "--json")
    warnings = json.loads(out)["analyses"][0]["cases"][0]["warnings"]
    assert (
        warnings and all("«" not in w for w in warnings) and any("--boundary periodic" in w for w in warnings)
    )


def test_a_note_of_an_answer_through_the_doors(capsys):
    from roughcontact.study.answers import answer
    from roughcontact.study.config import build_study

    document = {
        "study": {"name": "one draw", "seed": 1},
        "topographies": {
            "scan": {
                "generate": "self_affine",
                "shape": 16,
                "size": "1 um",
                "hurst": 0.8,
                "rms_height": "1 nm",
            }
        },
        "analysis": [
            {
                "name": "n",
                "model": "normal",
                "topography": "scan",
                "material": "SiO2",
                "mean_pressure": "1 MPa",
            }
        ],
    }
    study = build_study(document, folder=Path.cwd(), text="", source="notes")
    lines = "\n".join(answer(study).text_lines())
    assert "realisations=N" in lines and not OPTION.search(lines.split("  ")[-1])
    status, out, _ = _cli(capsys, "contact", TOP, "--material", "SiO2", "--pressure", "1 MPa")
    assert status == 0


def test_the_bad_inputs_of_the_command_line_name_no_study_key(capsys, tmp_path):
    """Every refusal of the option campaign (tests/cli/test_every_option.py's paths) in options only."""
    cases = [
        ["contact", TOP, "--material", "SiO2", "--pressure", "-1 MPa"],
        ["contact", TOP, "--material", "SiO2"],
        ["adhesion", TOP, "--material", "polysilicon", "--max-approach", "2 nm"],
        [
            "adhesion",
            TOP,
            "--material",
            "SiO2",
            "--work-of-adhesion",
            "50 mJ/m^2",
            "--max-approach",
            "2 nm",
            "--start",
            "3 nm",
        ],
        ["presliding", TOP, "--material", "POM", "--normal-force", "2 mN", "--stroke", "1 um"],
        ["asperity", "--moments", "1e-18", "1e-4", "1e10", "--material", "SU-8", "--max-force", "1 mN"],
        [
            "friction",
            TOP,
            "--material",
            "polysilicon",
            "--surface-energy",
            "50 mJ/m^2",
            "--normal-force",
            "1 uN",
            "--hold-time",
            "3 s",
            "--relaxed-modulus",
            "-1 GPa",
        ],
        ["inspect", TOP, "--height-unit", "furlong"],
    ]
    for argv in cases:
        status, _, err = _cli(capsys, *argv)
        assert status == 2 and "Fix:" in err, (argv, err)
        _no_study_key(err)
