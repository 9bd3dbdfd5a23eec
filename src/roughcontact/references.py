"""The papers and books roughcontact's models implement, and BibTeX for them.

Every study model names the references it implements (``Kind.references``, keys of
:data:`REFERENCES`); a study lists the union over its analyses, with :data:`ROUGHCONTACT` itself, in
``provenance.json``, and ``roughcontact cite OUT/`` prints them as BibTeX (:func:`bibtex`).

The entries are those the module docstrings cite (same authors, year and DOI; no DOI where the
work has none, as Cattaneo 1938). The three seed papers carry only what their texts print: paper
001's journal, year and DOI; paper 000's and paper 002's titles (their authors, journals, years and
DOIs are not given in the seed texts, so they are left out rather than guessed).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from ._version import __version__


@dataclass(frozen=True)
class Reference:
    """One cited work.

    Attributes
    ----------
    key : str
        Its BibTeX key (``polonsky1999``), also its key in :data:`REFERENCES`.
    kind : str
        The BibTeX entry type: ``"article"``, ``"book"`` or ``"software"``.
    title : str
        The title as published.
    authors : tuple of str
        ``"Family, G. N."`` each; an organisation without a comma (``"roughcontact developers"``).
        Empty where the source does not give them.
    year : int or None
        Year of publication, None where not known.
    journal : str
        The journal (articles).
    publisher : str
        The publisher (books).
    volume : str
        The volume (articles).
    pages : str
        First-last page (``"206-219"``) or the article number.
    doi : str or None
        The DOI without ``https://doi.org/``; None where the source gives none.
    version : str
        The version (software).
    note : str
        What a reader should know besides (an edition, what the source does not give).
    """

    key: str
    kind: str
    title: str
    authors: tuple[str, ...] = ()
    year: int | None = None
    journal: str = ""
    publisher: str = ""
    volume: str = ""
    pages: str = ""
    doi: str | None = None
    version: str = ""
    note: str = ""

    def to_dict(self) -> dict[str, Any]:
        """Return the entry as JSON-ready data: key, authors, title, year, doi, then the other fields set."""
        head = {"key": self.key, "authors": list(self.authors), "title": self.title}
        head |= {"year": self.year, "doi": self.doi}
        rest = {name: value for name, value in dataclasses.asdict(self).items() if name not in head}
        return head | {name: value for name, value in rest.items() if value}

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Reference:
        """Return the entry that :meth:`to_dict` wrote (entries unknown to this version are left out)."""
        names = {f.name for f in dataclasses.fields(cls)}
        values = {name: value for name, value in data.items() if name in names}
        return cls(**values | {"authors": tuple(values.get("authors") or ())})

    def citation(self) -> str:
        """Return the entry as one line of text: authors (year). Title. Where published."""
        *others, last = self.authors or ("",)
        names = f"{', '.join(others)} and {last}" if others else last
        year = "" if self.year is None else str(self.year)
        head = f"{names} ({year}). " if names and year else f"{names}. " if names else ""
        where = (
            f"{self.journal} {self.volume}".strip(),
            self.publisher,
            self.version and f"version {self.version}",
            self.pages,
            "" if names else year,
        )
        published = ", ".join(part for part in where if part).rstrip(".")
        return head + self.title.rstrip(".") + "." + (f" {published}." if published else "")


ROUGHCONTACT = Reference(
    key="roughcontact",
    kind="software",
    title="roughcontact: contact mechanics of rough surfaces from measured topographies",
    authors=("roughcontact developers",),
    year=2026,
    version=__version__,
)
"""The package itself (``CITATION.cff`` says the same)."""


REFERENCES: dict[str, Reference] = {
    r.key: r
    for r in (
        Reference(
            key="paper000",
            kind="article",
            title=(
                "Simulation model for frictional contact of two elastic surfaces in micro/nanoscale and its "
                "validation"
            ),
            note="roughcontact's seed paper 000; authors, journal, year and DOI not given in the seed text",
        ),
        Reference(
            key="paper001",
            kind="article",
            title="Evaluation of pre-sliding behavior at a rough interface: modeling and experiment",
            year=2020,
            journal="J. Appl. Mech.",
            doi="10.1115/1.4045900",
            note="roughcontact's seed paper 001; authors, volume and pages not given in the seed text",
        ),
        Reference(
            key="paper002",
            kind="article",
            title="Contact stress analysis of lightly compressed thin films: modeling and experimentation",
            note="roughcontact's seed paper 002; authors, journal, year and DOI not given in the seed text",
        ),
        Reference(
            key="johnson1985",
            kind="book",
            title="Contact Mechanics",
            authors=("Johnson, K. L.",),
            year=1985,
            publisher="Cambridge University Press",
            doi="10.1017/CBO9781139171731",
        ),
        Reference(
            key="israelachvili2011",
            kind="book",
            title="Intermolecular and Surface Forces",
            authors=("Israelachvili, J. N.",),
            year=2011,
            publisher="Academic Press",
            doi="10.1016/C2009-0-21560-1",
            note="3rd edition",
        ),
        Reference(
            key="cattaneo1938",
            kind="article",
            title="Sul contatto di due corpi elastici: distribuzione locale degli sforzi",
            authors=("Cattaneo, C.",),
            year=1938,
            journal="Rend. Accad. Naz. Lincei",
            volume="27",
            pages="342-348, 434-436, 474-478",
        ),
        Reference(
            key="mindlin1949",
            kind="article",
            title="Compliance of elastic bodies in contact",
            authors=("Mindlin, R. D.",),
            year=1949,
            journal="J. Appl. Mech.",
            volume="16",
            pages="259-268",
            doi="10.1115/1.4009973",
        ),
        Reference(
            key="mindlin1953",
            kind="article",
            title="Elastic spheres in contact under varying oblique forces",
            authors=("Mindlin, R. D.", "Deresiewicz, H."),
            year=1953,
            journal="J. Appl. Mech.",
            volume="20",
            pages="327-344",
            doi="10.1115/1.4010702",
        ),
        Reference(
            key="greenwood1966",
            kind="article",
            title="Contact of nominally flat surfaces",
            authors=("Greenwood, J. A.", "Williamson, J. B. P."),
            year=1966,
            journal="Proc. R. Soc. Lond. A",
            volume="295",
            pages="300-319",
            doi="10.1098/rspa.1966.0242",
        ),
        Reference(
            key="nayak1971",
            kind="article",
            title="Random process model of rough surfaces",
            authors=("Nayak, P. R.",),
            year=1971,
            journal="J. Lubr. Technol.",
            volume="93",
            pages="398-407",
            doi="10.1115/1.3451150",
        ),
        Reference(
            key="johnson1971",
            kind="article",
            title="Surface energy and the contact of elastic solids",
            authors=("Johnson, K. L.", "Kendall, K.", "Roberts, A. D."),
            year=1971,
            journal="Proc. R. Soc. Lond. A",
            volume="324",
            pages="301-313",
            doi="10.1098/rspa.1971.0141",
        ),
        Reference(
            key="derjaguin1975",
            kind="article",
            title="Effect of contact deformations on the adhesion of particles",
            authors=("Derjaguin, B. V.", "Muller, V. M.", "Toporov, Yu. P."),
            year=1975,
            journal="J. Colloid Interface Sci.",
            volume="53",
            pages="314-326",
            doi="10.1016/0021-9797(75)90018-1",
        ),
        Reference(
            key="mccool1986",
            kind="article",
            title="Comparison of models for the contact of rough surfaces",
            authors=("McCool, J. I.",),
            year=1986,
            journal="Wear",
            volume="107",
            pages="37-60",
            doi="10.1016/0043-1648(86)90045-1",
        ),
        Reference(
            key="chang1987",
            kind="article",
            title="An elastic-plastic model for the contact of rough surfaces",
            authors=("Chang, W. R.", "Etsion, I.", "Bogy, D. B."),
            year=1987,
            journal="J. Tribol.",
            volume="109",
            pages="257-263",
            doi="10.1115/1.3261348",
        ),
        Reference(
            key="oliver1992",
            kind="article",
            title=(
                "An improved technique for determining hardness and elastic modulus using load and "
                "displacement sensing indentation experiments"
            ),
            authors=("Oliver, W. C.", "Pharr, G. M."),
            year=1992,
            journal="J. Mater. Res.",
            volume="7",
            pages="1564-1583",
            doi="10.1557/JMR.1992.1564",
        ),
        Reference(
            key="maugis1992",
            kind="article",
            title="Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
            authors=("Maugis, D.",),
            year=1992,
            journal="J. Colloid Interface Sci.",
            volume="150",
            pages="243-269",
            doi="10.1016/0021-9797(92)90285-T",
        ),
        Reference(
            key="girifalco1957",
            kind="article",
            title=(
                "A theory for the estimation of surface and interfacial energies. I. Derivation and "
                "application to interfacial tension"
            ),
            authors=("Girifalco, L. A.", "Good, R. J."),
            year=1957,
            journal="J. Phys. Chem.",
            volume="61",
            pages="904-909",
            doi="10.1021/j150553a013",
        ),
        Reference(
            key="welch1947",
            kind="article",
            title=(
                "The generalization of 'Student's' problem when several different population variances are "
                "involved"
            ),
            authors=("Welch, B. L.",),
            year=1947,
            journal="Biometrika",
            volume="34",
            pages="28-35",
            doi="10.1093/biomet/34.1-2.28",
        ),
        Reference(
            key="greenwood1997",
            kind="article",
            title="Adhesion of elastic spheres",
            authors=("Greenwood, J. A.",),
            year=1997,
            journal="Proc. R. Soc. Lond. A",
            volume="453",
            pages="1277-1297",
            doi="10.1098/rspa.1997.0070",
        ),
        Reference(
            key="johnson1997",
            kind="article",
            title="An adhesion map for the contact of elastic spheres",
            authors=("Johnson, K. L.", "Greenwood, J. A."),
            year=1997,
            journal="J. Colloid Interface Sci.",
            volume="192",
            pages="326-333",
            doi="10.1006/jcis.1997.4984",
        ),
        Reference(
            key="stanley1997",
            kind="article",
            title="An FFT-based method for rough surface contact",
            authors=("Stanley, H. M.", "Kato, T."),
            year=1997,
            journal="J. Tribol.",
            volume="119",
            pages="481-485",
            doi="10.1115/1.2833523",
        ),
        Reference(
            key="polonsky1999",
            kind="article",
            title=(
                "A numerical method for solving rough contact problems based on the multi-level "
                "multi-summation and conjugate gradient techniques"
            ),
            authors=("Polonsky, I. A.", "Keer, L. M."),
            year=1999,
            journal="Wear",
            volume="231",
            pages="206-219",
            doi="10.1016/S0043-1648(99)00113-1",
        ),
        Reference(
            key="liu2000",
            kind="article",
            title="A versatile method of discrete convolution and FFT (DC-FFT) for contact analyses",
            authors=("Liu, S.", "Wang, Q.", "Liu, G."),
            year=2000,
            journal="Wear",
            volume="243",
            pages="101-111",
            doi="10.1016/S0043-1648(00)00427-0",
        ),
        Reference(
            key="kogut2002",
            kind="article",
            title="Elastic-plastic contact analysis of a sphere and a rigid flat",
            authors=("Kogut, L.", "Etsion, I."),
            year=2002,
            journal="J. Appl. Mech.",
            volume="69",
            pages="657-662",
            doi="10.1115/1.1490373",
        ),
        Reference(
            key="jacq2002",
            kind="article",
            title="Development of a three-dimensional semi-analytical elastic-plastic contact code",
            authors=("Jacq, C.", "Nélias, D.", "Lormand, G.", "Girodin, D."),
            year=2002,
            journal="J. Tribol.",
            volume="124",
            pages="653-667",
            doi="10.1115/1.1467920",
        ),
        Reference(
            key="feng2002",
            kind="article",
            title="Effects of creep and thermal drift on modulus measurement using depth-sensing indentation",
            authors=("Feng, G.", "Ngan, A. H. W."),
            year=2002,
            journal="J. Mater. Res.",
            volume="17",
            pages="660-668",
            doi="10.1557/JMR.2002.0094",
        ),
        Reference(
            key="tang2003",
            kind="article",
            title=(
                "Accurate measurement of tip-sample contact size during nanoindentation of viscoelastic "
                "materials"
            ),
            authors=("Tang, B.", "Ngan, A. H. W."),
            year=2003,
            journal="J. Mater. Res.",
            volume="18",
            pages="1141-1148",
            doi="10.1557/JMR.2003.0156",
        ),
        Reference(
            key="perriot2004",
            kind="article",
            title="Elastic contact to a coated half-space: effective elastic modulus and real penetration",
            authors=("Perriot, A.", "Barthel, E."),
            year=2004,
            journal="J. Mater. Res.",
            volume="19",
            pages="600-608",
            doi="10.1557/jmr.2004.19.2.600",
        ),
        Reference(
            key="frigo2005",
            kind="article",
            title="The design and implementation of FFTW3",
            authors=("Frigo, M.", "Johnson, S. G."),
            year=2005,
            journal="Proc. IEEE",
            volume="93",
            pages="216-231",
            doi="10.1109/JPROC.2004.840301",
        ),
        Reference(
            key="jackson2005",
            kind="article",
            title="A finite element study of elasto-plastic hemispherical contact against a rigid flat",
            authors=("Jackson, R. L.", "Green, I."),
            year=2005,
            journal="J. Tribol.",
            volume="127",
            pages="343-354",
            doi="10.1115/1.1866166",
        ),
        Reference(
            key="etsion2005",
            kind="article",
            title="Unloading of an elastic-plastic loaded spherical contact",
            authors=("Etsion, I.", "Kligerman, Y.", "Kadin, Y."),
            year=2005,
            journal="Int. J. Solids Struct.",
            volume="42",
            pages="3716-3729",
            doi="10.1016/j.ijsolstr.2004.12.006",
        ),
        Reference(
            key="kadin2006",
            kind="article",
            title="Unloading an elastic-plastic contact of rough surfaces",
            authors=("Kadin, Y.", "Kligerman, Y.", "Etsion, I."),
            year=2006,
            journal="J. Mech. Phys. Solids",
            volume="54",
            pages="2652-2674",
            doi="10.1016/j.jmps.2006.07.005",
        ),
        Reference(
            key="almqvist2007",
            kind="article",
            title="On the dry elasto-plastic contact of nominally flat surfaces",
            authors=("Almqvist, A.", "Sahlin, F.", "Larsson, R.", "Glavatskih, S."),
            year=2007,
            journal="Tribol. Int.",
            volume="40",
            pages="574-579",
            doi="10.1016/j.triboint.2005.11.008",
        ),
        Reference(
            key="pastewka2014",
            kind="article",
            title="Contact between rough surfaces and a criterion for macroscopic adhesion",
            authors=("Pastewka, L.", "Robbins, M. O."),
            year=2014,
            journal="Proc. Natl. Acad. Sci.",
            volume="111",
            pages="3298-3303",
            doi="10.1073/pnas.1320846111",
        ),
        Reference(
            key="jacobs2017",
            kind="article",
            title="Quantitative characterization of surface topography using spectral analysis",
            authors=("Jacobs, T. D. B.", "Junge, T.", "Pastewka, L."),
            year=2017,
            journal="Surf. Topogr.: Metrol. Prop.",
            volume="5",
            pages="013001",
            doi="10.1088/2051-672X/aa51f8",
        ),
        Reference(
            key="rey2017",
            kind="article",
            title=(
                "Normal adhesive contact on rough surfaces: efficient algorithm for FFT-based BEM resolution"
            ),
            authors=("Rey, V.", "Anciaux, G.", "Molinari, J.-F."),
            year=2017,
            journal="Comput. Mech.",
            volume="60",
            pages="69-81",
            doi="10.1007/s00466-017-1392-5",
        ),
        Reference(
            key="bazrafshan2019",
            kind="article",
            title="The effect of adhesion and roughness on friction hysteresis loops",
            authors=("Bazrafshan, M.", "de Rooij, M. B.", "Schipper, D. J."),
            year=2019,
            journal="Int. J. Mech. Sci.",
            volume="155",
            pages="9-18",
            note="paper 001's ref. 28, the boundary element model it evaluates; DOI not given there",
        ),
        Reference(
            key="bush1975",
            kind="article",
            title="The elastic contact of a rough surface",
            authors=("Bush, A. W.", "Gibson, R. D.", "Thomas, T. R."),
            year=1975,
            journal="Wear",
            volume="35",
            pages="87-111",
            doi="10.1016/0043-1648(75)90145-3",
        ),
        Reference(
            key="persson2001",
            kind="article",
            title="Theory of rubber friction and contact mechanics",
            authors=("Persson, B. N. J.",),
            year=2001,
            journal="J. Chem. Phys.",
            volume="115",
            pages="3840-3861",
            doi="10.1063/1.1388626",
        ),
        Reference(
            key="hyun2004",
            kind="article",
            title="Finite-element analysis of contact between elastic self-affine surfaces",
            authors=("Hyun, S.", "Pei, L.", "Molinari, J.-F.", "Robbins, M. O."),
            year=2004,
            journal="Phys. Rev. E",
            volume="70",
            pages="026117",
            doi="10.1103/PhysRevE.70.026117",
        ),
        Reference(
            key="persson2006",
            kind="article",
            title="Contact mechanics for randomly rough surfaces",
            authors=("Persson, B. N. J.",),
            year=2006,
            journal="Surf. Sci. Rep.",
            volume="61",
            pages="201-227",
            doi="10.1016/j.surfrep.2006.04.001",
        ),
        Reference(
            key="manners2006",
            kind="article",
            title="Some observations on Persson's diffusion theory of elastic contact",
            authors=("Manners, W.", "Greenwood, J. A."),
            year=2006,
            journal="Wear",
            volume="261",
            pages="600-610",
            doi="10.1016/j.wear.2006.01.007",
        ),
        Reference(
            key="persson2007",
            kind="article",
            title="Relation between interfacial separation and load: a general theory of contact mechanics",
            authors=("Persson, B. N. J.",),
            year=2007,
            journal="Phys. Rev. Lett.",
            volume="99",
            pages="125502",
            doi="10.1103/PhysRevLett.99.125502",
        ),
        Reference(
            key="almqvist2011",
            kind="article",
            title=(
                "Interfacial separation between elastic solids with randomly rough surfaces: comparison "
                "between theory and numerical techniques"
            ),
            authors=("Almqvist, A.", "Campañá, C.", "Prodanov, N.", "Persson, B. N. J."),
            year=2011,
            journal="J. Mech. Phys. Solids",
            volume="59",
            pages="2355-2369",
            doi="10.1016/j.jmps.2011.08.004",
        ),
        Reference(
            key="prodanov2014",
            kind="article",
            title=(
                "On the contact area and mean gap of rough, elastic contacts: dimensional analysis, "
                "numerical corrections, and reference data"
            ),
            authors=("Prodanov, N.", "Dapp, W. B.", "Müser, M. H."),
            year=2014,
            journal="Tribol. Lett.",
            volume="53",
            pages="433-448",
            doi="10.1007/s11249-013-0282-z",
        ),
        Reference(
            key="yastrebov2015",
            kind="article",
            title="From infinitesimal to full contact between rough surfaces: evolution of the contact area",
            authors=("Yastrebov, V. A.", "Anciaux, G.", "Molinari, J.-F."),
            year=2015,
            journal="Int. J. Solids Struct.",
            volume="52",
            pages="83-102",
            doi="10.1016/j.ijsolstr.2014.09.019",
        ),
        Reference(
            key="yastrebov2017",
            kind="article",
            title=(
                "On the accurate computation of the true contact-area in mechanical contact of random rough "
                "surfaces"
            ),
            authors=("Yastrebov, V. A.", "Anciaux, G.", "Molinari, J.-F."),
            year=2017,
            journal="Tribol. Int.",
            volume="114",
            pages="161-171",
            doi="10.1016/j.triboint.2017.04.023",
            note="the perimeter correction of the contact area, c = (pi - 1 + ln 2)/24 per switch",
        ),
        Reference(
            key="frerot2019",
            kind="article",
            title="A Fourier-accelerated volume integral method for elastoplastic contact",
            authors=("Frérot, L.", "Bonnet, M.", "Molinari, J.-F.", "Anciaux, G."),
            year=2019,
            journal="Comput. Methods Appl. Mech. Eng.",
            volume="351",
            pages="951-976",
            doi="10.1016/j.cma.2019.04.006",
        ),
    )
}
"""Key -> :class:`Reference` of every work a study model implements (``Kind.references``)."""


def references_of(keys: Iterable[str]) -> list[Reference]:
    """Return the references of ``keys`` in order, each once (an unknown key raises KeyError)."""
    return [REFERENCES[key] for key in dict.fromkeys(keys)]


def cited(keys: Iterable[str]) -> list[Reference]:
    """Return what to cite for models of these reference ``keys``: roughcontact, then each work once."""
    return [ROUGHCONTACT, *references_of(keys)]


_SPECIAL = str.maketrans(
    {
        "\\": r"\textbackslash{}",
        "{": r"\{",
        "}": r"\}",
        "&": r"\&",
        "%": r"\%",
        "$": r"\$",
        "#": r"\#",
        "_": r"\_",
        "~": r"\textasciitilde{}",
        "^": r"\textasciicircum{}",
    }
)
"""LaTeX's special characters, escaped in every field but the DOI (a verbatim field)."""


