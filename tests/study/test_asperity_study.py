"""The ``asperity`` and ``load_unload`` study kinds (paper 002) and the example study examples/paper002.toml.

* end to end: the example through the CLI at a reduced size (a 32^2 island, two replicates, five
  load steps, a short KKE curve) with a measured curve added, its results table, the section IV
  table against the paper's printed numbers, the combined KKE + BEM figure and the report;
* the kinds' scalars against direct calls of the models on the same inputs
  (``asperity_parameters`` on a generated surface's moments, ``compress_island`` on the same
  synthetic island);
* validation errors (surface and moments both given, neither, a negative m0) naming the field.
"""

from __future__ import annotations

import csv

import numpy as np
import pytest

from roughcontact.asperity.comparison import against_realisations
from roughcontact.asperity.parameters import asperity_parameters
from roughcontact.materials import get_material
from roughcontact.papers.paper002 import compress_island, paper002_island
from roughcontact.study import load_study
from roughcontact.study.config import StudyError
from roughcontact.study.inputs import CaseInputs
from roughcontact.study.kinds import get_kind
from roughcontact.study.outputs import context, read_study
from roughcontact.study.schema import GaussianRandom, Paper002Island
from roughcontact.study.store import notes_of, read_table
from roughcontact.topography.statistics import spectral_moments

SU8, DIAMOND, SILICON = (get_material(n) for n in ("SU-8", "diamond flat tip", "silicon wafer"))
MATERIALS = {"SU-8": SU8, "diamond flat tip": DIAMOND, "silicon wafer": SILICON}
REDUCED = {
    "shape = 384": "shape = 32",
    "shape = 128": "shape = 64",
    "layers = 16": "layers = 8",
    "steps = 40": "steps = 8",
    "load_steps = 10": "load_steps = 5",
    "realisations = 5                # five realisations of the synthetic": "realisations = 2 #",
    "realisations = 5                # five realisations of the island": "realisations = 1 #",
    "# [analysis.compare]\n# measured_curve": "[analysis.compare]\nmeasured_curve",
}
# Section IV of paper 002 as printed (eqs. 4, 5, 6, 9); the standard E' reproduces them.
PRINTED = {
    "summit_radius": 5.08e-6,
    "summit_height_std": 0.0431e-6,
    "critical_interference": 0.0125e-6,
    "plasticity_index": 1.86,
}


