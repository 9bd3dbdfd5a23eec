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
DATA = ROOT / "tests" / "data"
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


def _unit_files(folder: Path) -> dict[str, Path]:
    """Files whose columns carry no unit, or a wrong one, each beside the file that follows the fix.

    The loops are examples/paper001_measured_loop.csv (um, mN) written in nm and N; the indentation
    curves examples/paper001_indentation_hdpe.csv (nm, mN) with other header units; the points
    tests/data/csv-1.csv (``X_(microns),y1``) with a header without units.
    """
    loop = EXAMPLES / "paper001_measured_loop.csv"
    rows = [line.split(",") for line in loop.read_text().splitlines() if line and line[0].isdigit()]
    nm_newton = "".join(f"{float(r[2]) * 1e3:.6g},{float(r[3]) * 1e-3:.6g}\n" for r in rows)
    curve = (EXAMPLES / "paper001_indentation_hdpe.csv").read_text()
    points = (DATA / "csv-1.csv").read_text().splitlines()[1:]
    texts = {
        "loop_bare.csv": nm_newton,
        "loop_plain.csv": "displacement,force\n" + nm_newton,
        "loop_nm_N.csv": "# origin: synthetic\ndisplacement [nm],force [N]\n" + nm_newton,
        "curve_m.csv": curve.replace("depth (nm)", "depth (m)"),
        "curve_kN.csv": curve.replace("load (mN)", "load (kN)"),
        "points.csv": "\n".join(["x,z", *points]) + "\n",
        "measured_plain.csv": "interference,force\n0,25e-6\n2e-8,3e-4\n5e-8,1e-3\n",
        "measured.csv": "interference [m],force [N]\n0,25e-6\n2e-8,3e-4\n5e-8,1e-3\n",
    }
    files = {name: folder / name for name in texts}
    for name, text in texts.items():
        files[name].write_text(text)
    study = "[study]\nname = 'units'\n\n"
    loop_analysis = (
        "[[analysis]]\nname = 'loop'\nmodel = 'loop_analysis'\nloop = 'loop_nm_N.csv'\n"
        "normal_force = '25 mN'\n"
    )
    statistics = "[[analysis]]\nname = 'stats'\nmodel = 'statistics'\ntopography = 'a'\n"
    documents = {
        "loop_typed.toml": study + loop_analysis + "force_unit = 'mN'\n",
        "loop_header.toml": study + loop_analysis,
        "points_size.toml": study + "[topographies.a]\nfile = 'points.csv'\nsize = '0.3 um'\n"
        "height_unit = 'um'\n\n" + statistics,
        "points_unit.toml": study + "[topographies.a]\nfile = 'points.csv'\nposition_unit = 'um'\n"
        "height_unit = 'um'\n\n" + statistics,
    }
    for name, text in documents.items():
        files[name] = folder / name
        files[name].write_text(text)
    return files


def _plausibility_files(folder: Path) -> dict[str, Path]:
    """Surfaces whose numbers cannot be right (issue 45, part 4), each beside the one that follows the fix.

    ``huge``: a 32 x 32 height matrix (nm) with one token 1e300; ``holed``: the same with that token
    written as NaN. ``flat``: every height 3 nm; ``ramp``: a tilted profile (a sawtooth when repeated).
    ``tall``: heights of about 1000 (nm, read as Em by mistake). ``scan``: a self-affine 64 x 64 map of
    30 nm rms (a size of 160 m is the nms-1.nms of the issue). Study files read ``huge``, ``holed`` and
    ``flat``.
    """
    rough = np.random.default_rng(3).normal(size=(32, 32))
    arrays = {"huge": rough.copy(), "holed": rough.copy(), "flat": np.full((32, 32), 3.0)}
    arrays["huge"][5, 7], arrays["holed"][5, 7] = 1e300, np.nan
    arrays["ramp"] = np.arange(64.0) * 1e-3
    arrays["tall"] = 1e3 * rough
    arrays["scan"] = rc.generate.self_affine((64, 64), 1e-6, hurst=0.8, rms_height=3e-8, seed=5).heights * 1e9
    files = {name: folder / f"{name}.txt" for name in arrays}
    for name, heights in arrays.items():
        np.savetxt(files[name], heights)
    surface = '[topographies.a]\nfile = "{}.txt"\nsize = "1 um"\nheight_unit = "nm"\n{}'
    files["huge.toml"] = _study(folder, surface.format("huge", ""), name="huge.toml")
    files["holed.toml"] = _study(
        folder, surface.format("holed", "fill_undefined = true\n"), name="holed.toml"
    )
    for name, load in (("flat_approach", "approach = '1 nm'"), ("flat_load", "mean_pressure = '10 MPa'")):
        path = _study(folder, surface.format("flat", ""), 'boundary = "periodic"', f"{name}.toml")
        path.write_text(path.read_text().replace('mean_pressure = "10 MPa"', load))
        files[f"{name}.toml"] = path
    return files


