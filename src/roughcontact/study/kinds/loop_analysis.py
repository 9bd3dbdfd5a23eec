r"""Study kind ``loop_analysis``: a friction loop analysed as paper 001 does (stroke, mu, K_L).

One case is one record of tangential displacement and friction force at a constant normal force
F0 (a CSV file, :func:`roughcontact.experiment.friction_loop.read_loop_csv`: columns found by name,
``#`` comments, units from the header or, where it gives none, ``displacement_unit`` /
``force_unit``; no unit is assumed). The record is measured, reconstructed or synthetic as its
file's ``# origin:`` line says (:mod:`roughcontact.origin`), and the words follow it: the table
``loop`` names it (``synthetic: paper001_measured_loop.csv``) with a note, and so do the figure's
legend and title. It wraps :func:`roughcontact.experiment.friction_loop.analyse_loop`:

* the record is split into monotonic branches at its reversals, and the last complete loop (the
  converged cycle, paper 001 sec. 4) is kept; its stroke d_s = max - min of the displacement;
* mu = mean |F| on the gross-sliding plateaus / F0 (sec. 4);
* paper 001 eq. 9, F = c1 (1 - (1 - c2 delta)^n), fitted to the pre-sliding part of each branch
  from its reversal, and K_L = c1 c2 n (1 - c2 delta)^(n - 1) at the points A, B, C where the
  fitted force change reaches ``fractions`` (0.25, 0.5, 0.75) of the branch's span (Fig. 10);
* the energy dissipated per cycle, the area of the last loop.

The rules where the paper is silent (reversal force, plateau, point D) are those of
:mod:`roughcontact.experiment.friction_loop`. The file is read when the study is validated.

Scalars: :meth:`~roughcontact.experiment.friction_loop.LoopAnalysis.scalars` (stroke, mu,
normal_force, energy, c1, c2, n, span, direction, fraction_X, K_L_X, delta_X, distance_X for the
points X, and distance_D). Dataset: the record, its last loop, the eq. 9 fits and the points, with
the record's origin in its attributes (``origin``, ``origin_declared``, ``by_construction``).
Figure: ``loop`` (the record, named by its origin, the last loop, both fits, the points A, B, C with
their K_L). Table: ``loop`` (each record's origin, file, stroke, mu and K_L at A, B, C; its notes
say what the record is).

References
----------
Seed paper 001, sec. 4, sec. 5 eq. 9 and Fig. 10. doi:10.1115/1.4045900
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...experiment.friction_loop import LoopAnalysis
from ...origin import DataOrigin, Origin
from ..kind import CaseOutput, CaseParameters, Kind, figure
from ..schema import Force, ForceUnit, LengthUnit


class LoopAnalysisParameters(CaseParameters):
    """Keys of a ``model = "loop_analysis"`` analysis (SI after validation).

    Attributes
    ----------
    loop : Path
        The record: a CSV of displacement and force (and optionally time), relative to the study file.
    displacement_unit, force_unit : str or None
        Units of its columns where the header gives none (no default: a column without a unit in
        its header needs one); one that contradicts the header is refused, naming the header cell.
    normal_force : float
        F0 of the record [N] (mu = plateau force / F0).
    fractions : list of float
        Fractions of the pre-sliding span at the points A, B, C (paper 001 marks them on Fig. 10
        only; default 0.25, 0.5, 0.75).
    branch : {"increasing", "decreasing"}
        The branch of the last loop whose points are reported (default: along increasing
        displacement, as the paper's Fig. 10).
    """

    loop: Path
    displacement_unit: LengthUnit | None = None
    force_unit: ForceUnit | None = None
    normal_force: Annotated[Force, Field(gt=0.0, allow_inf_nan=False)]
    fractions: list[float] = Field(default_factory=lambda: [0.25, 0.5, 0.75], min_length=1, max_length=9)
    branch: str = "increasing"

    @model_validator(mode="after")
    def _points(self) -> LoopAnalysisParameters:
        if any(not 0.0 < f < 1.0 for f in self.fractions):
            raise PydanticCustomError(
                "quantity",
                "fractions {fractions} must each lie in (0, 1)",
                {"fractions": self.fractions, "fix": "e.g. fractions = [0.25, 0.5, 0.75]"},
            )
        if self.branch not in ("increasing", "decreasing"):
            raise PydanticCustomError(
                "quantity",
                "unknown branch {branch!r}",
                {"branch": self.branch, "fix": "use 'increasing' or 'decreasing'"},
            )
        return self


def _read(parameters: LoopAnalysisParameters):
    from ...experiment.friction_loop import read_loop_csv

    return read_loop_csv(parameters.loop, parameters.displacement_unit, parameters.force_unit)


def check(parameters: LoopAnalysisParameters) -> None:
    """Read the record at validation time (its errors name the file, row or column)."""
    _read(parameters)


def run(parameters: LoopAnalysisParameters, inputs) -> CaseOutput:
    """Analyse the last loop of the record; scalars and dataset of :class:`LoopAnalysis`."""
    from ...experiment.friction_loop import analyse_loop

    loop = _read(parameters)
    analysis = analyse_loop(
        loop.displacement,
        loop.force,
        parameters.normal_force,
        fractions=tuple(parameters.fractions),
        branch=parameters.branch,
    )
    dataset = analysis.to_xarray()
    dataset.attrs |= {
        "origin": loop.origin.word,
        "origin_declared": int(loop.origin.declared),
        "by_construction": loop.origin.by_construction or "",
    }
    return CaseOutput(analysis.scalars(), dataset)


def record_origin(record) -> DataOrigin | None:
    """Return the origin of a case's record: as its run stored it, else as its file says now.

    None where neither is at hand (a run by an earlier roughcontact whose file is gone).
    """
    dataset = record.dataset() if record.has_fields else None
    if dataset is not None and "origin" in dataset.attrs:
        return DataOrigin(
            Origin(str(dataset.attrs["origin"])),
            str(dataset.attrs.get("by_construction") or "") or None,
            bool(dataset.attrs.get("origin_declared", 0)),
        )
    path = Path(record.parameters["loop"])
    if not path.is_file():
        return None
    from ..._text_table import read_text_table

    return read_text_table(path, expected="displacement,force rows").origin("loop")


def origin_note(name: str, origin: DataOrigin) -> str:
    """Say in a sentence what the record ``name`` is, and so what its numbers describe."""
    said = "its '# origin:' line says so" if origin.declared else "its file does not say otherwise"
    if origin.is_measured:
        return f"The loop {name} is measured ({said})."
    text = (
        f"The loop {name} is {origin.words} ({said}): its stroke, mu and K_L describe what it was made "
        "from, not a measurement."
    )
    if origin.by_construction:
        text += f" It was built from this model's own output ({origin.by_construction})."
    return text


def _loop_table(records, context):
    """Tabulate each record by its origin (measured, reconstructed, synthetic) with its headline numbers."""
    from ..store import Table

    rows, notes = [], []
    for record in records:
        if not record.done:
            continue
        origin = record_origin(record)
        name = Path(record.parameters["loop"]).name
        word = "origin unknown (not stored, file gone)" if origin is None else origin.word
        row = {"case": record["case"], "loop": f"{word}: {name}"}
        row |= {
            f"{key} [{LoopAnalysis.UNITS[key]}]" if LoopAnalysis.UNITS.get(key) else key: record.scalars.get(
                key
            )
            for key in ("normal_force", "stroke", "mu", "K_L_A", "K_L_B", "K_L_C")
        }
        rows.append(row)
        if origin is not None and (note := origin_note(name, origin)) not in notes:
            notes.append(note)
    return Table(rows, notes) if rows else None


KIND = Kind(
    name="loop_analysis",
    summary="a friction loop (measured or synthetic, as its file's '# origin:' line says) as paper 001 "
    "analyses it: stroke, mu, eq. 9 fit, K_L at A, B, C",
    parameters=LoopAnalysisParameters,
    run=run,
    units=LoopAnalysis.UNITS,
    figures={"loop": figure("presliding.loop_analysis_figure")},
    tables={"loop": _loop_table},
    check=check,
    headline=("stroke", "mu", "energy", "K_L_A", "K_L_B", "K_L_C"),
    references=(
        "paper001",
        "mindlin1953",
        "johnson1985",
    ),
)
