"""A validated study: :class:`Study`, its :class:`Analysis` tables and their :class:`Case` records.

What :func:`~roughcontact.study.config.build_study` makes of a study document (through
:class:`~roughcontact.study.builder.StudyBuilder`), or :class:`StudyError` with every problem.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from ..errors import InputError
from ..materials import Material
from ..topography import Topography
from .kind import CaseParameters, Kind
from .problems import Problem
from .schema import Strict


class StudyError(InputError):
    """A study with problems; ``problems`` lists each (a :class:`~roughcontact.study.problems.Problem`).

    Each problem iterates as (field, problem, fix) and keeps the path of its value in the study
    document, so the command line can name the option the user typed.
    """

    def __init__(self, source: str, problems: list[Problem]):
        problems = list(dict.fromkeys(problems))  # a table's problem is met again by each case using it
        self.problems = problems
        lines = [f"{field}: {problem}" + (f" Fix: {fix}" if fix else "") for field, problem, fix in problems]
        count = f"{len(problems)} problem" + ("s" if len(problems) > 1 else "")
        super().__init__(source, f"{count} in the study file:\n  " + "\n  ".join(lines))


@dataclass(frozen=True)
class Case:
    """One case of an analysis: validated parameters and the inputs they name.

    Attributes
    ----------
    analysis : str
        Name of its analysis.
    index : int
        Position in the analysis' sweep (0-based).
    axes : dict
        The swept values of this case, as written in the study file (for tables and legends).
    parameters : CaseParameters
        Validated parameters of the kind, in SI.
    topographies : dict
        Name -> specification (pydantic) of every topography the case uses, with sweep overrides
        applied and derived seeds filled in.
    materials : dict
        Name -> :class:`~roughcontact.materials.Material` of every material the case uses.
    key : str
        SHA-256 of everything that determines the result; a stored case is reused only if its key
        matches.
    """

    analysis: str
    index: int
    axes: dict[str, Any]
    parameters: CaseParameters
    topographies: dict[str, Strict]
    materials: dict[str, Material]
    key: str

    @property
    def case_id(self) -> str:
        """File name stem of the case: the first 16 hex digits of its key.

        Only the key, not the position in the sweep: extending an axis leaves the other cases'
        names, and so their stored results, as they were.
        """
        return self.key[:16]

    @property
    def seeds(self) -> dict[str, int]:
        """Seed of every generated topography the case uses."""
        return {
            name: spec.seed
            for name, spec in self.topographies.items()
            if getattr(spec, "seed", None) is not None
        }


@dataclass(frozen=True)
class Analysis:
    """An ``[[analysis]]`` table: its kind, cases, figures and comparison with measured data.

    ``realisations`` counts the distinct ``replicate`` values of its cases; ``redrawn`` names the
    generated random topographies whose seed changes between them, ``drawn_once`` those drawn
    with one seed in every case (every number rests on that one draw).
    """

    name: str
    kind: Kind
    cases: tuple[Case, ...]
    figures: tuple[str, ...]
    compare: Strict | None
    sweep_axes: tuple[str, ...]
    realisations: int = 1
    redrawn: tuple[str, ...] = ()
    drawn_once: tuple[str, ...] = ()


@dataclass(frozen=True)
class Study:
    """A validated study file.

    Attributes
    ----------
    path : Path or None
        The study file (resolved); None for a study a command built from its options.
    name, description : str
        From ``[study]``.
    seed : int
        Base of the derived seeds.
    text : str
        The file as written (kept in the output folder and the provenance).
    analyses : tuple of Analysis
    files : dict
        Path -> SHA-256 of every input file (topographies and measured data).
    loaded : dict
        Specification JSON -> Topography of every file topography, read once during validation.
    notes : tuple of str
        What the user should know but that does not stop the study (deprecated spellings).
    prepared : dict
        Name -> :func:`~roughcontact.study.builder.preparation` of every file topography
        (levelling, filled points).
    device : {"cpu", "gpu"}
        From ``[study]``: where the cases' normal contact solves run.
    """

    path: Path | None
    name: str
    description: str
    seed: int
    text: str
    analyses: tuple[Analysis, ...]
    files: dict[str, str]
    loaded: dict[str, Topography]
    notes: tuple[str, ...] = ()
    prepared: dict[str, dict] = field(default_factory=dict)
    device: str = "cpu"

    @property
    def cases(self) -> list[Case]:
        """Every case of every analysis, in order."""
        return [case for analysis in self.analyses for case in analysis.cases]

    def analysis(self, name: str) -> Analysis:
        """Return the analysis called ``name``."""
        for analysis in self.analyses:
            if analysis.name == name:
                return analysis
        raise KeyError(name)


class StudySection(Strict):
    """The ``[study]`` table."""

    name: str
    description: str = ""
    seed: int = 0
    device: Literal["cpu", "gpu"] = "cpu"
    """Where the normal contact solves of the cases run (``roughcontact[gpu]`` for "gpu"); the
    answers do not depend on it, so it is no part of a case's key."""
