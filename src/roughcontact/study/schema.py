"""Building blocks of a study file's schema: quantities with units, references, topographies, materials.

A study file is TOML (see the documentation's Studies page). Every physical value is written with its unit
(``"20 nm"``, ``"70 GPa"``, ``"10 uN"``, ``"72 mJ/m^2"``) and converted to SI here, once, through
:func:`roughcontact.units.quantity`; a bare number is refused (zero excepted) with the units the
user probably meant: ``size = 5`` is not a 5 m scan. The pydantic models forbid unknown keys, so a
misspelt field is an error that names it rather than a silently ignored line.
"""

from __future__ import annotations

import dataclasses
import typing
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import (
    AfterValidator,
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationInfo,
    model_validator,
)
from pydantic_core import PydanticCustomError

from ..errors import InputError
from ..materials import Material, get_material, material_problems
from ..topography.io import MAX_FILLED
from ..units import SI_UNITS, quantity


class Strict(BaseModel):
    """A frozen pydantic model that refuses keys it does not know."""

    model_config = ConfigDict(extra="forbid", frozen=True, use_attribute_docstrings=True)


STORED = {"stored": True}
"""Validation context of a document roughcontact wrote itself (``study.json``): numbers in it are SI."""


def _si(dimension: str):
    def convert(value: Any, info: ValidationInfo | None) -> float:
        if isinstance(value, bool) or not isinstance(value, str | int | float):
            raise PydanticCustomError(
                "quantity", "expected a {dimension} such as a string with a unit", {"dimension": dimension}
            )
        bare_is_si = bool(info is not None and (info.context or {}).get("stored"))
        try:
            if dimension == "area" and isinstance(value, str) and " x " in value:  # '25 um x 25 um'
                first, second = value.split(" x ", 1)
                return quantity(first, "length", require_unit=True) * quantity(
                    second, "length", require_unit=True
                )
            return quantity(value, dimension, require_unit=not bare_is_si)
        except InputError as error:
            raise PydanticCustomError(
                "quantity", "{problem}", {"problem": error.problem, "fix": error.fix}
            ) from None

    convert.dimension = dimension
    return BeforeValidator(convert)


def _si_per_axis(dimension: str):
    """One value for both axes, or two (``["5 um", "10 um"]`` or ``"5 um x 10 um"``); one error either way."""
    single = _si(dimension).func

    def convert(value: Any, info: ValidationInfo | None) -> float | tuple[float, float]:
        if isinstance(value, str) and " x " in value:  # '5 um x 10 um'
            value = [part.strip() for part in value.split(" x ")]
        if isinstance(value, list | tuple):
            if len(value) != 2:
                raise PydanticCustomError(
                    "quantity", "give one value or two (one per axis), got {n}", {"n": len(value)}
                )
            return (single(value[0], info), single(value[1], info))
        return single(value, info)

    convert.dimension = dimension
    return BeforeValidator(convert)


def _grid_shape(value: Any) -> tuple[int, ...]:
    """``128`` is a square map of 128 x 128 points, ``[256, 128]`` a rectangular one, ``[1024]`` a profile."""
    values = list(value) if isinstance(value, list | tuple) else [value, value]
    if not 1 <= len(values) <= 2 or not all(isinstance(v, int) and not isinstance(v, bool) for v in values):
        raise PydanticCustomError(
            "shape",
            "expected a number of points or a list of one or two",
            {"fix": "e.g. shape = 128 or [256, 128]"},
        )
    if min(values) < 2:
        raise PydanticCustomError("shape", "a grid needs at least 2 points per axis", {"fix": "e.g. 128"})
    return tuple(values)


def _unit_of(dimension: str, examples: str):
    """Validate a unit name of ``dimension`` (``"um"``), kept as written; refuse a unit of another kind."""

    def check(value: str) -> str:
        try:
            quantity(f"1 {value}", dimension)
        except InputError as error:
            raise PydanticCustomError(
                "quantity",
                "{problem}",
                {
                    "problem": f"{value!r} is not a unit of {dimension} ({error.problem.rstrip('.')})",
                    "fix": f"give one, e.g. {examples}.",
                },
            ) from None
        return value

    return AfterValidator(check)


