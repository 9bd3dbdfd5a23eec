"""Results and study answers show themselves in a notebook (``_repr_html_``): scalars with units, a figure.

Every result class the protocol test builds (``test_result_protocol.BUILDERS``) is shown here.
"""

import base64
import html
import re
import subprocess
import sys
import tomllib
from dataclasses import dataclass
from html.parser import HTMLParser
from typing import ClassVar

import numpy as np
import pytest
from test_result_protocol import BUILDERS, SOLVED, _result_classes

from roughcontact.display_html import NotebookDisplay, value_text
from roughcontact.results import SolverResult, units_of
from roughcontact.units import shown

CHECKED = {"div", "table", "caption", "thead", "tbody", "tr", "th", "td", "p", "strong", "ul", "li"}


class _Tags(HTMLParser):
    """Check that the tags of a display open and close in order."""

    def __init__(self):
        super().__init__()
        self.open: list[str] = []
        self.seen: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.seen.append(tag)
        if tag in CHECKED:
            self.open.append(tag)

    def handle_endtag(self, tag):
        assert self.open and self.open[-1] == tag, f"</{tag}> closes {self.open}"
        self.open.pop()


def _tags(text: str) -> list[str]:
    """Parse a display; return the tags it opens (asserting they balance)."""
    parser = _Tags()
    parser.feed(text)
    parser.close()
    assert not parser.open, f"left open: {parser.open}"
    return parser.seen


@pytest.fixture(scope="module", params=list(BUILDERS))
def shown_result(request):
    result = BUILDERS[request.param]()
    return request.param, result, result._repr_html_()


def test_every_result_class_shows_itself():
    plain = sorted(cls.__qualname__ for cls in _result_classes() if not issubclass(cls, NotebookDisplay))
    assert not plain, f"result classes without a notebook display: {plain}"


def test_a_display_lists_every_scalar_with_its_unit(shown_result):
    name, result, text = shown_result
    units = units_of(result)
    for key, value in result.scalars().items():
        assert f">{html.escape(key)}</td>" in text, (name, key)
        assert f">{html.escape(value_text(value, units.get(key)))}</td>" in text, (name, key)
    tags = _tags(text)
    assert tags.count("tr") == len(result.scalars()) + 1, name
    assert "<script" not in text and "http" not in text, name
    assert type(result).__name__ in text


def test_dimensional_scalars_read_in_prefixed_units(shown_result):
    name, result, text = shown_result
    for key, unit in units_of(result).items():
        value = result.scalars().get(key)
        if unit and isinstance(value, float) and np.isfinite(value):
            written = shown(value, unit)
            assert written.split(" ")[-1] != written, (name, key)  # a unit is written
            assert f">{html.escape(written)}</td>" in text, (name, key)


def test_solvers_say_how_they_ended(shown_result):
    name, result, text = shown_result
    assert ("<p>converged in " in text) == isinstance(result, SolverResult), name
    assert name not in SOLVED or "<p>converged in " in text, name


def test_a_result_that_names_a_figure_shows_it(shown_result):
    name, result, text = shown_result
    assert ('<img alt="' in text) == (result.FIGURE is not None), name


def test_normal_contact_shows_area_convergence_and_a_pressure_map():
    result = BUILDERS["normal contact"]()
    text = result._repr_html_()
    area = shown(result.contact_area, "m^2")
    assert area.endswith("µm²")
    assert ">contact_area</td>" in text and f">{area}</td>" in text
    assert f"<p>converged in {result.iterations} iterations, residual " in text
    image = re.search(r'<img alt="[^"]*" src="data:image/png;base64,([A-Za-z0-9+/=]+)">', text)
    assert image, "no thumbnail"
    png = base64.b64decode(image.group(1))
    assert png.startswith(b"\x89PNG") and len(png) < 60_000
    assert repr(result).startswith("NormalContactResult(topography=")  # the text repr is the dataclass's


def test_a_result_outside_its_model_s_range_says_so_under_its_table():
    from roughcontact.contact import solve_normal
    from roughcontact.topography.generate import sphere

    ball = sphere((32, 32), (40e-6, 40e-6), radius=50e-6, kind="paraboloid")
    result = solve_normal(ball, 1e9, force=0.1)  # Hertz: peak 0.2 GPa, beyond 0.1 E*: steep slopes
    warnings = result.range_warnings()
    assert warnings
    text = result._repr_html_()
    assert "outside the model's range" in text
    for line in warnings:
        assert f"<li>{html.escape(line)}</li>" in text
    assert (
        "outside the model" not in BUILDERS["normal contact"]()._repr_html_()
        or BUILDERS["normal contact"]().range_warnings()
    )


@dataclass(frozen=True)
class _Odd(NotebookDisplay):
    """A result <of> odd names & labels."""

    converged: bool = False
    FIGURE = "contact.plot_pressure"  # it has no pressure to draw
    UNITS: ClassVar[dict[str, str]] = {"a<b": "m"}

    @property
    def iterations(self):
        return np.array([3, 4])

    @property
    def residual(self):
        return np.array([1e-3, 2e-2])

    def scalars(self):
        return {"a<b": 2.5e-8, "label": "x & <y>", "flag": True, "nothing": None}

    def to_xarray(self):
        return None


def test_names_and_labels_are_escaped_and_a_failed_figure_is_left_out():
    text = _Odd()._repr_html_()
    _tags(text)
    assert ">a&lt;b</td>" in text and ">25 nm</td>" in text
    assert ">x &amp; &lt;y&gt;</td>" in text and "<y>" not in text
    assert "A result &lt;of&gt; odd names &amp; labels." in text
    assert ">yes</td>" in text and ">—</td>" in text
    assert "<p>did not converge: 7 iterations over 2 steps, largest residual 0.02</p>" in text
    assert "<img" not in text


STUDY = """
[study]
name = "notebook <&>"

[topographies.scan]
generate = "self_affine"
shape = 16
size = "1 um"
hurst = 0.8
rms_height = "2 nm"
seed = 1

[[analysis]]
name = "contact"
model = "normal"
topography = "scan"
material = "polysilicon"
mean_pressure = "20 MPa"

[analysis.sweep]
mean_pressure = ["10 MPa", "20 MPa", "40 MPa"]
"""


def test_an_answer_shows_its_cases(tmp_path, monkeypatch):
    from roughcontact.study import answer, outputs
    from roughcontact.study.config import build_study

    result = answer(build_study(tomllib.loads(STUDY), folder=tmp_path, text=STUDY, source="notebook"))
    text = result._repr_html_()
    _tags(text)
    assert "<strong>notebook &lt;&amp;&gt;</strong>" in text and "<strong>contact</strong>" in text
    for title in ("mean_pressure (MPa)", "force (µN)", "contact_fraction", "max_pressure (GPa)"):
        assert f">{title}</th>" in text
    for case, pressure in zip(result.analyses[0].cases, ("10", "20", "40"), strict=True):
        assert f">{case}</td>" in text and f">{pressure}</td>" in text
    assert "more cases" not in text and "status" not in text

    monkeypatch.setattr(outputs, "CASES_SHOWN", 2)
    text = result._repr_html_()
    assert text.count("<tr>") == 3 and "<p>… 1 more cases</p>" in text


def test_the_result_module_does_not_import_matplotlib():
    code = "import sys, roughcontact.contact.result; print('matplotlib' in sys.modules)"
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert run.stdout.strip() == "False"
