r"""Study kind ``tangential_path``: a rough ball under the user's own tangential programme (paper 001).

One case is one rough ball (heights *with* its spherical shape) pressed on a flat with a constant
normal force F0, then driven along a programme read from a file; it wraps
:func:`roughcontact.models.paper001.programme_case`:

1. Normal contact (paper 001 eq. 4) on a free (non-periodic) grid at F0; with ``window`` only the
   central ``window`` x ``window`` pixels are solved and the pressure must vanish on the window's
   border (as in the ``presliding`` kind).
2. The programme: ``path`` is a CSV with one row per step, x and optionally y, and a unit in
   every column's header (:func:`roughcontact.contact.paths.read_path_csv`). Lengths
   (``x [um], y [um]``) prescribe the rigid tangential displacement of the flat, forces
   (``Q_x [mN], Q_y [mN]``) the tangential force, which must stay below mu_f F0 (gross sliding
   under force control is refused). Each step is an increment under the local Coulomb law of
   eq. 3 with the history of the steps before it; with ``coupling`` the pressure is re-solved
   under the shear of dissimilar materials.
3. Per step: the rigid displacement, the force, the stick and slip areas; per closed loop of the
   x programme: the energy dissipated. When a displacement programme closes a loop that slides,
   the last loop is analysed as paper 001 does (stroke, mu, K_L at A, B, C;
   :func:`roughcontact.experiment.friction_loop.analyse_loop`); a loop that never slides has no
   sliding plateau to take mu from, and these scalars are NaN.

The file is read and checked when the study is validated, and its content is part of each case's
key (editing it reruns the cases on ``--resume``). It must be readable where the case runs (a
Dask worker on another machine needs the same path).

Scalars (SI): control (``displacement`` or ``force``), steps, normal_force, friction_coefficient,
contact_area, patches, max_pressure, last_delta_x, last_delta_y, last_force_x, last_force_y,
last_stick_fraction, loops (closed loops), energy_last_loop (NaN without one), mu_from_loop,
stroke_from_loop, K_L_A, K_L_B, K_L_C (NaN unless a displacement loop slides and its pre-sliding
part has the 4 steps the eq. 9 fit needs) and analysis_note (why they are NaN).

Dataset: per step from the unloaded start (``delta_x``, ``delta_y``, ``force_x``, ``force_y``,
``stick_area``, ``slip_area``), the normal-contact ``pressure`` map and the normalised shear
sqrt(q_x^2 + q_y^2)/(mu_f p) at the last reversals and the last step (``normalised_shear`` along
``kept``, with ``kept_step``, 1-based).

Figures: ``loops`` (F_x against delta_x for every case, one panel per sample) and ``stick_slip``
(the maps of up to two cases).

References
----------
Seed paper 001, eqs. 1-4 and 9 (doi:10.1115/1.4045900); K. L. Johnson, *Contact Mechanics*,
Cambridge University Press, 1985, sec. 7.4 (loading histories, Mindlin-Deresiewicz).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

import numpy as np
from pydantic import Field

from ..kind import CaseOutput, CaseParameters, Kind
from ..schema import Force, MaterialName, TopographyName
from .common import evenly_chosen, grouped
from .presliding import POINTS, shear_maps

_Positive = Field(gt=0.0, allow_inf_nan=False)


class TangentialPathParameters(CaseParameters):
    """Keys of a ``model = "tangential_path"`` analysis (SI after validation).

    Attributes
    ----------
    surface : str
        The ball: a topography with its spherical shape, e.g. a generated ``sphere_with_roughness``.
    window : int or None
        Solve only the central ``window`` x ``window`` pixels (free boundary); None solves the
        whole surface.
    material, counter : str
        The ball's material and the flat's (None: a rigid flat).
    normal_force : float
        F0 [N].
    friction_coefficient : float
        mu_f of the local Coulomb law, > 0.
    path : Path
        CSV of the programme, relative to the study file: one row per step, ``x [um]`` (and
        ``y [um]``) for displacement control or ``Q_x [mN]`` (and ``Q_y [mN]``) for force control.
    coupling : bool
        Normal-tangential coupling of dissimilar materials (default True).
    tolerance : float
        Relative tolerance of the normal and tangential solvers.
    maps : int
        Steps whose shear maps are stored: the last ``maps - 1`` reversals and the last step.
    """

    surface: TopographyName
    window: Annotated[int, Field(ge=3)] | None = None
    material: MaterialName
    counter: MaterialName | None = None
    normal_force: Annotated[Force, _Positive]
    friction_coefficient: Annotated[float, _Positive]
    path: Path
    coupling: bool = True
    tolerance: float = Field(default=1e-8, gt=0.0, lt=1.0)
    maps: Annotated[int, Field(ge=1, le=12)] = 4


def check(parameters: TangentialPathParameters) -> None:
    """Read the programme file at validation time (its errors name the file, row or column)."""
    from ...contact.paths import read_path_csv

    read_path_csv(parameters.path)


def run(parameters: TangentialPathParameters, inputs) -> CaseOutput:
    """Solve one ball under the programme of ``path``; scalars and dataset as in the module docstring."""
    from ...contact.paths import read_path_csv
    from ...models.paper001 import central_window, programme_case

    surface = inputs.topography(parameters.surface)
    if parameters.window is not None:
        surface = central_window(surface, parameters.window)
    programme, control = read_path_csv(parameters.path)
    ball = parameters.sample or parameters.surface
    case = programme_case(
        surface,
        inputs.material(parameters.material),
        inputs.material(parameters.counter),
        parameters.normal_force,
        path=programme,
        control=control,
        friction_coefficient=parameters.friction_coefficient,
        label=f"{ball} at {parameters.normal_force * 1e3:g} mN",
        coupling=parameters.coupling,
        tolerance=parameters.tolerance,
        maps=parameters.maps,
    )
    return CaseOutput(_scalars(case), _dataset(case, surface))


def _scalars(case) -> dict[str, Any]:
    """Return the scalars under plain names (:meth:`ProgrammeCase.scalars` has units in its keys)."""
    row = case.scalars()
    energies = row["energy_per_loop [J]"]
    analysis = case.analysis
    scalars: dict[str, Any] = {
        "control": case.control,
        "steps": row["steps"],
        "normal_force": row["F0 [N]"],
        "friction_coefficient": row["mu"],
        "contact_area": row["contact_area [m^2]"],
        "patches": row["patches"],
        "max_pressure": float(np.max(case.result.normal.pressure)),
        "last_delta_x": row["last_delta_x [m]"],
        "last_delta_y": row["last_delta_y [m]"],
        "last_force_x": row["last_F_x [N]"],
        "last_force_y": row["last_F_y [N]"],
        "last_stick_fraction": row["last_stick_fraction"],
        "loops": len(energies),
        "energy_last_loop": energies[-1] if energies else math.nan,
        "mu_from_loop": analysis.mu if analysis is not None else math.nan,
        "stroke_from_loop": analysis.stroke if analysis is not None else math.nan,
        "analysis_note": case.note,
    }
    for point in POINTS:
        scalars[f"K_L_{point}"] = analysis.lateral_stiffness[point] if analysis is not None else math.nan
    return scalars


def _dataset(case, surface):
    """Return the per-step series, the pressure and the kept shear maps on the window's x/y."""
    import xarray as xr

    result = case.result
    steps = list(case.map_steps.values())
    maps = np.stack([result.states[k].normalised_shear for k in steps])
    x, y = surface.coordinates()

    def from_start(series, start=0.0):
        return np.concatenate([[start], series])

    series = {
        "delta_x": (result.displacement[:, 0], "m", "rigid tangential displacement along x"),
        "delta_y": (result.displacement[:, 1], "m", "rigid tangential displacement along y"),
        "force_x": (result.force[:, 0], "N", "friction force F_x"),
        "force_y": (result.force[:, 1], "N", "friction force F_y"),
        "slip_area": (result.slip_area, "m^2", "slipping part of the contact"),
    }
    data = {
        name: ("step", from_start(values), {"units": unit, "long_name": text})
        for name, (values, unit, text) in series.items()
    }
    data["stick_area"] = ("step", from_start(result.stick_area, result.normal.contact_area), {"units": "m^2"})
    data["pressure"] = (("x", "y"), result.normal.pressure.astype(np.float32), {"units": "Pa"})
    data["normalised_shear"] = (
        ("kept", "x", "y"),
        maps.astype(np.float32),
        {"units": "1", "long_name": "sqrt(q_x^2 + q_y^2) / (mu p)"},
    )
    data["kept_step"] = ("kept", np.array([k + 1 for k in steps], dtype=np.int32))
    return xr.Dataset(
        data,
        coords={
            "step": ("step", np.arange(result.steps + 1)),
            "x": ("x", x, {"units": "m"}),
            "y": ("y", y, {"units": "m"}),
        },
        attrs={"control": case.control},
    )


