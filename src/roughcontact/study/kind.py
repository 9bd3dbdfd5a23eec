"""What every analysis kind of a study provides: parameters, a run function, units, figures and tables.

A *kind* (``model = "normal"`` in a study file) adapts one of roughcontact's models to the runner:

* ``parameters``: a pydantic schema (a :class:`CaseParameters`) of the analysis' keys, in SI after
  validation; fields typed :data:`~roughcontact.study.schema.TopographyName` or
  :data:`~roughcontact.study.schema.MaterialName` name the study's topographies and materials;
* ``run(parameters, inputs)``: solves one case and returns its scalars and (optionally) an
  ``xarray.Dataset`` of fields and curves; it runs on a Dask worker as well as in-process, so it
  takes and returns only picklable values;
* ``figures`` and ``tables``: drawn and written from *stored* case records only, so
  ``roughcontact plot OUT/`` re-draws them without solving anything again. A figure is a function
  of :mod:`roughcontact.plotting` on cases (usable from Python on results too), wired with
  :func:`figure`; it carries the caption the report prints under it
  (:func:`~roughcontact.plotting.cases.caption`).
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

from ..cases import axis_words
from ..messages import marked
from ..plotting.cases import figure_caption, plotting_function
from ..units import format_si
from .schema import Strict


class CaseParameters(Strict):
    """Keys every analysis accepts besides its model's own.

    Attributes
    ----------
    sample : str
        Label of the sample a case belongs to; cases are grouped by it in figures and in the
        comparison with measured data (paper 000: the three polysilicon samples).
    replicate : int
        Index of a repeated case (paper 000: one of seven scans per sample). With ``sample`` it
        selects the derived seed of every generated topography that has no fixed seed.
    """

    sample: str = ""
    """Label of the sample the case belongs to (groups figures and measured data)."""
    replicate: int = 0
    """Index of a repeated case; selects the derived seeds of generated surfaces."""


def fill_from_paper(data: Any, flag: str, keys: Callable[[Mapping[str, Any]], Mapping[str, Any]]) -> Any:
    """Fill in a paper's scenario where an analysis with ``flag = true`` leaves a key out.

    For a ``model_validator(mode="before")`` of a kind's parameters: ``keys(given)`` returns the
    paper's keys as a study file writes them (with units, from :mod:`roughcontact.papers`), so the
    filled values are validated, stored and shown like typed ones; a key the analysis gives (not
    None) wins. Any other ``data`` is returned unchanged.
    """
    if not isinstance(data, Mapping) or data.get(flag) is not True:
        return data
    given = {key: value for key, value in data.items() if value is not None}
    return {**keys(given), **given}


@dataclass(frozen=True)
class CaseOutput:
    """What a kind's ``run`` returns: scalars (SI, JSON-ready), optional fields and curves, and warnings.

    ``warnings`` say where a finished case left its model's range (an elastic peak pressure beyond
    the small-slope theory, full contact): kept in the case's record, printed by the commands and
    listed in the report, never a reason to drop the numbers.
    """

    scalars: dict[str, Any]
    dataset: Any = None  # xarray.Dataset or None
    warnings: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        """Keep the warnings marked (:mod:`roughcontact.messages`): each door says them in its words."""
        object.__setattr__(self, "warnings", tuple(marked(w) for w in self.warnings))


_LOAD_KEYS = {"mean_pressure": "Pa", "force": "N", "normal_force": "N", "approach": "m", "max_force": "N"}
"""Parameters that name a case's load in its label, first found first, with their SI units."""


