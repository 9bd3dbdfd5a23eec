"""Every figure a study draws is a plotting function on cases, drawn from Python on results too.

``roughcontact.plotting.as_cases`` wraps results of the result protocol; the figure functions the
study kinds wire (``study.kind.figure``) are the same functions, so what ``roughcontact run``
draws can be drawn without a study. The kinds themselves draw nothing.
"""

import ast
from pathlib import Path

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from roughcontact import get_material, solve_normal  # noqa: E402
from roughcontact.contact.adhesive import solve_adhesive  # noqa: E402
from roughcontact.contact.interaction import MaugisDugdale  # noqa: E402
from roughcontact.plotting import as_cases, figure_caption  # noqa: E402
from roughcontact.plotting.adhesion import force_approach_figure, pull_off_figure  # noqa: E402
from roughcontact.plotting.contact import area_load_figure, contact_maps_figure  # noqa: E402
from roughcontact.study.kinds import get_kind, kind_names  # noqa: E402
from roughcontact.topography import generate  # noqa: E402

KINDS_FOLDER = Path(__file__).resolve().parents[2] / "src" / "roughcontact" / "study" / "kinds"


def test_normal_contact_figures_from_results():
    surface = generate.self_affine((32, 32), 1e-6, hurst=0.8, rms_height=5e-9, seed=1)
    material = get_material("polysilicon")
    results = [solve_normal(surface, material, mean_pressure=p) for p in (5e6, 20e6, 80e6)]
    cases = as_cases(results, labels=["5 MPa", "20 MPa", "80 MPa"])
    maps = contact_maps_figure(cases)
    assert len(maps.axes) >= 6 and "5 MPa" in maps.axes[0].get_title()
    curve = area_load_figure(cases)
    (line,) = curve.axes[0].get_lines()
    assert np.allclose(line.get_xdata(), [5, 20, 80])  # MPa
    assert np.all(np.diff(line.get_ydata()) > 0)


def test_adhesion_figures_from_results():
    surface = generate.sphere((32, 32), 0.4e-6, radius=1e-6)
    material = get_material("polysilicon")
    results = []
    for work in (0.05, 0.1):
        law = MaugisDugdale(work, 2e-9)
        results.append(solve_adhesive(surface, material, law, approach=np.linspace(-6e-9, 3e-9, 12)))
    cases = as_cases(results, labels=["50 mJ/m^2", "100 mJ/m^2"])
    cycles = force_approach_figure(cases)
    assert any("pull-off" in text.get_text() for text in cycles.axes[1].get_legend().get_texts())
    pull_off = pull_off_figure(cases)
    assert pull_off is not None and "work of adhesion" in pull_off.axes[0].get_xlabel()


def test_as_cases_checks_its_labels():
    with pytest.raises(ValueError, match="2 results, 1 labels"):
        as_cases([object(), object()], labels=["a"])


def test_every_study_figure_is_a_plotting_function_with_a_caption():
    for kind in map(get_kind, kind_names()):
        for name, wired in kind.figures.items():
            assert wired.draws.__module__.startswith("roughcontact.plotting."), (kind.name, name)
            assert len(figure_caption(wired.draws)) >= 40, (kind.name, name)


def test_the_kinds_draw_nothing():
    """No kind imports matplotlib or calls an axes method: figures live in roughcontact.plotting."""
    for path in KINDS_FOLDER.glob("*.py"):
        tree = ast.parse(path.read_text())
        imported = [node.module or "" for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)] + [
            alias.name for node in ast.walk(tree) if isinstance(node, ast.Import) for alias in node.names
        ]
        assert not [m for m in imported if "matplotlib" in m], path.name
        calls = [
            node.func.attr
            for node in ast.walk(tree)
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
        ]
        assert not {"plot", "pcolormesh", "set_xlabel", "imshow", "colorbar"} & set(calls), path.name
