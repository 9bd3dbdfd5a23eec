"""A number without a unit is refused at the edges, with the units the user probably meant (issue 15).

``--size 5`` used to be a 5 m AFM scan, ``--pressure 20`` 20 Pa, ``loop-analysis --normal-force 25``
25 N (mu = 0.0002) and a study's ``load = "10"`` 10 N: silent wrong answers. Dimensionless
quantities (Poisson's ratio, mu, tolerances) and zero stay bare.
"""

from pathlib import Path

import pytest

from roughcontact.errors import UnitError
from roughcontact.study.config import StudyError, build_study
from roughcontact.units import quantity

SHARED = "../shared/data/topographies"


@pytest.mark.parametrize(
    ("argv", "option", "meant"),
    [
        (
            ["contact", f"{SHARED}/top-1.top", "--material", "SU-8", "--pressure", "20"],
            "--pressure",
            "'20 MPa'",
        ),
        (["contact", f"{SHARED}/top-1.top", "--material", "SU-8", "--force", "10"], "--force", "'10 mN'"),
        (["inspect", f"{SHARED}/afm-slippy.txt", "--size", "5", "--height-unit", "nm"], "--size", "'5 um'"),
        (
            [
                "contact",
                f"{SHARED}/top-1.top",
                "--material-youngs-modulus",
                "70",
                "--material-poissons-ratio",
                "0.3",
                "--pressure",
                "1 MPa",
            ],
            "--material-youngs-modulus",
            "'70 GPa'",
        ),
    ],
)
def test_a_bare_number_is_refused_with_the_units_meant(run, argv, option, meant):
    status, out, err = run(*argv)
    assert status == 2, out
    assert err.startswith(f"roughcontact: error: {option}: ") and "has no unit" in err
    assert meant in err.split("did you mean", 1)[1]


def test_loop_analysis_normal_force_needs_a_unit(run, tmp_path):
    status, _, err = run("loop-analysis", "examples/paper001_measured_loop.csv", "--normal-force", "25")
    assert status == 2
    assert "--normal-force" in err and "did you mean '25 mN'" in err


def test_a_study_value_without_unit_is_refused_once_by_key():
    document = {
        "study": {"name": "bare"},
        "topographies": {
            "rough": {
                "generate": "gaussian_random",
                "shape": 16,
                "size": "1 um",
                "rms_height": "1 nm",
                "correlation_length": "100 nm",
            }
        },
        "analysis": [
            {"name": "contact", "model": "normal", "topography": "rough", "material": "SU-8", "force": "10"}
        ],
    }
    with pytest.raises(StudyError) as caught:
        build_study(document, folder=Path.cwd(), text="", source="bare.toml")
    problems = list(caught.value.problems)
    assert len(problems) == 1
    field, problem, fix = problems[0]
    assert field.endswith("force") and "10 has no unit" in problem and "'10 mN'" in fix


@pytest.mark.parametrize("value", [0, "0", 0.0, "0 nm"])
def test_zero_needs_no_unit(value):
    assert quantity(value, "length", require_unit=True) == 0.0


@pytest.mark.parametrize(
    "spelling", ["5 um", "5 µm", "5 μm", "5 micron", "5 microns", "5um", "5e-6 m", "5000 nm"]
)
def test_common_spellings_of_micrometres(spelling):
    assert quantity(spelling, "length", require_unit=True) == pytest.approx(5e-6, rel=1e-12)


def test_dimensionless_values_stay_bare():
    assert quantity("0.3", "dimensionless", require_unit=True) == 0.3
    with pytest.raises(UnitError, match="an area needs one"):
        quantity("1e-16", "area", require_unit=True)
