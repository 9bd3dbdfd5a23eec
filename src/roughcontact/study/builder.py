"""The study builder: a study document's tables validated and its analyses' cases built, every problem kept.

:class:`StudyBuilder` checks the ``[study]``, topography and material tables once (files are read
here), then builds each ``[[analysis]]`` table's cases: the kind's parameters with the sweeps
expanded, seeds derived, inputs checked (:meth:`~roughcontact.study.kind.Kind.check_inputs` with
:class:`KnownInputs`) and each case's key. :func:`~roughcontact.study.config.build_study` runs it.
"""

from __future__ import annotations

import copy
import difflib
import hashlib
import json
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import BaseModel

from ..errors import InputError, MissingMetadataError, UndefinedPointsError
from ..materials import MATERIALS, Material, get_material
from ..spread import realisation_seed
from ..topography import Topography
from ..topography.io import channel_of
from .kind import CaseParameters, Kind
from .problems import Problem, Where, collect
from .schema import (
    Combined,
    FileTopography,
    MaterialSpec,
    Reference,
    Strict,
    field_metadata,
    topography_schema,
)
from .sweeps import expand
from .validated import Analysis, Case, StudySection

ANALYSIS_KEYS = ("name", "model", "sweep", "zip", "figures", "compare", "realisations")
"""Keys of an ``[[analysis]]`` table that are not parameters of its model."""


def references(schema: type[BaseModel], kind: str) -> list[str]:
    """Names of the fields of ``schema`` that refer to a topography or a material (``kind``)."""
    return [
        name
        for name in schema.model_fields
        if any(isinstance(m, Reference) and m.kind == kind for m in field_metadata(schema, name))
    ]


def _drawn(spec: Strict) -> bool:
    """Return whether a topography is a random draw (a generated surface with a seed)."""
    return "seed" in type(spec).model_fields and getattr(spec, "generate", None) is not None


