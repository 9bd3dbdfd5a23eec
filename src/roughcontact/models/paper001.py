"""Paper 001's case: a rough polymer ball on a silicon wafer, pre-sliding loops and K_L vs Mindlin.

Inputs as the paper gives them:

* balls of 10 mm diameter (R = 5 mm), HDPE (0.98 GPa) and POM (1.38 GPa), nu = 0.5, on a
  silicon wafer (130 GPa, 0.28), Table 2; the wafer is smooth (sec. 4);
* ball roughness: RMS 3.17 um (HDPE) and 0.67 um (POM) after removing the sphere (Fig. 5),
  measured on 1.1 mm x 1.1 mm with 1024 x 1024 pixels (1.07 um);
* normal loads 25, 50, 75 mN with the strokes d_s and friction coefficients of Table 1;
* the displacement path of Fig. 6: 0 -> d_s -> 0, four cycles; the last loop is compared.

What the paper does not give, and what is done instead (stated in every result):

* the scans: without a file, a rough sphere is generated (:func:`roughness` : self-affine,
  Hurst 0.8, seeded, rms as Table 2, on the paper's 1.1 mm / 1024 px field);
* the solved window: only a small central part of the ball touches (paper Figs. 8-9), so the
  free-boundary problem is solved on the central ``window`` x ``window`` pixels at the scan's
  resolution (default 160 px of a 512 px scan = 0.34 mm; the paper zooms to 0.2 mm); the
  pressure is checked to vanish on the window's border, else an error asks for a larger window;
* the steps of the path: ``steps_per_stroke`` per branch, spaced quadratically from each reversal
  so the pre-sliding part (a fraction of a micrometre) is resolved.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..analytic.mindlin import paper001_mindlin
from ..contact import solve_normal
from ..contact.paths import as_path, reversals, stroke_path
from ..contact.tangential import solve_tangential
from ..errors import InputError
from ..experiment.friction_loop import LoopAnalysis, analyse_loop
from ..materials import Material, get_material
from ..topography import Topography, generate
from ..topography.process import crop

RADIUS = 5e-3
FIELD = 1.1e-3
SCAN_PIXELS = 1024
ROUGHNESS = {"HDPE": 3.17e-6, "POM": 0.67e-6}
# Table 1: F0 [N] -> (stroke [m], mu) per ball
TABLE1 = {
    "HDPE": {0.025: (2.805e-6, 0.153), 0.050: (2.943e-6, 0.146), 0.075: (3.697e-6, 0.129)},
    "POM": {0.025: (2.700e-6, 0.108), 0.050: (3.370e-6, 0.104), 0.075: (4.264e-6, 0.099)},
}
POINTS = (0.25, 0.5, 0.75)


def _ball(name: str) -> str:
    key = name.upper()
    if key not in ROUGHNESS:
        raise InputError("ball", f"unknown ball {name!r}.", "use 'HDPE' or 'POM'.")
    return key


def roughness(ball: str, *, seed: int = 1, pixels: int = SCAN_PIXELS) -> Topography:
    """Generate a ball scan: sphere R = 5 mm plus self-affine roughness of Table 2's rms (1.1 mm field)."""
    return generate.sphere_with_roughness(
        (pixels, pixels), (FIELD, FIELD), radius=RADIUS, rms_height=ROUGHNESS[_ball(ball)], seed=seed
    )


def central_window(scan: Topography, window: int) -> Topography:
    """Return the central ``window`` x ``window`` pixels of a scan (at its resolution), non-periodic."""
    nx, ny = scan.shape
    if window > min(nx, ny):
        raise InputError("window", f"{window} px exceeds the scan ({nx} x {ny}).", "use a smaller window.")
    hx, hy = scan.spacing
    i, j = (nx - window) // 2, (ny - window) // 2
    return crop(scan, ((i - 0.5) * hx, (i + window - 0.5) * hx), ((j - 0.5) * hy, (j + window - 0.5) * hy))


