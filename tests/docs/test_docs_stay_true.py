"""Docs that stay true: links between pages, titles without issue numbers, summaries as whole sentences.

Read from the sources, without building the site (``test_site.py`` builds it):

* a page of the documentation is referred to by a link (MyST ``[words](page.md)`` in the pages,
  ``:doc:`/page``` or plain words in docstrings, help texts and captions), never by its repository
  path ``docs/page.md``, which the site does not link and which goes stale when pages move;
* a ``:doc:`` role in a docstring names a page that exists (docstrings off the site are not
  checked by its build);
* no page title carries an issue number (a page says what it holds, not when it was asked for);
* the summary of a public name, its docstring's first sentence as Sphinx's ``autosummary`` cuts it
  (at the first period followed by a space), does not end in an abbreviation such as "eq." or
  "Fig.": the table of the API pages would show "Paper 001 eq.";
* the index names the three seed papers by their titles.
"""

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
SOURCE = ROOT / "src" / "roughcontact"
GENERATED = {"cli.md"}  # written from the parsers at every build (not kept in git)

DOCS_PATH = re.compile(r"\bdocs/[\w./-]*\.md\b")
"""A repository path to a page of the documentation."""

ISSUE = re.compile(r"\b[Ii]ssues?\s*#?\d+|#\d+\b")
"""An issue number: "issue 20", "issue #5", "#18"."""

CUT_AT = (
    "eq", "eqs", "Eq", "Eqs", "Fig", "Figs", "fig", "figs", "Sec", "sec", "Secs", "cf", "vs", "approx",
    "Ref", "Refs", "ref", "Tab", "No", "no",
)  # fmt: skip
"""Abbreviations at which Sphinx's summary would cut a first sentence short."""

_PERIOD = re.compile(r"\.(?:\s+)")
_KNOWN = ("et al.", "e.g.", "i.e.")  # autosummary's WELL_KNOWN_ABBREVIATIONS: it does not cut there


def pages() -> list[Path]:
    """The Markdown pages of the site, as kept in git."""
    return [page for page in sorted(DOCS.glob("*.md")) if page.name not in GENERATED]


def sources() -> list[Path]:
    """The package's modules and the gallery's scripts, whose strings the site and the commands show."""
    return sorted(SOURCE.rglob("*.py")) + sorted((DOCS / "gallery_scripts").glob("*.py"))


def strings_of(path: Path) -> list[tuple[int, str]]:
    """(line, text) of every string literal of a module: docstrings, help texts, captions."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return [
        (node.lineno, node.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant) and isinstance(node.value, str)
    ]


def docs_paths(text: str) -> list[str]:
    """The repository paths to documentation pages in a text."""
    return DOCS_PATH.findall(text)


def summary(docstring: str) -> str:
    """Return the summary autosummary makes of a docstring: its first stanza to its first sentence's end."""
    stanza = []
    for line in docstring.strip().splitlines():
        if not line.strip():
            break
        stanza.append(line.strip())
    parts = _PERIOD.split(" ".join(stanza))
    if len(parts) == 1:
        return parts[0]
    for number in range(len(parts)):
        cut = ". ".join(parts[: number + 1]).rstrip(".") + "."
        if not cut.endswith(_KNOWN):
            return cut
    return " ".join(stanza)


def cut_short(text: str) -> bool:
    """Whether a summary ends at an abbreviation (``"Paper 001 eq."``)."""
    words = text.rstrip(".").split()
    return bool(words) and text.endswith(".") and words[-1].lstrip("(") in CUT_AT


def public_docstrings(source: Path, top: str) -> list[tuple[str, str]]:
    """(dotted name, docstring) of every public module, class, function and method of a package."""
    found = []
    for path in sorted((source / top).rglob("*.py")):
        parts = list(path.relative_to(source).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        if any(part.startswith("_") for part in parts):
            continue
        module = ".".join(parts)
        tree = ast.parse(path.read_text(encoding="utf-8"))
        nodes = [(module, tree)]
        for node in tree.body:
            if isinstance(node, ast.FunctionDef | ast.ClassDef) and not node.name.startswith("_"):
                nodes.append((f"{module}.{node.name}", node))
                if isinstance(node, ast.ClassDef):
                    nodes += [
                        (f"{module}.{node.name}.{child.name}", child)
                        for child in node.body
                        if isinstance(child, ast.FunctionDef) and not child.name.startswith("_")
                    ]
        found += [(name, ast.get_docstring(node)) for name, node in nodes if ast.get_docstring(node)]
    return found


def test_no_page_refers_to_another_by_its_repository_path():
    found = [
        f"{page.name}:{number}: {path}"
        for page in pages()
        for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1)
        for path in docs_paths(line)
    ]
    assert not found, "link the page instead ([words](page.md)):\n" + "\n".join(found)


