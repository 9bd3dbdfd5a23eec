"""Each paper's scenario is data in ``roughcontact.papers``, taken by ``paperNNN = true`` and the generators.

The examples and the commands no longer type the papers' numbers; these tests pin that a flag fills
in exactly the paper's values (read back to the same floats), that a key given wins, and that the
generators build the paper's surfaces.
"""

from pathlib import Path

import numpy as np
import pytest

from roughcontact.materials import get_material
from roughcontact.papers import paper000, paper001, paper002
from roughcontact.study.config import StudyError, build_study
from roughcontact.study.inputs import build_topography
from roughcontact.study.schema import GENERATORS
from roughcontact.topography.statistics import ra
from roughcontact.units import quantity, written

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _study(tmp_path, analyses: str, topographies: str):
    text = '[study]\nname = "scenario"\n' + topographies + analyses
    import tomllib

    return build_study(tomllib.loads(text), folder=tmp_path, text=text, source="test")


SCAN = """
[topographies.scan]
generate = "paper000_scan"
shape = 16
sample = "Ra 1.49 nm"

[topographies.tip]
generate = "paper000_tip"
shape = 16
seed = 0
"""


@pytest.mark.parametrize(
    ("value", "unit"),
    [
        (10e-6, "N"),
        (50e-9, "m"),
        (2e-9, "m"),
        (0.05, "J/m^2"),
        (0.072, "J/m^2"),
        (2.805e-6, "m"),
        (6.25e-10, "m^2"),
        (2.13279e-15, "m^2"),
        (1.71036e10, "1/m^2"),
        (6.3e-6, "m"),
        (25e-6, "N"),
    ],
)
def test_written_reads_back_the_same_float(value, unit):
    assert quantity(written(value, unit)) == value


def test_paper000_flag_fills_the_friction_scenario(tmp_path):
    study = _study(
        tmp_path,
        '[[analysis]]\nname = "v"\nmodel = "friction"\npaper000 = true\n'
        'topography = "scan"\ncounter_topography = "tip"\n',
        SCAN,
    )
    parameters = study.cases[0].parameters
    assert (parameters.material, parameters.counter_body) == (paper000.MATERIAL, paper000.TIP_MATERIAL)
    assert parameters.normal_force == paper000.NORMAL_FORCE
    assert (parameters.layer_thickness, parameters.epsilon) == (paper000.LAYER_THICKNESS, paper000.EPSILON)
    assert parameters.surface_energy == paper000.SURFACE_ENERGY
    assert parameters.counter_surface_energy == get_material("SiO2").surface_energy
    assert "paper000" not in parameters.model_dump()  # stored as the keys it fills


def test_a_key_given_wins_and_another_body_keeps_its_own_energy(tmp_path):
    study = _study(
        tmp_path,
        '[[analysis]]\nname = "v"\nmodel = "friction"\npaper000 = true\n'
        'topography = "scan"\nnormal_force = "3 uN"\ncounter_body = "tip2"\n',
        SCAN
        + '[materials.tip2]\nyoungs_modulus = "70 GPa"\npoissons_ratio = 0.2\nsurface_energy = "40 mJ/m^2"\n',
    )
    parameters = study.cases[0].parameters
    assert parameters.normal_force == pytest.approx(3e-6, rel=1e-15)
    assert parameters.counter_body == "tip2" and parameters.counter_surface_energy is None
    assert parameters.surface_energy == paper000.SURFACE_ENERGY  # still paper 000's polysilicon


def test_paper000_generators_build_the_papers_scan_and_tip(tmp_path):
    scan_spec = GENERATORS["paper000_scan"].model_validate(
        {"generate": "paper000_scan", "shape": 16, "sample": "Ra 1.49 nm", "seed": 3}
    )
    scan = build_topography(scan_spec, None)
    assert scan.shape == (16, 16) and scan.size == pytest.approx((16 * paper000.PIXEL,) * 2)
    assert ra(scan) == pytest.approx(paper000.PAPER000_SAMPLES["Ra 1.49 nm"], rel=1e-12)
    assert np.array_equal(scan.heights, paper000.paper000_scan(1.49e-9, shape=16, seed=3).heights)
    tip_spec = GENERATORS["paper000_tip"].model_validate({"generate": "paper000_tip", "shape": 16, "seed": 0})
    assert np.array_equal(build_topography(tip_spec, None).heights, paper000.paper000_tip(shape=16).heights)