Length = Annotated[float, _si("length")]
Area = Annotated[float, _si("area")]
InverseArea = Annotated[float, _si("inverse_area")]
Pressure = Annotated[float, _si("pressure")]
Force = Annotated[float, _si("force")]
Time = Annotated[float, _si("time")]
SurfaceEnergy = Annotated[float, _si("surface_energy")]
LengthPerAxis = Annotated[float | tuple[float, float], _si_per_axis("length")]
GridShape = Annotated[tuple[int, ...], BeforeValidator(_grid_shape)]
LengthUnit = Annotated[str, _unit_of("length", "'um', 'nm' or 'm'")]
ForceUnit = Annotated[str, _unit_of("force", "'mN', 'uN' or 'N'")]


def field_metadata(schema: type[BaseModel], name: str) -> list[Any]:
    """Return the ``Annotated`` metadata of field ``name``, also inside ``X | None`` and ``list[X]``."""
    info = schema.model_fields.get(name)
    if info is None:
        return []
    metadata = list(info.metadata)
    for annotation in (info.annotation, *typing.get_args(info.annotation)):
        metadata += list(getattr(annotation, "__metadata__", ()))
        for inner in typing.get_args(annotation):  # list[Length]
            metadata += list(getattr(inner, "__metadata__", ()))
    return metadata


def unit_of(schema: type[BaseModel], name: str) -> str | None:
    """Return the SI unit of the quantity field ``name`` of ``schema`` (``"m"``, ``"Pa"``, ...), else None."""
    for item in field_metadata(schema, name):
        dimension = getattr(getattr(item, "func", None), "dimension", None)
        if dimension is not None:
            return SI_UNITS[dimension]
    return None


@dataclasses.dataclass(frozen=True)
class Reference:
    """Marks a string field that names a study's topography or material (resolved by the runner)."""

    kind: Literal["topography", "material"]


TopographyName = Annotated[str, Reference("topography")]
"""Name of a ``[topographies.NAME]`` table."""

MaterialName = Annotated[str, Reference("material")]
"""Name of a ``[materials.NAME]`` table or of a library material (``"SU-8"``, ``"SiO2"``, ...)."""


# --- topographies --------------------------------------------------------------------------------


class FileTopography(Strict):
    """An instrument file read through :func:`roughcontact.topography.io.read_topography`.

    ``file`` is relative to the study file. ``size`` and ``height_unit`` are needed only where the
    file lacks them (a text file of points gives its size by its positions: ``position_unit`` where
    its header does not give their unit, never ``size``); ``detrend`` removes a background after
    reading (one of ``none``, ``mean``, ``plane``, ``curvature``, ``sphere``:
    :func:`roughcontact.topography.process.level`). A measured scan is levelled with ``plane``
    unless the study says otherwise (its tilt would decide where contact happens); a generated
    surface is used as made.
    """

    file: Path
    channel: int | str | None = None
    treat_as_height: bool = False
    """Read a channel whose name says it holds no heights (phase, amplitude, ...) as heights."""
    size: LengthPerAxis | None = None
    height_unit: str | None = None
    position_unit: str | None = None
    """Unit of a text file's x (y) positions where its header gives none (the positions give the size)."""
    override_file_values: bool = False
    """Use size and height_unit where the file stores other values (else such a clash is refused)."""
    crop: list[Length] | None = None
    """Read a window only: [x0, x1, y0, y1] ([x0, x1] for a profile), before any filling."""
    fill_undefined: bool = False
    max_filled: float = Field(default=MAX_FILLED, ge=0.0, le=1.0)
    """Largest fraction of undefined points that fill_undefined may fill (more needs saying so)."""
    remove_specks: bool = False
    """Make measured points standing alone amid undefined ones undefined before filling."""
    exclude_filled: bool = False
    """Keep the filled points out of contact (lowered below every measured point after levelling)."""
    periodic: bool = False
    detrend: Literal["none", "mean", "plane", "curvature", "sphere"] | None = None
    """Default plane (its tilt), mean for a periodic surface (a plane would make it non-periodic)."""

    @model_validator(mode="after")
    def _periodic_levelling(self) -> FileTopography:
        if self.periodic and self.detrend not in (None, "none", "mean"):
            raise PydanticCustomError(
                "quantity",
                "«detrend={detrend}» removes a background from a periodic surface, which would not repeat",
                {
                    "detrend": self.detrend,
                    "fix": "use «detrend=mean» (or «detrend=none»), or leave «periodic» out",
                },
            )
        return self

    @property
    def levelling(self) -> str:
        """The levelling applied: ``detrend``, or its default (plane; mean for a periodic surface)."""
        return self.detrend or ("mean" if self.periodic else "plane")


