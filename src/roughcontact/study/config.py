"""Study files: TOML in; a validated :class:`Study` with its cases expanded, or one error with all problems.

Layout of a study file (``docs/studies.md`` has the reference, ``examples/*.toml`` the examples)::

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

A sweep axis is a list or a range table: ``{start = "1 uN", stop = "100 uN", num = 5, spacing =
"log"}`` (``num`` points from start to stop, ``"linear"`` by default) or ``{start = 0, stop = 6,
step = 1}`` (start, start + step, ... up to and including stop).

Every value is validated before anything is computed, and every case is built (its parameters,
materials and topography specifications checked, files read) so that a bad value in the seventh
case of a sweep is reported at once, with the field, the value and the fix.
"""

from __future__ import annotations

import copy
import difflib
import hashlib
import itertools
import json
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import BaseModel, ValidationError

from ..errors import InputError
from ..materials import MATERIALS, Material, get_material
from ..topography import Topography
from ..units import split_quantity, unit_factor
from .kind import CaseParameters, Kind
from .schema import (
    Combined,
    FileTopography,
    MaterialSpec,
    Reference,
    Strict,
    field_metadata,
    topography_schema,
)

ANALYSIS_KEYS = ("name", "model", "sweep", "zip", "figures", "compare")
"""Keys of an ``[[analysis]]`` table that are not parameters of its model."""


class StudyError(InputError):
    """A study file with problems; ``problems`` lists each as (field, problem, fix)."""

    def __init__(self, source: str, problems: list[tuple[str, str, str | None]]):
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
    """An ``[[analysis]]`` table: its kind, cases, figures and comparison with measured data."""

    name: str
    kind: Kind
    cases: tuple[Case, ...]
    figures: tuple[str, ...]
    compare: Strict | None
    sweep_axes: tuple[str, ...]


@dataclass(frozen=True)
class Study:
    """A validated study file.

    Attributes
    ----------
    path : Path
        The study file (resolved).
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
    """

    path: Path
    name: str
    description: str
    seed: int
    text: str
    analyses: tuple[Analysis, ...]
    files: dict[str, str]
    loaded: dict[str, Topography]

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


# --- errors --------------------------------------------------------------------------------------


def _where(prefix: str, loc: tuple) -> str:
    parts = [prefix] if prefix else []
    for item in loc:
        if isinstance(item, int):
            parts[-1] = f"{parts[-1]}[{item}]" if parts else f"[{item}]"
        elif "[" not in str(item) and "(" not in str(item):  # skip pydantic's union branch tags
            parts.append(str(item))
    return ".".join(parts)


def _problems(error: ValidationError, prefix: str, schema: type[BaseModel] | None = None) -> list:
    """Turn a pydantic error into (field, problem, fix) triples that show the bad value."""
    problems = []
    for item in error.errors(include_url=False):
        where = _where(prefix, item["loc"])
        context = item.get("ctx") or {}
        value = item.get("input")
        whole_table = not item["loc"]  # a model-level check: the value is the whole table
        shown = "" if item["type"] == "missing" or whole_table else f" (got {value!r})"
        fix = context.get("fix")
        if item["type"] == "missing":
            problem, fix = "is required but missing.", f"add {item['loc'][-1]} = ... to the table."
        elif item["type"] == "extra_forbidden":
            known = list(schema.model_fields) if schema is not None else []
            close = difflib.get_close_matches(str(item["loc"][-1]), known, n=1)
            problem = "is not a known key."
            fix = (
                f"did you mean {close[0]!r}?" if close else f"use one of {known}." if known else "remove it."
            )
            shown = ""
        elif item["type"] in ("quantity", "shape", "topography", "material"):
            problem = context.get("problem") or item["msg"]
            problem = problem.rstrip(".") + "."
            shown = "" if repr(value) in problem else shown
        else:
            problem = item["msg"].removeprefix("Value error, ").rstrip(".") + "."
            fix = fix or _generic_fix(item["type"], context)
        problems.append((where, problem + shown, fix))
    return problems


