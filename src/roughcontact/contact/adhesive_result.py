"""Immutable result of an adhesive contact programme (:func:`roughcontact.contact.solve_adhesive`)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ..display_html import NotebookDisplay
from ..messages import as_messages
from ..topography import Topography
from ..units import format_si
from .area import corrected_contact_count
from .interaction import INTERACTION_FRACTION, MaugisDugdale
from .trust import area_resolution, contact_shares, share_warnings

RESOLVED_ZONE_PIXELS = 2.0
"""Pixels the cohesive zone must span for a smooth law's pull-off to be mesh-independent (the
exponential law on Johnson's wavy surface: +1.3 % at 2 pixels, +0.1 % at 8)."""

MAUGIS_DUGDALE_ZONE_PIXELS = 24.0
"""The same for the Maugis-Dugdale law, whose step in traction converges at first order: its
pull-off is high by about 1.2 pixel / zone (+33 % at 2 pixels, +6 % at 16, +5 % at 24; Johnson's
wavy surface, tests/validation/test_adhesive_wavy.py)."""

MAUGIS_DUGDALE_ERROR = 1.2
"""First-order coefficient of the Maugis-Dugdale pull-off's error in pixel / zone."""

LINE_NAMES = {
    "pull_off_force": "pull_off_force_per_length",
    "max_force": "max_force_per_length",
    "dissipated_energy": "dissipated_energy_per_length",
    "max_contact_area": "max_contact_length",
    "contact_area_at_pull_off": "contact_length_at_pull_off",
    "interaction_area_at_pull_off": "interaction_zone_length_at_pull_off",
}
"""The scalars of a line contact (a profile in plane strain), named for what they are: per length
[N/m, J/m] and lengths [m] in place of forces [N], an energy [J] and areas [m^2]."""

MAP_STATES = ("peak", "pull_off", "end")
"""The states whose pressure and gap maps are kept: the largest approach, the pull-off, the last."""


