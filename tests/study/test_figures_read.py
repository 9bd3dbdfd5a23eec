"""Every study figure read as a reviewer would: units on the axes, words in the legends, no empty panel.

The figures of the embedded demo and of two small studies (an adhesive ball, a friction load sweep
with measurements) are drawn in memory and checked panel by panel:

- a panel with its axes shown draws something (a curve with a finite point, a map, a patch, bars);
- each axis label and colour-bar label names a unit in parentheses, or is a dimensionless quantity
  (μ, a ratio, a fraction, a count, ...);
- titles and legend entries hold no identifier of the code (``snake_case`` words) other than the
  names the study file gave its surfaces, materials, analyses and samples.

Figure functions no study here draws are listed in :data:`NOT_DRAWN_HERE`, each with where it is
drawn and checked otherwise; a new figure function must be drawn here or added there.
"""

from __future__ import annotations

import re
import tomllib

import numpy as np
import pytest

from roughcontact.study import load_study, run_study
from roughcontact.study.kinds import get_kind, kind_names
from roughcontact.study.outputs import produce, read_study
from study_documents import ADHESION_CYCLE, FRICTION_OVER_TWO_LOADS, SCAN_AND_TIP, adhesive_ball

IDENTIFIER = re.compile(r"\b[a-z][a-z0-9]*_[a-z0-9_]+\b")
DIMENSIONLESS = (
    "μ", "ratio", "fraction", "%", "count", "number", "coefficient", "probability", "/", "index",
    "normalised", "relative", "(-)", "step", "cycle",
)  # fmt: skip

NOT_DRAWN_HERE = {
    (
        "load_unload",
        "mesh_convergence",
    ): "examples/paper002_mesh.toml (minutes); tests/unit/test_mesh_convergence.py",
    ("load_unload", "von_mises"): "volume plasticity studies (tests/study/test_asperity_study.py)",
    ("load_unload", "von_mises_section"): "volume plasticity studies (tests/study/test_asperity_study.py)",
    ("loop_analysis", "loop"): "examples/paper001_measured_loop.py",
    ("nanoindentation", "indentation"): "examples/paper001_indentation.py",
    ("presliding", "lateral_stiffness"): "examples/paper001.toml (tests/study/test_presliding_study.py)",
    **{
        ("theories", name): "tests/study/test_theories_study.py (read here with figure_problems)"
        for name in ("area", "gap", "pressure", "kappa", "magnification")
    },
}

ADHESION = (
    adhesive_ball("adhesive ball")
    + ADHESION_CYCLE
    + """steps = 10
[analysis.sweep]
work_of_adhesion = ["30 mJ/m^2", "50 mJ/m^2"]
"""
)

FRICTION = (
    SCAN_AND_TIP
    + FRICTION_OVER_TWO_LOADS
    + """replicate = [0, 1]
sample = ["a", "b"]
[[analysis]]
name = "friction_at_one_load"
model = "friction"
topography = "scan"
counter_topography = "tip"
material = "polysilicon"
counter_body = "SiO2"
normal_force = "5 uN"
surface_energy = "50 mJ/m^2"
[analysis.sweep]
replicate = [0, 1, 2, 3, 4]
sample = ["a", "b"]
"""
)


def _names_given(text: str) -> set[str]:
    """The names a study file gives: surfaces, materials, analyses and swept samples."""
    document = tomllib.loads(text)
    names = set(document.get("topographies", {})) | set(document.get("materials", {}))
    for analysis in document.get("analysis", []):
        names.add(analysis.get("name", ""))
        names |= {str(s) for s in analysis.get("sweep", {}).get("sample", [])}
    return names


@pytest.fixture(scope="module")
def drawn(tmp_path_factory) -> list[tuple[str, str, object, set[str]]]:
    from roughcontact.cli.study import demo_study

    folder = tmp_path_factory.mktemp("figures")
    studies = [("demo", demo_study().read_text(), demo_study())]
    for name, text in (("adhesion", ADHESION), ("friction", FRICTION)):
        path = folder / f"{name}.toml"
        path.write_text(text)
        studies.append((name, text, path))
    made = []
    for name, text, path in studies:
        output = folder / name
        run_study(load_study(path), output)
        analyses = read_study(output)[1]
        figures, problems = produce(analyses, "figure")
        assert not problems, problems
        kinds = {a.name: a.kind.name for a in analyses}
        made += [
            (kinds[analysis], figure_name, figure, _names_given(text))
            for analysis, figure_name, figure in figures
        ]
    return made