def _cases(folder: Path) -> dict[str, Bad]:
    files = _plausibility_files(folder)
    unit = ("--size", "1 um", "--height-unit", "nm")
    filled = (*unit, "--fill-undefined")
    overflow = "(grid point 7, 5) is 1e+300 nm in the file, 1e+291 m, beyond 1e+100 m"
    said = "write it as NaN and add --fill-undefined"
    friction = (*POLY, "--surface-energy", "50 mJ/m^2", "--normal-forces", "1 uN")
    adhesion = (*POLY, "--surface-energy", "50 mJ/m^2", "--range", "1 nm", "--max-approach", "3 nm")
    periodic_flat = ("contact", files["flat"], *unit, *POLY, "--boundary", "periodic")
    profile = ("contact", files["ramp"], "--size", "1 um", "--height-unit", "um", "--detrend", "none", *POLY)
    units = _unit_files(folder)
    loop = ["loop-analysis", "--normal-force", "25 mN"]
    csv1 = DATA / "csv-1.csv"
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
        "a height of 1e300 in a matrix passed inspect (statistics of 1e288 m)": Bad(
            ["inspect", files["huge"], *unit], 2, overflow, said, ["inspect", files["holed"], *filled]
        ),
        "a height of 1e300 passed plot": Bad(
            ["plot", files["huge"], *unit, "-o", folder / "huge.png"],
            2,
            str(files["huge"]),
            said,
            ["plot", files["holed"], *filled, "-o", folder / "holed.png"],
        ),
        "a height of 1e300 gave an approach of 1e290 m and exit 0 in contact": Bad(
            ["contact", files["huge"], *unit, *POLY, "--pressure", "20 MPa"],
            2,
            overflow,
            said,
            ["contact", files["holed"], *filled, *POLY, "--pressure", "20 MPa"],
        ),
        "a height of 1e300 passed friction": Bad(
            ["friction", files["huge"], *unit, *friction],
            2,
            overflow,
            said,
            ["friction", files["holed"], *filled, *friction],
        ),
        "a height of 1e300 passed adhesion": Bad(
            ["adhesion", files["huge"], *unit, *adhesion],
            2,
            overflow,
            said,
            ["adhesion", files["holed"], *filled, *adhesion],
        ),
        "a height of 1e300 passed validate": Bad(
            ["validate", files["huge.toml"]],
            2,
            "topographies.a (",
            "write it as NaN and add fill_undefined = true",
            ["validate", files["holed.toml"]],
        ),
        "a height of 1e300 passed run": Bad(
            ["run", files["huge.toml"], "-o", folder / "huge_run"],
            2,
            overflow,
            "fill_undefined = true",
            ["run", files["holed.toml"], "-o", folder / "holed_run"],
        ),
        "an approach on a periodic flat did not converge and blamed noise": Bad(
            [*periodic_flat, "--approach", "1 nm"],
            2,
            "--approach",
            "give the load instead (--pressure or --force)",
            [*periodic_flat, "--pressure", "20 MPa"],
        ),
        "a periodic approach on a flat passed validate and failed at run": Bad(
            ["validate", files["flat_approach.toml"]],
            2,
            "a periodic flat surface carries any mean pressure at approach 0",
            "give the load instead (mean_pressure or force)",
            ["run", files["flat_load.toml"], "-o", folder / "flat_run"],
        ),
        "a tilted profile pressed past half its height did not converge and blamed noise": Bad(
            [*profile, "--approach", "40 nm"],
            2,
            "is not reached: a periodic surface is in full contact at its mean separation 31.5 nm",
            "or an approach below the mean separation",
            [*profile, "--approach", "20 nm"],
        ),
        "heights of 1e21 m (a wrong height unit) filled stderr with numpy overflow warnings": Bad(
            [
                "contact",
                files["tall"],
                "--size",
                "1 um",
                "--height-unit",
                "Em",
                *POLY,
                "--pressure",
                "20 MPa",
            ],
            2,
            "overflow the solver's single-precision arithmetic",
            "check the height unit",
            ["contact", files["tall"], *unit, *POLY, "--pressure", "20 MPa"],
        ),
        "a scan of 160 m did not converge and was told to loosen its tolerance": Bad(
            [
                "contact",
                files["scan"],
                "--size",
                "160 m",
                "--height-unit",
                "nm",
                *POLY,
                "--pressure",
                "20 MPa",
            ],
            3,
            "the scan is 160 m x 160 m, outside 1 nm to 1 m (implausible)",
            "check the scan's size and height unit",
            [
                "contact",
                files["scan"],
                "--size",
                "160 um",
                "--height-unit",
                "nm",
                *POLY,
                "--pressure",
                "20 MPa",
            ],
        ),
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
        "a loop without a header was read as um and mN (mu 0.000153 for nm and N)": Bad(
            [*loop, units["loop_bare.csv"]],
            2,
            "--displacement-unit",
            "--displacement-unit um --force-unit mN",
            [*loop, units["loop_bare.csv"], "--displacement-unit", "nm", "--force-unit", "N"],
        ),
        "a loop whose header gives no units was read as um and mN": Bad(
            [*loop, units["loop_plain.csv"]],
            2,
            "the header cells 'displacement' and 'force' of loop_plain.csv have no unit",
            "write the units in the header, e.g. 'displacement [um]', 'force [mN]'",
            [*loop, units["loop_plain.csv"], "--displacement-unit", "nm", "--force-unit", "N"],
        ),
        "a loop given one unit of two names the other column": Bad(
            [*loop, units["loop_plain.csv"], "--displacement-unit", "nm"],
            2,
            "--force-unit",
            "or give the unit the values are in, e.g. --force-unit mN.",
            [*loop, units["loop_plain.csv"], "--displacement-unit", "nm", "--force-unit", "N"],
        ),
        "a typed force unit that contradicts the header 'force [N]' names the header cell": Bad(
            [*loop, units["loop_nm_N.csv"], "--force-unit", "mN"],
            2,
            "'mN' contradicts the header cell 'force [N]' of loop_nm_N.csv, which gives [N]",
            "leave --force-unit out: the column is read in N, as its header says",
            [*loop, units["loop_nm_N.csv"]],  # a correct 'force [N]' header needs no option
        ),
        "a study's force_unit that contradicts the loop's header is refused at validate": Bad(
            ["validate", units["loop_typed.toml"]],
            2,
            "analysis[0] (loop).force_unit",
            "remove force_unit: the column is read in N, as its header says",
            ["run", units["loop_header.toml"], "-o", folder / "loop"],
        ),
        "an indentation depth in nm labelled m gave 3 km and E 967 pPa": Bad(
            ["nanoindent", units["curve_m.csv"]],
            2,
            "reaches 3.004 km, above what an indentation reaches",
            "check the unit of the depth column: correct its header cell 'depth (m)'",
            ["nanoindent", EXAMPLES / "paper001_indentation_hdpe.csv"],
        ),
        "an indentation load in kN is refused": Bad(
            ["nanoindent", units["curve_kN.csv"]],
            2,
            "the load column of curve_kN.csv, read in the unit of its header cell 'load (kN)', reaches 10 kN",
            "check the unit of the load column",
            ["nanoindent", EXAMPLES / "paper001_indentation_hdpe.csv"],
        ),
        "a depth unit that contradicts the indentation header no longer overrides it": Bad(
            ["nanoindent", EXAMPLES / "paper001_indentation_hdpe.csv", "--depth-unit", "um"],
            2,
            "--depth-unit: 'um' contradicts the header cell 'depth (nm)'",
            "leave --depth-unit out",
            ["nanoindent", EXAMPLES / "paper001_indentation_hdpe.csv"],
        ),
        "csv-1.csv's positions in microns give its size: only its heights need a unit": Bad(
            ["inspect", csv1],
            2,
            "--height-unit",
            "--height-unit nm",
            ["inspect", csv1, "--height-unit", "um"],
        ),
        "a --size beside csv-1.csv's positions was accepted (any size went)": Bad(
            ["inspect", csv1, "--size", "0.2703 um", "--height-unit", "um"],
            2,
            "its header cell 'X_(microns)'), 8 points 38.61 nm apart: a size of 8 x 38.61 nm = 308.9 nm",
            "leave --size out: the positions give the size, 308.9 nm.",
            ["inspect", csv1, "--height-unit", "um"],
        ),
        "positions without a unit: the hint said the x range, a pixel 12.5 % too small": Bad(
            ["inspect", units["points.csv"], "--height-unit", "um"],
            2,
            "8 points 0.03861 apart: a size of 8 x 0.03861 = 0.3089 in a unit the file does not name",
            "--position-unit um; positions in um make a size of 308.9 nm",
            ["inspect", units["points.csv"], "--height-unit", "um", "--position-unit", "um"],
        ),
        "a --size beside positions without a unit asks for their unit instead": Bad(
            ["inspect", units["points.csv"], "--height-unit", "um", "--size", "0.2703 um"],
            2,
            "--size",
            "leave --size out and give the positions' unit: --position-unit um",
            ["inspect", units["points.csv"], "--height-unit", "um", "--position-unit", "um"],
        ),
        "a --position-unit that contradicts the header cell 'X_(microns)'": Bad(
            ["inspect", csv1, "--height-unit", "um", "--position-unit", "nm"],
            2,
            "gives its positions in 'microns' (its header cell 'X_(microns)')",
            "leave --position-unit out to use the file's 'microns'",
            ["inspect", csv1, "--height-unit", "um", "--position-unit", "um"],
        ),
        "a --position-unit for a height matrix": Bad(
            ["inspect", DATA / "txt_example.txt", "--position-unit", "um"],
            2,
            "--position-unit: txt_example.txt holds a grid of heights",
            "leave --position-unit out",
            ["inspect", DATA / "txt_example.txt"],
        ),
        "a study's size beside a file's positions is refused at validate": Bad(
            ["validate", units["points_size.toml"]],
            2,
            "topographies.a (size)",
            'remove size and give the positions\' unit: position_unit = "um"',
            ["validate", units["points_unit.toml"]],
        ),
        "a measured load curve without units was read as m and N, and failed only after the run": Bad(
            ["asperity", "--paper002", "--steps", "4", "--measured", units["measured_plain.csv"]],
            2,
            "--measured: the header cells 'interference' and 'force' give no unit in measured_plain.csv",
            "write the unit of each column in its header cell, e.g. 'interference [nm],load [uN]'",
            [
                "asperity",
                "--paper002",
                "--steps",
                "4",
                "--measured",
                units["measured.csv"],
                "-o",
                folder / "asp",
            ],
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


# --- a loop in nm and N: the analysis of what the file holds, called what its header says ---------------


def test_a_loop_in_nm_and_newtons_gives_the_papers_mu_and_says_it_is_synthetic(capsys, tmp_path):
    import json

    files = _unit_files(tmp_path)
    for argv in (
        [files["loop_nm_N.csv"]],  # its header's units
        [files["loop_bare.csv"], "--displacement-unit", "nm", "--force-unit", "N"],  # typed
    ):
        status, out, err = _run(capsys, ["loop-analysis", *argv, "--normal-force", "25 mN", "--json"])
        assert status == 0, err
        (analysis,) = json.loads(out)["analyses"]
        assert analysis["cases"][0]["scalars"]["mu"] == pytest.approx(0.153, rel=5e-3)  # not 0.000153
    (row,) = analysis["tables"]["loop"]
    assert row["loop"] == "measured: loop_bare.csv"  # no '# origin:' line: measured, as its file says
    status, out, err = _run(capsys, ["loop-analysis", files["loop_nm_N.csv"], "--normal-force", "25 mN"])
    assert status == 0, err
    assert "synthetic: loop_nm_N.csv" in out
    assert "note: The loop loop_nm_N.csv is synthetic (its '# origin:' line says so)" in out