class _Generated(Strict):
    shape: GridShape
    size: LengthPerAxis

    @model_validator(mode="after")
    def _generator_checks(self) -> _Generated:
        """Run the generator's own checks (:func:`~roughcontact.topography.generate.check_arguments`).

        So validation refuses what building the surface would, before any case runs.
        """
        from ..checks import positive
        from ..topography.generate import check_arguments

        options = self.model_dump(exclude={"generate", "shape", "size", "ra"})
        try:
            check_arguments(self.generate, self.shape, self.size, options)
            if getattr(self, "ra", None) is not None:
                positive(self.ra, "ra", example="'5 nm'")
        except InputError as error:
            raise PydanticCustomError(
                "quantity",
                "{field}: {problem}",
                {"field": error.field, "problem": error.problem, "fix": error.fix},
            ) from None
        return self


class _Seeded(_Generated):
    seed: int | None = Field(
        default=None,
        description="fixed seed; without it the runner derives one per (sample, replicate) of a case",
    )


Modes = Literal["grid", "wavevector"]
"""How a random surface is drawn (:data:`roughcontact.topography.generate.MODES`): white noise on the
grid, or one draw per wavevector (the same surface on every grid: a mesh-convergence study)."""


class SelfAffine(_Seeded):
    """:func:`~roughcontact.topography.generate.self_affine`; ``ra`` rescales to an exact Ra afterwards."""

    generate: Literal["self_affine"]
    hurst: float
    rms_height: Length | None = None
    rms_slope: float | None = None
    ra: Length | None = None
    short_cutoff: Length | None = None
    long_cutoff: Length | None = None
    rolloff: float | None = None
    modes: Modes = "grid"


class GaussianRandom(_Seeded):
    """:func:`~roughcontact.topography.generate.gaussian_random`."""

    generate: Literal["gaussian_random"]
    rms_height: Length
    correlation_length: Length
    modes: Modes = "grid"


class MatchedMoments(_Seeded):
    """:func:`~roughcontact.topography.generate.matched_moments`: given spectral moments (paper 002)."""

    generate: Literal["matched_moments"]
    m0: Area
    m2: float
    m4: InverseArea
    hurst: float = 0.8
    modes: Modes = "wavevector"
    coarse: Literal["refuse", "truncate"] = "refuse"


class Sphere(_Generated):
    """:func:`~roughcontact.topography.generate.sphere` (apex at height 0, centred)."""

    generate: Literal["sphere"]
    radius: Length
    kind: Literal["sphere", "paraboloid"] = "sphere"


class SphereWithRoughness(_Seeded):
    """:func:`~roughcontact.topography.generate.sphere_with_roughness`."""

    generate: Literal["sphere_with_roughness"]
    radius: Length
    rms_height: Length
    hurst: float = 0.8
    kind: Literal["sphere", "paraboloid"] = "paraboloid"
    short_cutoff: Length | None = None
    long_cutoff: Length | None = None
    modes: Modes = "grid"