def test_no_docstring_help_text_or_caption_names_a_page_by_its_repository_path():
    found = [
        f"{path.relative_to(ROOT)}:{line}: {where}"
        for path in sources()
        for line, text in strings_of(path)
        for where in docs_paths(text)
    ]
    assert not found, "write :doc:`/page` in a docstring, or the page's name in words:\n" + "\n".join(found)


def test_every_page_a_docstring_links_exists():
    role = re.compile(r":doc:`(?:[^`<]*<)?/?([\w/-]+)>?`")
    missing = [
        f"{path.relative_to(ROOT)}:{line}: {target}"
        for path in sources()
        for line, text in strings_of(path)
        for target in role.findall(text)
        if not (DOCS / f"{target}.md").is_file() and not (DOCS / f"{target}.rst").is_file()
    ]
    assert not missing, "\n".join(missing)


def test_no_page_title_carries_an_issue_number():
    titles = [(page.name, next(iter(page.read_text(encoding="utf-8").splitlines()), "")) for page in pages()]
    titles += [
        (
            script.name,
            (ast.get_docstring(ast.parse(script.read_text(encoding="utf-8"))) or "").splitlines()[0],
        )
        for script in sorted((DOCS / "gallery_scripts").glob("plot_*.py"))
    ]
    assert all(title for _, title in titles)
    with_issue = [f"{name}: {title}" for name, title in titles if ISSUE.search(title)]
    assert not with_issue, "\n".join(with_issue)


def test_no_api_summary_is_cut_at_an_abbreviation():
    cut = [
        f"{name}: {summary(text)!r}"
        for name, text in public_docstrings(SOURCE.parent, "roughcontact")
        if cut_short(summary(text))
    ]
    assert not cut, "say 'equation 5', 'figure 3' in the first sentence:\n" + "\n".join(cut)


def test_the_index_names_the_three_papers_by_their_titles():
    from roughcontact.references import REFERENCES

    index = " ".join(DOCS.joinpath("index.md").read_text(encoding="utf-8").split())
    for key in ("paper000", "paper001", "paper002"):
        assert REFERENCES[key].title in index, key


@pytest.mark.parametrize(
    ("docstring", "expected", "short"),
    [
        ("Hertz contact radius, paper 001 eq. 11 [m].", "Hertz contact radius, paper 001 eq.", True),
        ("Draw paper 002's Figs. 7-9.\n\nMore.", "Draw paper 002's Figs.", True),
        ("Hertz contact radius, equation 11 [m].", "Hertz contact radius, equation 11 [m].", False),
        ("Fit it, e.g. by least squares. Then more.", "Fit it, e.g. by least squares.", False),
        ("One line without a period", "One line without a period", False),
    ],
)  # fmt: skip
def test_the_summary_rule_cuts_as_autosummary_does(docstring, expected, short):
    assert summary(docstring) == expected
    assert cut_short(summary(docstring)) is short


def test_the_rules_see_a_path_and_an_issue_number(tmp_path):
    assert docs_paths("see ``docs/asperity.md`` and docs/api/index.md") == [
        "docs/asperity.md",
        "docs/api/index.md",
    ]
    assert docs_paths("see :doc:`/asperity` and benchmarks/results/log.md") == []
    assert ISSUE.search("# Frictional programmes (issue 20)") and ISSUE.search("# Speed (#18)")
    assert not ISSUE.search("# Asperity models and the thin-film island (seed paper 002)")
    package = tmp_path / "fake"
    package.mkdir()
    (package / "__init__.py").write_text('"""Paper 000 eq. 5, read here."""\n')
    (package / "_private.py").write_text('"""Fig. 3 of a paper."""\n')
    (package / "api.py").write_text(
        'def solve():\n    """Solve eq. 2 for the gap."""\n\n\nclass Model:\n    def run(self):\n'
        '        """Run it (Figs. 8-9)."""\n\n    def _inner(self):\n        """See eq. 4 here."""\n'
    )
    cut = [name for name, text in public_docstrings(tmp_path, "fake") if cut_short(summary(text))]
    assert cut == ["fake", "fake.api.solve", "fake.api.Model.run"]
