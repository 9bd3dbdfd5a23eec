r"""Study kind ``load_unload``: elastic-perfectly-plastic load-unload of a surface against a rigid flat punch.

One case is :func:`roughcontact.contact.load_unload.load_unload` (seed paper 002, sections III and
VI, Figs. 7-9): the surface is pressed by a rigid flat to ``max_force`` and unloaded,
force-controlled, through the targets

.. math:: W_k = \frac{k}{n} W_{max}, \quad k = 0 \dots n \quad (n = \text{load\_steps}),

plus ``reference_force`` on loading, and the same targets back down to zero on unloading. Each
step is an FFT boundary-element solution (paper 001 eq. 4) with the contact pressure capped at the
hardness H; the overlap at the cap is kept as plastic flattening, and unloading is elastic on the
flattened surface. The interference follows the experiment's convention: omega = 0 where the
loading branch carries ``reference_force`` (paper 002: 25 uN, the smallest load its nanoindenter
resolves; default here 0, the first touch). The body is a film of ``film_thickness`` bonded to a
``substrate`` (paper 002: SU-8, 6.3 um, on silicon), or a half-space of ``material``.

``plasticity`` chooses the plastic model. ``"surface"`` (default, the cheaper approximation): the
pressure capped at the hardness as above; its von Mises stress (paper 002 eq. 12) is that of the
elastic body (the film on its substrate, or the half-space) under each step's surface pressure, on
the plane ``stress_depth`` below the surface (0: the surface, as the paper's maps). ``"volume"``:
J2 plasticity with linear hardening in a volume of ``layers`` cells down to ``depth`` below the surface
(:mod:`roughcontact.contact.volume_plastic`; ``yield_strength`` default the material's, paper 002
Table I: 0.165 GPa for SU-8; ``hardening_modulus`` default 0), in the film on its substrate where
one is given. Its maps are of the total stress (pressure plus residual) of the cell layer nearest
``stress_depth`` (the top cell's centre for 0), and a section along x through the line of pixels
that carries the most load at the peak shows the
stress in depth; at zero load after unloading they show the residual stress (paper 002 Fig. 9e).

Assumptions (those of the model; see :mod:`roughcontact.contact.load_unload`): with
``plasticity = "surface"`` plasticity is confined to the surface (no subsurface plastic zone, no
hardening, no residual stress after unloading, so a map at 0 N on unloading is empty where the
paper's FEM shows residual stress); the film is laterally infinite (the island's free side walls
are not modelled); strains are small and the load quasi-static; the punch is rigid (diamond is ~150
times stiffer than SU-8).

Scalars: peak force, peak interference, ``residual_interference`` (at zero load, where the
unloaded surface first touches the flat), ``interference_at_return_force`` (where unloading comes
back to ``reference_force``, the ``return_force``: the point the statistical KKE model's unloading
curve ends at, so the one compared with it), peak contact area, fraction of it at the hardness,
largest pressure, largest plastic flattening, largest von Mises stress at the peak.
Dataset: the curve (``branch``, ``approach`` (the interference), ``force``, ``contact_area``,
``plastic_fraction``, ``max_pressure``) on the dimension ``point``, and von Mises maps
``von_mises(map, x, y)`` at a few loads (``von_mises_loads``), each coarsened to at most
``map_points`` per axis by the largest value of each block, so that peaks are kept.

Figures: ``load_interference`` (paper 002 Fig. 7: this analysis' curves with those of every
``asperity`` analysis of the study and the measured curve of ``[analysis.compare]``, against
omega / omega_c where the asperity analyses give one omega_c, the legend ending with KKE's peak over
the BEM's), ``von_mises`` (Figs. 8-9), ``mesh_convergence`` (Fig. 6, for a study that sweeps the
grid) and, for ``plasticity = "volume"``, ``von_mises_section`` (the same loads on a vertical section).

Tables: ``against_statistical`` (with an ``asperity`` analysis in the study: the BEM's peak
interference and interference back at the reference load over its realisations against KKE's,
judged for one island, the paper's claim, with the prediction interval of one realisation and for
the mean with its confidence interval; the ratio KKE / BEM with both intervals beside paper 002's
words; a sentence per comparison in the table's notes) and ``mesh_convergence`` (Fig. 6 in full:
peak interference, interference back at the reference load and peak contact area per grid, their
changes per refinement, the observed order or why there is none).
"""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...cases import evenly_chosen
from ...contact.load_unload import LoadUnloadResult
from ...units import format_si
from ..kind import CaseOutput, CaseParameters, Kind, figure, fill_from_paper
from ..schema import Force, Length, MaterialName, Pressure, TopographyName
from .asperity import MeasuredCurve, measured_of