def _check_inside(pressure: np.ndarray, label: str) -> None:
    border = np.concatenate([pressure[0], pressure[-1], pressure[:, 0], pressure[:, -1]])
    if np.any(border > 0):
        raise InputError(
            "window",
            f"{label}: the contact reaches the border of the solved window, so the free-boundary "
            "answer would be cut off.",
            "pass a larger window (pixels) or a coarser scan.",
        )


def loop_from_start(result) -> tuple[np.ndarray, np.ndarray]:
    """Return a tangential result's x displacement [m] and force [N] from the unloaded start (0, 0).

    The record that :func:`~roughcontact.experiment.friction_loop.analyse_loop` takes and the loop
    figures draw.
    """
    return (
        np.concatenate([[0.0], result.displacement[:, 0]]),
        np.concatenate([[0.0], result.force[:, 0]]),
    )


@dataclass(frozen=True)
class PreslidingCase:
    """One ball at one load: the simulated programme, its last-loop analysis and Mindlin's K_L."""

    label: str
    ball: str
    normal_force: float
    stroke: float
    friction_coefficient: float
    result: Any  # TangentialPathResult
    analysis: LoopAnalysis
    mindlin: dict[str, Any]
    point_steps: dict[str, int]
    notes: dict[str, Any] = field(default_factory=dict)

    def loop(self) -> tuple[np.ndarray, np.ndarray]:
        """Displacement [m] and friction force [N] from the start (0, 0), all steps."""
        return loop_from_start(self.result)

    def scalars(self) -> dict[str, float]:
        """Table row: inputs, contact, K_L at A, B, C simulated and Mindlin (both readings) [N/m]."""
        row = {
            "case": self.label,
            "ball": self.ball,
            "F0 [N]": self.normal_force,
            "stroke [m]": self.stroke,
            "mu": self.friction_coefficient,
            "contact_area [m^2]": self.result.normal.contact_area,
            "patches": self.result.normal.number_of_patches,
            "mu_from_loop": self.analysis.mu,
            "energy_last_loop [J]": self.analysis.energy,
        }
        for name, value in self.analysis.lateral_stiffness.items():
            row[f"K_L_{name} [N/m]"] = value
        for reading, values in self.mindlin.items():
            for name, value in values.items():
                row[f"K_L_{name}_mindlin_{reading} [N/m]"] = value
        row.update({f"note_{k}": v for k, v in self.notes.items()})
        return row


def presliding_case(
    surface: Topography,
    material: Material,
    counter: Material | None,
    normal_force: float,
    *,
    stroke: float,
    friction_coefficient: float,
    radius: float = RADIUS,
    label: str = "",
    ball: str = "",
    cycles: int = 4,
    steps_per_stroke: int = 20,
    coupling: bool = True,
    tolerance: float = 1e-8,
) -> PreslidingCase:
    """Run paper 001's programme on any ball surface and analyse the last loop.

    Normal contact at ``normal_force`` (free boundary; the pressure must vanish on the window's
    border), the path of Fig. 6 with quadratic spacing, the last loop analysed by
    :func:`roughcontact.experiment.friction_loop.analyse_loop` (K_L at A, B, C = 0.25, 0.5,
    0.75 of the pre-sliding span) and Mindlin's K_L at the same points (eqs. 10-12, both
    readings) for a smooth ball of ``radius``. Fields are kept for the last cycle only.
    """
    normal = solve_normal(surface, material, counter_body=counter, force=normal_force, tolerance=tolerance)
    _check_inside(normal.pressure, label or "the surface")
    path = stroke_path(stroke, cycles=cycles, steps_per_stroke=steps_per_stroke, spacing="quadratic")
    last_cycle = range(len(path) - 2 * steps_per_stroke, len(path))
    result = solve_tangential(
        normal,
        material,
        counter_body=counter,
        friction_coefficient=friction_coefficient,
        displacement=path,
        coupling=coupling,
        tolerance=tolerance,
        fields_at=list(last_cycle),
    )
    analysis = analyse_loop(*loop_from_start(result), normal_force, fractions=POINTS)
    rising = analysis.branch.direction > 0
    branch = [k for k in last_cycle if (k < len(path) - steps_per_stroke) == rising]
    point_steps = {
        point: min(branch, key=lambda k, target=target: abs(result.displacement[k, 0] - target))
        for point, target in zip(analysis.point_names, analysis.branch.point_displacement, strict=True)
    }
    references = {}
    for reading in ("johnson", "printed"):
        reference = paper001_mindlin(
            mu=friction_coefficient,
            normal_force=normal_force,
            radius=radius,
            material=material,
            counter=counter,
            normalisation=reading,
        )
        stiffness = map(float, reference.point_stiffness(POINTS))
        references[reading] = dict(zip(analysis.point_names, stiffness, strict=True))
    notes = {
        "window [m]": surface.size[0],
        "pixel [m]": surface.spacing[0],
        "steps": len(path),
        "coupling": coupling,
    }
    return PreslidingCase(
        label,
        ball,
        float(normal_force),
        float(stroke),
        float(friction_coefficient),
        result,
        analysis,
        references,
        point_steps,
        notes,
    )