def _escape(text: str) -> str:
    return text.translate(_SPECIAL)


def _names(authors: tuple[str, ...]) -> str:
    """BibTeX's author list: ``A and B``; an organisation (no comma) braced, so it is not split into names."""
    return " and ".join(_escape(a) if "," in a else "{" + _escape(a) + "}" for a in authors)


def bibtex(references: Iterable[Reference]) -> str:
    """Return BibTeX entries of ``references``, one blank line between them.

    Titles are double-braced (their capitals kept), page ranges written with ``--``, LaTeX's special
    characters escaped; the DOI is written bare (``doi = {10.1115/1.4045900}``, no ``https://``).
    """
    entries = []
    for ref in references:
        fields = {
            "author": _names(ref.authors),
            "title": "{" + _escape(ref.title) + "}",
            "journal": _escape(ref.journal),
            "publisher": _escape(ref.publisher),
            "year": "" if ref.year is None else str(ref.year),
            "volume": _escape(ref.volume),
            "pages": _escape(ref.pages).replace("-", "--"),
            "version": _escape(ref.version),
            "doi": ref.doi or "",
            "note": _escape(ref.note),
        }
        lines = [f"@{ref.kind}{{{ref.key},"]
        lines += [f"  {name} = {{{value}}}," for name, value in fields.items() if value]
        entries.append("\n".join(lines) + "\n}\n")
    return "\n".join(entries)
