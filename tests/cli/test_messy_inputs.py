"""Bad and messy inputs (issue 32): each ends in one message naming the field and a fix that works.

Every case runs a command as a user types it and asserts the exit status, that no traceback is
printed, that the message names the field (the option, key or file) and says a fix; then it follows
that fix as written and asserts that the command now succeeds (or, for a warning, that the warning
is gone). Files are the shared instrument files, SurfaceTopography's ``frt-2.frt`` (tests/data) and
text files written here.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest

from roughcontact.cli import main

DATA = Path(__file__).resolve().parents[1] / "data"
POLY = ("--material", "polysilicon")
CORNER = ("--crop", "0 mm", "0.7 mm", "0 mm", "0.7 mm")


@dataclass
class Messy:
    """A command that must fail (or warn) helpfully, and the command with its fix followed."""

    argv: list
    status: int
    field: str
    fix: str
    follow: list | None
    gone: str | None = None  # for a warning: what must no longer be said once the fix is followed
    prepare_follow: object = field(default=None)  # a callable run before the follow-up (e.g. a repaired file)


def _matrix(rows: int = 12, columns: int = 12, seed: int = 1) -> list[str]:
    heights = np.random.default_rng(seed).normal(size=(rows, columns))
    return [" ".join(f"{v:.6f}" for v in row) for row in heights]


def _write(path: Path, lines: list[str]) -> Path:
    path.write_text("\n".join(lines) + "\n")
    return path


def _repair(path: Path, lines: list[str]):
    return lambda: _write(path, lines)


def _duplicate_height_channels(shared: Path, folder: Path) -> Path:
    """di-3.di with its ZSensor channel renamed Height: two channels of one name (as in di-1.di)."""
    content = (shared / "di-3.di").read_bytes()
    old, new = b'S [ZSensor] "Height Sensor"', b'S [Height]  "Height Sensor"'
    assert content.count(old) == 1
    path = folder / "two-heights.di"
    path.write_bytes(content.replace(old, new))
    return path


def _study(
    folder: Path, topography: str, material: str = 'material = "polysilicon"', extra: str = ""
) -> Path:
    text = f"""
[study]
name = "messy"

[topographies.surface]
{topography}

[materials.body]
{material}