@dataclass(frozen=True)
class ProgrammeCase:
    """A ball under a user's tangential programme (displacement or force path, x and y).

    ``analysis`` is the last loop's (as paper 001 analyses its Fig. 6 cycles) when the x
    displacement programme closes a loop that slides, else None and ``note`` says why;
    ``map_steps`` names the steps whose fields were kept (the reversals of the x programme and
    the last step).
    """

    label: str
    normal_force: float
    friction_coefficient: float
    control: str
    result: Any  # TangentialPathResult
    analysis: LoopAnalysis | None
    map_steps: dict[str, int]
    note: str = ""

    def loop(self) -> tuple[np.ndarray, np.ndarray]:
        """Displacement [m] and friction force [N] along x from the start (0, 0), all steps."""
        return loop_from_start(self.result)

    def scalars(self) -> dict[str, Any]:
        """Table row: inputs, contact, the last step, energy per closed loop and the last loop's analysis."""
        result = self.result
        row = {
            "case": self.label,
            "control": self.control,
            "steps": result.steps,
            "F0 [N]": self.normal_force,
            "mu": self.friction_coefficient,
            "contact_area [m^2]": result.normal.contact_area,
            "patches": result.normal.number_of_patches,
            "last_delta_x [m]": float(result.displacement[-1, 0]),
            "last_delta_y [m]": float(result.displacement[-1, 1]),
            "last_F_x [N]": float(result.force[-1, 0]),
            "last_F_y [N]": float(result.force[-1, 1]),
            "last_stick_fraction": float(result.stick_area[-1] / result.contact_area[-1]),
            "energy_per_loop [J]": result.dissipated_energy().tolist(),
            "analysis_note": self.note,
        }
        if self.analysis is not None:
            row |= {"mu_from_loop": self.analysis.mu, "stroke_from_loop [m]": self.analysis.stroke}
            row |= {f"K_L_{name} [N/m]": value for name, value in self.analysis.lateral_stiffness.items()}
        return row


