r"""Pre-sliding of a rough ball on a flat: the tangential programme, its last loop, Mindlin's smooth ball.

The driver of paper 001's model on any ball and any programme (the paper's stroke path of Fig. 6
or a user's displacement or force programme, with or without a normal programme): the normal
contact at F0 (eq. 4, free boundary, checked not to reach the window's border), the tangential
programme under the local Coulomb law of eq. 3 with its history
(:func:`~roughcontact.contact.tangential.solve_tangential`, or
:func:`~roughcontact.contact.frictional.solve_frictional` for a combined programme), the analysis
of the last loop as the paper does (:func:`~roughcontact.experiment.friction_loop.analyse_loop`:
stroke, mu, eq. 9, K_L at the loop points A, B, C) and Mindlin's smooth ball at the same points
(eqs. 10-12, :func:`mindlin_reference`, in the textbook reading and as the paper prints it).
Paper 001's own scenario (Tables 1-2, the generated balls) is :mod:`roughcontact.papers.paper001`.
Mindlin's smooth ball is in :mod:`.smooth_ball`, the choice of the solved window in :mod:`.window`;
both are served from here as well.

References
----------
Seed paper 001, secs. 2-5, eqs. 3-4 and 9-12, Figs. 6-15. doi:10.1115/1.4045900
K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, sec. 7.4.
doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ..display_html import NotebookDisplay
from ..errors import InputError
from ..experiment.friction_loop import LoopAnalysis, analyse_loop
from ..materials import Material
from ..topography import Topography
from ..topography.surface import topography_argument
from .frictional import solve_frictional
from .normal import solve_normal
from .paths import as_path, reversals, stroke_path
from .shear_solver import ShearSolver
from .smooth_ball import (
    MINDLIN_READINGS,
    NORMALISATIONS,
    POINT_NAMES,
    POINTS,
    READING_WORDS,
    MindlinReference,
    effective_shear_modulus_paper001,
    mindlin_ratios,
    mindlin_reference,
    rough_vs_smooth,
    verdict_words,
)
from .tangential import solve_tangential
from .window import (
    WINDOW_MARGIN,
    ContactWindow,
    check_inside,
    contact_window,
    solved_window,
    touches_border,
    window_holds,
)

__all__ = [  # the model, and the names of its two neighbours it has always served
    "MINDLIN_READINGS",
    "NORMALISATIONS",
    "POINTS",
    "POINT_NAMES",
    "READING_WORDS",
    "WINDOW_MARGIN",
    "ContactWindow",
    "MindlinReference",
    "PreslidingResult",
    "check_inside",
    "contact_window",
    "effective_shear_modulus_paper001",
    "loop_from_start",
    "mindlin_ratios",
    "mindlin_reference",
    "presliding",
    "rough_vs_smooth",
    "touches_border",
    "verdict_words",
    "window_holds",
]


def loop_from_start(result) -> tuple[np.ndarray, np.ndarray]:
    """Return a tangential result's x displacement [m] and force [N] from the unloaded start (0, 0).

    The record that :func:`~roughcontact.experiment.friction_loop.analyse_loop` takes and the loop
    figures draw.
    """
    return (
        np.concatenate([[0.0], result.displacement[:, 0]]),
        np.concatenate([[0.0], result.force[:, 0]]),
    )


def _start_stick_area(result) -> float:
    """Return the stick area where the programme starts (after the loading, the whole contact, or 0)."""
    if result.loading is not None:
        return float(result.loading.stick_area[-1])
    return float(result.normal.contact_area) if result.normal is not None else 0.0


@dataclass(frozen=True)
class PreslidingResult(NotebookDisplay):
    """A rough ball on a flat under a tangential programme, its last loop analysed, against Mindlin.

    The result of :func:`presliding` (paper 001's model): the normal contact at F0, the
    tangential programme (paper 001's Fig. 6 stroke path or any user programme, under
    displacement or force control), the analysis of its last loop as the paper does (stroke, mu,
    eq. 9 fit, K_L at A, B, C; None where there is no sliding loop to analyse, and ``note`` says
    why) and Mindlin's K_L of a smooth ball of ``radius`` at the same points (eqs. 10-12, both
    readings).

    Attributes
    ----------
    label : str
        Names the case in figures and tables.
    normal_force, friction_coefficient, radius : float
        F0 [N], mu_f [-], the ball radius of Mindlin's reference [m].
    control : {"displacement", "force"}
        What the programme prescribes.
    stroke : float or None
        d_s [m] of paper 001's programme; None for a user programme.
    result : TangentialPathResult
        Every step (forces, displacements, stick and slip areas) and the kept fields.
    normal : NormalContactResult
        The frictionless normal contact at F0 (for a combined programme, at its largest normal
        force or approach): the pressure map, the contact area and the window check.
    analysis : LoopAnalysis or None
        The last loop's analysis.
    note : str
        Why there is no analysis (empty when there is one).
    mindlin : dict
        Reading (``johnson``, ``printed``) -> point -> Mindlin's K_L [N/m].
    hertz_radius : float
        Hertz contact radius a of the smooth ball (eq. 11) [m].
    sliding_distance_mindlin : float
        2 delta_0, Mindlin's pre-sliding distance of a reversed branch (Johnson reading) [m].
    map_steps : dict
        Label -> step index of the kept shear maps: the points A, B, C of the last loop for the
        paper's programme, the last reversals and the last step for a user programme.
    window_choice : str
        The part of the scan that was solved and how it was chosen (``window``): the whole scan,
        a given window or the one ``"auto"`` chose.
    window_warnings : tuple of str
        What a given window cannot vouch for: points of the ball outside it that may touch.
    """

    label: str
    normal_force: float
    friction_coefficient: float
    radius: float
    control: str
    stroke: float | None
    result: Any  # TangentialPathResult
    normal: Any  # NormalContactResult
    analysis: LoopAnalysis | None
    note: str
    mindlin: dict[str, dict[str, float]]
    hertz_radius: float
    sliding_distance_mindlin: float
    map_steps: dict[str, int]
    window_choice: str = "the whole scan (window not given)"
    window_warnings: tuple[str, ...] = ()

    UNITS: ClassVar[dict[str, str]] = {
        "normal_force": "N",
        "stroke": "m",
        "radius": "m",
        "contact_area": "m^2",
        "contact_area_corrected": "m^2",
        "max_pressure": "Pa",
        "last_delta_x": "m",
        "last_delta_y": "m",
        "last_force_x": "N",
        "last_force_y": "N",
        "stroke_from_loop": "m",
        "energy_last_loop": "J",
        "presliding_distance": "m",
        "eq9_c1": "N",
        "eq9_c2": "1/m",
        **{f"K_L_{p}": "N/m" for p in POINT_NAMES},
        **{f"K_L_{p}_mindlin_{r}": "N/m" for r in MINDLIN_READINGS for p in POINT_NAMES},
        "hertz_radius": "m",
        "sliding_distance_mindlin": "m",
        "window_size": "m",
        "pixel": "m",
        "locked_in_shear_rms": "Pa",
    }
    """SI unit of each dimensional scalar of :meth:`scalars`."""

    @property
    def converged(self) -> bool:
        """True when every step met its tolerance."""
        return self.result.converged

    @property
    def iterations(self) -> int:
        """Tangential iterations of the whole programme (the normal solve's are in ``normal``)."""
        return int(self.result.iterations.sum())

    @property
    def residual(self) -> float:
        """Largest residual of the programme's steps."""
        return float(self.result.residual.max())

    def loop(self) -> tuple[np.ndarray, np.ndarray]:
        """Displacement [m] and friction force [N] along x from the start (0, 0), all steps."""
        return loop_from_start(self.result)

    def range_warnings(self) -> list[str]:
        """Return what the solved window cannot vouch for (:attr:`window_warnings`)."""
        return list(self.window_warnings)

    def scalars(self) -> dict[str, Any]:
        """Return the scalars (SI, units in :attr:`UNITS`).

        The programme (control, steps, normal_force, friction_coefficient, radius, and stroke for
        paper 001's), the contact (contact_area, patches, max_pressure), the last step
        (last_delta_x, last_delta_y, last_force_x, last_force_y, last_stick_fraction), the closed
        loops, the last loop's analysis (stroke_from_loop, mu_from_loop, energy_last_loop,
        presliding_distance, eq9_c1, eq9_c2, eq9_n, K_L_A, K_L_B, K_L_C: NaN without one, and
        analysis_note says why), Mindlin's reference (K_L_A_mindlin_johnson, ...,
        K_L_C_mindlin_printed, hertz_radius, sliding_distance_mindlin) and the numerics
        (window_size, window_pixels, pixel, coupling, iterations, residual).

        energy_last_loop is the area of the analysed loop (0 -> d_s -> 0) for paper 001's
        programme, and of the last loop the x programme closes for a user programme.
        """
        result, analysis, normal = self.result, self.analysis, self.normal
        path = result.scalars()
        scalars: dict[str, Any] = {"control": self.control, "steps": result.steps}
        scalars["normal_force"] = self.normal_force
        if self.stroke is not None:
            scalars["stroke"] = self.stroke
        scalars |= {
            "friction_coefficient": self.friction_coefficient,
            "radius": self.radius,
            "contact_area": normal.contact_area,
            "contact_area_corrected": normal.contact_area_corrected,  # for its pixelated perimeter
            "patches": normal.number_of_patches,
            "max_pressure": float(np.max(normal.pressure)),
        }
        scalars |= {key: path[key] for key in _LAST_STEP}
        scalars["loops"] = path["loops"]
        if self.stroke is None or analysis is None:
            scalars["energy_last_loop"] = path["energy_last_closed_loop"]
        else:
            scalars["energy_last_loop"] = analysis.energy
        nan = math.nan
        branch = analysis.branch if analysis is not None else None
        scalars |= {
            "stroke_from_loop": analysis.stroke if analysis is not None else nan,
            "mu_from_loop": analysis.mu if analysis is not None else nan,
            "presliding_distance": branch.sliding_distance if branch is not None else nan,
            "eq9_c1": branch.c1 if branch is not None else nan,
            "eq9_c2": branch.c2 if branch is not None else nan,
            "eq9_n": branch.n if branch is not None else nan,
        }
        stiffness = analysis.lateral_stiffness if analysis is not None else {}
        for point in POINT_NAMES:
            scalars[f"K_L_{point}"] = stiffness.get(point, nan)
        for reading, values in self.mindlin.items():
            for point, value in values.items():
                scalars[f"K_L_{point}_mindlin_{reading}"] = value
        topography = normal.topography
        scalars |= {
            "hertz_radius": self.hertz_radius,
            "sliding_distance_mindlin": self.sliding_distance_mindlin,
            "window_size": topography.size[0],
            "window_pixels": int(topography.shape[0]),
            "pixel": topography.spacing[0],
            "coupling": bool(result.parameters.get("coupling", True)),
            "normal_loading": result.parameters.get("normal_loading", "frictionless"),
            **{key: path[key] for key in ("locked_in_stick_fraction", "locked_in_shear_rms")},
            "inserted_steps": int(result.steps - (result.programme_index.max() + 1)),
            "loading_steps": 0 if result.loading is None else int(result.loading.steps),
            "iterations": self.iterations,
            "residual": self.residual,
            "analysis_note": self.note,
        }
        return scalars

    def to_xarray(self):
        """Return the programme as an ``xarray.Dataset`` on the solved window's x/y [m].

        Per step from the unloaded start (``step`` 0): ``delta_x``, ``delta_y``, ``force_x``,
        ``force_y``, ``stick_area``, ``slip_area``; the normal-contact ``pressure`` map; the
        normalised shear sqrt(q_x^2 + q_y^2) / (mu_f p) (< 1 stick, 1 slip, NaN outside the
        contact; paper Figs. 11-12) at the kept steps (``normalised_shear`` along ``map``, with
        ``map_step``, the step counted from the start); the energy dissipated in each closed loop
        (``loop_energy``); for an analysed loop the points' fitted ``point_displacement`` and
        ``point_force``. Maps in single precision.
        """
        import xarray as xr

        result = self.result
        labels = list(self.map_steps)
        steps = [self.map_steps[label] for label in labels]
        x, y = self.normal.topography.coordinates()

        def from_start(series, start=0.0):
            return np.concatenate([[start], series])

        series = {
            "delta_x": (result.displacement[:, 0], "m", "rigid tangential displacement along x"),
            "delta_y": (result.displacement[:, 1], "m", "rigid tangential displacement along y"),
            "force_x": (result.force[:, 0], "N", "friction force F_x"),
            "force_y": (result.force[:, 1], "N", "friction force F_y"),
            "slip_area": (result.slip_area, "m^2", "slipping part of the contact"),
        }
        start_load = 0.0 if result.normal is None else result.normal.force
        data = {
            name: ("step", from_start(values), {"units": unit, "long_name": text})
            for name, (values, unit, text) in series.items()
        }
        data["normal_force"] = ("step", from_start(result.normal_load, start_load), {"units": "N"})
        loading = result.loading
        data["stick_area"] = (
            "step",
            from_start(result.stick_area, _start_stick_area(result)),
            {"units": "m^2", "long_name": "sticking part of the contact"},
        )
        data["pressure"] = (("x", "y"), self.normal.pressure.astype(np.float32), {"units": "Pa"})
        data["normalised_shear"] = (
            ("map", "x", "y"),
            np.stack([result.states[k].normalised_shear for k in steps]).astype(np.float32),
            {"units": "1", "long_name": "sqrt(q_x^2 + q_y^2) / (mu p)"},
        )
        data["map_step"] = ("map", np.array([k + 1 for k in steps], dtype=np.int32))
        data["programme_point"] = (
            "step",
            from_start(result.programme_index + 1, 0).astype(np.int32),
            {"long_name": "programme point each step belongs to (inserted steps share the next point's)"},
        )
        if loading is not None:
            data["locked_in_shear"] = (
                ("x", "y"),
                loading.states[loading.steps - 1].normalised_shear.astype(np.float32),
                {
                    "units": "1",
                    "long_name": "sqrt(q_x^2 + q_y^2) / (mu p) after the frictional normal loading",
                },
            )
        data["loop_energy"] = (
            "loop",
            result.dissipated_energy(),
            {"units": "J", "long_name": "energy dissipated in each loop the x programme closes"},
        )
        attrs: dict[str, Any] = {"control": self.control, "label": self.label}
        if self.analysis is not None:
            branch = self.analysis.branch
            attrs |= {
                "last_loop_start": int(self.analysis.loop.start),
                "last_loop_stop": int(self.analysis.loop.stop),
                "reversal_displacement": float(branch.reversal_displacement),
            }
            if labels == list(self.analysis.point_names):
                data["point_displacement"] = ("map", np.asarray(branch.point_displacement), {"units": "m"})
                data["point_force"] = ("map", np.asarray(branch.point_force), {"units": "N"})
        return xr.Dataset(
            data,
            coords={
                "step": ("step", np.arange(result.steps + 1)),
                "map": ("map", labels),
                "x": ("x", x, {"units": "m"}),
                "y": ("y", y, {"units": "m"}),
            },
            attrs=attrs,
        )


_LAST_STEP = ("last_delta_x", "last_delta_y", "last_force_x", "last_force_y", "last_stick_fraction")


def _analysed(result, normal_force: float, control: str) -> tuple[LoopAnalysis | None, str]:
    """Analyse the last loop as paper 001 does where the programme has one that slides; else say why."""
    if control == "force":
        return None, "force control: the paper's loop analysis needs a displacement programme that slides"
    loops = result.loops()
    if not loops:
        return None, "no closed loop of the x programme"
    start, stop = loops[-1]
    loads = result.normal_load[start : stop + 1]
    if np.ptp(loads) > 1e-6 * loads.max():
        return None, "the normal force varies along the last loop: the paper's analysis needs it constant"
    try:
        analysis = analyse_loop(*loop_from_start(result), normal_force, fractions=POINTS)
    except InputError as error:  # e.g. too few steps in the pre-sliding part for the eq. 9 fit
        return None, f"last loop not analysed: {error.problem} {error.fix or ''}".strip()
    if analysis.mu is None or not math.isfinite(analysis.mu):
        return None, "last loop not analysed: it never slides (no plateau to take mu from)"
    return analysis, ""


def presliding(
    topography: Topography,
    material: Material,
    counter_body: Material | None = None,
    *,
    normal_force: float | None = None,
    friction_coefficient: float,
    stroke: float | None = None,
    cycles: int = 4,
    steps_per_stroke: int = 20,
    path=None,
    control: str = "displacement",
    normal_path=None,
    normal_control: str = "force",
    radius: float,
    coupling: bool = True,
    normal_loading: str = "auto",
    loading_steps: int = 10,
    max_stick_change: float | None = 0.1,
    tolerance: float = 1e-8,
    maps: int = 4,
    window: int | str | None = None,
    label: str = "",
) -> PreslidingResult:
    """Run paper 001's model: a rough ball pressed on a flat, then a tangential programme.

    0. The part of ``topography`` that is solved (``window``): the whole of it, a central window
       of a given size, or the smallest one that holds every point that can touch
       (:func:`contact_window`).
    1. Normal contact at ``normal_force`` (paper 001 eq. 4, free boundary); the pressure must
       vanish on the border of the solved window, else an error asks for a larger window.
    2. The programme, either paper 001's (``stroke``: 0 -> d_s -> 0, ``cycles`` times, Fig. 6,
       ``steps_per_stroke`` per branch spaced quadratically from each reversal so the short
       pre-sliding part is resolved) or the user's (``path``: an (n,) or (n, 2) array of the
       rigid tangential displacement [m] or the tangential force [N] after each step, as
       ``control`` says; e.g. from :func:`roughcontact.contact.paths.read_path_csv`), solved by
       :func:`~roughcontact.contact.tangential.solve_tangential` under the local Coulomb law of
       eq. 3 with the history of every step.
    3. The last loop, where the x programme closes one that slides, analysed as the paper does
       (:func:`~roughcontact.experiment.friction_loop.analyse_loop`: stroke, mu, eq. 9, K_L at A,
       B, C = 0.25, 0.5, 0.75 of the pre-sliding span). A loop that never slides, a force
       programme (no sliding plateau to take mu from) and a pre-sliding part too short for the
       eq. 9 fit are not analysed: ``note`` says which, and the rest of the results stand.
    4. Mindlin's K_L of a smooth ball of ``radius`` at the same points (eqs. 10-12, the textbook
       reading and the paper's printed one, 4x larger).

    With ``normal_path`` (a normal force or approach for every row of ``path``) the programme is a
    combined one, solved from the unloaded state by
    :func:`~roughcontact.contact.frictional.solve_frictional` (no ``normal_force``): the normal
    contact of the result (pressure map, window check, Mindlin's reference) is then the
    frictionless one at the programme's largest normal force or approach, and the last loop is
    analysed only where the normal force is constant along it.

    Fields are kept at the points A, B, C of the last loop for the paper's programme, else at the
    last ``maps - 1`` reversals and the last step.

    Parameters
    ----------
    topography : Topography
        The ball with its spherical shape (paper Fig. 4), e.g. the
        :func:`~roughcontact.topography.process.central_window` of a scan.
    material, counter_body : Material
        The ball and the flat (None: rigid).
    normal_force : float
        F0 [N] (not with ``normal_path``).
    friction_coefficient : float
        mu_f of the local Coulomb law.
    stroke : float, optional
        d_s [m] of paper 001's programme; or give ``path``.
    cycles, steps_per_stroke : int
        Of paper 001's programme.
    path : array_like, optional
        The user's programme.
    control : {"displacement", "force"}
        What ``path`` prescribes.
    normal_path : array_like, optional
        Normal force [N] or approach [m] after each row of ``path`` (combined programme).
    normal_control : {"force", "approach"}
        What ``normal_path`` prescribes.
    radius : float
        Ball radius R of Mindlin's reference [m] (paper 001: 5 mm).
    coupling : bool
        Normal-tangential coupling of dissimilar materials (False: Goodman's approximation).
    normal_loading : {"auto", "frictional", "frictionless"}
        How F0 is applied before the programme (:func:`~roughcontact.contact.tangential.solve_tangential`):
        "auto" is "frictional" for a coupled pair (beta != 0), which locks in shear (Spence 1975).
    loading_steps : int
        Steps of the frictional normal loading (default 10: enough for ``|beta|``/mu of paper 001's
        pairs; beta/mu near 1 needs 30 or more to resolve Spence's stick zone).
    max_stick_change : float, optional
        Step control (default 0.1): steps are inserted where the stick fraction would change by
        more than this in one step, so every pre-sliding branch has at least 10 steps between
        its reversal and full slip; the programme's own points are all solved. None: the
        programme's points only.
    tolerance : float
        Of the normal and tangential solvers.
    maps : int
        Kept maps of a user programme.
    window : int or "auto", optional
        The central window of ``topography`` to solve [px] (free boundary); ``"auto"`` chooses the
        smallest that holds every point that can touch at the largest normal force or approach of
        the programme (:func:`contact_window`); None (default) solves the whole ``topography``.
        With a given window the result's :meth:`~PreslidingResult.range_warnings` say where points
        outside it may touch.
    label : str
        Names the case in messages and figures.

    Returns
    -------
    PreslidingResult

    Raises
    ------
    InputError
        Both or neither of ``stroke`` and ``path``, an unknown control, a contact that reaches the
        window's border, and the solvers' refusals.
    ConvergenceError
        A solve did not converge.
    """
    topography = topography_argument(topography, "topography")
    if (stroke is None) == (path is None):
        raise InputError(
            "stroke",
            "give the stroke of paper 001's programme or a path, exactly one.",
            "e.g. stroke=2.8e-6.",
        )
    if control not in ("displacement", "force"):
        raise InputError("control", f"unknown control {control!r}.", "use 'displacement' or 'force'.")
    if stroke is not None:
        control = "displacement"
        path = stroke_path(stroke, cycles=cycles, steps_per_stroke=steps_per_stroke, spacing="quadratic")
    path = as_path(path, control)
    if (normal_path is None) == (normal_force is None):
        raise InputError(
            "normal_force",
            "give the constant normal force F0 or a normal programme (normal_path), exactly one.",
            "e.g. normal_force=0.025 (N), or a path file with an 'F_n [mN]' column.",
        )
    peak = {"force": normal_force} if normal_path is None else {normal_control: float(np.max(normal_path))}
    scan = topography
    topography, window_choice = solved_window(
        scan,
        window,
        material,
        counter_body,
        normal_force=peak.get("force"),
        approach=peak.get("approach"),
        radius=radius,
        tolerance=tolerance,
    )
    normal = solve_normal(topography, material, counter_body=counter_body, tolerance=tolerance, **peak)
    normal_force = normal.force if normal_path is not None else normal_force
    check_inside(normal.pressure, label or "the surface")
    normal_turns = [] if normal_path is None else reversals(normal_path)
    turns = sorted({int(k) for k in reversals(path[:, 0])} | {int(k) for k in normal_turns})
    last_turns = sorted(set(turns[max(len(turns) - maps + 1, 0) :]) | {len(path) - 1})
    if stroke is not None:  # the last cycle, where the points A, B, C are looked for
        kept = list(range(len(path) - 2 * steps_per_stroke, len(path)))
    else:
        kept = last_turns
    common = dict(
        counter_body=counter_body,
        friction_coefficient=friction_coefficient,
        coupling=coupling,
        max_stick_change=max_stick_change,
        solver=ShearSolver(tolerance=tolerance),
        fields_at=kept,
        **{control: path},
    )
    if normal_path is None:
        result = solve_tangential(
            normal, material, normal_loading=normal_loading, loading_steps=loading_steps, **common
        )
    else:
        normal_target = {"normal_force" if normal_control == "force" else "approach": normal_path}
        result = solve_frictional(topography, material, **normal_target, **common)
    analysis, note = _analysed(result, normal_force, control)
    if stroke is not None and analysis is not None:
        rising = analysis.branch.direction > 0
        first_falling = len(path) - steps_per_stroke  # programme point where the last cycle turns back
        branch = [k for k in result.states if (result.programme_index[k] < first_falling) == rising]
        targets = zip(analysis.point_names, analysis.branch.point_displacement, strict=True)
        map_steps = {
            point: min(branch, key=lambda k, target=target: abs(result.displacement[k, 0] - target))
            for point, target in targets
        }
    else:
        map_steps = {f"step {result.step_of(k) + 1}": result.step_of(k) for k in last_turns if k in kept}
    references = {
        reading: mindlin_reference(
            friction_coefficient=friction_coefficient,
            normal_force=normal_force,
            radius=radius,
            material=material,
            counter_body=counter_body,
            normalisation=reading,
        )
        for reading in MINDLIN_READINGS
    }
    textbook = references["johnson"]
    return PreslidingResult(
        label=label,
        normal_force=float(normal_force),
        friction_coefficient=float(friction_coefficient),
        radius=float(radius),
        control=control,
        stroke=None if stroke is None else float(stroke),
        result=result,
        normal=normal,
        analysis=analysis,
        note=note,
        mindlin={
            reading: dict(zip(POINT_NAMES, map(float, reference.point_stiffness(POINTS)), strict=True))
            for reading, reference in references.items()
        },
        hertz_radius=textbook.contact_radius,
        sliding_distance_mindlin=2.0 * textbook.sliding_distance,
        map_steps=map_steps,
        window_choice=window_choice,
        window_warnings=_window_warnings(scan, normal, window),
    )


def _window_warnings(scan: Topography, normal, window: int | str | None) -> tuple[str, ...]:
    """Say where points of the ball outside a given window lie within the approach and may touch."""
    if not isinstance(window, int):
        return ()
    holds, depth = window_holds(scan, normal)
    if holds:
        return ()
    return (
        f"points of the ball outside the given {window} px window lie within the approach "
        f"({depth * 1e6:.3g} um below the highest point) and may touch: the window's answer is not "
        "proven to hold the whole contact. «window=auto» chooses one that holds them.",
    )