class Sinusoid(_Generated):
    """:func:`~roughcontact.topography.generate.sinusoid`."""

    generate: Literal["sinusoid"]
    amplitude: Length
    wavelength: Length
    axis: Literal[0, 1] = 0


class Bisinusoid(_Generated):
    """:func:`~roughcontact.topography.generate.bisinusoid`."""

    generate: Literal["bisinusoid"]
    amplitude: Length
    wavelength: LengthPerAxis


class FlatPunch(_Generated):
    """:func:`~roughcontact.topography.generate.flat_punch`."""

    generate: Literal["flat_punch"]
    radius: Length
    depth: Length


class RaisedIsland(_Seeded):
    """:func:`~roughcontact.topography.generate.raised_island`."""

    generate: Literal["raised_island"]
    island_size: Length
    thickness: Length
    rms_height: Length = 0.0
    hurst: float = 0.8
    short_cutoff: Length | None = None
    modes: Modes = "grid"


class Paper002Island(Strict):
    """:func:`~roughcontact.papers.paper002.paper002_island`: paper 002's island stand-in."""

    generate: Literal["paper002_island"]
    shape: GridShape = (64, 64)
    seed: int | None = None
    margin: Length = 2.5e-6
    roughness: Literal["moments", "gaussian"] = "moments"
    """The paper's three moments (one surface on every grid) or release 0.2's Gaussian stand-in."""


class Paper000Scan(Strict):
    """A synthetic polysilicon scan of paper 000 (:func:`~roughcontact.papers.paper000.paper000_scan`).

    The sample's Ra as ``ra``, or ``sample``, one of paper 000's (``"Ra 1.45 nm"``, ``"Ra 1.49 nm"``,
    ``"Ra 1.7 nm"``: :data:`~roughcontact.papers.paper000.PAPER000_SAMPLES`); 20 nm pixels,
    ``shape`` per side. Without ``seed`` each case derives its own.
    """

    generate: Literal["paper000_scan"]
    ra: Length | None = None
    sample: str | None = None
    shape: int = Field(default=250, ge=2)
    seed: int | None = None

    @model_validator(mode="after")
    def _one_roughness(self) -> Paper000Scan:
        from ..papers.paper000 import PAPER000_SAMPLES

        if (self.ra is None) == (self.sample is None):
            raise PydanticCustomError(
                "quantity",
                "give the scan's «ra» or paper 000's «sample», exactly one",
                {"fix": "e.g. «sample=Ra 1.45 nm», or «ra=1.45 nm»"},
            )
        if self.sample is not None and self.sample not in PAPER000_SAMPLES:
            raise PydanticCustomError(
                "quantity",
                "sample {sample!r} is not one of paper 000's",
                {"sample": self.sample, "fix": f"«sample» is one of {list(PAPER000_SAMPLES)}"},
            )
        if self.ra is not None and not self.ra > 0:
            raise PydanticCustomError("quantity", "«ra» must be positive", {"fix": "e.g. «ra=1.45 nm»"})
        return self

    @property
    def roughness(self) -> float:
        """The scan's Ra [m]: ``ra``, or the sample's."""
        from ..papers.paper000 import PAPER000_SAMPLES

        return self.ra if self.ra is not None else PAPER000_SAMPLES[self.sample]

    @property
    def grid(self) -> tuple[tuple[int, int], tuple[float, float]]:
        """(shape, size [m]) of the scan: square, 20 nm pixels."""
        from ..papers.paper000 import PIXEL

        return (self.shape, self.shape), (self.shape * PIXEL, self.shape * PIXEL)


class Paper000Tip(Strict):
    """Paper 000's rough SiO2 sphere, 20 nm pixels (:func:`~roughcontact.papers.paper000.paper000_tip`)."""

    generate: Literal["paper000_tip"]
    shape: int = Field(default=250, ge=2)
    seed: int | None = None

    grid = Paper000Scan.grid


