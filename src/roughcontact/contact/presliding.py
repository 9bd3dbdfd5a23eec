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

References
----------
Seed paper 001, secs. 2-5, eqs. 3-4 and 9-12, Figs. 6-15. doi:10.1115/1.4045900
K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, sec. 7.4.
doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ..analytic.mindlin import (
    hertz_contact_radius,
    lateral_stiffness,
    sliding_displacement,
    tangential_displacement,
    tangential_force,
)
from ..checks import finite_array, positive
from ..display_html import NotebookDisplay
from ..errors import InputError
from ..experiment.friction_loop import LoopAnalysis, analyse_loop
from ..materials import Material, compliance_sum, contact_modulus, johnson_shear_modulus
from ..spread import Spread, Verdict, spread
from ..topography import Topography
from ..topography.surface import topography_argument
from .frictional import solve_frictional
from .normal import solve_normal
from .paths import as_path, reversals, stroke_path
from .shear_solver import ShearSolver
from .tangential import solve_tangential

POINTS = (0.25, 0.5, 0.75)
"""Fractions of a branch's pre-sliding force span at the loop points A, B, C (paper 001 Fig. 10; assumed)."""
POINT_NAMES = ("A", "B", "C")
"""The loop points of paper 001 Fig. 10 at which K_L is evaluated."""


MINDLIN_READINGS = ("johnson", "printed")
"""The two readings of Mindlin's K_L (paper 001 eqs. 10-12): textbook (Johnson) and as printed (4x)."""

NORMALISATIONS = MINDLIN_READINGS
"""Readings of paper 001 eqs. 10 and 12, see :func:`mindlin_reference`."""


@dataclass(frozen=True)
class MindlinReference:
    """Mindlin's smooth ball (paper 001 equations 10-12) for one ball, load and friction coefficient.

    Attributes
    ----------
    friction_coefficient : float
        mu_f [-].
    normal_force : float
        F0 [N].
    contact_radius : float
        Hertz radius a from eq. 11 [m].
    shear_modulus : float
        The modulus that multiplies the prefactors 3/16 and 8: G* for ``"johnson"``, G_s (= 4 G*)
        for ``"printed"`` [Pa].
    normalisation : str
        ``"johnson"`` or ``"printed"``.
    """

    friction_coefficient: float
    normal_force: float
    contact_radius: float
    shear_modulus: float
    normalisation: str

    @property
    def sliding_distance(self) -> float:
        """delta_0 = 3 mu F0 / (16 a G) [m] (equation 10)."""
        return sliding_displacement(
            self.friction_coefficient, self.normal_force, self.contact_radius, self.shear_modulus
        )

    @property
    def initial_stiffness(self) -> float:
        """K_L at F_x = 0: 8 a G [N/m] (equation 12)."""
        return 8.0 * self.contact_radius * self.shear_modulus

    def force(self, displacement):
        """F_x(delta_x), equation 10 [N] (saturated at mu F0 beyond delta_0)."""
        return tangential_force(
            displacement,
            self.friction_coefficient,
            self.normal_force,
            self.contact_radius,
            self.shear_modulus,
        )

    def displacement(self, force):
        """delta_x(F_x), inverse of equation 10 [m]."""
        return tangential_displacement(
            force, self.friction_coefficient, self.normal_force, self.contact_radius, self.shear_modulus
        )

    def lateral_stiffness(self, force):
        """K_L = 8 a G (1 - F_x / (mu F0))^(1/3), equation 12 [N/m], at tangential force F_x [N]."""
        return lateral_stiffness(
            force, self.friction_coefficient, self.normal_force, self.contact_radius, self.shear_modulus
        )

    def point_stiffness(self, fractions=(0.25, 0.5, 0.75)) -> np.ndarray:
        """K_L [N/m] at the loop points A, B, C of :mod:`roughcontact.experiment.friction_loop`.

        A point at the fraction f of a sliding branch's force span 2 mu F0 lies where the
        Masing branch has changed by 2 Q_M(x/2) = f 2 mu F0, so its stiffness is eq. 12 at
        F_x = f mu F0: K_L = 8 a G (1 - f)^(1/3).
        """
        f = np.asarray(fractions, dtype=float)
        if np.any((f < 0) | (f > 1)) or not np.all(np.isfinite(f)):
            raise InputError("fractions", f"{fractions!r} must lie in [0, 1].", "use e.g. (0.25, 0.5, 0.75).")
        return self.initial_stiffness * np.cbrt(1.0 - f)

    def lateral_stiffness_at_displacement(self, displacement):
        """K_L = 3 mu F0 / (2 delta_0) (1 - delta_x / delta_0)^(1/2), equation 12 [N/m]."""
        delta0 = self.sliding_distance
        x = np.minimum(np.abs(finite_array(displacement, "displacement")) / delta0, 1.0)
        stiffness = 1.5 * self.friction_coefficient * self.normal_force / delta0 * np.sqrt(1.0 - x)
        return float(stiffness) if np.ndim(displacement) == 0 else stiffness