def test_paper000_scan_needs_one_roughness(tmp_path):
    with pytest.raises(StudyError, match="exactly one"):
        _study(tmp_path, "", '[topographies.scan]\ngenerate = "paper000_scan"\nshape = 16\n')
    with pytest.raises(StudyError, match="not one of paper 000's"):
        _study(tmp_path, "", '[topographies.scan]\ngenerate = "paper000_scan"\nsample = "Ra 2 nm"\n')


def test_paper001_flag_fills_table1_per_load(tmp_path):
    balls = '[topographies.ball]\ngenerate = "paper001_ball"\nball = "POM"\nshape = 16\n'
    study = _study(
        tmp_path,
        '[[analysis]]\nname = "p"\nmodel = "presliding"\npaper001 = true\n'
        'topography = "ball"\nsample = "POM"\n[analysis.sweep]\nnormal_force = ["25 mN", "75 mN"]\n',
        balls,
    )
    for case, force in zip(study.cases, (0.025, 0.075), strict=True):
        stroke, mu = paper001.table1("POM", force)
        parameters = case.parameters
        assert (parameters.material, parameters.counter_body) == ("POM", paper001.FLAT)
        assert (parameters.stroke, parameters.friction_coefficient) == (stroke, mu)
        assert parameters.radius == paper001.RADIUS
    ball = build_topography(study.cases[0].topographies["ball"], None)
    assert ball.size == pytest.approx((paper001.FIELD,) * 2)


def test_paper001_flag_names_the_missing_ball(tmp_path):
    balls = '[topographies.ball]\ngenerate = "paper001_ball"\nball = "POM"\nshape = 16\n'
    with pytest.raises(StudyError, match="needs the ball"):
        _study(
            tmp_path,
            '[[analysis]]\nname = "p"\nmodel = "presliding"\npaper001 = true\n'
            'topography = "ball"\nnormal_force = "25 mN"\n',
            balls,
        )


def test_paper002_flags_fill_the_asperity_and_island_scenarios(tmp_path):
    island = '[topographies.island]\ngenerate = "paper002_island"\nshape = 16\n'
    study = _study(
        tmp_path,
        '[[analysis]]\nname = "kke"\nmodel = "asperity"\npaper002 = true\n'
        '[[analysis]]\nname = "bem"\nmodel = "load_unload"\npaper002 = true\ntopography = "island"\n',
        island,
    )
    kke, bem = (case.parameters for case in study.cases)
    assert (kke.m0, kke.m2, kke.m4) == (
        paper002.MOMENTS["m0"],
        paper002.MOMENTS["m2"],
        paper002.MOMENTS["m4"],
    )
    assert (kke.material, kke.counter_body) == (paper002.MATERIAL, paper002.PUNCH)
    assert (kke.max_force, kke.reference_force) == (paper002.PEAK_FORCE, paper002.REFERENCE_FORCE)
    assert kke.nominal_area == paper002.ISLAND_SIDE**2 and kke.paper002
    assert (bem.material, bem.substrate) == (paper002.MATERIAL, paper002.SUBSTRATE)
    assert (bem.film_thickness, bem.max_force) == (paper002.FILM_THICKNESS, paper002.PEAK_FORCE)


def test_the_examples_type_no_paper_number():
    """The examples take the papers' scenarios from the flags and generators, not as typed numbers."""
    for name, typed in {
        "paper000.toml": ('"10 uN"', '"50 mJ/m^2"', '"72 mJ/m^2"', '"0.3 nm"', "hurst"),
        "paper001.toml": ('"2.805 um"', "0.153", '"3.17 um"', '"0.98 GPa"', '"5 mm"'),
        "paper002.toml": ('"0.00213279 um^2"', '"6.3 um"', '"625 um^2"'),
    }.items():
        code = "\n".join(line.split("#")[0] for line in (EXAMPLES / name).read_text().splitlines())
        assert not [value for value in typed if value in code], name


@pytest.mark.parametrize(
    "name", sorted(p.name for p in (Path(__file__).parents[2] / "examples").glob("*.toml"))
)
def test_every_example_study_validates(name):
    """Each shipped study (paper002_mesh.toml included) builds all its cases without a problem."""
    from roughcontact.study import load_study

    study = load_study(Path(__file__).parents[2] / "examples" / name)
    assert study.cases and not study.notes