def programme_case(
    surface: Topography,
    material: Material,
    counter: Material | None,
    normal_force: float,
    *,
    path,
    control: str,
    friction_coefficient: float,
    label: str = "",
    coupling: bool = True,
    tolerance: float = 1e-8,
    maps: int = 6,
) -> ProgrammeCase:
    """Run any tangential programme on a ball surface (paper 001's model, a user's path).

    Normal contact at ``normal_force`` (free boundary; the pressure must vanish on the window's
    border), then ``path`` (an (n,) or (n, 2) array, the rigid tangential displacement [m] or the
    tangential force [N] after each step, as ``control`` says; e.g. from
    :func:`roughcontact.contact.paths.read_path_csv`) through :func:`solve_tangential`. When a
    displacement programme closes a loop that reaches full sliding, the last loop is analysed as
    paper 001 does (stroke, mu, K_L at A, B, C); a loop that never slides (a small stroke, any
    force programme below mu F0) has no sliding plateau to take mu and the pre-sliding span from,
    so it is not, and neither is a loop whose pre-sliding part has too few steps for the eq. 9 fit:
    the case's ``note`` says which, and the rest of the results stand. Fields are kept at the last
    ``maps - 1`` reversals and at the last step.
    """
    if control not in ("displacement", "force"):
        raise InputError("control", f"unknown control {control!r}.", "use 'displacement' or 'force'.")
    path = as_path(path, control)
    normal = solve_normal(surface, material, counter_body=counter, force=normal_force, tolerance=tolerance)
    _check_inside(normal.pressure, label or "the surface")
    turns = [int(k) for k in reversals(path[:, 0])]
    kept = sorted(set(turns[max(len(turns) - maps + 1, 0) :]) | {len(path) - 1})
    result = solve_tangential(
        normal,
        material,
        counter_body=counter,
        friction_coefficient=friction_coefficient,
        coupling=coupling,
        tolerance=tolerance,
        fields_at=kept,
        **{control: path},
    )
    analysis, note = None, "no closed loop of the x programme"
    if control == "force":
        note = "force control: the paper's loop analysis needs a displacement programme that slides"
    elif result.loops():
        try:
            analysis = analyse_loop(*loop_from_start(result), normal_force, fractions=POINTS)
            note = ""
        except InputError as error:  # e.g. too few steps in the pre-sliding part for the eq. 9 fit
            note = f"last loop not analysed: {error.problem} {error.fix or ''}".strip()
        if analysis is not None and analysis.mu is None:
            analysis, note = None, "last loop not analysed: it never slides (no plateau to take mu from)"
    map_steps = {f"step {k + 1}": k for k in kept}
    return ProgrammeCase(
        label, float(normal_force), float(friction_coefficient), control, result, analysis, map_steps, note
    )


def run_case(
    ball: str,
    normal_force: float,
    *,
    scan: Topography | None = None,
    window: int = 160,
    pixels: int = 512,
    seed: int = 1,
    stroke: float | None = None,
    friction_coefficient: float | None = None,
    **options,
) -> PreslidingCase:
    """Simulate one ball at one load of Table 1 and analyse its last loop (paper 001 secs. 4-5).

    Parameters
    ----------
    ball : {"HDPE", "POM"}
    normal_force : float
        F0 [N]; Table 1's stroke and mu are used when it is one of 0.025, 0.05, 0.075 N.
    scan : Topography, optional
        The measured ball (heights with the spherical shape, as paper Fig. 4); default generated.
    window : int
        Pixels of the central window that is solved (free boundary).
    pixels : int
        Pixels across the generated 1.1 mm scan (the paper's 1024 gives 1.07 um; the default
        512 gives 2.15 um, so the default 160-pixel window is 0.34 mm, wide enough for the
        HDPE ball at 75 mN).
    seed : int
        Seed of the generated roughness.
    stroke, friction_coefficient : float, optional
        Override Table 1 (needed for other loads).
    **options
        ``cycles``, ``steps_per_stroke``, ``coupling``, ``tolerance`` of :func:`presliding_case`
        (normal-tangential coupling is on by default; beta = -0.003 for HDPE on silicon, small as
        expected for a nearly incompressible ball).
    """
    name = _ball(ball)
    table = TABLE1[name].get(round(float(normal_force), 6))
    if (stroke is None or friction_coefficient is None) and table is None:
        raise InputError(
            "normal_force",
            f"{normal_force} N is not in Table 1 (25, 50, 75 mN).",
            "pass stroke= and friction_coefficient= for other loads.",
        )
    surface = central_window(scan if scan is not None else roughness(name, seed=seed, pixels=pixels), window)
    case = presliding_case(
        surface,
        get_material(name),
        get_material("silicon wafer"),
        normal_force,
        stroke=table[0] if stroke is None else stroke,
        friction_coefficient=table[1] if friction_coefficient is None else friction_coefficient,
        label=f"{name} {normal_force * 1e3:g} mN",
        ball=name,
        **options,
    )
    case.notes["surface"] = "measured scan" if scan is not None else f"generated (seed {seed}, Hurst 0.8)"
    return case