def mindlin_reference(
    *,
    friction_coefficient: float,
    normal_force: float,
    radius: float,
    material: Material,
    counter_body: Material | None = None,
    normalisation: str = "johnson",
) -> MindlinReference:
    r"""Mindlin's smooth-ball reference (paper 001 equations 10-12) for a ball of ``radius`` on a flat.

    Eq. 11 gives a^3 = 3 F0 R / (4 E_s) with 1/E_s = sum (1 - nu^2)/E. Eqs. 10 and 12 give
    delta_0 = 3 mu F0 / (16 a G) and K_L = 8 a G (1 - F_x/(mu F0))^(1/3), where G is

    * ``normalisation="johnson"`` (default): Johnson's G*, 1/G* = sum (2 - nu)/G. This is the
      textbook Mindlin solution (Johnson 1985, eq. 7.42), to which the prefactors 3/16 and 8
      belong.
    * ``normalisation="printed"``: the paper's G_s as printed, 1/G_s = sum (2 - nu)(1 + nu)/(2E)
      = sum (2 - nu)/(4G), i.e. G_s = 4 G*. Combined with the prefactors 3/16 and 8 this makes
      delta_0 4 times smaller and K_L exactly 4 times larger than Johnson's (the force at a given
      fraction of mu F0 is unchanged). Use it only to reproduce the paper's printed numbers
      (Fig. 15, dashed lines). The consistent form with G_s would be delta_0 = 3 mu F0/(4 a G_s)
      and K_L = 2 a G_s, which equals the ``"johnson"`` reading.

    Parameters
    ----------
    friction_coefficient : float
        mu_f [-] (paper Table 1).
    normal_force : float
        F0 [N].
    radius : float
        Ball radius R [m] (paper: 5 mm, a 10 mm ball).
    material, counter_body : Material, Material or None
        The two bodies (``counter_body=None`` is rigid), e.g. HDPE (0.98 GPa, 0.5) and silicon
        (130 GPa, 0.28) from Table 2.
    normalisation : {"johnson", "printed"}
        See above.

    Returns
    -------
    MindlinReference
        a, the modulus used, delta_0 and the force and stiffness functions.

    Raises
    ------
    InputError
        Unknown ``normalisation``, non-positive numbers or bodies that are not Materials.
    """
    if normalisation not in NORMALISATIONS:
        raise InputError(
            "normalisation",
            f"unknown normalisation {normalisation!r}.",
            "choose 'johnson' (textbook Mindlin, default) or 'printed' (paper 001 as printed, "
            "K_L 4x larger).",
        )
    positive(friction_coefficient, "friction_coefficient", example="0.153")
    a = hertz_contact_radius(normal_force, radius, contact_modulus(material, counter_body))
    if normalisation == "johnson":
        g = johnson_shear_modulus(material, counter_body)
    else:
        g = effective_shear_modulus_paper001(material, counter_body)
    return MindlinReference(float(friction_coefficient), float(normal_force), a, g, normalisation)