def _rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def test_example_end_to_end_reproduces_section_iv_and_draws_kke_against_bem(cli, shrunk, tmp_path):
    study = shrunk("paper002.toml", tmp_path, REDUCED)
    # A made-up measured curve (the paper's is not published): it must appear in the combined figure.
    (tmp_path / "paper002_measured_curve.csv").write_text(
        "interference_m,force_N\n0,25e-6\n2e-8,3e-4\n4e-8,8e-4\n"
    )
    out = tmp_path / "out"
    status, printed, err = cli("run", study, "-o", out, "--no-progress")
    assert status == 0, err

    rows = _rows(out / "results.csv")
    analyses = [("kke", "done"), ("bem", "done"), ("bem", "done"), ("bem_volume", "done")]
    assert [(r["analysis"], r["status"]) for r in rows] == analyses
    kke, bem, volume = rows[0], rows[1:3], rows[3]
    omega_c = float(kke["critical_interference [m]"])
    for name in ("peak_interference", "interference_at_return_force"):
        assert float(kke[f"{name}_over_omega_c"]) == pytest.approx(
            float(kke[f"{name} [m]"]) / omega_c, rel=1e-12
        )
    assert float(kke["peak_force [N]"]) == pytest.approx(1000e-6, rel=1e-9)
    # loading then elastic recovery: back at 25 uN the interference lies below the peak one
    assert 0 < float(kke["interference_at_return_force [m]"]) < float(kke["peak_interference [m]"])
    assert float(kke["return_force [N]"]) == pytest.approx(25e-6, rel=1e-12)
    assert kke["residual_interference [m]"] == ""  # one name, one meaning: KKE has no zero-load residual
    for row in bem:
        assert float(row["peak_force [N]"]) == pytest.approx(1000e-6, rel=1e-6)
        assert float(row["residual_interference [m]"]) < float(row["peak_interference [m]"])
        # the BEM's residual is at zero load, below (or at) its interference back at 25 uN
        assert float(row["residual_interference [m]"]) <= float(row["interference_at_return_force [m]"])
        assert float(row["max_pressure [Pa]"]) <= SU8.hardness
    # the two replicates are two realisations of the island (derived seeds)
    assert bem[0]["peak_interference [m]"] != bem[1]["peak_interference [m]"]
    # KKE against the BEM's realisations: for one island (the paper's claim), the mean beside it
    against = read_table(out / "tables" / "bem_against_statistical.csv")
    assert [(r["quantity"], r["judged for"]) for r in against] == [
        ("peak_interference", "one island (prediction interval)"),
        ("peak_interference", "the mean (confidence interval)"),
        ("interference_at_return_force", "one island (prediction interval)"),
        ("interference_at_return_force", "the mean (confidence interval)"),
    ]
    one, mean = against[0], against[1]
    peaks = [float(row["peak_interference [m]"]) for row in bem]
    peak = float(kke["peak_interference [m]"])
    found = against_realisations(peak, peaks, quantity="peak_interference")
    assert float(one["bem mean [m]"]) == pytest.approx(np.mean(peaks), rel=1e-12)
    assert float(one["statistical [m]"]) == peak
    for row, of in ((one, "one"), (mean, "mean")):
        low, high = (float(row[f"bem 95% {end} [m]"]) for end in ("low", "high"))
        assert (low, high) == pytest.approx(found.verdict(of).interval, rel=1e-12)
        assert low >= 0  # an interference past the reference load is not negative
        expected = "over-predicts" if high < peak else "under-predicts" if low > peak else "not established"
        assert row["statistical model"] == expected and row["n"] == "2"
        assert float(row["statistical / bem"]) == pytest.approx(peak / np.mean(peaks), rel=1e-12)
        assert row["paper's words"] == "slightly over-predicts"
    # the prediction interval of one island is wider than the mean's
    assert float(one["bem 95% high [m]"]) > float(mean["bem 95% high [m]"])
    notes = notes_of(against)
    assert len(notes) == 2 and all('Paper 002\'s words: "KKE slightly over-predicts"' in n for n in notes)
    # plasticity in the volume: the yield strength of Table I, and stress left at zero load
    assert float(volume["yield_strength [Pa]"]) == SU8.yield_strength
    assert float(volume["max_residual_von_mises [Pa]"]) > 0
    assert (out / "figures" / "bem_volume_von_mises_section.png").stat().st_size > 0

    table = {row["quantity"]: row for row in read_table(out / "tables" / "kke_paper002.csv")}
    for key, value in PRINTED.items():
        assert table[key]["modulus_form"] == "standard"
        assert float(table[key]["paper"]) == pytest.approx(value, rel=1e-12)
        assert float(table[key]["this_case"]) == pytest.approx(value, rel=5e-3)
        column = f"{key} [m]" if key != "plasticity_index" else key
        assert float(table[key]["this_case"]) == pytest.approx(float(kke[column]), rel=1e-12)
    # eq. 7 as printed (1 - nu) does not reproduce omega_c: the table keeps both readings
    assert (
        float(table["critical_interference"]["printed_inputs_eq7_printed"])
        < 0.7 * PRINTED["critical_interference"]
    )

    assert (out / "figures" / "bem_load_interference.png").stat().st_size > 0
    assert (out / "figures" / "bem_von_mises.png").stat().st_size > 0
    assert (out / "figures" / "kke_load_interference.png").stat().st_size > 0
    report = (out / "report.html").read_text()
    assert "kke" in report and "bem" in report and "paper002" in report
    assert "prediction interval of one island" in report  # the table's sentence, under it
    # each analysis shows its own tables: bem's section not bem_volume's (whose name starts alike)
    assert report.count("<h3>against statistical</h3>") == 2 and "volume against statistical" not in report
    assert report.count("data:image/png;base64") >= 4

    # The combined figure (paper 002 Fig. 7): the KKE curve of the other analysis, the mean of both
    # BEM replicates and the measured points, on the KKE analysis' omega_c.
    _, analyses = read_study(out)
    analysis = next(a for a in analyses if a.name == "bem")
    figure = analysis.kind.figures["load_interference"](analysis.finished, context(analysis, analyses))
    ax = figure.axes[0]
    labels = [line.get_label() for line in ax.get_lines()]
    assert "KKE (Kogut-Etsion), loading" in labels and "KKE (Kogut-Etsion), unloading" in labels
    bem = [label for label in labels if label.startswith("BEM")]  # the mean of the two replicates
    assert len(bem) == 2 and all("mean of 2 realisations" in label for label in bem)
    assert len(ax.collections) == 2  # the range of the replicates shaded, loading and unloading
    assert "measured" in labels
    # the legend ends with KKE's peak over the BEM's, judged for one island and for the mean
    legend = [text.get_text() for text in ax.get_legend().get_texts()]
    verdict = next(label for label in legend if label.startswith("KKE ω_max / BEM mean"))
    assert "95 % for one island" in verdict and "for the mean" in verdict
    assert ax.get_xlabel() == "interference ω/ω_c"
    kke_loading = ax.get_lines()[labels.index("KKE (Kogut-Etsion), loading")]
    assert np.max(kke_loading.get_xdata()) == pytest.approx(float(kke["peak_interference_over_omega_c"]))