# --- figures (from stored records only) ----------------------------------------------------------


def _loops(records, context):
    """F_x against delta_x of every case, one panel per sample."""
    from ...plotting.presliding import plot_hysteresis_loops
    from ...plotting.study import new_figure

    groups = grouped([r for r in records if r.fields_path is not None])
    if not groups:
        return None
    figure, axes = new_figure(1, len(groups), width=5.5, height=4.2)
    for ax, (sample, group) in zip(axes[0], groups.items(), strict=True):
        curves = []
        for record in group:
            data = record.dataset()
            force, mu = record.scalars["normal_force"], record.scalars["friction_coefficient"]
            label = f"{force * 1e3:g} mN, μ {mu:g}, {data.attrs['control']}"
            curves.append((np.asarray(data["delta_x"]), np.asarray(data["force_x"]), label))
        plot_hysteresis_loops(curves, ax=ax, title=f"{sample or context.analysis}: friction loops")
    return figure


def _stick_slip(records, context):
    """Normalised shear maps at the kept steps of up to two cases."""
    chosen = evenly_chosen([r for r in records if r.fields_path is not None], 2)
    if not chosen:
        return None
    panels = []
    for record in chosen:
        data = record.dataset()
        name = record.parameters.get("sample") or record.parameters["surface"]
        for index, step in enumerate(np.asarray(data["kept_step"]).tolist()):
            delta = float(data["delta_x"][step]) * 1e6
            values = data["normalised_shear"].isel(kept=index)
            panels.append((f"{name}, step {step} (δx {delta:.3g} µm)", values, data["x"], data["y"]))
    return shear_maps(panels, columns=max(len(panels) // len(chosen), 1))


UNITS = {
    "normal_force": "N",
    "contact_area": "m^2",
    "max_pressure": "Pa",
    "last_delta_x": "m",
    "last_delta_y": "m",
    "last_force_x": "N",
    "last_force_y": "N",
    "energy_last_loop": "J",
    "stroke_from_loop": "m",
    **{f"K_L_{p}": "N/m" for p in POINTS},
}
"""Scalar name -> SI unit (the results table's column headers)."""

KIND = Kind(
    name="tangential_path",
    summary="rough ball on a flat under your own displacement or force programme (CSV): loops, maps",
    parameters=TangentialPathParameters,
    run=run,
    units=UNITS,
    figures={"loops": _loops, "stick_slip": _stick_slip},
    check=check,
)