def _has_data(ax) -> bool:
    for line in ax.lines:
        x, y = np.asarray(line.get_xdata(), dtype=float), np.asarray(line.get_ydata(), dtype=float)
        if (np.isfinite(x) & np.isfinite(y)).any():
            return True
    return bool(ax.collections or ax.images or ax.patches or ax.containers)


def _has_unit(label: str) -> bool:
    return bool(re.search(r"\([^()]+\)", label)) or any(word in label for word in DIMENSIONLESS)


def figure_problems(figure, names_given: set[str]) -> list[str]:
    """What a reviewer would send back about ``figure`` (see the module docstring)."""
    problems = []
    for k, ax in enumerate(figure.axes):
        if not ax.axison:
            continue
        where = f"panel {k} ({ax.get_title()!r})"
        if ax.get_label() == "<colorbar>":
            label = ax.get_ylabel() or ax.get_xlabel()
            if not label or not _has_unit(label):
                problems.append(f"{where}: colour bar label without a unit: {label!r}")
            continue
        if not _has_data(ax):
            problems.append(f"{where}: nothing drawn")
        for axis, label in (("x", ax.get_xlabel()), ("y", ax.get_ylabel())):
            ticks = [t.get_text() for t in (ax.get_xticklabels() if axis == "x" else ax.get_yticklabels())]
            categorical = any(t and not re.fullmatch(r"[-−\d.,e+ ]*", t) for t in ticks)
            if not label and not categorical:
                problems.append(f"{where}: no {axis} label")
            elif label and not _has_unit(label):
                problems.append(f"{where}: {axis} label without a unit: {label!r}")
        texts = [ax.get_title()]
        if ax.get_legend() is not None:
            texts += [t.get_text() for t in ax.get_legend().get_texts()]
        for text in texts:
            leaked = set(IDENTIFIER.findall(text)) - names_given
            if leaked:
                problems.append(f"{where}: code identifier {sorted(leaked)} in {text!r}")
    return problems


def test_every_figure_reads_as_a_reviewer_wants(drawn):
    problems = [
        f"{kind}/{name}: {problem}"
        for kind, name, figure, names in drawn
        for problem in figure_problems(figure, names)
    ]
    assert not problems, "\n".join(problems)


def test_every_figure_function_is_drawn_here_or_accounted_for(drawn):
    every = {(kind, name) for kind in kind_names() for name in get_kind(kind).figures}
    here = {(kind, name) for kind, name, _, _ in drawn}
    assert every - here == set(NOT_DRAWN_HERE), sorted(every - here)


def test_the_checks_catch_what_they_are_for():
    from matplotlib.figure import Figure

    figure = Figure()
    ax, empty = figure.subplots(1, 2)
    ax.plot([0, 1], [0, 1], label="mean_pressure=20 MPa")
    ax.set_xlabel("approach")
    ax.set_ylabel("force (uN)")
    ax.legend()
    problems = figure_problems(figure, set())
    assert any("x label without a unit" in p for p in problems)
    assert any("code identifier ['mean_pressure']" in p for p in problems)
    assert any("panel 1" in p and "nothing drawn" in p for p in problems)
    assert figure_problems(figure, {"mean_pressure"}) != problems  # a name the study gave is its own


def test_sparse_contact_is_ringed_enlarged_and_on_grey():
    from roughcontact.contact import solve_normal
    from roughcontact.plotting.cases import as_cases
    from roughcontact.plotting.contact import contact_maps_figure
    from roughcontact.topography import Topography
    from roughcontact.topography.generate import sphere

    ball = sphere((128, 128), (10e-6, 10e-6), radius=1e-3, kind="paraboloid")
    heights = ball.heights.copy()
    heights[90, 30] += 8e-9  # a one-pixel asperity beside the ball's contact
    result = solve_normal(Topography(heights, ball.size), 1e9, force=2e-7)
    assert result.contact_fraction < 0.02
    figure = contact_maps_figure(as_cases([result]))
    titles = [ax.get_title() for ax in figure.axes]
    assert "enlarged: the most loaded patch" in titles
    area = figure.axes[0]
    legend = [t.get_text() for t in area.get_legend().get_texts()]
    assert legend == ["in contact", "2 patches"]
    pressure = figure.axes[1].collections[0]
    assert np.ma.count_masked(pressure.get_array()) > 0.9 * pressure.get_array().size  # no contact: grey
    assert not figure_problems(figure, set())