def test_asperity_scalars_equal_a_direct_call_on_the_surface_moments():
    spec = GaussianRandom(
        generate="gaussian_random",
        shape=(64, 64),
        size="20 um",
        rms_height="30 nm",
        correlation_length="1.5 um",
        seed=5,
    )
    inputs = CaseInputs({"rough": spec}, {}, MATERIALS)
    kind = get_kind("asperity")
    parameters = kind.parameters.model_validate(
        {
            "topography": "rough",
            "material": "SU-8",
            "counter_body": "diamond flat tip",
            "max_force": "100 uN",
            "nominal_area": "400 um^2",
            "steps": 6,
        }
    )
    output = kind.run(parameters, inputs)
    moments = spectral_moments(inputs.topography("rough"))
    direct = asperity_parameters(
        m0=moments.m0, m2=moments.m2, m4=moments.m4, sample=SU8, counter_body=DIAMOND
    ).scalars()
    assert {k: output.scalars[k] for k in direct} == direct
    curve = output.dataset
    loading = np.asarray(curve["branch"]) == "loading"
    assert float(curve["force"][loading][-1]) == pytest.approx(100e-6, rel=1e-9)
    assert output.scalars["peak_interference"] == float(curve["approach"][loading][-1])


def _island_case(pixels: int, **keys):
    """Run the load_unload kind on paper 002's island (seed 4) on SU-8 over silicon to 1000 uN."""
    inputs = CaseInputs(
        {"island": Paper002Island(generate="paper002_island", shape=(pixels, pixels), seed=4)}, {}, MATERIALS
    )
    kind = get_kind("load_unload")
    parameters = kind.parameters.model_validate(
        {
            "topography": "island",
            "material": "SU-8",
            "substrate": "silicon wafer",
            "film_thickness": "6.3 um",
            "max_force": "1000 uN",
            "reference_force": "25 uN",
            **keys,
        }
    )
    return kind.run(parameters, inputs)


def test_load_unload_interferences_equal_a_direct_compress_island():
    output = _island_case(24)
    # compress_island's own default targets (0, 25 uN, 100 ... 1000 uN and back) are load_steps = 10's
    direct = compress_island(paper002_island(24, seed=4), SU8, substrate=SILICON, film_thickness=6.3e-6)
    peak = int(np.sum(direct.branch == "loading")) - 1
    assert output.scalars["peak_interference"] == pytest.approx(direct.interference[peak], rel=1e-12, abs=0)
    assert output.scalars["residual_interference"] == pytest.approx(
        direct.residual_interference, rel=1e-12, abs=0
    )
    np.testing.assert_allclose(output.dataset["approach"], direct.interference, rtol=1e-12, atol=0)
    # maps at 0, 200, ..., 1000 uN on loading and 800, ..., 0 uN on unloading (paper 002 Figs. 8-9)
    forces = np.round(output.dataset["map_force"].values * 1e6).astype(int)
    assert list(forces) == [0, 200, 400, 600, 800, 1000, 800, 600, 400, 200, 0]
    assert float(output.dataset["von_mises"].isel(map=5).max()) == pytest.approx(
        output.scalars["max_von_mises_at_peak"], rel=1e-6
    )


