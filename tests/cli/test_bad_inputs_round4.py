"""Bad and messy inputs of round four (issue 45): every input used or refused, every message true.

Each case runs a command as a user types it (or a study file through ``validate`` and ``run``)
and asserts the exit status, that no traceback or internal error is printed, that the message
names the field the user typed (the option, key or file) and the fix; then it follows that fix
as written and asserts that the command succeeds. Python-door cases assert the error's field and
fix. Files are written here or taken from the repository (examples/, src/roughcontact/data/).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

import roughcontact as rc
from roughcontact.cli import main
from roughcontact.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
TOP = ROOT / "src" / "roughcontact" / "data" / "top-1.top"
EXAMPLES = ROOT / "examples"
POLY = ("--material", "polysilicon", "--counter-body", "SiO2")


@dataclass
class Bad:
    """A command that must be refused with its field and fix, and the command with the fix followed."""

    argv: list
    status: int
    field: str
    fix: str
    follow: list | None = None
    prepare: object = None  # writes the files both commands read, into the folder it is given


def _run(capsys, argv):
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def _self_affine(name: str, seed: int) -> str:
    return (
        f'[topographies.{name}]\ngenerate = "self_affine"\nshape = 32\nsize = "1 um"\nhurst = 0.8\n'
        f'rms_height = "1 nm"\nseed = {seed}\n'
    )


def _study(folder: Path, topographies: str, analysis_extra: str = "", name: str = "study.toml") -> Path:
    text = f"""[study]
name = "bad"

{topographies}
[[analysis]]
name = "contact"
model = "normal"
topography = "a"
material = "SiO2"
mean_pressure = "10 MPa"
{analysis_extra}
"""
    path = folder / name
    path.write_text(text)
    return path


def _cases(folder: Path) -> dict[str, Bad]:
    circular = _study(
        folder,
        '[topographies.a]\ncombine = ["b", "c"]\n[topographies.b]\ncombine = ["a", "c"]\n'
        + _self_affine("c", 1),
        name="circular.toml",
    )
    not_circular = _study(
        folder,
        '[topographies.a]\ncombine = ["b", "c"]\n' + _self_affine("b", 2) + _self_affine("c", 1),
        name="combined.toml",
    )
    negative = _study(
        folder,
        _self_affine("a", 1),
        '[analysis.sweep]\nmean_pressure = ["10 MPa", "-5 MPa"]',
        "negative.toml",
    )
    positive = _study(
        folder, _self_affine("a", 1), '[analysis.sweep]\nmean_pressure = ["10 MPa", "5 MPa"]', "positive.toml"
    )
    return {
        "a circular combination passes validate (it recursed at run)": Bad(
            ["validate", circular],
            2,
            "topographies.b.combine",
            "a file or a generator",
            ["validate", not_circular],
        ),
        "a negative value in a sweep passes validate (run refused it)": Bad(
            ["validate", negative],
            2,
            "sweep.mean_pressure",
            "at least 0",
            ["run", positive, "-o", folder / "p"],
        ),
        "a negative pressure names the option and the value as typed": Bad(
            ["contact", TOP, *POLY, "--pressure", "-1 MPa"],
            2,
            "--pressure",
            "give a value at least 0",
            ["contact", TOP, *POLY, "--pressure", "1 MPa"],
        ),
    }


@pytest.fixture(scope="module")
def bad(tmp_path_factory):
    return _cases(tmp_path_factory.mktemp("bad"))


def _names() -> list[str]:
    import inspect
    import re

    return re.findall(r'^        "([^"]+)": Bad\(', inspect.getsource(_cases), flags=re.MULTILINE)


@pytest.mark.parametrize("name", _names())
def test_a_bad_input_is_refused_with_its_field_and_a_fix_that_works(bad, capsys, name):
    case = bad[name]
    status, out, err = _run(capsys, case.argv)
    said = out + err
    assert "Traceback" not in said and "internal error" not in said
    assert status == case.status, said
    assert case.field in err and case.fix in err and "Fix:" in err, err
    if case.follow is not None:
        status, out, err = _run(capsys, case.follow)
        assert status == 0 and "Traceback" not in out + err, out + err


# --- zero loads: the unloaded state, not a division by zero -----------------------------------------


def test_zero_pressure_is_the_unloaded_state_through_every_door(capsys, tmp_path):
    status, out, err = _run(capsys, ["contact", TOP, *POLY, "--pressure", "0 MPa", "--json"])
    assert status == 0 and "internal error" not in err, err
    import json

    scalars = json.loads(out)["analyses"][0]["cases"][0]["scalars"]
    assert scalars["force"] == 0 and scalars["contact_fraction"] == 0 and scalars["approach"] == 0
    surface = rc.generate.self_affine((32, 32), 1e-6, hurst=0.8, rms_height=1e-9, seed=1)
    for target in ({"mean_pressure": 0.0}, {"force": 0.0}):
        result = rc.solve_normal(surface, rc.get_material("SiO2"), **target)
        assert result.converged and result.contact_area == 0 and result.approach == 0
        assert np.all(result.pressure == 0) and np.all(result.gap >= 0)


# --- the Python door checks the types of its arguments ------------------------------------------------


@pytest.mark.parametrize(
    ("call", "field", "fix"),
    [
        (lambda: rc.Topography(np.zeros((4, 4)), 1e-6, periodic="no"), "periodic", "periodic=False"),
        (
            lambda: rc.solve_normal(np.zeros((8, 8)), rc.get_material("SiO2"), mean_pressure=1e6),
            "topography",
            "Topography(heights, size=5e-6)",
        ),
        (lambda: rc.run_study(42, "out"), "study", "load_study('study.toml')"),
        (lambda: rc.spectral_moments([1.0, 2.0, 3.0]), "topography", "read_topography(path)"),
    ],
    ids=["periodic-string", "array-as-topography", "number-as-study", "list-as-topography"],
)
def test_the_python_door_refuses_arguments_of_the_wrong_type(call, field, fix):
    with pytest.raises(InputError) as refused:
        call()
    assert refused.value.field == field and fix in refused.value.fix