class Paper001Ball(Strict):
    """Paper 001's rough ball over its 1.1 mm field (:func:`~roughcontact.papers.paper001.roughness`)."""

    generate: Literal["paper001_ball"]
    ball: Literal["HDPE", "POM"]
    shape: int = Field(default=1024, ge=2)
    """Pixels across the field (the paper's scans: 1024)."""
    seed: int | None = None
    rms: Literal["flattened", "drawn"] = "flattened"
    """Table 2's RMS after the fitted sphere is removed (as the paper measures it), or as drawn."""

    @property
    def grid(self) -> tuple[tuple[int, int], tuple[float, float]]:
        """(shape, size [m]) of the ball's scan: square, over the 1.1 mm field."""
        from ..papers.paper001 import FIELD

        return (self.shape, self.shape), (FIELD, FIELD)


class Combined(Strict):
    """The composite of two named topographies (:func:`~roughcontact.topography.process.combine`)."""

    combine: tuple[TopographyName, TopographyName]
    resample: bool = False


GENERATED = (
    SelfAffine,
    GaussianRandom,
    MatchedMoments,
    Sphere,
    SphereWithRoughness,
    Sinusoid,
    Bisinusoid,
    FlatPunch,
    RaisedIsland,
    Paper000Scan,
    Paper000Tip,
    Paper001Ball,
    Paper002Island,
)
GENERATORS = {model.model_fields["generate"].annotation.__args__[0]: model for model in GENERATED}
"""Generator name -> its schema."""


def topography_schema(raw: Any) -> type[Strict]:
    """Return the schema a raw ``[topographies.NAME]`` table is validated with.

    One of ``file``, ``generate`` or ``combine`` says what the table is; unknown generators are
    refused by the ``generate`` field itself, with the known ones listed.
    """
    if not isinstance(raw, dict):
        raise PydanticCustomError("topography", "expected a table with file, generate or combine", {})
    given = [key for key in ("file", "generate", "combine") if key in raw]
    if len(given) != 1:
        raise PydanticCustomError(
            "topography",
            "give exactly one of file, generate, combine (found {found})",
            {"found": ", ".join(given) or "none", "fix": "e.g. file = 'scan.di' or generate = 'self_affine'"},
        )
    if given[0] == "file":
        return FileTopography
    if given[0] == "combine":
        return Combined
    name = raw["generate"]
    if name not in GENERATORS:
        raise PydanticCustomError(
            "topography",
            "unknown generator {name}",
            {"name": repr(name), "fix": f"use one of {sorted(GENERATORS)}"},
        )
    return GENERATORS[name]


# --- materials -----------------------------------------------------------------------------------


class MaterialSpec(Strict):
    """A material: a library entry (``library = "SU-8"``) with optional overrides, or given in full."""

    library: str | None = None
    youngs_modulus: Pressure | None = None
    poissons_ratio: float | None = None
    hardness: Pressure | None = None
    yield_strength: Pressure | None = None
    surface_energy: SurfaceEnergy | None = None

    @model_validator(mode="after")
    def _complete(self) -> MaterialSpec:
        if self.library is None and (self.youngs_modulus is None or self.poissons_ratio is None):
            raise PydanticCustomError(
                "material",
                "a material needs «library=NAME», or «youngs_modulus» and «poissons_ratio»",
                {"fix": "e.g. «youngs_modulus=70 GPa» and «poissons_ratio=0.17»"},
            )
        return self

    def problems(self) -> list[InputError]:
        """Return every problem of the values (:func:`~roughcontact.materials.material_problems`)."""
        values = self.model_dump(exclude={"library"})
        if self.library is not None:
            base = dataclasses.asdict(get_material(self.library))
            values = {key: base[key] if values[key] is None else values[key] for key in values}
        return material_problems(**values)

    def build(self, name: str) -> Material:
        """Return the :class:`~roughcontact.materials.Material` (checked by its constructor)."""
        overrides = {
            key: value for key, value in self.model_dump(exclude={"library"}).items() if value is not None
        }
        if self.library is None:
            return Material(name=name, source="study file", **overrides)
        base = get_material(self.library)
        return dataclasses.replace(base, **overrides) if overrides else base