MAPS_PER_BRANCH = 6
"""Default number of von Mises maps on loading (evenly spread over the targets; unloading: the same loads)."""


class LoadUnloadParameters(CaseParameters):
    """Keys of a ``model = "load_unload"`` analysis (SI after validation).

    Attributes
    ----------
    topography : str
        The study topography (heights towards the punch; paper 002: ``generate = "paper002_island"``).
    material : str
        The film or half-space; its hardness caps the pressure unless ``hardness``.
    substrate : str, optional
        Substrate the film is bonded to (needs ``film_thickness``); default: a half-space.
    film_thickness : float, optional
        Film thickness [m] (paper 002: 6.3 um).
    max_force : float
        Peak load [N].
    reference_force : float
        Load of zero interference on loading [N] (paper 002: 25 uN; default 0, the first touch).
    load_steps : int
        Equal load increments from 0 to the peak (and back).
    hardness : float, optional
        Pressure cap [Pa] (default: the material's).
    tolerance : float
        Solver tolerance (:func:`~roughcontact.contact.solve_normal`).
    stress_depth : float
        Depth [m] of the von Mises maps (0: the surface).
    von_mises_loads : list of float, optional
        Loads [N] of the maps, each one of the targets (on both branches where it occurs); default:
        six loads evenly spread from 0 to the peak (0, 20, ..., 100 % for ``load_steps = 10``, as
        paper 002 Figs. 8-9).
    map_points : int
        Largest number of map points per axis that is stored.
    plasticity : {"surface", "volume"}
        The pressure cap at the hardness, or J2 plasticity in the volume.
    yield_strength : float, optional
        Yield strength [Pa] for ``plasticity = "volume"`` (default: the material's).
    hardening_modulus : float
        Linear hardening slope [Pa] for ``plasticity = "volume"`` (0: perfectly plastic).
    depth : float, optional
        Depth [m] of the plastic volume (default: ``layers`` pixels, within the film).
    layers : int
        Cells through the depth.
    paper002 : bool
        Fill in paper 002's film on its substrate and its loads
        (:func:`roughcontact.papers.paper002.load_unload_keys`) where the analysis leaves them out.
    """

    topography: TopographyName
    material: MaterialName
    substrate: MaterialName | None = None
    film_thickness: Length | None = None
    max_force: Force
    reference_force: Force = 0.0
    load_steps: int = Field(default=10, ge=1)
    hardness: Pressure | None = None
    tolerance: float = Field(default=1e-8, gt=0.0, lt=1.0)
    stress_depth: Length = 0.0
    von_mises_loads: list[Force] | None = None
    map_points: int = Field(default=128, ge=8)
    plasticity: Literal["surface", "volume"] = "surface"
    yield_strength: Pressure | None = None
    hardening_modulus: Pressure = 0.0
    depth: Length | None = None
    layers: int = Field(default=16, ge=1)
    paper002: bool = Field(default=False, exclude=True)
    """Fill in paper 002's scenario (stored as the keys it fills, not as the flag)."""

    @model_validator(mode="before")
    @classmethod
    def _paper002_scenario(cls, data: Any) -> Any:
        from ...papers.paper002 import load_unload_keys

        return fill_from_paper(data, "paper002", lambda given: load_unload_keys())

    @model_validator(mode="after")
    def _consistent(self) -> LoadUnloadParameters:
        if not self.max_force > 0:
            raise PydanticCustomError(
                "quantity", "«max_force» must be positive", {"fix": "e.g. «max_force=1000 uN»"}
            )
        if not 0 <= self.reference_force < self.max_force:
            raise PydanticCustomError(
                "quantity",
                "«reference_force» must be 0 or more and below «max_force»",
                {"fix": "e.g. «reference_force=25 uN» with «max_force=1000 uN»"},
            )
        if (self.substrate is None) != (self.film_thickness is None):
            raise PydanticCustomError(
                "quantity",
                "a film needs both «substrate» and «film_thickness» (without them the body is a half-space)",
                {"fix": "e.g. «substrate=silicon wafer» and «film_thickness=6.3 um»"},
            )
        if self.film_thickness is not None and not self.film_thickness > 0:
            raise PydanticCustomError(
                "quantity", "«film_thickness» must be positive", {"fix": "e.g. «film_thickness=6.3 um»"}
            )
        if not self.stress_depth >= 0:
            raise PydanticCustomError(
                "quantity", "«stress_depth» must be 0 or more", {"fix": "e.g. «stress_depth=0.5 um»"}
            )
        if self.von_mises_loads is not None:
            loading, _ = load_targets(self.max_force, self.reference_force, self.load_steps)
            missing = [f for f in self.von_mises_loads if not np.isclose(loading, f, rtol=1e-9, atol=0).any()]
            if missing:
                raise PydanticCustomError(
                    "quantity",
                    "«von_mises_loads» {missing} uN are not among the load targets {targets} uN",
                    {
                        "missing": [float(f"{f * 1e6:.6g}") for f in missing],
                        "targets": [float(f"{f * 1e6:.6g}") for f in loading],
                        "fix": "choose among the targets (k / «load_steps» x «max_force», «reference_force»)",
                    },
                )
        return self