def _file_hash(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def preparation(spec: FileTopography, topography: Topography) -> dict[str, Any]:
    """Return what was done to a measured file before use: grid, size, filling and levelling (JSON-ready).

    Printed by the commands, kept in ``provenance.json`` and shown in the report, so that a result
    is never read without knowing whether its scan was levelled or partly interpolated.
    """
    filled = int(topography.info.get("undefined_points_filled", 0))
    return {
        "file": Path(spec.file).name,
        "channel": channel_of(topography.info),
        "grid": list(topography.shape),
        "size_m": list(topography.size),
        "detrend": topography.info.get("detrend", spec.levelling),
        "undefined_points_filled": filled,
        "undefined_fraction_filled": filled / topography.heights.size,
        "filled_excluded_from_contact": bool(spec.exclude_filled and filled),
        "specks": 0 if topography.specks is None else int(topography.specks.sum()),
        "specks_removed": int(topography.info.get("specks_removed", 0)),
    }


@dataclass(frozen=True)
class KnownInputs:
    """What validation knows of a case's inputs before building them: materials, and grids of topographies.

    Passed to a kind's ``check_inputs`` (:class:`~roughcontact.study.kind.Kind`).
    """

    specs: dict[str, Any]
    loaded: dict[str, Topography]
    materials: dict[str, Material]

    def material(self, name: str | None) -> Material | None:
        """Return the material called ``name`` (None for None: rigid)."""
        return None if name is None else self.materials.get(name)

    def check_pair(self, first: str, second: str | None, resample: bool) -> None:
        """Refuse two topographies merged without ``resample`` whose grids differ (known ones only).

        Raises
        ------
        InputError
            Field ``counter_topography``, with the fix ``resample = true``.
        """
        from ..topography.process import check_same_grid

        grids = (self.grid(first), None if second is None else self.grid(second))
        if resample or None in grids:
            return
        try:
            check_same_grid(*grids)
        except InputError as error:
            raise InputError(
                "counter_topography",
                error.problem,
                "add «resample=true» to interpolate both onto a common grid, or bring the scans to one grid.",
            ) from None

    def grid(self, name: str) -> tuple[tuple[int, ...], tuple[float, ...]] | None:
        """Return (shape, size [m]) of topography ``name``; None where it is known only once built."""
        from ..topography.generate import grid_of

        spec = self.specs.get(name)
        if isinstance(spec, FileTopography):
            topography = self.loaded.get(spec.model_dump_json())
            return None if topography is None else (topography.shape, topography.size)
        if hasattr(spec, "grid"):  # a paper's generator
            return spec.grid
        if hasattr(spec, "shape") and hasattr(spec, "size"):
            return grid_of(spec.shape, spec.size)
        return None


class StudyBuilder:
    """Validates the study's tables and builds the cases of its analyses, collecting every problem.

    :func:`~roughcontact.study.config.build_study` makes one per document: it checks the
    ``[study]``, ``[topographies.*]`` and ``[materials.*]`` tables once (reading the files),
    then :meth:`analysis` builds each ``[[analysis]]`` table's cases; every problem is recorded
    with its place in :attr:`problems`.
    """

    def __init__(self, folder: Path, document: dict):
        self.folder = folder
        self.document = document
        self.problems: list[Problem] = []
        self.files: dict[str, str] = {}
        self.loaded: dict[str, Topography] = {}
        self.prepared: dict[str, dict] = {}
        self.notes: list[str] = []
        self.section = collect(
            self.problems, Where(("study",), "study"), StudySection, document.get("study", {})
        )
        if self.section is not None and self.section.device == "gpu":
            self._check_gpu()
        self.raw_topographies = self._tables("topographies")
        self.raw_materials = self._tables("materials")
        for name, raw in self.raw_topographies.items():  # report bad tables once, not per case
            spec = self._topography_spec(name, raw)
            if isinstance(spec, FileTopography):
                self.prepared[name] = preparation(spec, self.loaded[spec.model_dump_json()])
        for name, raw in self.raw_materials.items():
            self._material(name, raw)

    def problem(self, where: Where, problem: str, fix: str | None, cli_fix: str | None = None) -> None:
        """Record a problem at ``where`` (``cli_fix``: its fix in the command line's words, if known)."""
        self.problems.append(Problem(where.label, problem, fix, where.path, cli_fix))

    def _check_gpu(self) -> None:
        """Record a problem at ``study.device`` when the GPU it asks for cannot be used here."""
        from .._device import resolve_device

        try:
            resolve_device("gpu")
        except InputError as error:
            where = Where(("study", "device"), "study.device")
            self.problem(
                where,
                error.problem,
                "install roughcontact[gpu], or «device=cpu».",
                error.fix_in("cli"),
            )

    def _tables(self, key: str) -> dict[str, dict]:
        tables = self.document.get(key, {})
        if not isinstance(tables, dict) or not all(isinstance(t, dict) for t in tables.values()):
            self.problem(Where((key,), key), f"expected tables [{key}.NAME].", f"write [{key}.NAME] tables.")
            return {}
        return tables

    def file(self, value: Path | str, where: Where) -> Path | None:
        """Resolve a file relative to the study file; check it exists and record its hash."""
        path = (self.folder / Path(value).expanduser()).resolve()
        if not path.is_file():
            self.problem(
                where,
                f"file {str(value)!r} not found (looked for {path}).",
                "correct the path; relative paths are relative to the study file.",
                "correct the path.",
            )
            return None
        self.files.setdefault(str(path), _file_hash(path))
        return path

    def _topography_spec(self, name: str, raw: dict):
        where = Where(("topographies", name), f"topographies.{name}")
        try:
            schema = topography_schema(raw)
        except Exception as error:  # PydanticCustomError from the dispatcher
            context = getattr(error, "context", None) or {}
            self.problem(where, str(error).rstrip(".") + ".", context.get("fix"))
            return None
        spec = collect(self.problems, where, schema, raw)
        if isinstance(spec, FileTopography):
            path = self.file(spec.file, where.child("file"))
            if path is None:
                return None
            spec = spec.model_copy(update={"file": path})
            key = spec.model_dump_json()
            if key not in self.loaded:
                self.loaded[key] = self._read(spec, where)
            if self.loaded[key] is None:
                return None
        elif getattr(spec, "size", None) is not None:  # a generator's: the same check as a file's
            from ..topography.generate import grid_of
            from ..topography.plausible import size_doubt

            doubt = size_doubt(grid_of(spec.shape, spec.size)[1], generated=True)
            if doubt is not None:
                self.notes.append(f"{where.label}: {doubt.said('marked')}")
        return spec

    def _read(self, spec: FileTopography, where: Where) -> Topography | None:
        from ..topography.io import read_topography
        from ..topography.plausible import PlausibilityWarning, doubts
        from ..topography.process import exclude_filled

        try:
            with warnings.catch_warnings():  # said below as notes, in a study's words
                warnings.simplefilter("ignore", PlausibilityWarning)
                topography = read_topography(
                    spec.file,
                    channel=spec.channel,
                    size=spec.size,
                    height_unit=spec.height_unit,
                    position_unit=spec.position_unit,
                    crop=spec.crop,
                    undefined="interpolate" if spec.fill_undefined else "refuse",
                    max_filled=spec.max_filled,
                    remove_specks=spec.remove_specks,
                    periodic=spec.periodic,
                    treat_as_height=spec.treat_as_height,
                    override_file_values=spec.override_file_values,
                    detrend=spec.detrend,
                )
        except InputError as error:  # said in a study file's words
            fix = error.fix
            if isinstance(error, MissingMetadataError):
                keys = ", ".join(f"«{key}={value}»" for key, value in error.missing.items())
                notes = "".join(f"; {note}" for note in error.notes)
                square = " (a non-square scan: «size=5 um x 10 um»)" if "size" in error.missing else ""
                fix = f"give the real values, e.g. {keys}{square}{notes}."
            elif isinstance(error, UndefinedPointsError) and error.allowing is not None:
                fix = f"if that is acceptable, allow it: «max_filled={error.allowing:g}»; or crop them away."
            elif isinstance(error, UndefinedPointsError):
                fix = "add «fill_undefined=true» to fill them by harmonic interpolation, or crop them away."
            else:
                fix = error.fix_in("study")
            named = ("size", "height_unit", "position_unit", "channel", "max_filled", "crop", "x", "y")
            key = {"x": "crop", "y": "crop"}.get(error.field, error.field) if error.field in named else "file"
            place = Where(where.child(key).path, f"{where.label} ({error.field})")
            self.problem(place, error.problem, fix, error.fixes.get("cli"))
            return None
        self.notes += [f"{where.label}: {doubt.said('marked')}" for doubt in doubts(topography)]
        return exclude_filled(topography) if spec.exclude_filled else topography

    def _material(self, name: str, raw: dict) -> Material | None:
        where = Where(("materials", name), f"materials.{name}")
        spec = collect(self.problems, where, MaterialSpec, raw)
        if spec is None:
            return None
        try:
            problems = spec.problems()
        except InputError as error:  # an unknown library name
            problems = [error]
        for error in problems:
            typed = raw.get(error.field)  # the constructor sees SI: show the value as written too
            shown = f" (written {typed!r})" if isinstance(typed, str) and typed not in error.problem else ""
            self.problem(where.child(error.field), error.problem.rstrip(".") + shown + ".", error.fix)
        return None if problems else spec.build(name)

    def material(self, name: str, raw_tables: dict, where: Where) -> Material | None:
        """Return a study material (with this case's overrides) or a library material by name."""
        if name in raw_tables:
            return self._material(name, raw_tables[name])
        try:
            return get_material(name)
        except InputError:
            pass
        known = sorted(raw_tables) + [m.name for m in MATERIALS.values()]
        close = difflib.get_close_matches(str(name), known, n=1)
        fix = f"did you mean {close[0]!r}? " if close else ""
        self.problem(
            where,
            f"unknown material {name!r}.",
            fix + f"define [materials.{name}] or use one of {known}.",
            fix + f"use a library material, one of {known}.",
        )
        return None

    def topographies(
        self,
        name: str,
        raw_tables: dict,
        case: CaseParameters,
        where: Where,
        found: dict,
        chain: tuple[str, ...] = (),
    ):
        """Add the specification of topography ``name`` (and of its components) to ``found``.

        ``chain`` is the combinations being resolved around it: a name that combines itself,
        directly or through another, is a problem (it would never be made).
        """
        if name in chain:
            loop = " -> ".join((*chain[chain.index(name) :], name))
            self.problem(
                where,
                f"the combinations are circular: {loop}.",
                f"combine surfaces that are made without {name!r} (a file or a generator).",
            )
            return
        if name in found:
            return
        if name not in raw_tables:
            close = difflib.get_close_matches(str(name), list(raw_tables), n=1)
            self.problem(
                where,
                f"unknown topography {name!r}.",
                f"did you mean {close[0]!r}?" if close else f"define [topographies.{name}].",
            )
            return
        spec = self._topography_spec(name, raw_tables[name])
        if spec is None:
            return
        if "seed" in type(spec).model_fields and spec.seed is None:
            seed = realisation_seed(
                self.section.seed if self.section else 0, name, case.sample, case.replicate
            )
            spec = spec.model_copy(update={"seed": seed})
        found[name] = spec
        if isinstance(spec, Combined):
            for part in spec.combine:
                parts = Where(("topographies", name, "combine"), f"topographies.{name}.combine")
                self.topographies(part, raw_tables, case, parts, found, (*chain, name))

    def analysis(self, index: int, raw: Any) -> Analysis | None:
        """Return the ``[[analysis]]`` table at ``index`` with its cases built; None where it has problems."""
        from .kinds import get_kind, kind_names

        where = Where(("analysis", index), f"analysis[{index}]")
        if not isinstance(raw, dict):
            self.problem(where, "expected a table.", "write [[analysis]] with name and model.")
            return None
        name = raw.get("name")
        if isinstance(name, str):
            where = Where(where.path, f"analysis[{index}] ({name})")
        else:
            self.problem(where.child("name"), "is required (a short label).", "e.g. name = 'contact'.")
            name = f"analysis{index}"
        model = raw.get("model")
        if model not in kind_names(aliases=True):
            close = difflib.get_close_matches(str(model), kind_names(), n=1)
            self.problem(
                where.child("model"),
                f"unknown model {model!r}.",
                (f"did you mean {close[0]!r}? " if close else "") + f"use one of {kind_names()}.",
            )
            return None
        kind = get_kind(model)
        if model != kind.name:
            self.notes.append(f"{where.label}: model {model!r} is now called {kind.name!r}; write that.")
        base = self._renamed(kind, where, {k: v for k, v in raw.items() if k not in ANALYSIS_KEYS})
        sweep = self._renamed(kind, where.child("sweep"), raw.get("sweep", {}))
        zips = self._zips(kind, where, raw.get("zip", {}))
        zipped = {axis: values for group in zips for axis, values in group.items()}
        figures = raw.get("figures", list(kind.figures))
        unknown = [f for f in figures if f not in kind.figures] if isinstance(figures, list) else [figures]
        if unknown:
            self.problem(
                where.child("figures"),
                f"unknown figure(s) {unknown} for model {model!r}.",
                f"use some of {list(kind.figures)}.",
            )
        compare = None
        if "compare" in raw:
            if kind.compare is None:
                self.problem(where.child("compare"), f"model {model!r} takes no measured data.", "remove it.")
            else:
                compare = self._compare(kind, raw["compare"], where.child("compare"))
        realisations = self._realisations(raw, where, sweep, zipped)
        axes_of_cases = sweep | ({"replicate": list(range(realisations))} if realisations > 1 else {})
        try:
            rows = expand(axes_of_cases, zips, where.label)
        except InputError as error:
            axis = error.field.removeprefix(where.label + ".").split(".")
            self.problem(Where((*where.path, *axis), error.field), error.problem, error.fix)
            return None
        sections = {axis: "sweep" for axis in sweep} | {
            axis: "zip" if len(zips) == 1 else f"zip[{number}]"
            for number, group in enumerate(zips)
            for axis in group
        }
        swept = {axis: (section, _distinct(row[axis] for row in rows)) for axis, section in sections.items()}
        cases = []
        before = len(self.problems)
        for number, axes in enumerate(rows):
            case = self.case(name, kind, number, base, axes, where, swept)
            if case is not None:
                cases.append(case)
            if len(self.problems) > before + 5:  # one bad axis fails every case: say it a few times
                break
        sweep_axes = tuple(a for a in (*sweep, *zipped) if a != "replicate")
        drawn = tuple(sorted({n for case in cases for n, s in case.topographies.items() if _drawn(s)}))
        seeds: dict[str, set[int]] = {}
        for case in cases:
            for surface, seed in case.seeds.items():
                seeds.setdefault(surface, set()).add(seed)
        counted = len({case.parameters.replicate for case in cases}) if cases else realisations
        if realisations > 1 and cases and not any(len(seeds.get(d, ())) > 1 for d in drawn):
            self.problem(
                where.child("realisations"),
                "every realisation would draw the same surfaces: no generated topography of the analysis "
                "derives its seed from the realisation"
                + (f" ({', '.join(drawn)} have a fixed seed)." if drawn else " (there is none)."),
                "remove the fixed seed of the generated topography, or leave realisations out.",
                "realisations need a generated surface without a fixed seed; leave --realisations out.",
            )
        return Analysis(
            name,
            kind,
            tuple(cases),
            tuple(figures) if not unknown else (),
            compare,
            sweep_axes,
            counted,
            tuple(d for d in drawn if len(seeds.get(d, ())) > 1),
            tuple(d for d in drawn if len(seeds.get(d, ())) == 1),
        )

    def _realisations(self, raw: dict, where: Where, sweep: dict, zipped: dict) -> int:
        """Return the analysis' ``realisations`` (1 without it); a problem where it is not a count."""
        value = raw.get("realisations", 1)
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            problem = f"expected a whole number >= 1, got {value!r}."
            self.problem(where.child("realisations"), problem, "e.g. realisations = 5.")
            return 1
        if value > 1 and ("replicate" in sweep or "replicate" in zipped):
            self.problem(
                where.child("realisations"),
                "is given and replicate is swept: both set the realisations.",
                "keep realisations = N (replicates 0 to N-1), or the replicate sweep.",
            )
            return 1
        return value

    def _zips(self, kind: Kind, where: Where, raw: Any) -> list[dict]:
        """Return the zip tables as a list: one ``[analysis.zip]`` or several ``[[analysis.zip]]``."""
        if isinstance(raw, dict):
            return [self._renamed(kind, where.child("zip"), raw)] if raw else []
        if isinstance(raw, list) and all(isinstance(group, dict) for group in raw):
            return [self._renamed(kind, where.child("zip"), group) for group in raw if group]
        self.problem(
            where.child("zip"),
            f"expected a table of lists, or a list of such tables, got {raw!r}.",
            'e.g. [analysis.zip] with sample = ["a", "b"] and normal_force = ["1 uN", "2 uN"].',
        )
        return []

    def _renamed(self, kind: Kind, where: Where, table: Any) -> Any:
        """Return ``table`` with the kind's deprecated keys under their names now, noting each."""
        if not isinstance(table, dict) or not kind.renamed:
            return table
        renamed = {}
        for key, value in table.items():
            new = kind.renamed.get(key, key)
            if new != key:
                if new in table:
                    self.problem(
                        where.child(key), f"{key!r} is the old name of {new!r}, also given.", "keep one."
                    )
                    continue
                self.notes.append(f"{where.label}.{key}: {key!r} is now called {new!r}; write that.")
            renamed[new] = value
        return renamed

    def _compare(self, kind: Kind, raw: Any, where: Where):
        spec = collect(self.problems, where, kind.compare, self._renamed(kind, where, raw))
        spec = None if spec is None else self.with_files(spec, where)
        if spec is not None and hasattr(spec, "check"):  # its files read now (their units, columns)
            try:
                spec.check()
            except InputError as error:
                self.problem(
                    where.child(error.field), error.problem, error.fix_in("study"), error.fixes.get("cli")
                )
                return None
        return spec

    def with_files(self, spec: Strict, where: Where) -> Strict | None:
        """Return ``spec`` with its file (Path) fields resolved by :meth:`file`; None if one is missing."""
        updates = {}
        for field_name, value in spec:
            if isinstance(value, Path):
                path = self.file(value, where.child(field_name))
                if path is None:
                    return None
                updates[field_name] = path
        return spec.model_copy(update=updates)

    def case(
        self, analysis: str, kind: Kind, index: int, base: dict, axes: dict, where: Where, swept: dict
    ) -> Case | None:
        """Validate one case of an analysis: ``axes`` its swept values, ``swept`` each axis' table and values.

        Its problems are said once for the analysis, not once per case: a problem of a key every
        case shares reads the same in each (the study reports it once), and a problem of a swept
        value names the sweep key and the value (``analysis[0] (contact).sweep.mean_pressure:
        '20 uN' is a force ...``), with a value of the same sweep that was fine as the example.
        """
        before = len(self.problems)
        made = self._case(analysis, kind, index, base, axes, where)
        self.problems[before:] = [self._swept(p, where, axes, swept) for p in self.problems[before:]]
        return made

    @staticmethod
    def _swept(problem: Problem, where: Where, axes: dict, swept: dict) -> Problem:
        """Return ``problem`` placed at its sweep key when it is about a swept value.

        ``swept`` maps each axis to its table ("sweep" or "zip") and its values as written.
        """
        inside = problem.path[len(where.path) :] if problem.path[: len(where.path)] == where.path else ()
        axis = (
            ".".join(map(str, problem.path))
            if problem.path[:1] in (("topographies",), ("materials",))
            else None
        )
        axis = axis if axis in axes else (str(inside[0]) if inside and str(inside[0]) in axes else None)
        if axis is None:
            return problem
        section, values = swept.get(axis, ("sweep", []))
        said, fix = problem.marked
        fix = fix or ""
        others = [v for v in values if v != axes[axis]]
        if others and (
            "kind" in problem.problem or "unit" in problem.problem or "expected" in problem.problem
        ):
            fix = f"{fix} (other values of this {section}: {others[0]!r})".strip()
        return Problem(
            f"{where.label}.{section}.{axis}",
            said,
            fix or None,
            (*where.path, section, axis),
            problem.cli_fix,
        )

    def _case(
        self, analysis: str, kind: Kind, index: int, base: dict, axes: dict, where: Where
    ) -> Case | None:
        parameters = copy.deepcopy(base)
        topographies = copy.deepcopy(self.raw_topographies)
        materials = copy.deepcopy(self.raw_materials)
        label = where
        for axis, value in axes.items():
            section, _, rest = axis.partition(".")
            if section in ("topographies", "materials") and rest:
                table, _, key = rest.partition(".")
                tables = topographies if section == "topographies" else materials
                if table not in tables or not key:
                    self.problem(
                        Where((*where.path, "sweep", axis), f"{where.label}.sweep '{axis}'"),
                        f"no [{section}.{table}] table with a key to set.",
                        f"name an existing table and key, e.g. '{section}.NAME.KEY'.",
                    )
                    return None
                tables[table][key] = value
            else:
                parameters[axis] = value
        schema = kind.parameters
        checked = collect(self.problems, label, schema, parameters)
        if checked is not None:
            checked = self.with_files(checked, label)
        if checked is None:
            return None
        if kind.check is not None:
            try:
                kind.check(checked)
            except InputError as error:
                self.problem(
                    label.child(error.field), error.problem, error.fix_in("study"), error.fixes.get("cli")
                )
                return None
        found: dict[str, Strict] = {}
        for field_name in references(schema, "topography"):
            value = getattr(checked, field_name)
            if value is not None:
                self.topographies(value, topographies, checked, label.child(field_name), found)
        used_materials = {}
        for field_name in references(schema, "material"):
            value = getattr(checked, field_name)
            if value is not None:
                material = self.material(value, materials, label.child(field_name))
                if material is None:
                    return None
                used_materials[value] = material
        if kind.check_inputs is not None:
            try:
                kind.check_inputs(checked, KnownInputs(found, self.loaded, used_materials))
            except InputError as error:
                self.problem(
                    label.child(error.field), error.problem, error.fix_in("study"), error.fixes.get("cli")
                )
                return None
        files = {name: self.files[str(value)] for name, value in checked if isinstance(value, Path)}
        key_data = {
            "model": kind.name,
            "parameters": checked.model_dump(mode="json"),
            "topographies": {
                name: [spec.model_dump(mode="json"), self.files.get(str(getattr(spec, "file", "")))]
                for name, spec in sorted(found.items())
            },
            "materials": {name: repr(material) for name, material in sorted(used_materials.items())},
        }
        if files:  # the content of a case's own files (absent otherwise, so older keys stay valid)
            key_data["files"] = files
        key = hashlib.sha256(json.dumps(key_data, sort_keys=True).encode()).hexdigest()
        return Case(analysis, index, dict(axes), checked, found, used_materials, key)


def _distinct(values) -> list:
    """Return the values once each, in first-seen order (tables of a swept ``readings`` included)."""
    seen: dict[str, Any] = {}
    for value in values:
        seen.setdefault(json.dumps(value, sort_keys=True, default=str), value)
    return list(seen.values())
