"""Citations (issue 37): every model names the works it implements, as valid BibTeX; CITATION.cff agrees."""

import re
import tomllib
from pathlib import Path

import pytest
import yaml

import roughcontact
from roughcontact.references import REFERENCES, ROUGHCONTACT, Reference, bibtex, references_of
from roughcontact.study.kinds import get_kind, kind_names

ROOT = Path(__file__).resolve().parents[2]


def parse_bibtex(text: str) -> list[tuple[str, str, dict[str, str]]]:
    """Return (type, key, fields) of each entry; fail on unbalanced braces or text outside the entries."""
    entries, position = [], 0
    for match in re.finditer(r"@(\w+)\{([^,\s{}]+),", text):
        assert not text[position : match.start()].strip(), "text between entries"
        depth, end = 1, match.end()
        while depth:
            assert end < len(text), f"unbalanced braces in {match.group(2)}"
            depth += {"{": 1, "}": -1}.get(text[end], 0) if text[end - 1] != "\\" else 0
            end += 1
        body = text[match.end() : end - 1]
        fields = {}
        for line in body.strip().splitlines():
            name, value = re.fullmatch(r"\s*(\w+) = \{(.*)\},", line).groups()
            fields[name] = value
        entries.append((match.group(1), match.group(2), fields))
        position = end
    assert not text[position:].strip(), "text after the last entry"
    return entries


@pytest.mark.parametrize("name", kind_names())
def test_every_model_names_the_works_it_implements(name):
    keys = get_kind(name).references
    assert keys, f"model {name!r} cites nothing"
    assert len(set(keys)) == len(keys)
    assert [r.key for r in references_of(keys)] == list(keys)  # every key resolves


def test_every_reference_is_implemented_by_some_model():
    cited = {key for name in kind_names() for key in get_kind(name).references}
    assert set(REFERENCES) == cited


def test_every_doi_is_the_one_a_docstring_of_the_code_cites():
    source = "\n".join(
        path.read_text(encoding="utf-8").lower()
        for path in (ROOT / "src" / "roughcontact").rglob("*.py")
        if path.name != "references.py"
    )
    for reference in REFERENCES.values():
        assert reference.key == reference.key.lower() and reference.title
        if reference.doi is not None:
            assert not reference.doi.startswith(("http", "doi:")), reference.key
            assert f"doi:{reference.doi.lower()}" in source, reference.key


def test_the_bibtex_of_every_reference_parses_with_its_doi():
    references = [ROUGHCONTACT, *REFERENCES.values()]
    entries = parse_bibtex(bibtex(references))
    assert [key for _, key, _ in entries] == [r.key for r in references]
    for (kind, _, fields), reference in zip(entries, references, strict=True):
        assert kind == reference.kind and fields["title"].startswith("{")
        assert fields.get("doi") == reference.doi
        assert ("author" in fields) == bool(reference.authors)
    assert entries[0][2]["author"] == "{roughcontact developers}"  # an organisation, not two names
    assert entries[0][2]["version"] == roughcontact.__version__
    assert dict(e[1:] for e in entries)["mindlin1953"]["pages"] == "327--344"


def test_special_characters_are_escaped_and_the_doi_is_kept_verbatim():
    odd = Reference("odd", "article", "Heat & mass {flow}: 5% of x_1 ~ $y$", ("Doe, J.",), doi="10.1/a_b")
    ((_, _, fields),) = parse_bibtex(bibtex([odd]))
    assert fields["title"] == r"{Heat \& mass \{flow\}: 5\% of x\_1 \textasciitilde{} \$y\$}"
    assert fields["doi"] == "10.1/a_b"


@pytest.mark.parametrize("reference", [ROUGHCONTACT, *REFERENCES.values()], ids=lambda r: r.key)
def test_a_reference_survives_provenance_json(reference):
    data = reference.to_dict()
    assert list(data)[:5] == ["key", "authors", "title", "year", "doi"]
    assert Reference.from_dict(data) == reference
    assert reference.title.rstrip(".") in reference.citation()


def test_citation_cff_names_this_version_license_and_the_seed_papers():
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert cff["cff-version"] == "1.2.0"
    assert cff["version"] == project["version"] == roughcontact.__version__
    assert cff["license"] == project["license"]
    assert cff["title"] == ROUGHCONTACT.title
    assert [a["name"] for a in cff["authors"]] == list(ROUGHCONTACT.authors)
    assert cff["abstract"] and cff["keywords"]
    seeds = [REFERENCES[f"paper00{i}"] for i in range(3)]
    assert [r["title"] for r in cff["references"]] == [s.title for s in seeds]
    assert [r.get("doi") for r in cff["references"]] == [s.doi for s in seeds]