def touches_border(pressure: np.ndarray) -> bool:
    """Return True where a pressure map carries load on its outermost rows or columns."""
    border = np.concatenate([pressure[0], pressure[-1], pressure[:, 0], pressure[:, -1]])
    return bool(np.any(border > 0))


READING_WORDS = {
    "johnson": "Johnson's Mindlin",
    "printed": "Mindlin as printed (eq. 12, 4x Johnson's)",
}
"""How tables, notes and figures name each reading of Mindlin's K_L (:data:`MINDLIN_READINGS`)."""


def mindlin_ratios(stiffness, mindlin: Mapping[str, Any]) -> dict[str, Spread]:
    """Return the spread of K_L / K_L,Mindlin over realisations, in each reading of equation 12.

    Parameters
    ----------
    stiffness : iterable of float
        K_L at one point (A, B or C) of each realisation [N/m]; NaN where a loop was not analysed
        (left out).
    mindlin : dict
        Reading (``"johnson"``, ``"printed"``) -> Mindlin's K_L at the same point for each
        realisation [N/m].

    Returns
    -------
    dict
        Reading -> :class:`~roughcontact.spread.Spread` of the ratio (bounded below by 0).
    """
    values = [float(k) for k in stiffness]
    ratios = {}
    for reading, references in mindlin.items():
        each = [
            k / float(m) if float(m) > 0 and math.isfinite(float(m)) else math.nan
            for k, m in zip(values, references, strict=True)
        ]
        ratios[reading] = spread(each, bounds=(0.0, math.inf))
    return ratios


def rough_vs_smooth(ratios: Mapping[str, Spread]) -> dict[str, Verdict]:
    """Judge where one rough ball's K_L lies against Mindlin's smooth ball, in each reading of equation 12.

    Paper 001's claim (the rough ball is laterally softer than Mindlin's smooth one) is about one
    ball. The ratios of :func:`mindlin_ratios` over realisations (balls drawn with the same
    statistics) are judged with :meth:`~roughcontact.spread.Spread.verdict` ``(1.0, of="one")``: the
    95 % prediction interval of one more ball, the interval of the mean beside it
    (``Verdict.mean_interval``). ``below`` where one ball's ratio lies below 1 at 95 %, ``above``
    where it lies above, ``not established`` where the interval holds 1, ``one realisation``
    without an interval.
    """
    return {reading: ratio.verdict(1.0, of="one") for reading, ratio in ratios.items()}


def verdict_words(verdicts: Mapping[str, Verdict], reading: str) -> str:
    """Return a reading's verdict word, saying so where equation 12's printed factor 4 decides it.

    The printed reading's K_L is exactly 4x Johnson's (:func:`mindlin_reference`). Where its
    verdict differs from Johnson's for the same ball and point, the roughness does not decide it:
    the constant does, e.g. ``"below (decided by eq. 12's printed factor 4: with Johnson's Mindlin
    not established)"``.
    """
    word = verdicts[reading].word
    textbook = verdicts.get("johnson")
    if reading != "johnson" and textbook is not None and textbook.word != word:
        return f"{word} (decided by eq. 12's printed factor 4: with Johnson's Mindlin {textbook.word})"
    return word


def check_inside(pressure: np.ndarray, label: str) -> None:
    """Refuse a free-boundary contact that reaches the border of its window (the answer would be cut off)."""
    if touches_border(pressure):
        n, m = pressure.shape
        raise InputError(
            "window",
            f"{label}: the contact reaches the border of the solved window ({n} x {m} px), so the "
            "free-boundary answer would be cut off.",
            "pass a larger «window» (pixels), «window=auto» (chosen from the ball's heights and grown "
            "until it holds the contact), or a coarser scan.",
        )


WINDOW_MARGIN = 4
"""Free pixels on each side of the region that can touch, in a window :func:`contact_window` chooses."""