@dataclass(frozen=True)
class CaseRecord:
    """A finished (or failed) case as stored in ``OUT/cases/ANALYSIS/CASE.json``.

    Attributes
    ----------
    data : dict
        The JSON record: ``analysis``, ``case``, ``status``, ``parameters`` (SI), ``axes`` (the
        swept values as written), ``scalars``, ``seconds``, ``fields`` (path of the NetCDF file, or
        None), ``fields_sha256`` and ``fields_bytes`` (that file as written), ``error``, and
        ``checksum`` (of the record's own content, :func:`roughcontact.study.store.sealed`).
    folder : Path
        The study's output folder (relative field paths are relative to it).
    """

    data: dict[str, Any]
    folder: Path

    @classmethod
    def read(cls, path: Path, folder: Path) -> CaseRecord:
        """Read a record file as it is (:func:`roughcontact.study.store.stored_case` verifies it).

        Raises
        ------
        ValueError
            The file is not a JSON object (truncated, damaged, or not a record).
        """
        data = json.loads(path.read_text())
        if not isinstance(data, dict):
            raise ValueError(f"{path} holds a JSON {type(data).__name__}, not a case record")
        return cls(data, folder)

    def __getitem__(self, key: str) -> Any:
        return self.data[key]

    @property
    def parameters(self) -> dict[str, Any]:
        """The case's validated parameters (SI)."""
        return self.data["parameters"]

    @property
    def scalars(self) -> dict[str, Any]:
        """The case's scalar results (SI)."""
        return self.data.get("scalars") or {}

    @property
    def done(self) -> bool:
        """True when the case finished."""
        return self.data.get("status") == "done"

    @property
    def label(self) -> str:
        """A short legend label in words: the swept values as written (``sample A, force 10 uN``).

        A case of no sweep (a command's one case) is named by its surface and its load instead
        (``surface, mean pressure 20 MPa``); the case's hash only when it has neither. Keys are
        written with spaces for underscores: a legend is read, not parsed.
        """
        axes = self.data.get("axes") or {}
        if axes:
            return ", ".join(f"{axis_words(k)} {v}" for k, v in axes.items())
        parameters = self.parameters
        parts = [str(parameters[k]) for k in ("sample", "topography") if parameters.get(k)][:1]
        for key, unit in _LOAD_KEYS.items():
            if isinstance(parameters.get(key), int | float):
                parts.append(f"{axis_words(key)} {format_si(parameters[key], unit)}")
                break
        return ", ".join(parts) or self.data["case"]

    @property
    def has_fields(self) -> bool:
        """Whether the case stored fields and curves (:meth:`dataset`)."""
        return self.fields_path is not None

    @cached_property
    def fields_path(self) -> Path | None:
        """Where the case's NetCDF file is (None when the case stored none)."""
        fields = self.data.get("fields")
        return None if fields is None else self.folder / fields

    def dataset(self):
        """Load the case's fields and curves as an ``xarray.Dataset`` (None when it has none)."""
        import xarray as xr

        path = self.fields_path
        if path is None or not path.exists():
            return None
        return xr.load_dataset(path)


@dataclass(frozen=True)
class FigureContext:
    """What a figure or table function gets besides its analysis' records.

    Attributes
    ----------
    analysis : str
        The analysis' name.
    compare : Strict or None
        The validated ``[analysis.compare]`` table (measured data), or None.
    others : mapping
        Name -> (model, finished records) of the study's other analyses, for figures that overlay
        them (paper 002's Fig. 7: the statistical KKE curve beside the BEM island's).
    """

    analysis: str
    compare: Any = None
    others: Mapping[str, tuple[str, Sequence[CaseRecord]]] = field(default_factory=dict)


FigureFunction = Callable[[Sequence[CaseRecord], FigureContext], Any]
"""Draws one figure from the analysis' finished cases; returns a matplotlib Figure, or None to skip."""

TableFunction = Callable[[Sequence[CaseRecord], FigureContext], list[dict[str, Any]] | None]
"""Derives one table (a list of rows) from the finished cases; returns None to skip."""


