"""Study files: TOML in; a validated :class:`Study` with its cases expanded, or one error with all problems.

Layout of a study file (the documentation's Studies page has the reference, ``examples/*.toml``
the examples)::

    [study]
    name = "rough contact"
    seed = 1                          # derives the seeds of generated surfaces without one

    [topographies.scan]               # a file (units from the file, or given here) ...
    file = "scan.di"
    [topographies.flat]               # ... or a generator ...
    generate = "self_affine"
    shape = 128
    size = "5 um"
    hurst = 0.8
    rms_height = "1 nm"
    [topographies.both]               # ... or the composite of two of them
    combine = ["scan", "flat"]

    [materials.film]                  # library entries need no table: material = "SU-8"
    youngs_modulus = "70 GPa"
    poissons_ratio = 0.17

    [[analysis]]
    name = "contact"
    model = "normal"                  # a kind: roughcontact.study.kinds.KINDS
    surface = "both"
    material = "film"
    mean_pressure = "20 MPa"
    figures = ["contact", "area_load"]     # default: all of the kind's
    [analysis.sweep]                  # Cartesian product of the axes ...
    mean_pressure = ["5 MPa", "10 MPa", "20 MPa"]
    "topographies.flat.hurst" = [0.7, 0.8]    # ... of any parameter, also of a topography or material
    [analysis.zip]                    # ... times one axis of equally long lists taken together
    sample = ["a", "b"]
    "materials.film.youngs_modulus" = ["60 GPa", "80 GPa"]

The sweeps are expanded into cases by :mod:`~roughcontact.study.sweeps`; problems are collected
with their places by :mod:`~roughcontact.study.problems`. A command of the command line builds the
same document from its options and validates it here too (:func:`build_study`).

Every value is validated before anything is computed, and every case is built (its parameters,
materials and topography specifications checked, files read) so that a bad value in the seventh
case of a sweep is reported at once, with the field, the value and the fix.

:func:`build_study` and :func:`load_study` are here; the builder that checks the tables and builds
the cases is :mod:`~roughcontact.study.builder`, what it makes (:class:`Study`, :class:`Case`,
:class:`StudyError`) :mod:`~roughcontact.study.validated`.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

from .._files import read_text
from ..errors import InputError
from .builder import ANALYSIS_KEYS as ANALYSIS_KEYS  # the names config has always served
from .builder import KnownInputs as KnownInputs
from .builder import StudyBuilder
from .builder import preparation as preparation
from .builder import references as references
from .problems import Problem, Where
from .sweeps import expand as expand  # served here as before
from .validated import Analysis as Analysis
from .validated import Case as Case
from .validated import Study, StudyError
from .validated import StudySection as StudySection


def build_study(document: dict, *, folder: Path, text: str, source: str, path: Path | None = None) -> Study:
    """Validate a study document (the TOML structure as a dict) and build every case.

    Parameters
    ----------
    document : dict
        ``study``, ``topographies``, ``materials`` and ``analysis`` tables, values as written
        (``"10 uN"``); from a TOML file (:func:`load_study`) or built by a command.
    folder : Path
        Relative file names in the document are relative to it.
    text : str
        The document as written (kept in the output folder and the provenance).
    source : str
        What the document came from, for messages (the file, or ``"command line"``).
    path : Path, optional
        The study file, where there is one.

    Returns
    -------
    Study

    Raises
    ------
    StudyError
        Listing every problem, each with its place (shown and as a path), value and fix.
    """
    builder = StudyBuilder(folder, document)
    unknown = sorted(set(document) - {"study", "topographies", "materials", "analysis"})
    for key in unknown:
        builder.problem(
            Where((key,), key), "is not a known section.", "use study, topographies, materials, analysis."
        )
    raw_analyses = document.get("analysis", [])
    if not isinstance(raw_analyses, list) or not raw_analyses:
        builder.problem(
            Where(("analysis",), "analysis"),
            "the study has no [[analysis]] table.",
            "add one with name and model.",
        )
        raw_analyses = []
    analyses = [builder.analysis(i, raw) for i, raw in enumerate(raw_analyses)]
    names = [a.name for a in analyses if a is not None]
    for name in {n for n in names if names.count(n) > 1}:
        builder.problem(
            Where(("analysis",), f"analysis ({name})"), "two analyses share this name.", "rename one."
        )
    if builder.problems:
        raise StudyError(source, builder.problems)
    section = builder.section
    return Study(
        path=path,
        name=section.name,
        description=section.description,
        seed=section.seed,
        text=text,
        analyses=tuple(analyses),
        files=builder.files,
        loaded=builder.loaded,
        notes=tuple(dict.fromkeys(builder.notes)),
        prepared=builder.prepared,
        device=section.device,
    )


def load_study(path: str | Path) -> Study:
    """Read a study file (TOML) and validate it with :func:`build_study`.

    ``path``'s relative file names are relative to its folder. Raises :class:`StudyError` for a
    missing file, a file that is not TOML, and every problem :func:`build_study` finds.
    """
    path = Path(path).expanduser().resolve()
    if not path.is_file():
        raise StudyError(
            str(path), [Problem("STUDY", f"study file {str(path)!r} not found.", "check the path.")]
        )
    try:
        text = read_text(path, holds="a study file (TOML text)", utf8_only=True)
    except InputError as error:
        raise StudyError(str(path), [Problem("STUDY", error.problem, error.fix)]) from None
    try:
        document = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise StudyError(
            str(path), [Problem("TOML", f"not valid TOML: {error}.", "fix the syntax at that line.")]
        ) from None
    return build_study(document, folder=path.parent, text=text, source=str(path), path=path)