def _generic_fix(kind: str, context: dict) -> str | None:
    """Return a fix for pydantic's own checks (bounds, choices, types), which carry none."""
    bounds = {"greater_than": "gt", "greater_than_equal": "ge", "less_than": "lt", "less_than_equal": "le"}
    if kind in bounds:
        words = {"gt": "above", "ge": "at least", "lt": "below", "le": "at most"}[bounds[kind]]
        return f"give a value {words} {context.get(bounds[kind])}."
    if kind == "literal_error":
        return f"use one of {context.get('expected')}."
    if kind in ("int_parsing", "int_type", "int_from_float"):
        return "give a whole number, e.g. 3."
    if kind in ("float_parsing", "float_type", "finite_number"):
        return "give a finite number, e.g. 0.3."
    if kind in ("bool_parsing", "bool_type"):
        return "write true or false."
    if kind in ("string_type", "list_type", "tuple_type", "dict_type"):
        return "see roughcontact models NAME for the key's type."
    return None


def _collect(problems: list, prefix: str, schema: type[BaseModel], raw: Any):
    """Validate ``raw`` with ``schema``; on failure append its problems and return None."""
    try:
        return schema.model_validate(raw)
    except ValidationError as error:
        problems.extend(_problems(error, prefix, schema))
    except InputError as error:
        problems.append((prefix, error.problem, error.fix))
    return None


# --- sweeps --------------------------------------------------------------------------------------


def _split_quantity(value: Any, where: str) -> tuple[float, str]:
    if isinstance(value, bool):
        raise InputError(where, f"expected a number or a quantity, got {value!r}.", "e.g. '1 uN' or 3.")
    if isinstance(value, int | float):
        return float(value), ""
    number, unit = split_quantity(str(value), field=where)
    return float(number), unit


def _range_values(spec: dict, where: str) -> list:
    """Expand a range table into a list of values written in the unit of ``start``."""
    known = {"start", "stop", "num", "step", "spacing"}
    if not known >= set(spec) or not {"start", "stop"} <= set(spec) or ("num" in spec) == ("step" in spec):
        raise InputError(
            where,
            f"a range is start, stop and one of num or step, got {sorted(spec)}.",
            "e.g. {start = '1 uN', stop = '100 uN', num = 5, spacing = 'log'} "
            "or {start = 0, stop = 6, step = 1}.",
        )
    start, unit = _split_quantity(spec["start"], f"{where}.start")
    stop, stop_unit = _split_quantity(spec["stop"], f"{where}.stop")
    if stop_unit != unit:
        factor, dimension = unit_factor(stop_unit)
        own_factor, own_dimension = unit_factor(unit)
        if dimension != own_dimension:
            raise InputError(
                f"{where}.stop", f"{spec['stop']!r} is not in the dimension of {spec['start']!r}."
            )
        stop *= float(factor / own_factor)
    integers = all(isinstance(spec[k], int) and not isinstance(spec[k], bool) for k in ("start", "stop"))
    if "step" in spec:
        step, step_unit = _split_quantity(spec["step"], f"{where}.step")
        if step_unit not in ("", unit) or not step > 0 or stop < start:
            raise InputError(
                f"{where}.step", f"need step > 0 and stop >= start, got {spec}.", "e.g. step = 1."
            )
        count = int(math.floor((stop - start) / step * (1 + 1e-12))) + 1
        numbers = [start + k * step for k in range(count)]
        integers = integers and isinstance(spec["step"], int)
    else:
        num = spec["num"]
        if not isinstance(num, int) or num < 1:
            raise InputError(f"{where}.num", f"need a whole number >= 1, got {num!r}.", "e.g. num = 5.")
        spacing = spec.get("spacing", "linear")
        if spacing == "log":
            if not (start > 0 and stop > 0):
                raise InputError(f"{where}.spacing", "log spacing needs start and stop > 0.", "use linear.")
            numbers = list(np.geomspace(start, stop, num))
        elif spacing == "linear":
            numbers = list(np.linspace(start, stop, num))
        else:
            raise InputError(f"{where}.spacing", f"unknown spacing {spacing!r}.", "use 'linear' or 'log'.")
        integers = integers and all(float(n).is_integer() for n in numbers)
    if integers and not unit:
        return [int(round(n)) for n in numbers]
    return [f"{float(n):.12g} {unit}".strip() if unit else float(n) for n in numbers]


def _axis_values(value: Any, where: str) -> list:
    if isinstance(value, dict):
        return _range_values(value, where)
    if isinstance(value, list) and value:
        return value
    raise InputError(
        where, f"an axis is a non-empty list or a range table, got {value!r}.", "e.g. [1, 2, 3]."
    )