@dataclass(frozen=True)
class ContactWindow:
    """The central window that :func:`contact_window` chose to hold a ball's contact.

    Attributes
    ----------
    pixels : int
        Side of the central window [px] (:func:`~roughcontact.topography.process.central_window`);
        the scan's smaller side where the whole scan is needed.
    whole : bool
        True where the window is the whole scan.
    depth : float
        The depth below the highest point within which the surface can touch [m]: the region
        ``h >= h_top - depth`` is what the window holds.
    solves : int
        Normal solves it took (the last one on ``pixels`` holds the contact).
    note : str
        How it was chosen, in one sentence.
    """

    pixels: int
    whole: bool
    depth: float
    solves: int
    note: str


def _window_holding(heights: np.ndarray, floor: float, margin: int) -> int:
    """Return the side of the smallest central window that holds every pixel at or above ``floor``."""
    inside = np.argwhere(heights >= floor)
    n = min(heights.shape)
    if inside.size == 0:
        return n
    need = []
    for axis, size in enumerate(heights.shape):
        low = max(int(inside[:, axis].min()) - margin, 0)
        high = min(int(inside[:, axis].max()) + margin, size - 1)
        need.append((size, low, high))
    for window in range(3, n + 1):
        if all(
            (size - window) // 2 <= low and (size - window) // 2 + window - 1 >= high
            for size, low, high in need
        ):
            return window
    return n


def contact_window(
    topography: Topography,
    material: Material,
    counter_body: Material | None = None,
    *,
    normal_force: float | None = None,
    approach: float | None = None,
    radius: float,
    tolerance: float = 1e-8,
    margin: int = WINDOW_MARGIN,
) -> ContactWindow:
    r"""Choose the central window of a ball's scan that holds its contact, before the programme is solved.

    A point can touch only where the undeformed surface lies within the approach d of the highest
    point, :math:`h \ge h_\mathrm{top} - d`: a compressive pressure moves the surfaces apart
    everywhere, so the gap is at least :math:`h_\mathrm{top} - d - h`, positive below that depth.
    A window that holds this whole region solves the ball exactly (outside it nothing touches);
    a pressure that vanishes on the window's border is not enough, since a high asperity just
    beyond the border may touch while the border does not. The window is the smallest central
    square that holds the region with ``margin`` pixels to spare:

    1. Given an ``approach`` (a programme in approach), the region is known and no solve is needed.
    2. Given a ``normal_force``, d is first guessed as twice the Hertz approach of a smooth ball
       of ``radius``, :math:`2 a^2 / R` (paper 001 eq. 11; the rough balls of paper 001 need 1.0 to
       4.0 times it), and the normal contact is solved on the window that holds that region. The
       approach found there, measured from that window's own highest point, bounds the region
       of the whole scan that can touch: solved on a window that holds it, the flat can only sit
       higher (more surface carries the load), so that region shrinks. Where it does not fit, the
       window grows to hold it and is solved once more, which then holds its own region.

    Parameters
    ----------
    topography : Topography
        The ball's scan with its spherical shape (heights up, apex near the centre).
    material, counter_body : Material, Material or None
        The ball and the flat (None: rigid).
    normal_force : float, optional
        The largest normal force the programme applies [N].
    approach : float, optional
        Or the largest approach [m] (not both).
    radius : float
        Ball radius R [m], for the first guess.
    tolerance : float
        Of the normal solves.
    margin : int
        Free pixels around the region that can touch.

    Returns
    -------
    ContactWindow
        The window, the depth of the region it holds and how it was found.

    Raises
    ------
    InputError
        Neither or both of ``normal_force`` and ``approach``; a contact that reaches the border of
        the whole scan.
    """
    from ..topography.process import central_window

    if (normal_force is None) == (approach is None):
        raise InputError(
            "normal_force", "give the largest normal force or the largest approach, exactly one.", None
        )
    heights = np.asarray(topography.heights, dtype=float)
    whole = min(heights.shape)
    top = float(heights.max())
    microns = topography.spacing[0] * 1e6

    def described(window: int, how: str) -> str:
        where = "the whole scan" if window >= whole else f"{window * microns:.4g} um"
        return f"{window} px ({where}): {how}"

    if approach is not None:
        depth = float(approach)
        window = _window_holding(heights, top - depth, margin)
        how = f"holds every point within the largest approach, {depth * 1e6:.3g} um, of the highest point"
        return ContactWindow(window, window >= whole, depth, 0, described(window, how))
    positive(normal_force, "normal_force", example="0.025")
    hertz = hertz_contact_radius(normal_force, radius, contact_modulus(material, counter_body))
    depth = 2.0 * hertz**2 / radius
    window = guess = _window_holding(heights, top - depth, margin)
    solves = 0
    while True:
        surface = topography if window >= whole else central_window(topography, window)
        normal = solve_normal(
            surface, material, counter_body=counter_body, force=normal_force, tolerance=tolerance
        )
        solves += 1
        floor = float(surface.heights.max()) - normal.approach
        need = _window_holding(heights, floor, margin)
        if window >= whole and touches_border(normal.pressure):
            raise InputError(
                "window",
                f"the contact reaches the border of the whole scan ({heights.shape[0]} x "
                f"{heights.shape[1]} px) at {normal_force * 1e3:g} mN, so the free-boundary answer "
                "would be cut off.",
                "give a scan of a larger field, or a smaller normal force.",
            )
        if need <= window or window >= whole:
            break
        window = min(need, whole)
    depth = top - floor
    how = (
        f"holds every point within {depth * 1e6:.3g} um of the highest point, the approach of the "
        f"normal contact at {normal_force * 1e3:g} mN solved on it (nothing outside can touch)"
    )
    if solves > 1:
        how += f"; the first guess, {guess} px from twice the smooth ball's Hertz approach, held less"
    return ContactWindow(window, window >= whole, depth, solves, described(window, how))


