"""Whether a surface's numbers are plausible: one check and one message for every door.

A file whose metadata are wrong reads without an error: SurfaceTopography's ``nms-1.nms`` reads as
a scan of 160 m x 160 m, and every statistic and contact computed on it is a number, a wrong
one. :func:`doubts` says what is implausible about a topography, and every door that reads one
says it in its own words: ``roughcontact inspect`` and ``plot`` as a note, ``validate``, ``run``
and the model commands as a note of the study, Python's
:func:`~roughcontact.topography.io.read_topography` as a :class:`PlausibilityWarning` (a
``UserWarning``: shown once, filtered or turned into an error as any warning is). Nothing is
refused for being implausible (a 2 m scan exists); what cannot be computed at all is refused
where it is read (a height whose square overflows: ``roughcontact.topography.surface.LARGEST``).

The checks:

* the physical size of each axis lies in :data:`SIZES` (a nanometre to a metre);
* the heights' peak-to-valley lies in :data:`HEIGHTS` (a picometre to a metre) unless the surface is
  flat;
* a flat surface (:func:`is_flat`: its heights vary by round-off of their magnitude at most) is
  said to be flat: it has no roughness, and a contact on it is the flat punch's.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from ..units import format_si
from .surface import Topography

__all__ = ["FLAT", "HEIGHTS", "SIZES", "Doubt", "PlausibilityWarning", "doubts", "is_flat", "size_doubt"]

SIZES = (1e-9, 1.0)
"""Physical size of a plausible scan along each axis [m]: from a nanometre (a few atoms) to a metre."""

HEIGHTS = (1e-12, 1.0)
"""Peak-to-valley height of a plausible rough surface [m]: from a picometre (a hundredth of an atom's
diameter, below every instrument's resolution) to a metre."""

FLAT = 1e-12
"""Largest peak-to-valley height, as a fraction of the largest height's magnitude, of a flat surface.

Levelling a perfectly flat or planar surface (a constant, a ramp) leaves round-off of up to 5e-15
of the heights' magnitude (measured with ``level`` on grids up to 2048 x 2048, every mode); the
finest measured variation is about 1e-7 of it (a 24-bit instrument). 1e-12 lies between, with a
margin of a factor 200 from the round-off."""


class PlausibilityWarning(UserWarning):
    """A topography read with implausible numbers (:func:`doubts`); ``doubt`` is the :class:`Doubt`."""

    def __init__(self, message: str, doubt: Doubt | None = None):
        super().__init__(message)
        self.doubt = doubt


@dataclass(frozen=True)
class Doubt:
    """What is implausible about a topography, and what to check, in each door's words.

    Attributes
    ----------
    problem : str
        What is implausible (``"the scan is 160 m x 160 m, outside 1 nm to 1 m"``).
    fixes : mapping of str to str
        What to check, by door: ``"python"``, ``"study"`` (a study file's keys), ``"cli"`` (options),
        and ``"marked"``: with its keys marked (``«height_unit»``, ``roughcontact.messages``) for a
        note that a door renders later in its own words (a study's notes, said by ``validate`` in a
        study file's words and by a model command in its options').
    """

    problem: str
    fixes: Mapping[str, str] = field(default_factory=dict)

    def said(self, style: str = "python") -> str:
        """Return the one sentence a door prints: the problem and what to check in ``style``'s words."""
        fix = self.fixes.get(style) or self.fixes.get("python")
        return f"{self.problem}; {fix}." if fix else f"{self.problem}."


def is_flat(heights: np.ndarray) -> bool:
    """Return True when ``heights`` vary by :data:`FLAT` of their largest magnitude at most.

    Exactly equal heights (all zero included) are flat; so is what levelling a perfect plane
    leaves (:func:`~roughcontact.topography.process.level` sets that to zero).
    """
    heights = np.asarray(heights, dtype=float)
    defined = heights[np.isfinite(heights)]
    if defined.size == 0:
        return False
    return bool(np.ptp(defined) <= FLAT * np.max(np.abs(defined)))


_UNIT_FIXES = {
    "python": "check its size and height unit (the file's metadata, or give size= and height_unit=, "
    "with override_file_values=True where the file stores others)",
    "study": "check its size and height unit (the file's metadata, or size and height_unit here, with "
    "override_file_values = true where the file stores others)",
    "cli": "check its size and height unit (the file's metadata, or --size and --height-unit, with "
    "--override-file-values where the file stores others)",
    "marked": "check its size and height unit (the file's metadata, or «size» and «height_unit», with "
    "«override_file_values=true» where the file stores others)",
}
_HEIGHT_FIXES = {
    "python": "check its height unit (the file's metadata, or give height_unit=, with "
    "override_file_values=True where the file stores another)",
    "study": "check its height unit (the file's metadata, or height_unit here, with "
    "override_file_values = true where the file stores another)",
    "cli": "check its height unit (the file's metadata, or --height-unit, with --override-file-values "
    "where the file stores another)",
    "marked": "check its height unit (the file's metadata, or «height_unit», with "
    "«override_file_values=true» where the file stores another)",
}
_GENERATED_FIXES = {
    "python": "check the size given to the generator and its unit",
    "study": "check size and its unit",
    "cli": "check the size given and its unit",
    "marked": "check «size» and its unit",
}


def size_doubt(size: float | tuple[float, ...], *, generated: bool = False) -> Doubt | None:
    """Return the :class:`Doubt` of a physical ``size`` [m] outside :data:`SIZES` (None when inside).

    ``generated``: the size was given to a generator (what to check is then that value).
    """
    sides = tuple(float(side) for side in np.atleast_1d(size))
    if all(SIZES[0] <= side <= SIZES[1] for side in sides):
        return None
    shown = " x ".join(format_si(side, "m") for side in sides)
    low, high = (format_si(bound, "m") for bound in SIZES)
    fixes = _GENERATED_FIXES if generated else _UNIT_FIXES
    return Doubt(f"the scan is {shown}, outside {low} to {high}", fixes)


def doubts(topography: Topography) -> tuple[Doubt, ...]:
    """Return what is implausible about ``topography`` (empty when nothing is).

    Its size (:data:`SIZES`), its heights' peak-to-valley (:data:`HEIGHTS`), and whether it is flat
    (:func:`is_flat`). Called by every door that reads a surface (module docstring).
    """
    found = []
    size = size_doubt(topography.size)
    if size is not None:
        found.append(size)
    heights = topography.heights
    span = float(np.ptp(heights))
    if is_flat(heights):
        magnitude = format_si(float(np.max(np.abs(heights))), "m")
        varies = (
            "every height is the same"
            if span == 0
            else f"its heights vary by {span:.3g} m, round-off of their magnitude ({magnitude})"
        )
        levelled = " once levelled" if topography.info.get("detrend", "none") != "none" else ""
        found.append(
            Doubt(
                f"the surface is flat{levelled}: {varies}, so it has no roughness (its statistics are 0 "
                "and it has no summits)",
                {
                    style: "a contact on it is the flat punch's (full contact); check the file and the "
                    "channel if a rough surface was expected"
                    for style in ("python", "study", "cli", "marked")
                },
            )
        )
    elif not HEIGHTS[0] <= span <= HEIGHTS[1]:
        low, high = (format_si(bound, "m") for bound in HEIGHTS)
        side = "more" if span > HEIGHTS[1] else "less"
        bound = high if span > HEIGHTS[1] else low
        found.append(
            Doubt(
                f"its heights span {format_si(span, 'm')} (peak to valley), {side} than {bound}",
                _HEIGHT_FIXES,
            )
        )
    return tuple(found)