def expand(sweep: dict, zipped: dict, where: str) -> list[dict[str, Any]]:
    """Return one ``{axis: value}`` dictionary per case: the product of the sweep axes and the zip axis.

    Parameters
    ----------
    sweep : dict
        Axis -> list or range table; the cases are their Cartesian product, the first axis
        varying slowest.
    zipped : dict
        Axis -> list, all of one length; taken together as one more (last) axis.
    where : str
        The analysis' field name for error messages.

    Returns
    -------
    list of dict
        One dictionary of raw (as written) values per case; ``[{}]`` without axes.
    """
    axes = {name: _axis_values(value, f"{where}.sweep.{name}") for name, value in sweep.items()}
    overlap = set(axes) & set(zipped)
    if overlap:
        raise InputError(
            f"{where}.zip", f"{sorted(overlap)} is both swept and zipped.", "keep it in one place."
        )
    rows: list[dict] = [{}]
    if zipped:
        lists = {name: _axis_values(value, f"{where}.zip.{name}") for name, value in zipped.items()}
        lengths = {name: len(values) for name, values in lists.items()}
        if len(set(lengths.values())) > 1:
            raise InputError(f"{where}.zip", f"zipped lists differ in length: {lengths}.", "make them equal.")
        rows = [dict(zip(lists, values, strict=True)) for values in zip(*lists.values(), strict=True)]
    names = list(axes)
    return [
        dict(zip(names, values, strict=True)) | row
        for values in itertools.product(*axes.values())
        for row in rows
    ]


# --- cases ---------------------------------------------------------------------------------------


def references(schema: type[BaseModel], kind: str) -> list[str]:
    """Names of the fields of ``schema`` that refer to a topography or a material (``kind``)."""
    return [
        name
        for name in schema.model_fields
        if any(isinstance(m, Reference) and m.kind == kind for m in field_metadata(schema, name))
    ]


def _derived_seed(study_seed: int, topography: str, sample: str, replicate: int) -> int:
    text = json.dumps([study_seed, topography, sample, replicate])
    return int(hashlib.sha256(text.encode()).hexdigest()[:8], 16)