def load_targets(max_force: float, reference_force: float, steps: int) -> tuple[np.ndarray, np.ndarray]:
    """Return the loading targets 0, W/n, ..., W with ``reference_force`` added, and unloading ones [N].

    :func:`roughcontact.contact.load_unload.force_targets` and back down (with ``steps = 10``
    paper 002's, :func:`roughcontact.papers.paper002.compress_island`).
    """
    from ...contact.load_unload import force_targets

    loading = force_targets(max_force, steps, reference_force)
    return loading, loading[::-1][1:]


def _map_steps(parameters: LoadUnloadParameters, loading: np.ndarray, unloading: np.ndarray) -> list[int]:
    """Return the indices of the steps (loading, then unloading) whose von Mises maps are stored."""
    if parameters.von_mises_loads is None:
        regular = np.linspace(0.0, parameters.max_force, parameters.load_steps + 1)
        wanted = evenly_chosen(list(regular), MAPS_PER_BRANCH)
    else:
        wanted = parameters.von_mises_loads
    steps = [int(np.flatnonzero(np.isclose(loading, f, rtol=1e-9, atol=0))[0]) for f in wanted]
    for force in wanted:
        match = np.flatnonzero(np.isclose(unloading, force, rtol=1e-9, atol=0))
        if match.size:
            steps.append(loading.size + int(match[0]))
    return sorted(set(steps))