STUDY_HEAD = """
[study]
name = "bad asperity"
[topographies.rough]
generate = "gaussian_random"
shape = 16
size = "5 um"
rms_height = "10 nm"
correlation_length = "1 um"
[[analysis]]
name = "kke"
model = "asperity"
material = "SU-8"
"""


@pytest.mark.parametrize(
    ("lines", "field", "words"),
    [
        (
            'topography = "rough"\nm0 = "0.002 um^2"\nm2 = 0.002\nm4 = "0.017 1/um^2"',
            "analysis[0] (kke)",
            "found topography, m0, m2, m4",
        ),
        ("", "analysis[0] (kke)", "found none"),
        ('m0 = "-0.002 um^2"\nm2 = 0.002\nm4 = "0.017 1/um^2"', "analysis[0] (kke).m0", "must be positive"),
    ],
    ids=["surface-and-moments", "neither", "negative-m0"],
)
def test_validation_names_the_field(tmp_path, cli, lines, field, words):
    path = tmp_path / "bad.toml"
    path.write_text(STUDY_HEAD + lines + "\n")
    with pytest.raises(StudyError) as caught:
        load_study(path)
    [(where, problem, fix)] = caught.value.problems
    assert where == field
    assert words in problem and fix
    status, _, err = cli("validate", path)
    assert status == 2 and field in err and words in err


def test_load_unload_refuses_map_loads_that_are_not_targets(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(
        STUDY_HEAD.replace('model = "asperity"\nmaterial = "SU-8"\n', 'model = "load_unload"\n')
        + 'surface = "rough"\nmaterial = "SU-8"\nmax_force = "1000 uN"\nvon_mises_loads = ["250 uN"]\n'
    )
    with pytest.raises(StudyError, match=r"von_mises_loads \[250\.0\] uN are not among the load targets"):
        load_study(path)


def test_a_curve_needs_max_force_and_nominal_area_together():
    kind = get_kind("asperity")
    with pytest.raises(ValueError, match="both «max_force» and «nominal_area»"):  # marked for each door
        kind.parameters.model_validate(
            {"m0": "0.002 um^2", "m2": 0.002, "m4": "0.017 1/um^2", "material": "SU-8", "max_force": "1 mN"}
        )


def test_load_unload_with_volume_plasticity_equals_compress_island_and_keeps_residual_stress():
    output = _island_case(48, plasticity="volume", layers=8)
    direct = compress_island(
        paper002_island(48, seed=4),
        SU8,
        substrate=SILICON,
        film_thickness=6.3e-6,
        plasticity="volume",
        layers=8,
    )
    np.testing.assert_allclose(output.dataset["approach"], direct.interference, rtol=1e-12, atol=0)
    assert output.scalars["residual_interference"] == direct.residual_interference
    assert output.scalars["yield_strength"] == SU8.yield_strength  # paper 002 Table I, the default
    assert output.scalars["plastic_dissipation"] > 0
    # the last map, 0 uN after unloading, shows the residual stress; the first, 0 uN before loading, nothing
    maps = output.dataset["von_mises"]
    assert float(maps.isel(map=0).max()) == 0.0 and float(maps.isel(map=-1).max()) > 0.0
    section = output.dataset["von_mises_section"]
    assert section.sizes["map"] == maps.sizes["map"] and section.sizes["z"] == 8
    assert output.dataset.attrs["stress_depth"] == pytest.approx(direct.volume.depths[0])


def test_load_unload_refuses_an_unknown_plasticity(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(
        STUDY_HEAD.replace('model = "asperity"\nmaterial = "SU-8"\n', 'model = "load_unload"\n')
        + 'topography = "rough"\nmaterial = "SU-8"\nmax_force = "1000 uN"\nplasticity = "bulk"\n'
    )
    with pytest.raises(StudyError, match="plasticity"):
        load_study(path)