def _file_hash(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


class _Builder:
    """Validates the study's tables and builds the cases of its analyses, collecting every problem."""

    def __init__(self, path: Path, document: dict):
        self.path = path
        self.folder = path.parent
        self.document = document
        self.problems: list[tuple[str, str, str | None]] = []
        self.files: dict[str, str] = {}
        self.loaded: dict[str, Topography] = {}
        self.section = _collect(self.problems, "study", StudySection, document.get("study", {}))
        self.raw_topographies = self._tables("topographies")
        self.raw_materials = self._tables("materials")
        for name, raw in self.raw_topographies.items():  # report bad tables once, not per case
            self._topography_spec(name, raw, f"topographies.{name}")
        for name, raw in self.raw_materials.items():
            self._material(name, raw, f"materials.{name}")

    def _tables(self, key: str) -> dict[str, dict]:
        tables = self.document.get(key, {})
        if not isinstance(tables, dict) or not all(isinstance(t, dict) for t in tables.values()):
            self.problems.append((key, "expected tables [" + key + ".NAME].", f"write [{key}.NAME] tables."))
            return {}
        return tables

    def file(self, value: Path | str, where: str) -> Path | None:
        """Resolve a file relative to the study file; check it exists and record its hash."""
        path = (self.folder / Path(value).expanduser()).resolve()
        if not path.is_file():
            self.problems.append(
                (
                    where,
                    f"file {str(value)!r} not found (looked for {path}).",
                    "correct the path; relative paths are relative to the study file.",
                )
            )
            return None
        self.files.setdefault(str(path), _file_hash(path))
        return path

    def _topography_spec(self, name: str, raw: dict, where: str):
        try:
            schema = topography_schema(raw)
        except Exception as error:  # PydanticCustomError from the dispatcher
            context = getattr(error, "context", None) or {}
            self.problems.append((where, str(error).rstrip(".") + ".", context.get("fix")))
            return None
        spec = _collect(self.problems, where, schema, raw)
        if isinstance(spec, FileTopography):
            path = self.file(spec.file, f"{where}.file")
            if path is None:
                return None
            spec = spec.model_copy(update={"file": path})
            key = spec.model_dump_json()
            if key not in self.loaded:
                self.loaded[key] = self._read(spec, where)
            if self.loaded[key] is None:
                return None
        return spec

    def _read(self, spec: FileTopography, where: str) -> Topography | None:
        from ..topography.io import read_topography
        from ..topography.process import detrend

        try:
            topography = read_topography(
                spec.file,
                channel=spec.channel,
                size=spec.size,
                height_unit=spec.height_unit,
                undefined="interpolate" if spec.fill_undefined else "refuse",
                periodic=spec.periodic,
            )
        except InputError as error:
            fix = (error.fix or "").replace("--fill-undefined", "fill_undefined = true")
            fix = fix.replace("--size", "size = ...").replace("--height-unit", "height_unit = ...")
            self.problems.append((f"{where} ({error.field})", error.problem, fix or None))
            return None
        return topography if spec.detrend == "none" else detrend(topography, spec.detrend)

    def _material(self, name: str, raw: dict, where: str) -> Material | None:
        spec = _collect(self.problems, where, MaterialSpec, raw)
        if spec is None:
            return None
        try:
            return spec.build(name)
        except InputError as error:
            self.problems.append((f"{where}.{error.field}", error.problem, error.fix))
            return None

    def material(self, name: str, raw_tables: dict, where: str) -> Material | None:
        """Return a study material (with this case's overrides) or a library material by name."""
        if name in raw_tables:
            return self._material(name, raw_tables[name], f"materials.{name}")
        try:
            return get_material(name)
        except InputError:
            pass
        known = sorted(raw_tables) + [m.name for m in MATERIALS.values()]
        close = difflib.get_close_matches(str(name), known, n=1)
        fix = f"did you mean {close[0]!r}? " if close else ""
        self.problems.append(
            (where, f"unknown material {name!r}.", fix + f"define [materials.{name}] or use one of {known}.")
        )
        return None

    def topographies(self, name: str, raw_tables: dict, case: CaseParameters, where: str, found: dict):
        """Add the specification of topography ``name`` (and of its components) to ``found``."""
        if name in found:
            return
        if name not in raw_tables:
            close = difflib.get_close_matches(str(name), list(raw_tables), n=1)
            self.problems.append(
                (
                    where,
                    f"unknown topography {name!r}.",
                    (f"did you mean {close[0]!r}?" if close else f"define [topographies.{name}]."),
                )
            )
            return
        spec = self._topography_spec(name, raw_tables[name], f"topographies.{name}")
        if spec is None:
            return
        if "seed" in type(spec).model_fields and spec.seed is None:
            seed = _derived_seed(self.section.seed if self.section else 0, name, case.sample, case.replicate)
            spec = spec.model_copy(update={"seed": seed})
        found[name] = spec
        if isinstance(spec, Combined):
            for part in spec.combine:
                self.topographies(part, raw_tables, case, f"topographies.{name}.combine", found)

    def analysis(self, index: int, raw: Any) -> Analysis | None:
        from .kinds import get_kind, kind_names

        where = f"analysis[{index}]"
        if not isinstance(raw, dict):
            self.problems.append((where, "expected a table.", "write [[analysis]] with name and model."))
            return None
        name = raw.get("name")
        if isinstance(name, str):
            where = f"analysis[{index}] ({name})"
        else:
            self.problems.append((f"{where}.name", "is required (a short label).", "e.g. name = 'contact'."))
            name = f"analysis{index}"
        model = raw.get("model")
        if model not in kind_names():
            close = difflib.get_close_matches(str(model), kind_names(), n=1)
            self.problems.append(
                (
                    f"{where}.model",
                    f"unknown model {model!r}.",
                    (f"did you mean {close[0]!r}? " if close else "") + f"use one of {kind_names()}.",
                )
            )
            return None
        kind = get_kind(model)
        base = {k: v for k, v in raw.items() if k not in ANALYSIS_KEYS}
        figures = raw.get("figures", list(kind.figures))
        unknown = [f for f in figures if f not in kind.figures] if isinstance(figures, list) else [figures]
        if unknown:
            self.problems.append(
                (
                    f"{where}.figures",
                    f"unknown figure(s) {unknown} for model {model!r}.",
                    f"use some of {list(kind.figures)}.",
                )
            )
        compare = None
        if "compare" in raw:
            if kind.compare is None:
                self.problems.append(
                    (f"{where}.compare", f"model {model!r} takes no measured data.", "remove it.")
                )
            else:
                compare = self._compare(kind, raw["compare"], f"{where}.compare")
        try:
            rows = expand(raw.get("sweep", {}), raw.get("zip", {}), where)
        except InputError as error:
            self.problems.append((error.field, error.problem, error.fix))
            return None
        cases = []
        before = len(self.problems)
        for number, axes in enumerate(rows):
            case = self.case(name, kind, number, base, axes, where)
            if case is not None:
                cases.append(case)
            if len(self.problems) > before + 5:  # one bad axis fails every case: say it a few times
                break
        sweep_axes = tuple(raw.get("sweep", {})) + tuple(raw.get("zip", {}))
        return Analysis(name, kind, tuple(cases), tuple(figures) if not unknown else (), compare, sweep_axes)

    def _compare(self, kind: Kind, raw: Any, where: str):
        spec = _collect(self.problems, where, kind.compare, raw)
        return None if spec is None else self.with_files(spec, where)

    def with_files(self, spec: Strict, where: str) -> Strict | None:
        """Return ``spec`` with its file (Path) fields resolved by :meth:`file`; None if one is missing."""
        updates = {}
        for field_name, value in spec:
            if isinstance(value, Path):
                path = self.file(value, f"{where}.{field_name}")
                if path is None:
                    return None
                updates[field_name] = path
        return spec.model_copy(update=updates)

    def case(self, analysis: str, kind: Kind, index: int, base: dict, axes: dict, where: str) -> Case | None:
        parameters = copy.deepcopy(base)
        topographies = copy.deepcopy(self.raw_topographies)
        materials = copy.deepcopy(self.raw_materials)
        label = where + (f" case {index} {axes}" if axes else "")
        for axis, value in axes.items():
            section, _, rest = axis.partition(".")
            if section in ("topographies", "materials") and rest:
                table, _, key = rest.partition(".")
                tables = topographies if section == "topographies" else materials
                if table not in tables or not key:
                    self.problems.append(
                        (
                            f"{where}.sweep '{axis}'",
                            f"no [{section}.{table}] table with a key to set.",
                            f"name an existing table and key, e.g. '{section}.NAME.KEY'.",
                        )
                    )
                    return None
                tables[table][key] = value
            else:
                parameters[axis] = value
        schema = kind.parameters
        checked = _collect(self.problems, label, schema, parameters)
        if checked is not None:
            checked = self.with_files(checked, label)
        if checked is None:
            return None
        if kind.check is not None:
            try:
                kind.check(checked)
            except InputError as error:
                self.problems.append((f"{label}.{error.field}", error.problem, error.fix))
                return None
        found: dict[str, Strict] = {}
        for field_name in references(schema, "topography"):
            value = getattr(checked, field_name)
            if value is not None:
                self.topographies(value, topographies, checked, f"{label}.{field_name}", found)
        used_materials = {}
        for field_name in references(schema, "material"):
            value = getattr(checked, field_name)
            if value is not None:
                material = self.material(value, materials, f"{label}.{field_name}")
                if material is None:
                    return None
                used_materials[value] = material
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


def load_study(path: str | Path) -> Study:
    """Read and validate a study file, building every case; raise :class:`StudyError` listing all problems.

    Parameters
    ----------
    path : str or Path
        The TOML study file; relative file names inside it are relative to its folder.

    Returns
    -------
    Study

    Raises
    ------
    StudyError
        The file is missing, is not TOML, or has problems (each named with its field, value and fix).
    """
    path = Path(path).expanduser().resolve()
    if not path.is_file():
        raise StudyError(str(path), [("STUDY", f"study file {str(path)!r} not found.", "check the path.")])
    text = path.read_text(encoding="utf-8")
    try:
        document = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise StudyError(
            str(path), [("TOML", f"not valid TOML: {error}.", "fix the syntax at that line.")]
        ) from None
    builder = _Builder(path, document)
    unknown = sorted(set(document) - {"study", "topographies", "materials", "analysis"})
    for key in unknown:
        builder.problems.append(
            (key, "is not a known section.", "use study, topographies, materials, analysis.")
        )
    raw_analyses = document.get("analysis", [])
    if not isinstance(raw_analyses, list) or not raw_analyses:
        builder.problems.append(
            ("analysis", "the study has no [[analysis]] table.", "add one with name and model.")
        )
        raw_analyses = []
    analyses = [builder.analysis(i, raw) for i, raw in enumerate(raw_analyses)]
    names = [a.name for a in analyses if a is not None]
    for name in {n for n in names if names.count(n) > 1}:
        builder.problems.append((f"analysis ({name})", "two analyses share this name.", "rename one."))
    if builder.problems:
        raise StudyError(str(path), builder.problems)
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
    )