[[analysis]]
name = "contact"
model = "normal"
topography = "surface"
material = "body"
mean_pressure = "20 MPa"
{extra}
"""
    path = folder / "study.toml"
    path.write_text(text)
    return path


def cases(shared: Path, tmp: Path) -> dict[str, Messy]:
    top, di3, ibw = shared / "top-1.top", shared / "di-3.di", shared / "spot_1-1000nm.ibw"
    slippy, sur2, opdx = shared / "afm-slippy.txt", shared / "sur-2.sur", shared / "opdx-3.opdx"
    frt2 = DATA / "frt-2.frt"
    inspect_txt = ["inspect", None, "--size", "5 um", "--height-unit", "nm"]

    def with_file(argv, path):
        return [path if item is None else item for item in argv]

    good = _matrix()
    bad_token = list(good)
    bad_token[5] = bad_token[5].replace(bad_token[5].split()[3], "1.2.3", 1)
    bad_first = list(good)
    bad_first[0] = bad_first[0].replace(bad_first[0].split()[2], "n/a", 1)
    short_row = list(good)
    short_row[-1] = " ".join(short_row[-1].split()[:7])
    trailing = [*good, "end of scan"]
    made = {
        name: _write(tmp / f"{name}.txt", lines)
        for name, lines in [
            ("bad_token", bad_token),
            ("bad_first", bad_first),
            ("short_row", short_row),
            ("trailing", trailing),
            ("ragged18", ["1 2 3", "4 5", "6 7 8 9"]),
        ]
    }
    empty = tmp / "empty.top"
    empty.write_bytes(b"")
    sized_only = tmp / "tile.bin"
    sized_only.write_bytes(np.arange(9, dtype=">i2").tobytes())  # 18 bytes: 3 x 3 points of 2 bytes
    two_heights = _duplicate_height_channels(shared, tmp)
    folder_file = tmp / "not-a-folder"
    folder_file.write_text("x")
    other_results = tmp / "other"
    main(["contact", str(top), *POLY, "--pressure", "20 MPa", "-o", str(other_results)])
    contact = ["contact", top, *POLY, "--pressure", "20 MPa"]

    return {
        # --- text files that are not clean tables ------------------------------------------------
        "token that is not a number": Messy(
            with_file(inspect_txt, made["bad_token"]),
            2,
            "bad_token.txt",
            "line 6",
            with_file(inspect_txt, made["bad_token"]),
            prepare_follow=_repair(made["bad_token"], good),
        ),
        "damaged first row": Messy(
            with_file(inspect_txt, made["bad_first"]),
            2,
            "bad_first.txt",
            "line 1",
            with_file(inspect_txt, made["bad_first"]),
            prepare_follow=_repair(made["bad_first"], good),
        ),
        "short last row": Messy(
            with_file(inspect_txt, made["short_row"]),
            2,
            "short_row.txt",
            "7 values",
            with_file(inspect_txt, made["short_row"]),
            prepare_follow=_repair(made["short_row"], good),
        ),
        "text after the data": Messy(
            with_file(inspect_txt, made["trailing"]),
            2,
            "trailing.txt",
            "only comments",
            with_file(inspect_txt, made["trailing"]),
            prepare_follow=_repair(made["trailing"], good),
        ),
        "18-byte ragged file": Messy(
            with_file(inspect_txt, made["ragged18"]),
            2,
            "ragged18.txt",
            "4 or more for a height matrix",
            with_file(inspect_txt, made["ragged18"]),
            prepare_follow=_repair(made["ragged18"], ["1 2 3 4", "5 6 7 8", "9 8 7 6"]),
        ),
        "text that is no table": Messy(
            ["inspect", shared / "nonsense_txt_file.txt"],
            2,
            "nonsense_txt_file.txt",
            "give an instrument file",
            ["inspect", top],
        ),
        "binary taken only by its size": Messy(
            ["inspect", sized_only], 2, "tile.bin", "export it again", ["inspect", top]
        ),
        "broken .npy": Messy(
            ["inspect", shared / "wrongnpyfile.npy"],
            2,
            "wrongnpyfile.npy",
            "export it again",
            ["inspect", top],
        ),
        "corrupted .di": Messy(
            ["inspect", shared / "di_corrupted.di"], 2, "di_corrupted.di", "export it again", ["inspect", di3]
        ),
        "empty file": Messy(["inspect", empty], 2, "empty.top", "export it again", ["inspect", top]),
        "missing file": Messy(
            ["inspect", tmp / "scan.top"], 2, "scan.top", "check the path", ["inspect", top]
        ),
        "folder as file": Messy(
            ["inspect", tmp], 2, str(tmp), "one topography file inside it", ["inspect", top]
        ),
        # --- channels ----------------------------------------------------------------------------------
        "phase channel": Messy(
            [*contact[:1], di3, "--channel", "Phase", *contact[2:]],
            2,
            "--channel",
            "--channel 0",
            [*contact[:1], di3, "--channel", "0", *contact[2:]],
        ),
        "amplitude channel in metres": Messy(
            ["inspect", ibw, "--channel", "AmplitudeTrace"],
            2,
            "--channel",
            "--channel 0",
            ["inspect", ibw, "--channel", "0"],
        ),
        "phase channel in degrees": Messy(
            ["inspect", ibw, "--channel", "PhaseTrace"],
            2,
            "--channel",
            "--channel 1",
            ["inspect", ibw, "--channel", "1"],
        ),
        "two channels of one name": Messy(
            ["inspect", two_heights, "--channel", "Height"],
            2,
            "--channel",
            "--channel 3",
            ["inspect", two_heights, "--channel", "3"],
        ),
        "unknown channel": Messy(
            ["inspect", di3, "--channel", "Topography"],
            2,
            "--channel",
            "--channel 0",
            ["inspect", di3, "--channel", "0"],
        ),
        "channel index out of range": Messy(
            ["inspect", di3, "--channel", "9"],
            2,
            "--channel",
            "--channel 3",
            ["inspect", di3, "--channel", "3"],
        ),
        "misnamed channel read as heights needs its unit": Messy(
            ["inspect", di3, "--channel", "Phase", "--treat-as-height"],
            2,
            "--height-unit",
            "--height-unit",
            ["inspect", di3, "--channel", "Phase", "--treat-as-height", "--height-unit", "nm"],
        ),
        # --- what the file lacks, and values beside the file's own --------------------------------
        "no size in the file": Messy(
            ["inspect", slippy],
            2,
            "--size",
            '--size "5 um"',
            ["inspect", slippy, "--size", "5 um", "--height-unit", "nm"],
        ),
        "no height unit in the file": Messy(
            ["inspect", slippy, "--size", "5 um"],
            2,
            "--height-unit",
            "--height-unit",
            ["inspect", slippy, "--size", "5 um", "--height-unit", "nm"],
        ),
        "size beside the file's": Messy(
            ["inspect", top, "--size", "5 um"],
            2,
            "--size",
            "--override-file-values",
            ["inspect", top, "--size", "5 um", "--override-file-values"],
        ),
        "height unit beside the file's": Messy(
            ["inspect", di3, "--height-unit", "um"],
            2,
            "--height-unit",
            "--override-file-values",
            ["inspect", di3, "--height-unit", "um", "--override-file-values"],
        ),
        "size without a unit": Messy(
            ["inspect", slippy, "--size", "5", "--height-unit", "nm"],
            2,
            "--size",
            "5 um",
            ["inspect", slippy, "--size", "5 um", "--height-unit", "nm"],
        ),
        "size in pascals": Messy(
            ["inspect", slippy, "--size", "5 Pa", "--height-unit", "nm"],
            2,
            "--size",
            "give a length",
            ["inspect", slippy, "--size", "5 um", "--height-unit", "nm"],
        ),
        "crop with three edges": Messy(
            ["inspect", top, "--crop", "0 nm", "300 nm", "0 nm"],
            2,
            "--crop",
            "x0 x1 y0 y1",
            ["inspect", top, "--crop", "0 nm", "300 nm", "0 nm", "300 nm"],
        ),
        "crop outside the scan": Messy(
            ["inspect", top, "--crop", "700 nm", "900 nm", "0 nm", "300 nm"],
            2,
            "--crop",
            "at least 2 grid points",
            ["inspect", top, "--crop", "100 nm", "300 nm", "0 nm", "300 nm"],
        ),
        # --- undefined points, specks and edges -----------------------------------------------------
        "undefined points not filled": Messy(
            ["contact", sur2, *POLY, "--pressure", "20 MPa"],
            2,
            "FILE",
            "--fill-undefined",
            ["inspect", sur2, "--fill-undefined"],
        ),
        "most of the file to be invented": Messy(
            ["inspect", frt2, "--fill-undefined"],
            2,
            "--max-filled",
            "--max-filled 0.28",
            ["inspect", frt2, "--fill-undefined", "--max-filled", "0.28"],
        ),
        "contact on specks": Messy(
            ["contact", frt2, "--fill-undefined", "--max-filled", "0.28", *POLY, "--pressure", "20 MPa"],
            0,
            "specks",
            "--remove-specks",
            [
                "contact",
                frt2,
                "--fill-undefined",
                "--max-filled",
                "0.29",
                "--remove-specks",
                *POLY,
                "--pressure",
                "20 MPa",
            ],
            gone="rests on specks",
        ),
        "contact on filled points": Messy(
            [
                "contact",
                frt2,
                "--fill-undefined",
                "--max-filled",
                "0.29",
                "--remove-specks",
                *POLY,
                "--pressure",
                "200 MPa",
            ],
            0,
            "filled points",
            "--exclude-filled",
            [
                "contact",
                frt2,
                "--fill-undefined",
                "--max-filled",
                "0.29",
                "--remove-specks",
                "--exclude-filled",
                *POLY,
                "--pressure",
                "200 MPa",
            ],
            gone="rests on filled points",
        ),
        # a 0.7 mm corner of the scan (201^2): the same edge load in 5 s, where the whole scan took 30
        "contact at a free window's edge": Messy(
            ["contact", sur2, "--fill-undefined", *CORNER, *POLY, "--pressure", "20 MPa"],
            0,
            "window's edge",
            "--boundary periodic",
            [
                "contact",
                sur2,
                "--fill-undefined",
                *CORNER,
                *POLY,
                "--pressure",
                "20 MPa",
                "--boundary",
                "periodic",
            ],
            gone="window's edge",
        ),
        "unresolved contact area": Messy(
            [*contact[:-1], "0.5 MPa"],
            0,
            "not resolved by the grid",
            "higher load",
            [*contact[:-1], "5 MPa"],
            gone="not resolved by the grid",
        ),
        # --- periodic surfaces and line scans --------------------------------------------------------
        "periodic surface levelled by a plane": Messy(
            ["inspect", top, "--periodic", "--detrend", "plane"],
            2,
            "--detrend",
            "--detrend mean",
            ["inspect", top, "--periodic", "--detrend", "mean"],
        ),
        "free line contact": Messy(
            ["contact", opdx, *POLY, "--pressure", "20 MPa", "--boundary", "free"],
            2,
            "--boundary",
            "--boundary periodic",
            ["contact", opdx, *POLY, "--pressure", "20 MPa", "--boundary", "periodic"],
        ),
        # --- loads and materials -------------------------------------------------------------------
        "force that no scan carries": Messy(
            [*contact[:-2], "--force", "100 N"],
            2,
            "--force",
            "check the load's unit",
            [*contact[:-2], "--force", "100 uN"],
        ),
        "pressure above the hardness": Messy(
            [*contact, "--hardness", "15 MPa"],
            2,
            "--pressure",
            "lower the load",
            [*contact[:-1], "10 MPa", "--hardness", "15 MPa"],
        ),
        "pressure without a unit": Messy([*contact[:-1], "20"], 2, "--pressure", "20 MPa", contact),
        "pressure as a length": Messy([*contact[:-1], "20 nm"], 2, "--pressure", "give a pressure", contact),
        "two loads": Messy(
            [*contact, "--force", "1 uN"], 2, "--pressure, --force", "--pressure '20 MPa'", contact
        ),
        "no load": Messy(contact[:-2], 2, "--pressure", "'20 MPa'", contact),
        "unknown material": Messy(
            ["contact", top, "--material", "polysilicone", "--pressure", "20 MPa"],
            2,
            "--material",
            "'polysilicon'",
            contact,
        ),
        "negative modulus and a Poisson's ratio of 0.6": Messy(
            [
                "contact",
                top,
                "--material-youngs-modulus",
                "-70 GPa",
                "--material-poissons-ratio",
                "0.6",
                "--pressure",
                "20 MPa",
            ],
            2,
            "2 problems",
            "(-1, 0.5]",
            [
                "contact",
                top,
                "--material-youngs-modulus",
                "70 GPa",
                "--material-poissons-ratio",
                "0.3",
                "--pressure",
                "20 MPa",
            ],
        ),
        # --- outputs ---------------------------------------------------------------------------------
        "-o names a file": Messy(
            [*contact, "-o", folder_file],
            2,
            "-o/--output",
            "give a folder",
            [*contact, "-o", tmp / "results"],
        ),
        "-o inside a file": Messy(
            [*contact, "-o", folder_file / "sub"],
            2,
            "-o/--output",
            "give a folder",
            [*contact, "-o", tmp / "results-2"],
        ),
        "dpi of zero": Messy(
            [*contact, "-o", tmp / "d0", "--dpi", "0"],
            2,
            "--dpi",
            "300",
            [*contact, "-o", tmp / "d0", "--dpi", "300"],
        ),
        "figure file that is not a figure": Messy(
            ["plot", top, "-o", tmp / "scan.xyz"],
            2,
            "-o/--output",
            ".png",
            ["plot", top, "-o", tmp / "scan.png"],
        ),
        "plot without -o": Messy(
            ["plot", top], 2, "-o/--output", "-o FIGURE.png", ["plot", top, "-o", tmp / "s.png"]
        ),
        "-o of another command's results": Messy(
            ["contact", top, *POLY, "--pressure", "30 MPa", "-o", other_results],
            2,
            "-o/--output",
            "--overwrite",
            ["contact", top, *POLY, "--pressure", "30 MPa", "-o", other_results, "--overwrite"],
        ),
        # --- two bodies ------------------------------------------------------------------------------
        "merged scans of different grids": Messy(
            [
                "friction",
                top,
                di3,
                *POLY,
                "--surface-energy",
                "50 mJ/m^2",
                "--counter-surface-energy",
                "50 mJ/m^2",
                "--normal-forces",
                "1 uN",
            ],
            2,
            "COUNTER_FILE",
            "--resample",
            [
                "friction",
                top,
                di3,
                *POLY,
                "--surface-energy",
                "50 mJ/m^2",
                "--counter-surface-energy",
                "50 mJ/m^2",
                "--normal-forces",
                "1 uN",
                "--resample",
            ],
        ),
        "no surface energy for paper 000's model": Messy(
            ["friction", top, *POLY, "--normal-forces", "1 uN"],
            2,
            "--surface-energy",
            "surface energy",
            [
                "friction",
                top,
                *POLY,
                "--surface-energy",
                "50 mJ/m^2",
                "--counter-surface-energy",
                "50 mJ/m^2",
                "--normal-forces",
                "1 uN",
            ],
        ),
        # --- adhesion --------------------------------------------------------------------------------
        "adhesion programme that never touches": Messy(
            [
                "adhesion",
                top,
                *POLY,
                "--work-of-adhesion",
                "100 mJ/m^2",
                "--law",
                "exp",
                "--range",
                "1 nm",
                "--start",
                "-20 nm",
                "--max-approach",
                "-10 nm",
                "--steps",
                "8",
                "--json",
            ],
            0,
            "never touch",
            "positive --max-approach",
            [
                "adhesion",
                top,
                *POLY,
                "--work-of-adhesion",
                "100 mJ/m^2",
                "--law",
                "exp",
                "--range",
                "1 nm",
                "--start",
                "-5 nm",
                "--max-approach",
                "2 nm",
                "--steps",
                "8",
                "--json",
            ],
            gone="never touch",
        ),
    }


def _run(capsys, argv) -> tuple[int, str, str]:
    try:
        status = main([str(a) for a in argv])
    except SystemExit as exit:  # the option parser's own errors
        status = exit.code
    captured = capsys.readouterr()
    return status, captured.out, captured.err


@pytest.fixture(scope="module")
def messy(shared_topographies, tmp_path_factory):
    return cases(shared_topographies, tmp_path_factory.mktemp("messy"))


def _names() -> list[str]:
    import inspect
    import re

    source = inspect.getsource(cases)
    return re.findall(r'^        "([^"]+)": Messy\(', source, flags=re.MULTILINE)


@pytest.mark.parametrize("name", _names())
def test_a_messy_input_is_refused_or_flagged_with_a_fix_that_works(messy, capsys, name):
    case = messy[name]
    status, out, err = _run(capsys, case.argv)
    said = out + err
    assert "Traceback" not in said and "internal error" not in said
    assert status == case.status, said
    assert case.field in err, err
    assert case.fix in err, err
    if case.status:
        assert "Fix:" in err
    if case.prepare_follow is not None:
        case.prepare_follow()
    status, out, err = _run(capsys, case.follow)
    assert status == 0, out + err
    assert "Traceback" not in out + err
    if case.gone is not None:
        assert case.gone not in err, err


def test_there_are_at_least_forty_of_them():
    assert len(_names()) >= 40


# --- study files: validate says what run would, all at once -------------------------------------


@pytest.mark.parametrize(
    ("topography", "material", "extra", "field", "fix", "topography_fixed", "material_fixed"),
    [
        (
            'generate = "self_affine"\nshape = 32\nsize = "1 um"\nhurst = 1.8\nrms_height = "1 nm"',
            'library = "polysilicon"',
            "",
            "topographies.surface.hurst",
            "0 < hurst <= 1",
            'generate = "self_affine"\nshape = 32\nsize = "1 um"\nhurst = 0.8\nrms_height = "1 nm"',
            None,
        ),
        (
            'generate = "sphere"\nshape = 32\nsize = "1 mm"\nradius = "0.1 mm"',
            'library = "polysilicon"',
            "",
            "topographies.surface.radius",
            "kind='paraboloid'",
            'generate = "sphere"\nshape = 32\nsize = "1 mm"\nradius = "0.1 mm"\nkind = "paraboloid"',
            None,
        ),
        (
            'generate = "sinusoid"\nshape = 32\nsize = "1 um"\namplitude = "1 nm"\nwavelength = "1 um"',
            'youngs_modulus = "-70 GPa"\npoissons_ratio = 0.6',
            "",
            "materials.body.poissons_ratio",
            "(-1, 0.5]",
            None,
            'youngs_modulus = "70 GPa"\npoissons_ratio = 0.3',
        ),
        (
            'file = "{top}"\nperiodic = true\ndetrend = "plane"',
            'library = "polysilicon"',
            "",
            "topographies.surface",
            'detrend = "mean"',
            'file = "{top}"\nperiodic = true\ndetrend = "mean"',
            None,
        ),
        (
            'file = "{top}"\nsize = "5 um"',
            'library = "polysilicon"',
            "",
            "topographies.surface",
            "override_file_values = true",
            'file = "{top}"\nsize = "5 um"\noverride_file_values = true',
            None,
        ),
        (
            'file = "{di3}"\nchannel = "Phase"',
            'library = "polysilicon"',
            "",
            "topographies.surface",
            "channel = 0",
            'file = "{di3}"\nchannel = 0',
            None,
        ),
        (
            'file = "{top}"',
            'library = "polysilicon"',
            'hardness = "15 MPa"',
            "hardness 15 MPa",
            "lower the load",
            None,
            None,
        ),
    ],
    ids=["hurst", "sphere", "material", "periodic-plane", "size", "channel", "capacity"],
)
def test_validate_refuses_what_run_would_with_every_problem(
    shared_topographies,
    tmp_path,
    capsys,
    topography,
    material,
    extra,
    field,
    fix,
    topography_fixed,
    material_fixed,
):
    files = {"top": shared_topographies / "top-1.top", "di3": shared_topographies / "di-3.di"}
    path = _study(tmp_path, topography.format(**files), material, extra)
    status, _, err = _run(capsys, ["validate", path])
    assert status == 2 and field in err and fix in err and "Traceback" not in err
    if material_fixed is not None and "-70 GPa" in material:
        assert "2 problems" in err or "youngs_modulus" in err  # both problems of the material at once
        assert "materials.body.youngs_modulus" in err
    path = _study(
        tmp_path,
        (topography_fixed or topography).format(**files),
        material_fixed or material,
        "" if extra and topography_fixed is None and material_fixed is None else extra,
    )
    status, out, err = _run(capsys, ["validate", path])
    assert status == 0, err


def test_every_summary_names_the_channel_used(shared_topographies, tmp_path, capsys):
    two = _duplicate_height_channels(shared_topographies, tmp_path)
    status, out, err = _run(capsys, ["contact", two, *POLY, "--pressure", "20 MPa"])
    assert status == 0
    assert "channel 'Height' (index 0; index 3 has the same name)" in out
    status, out, _ = _run(capsys, ["contact", two, *POLY, "--pressure", "20 MPa", "--json"])
    document = json.loads(out)
    assert document["topographies"]["surface"]["channel"] == {
        "name": "Height",
        "index": 0,
        "shares_name_with": [3],
    }
    status, out, _ = _run(capsys, ["inspect", two, "--json"])
    description = json.loads(out)
    assert description["channel"]["index"] == 0
    assert [c["holds_heights"] for c in description["channels"]] == [True, False, False, True]
    status, out, _ = _run(capsys, ["contact", two, *POLY, "--pressure", "20 MPa", "-o", tmp_path / "out"])
    provenance = json.loads((tmp_path / "out" / "provenance.json").read_text())
    assert provenance["topographies"]["surface"]["channel"]["index"] == 0
    assert "channel &#x27;Height&#x27; (index 0" in (tmp_path / "out" / "report.html").read_text()


@pytest.mark.parametrize(
    ("argv", "field", "words"),
    [
        (["--max-filled", "2", "--fill-undefined"], "--max-filled", "a fraction from 0 to 1"),
        (["--approach", "1 m"], "--approach", "its own size or more"),
        (["--pressure", "20 MPa", "--hardness", "-1 GPa"], "--hardness", "must be positive"),
        (["--pressure", "20 MPa", "--stress-depths", "-5 nm"], "--stress-depths", "at least 0"),
    ],
)
def test_more_values_no_model_can_take(shared_topographies, capsys, argv, field, words):
    status, out, err = _run(capsys, ["contact", shared_topographies / "top-1.top", *POLY, *argv])
    assert status == 2 and field in err and words in err and "Traceback" not in out + err


def test_a_binary_file_given_as_a_study_or_a_table(shared_topographies, capsys):
    top = shared_topographies / "top-1.top"
    for argv in (["validate", top], ["loop-analysis", top, "--normal-force", "25 mN"]):
        status, out, err = _run(capsys, argv)
        assert status == 2 and "binary file" in err and "internal error" not in err
