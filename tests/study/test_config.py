"""Study files: validation messages (field, value, fix), sweeps, seeds and case keys; nothing is solved."""

import math
import textwrap
from pathlib import Path

import pytest

from roughcontact.study import StudyError, load_study
from roughcontact.study.config import expand

SCAN = Path(__file__).resolve().parents[2] / "src" / "roughcontact" / "data" / "top-1.top"

BASE = """
[study]
name = "check"
seed = 7

[topographies.rough]
generate = "self_affine"
shape = 32
size = "2 um"
hurst = 0.8
rms_height = "1 nm"

[[analysis]]
name = "contact"
model = "normal"
surface = "rough"
material = "polysilicon"
mean_pressure = "20 MPa"
"""


def write(tmp_path, text, name="study.toml"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


def problems(tmp_path, text):
    with pytest.raises(StudyError) as caught:
        load_study(write(tmp_path, text))
    return caught.value.problems, str(caught.value)


def test_a_valid_study_builds_its_cases(tmp_path):
    study = load_study(write(tmp_path, BASE))
    (case,) = study.cases
    assert case.parameters.mean_pressure == 20e6
    assert case.materials["polysilicon"].youngs_modulus == 110e9
    assert study.analyses[0].figures == ("contact", "area_load", "load_approach", "von_mises")
    assert case.topographies["rough"].shape == (32, 32)


def test_wrong_unit_names_field_value_and_fix(tmp_path):
    found, message = problems(tmp_path, BASE.replace('"20 MPa"', '"20 nm"'))
    ((field, problem, fix),) = found
    assert field.endswith("mean_pressure") and "analysis[0] (contact)" in field
    assert "'20 nm'" in problem and "pressure" in problem
    assert "MPa" in fix or "GPa" in fix
    assert "1 problem in the study file" in message


def test_unknown_unit(tmp_path):
    ((field, problem, _),) = problems(tmp_path, BASE.replace('"1 nm"', '"1 nmm"'))[0]
    assert field == "topographies.rough.rms_height"
    assert "nmm" in problem


def test_missing_field_says_what_to_add(tmp_path):
    ((field, problem, fix),) = problems(tmp_path, BASE.replace('material = "polysilicon"\n', ""))[0]
    assert field.endswith(".material")
    assert "missing" in problem and "material = " in fix


def test_unknown_key_suggests_the_close_one(tmp_path):
    ((field, problem, fix),) = problems(tmp_path, BASE.replace("mean_pressure =", "mean_presure ="))[0]
    assert "mean_presure" in field and "not a known key" in problem
    assert "mean_pressure" in fix


def test_unknown_material_lists_known_ones(tmp_path):
    ((field, problem, fix),) = problems(tmp_path, BASE.replace('"polysilicon"', '"polysilicone"'))[0]
    assert field.endswith(".material")
    assert "'polysilicone'" in problem
    assert "did you mean 'polysilicon'" in fix


def test_missing_file_names_the_path(tmp_path):
    text = BASE + '\n[topographies.scan]\nfile = "nowhere/scan.di"\n'
    ((field, problem, fix),) = problems(tmp_path, text)[0]
    assert field == "topographies.scan.file"
    assert "nowhere/scan.di" in problem and "not found" in problem
    assert "relative to the study file" in fix


def test_file_without_size_asks_for_it_in_toml_words(tmp_path):
    rows = (" ".join(str(i * j % 7) for j in range(8)) for i in range(8))
    (tmp_path / "scan.txt").write_text("\n".join(rows))
    text = BASE + '\n[topographies.scan]\nfile = "scan.txt"\n'
    ((field, problem, fix),) = problems(tmp_path, text)[0]
    assert field.startswith("topographies.scan")
    assert "size = " in fix and "--size" not in fix


def test_every_problem_is_reported_at_once(tmp_path):
    text = BASE.replace('"20 MPa"', '"20 MPaa"').replace('"polysilicon"', '"unobtainium"')
    text = text.replace("hurst = 0.8", "hurst = 0.8\nroughness = 3")
    found, message = problems(tmp_path, text)
    fields = [f for f, _, _ in found]
    assert any(f.endswith("mean_pressure") for f in fields)
    assert any(f.endswith("roughness") for f in fields)
    assert "problems in the study file" in message


def test_unknown_model_and_figure(tmp_path):
    found = problems(tmp_path, BASE.replace('model = "normal"', 'model = "normall"'))[0]
    assert "did you mean 'normal'" in found[0][2]
    found = problems(tmp_path, BASE + 'figures = ["contact", "heatmap"]\n')[0]
    assert "heatmap" in found[0][1]


def test_two_load_targets_are_refused(tmp_path):
    ((field, problem, fix),) = problems(tmp_path, BASE + 'force = "1 uN"\n')[0]
    assert "exactly one of mean_pressure, force, approach" in problem


def test_bad_toml_says_where(tmp_path):
    ((field, problem, _),) = problems(tmp_path, BASE + "this is not toml\n")[0]
    assert field == "TOML" and "line" in problem


def test_missing_study_file(tmp_path):
    with pytest.raises(StudyError, match="not found"):
        load_study(tmp_path / "absent.toml")


def test_bad_value_in_one_case_of_a_sweep_names_the_sweep_key_and_a_good_value(tmp_path):
    text = BASE + '[analysis.sweep]\nmean_pressure = ["10 MPa", "20 MPa", "-30 kN"]\n'
    ((field, problem, fix),) = problems(tmp_path, text)[0]
    assert field == "analysis[0] (contact).sweep.mean_pressure" and "-30 kN" in problem
    assert "give a pressure" in fix and "'10 MPa'" in fix  # another value of the sweep as the example


def test_one_typo_is_one_problem_however_many_cases_use_it(tmp_path):
    sweep = '[analysis.sweep]\nmean_pressure = ["10 MPa", "20 MPa"]\n'
    text = BASE.replace("material =", "materail =") + sweep
    found, message = problems(tmp_path, text)
    assert [(f, p, x) for f, p, x in found] == [
        ("analysis[0] (contact).materail", "is not a known key.", "did you mean 'material'?")
    ]
    assert message.count("materail") == 1


def test_a_range_whose_ends_differ_in_kind_says_how_to_write_it(tmp_path):
    text = BASE + '[analysis.sweep]\nmean_pressure = {start = "10 MPa", stop = "40 nm", num = 3}\n'
    ((field, problem, fix),) = problems(tmp_path, text)[0]
    assert field.endswith("sweep.mean_pressure.stop") and "'40 nm'" in problem
    assert fix == "write start and stop in units of one kind, e.g. stop = '40 MPa'."


def test_ranges_and_products():
    rows = expand(
        {
            "force": {"start": "1 uN", "stop": "100 uN", "num": 3, "spacing": "log"},
            "replicate": {"start": 0, "stop": 2, "step": 1},
        },
        {},
        "a",
    )
    assert [r["force"] for r in rows[::3]] == ["1 uN", "10 uN", "100 uN"]
    assert [r["replicate"] for r in rows[:3]] == [0, 1, 2]
    assert len(rows) == 9
    rows = expand({"x": {"start": "1 um", "stop": "2000 nm", "num": 2}}, {"s": ["a", "b"], "t": [1, 2]}, "a")
    assert rows == [
        {"x": "1 um", "s": "a", "t": 1},
        {"x": "1 um", "s": "b", "t": 2},
        {"x": "2 um", "s": "a", "t": 1},
        {"x": "2 um", "s": "b", "t": 2},
    ]


def test_several_zip_tables_are_crossed_with_each_other_and_the_sweep():
    rows = expand({"r": [0, 1]}, [{"s": ["a", "b"], "t": [1, 2]}, {"u": [{"k": 1}, {}]}], "a")
    assert len(rows) == 8
    assert rows[:4] == [
        {"r": 0, "s": "a", "t": 1, "u": {"k": 1}},
        {"r": 0, "s": "a", "t": 1, "u": {}},
        {"r": 0, "s": "b", "t": 2, "u": {"k": 1}},
        {"r": 0, "s": "b", "t": 2, "u": {}},
    ]
    with pytest.raises(Exception, match=r"zip\[1\].*differ in length"):
        expand({}, [{"s": ["a"]}, {"u": [1, 2], "v": [1]}], "a")
    with pytest.raises(Exception, match="both swept and zipped"):
        expand({}, [{"s": ["a"]}, {"s": ["b"]}], "a")


def test_a_study_zips_samples_against_swept_tables_of_readings(tmp_path):
    text = """
[study]
name = "readings per sample"
[topographies.scan]
generate = "paper000_scan"
shape = 32
sample = "Ra 1.45 nm"
[topographies.tip]
generate = "paper000_tip"
shape = 32
seed = 0
[[analysis]]
name = "claims"
model = "friction"
paper000 = true
topography = "scan"
counter_topography = "tip"
[[analysis.zip]]
sample = ["Ra 1.45 nm", "Ra 1.7 nm"]
"topographies.scan.sample" = ["Ra 1.45 nm", "Ra 1.7 nm"]
[[analysis.zip]]
reading = ["default", "default", "paper"]
readings = [{}, {adhesive_range = "all_springs", base = "half_sphere"}, {}]
"""
    path = tmp_path / "study.toml"
    path.write_text(text)
    study = load_study(path)
    cases = study.analyses[0].cases
    assert len(cases) == 6
    assert [c.parameters.readings for c in cases[:3]] == [
        {},
        {"adhesive_range": "all_springs", "base": "half_sphere"},
        {},
    ]
    assert [c.parameters.reading for c in cases[:3]] == ["default", "default", "paper"]
    assert {c.parameters.sample for c in cases[:3]} == {"Ra 1.45 nm"}


@pytest.mark.parametrize(
    ("sweep", "zipped", "words"),
    [
        ({"x": []}, {}, "non-empty list"),
        ({"x": {"start": 1, "stop": 2}}, {}, "one of num or step"),
        ({"x": {"start": "1 uN", "stop": "2 nm", "num": 2}}, {}, "same kind of quantity"),
        ({"x": {"start": 0, "stop": 1, "num": 3, "spacing": "log"}}, {}, "log spacing"),
        ({}, {"a": [1, 2], "b": [1]}, "differ in length"),
        ({"a": [1]}, {"a": [1]}, "both swept and zipped"),
    ],
)
def test_bad_axes(sweep, zipped, words):
    with pytest.raises(Exception, match=words):
        expand(sweep, zipped, "analysis[0]")


def test_derived_seeds_follow_sample_and_replicate_not_load(tmp_path):
    text = BASE + textwrap.dedent(
        """
        [analysis.sweep]
        mean_pressure = ["10 MPa", "20 MPa"]
        replicate = [0, 1]
        """
    )
    cases = load_study(write(tmp_path, text)).cases
    seeds = {(c.parameters.mean_pressure, c.parameters.replicate): c.seeds["rough"] for c in cases}
    assert seeds[(10e6, 0)] == seeds[(20e6, 0)]  # the same surface along a load path
    assert seeds[(10e6, 0)] != seeds[(10e6, 1)]  # another scan per replicate
    assert len({c.key for c in cases}) == 4
    again = load_study(write(tmp_path, text, "again.toml")).cases
    assert [c.key for c in again] == [c.key for c in cases]  # keys are reproducible


def test_fixed_seed_is_kept_and_sweepable(tmp_path):
    text = BASE.replace('rms_height = "1 nm"', 'rms_height = "1 nm"\nseed = 5')
    text += '[analysis.sweep]\n"topographies.rough.seed" = [5, 6]\n'
    cases = load_study(write(tmp_path, text)).cases
    assert [c.seeds["rough"] for c in cases] == [5, 6]
    assert cases[0].axes == {"topographies.rough.seed": 5}


def test_material_overrides_and_sweeps(tmp_path):
    text = BASE.replace('material = "polysilicon"', 'material = "film"') + textwrap.dedent(
        """
        [analysis.sweep]
        "materials.film.youngs_modulus" = ["60 GPa", "80 GPa"]

        [materials.film]
        library = "SiO2"
        poissons_ratio = 0.2
        """
    )
    cases = load_study(write(tmp_path, text)).cases
    assert [c.materials["film"].youngs_modulus for c in cases] == [60e9, 80e9]
    assert all(c.materials["film"].poissons_ratio == 0.2 for c in cases)
    assert cases[0].materials["film"].surface_energy == 72e-3  # the library's, kept


@pytest.mark.parametrize(
    ("table", "words"),
    [
        ('youngs_modulus = "70 GPa"', "poissons_ratio"),
        ('youngs_modulus = "-70 GPa"\npoissons_ratio = 0.2', "youngs_modulus"),
        ('library = "SiO2"\npoissons_ratio = 0.7', "poissons_ratio"),
    ],
)
def test_bad_materials(tmp_path, table, words):
    text = BASE.replace('material = "polysilicon"', 'material = "film"') + f"\n[materials.film]\n{table}\n"
    found, message = problems(tmp_path, text)
    assert words in message


def test_sweeping_an_unknown_table_key(tmp_path):
    found = problems(tmp_path, BASE + '[analysis.sweep]\n"topographies.smooth.hurst" = [0.7]\n')[0]
    assert "topographies.smooth" in found[0][1]


def test_generator_errors(tmp_path):
    found = problems(tmp_path, BASE.replace('"self_affine"', '"self_afine"'))[0]
    assert "self_afine" in found[0][1] and "self_affine" in found[0][2]
    found = problems(tmp_path, BASE.replace("shape = 32", "shape = [32, 32, 32]"))[0]
    assert found[0][0] == "topographies.rough.shape"


def test_profiles_and_rectangles(tmp_path):
    text = BASE.replace("shape = 32", "shape = [64]").replace('size = "2 um"', 'size = "2 um"')
    (case,) = load_study(write(tmp_path, text)).cases
    assert case.topographies["rough"].shape == (64,)
    text = BASE.replace("shape = 32", "shape = [64, 32]").replace('size = "2 um"', 'size = ["2 um", "1 um"]')
    (case,) = load_study(write(tmp_path, text)).cases
    assert case.topographies["rough"].size == (2e-6, 1e-6)


def test_file_topographies_are_read_once_and_hashed(tmp_path):
    text = BASE + f'\n[topographies.scan]\nfile = "{SCAN}"\ndetrend = "plane"\n'
    text += '[[analysis]]\nname = "stats"\nmodel = "statistics"\nsurface = "scan"\n'
    study = load_study(write(tmp_path, text))
    assert list(study.files) == [str(SCAN)]
    assert len(next(iter(study.files.values()))) == 64
    (scan,) = study.loaded.values()
    assert scan.shape == (256, 256) and math.isclose(scan.size[0], 600e-9)
