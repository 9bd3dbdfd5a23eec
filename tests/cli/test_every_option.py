"""Every option of every model command is used or refused (issue 45, part 1).

For each command that runs a model (a one-case study) and each of its options, the command is run
as a user types it: a baseline that works, plus that option with a value it takes. The model is
not run: the command's study document is captured where :func:`roughcontact.cli.output.run_command`
would run it, after the command has refused what its path did not read. Each option must then be

* refused, with its name and "not used" and the reason (what chose the path), or
* used: the study document differs from the baseline's (the option reached the model), or it is
  an option of the output itself (``-o``, ``--json``, ...), which acts outside the document.

An option read and then dropped without a word fails this test.
"""

from __future__ import annotations

import argparse
import copy
from pathlib import Path

import pytest

from roughcontact.cli import build_parser, main
from roughcontact.cli.options import CommandStudy

ROOT = Path(__file__).resolve().parents[2]
TOP = ROOT / "src" / "roughcontact" / "data" / "top-1.top"
EXAMPLES = ROOT / "examples"

BASELINES = {
    "contact": [TOP, "--material", "polysilicon", "--pressure", "10 MPa"],
    "adhesion": [
        TOP,
        "--material",
        "polysilicon",
        "--work-of-adhesion",
        "50 mJ/m^2",
        "--max-approach",
        "2 nm",
    ],
    "friction": [
        TOP,
        TOP,
        "--material",
        "polysilicon",
        "--surface-energy",
        "50 mJ/m^2",
        "--normal-force",
        "1 uN",
    ],
    "friction-compare": [EXAMPLES / "paper000_reported_mu.csv"],
    "friction-compare --sample": [
        EXAMPLES / "paper000_reported_mu.csv",
        "--sample",
        f"Ra 1.45 nm={TOP},{TOP}",
    ],
    "asperity": ["--paper002"],
    "asperity FILE --bem": [TOP, "--material", "polysilicon", "--bem", "--max-force", "1 uN"],
    "presliding": ["--paper001"],
    "presliding FILE": [TOP, "--material", "POM", "--normal-force", "25 mN", "--stroke", "2 um"],
    "loop-analysis": [
        EXAMPLES / "paper001_measured_loop.csv",
        "--normal-force",
        "25 mN",
        "--displacement-unit",
        "um",
        "--force-unit",
        "mN",
    ],
    "nanoindent": [EXAMPLES / "paper001_indentation_hdpe.csv"],
    "theories FILE": [TOP, "--material", "polysilicon"],
    "theories": ["--material", "polysilicon"],
}
"""A command line of each path of each model command that runs as typed (its first word is the
command; the files are only named, the study is not built)."""

INSTEAD = {
    ("friction", "normal_forces"): ("--normal-force", "1 uN"),
    ("presliding", "path"): ("--stroke", "2 um"),
}
"""Words of a baseline an option replaces (the baseline's --normal-force beside --normal-forces is
refused as not used, rightly)."""

OUTPUT = {"output", "overwrite", "json", "dpi"}
"""Options of the output itself: they act on what is written or printed, not on the study document."""