@dataclass(frozen=True)
class figure:  # noqa: N801 - used like a function in the kinds' tables of figures
    """A figure function of :mod:`roughcontact.plotting`, wired as one of a kind's figures.

    ``figure("adhesion.force_approach_figure")`` names ``draw`` in its plotting module, imported
    when the figure is drawn or its caption read (matplotlib is not loaded to validate a study).
    ``draw(records, **keywords)`` takes the analysis' records as its cases; each keyword is what
    ``inputs[name](records, context)`` returns (the measured data of ``[analysis.compare]``, the
    curves of the study's other analyses).
    """

    name: str
    inputs: Mapping[str, Callable[[Sequence[CaseRecord], FigureContext], Any]] = field(default_factory=dict)

    @property
    def draws(self) -> Callable[..., Any]:
        """The plotting function."""
        return plotting_function(self.name)

    @property
    def caption(self) -> str:
        """The plotting function's caption."""
        return figure_caption(self.draws)

    def __call__(self, records: Sequence[CaseRecord], context: FigureContext):
        """Draw the figure of ``records``; a Figure, or None where the cases do not make it."""
        return self.draws(records, **{name: read(records, context) for name, read in self.inputs.items()})


@dataclass(frozen=True)
class Kind:
    """One analysis kind: see the module docstring.

    Attributes
    ----------
    name : str
        The ``model = "..."`` value.
    summary : str
        One line for ``roughcontact validate`` and the report.
    parameters : type of CaseParameters
        The schema of the analysis' keys.
    run : callable
        ``run(parameters, inputs) -> CaseOutput``.
    units : mapping
        Scalar name -> SI unit, for the table's column headers.
    figures, tables : mapping
        Name -> function drawing a figure or deriving a table from stored records.
    compare : type of Strict, optional
        Schema of the analysis' ``[analysis.compare]`` table (measured data), if it takes one.
    check : callable, optional
        ``check(parameters)``: reads a case's input files (its Path keys, resolved relative to the
        study file) at validation time and raises :class:`~roughcontact.errors.InputError` naming
        the problem, so a bad file fails ``roughcontact validate``, not a case half-way through a run.
    check_inputs : callable, optional
        ``check_inputs(parameters, known)``: a case's checks that need its materials and the grids
        of its topographies but not their heights (``known.material(name)``, ``known.grid(name)``
        -> ``(shape, size)`` or None; :class:`roughcontact.study.config.KnownInputs`), run at
        validation time: a load the scan cannot carry fails ``roughcontact validate`` as the run
        would.
    headline : tuple of str
        The scalars a command prints per case when it runs several (a sweep), besides the swept
        values; one case prints all of them.
    renamed : mapping
        Deprecated key -> its key now (the spellings of release 0.1); a study that still uses one
        validates, with a note saying what to write instead.
    missing : mapping
        Scalar name -> why a case may have no value of it (``"no jump on loading"``): the tables
        and summaries show such a value as ``none (no jump on loading)`` rather than a bare unit.
    references : tuple of str
        Keys of :data:`roughcontact.references.REFERENCES`: the papers and books the model
        implements, listed in a study's ``provenance.json`` and printed by ``roughcontact cite``.
    bounds : mapping
        Scalar name -> the range it can take, ``(low, high)``, or None for unbounded, where
        :func:`roughcontact.spread.natural_bounds` cannot tell it from the name and unit (a
        modulus or a hardness is positive, a stress is not): the spread table cuts a 95 %
        interval over realisations at it, with a note. Names not listed take the natural bounds.
    """

    name: str
    summary: str
    parameters: type[CaseParameters]
    run: Callable[[Any, Any], CaseOutput]
    units: Mapping[str, str] = field(default_factory=dict)
    figures: Mapping[str, FigureFunction] = field(default_factory=dict)
    tables: Mapping[str, TableFunction] = field(default_factory=dict)
    compare: type[Strict] | None = None
    check: Callable[[Any], None] | None = None
    check_inputs: Callable[[Any, Any], None] | None = None
    headline: tuple[str, ...] = ()
    renamed: Mapping[str, str] = field(default_factory=dict)
    missing: Mapping[str, str] = field(default_factory=dict)
    references: tuple[str, ...] = ()
    bounds: Mapping[str, tuple[float, float] | None] = field(default_factory=dict)

    def bounds_of(self, name: str) -> tuple[float, float] | None:
        """Return the range the scalar ``name`` can take: :attr:`bounds`, else its natural bounds."""
        from ..spread import natural_bounds

        if name in self.bounds:
            return self.bounds[name]
        return natural_bounds(name, self.units.get(name))
