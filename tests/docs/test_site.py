"""The documentation site builds with no warning, and shows what a reader needs (issue 37).

The site is built once per test session, as ``make docs`` builds it (every warning an error,
the gallery's scripts run), into a folder of the session. Then: every public name of
``roughcontact`` has its reference page, ``solve_normal``'s shows its parameters with units and
a rendered equation, the gallery shows a figure per example, and the command-line reference
holds every command.
"""

import importlib
import inspect
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("sphinx")
pytest.importorskip("sphinx_gallery")
pytest.importorskip("numpydoc")
pytest.importorskip("myst_parser")

DOCS = Path(__file__).resolve().parents[2] / "docs"


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """Build the site (warnings are errors) and return its folder."""
    out = tmp_path_factory.mktemp("site")
    done = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html", str(DOCS), str(out)],
        capture_output=True,
        text=True,
        env=os.environ | {"MPLBACKEND": "Agg"},
    )
    assert done.returncode == 0, f"the site did not build cleanly:\n{done.stderr[-6000:]}"
    return out


def _api_pages():
    """Return the site's extension that writes the API pages (``docs/_ext/api_pages.py``)."""
    sys.path.insert(0, str(DOCS / "_ext"))
    try:
        return importlib.import_module("api_pages")
    finally:
        sys.path.remove(str(DOCS / "_ext"))


def _page_of(name: str) -> str:
    """Return the page of ``roughcontact.name`` in the site: a module's own, else its home package's."""
    home = _api_pages().homes()["roughcontact"][name]
    if inspect.ismodule(getattr(importlib.import_module("roughcontact"), name)):
        return f"api/{home}.html"
    return f"api/generated/{home}.{name}.html"


@pytest.mark.parametrize("name", importlib.import_module("roughcontact").__all__)
def test_every_public_name_has_a_reference_page(site, name):
    page = site / _page_of(name)
    assert page.is_file(), page
    assert name in page.read_text()


def test_the_page_of_solve_normal_shows_its_parameters_with_units_and_an_equation(site):
    text = (site / "api" / "generated" / "roughcontact.contact.solve_normal.html").read_text()
    for words in ("mean_pressure", "[Pa]", "force", "[N]", "approach", "[m]", "tolerance"):
        assert words in text, words
    assert 'class="math' in text and "\\qquad p \\ge 0" in text  # the complementarity equation, for MathJax
    assert (site / "_static" / "mathjax" / "tex-chtml.js").is_file()  # MathJax served from the site


def test_the_pages_load_nothing_from_the_network(site):
    for page in site.rglob("*.html"):
        text = page.read_text()
        assert "cdn.jsdelivr" not in text and "cdnjs" not in text and "unpkg.com" not in text, page


def test_the_gallery_shows_a_figure_per_example(site):
    scripts = sorted((DOCS / "gallery_scripts").glob("plot_*.py"))
    assert len(scripts) >= 5
    for script in scripts:
        page = site / "gallery" / f"{script.stem}.html"
        assert page.is_file(), page
        images = list((site / "_images").glob(f"sphx_glr_{script.stem}_*.png"))
        assert images, f"{script.name} drew no figure"


def test_the_command_line_reference_holds_every_command(site):
    from roughcontact.cli import GROUPS

    text = (site / "cli.html").read_text()
    for group in GROUPS:
        for name in group.COMMANDS:
            assert f"roughcontact {name}" in text, name
