r"""The window of a ball's scan that is solved: chosen to hold every point that can touch, or given.

A free-boundary contact is solved on a central window of the scan (the whole scan is slow, and
most of it never comes near the flat); :func:`contact_window` chooses the smallest one that holds
the region that can touch, :func:`window_holds` checks a given one, :func:`check_inside` refuses
a contact that reaches its window's border, and :func:`solved_window` is the choice
:func:`~roughcontact.contact.presliding.presliding` makes of its ``window`` argument.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..analytic.mindlin import hertz_contact_radius
from ..errors import InputError
from ..materials import Material, contact_modulus
from ..topography import Topography
from .normal import solve_normal


def touches_border(pressure: np.ndarray) -> bool:
    """Return True where a pressure map carries load on its outermost rows or columns."""
    border = np.concatenate([pressure[0], pressure[-1], pressure[:, 0], pressure[:, -1]])
    return bool(np.any(border > 0))


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
    hertz = hertz_contact_radius(normal_force, radius, contact_modulus(material, counter_body))  # checks F0
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


def solved_window(
    scan: Topography,
    window: int | str | None,
    material: Material,
    counter_body: Material | None = None,
    *,
    normal_force: float | None = None,
    approach: float | None = None,
    radius: float,
    tolerance: float = 1e-8,
) -> tuple[Topography, str]:
    """Return the part of ``scan`` to solve for ``window`` and how it was chosen, in words.

    ``window``: None, the whole scan; ``"auto"``, the central window :func:`contact_window`
    chooses for the largest ``normal_force`` (or ``approach``) of the programme; an int, the
    central window of that many pixels (:func:`~roughcontact.topography.process.central_window`).
    """
    from ..topography.process import central_window

    if window == "auto":
        chosen = contact_window(
            scan,
            material,
            counter_body,
            normal_force=normal_force,
            approach=approach,
            radius=radius,
            tolerance=tolerance,
        )
        return (scan if chosen.whole else central_window(scan, chosen.pixels)), f"auto: {chosen.note}"
    if window is None:
        return scan, "the whole scan (window not given)"
    return central_window(scan, window), f"given: {window} px"