def window_holds(scan: Topography, normal) -> tuple[bool, float]:
    """Return whether a normal contact solved on a central window of ``scan`` holds all that can touch.

    ``normal`` is a normal-contact result on the window (its ``topography``, ``approach``). Every
    point of the whole scan within the approach of the window's highest point could touch
    (:func:`contact_window`); True where they all lie inside the window, with the depth of that
    region below the scan's highest point [m].
    """
    heights = np.asarray(scan.heights, dtype=float)
    window = min(normal.topography.shape)
    floor = float(np.max(normal.topography.heights)) - normal.approach
    return _window_holding(heights, floor, 0) <= window, float(heights.max()) - floor


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
    label: str = "",
) -> PreslidingResult:
    """Run paper 001's model: a rough ball pressed on a flat, then a tangential programme.

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
    )


def effective_shear_modulus_paper001(a: Material, b: Material | None = None) -> float:
    r"""Effective shear modulus G_s as defined in paper 001 (below equation 10) [Pa].

    .. math:: \frac{1}{G_s} = \sum_i \frac{(2 - \nu_i)(1 + \nu_i)}{2 E_i}
              = \sum_i \frac{2 - \nu_i}{4 G_i}

    This is 4 times Johnson's G* (:func:`johnson_shear_modulus`): G_s = 4 G*. Paper 001 uses it
    with the prefactors of Johnson's Mindlin solution (delta_0 = 3 mu F0 / (16 a G),
    K_L = 8 a G), which belong to G*; used with G_s as printed, K_L is 4 times the textbook
    Mindlin stiffness. With G_s the consistent prefactors are delta_0 = 3 mu F0 / (4 a G_s)
    and K_L = 2 a G_s.

    Parameters
    ----------
    a : Material
        First body.
    b : Material or None
        Second body; ``None`` is rigid.

    Returns
    -------
    float
        G_s [Pa].

    References
    ----------
    Seed paper 001, text below eq. 10. doi:10.1115/1.4045900
    """
    return 1.0 / compliance_sum(a, b, lambda m: (2.0 - m.poissons_ratio) / (4.0 * m.shear_modulus))