@dataclass(frozen=True, eq=False)
class AdhesiveResult(NotebookDisplay):
    """Adhesive contact along an approach programme (SI; per step unless noted).

    Attributes
    ----------
    topography : Topography
        The surface solved.
    interaction : interaction law
        :class:`~roughcontact.contact.interaction.MaugisDugdale`, ``Exponential`` or ``LennardJones``.
    delta : ndarray
        The flat's imposed position [m] (equal to ``approach`` for a free boundary).
    approach : ndarray
        Approach from the first touch [m] (periodic: zero-mean displacement convention).
    force : ndarray
        Normal force [N] (N/m for a profile), compressive positive, tensile negative.
    contact_area, interaction_area : ndarray
        Area at the wall (in repulsion for Lennard-Jones) [m^2]; area out of contact under a tension
        of at least ``INTERACTION_FRACTION`` of the peak tension [m^2].
    requested : ndarray of bool
        True for the programme's own steps, False for steps inserted to resolve fast changes
        or to reach detachment.
    jump : ndarray of bool
        True where the state jumped from the previous step (an instability, bracketed to the
        jump resolution).
    iterations : ndarray of int
    residual : ndarray
        Largest force imbalance of a pixel relative to the peak tension, per step.
    maps : dict
        ``{state: (pressure [Pa], gap [m])}`` at the states of :data:`MAP_STATES`.
    map_steps : dict
        The step index of each of those states.
    pixel_area : float
        [m^2] (a profile: the spacing [m]).
    contact_modulus : float
        E* [Pa].
    boundary : str
    tolerance : float
    cohesive_zone : float
        (pi / 4) E* w / sigma0^2 [m], the cohesive-zone length the grid must resolve.
    parameters : dict
    contact_area_corrected : ndarray or None
        The contact area corrected for its pixelated perimeter [m^2] per step (maps; None for a
        profile): :func:`roughcontact.contact.area.corrected_contact_count` of the touching pixels.
    """

    topography: Topography
    interaction: Any
    delta: np.ndarray
    approach: np.ndarray
    force: np.ndarray
    contact_area: np.ndarray
    interaction_area: np.ndarray
    requested: np.ndarray
    jump: np.ndarray
    iterations: np.ndarray
    residual: np.ndarray
    maps: dict = field(repr=False)
    map_steps: dict
    pixel_area: float
    contact_modulus: float
    boundary: str
    tolerance: float
    cohesive_zone: float
    parameters: dict = field(default_factory=dict)
    contact_area_corrected: np.ndarray | None = None

    UNITS: ClassVar[dict[str, str]] = {
        "pull_off_force": "N",
        "pull_off_approach": "m",
        "max_force": "N",
        "max_approach": "m",
        "jump_in_approach": "m",
        "jump_out_approach": "m",
        "dissipated_energy": "J",
        "max_contact_area": "m^2",
        "contact_area_at_pull_off": "m^2",
        "max_contact_area_corrected": "m^2",
        "contact_area_at_pull_off_corrected": "m^2",
        "interaction_area_at_pull_off": "m^2",
        "work_of_adhesion": "J/m^2",
        "interaction_length": "m",
        "peak_tension": "Pa",
        "cohesive_zone_length": "m",
        "pull_off_force_per_length": "N/m",
        "max_force_per_length": "N/m",
        "dissipated_energy_per_length": "J/m",
        "max_contact_length": "m",
        "contact_length_at_pull_off": "m",
        "interaction_zone_length_at_pull_off": "m",
    }

    @classmethod
    def from_states(
        cls,
        *,
        topography: Topography,
        interaction: Any,
        states: Sequence,
        pixel_area: float,
        requested: np.ndarray,
        jump: np.ndarray,
        contact_modulus: float,
        boundary: str,
        tolerance: float,
        cohesive_zone: float,
        parameters: dict,
    ) -> AdhesiveResult:
        """Build the result from the engine's states (see :mod:`roughcontact.contact.adhesive`).

        The curves and the maps at the peak, the pull-off and the end come from ``states``; the
        other keywords are the fields of the same name.
        """
        law = interaction
        threshold = -INTERACTION_FRACTION * law.peak_tension
        force = np.array([s.pressure.sum() * pixel_area for s in states])
        delta = np.array([s.delta for s in states])
        steps = {
            "peak": int(np.argmax(delta)),
            "pull_off": int(np.argmin(force)),
            "end": len(states) - 1,
        }
        shape = topography.shape
        return cls(
            topography=topography,
            interaction=law,
            delta=delta,
            approach=np.array([s.approach for s in states]),
            force=force,
            contact_area=np.array([law.in_contact(s.gap).sum() * pixel_area for s in states]),
            contact_area_corrected=(
                np.array(
                    [
                        corrected_contact_count(
                            law.in_contact(s.gap).reshape(shape), periodic=boundary == "periodic"
                        )
                        * pixel_area
                        for s in states
                    ]
                )
                if topography.dim == 2
                else None
            ),
            interaction_area=np.array(
                [
                    np.count_nonzero(~law.in_contact(s.gap) & (law.traction(s.gap) <= threshold)) * pixel_area
                    for s in states
                ]
            ),
            iterations=np.array([s.iterations for s in states]),
            residual=np.array([s.residual for s in states]),
            maps={
                name: (states[i].pressure.reshape(shape).copy(), states[i].gap.reshape(shape).copy())
                for name, i in steps.items()
            },
            map_steps=steps,
            pixel_area=pixel_area,
            requested=requested,
            jump=jump,
            contact_modulus=contact_modulus,
            boundary=boundary,
            tolerance=tolerance,
            cohesive_zone=cohesive_zone,
            parameters=parameters,
        )

    @property
    def converged(self) -> bool:
        """True: every step met the tolerance (an unconverged step raises instead)."""
        return bool(np.all(self.residual <= self.tolerance))

    @property
    def touched(self) -> bool:
        """Whether the programme brought the surfaces into contact at any step."""
        return bool(np.any(self.contact_area > 0))

    @property
    def pull_off_force(self) -> float:
        """Most tensile force [N], positive (parabola through the smallest force and its neighbours).

        The parabola's vertex is used when it lies between the neighbours and below the smallest
        force by no more than the neighbours lie above it; otherwise the smallest force itself.
        NaN when the surfaces never touched: the largest attraction along a programme that stays
        apart is no pull-off.
        """
        return -self._pull_off()[1]

    def _pull_off(self) -> tuple[float, float]:
        if not self.touched:
            return float("nan"), float("nan")
        i = int(np.argmin(self.force))
        approach, force = float(self.approach[i]), float(self.force[i])
        if 0 < i < len(self.force) - 1 and not (self.jump[i] or self.jump[i + 1]):
            (x0, x1, x2), (y0, y1, y2) = self.approach[i - 1 : i + 2], self.force[i - 1 : i + 2]
            if x0 != x1 != x2 != x0:
                slope_left, slope_right = (y1 - y0) / (x1 - x0), (y2 - y1) / (x2 - x1)
                curvature = (slope_right - slope_left) / (x2 - x0)  # the parabola's leading coefficient
                if curvature > 0:
                    vertex = 0.5 * (x0 + x1) - slope_left / (2 * curvature)
                    if min(x0, x2) <= vertex <= max(x0, x2):
                        value = y1 + (vertex - x1) * (slope_left + curvature * (vertex - x0))
                        # an interpolation, not an extrapolation: uneven steps across a change of
                        # regime (contact starting) can put a parabola's vertex far below the points
                        if y1 - value <= max(y0, y2) - y1:
                            return float(vertex), float(value)
        return approach, force

    def _jump_approach(self, loading: bool) -> float:
        rising = np.diff(self.delta) > 0
        marks = [i for i in np.flatnonzero(self.jump) if i > 0 and rising[i - 1] == loading]
        if not marks:
            return float("nan")
        i = marks[0] if loading else marks[-1]
        return float(0.5 * (self.approach[i - 1] + self.approach[i]))

    @property
    def dissipated_energy(self) -> float:
        """Work done by the flat along the programme [J]: sum F d(approach) (trapezoid rule).

        Over a cycle that starts and ends apart, the energy the adhesive hysteresis dissipated
        (the area between the loading and the unloading curves). The jumps dissipate it; on the
        branches the sum is the trapezoid rule's error, a few pixels' worth of w A_pixel at most
        (the step control's threshold), so a cycle without a jump (DMT-like) reads zero within
        that, of either sign (paper 000's tip: 1e-21 J against w A_pixel = 5e-17 J).
        """
        return float(np.sum(0.5 * (self.force[1:] + self.force[:-1]) * np.diff(self.approach)))

    @property
    def _force_unit(self) -> str:
        return "N" if self.topography.dim == 2 else "N/m"

    @property
    def _spacing(self) -> float:
        """Pixel size [m] (the side of a square pixel; the spacing of a profile)."""
        return float(np.sqrt(self.pixel_area)) if self.topography.dim == 2 else self.pixel_area

    @as_messages
    def range_warnings(self) -> list[str]:
        """Why the answer may depend on the grid or the window.

        A programme that never brings the surfaces into contact (no pull-off); a contact area at
        pull-off (or at its largest) of fewer than ten pixels
        (:func:`roughcontact.contact.trust.area_resolution`); a cohesive zone narrower than
        :data:`RESOLVED_ZONE_PIXELS` pixels (:data:`MAUGIS_DUGDALE_ZONE_PIXELS` for the
        Maugis-Dugdale law); on a free window, an interaction that reaches the window's edge at
        the pull-off (the attraction beyond it is missing, so the pull-off is too small).
        """
        warnings = []
        if not self.touched:
            i = int(np.argmin(self.force))
            deepest, attraction = (
                format_si(self.approach.max(), "m"),
                format_si(-self.force[i], self._force_unit),
            )
            return [
                f"the surfaces never touch: the programme's deepest approach, {deepest} from the first "
                f"touch, leaves them apart, so there is no pull-off (the largest attraction along it, "
                f"{attraction} at {format_si(self.approach[i], 'm')}, is not one). Give a positive "
                "«max_approach», e.g. a few interaction lengths."
            ]
        warnings += share_warnings(self.shares, self.topography, self.boundary)
        measure, dim = self.pixel_area, self.topography.dim
        at_pull_off = float(self.contact_area[self.map_steps["pull_off"]])
        fix = "Use a scan with smaller pixels over the contact."
        warnings += area_resolution("the contact area at pull-off", at_pull_off, measure, dim, fix)
        warnings += area_resolution("the largest contact area", float(self.contact_area.max()), measure, dim)
        spacing = self._spacing
        pixels = self.cohesive_zone / spacing
        stepped = isinstance(self.interaction, MaugisDugdale)
        needed = MAUGIS_DUGDALE_ZONE_PIXELS if stepped else RESOLVED_ZONE_PIXELS
        if pixels < needed:
            largest = self.cohesive_zone / needed
            error = (
                f" (expect about +{100 * MAUGIS_DUGDALE_ERROR / pixels:.2g} %, first order)"
                if stepped
                else ""
            )
            warnings.append(
                f"the cohesive zone (pi/4) E* w / sigma0^2 = {self.cohesive_zone:.3g} m spans {pixels:.2g} "
                f"pixels of {spacing:.3g} m; below {needed:g} the {self.interaction.name} pull-off and "
                f"jumps depend on the grid{error}: use a pixel of at most {largest:.3g} m "
                "or a longer interaction length."
            )
        if self.boundary == "free" and self._interacting_at_edge():
            warnings.append(
                "the surfaces still attract at the window's edge at the pull-off: the attraction "
                "beyond the window is missing and the pull-off is underestimated; use a larger window "
                "or a shorter interaction length."
            )
        return warnings

    def _interacting_at_edge(self) -> bool:
        """Whether an edge pixel is under a tension of INTERACTION_FRACTION of the peak at the pull-off."""
        pressure = self.maps["pull_off"][0]
        edges = [pressure[0], pressure[-1]]
        if pressure.ndim == 2:
            edges += [pressure[:, 0], pressure[:, -1]]
        threshold = -INTERACTION_FRACTION * self.interaction.peak_tension
        return any(bool(np.any(edge <= threshold)) for edge in edges)

    def scalars(self) -> dict[str, Any]:
        """Return the headline numbers (SI), see ``UNITS``; a line contact's named per :data:`LINE_NAMES`.

        A map adds its contact areas corrected for their pixelated perimeter beside the raw pixel
        counts (``max_contact_area_corrected``, ``contact_area_at_pull_off_corrected``;
        :mod:`roughcontact.contact.area`).
        """
        law = self.interaction
        pull_off_approach, pull_off = self._pull_off()
        i = self.map_steps["pull_off"]
        spacing = self._spacing
        scalars = {
            "law": law.name,
            "work_of_adhesion": law.work_of_adhesion,
            "interaction_length": law.length,
            "peak_tension": law.peak_tension,
            "pull_off_force": -pull_off,
            "pull_off_approach": pull_off_approach,
            "max_force": float(self.force.max()),
            "max_approach": float(self.approach.max()),
            "jump_in_approach": self._jump_approach(True),
            "jump_out_approach": self._jump_approach(False),
            "jumps": int(self.jump.sum()),
            "dissipated_energy": self.dissipated_energy,
            "max_contact_area": float(self.contact_area.max()),
            "contact_area_at_pull_off": float(self.contact_area[i]),
        }
        if self.contact_area_corrected is not None:
            scalars |= {
                "max_contact_area_corrected": float(self.contact_area_corrected.max()),
                "contact_area_at_pull_off_corrected": float(self.contact_area_corrected[i]),
            }
        scalars |= {
            "interaction_area_at_pull_off": float(self.interaction_area[i]),
            "cohesive_zone_length": self.cohesive_zone,
            "cohesive_zone_pixels": self.cohesive_zone / spacing,
            "boundary": self.boundary,
            "steps": int(self.force.size),
            "inserted_steps": int((~self.requested).sum()),
            "iterations": int(self.iterations.sum()),
            "residual": float(self.residual.max()),
            "converged": self.converged,
        } | self.shares
        if self.topography.dim == 1:
            scalars = {LINE_NAMES.get(name, name): value for name, value in scalars.items()}
        return scalars

    @property
    def shares(self) -> dict[str, float]:
        """Shares of the load and the contact at the deepest approach on filled points, specks and an edge.

        :func:`roughcontact.contact.trust.contact_shares` of the compressive pressure of the
        ``"peak"`` state, the contact where the law says the surfaces touch (``in_contact(gap)``,
        as :attr:`contact_area` counts it), not wherever the pressure is positive: the tail of a
        law leaves tractions of a fraction of a pascal tens of nanometres from the contact.
        """
        pressure, gap = self.maps["peak"]
        touching = self.interaction.in_contact(gap)
        return contact_shares(pressure, self.topography, self.boundary, touching)

    def to_xarray(self):
        """Return the force-approach curve per step and the pressure and gap maps of :data:`MAP_STATES`."""
        import xarray as xr

        data = {
            "delta": ("step", self.delta, {"units": "m", "long_name": "imposed position of the flat"}),
            "approach": ("step", self.approach, {"units": "m"}),
            "force": ("step", self.force, {"units": self._force_unit}),
            "contact_area": (
                "step",
                self.contact_area,
                {"units": "m^2" if self.topography.dim == 2 else "m"},
            ),
            **(
                {}
                if self.contact_area_corrected is None
                else {
                    "contact_area_corrected": (
                        "step",
                        self.contact_area_corrected,
                        {"units": "m^2", "long_name": "contact area corrected for its pixelated perimeter"},
                    )
                }
            ),
            "interaction_area": (
                "step",
                self.interaction_area,
                {"units": "m^2" if self.topography.dim == 2 else "m"},
            ),
            "requested": ("step", self.requested, {"units": "1"}),
            "jump": ("step", self.jump, {"units": "1"}),
            "iterations": ("step", self.iterations, {"units": "1"}),
            "residual": ("step", self.residual, {"units": "1"}),
        }
        axes = ("x", "y")[: self.topography.dim]
        dims = ("state", *axes)
        coords = {a: (a, c, {"units": "m"}) for a, c in zip(axes, self.topography.coordinates(), strict=True)}
        data["pressure"] = (dims, np.stack([self.maps[s][0] for s in MAP_STATES]), {"units": "Pa"})
        data["gap"] = (dims, np.stack([self.maps[s][1] for s in MAP_STATES]), {"units": "m"})
        data["state_step"] = ("state", np.array([self.map_steps[s] for s in MAP_STATES]), {"units": "1"})
        coords["state"] = ("state", list(MAP_STATES))
        return xr.Dataset(data, coords=coords, attrs={"law": self.interaction.describe()})
