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
  Hurst 0.8, seeded, on the paper's 1.1 mm / 1024 px field), the drawn roughness of Table 2's rms
  (``rms="flattened"``: the scan after sphere removal has it, as the paper measured). Several
  seeds give several *stand-in balls* of the same statistics (``--realisations``): they stand in
  for the paper's unpublished balls; they are not the five spots on the wafer where it measured;
* the solved window: only a small central part of the ball touches (paper Figs. 8-9), so the
  free-boundary problem is solved on the central ``window`` x ``window`` pixels at the scan's
  resolution (:func:`run_case`'s default 160 px of a 512 px scan = 0.34 mm; the paper zooms to
  0.2 mm); the pressure is checked to vanish on the window's border, else an error asks for a
  larger window. ``window="auto"`` (the ``--paper001`` command's default) chooses, per ball and
  load, the smallest window that holds every point that can touch
  (``roughcontact.contact.presliding.contact_window``): with HDPE's 3.17 um roughness some
  balls touch 0.19 mm off the apex, beyond a 160 px window;
* the steps of the path: ``steps_per_stroke`` per branch, spaced quadratically from each reversal
  so the pre-sliding part (a fraction of a micrometre) is resolved.

:func:`roughcontact.contact.presliding.presliding` runs the model on any ball and any programme (the
paper's or a user's); :func:`run_case` runs one ball and load of Table 1 with it, and
:func:`paper001_mindlin` is the paper's Mindlin reference (eqs. 10-12, in both readings).
"""

from __future__ import annotations

from typing import Any

from .._deprecation import moved, renamed
from ..contact.presliding import MindlinReference, PreslidingResult, mindlin_reference
from ..contact.presliding import presliding as _presliding
from ..errors import InputError
from ..materials import get_material
from ..topography import Topography, generate
from ..topography.process import level
from ..topography.statistics import rq
from ..units import written

RADIUS = 5e-3
"""Ball radius [m] (10 mm balls, sec. 3)."""
FIELD = 1.1e-3
"""Side of the scanned field [m] (sec. 4, Fig. 4)."""
SCAN_PIXELS = 1024
"""Pixels across the paper's scans."""
ROUGHNESS = {"HDPE": 3.17e-6, "POM": 0.67e-6}
"""RMS roughness of each ball after removing the sphere [m] (Table 2)."""
FLAT = "silicon wafer"
"""The library material of the flat (Table 2; smooth, sec. 4)."""
# Table 1: F0 [N] -> (stroke [m], mu) per ball
TABLE1 = {
    "HDPE": {0.025: (2.805e-6, 0.153), 0.050: (2.943e-6, 0.146), 0.075: (3.697e-6, 0.129)},
    "POM": {0.025: (2.700e-6, 0.108), 0.050: (3.370e-6, 0.104), 0.075: (4.264e-6, 0.099)},
}


def ball_name(name: str) -> str:
    """Return the paper's name of a ball (``"HDPE"`` or ``"POM"``, any case); refuse others."""
    key = name.upper()
    if key not in ROUGHNESS:
        raise InputError("ball", f"unknown ball {name!r}.", "use 'HDPE' or 'POM'.")
    return key


def table1(ball: str, normal_force: float) -> tuple[float, float]:
    """Return Table 1's stroke d_s [m] and friction coefficient mu_f of ``ball`` at ``normal_force`` [N]."""
    values = TABLE1[ball_name(ball)].get(round(float(normal_force), 6))
    if values is None:
        raise InputError(
            "normal_force",
            f"{normal_force * 1e3:g} mN is not in Table 1 (25, 50, 75 mN).",
            "use one of Table 1's loads, or give the stroke and friction coefficient of another load.",
        )
    return values


def presliding_keys(ball: str, normal_force: float | None) -> dict[str, Any]:
    """Return the keys of paper 001's ``presliding`` analysis for one ball and load (with units).

    The ball's library material (Table 2), the flat, the radius of Mindlin's reference and, at a
    load of Table 1 (None: none), its stroke and friction coefficient: what ``paper001 = true``
    fills in where an analysis leaves a key out.
    """
    name = ball_name(ball)
    keys = {"material": name, "counter_body": FLAT, "radius": written(RADIUS, "m")}
    if normal_force is not None and round(float(normal_force), 6) in TABLE1[name]:
        stroke, mu = table1(name, normal_force)
        keys |= {"stroke": written(stroke, "m"), "friction_coefficient": mu}
    return keys


def roughness(ball: str, *, seed: int = 1, pixels: int = SCAN_PIXELS, rms: str = "flattened") -> Topography:
    """Generate a ball scan: sphere R = 5 mm plus self-affine roughness of Table 2's rms (1.1 mm field).

    ``rms`` says which surface has Table 2's RMS (HDPE 3.17 um, POM 0.67 um):

    * ``"drawn"`` (the balls of releases up to 0.2): the self-affine roughness as drawn, before
      the sphere is added. Removing the fitted sphere (:func:`~roughcontact.topography.process.level`
      with ``"sphere"``, what ``roughcontact inspect --detrend sphere`` applies) takes the
      roughness' longest waves with it, so the flattened RMS is 10-25 % below Table 2 (seed 1:
      16 % at 256 pixels, 10 % at 512, 24 % at 1024; HDPE 2.66, 2.85 and 2.40 um).
    * ``"flattened"`` (default): the scan after that sphere removal, as the paper reports it (Fig. 5,
      Table 2). The ball is drawn, flattened, and drawn again with the same seed and its roughness
      rescaled by Table 2's RMS over the flattened one. The fit is linear in the heights but for
      the cap's nonlinearity and the paraboloid body's own residual against a sphere, so one
      rescaling leaves the flattened RMS within 0.1 % of Table 2 (seed 1, 256 and 1024 pixels).

    Parameters
    ----------
    ball : {"HDPE", "POM"}
    seed : int
        Seed of the roughness.
    pixels : int
        Pixels across the 1.1 mm field (the paper's 1024).
    rms : {"drawn", "flattened"}
        Which surface has Table 2's RMS, see above.

    Returns
    -------
    Topography
        Non-periodic scan of the ball (the smooth body's apex at 0); ``info["rms"]`` records ``rms``.

    Raises
    ------
    InputError
        Unknown ``ball`` or ``rms``.
    """
    target = ROUGHNESS[ball_name(ball)]
    if rms not in ("drawn", "flattened"):
        raise InputError(
            "rms",
            f"unknown rms {rms!r}.",
            "choose 'drawn' (the roughness as drawn has Table 2's RMS) or 'flattened' (the scan after "
            "sphere removal has it).",
        )

    def scan(rms_height: float) -> Topography:
        return generate.sphere_with_roughness(
            (pixels, pixels), (FIELD, FIELD), radius=RADIUS, rms_height=rms_height, seed=seed
        )

    ball_scan = scan(target)
    if rms == "flattened":
        ball_scan = scan(target * target / rq(level(ball_scan, "sphere")))
    return Topography(ball_scan.heights, ball_scan.size, periodic=False, info={**ball_scan.info, "rms": rms})


def flattened_roughness(scan: Topography, ball: str) -> dict[str, float]:
    """Return a ball scan's RMS after the fitted sphere is removed, beside Table 2's (paper 001).

    The flattening is :func:`~roughcontact.topography.process.level` with ``"sphere"``, what the
    paper does to its scans and ``roughcontact inspect --detrend sphere`` applies. Keys
    ``flattened_rq`` (this scan) and ``table2_rq`` [m].
    """
    return {"flattened_rq": rq(level(scan, "sphere")), "table2_rq": ROUGHNESS[ball_name(ball)]}


Paper001Mindlin = MindlinReference
"""Paper 001's Mindlin reference: :class:`roughcontact.contact.presliding.MindlinReference`."""

paper001_mindlin = renamed(mu="friction_coefficient", counter="counter_body")(mindlin_reference)
"""Paper 001's Mindlin reference (eqs. 10-12): :func:`roughcontact.contact.presliding.mindlin_reference`."""


def run_case(
    ball: str,
    normal_force: float,
    *,
    scan: Topography | None = None,
    window: int | str = 160,
    pixels: int = 512,
    seed: int = 1,
    stroke: float | None = None,
    friction_coefficient: float | None = None,
    cycles: int = 4,
    steps_per_stroke: int = 20,
    coupling: bool = True,
    tolerance: float = 1e-8,
) -> PreslidingResult:
    """Simulate one ball at one load of Table 1 and analyse its last loop (paper 001 secs. 4-5).

    Parameters
    ----------
    ball : {"HDPE", "POM"}
    normal_force : float
        F0 [N]; Table 1's stroke and mu are used when it is one of 0.025, 0.05, 0.075 N.
    scan : Topography, optional
        The measured ball (heights with the spherical shape, as paper Fig. 4); default generated.
    window : int or "auto"
        Pixels of the central window that is solved (free boundary); ``"auto"`` chooses the
        smallest that holds every point of the ball that can touch at ``normal_force``
        (``roughcontact.contact.presliding.contact_window``).
    pixels : int
        Pixels across the generated 1.1 mm scan (the paper's 1024 gives 1.07 um; the default
        512 gives 2.15 um, so the default 160-pixel window is 0.34 mm, wide enough for the
        HDPE ball at 75 mN).
    seed : int
        Seed of the generated roughness.
    stroke, friction_coefficient : float, optional
        Override Table 1 (needed for other loads).
    cycles, steps_per_stroke, coupling, tolerance
        Of :func:`~roughcontact.contact.presliding.presliding` (normal-tangential coupling is on
        by default; beta = -0.003 for HDPE on silicon, small as expected for a nearly
        incompressible ball).
    """
    name = ball_name(ball)
    if stroke is None or friction_coefficient is None:
        table = table1(name, normal_force)
        stroke = table[0] if stroke is None else stroke
        friction_coefficient = table[1] if friction_coefficient is None else friction_coefficient
    ball = scan if scan is not None else roughness(name, seed=seed, pixels=pixels)
    return _presliding(
        ball,
        get_material(name),
        get_material(FLAT),
        normal_force=normal_force,
        stroke=stroke,
        friction_coefficient=friction_coefficient,
        radius=RADIUS,
        cycles=cycles,
        steps_per_stroke=steps_per_stroke,
        coupling=coupling,
        tolerance=tolerance,
        window=window,
        label=f"{name} {normal_force * 1e3:g} mN",
    )


def __getattr__(name: str):
    """Serve the model's names that moved beside the tangential engine, with a warning."""
    return moved(__name__, name, _MOVED)


_MOVED = dict.fromkeys(
    (
        "MINDLIN_READINGS",
        "NORMALISATIONS",
        "POINTS",
        "POINT_NAMES",
        "loop_from_start",
        "presliding",
    ),
    "roughcontact.contact.presliding",
)