def _coarsened(field: np.ndarray, coordinates, points: int):
    """Return the block maxima of ``field`` (>= 0), at most ``points`` blocks per axis, and their centres."""
    factors = [max(1, math.ceil(n / points)) for n in field.shape]
    padded_shape = [-(-n // f) * f for n, f in zip(field.shape, factors, strict=True)]
    padded = np.zeros(padded_shape, dtype=field.dtype)
    padded[: field.shape[0], : field.shape[1]] = field
    (fx, fy), (px, py) = factors, padded_shape
    blocks = padded.reshape(px // fx, fx, py // fy, fy).max(axis=(1, 3))
    centres = [
        c[0] + (np.arange(p // f) * f + (f - 1) / 2) * (c[1] - c[0] if c.size > 1 else 0.0)
        for c, f, p in zip(coordinates, factors, padded_shape, strict=True)
    ]
    return blocks, centres


def run(parameters: LoadUnloadParameters, inputs) -> CaseOutput:
    """Load and unload the surface; scalars, the curve and the von Mises maps."""
    import xarray as xr

    from ...contact.load_unload import load_unload, plasticity_model

    surface = inputs.topography(parameters.topography)
    material = inputs.material(parameters.material)
    loading, unloading = load_targets(parameters.max_force, parameters.reference_force, parameters.load_steps)
    plasticity = plasticity_model(
        parameters.plasticity,
        hardness=parameters.hardness,
        yield_strength=parameters.yield_strength,
        hardening_modulus=parameters.hardening_modulus,
        depth=parameters.depth,
        layers=parameters.layers,
    )
    compression = load_unload(
        surface,
        material,
        forces=loading,
        unloading_forces=unloading,
        reference_force=parameters.reference_force,
        plasticity=plasticity,
        substrate=inputs.material(parameters.substrate),
        film_thickness=parameters.film_thickness,
        boundary="free",
        tolerance=parameters.tolerance,
    )
    peak_index = compression.peak
    chosen = _map_steps(parameters, loading, unloading)
    if parameters.plasticity == "volume":
        path = compression.volume
        layer = int(np.argmin(np.abs(path.depths - parameters.stress_depth)))
        stress_depth = float(path.depths[layer])
        maps = {i: path.von_mises[i, layer].astype(float) for i in sorted({*chosen, peak_index})}
    else:
        stress_depth = parameters.stress_depth
        maps = {
            i: compression.stress(i, depths=[stress_depth]).von_mises()[0]
            for i in sorted({*chosen, peak_index})
        }
    scalars = compression.scalars() | {"max_von_mises_at_peak": float(maps[peak_index].max())}
    scalars["surface_origin"] = inputs.origin(parameters.topography)
    scalars |= {
        "grid_points": int(surface.heights.size),
        "pixel_size": float(surface.size[0] / surface.shape[0]),
    }
    if surface.info.get("generator") == "raised_island" and "m4" in surface.info:  # paper 002's stand-in
        from ...papers.paper002 import island_top_moments

        scalars |= island_top_moments(surface)
    dataset = compression.to_xarray()
    dataset.attrs["stress_depth"] = stress_depth
    dataset.attrs["plasticity"] = parameters.plasticity
    coarse = [_coarsened(maps[i], surface.coordinates(), parameters.map_points) for i in chosen]
    x, y = coarse[0][1]
    dataset["von_mises"] = xr.DataArray(
        np.stack([blocks for blocks, _ in coarse]).astype(np.float32),
        dims=("map", "x", "y"),
        coords={
            "x": ("x", x, {"units": "m"}),
            "y": ("y", y, {"units": "m"}),
            "map_point": ("map", np.array(chosen)),
            "map_force": ("map", np.asarray(compression.curve()["force"])[chosen], {"units": "N"}),
            "map_branch": ("map", compression.branch[chosen].astype(str)),
        },
        attrs={
            "units": "Pa",
            "long_name": f"von Mises stress at z = {stress_depth:g} m (block maxima)",
        },
    )
    warnings: tuple[str, ...] = ()
    if parameters.plasticity == "volume":
        dataset["von_mises_section"] = _section(
            compression.volume, chosen, peak_index, surface, parameters.map_points
        )
        warnings = tuple(compression.range_warnings())
    return CaseOutput(scalars, dataset, warnings)


def _section(path, chosen: list[int], peak: int, surface, points: int):
    """Return the von Mises stress of the chosen steps on the x-z section carrying most of the peak load."""
    import xarray as xr

    row = int(np.argmax(path.pressure[peak].sum(axis=0)))  # the line that carries the most load
    x, y = surface.coordinates()
    step = max(1, math.ceil(x.size / points))
    sections = np.stack([path.von_mises[i][:, ::step, row].T for i in chosen])  # (map, x, z)
    return xr.DataArray(
        sections.astype(np.float32),
        dims=("map", "x_section", "z"),
        coords={
            "x_section": ("x_section", x[::step], {"units": "m"}),
            "z": ("z", path.depths, {"units": "m"}),
        },
        attrs={"units": "Pa", "long_name": f"von Mises stress on the section y = {format_si(y[row], 'm')}"},
    )


# --- figures -------------------------------------------------------------------------------------


def _statistical(records, context) -> dict[str, list]:
    """Return the finished cases of the study's ``asperity`` analyses, by analysis (Fig. 7's KKE curves)."""
    return {name: list(cases) for name, (model, cases) in context.others.items() if model == "asperity"}


def _mesh_convergence(records, context):
    """Return paper 002's Fig. 6 as a table: every quantity it and the comparison use, trends in notes.

    One row per quantity and grid (:meth:`roughcontact.asperity.convergence.QuantityConvergence.rows`:
    the mean over the realisations with its 95 % interval, the change per refinement of the mean
    and of each draw, the observed order or why there is none); one note per quantity says it in a
    sentence. None with fewer than two grids.
    """
    from ...asperity.convergence import mesh_convergence
    from ..store import Table

    found = mesh_convergence(records)
    if found is None:
        return None
    return Table([row for quantity in found for row in quantity.rows()], [q.summary() for q in found])


INTERVALS = {"one": "prediction interval", "mean": "confidence interval"}
"""The 95 % interval each row of the comparison rests on."""

COMPARED = ("peak_interference", "interference_at_return_force")
"""The interferences judged against the statistical model: at the peak, and back at the reference load."""

RENAMED_SCALARS = {"interference_at_return_force": "residual_interference"}
"""Scalars of the statistical model stored under another name by earlier versions (see the notes)."""


def _length(value: float) -> str:
    """Write an interference for a sentence: three digits with its prefix, a bound at zero as 0."""
    from ...units import format_si

    return "0" if value == 0 else format_si(value, "m", digits=3)


def _words(quantity: str, case) -> str:
    """Name a compared interference in a sentence, with the loads of the statistical case."""
    from ...units import format_si

    if quantity == "peak_interference":
        peak = case.scalars.get("peak_force")
        return "peak interference" + (f" (at {format_si(peak, 'N', digits=3)})" if peak else "")
    back = case.scalars.get("return_force")
    return (
        "interference back at "
        + (format_si(back, "N", digits=3) if back else "the return force")
        + (" on unloading")
    )


def _against_statistical(records, context):
    """Return the BEM's interferences over its realisations against each statistical (KKE) prediction.

    Per group of realisations (cases that differ only in ``replicate``), per case of the study's
    ``asperity`` analyses and per compared interference (:data:`COMPARED`: at the peak load, and
    back at the reference load on unloading), two rows: paper 002's claim is about ONE island, so
    the first judges with the 95 % prediction interval of one realisation, the second (``judged
    for = the mean``) with the 95 % confidence interval of the mean
    (:func:`roughcontact.asperity.comparison.against_realisations`). ``statistical model`` says
    whether KKE over-predicts, under-predicts, or whether that is not established (the interval
    holds KKE's value); ``statistical / bem`` is KKE's value over the BEM mean with the row's interval
    carried through ``x -> KKE / x``; ``paper's words`` is what paper 002 says (for cases with
    ``paper002 = true``). The table's notes say each comparison in a sentence. None without an
    asperity analysis.
    """
    from ...asperity.comparison import LEVELS, against_realisations
    from ...cases import realisations_of
    from ...papers.paper002 import STATISTICAL_WORDS
    from ..store import Table

    statistical = [(name, case) for name, cases in _statistical(records, context).items() for case in cases]
    statistical = [(n, c) for n, c in statistical if c.scalars.get("peak_interference") is not None]
    if not statistical:
        return None
    rows, notes = [], []
    for label, group in realisations_of(records).items():
        bem = label or context.analysis
        plasticity = group[0].parameters.get("plasticity", "surface")
        for name, case in statistical:
            omega_c = float(case.scalars["critical_interference"])
            model = f"{name} ({case.parameters.get('law', '')})"
            words = STATISTICAL_WORDS if case.parameters.get("paper002") else ""
            for quantity in COMPARED:
                value = case.scalars.get(quantity)
                if value is None or all(r.scalars.get(quantity) is None for r in group):
                    old = RENAMED_SCALARS.get(quantity)
                    if old is not None and old in case.scalars:
                        notes.append(
                            f"{quantity} not compared: the case of {name} was stored by an earlier "
                            f"roughcontact, whose {old} of the statistical model was this quantity "
                            "(the interference back at the reference load, not at zero load); run the "
                            "study again to compare it."
                        )
                    continue
                found = against_realisations(
                    float(value),
                    [float("nan") if r.scalars.get(quantity) is None else r.scalars[quantity] for r in group],
                    quantity=quantity,
                    bounds=BOUNDS[quantity],
                )
                for of in ("one", "mean"):
                    low, high = found.verdict(of).interval
                    ratio_low, ratio_high = found.ratio_interval(of)
                    rows.append(
                        {
                            "bem": f"{bem} ({plasticity} plasticity)",
                            "statistical": model,
                            "quantity": quantity,
                            "judged for": f"{LEVELS[of]} ({INTERVALS[of]})",
                            "n": found.deterministic.n,
                            "bem mean [m]": found.deterministic.mean,
                            "bem 95% low [m]": low,
                            "bem 95% high [m]": high,
                            "statistical [m]": found.statistical,
                            "bem mean / omega_c": found.deterministic.mean / omega_c,
                            "statistical / omega_c": found.statistical / omega_c,
                            "statistical / bem": found.ratio,
                            "statistical / bem 95% low": ratio_low,
                            "statistical / bem 95% high": None if math.isinf(ratio_high) else ratio_high,
                            "statistical model": found.model_words(of),
                            "paper's words": words,
                        }
                    )
                sentence = found.sentence(_length, words=words, name=_words(quantity, case))
                notes.append(f"{bem} ({plasticity} plasticity) against {model}: {sentence}")
    return Table(rows, notes)


BOUNDS = {"peak_interference": (0.0, math.inf), "interference_at_return_force": (0.0, math.inf)}
"""Interferences past the reference load are not negative (the residual at zero load may be)."""

KIND = Kind(
    name="load_unload",
    summary="elastic-plastic load-unload of a surface or a film island against a rigid flat punch "
    "(FFT-BEM, force control, paper 002 Figs. 7-9)",
    parameters=LoadUnloadParameters,
    run=run,
    units=LoadUnloadResult.UNITS
    | {"max_von_mises_at_peak": "Pa", "pixel_size": "m"}
    | {f"{who}_{m}": unit for who in ("top", "paper") for m, unit in (("m0", "m^2"), ("m4", "1/m^2"))},
    figures={
        "load_interference": figure(
            "asperity.island_load_interference_figure", {"statistical": _statistical, "measured": measured_of}
        ),
        "von_mises": figure("asperity.island_von_mises_figure"),
        "mesh_convergence": figure("asperity.mesh_convergence_figure"),
        "von_mises_section": figure("asperity.von_mises_section_figure"),
    },
    tables={"against_statistical": _against_statistical, "mesh_convergence": _mesh_convergence},
    compare=MeasuredCurve,
    bounds=BOUNDS,
    missing={
        "statistical / bem 95% high": "unbounded: the BEM interval reaches 0",
        "interference_at_return_force": "unloading never came back to the return force",
    },
    headline=(
        "peak_interference",
        "interference_at_return_force",
        "residual_interference",
        "peak_contact_area",
        "max_von_mises_at_peak",
    ),
    renamed={"surface": "topography", "peak_force": "max_force"},
    references=(
        "paper002",
        "polonsky1999",
        "stanley1997",
        "liu2000",
        "almqvist2007",
        "jacq2002",
        "frerot2019",
        "perriot2004",
        "johnson1985",
        "frigo2005",
    ),
)