VALUES = {
    "channel": ["0"],
    "size": ["600 nm"],
    "height_unit": ["nm"],
    "position_unit": ["um"],
    "max_filled": ["0.3"],
    "crop": ["0 nm", "300 nm"],
    "detrend": ["curvature"],
    "boundary": ["periodic"],
    "material": ["SiO2"],
    "material_youngs_modulus": ["100 GPa"],
    "material_poissons_ratio": ["0.3"],
    "counter_body": ["SiO2"],
    "counter_body_youngs_modulus": ["100 GPa"],
    "counter_body_poissons_ratio": ["0.3"],
    "pressure": ["5 MPa"],
    "force": ["1 uN"],
    "approach": ["1 nm"],
    "hardness": ["5 GPa"],
    "tolerance": ["1e-7"],
    "stress_depths": ["5 nm"],
    "device": ["cpu"],
    "output": ["{tmp}/out"],
    "dpi": ["100"],
    "law": ["exponential"],
    "range": ["0.5 nm"],
    "ranges": ["0.5 nm", "1 nm"],
    "work_of_adhesion": ["60 mJ/m^2"],
    "surface_energy": ["40 mJ/m^2"],
    "counter_surface_energy": ["60 mJ/m^2"],
    "combining_rule": ["printed"],
    "max_approach": ["1.5 nm"],
    "start": ["-3 nm"],
    "steps": ["10"],
    "jump_resolution": ["0.1 nm"],
    "film_thickness": ["100 nm"],
    "layer_thickness": ["40 nm"],
    "reading": ["contact=zero_gap"],
    "normal_force": ["2 uN"],
    "normal_forces": ["1 uN", "2 uN"],
    "hold_time": ["5 s"],
    "relaxed_modulus": ["80 GPa"],
    "relaxation_time": ["2 s"],
    "epsilon": ["1.5 nm"],
    "tip_radius": ["1 um"],
    "gap_model": ["bem"],
    "sample": ["Ra 1.45 nm={top},{top}"],
    "tip": ["{top}"],
    "alpha": ["0.05"],
    "seed": ["3"],
    "grid": ["32"],
    "realisations": ["2"],
    "moments": ["1e-18", "1e-4", "1e10"],
    "yield_strength": ["1 GPa"],
    "modulus_form": ["paper002_eq7_printed"],
    "distribution": ["measured"],
    "max_force": ["10 uN"],
    "area": ["1e-8 m^2"],
    "reference_force": ["1 uN"],
    "substrate": ["SiO2"],
    "plasticity": ["volume"],
    "hardening_modulus": ["1 GPa"],
    "depth": ["5 um"],
    "layers": ["8"],
    "measured": ["{loop}"],
    "ball": ["POM"],
    "friction_coefficient": ["0.2"],
    "stroke": ["1 um"],
    "path": ["{path}"],
    "maps": ["2"],
    "radius": ["5 mm"],
    "cycles": ["2"],
    "steps_per_stroke": ["10"],
    "window": ["100"],
    "pixels": ["128"],
    "normal_loading": ["frictionless"],
    "loading_steps": ["6"],
    "max_stick_change": ["0.2"],
    "measured_displacement_unit": ["um"],
    "measured_force_unit": ["mN"],
    "measured_normal_force": ["25 mN"],
    "displacement_unit": ["um"],
    "force_unit": ["mN"],
    "branch": ["decreasing"],
    "depth_column": ["depth"],
    "load_column": ["load"],
    "time_column": ["time"],
    "depth_unit": ["nm"],
    "load_unit": ["mN"],
    "time_unit": ["s"],
    "indenter": ["diamond berkovich"],
    "poissons_ratio": ["0.4"],
    "beta": ["1.05"],
    "fit_range": ["0.3", "0.9"],
    "rate_sign": ["printed"],
    "creep_fit": ["linear"],
}
VALUES |= {
    "loads": ["0.01", "0.1"],
    "pressures": ["5 MPa", "50 MPa"],
    "gamma": ["0.45"],
    "kappa_max_fraction": ["0.05"],
    "hurst": ["0.6"],
    "rms_slope": ["0.2"],
    "short_cutoff": ["100 nm"],
    "long_cutoff": ["1 um"],
    "rolloff": ["0.5"],
}
VALUES |= {
    ("adhesion", "reading"): ["paper"],
    ("asperity", "law"): ["jackson_green"],
    ("presliding", "normal_forces"): ["25 mN"],
    ("nanoindent", "indenter"): ["diamond flat tip"],
    ("nanoindent", "epsilon"): ["0.72"],
}
"""A value each option takes (``{tmp}``, ``{top}``, ``{loop}``, ``{path}``: files of the test); a
(command, destination) key where a command takes another."""


def _options():
    """(path, option string, destination, takes a value) of every option of every model command path."""
    parser = build_parser()
    commands = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    found = []
    for path, baseline in BASELINES.items():
        typed = {str(word) for word in baseline}
        for action in commands.choices[path.split()[0]]._actions:
            if (
                action.option_strings
                and action.dest not in ("help",)
                and not typed & set(action.option_strings)
            ):
                flag = isinstance(action, argparse._StoreTrueAction | argparse._StoreFalseAction)
                found.append((path, action.option_strings[0], action.dest, not flag))
    return found


class _Built(BaseException):
    """Raised where the command's study is built: the options have been read (or refused) by then."""

    def __init__(self, document):
        super().__init__()
        self.document = document


def _captured(monkeypatch, capsys, argv):
    """Run ``argv`` up to the building of its study; return (status, error text, the study document).

    The command runs as typed (:func:`roughcontact.cli.output.run_command` reads its output
    options and refuses unused ones); where it would validate and solve, the document is taken.
    """

    def built(command):
        raise _Built(copy.deepcopy(command.document))

    monkeypatch.setattr(CommandStudy, "build", built)
    try:
        status = main([str(a) for a in argv])
    except _Built as stop:
        capsys.readouterr()
        return 0, "", stop.document
    return status, capsys.readouterr().err, None


@pytest.fixture
def files(tmp_path):
    path = tmp_path / "programme.csv"
    path.write_text("x [um],y [um]\n0,0\n1,0\n0,0\n")
    return {"tmp": tmp_path, "top": TOP, "loop": EXAMPLES / "paper001_measured_loop.csv", "path": path}


@pytest.mark.parametrize(("command", "option", "dest", "valued"), _options(), ids=lambda v: str(v))
def test_every_option_is_used_or_refused(monkeypatch, tmp_path, capsys, files, command, option, dest, valued):
    name = command.split()[0]
    status, err, before = _captured(monkeypatch, capsys, [name, *BASELINES[command]])
    assert status == 0 and before is not None, err
    instead = INSTEAD.get((name, dest), ())
    baseline = [name, *(w for w in BASELINES[command] if w not in instead)]
    values = [v.format(**files) for v in VALUES.get((name, dest), VALUES.get(dest, ()))] if valued else []
    status, err, after = _captured(monkeypatch, capsys, [*baseline, option, *values])
    if status == 2:  # refused: "not used" and why, or a value this path cannot take, with its fix
        assert option in err and "Fix:" in err, err
        return
    assert status == 0, f"{option} {values}: neither used nor refused as not used:\n{err}"
    assert dest in OUTPUT or after != before, f"{option} was read and dropped: the study is the same"
