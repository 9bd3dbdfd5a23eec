"""Results of partial-slip tangential contact: one state per step and the whole loading programme."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ..display_html import NotebookDisplay
from ..topography import Topography
from .paths import reversals
from .result import NormalContactResult


@dataclass(frozen=True)
class TangentialState:
    """Converged state after one tangential step (all SI, fields on the topography's grid).

    Attributes
    ----------
    shear_x, shear_y : ndarray
        Shear tractions q_x, q_y [Pa] on the rough body (in the direction the flat drags it).
    pressure : ndarray
        Contact pressure [Pa] (changes along the path only when normal and tangential are coupled).
    slip_x, slip_y : ndarray
        Accumulated relative tangential displacement s = u_t - delta [m] (paper 001 eq. 1).
    slip_increment_x, slip_increment_y : ndarray
        Change of s in this step [m] (0 in stick, eq. 3), 0 outside the contact.
    stick : ndarray of bool
        Contact points that stick in this step.
    displacement : (float, float)
        Rigid tangential displacement (delta_x, delta_y) of the flat [m].
    friction_coefficient : float
        mu of the local Coulomb law.
    pixel_area : float
        [m^2].
    """

    shear_x: np.ndarray
    shear_y: np.ndarray
    pressure: np.ndarray
    slip_x: np.ndarray
    slip_y: np.ndarray
    slip_increment_x: np.ndarray
    slip_increment_y: np.ndarray
    stick: np.ndarray
    displacement: tuple[float, float]
    friction_coefficient: float
    pixel_area: float

    def __post_init__(self):
        for name in (
            "shear_x",
            "shear_y",
            "pressure",
            "slip_x",
            "slip_y",
            "slip_increment_x",
            "slip_increment_y",
            "stick",
        ):
            getattr(self, name).setflags(write=False)

    @property
    def contact(self) -> np.ndarray:
        """Points with positive pressure."""
        return self.pressure > 0

    @property
    def slip(self) -> np.ndarray:
        """Contact points that slip in this step (``|q|`` = mu p, equation 3)."""
        return self.contact & ~self.stick

    @property
    def force(self) -> tuple[float, float]:
        """Friction force (F_x, F_y) [N] on the rough body."""
        return (float(self.shear_x.sum() * self.pixel_area), float(self.shear_y.sum() * self.pixel_area))

    @property
    def normalised_shear(self) -> np.ndarray:
        """sqrt(q_x^2 + q_y^2) / (mu p): < 1 in stick, 1 in slip, NaN outside the contact (figures 11-12)."""
        out = np.full(self.pressure.shape, np.nan)
        contact = self.contact
        out[contact] = np.hypot(self.shear_x, self.shear_y)[contact] / (
            self.friction_coefficient * self.pressure[contact]
        )
        return out


@dataclass(frozen=True)
class TangentialPathResult(NotebookDisplay):
    """A frictional loading programme (paper 001 figures 6, 10-14; combined normal and tangential steps).

    Attributes
    ----------
    normal : NormalContactResult or None
        The frictionless normal contact at F_0 of :func:`solve_tangential` (with the frictionless
        start, the programme starts from it: q = 0, delta = 0); None for a programme of
        :func:`solve_frictional`, which starts unloaded.
    topography : Topography
        The rough surface.
    displacement : ndarray, shape (n, 2)
        Rigid tangential displacement of the flat at each step [m].
    force : ndarray, shape (n, 2)
        Friction force on the rough body at each step [N].
    contact_area, stick_area, slip_area : ndarray, shape (n,)
        [m^2] at each step.
    iterations, coupling_iterations : ndarray of int, shape (n,)
        Conjugate-gradient iterations (summed over the coupling passes) and coupling passes.
    residual : ndarray, shape (n,)
        Scale-free residual of the last tangential solve of each step.
    states : dict of int -> TangentialState
        Full fields at the steps that were kept (see ``fields_at`` of the solver).
    normal_load : ndarray, shape (n,)
        Normal force at each step [N] (F_0 throughout for :func:`solve_tangential`).
    approach : ndarray, shape (n,)
        Rigid normal approach of the flat from first touch of the undeformed surface [m].
    dissipation : ndarray, shape (n,)
        Frictional work of each step, -sum q . w A_px >= 0 [J].
    programme_index : ndarray of int, shape (n,)
        The user's programme point each step reaches or heads to: steps inserted by the step
        control (``max_stick_change``) share the index of the point they lead to, and the step
        at a programme point is the last with its index (:meth:`step_of`).
    loading : TangentialPathResult or None
        The frictional normal loading the programme starts from (``normal_loading="frictional"``
        of :func:`solve_tangential`); its last state holds the locked-in shear.
    parameters : dict
        What was asked for.
    """

    normal: NormalContactResult | None
    topography: Topography
    displacement: np.ndarray
    force: np.ndarray
    contact_area: np.ndarray
    stick_area: np.ndarray
    slip_area: np.ndarray
    iterations: np.ndarray
    coupling_iterations: np.ndarray
    residual: np.ndarray
    states: dict[int, TangentialState]
    normal_load: np.ndarray
    approach: np.ndarray
    dissipation: np.ndarray
    programme_index: np.ndarray
    loading: TangentialPathResult | None = None
    parameters: dict[str, Any] = field(default_factory=dict)

    UNITS: ClassVar[dict[str, str]] = {
        "normal_force": "N",
        "last_delta_x": "m",
        "last_delta_y": "m",
        "last_force_x": "N",
        "last_force_y": "N",
        "last_contact_area": "m^2",
        "last_stick_area": "m^2",
        "last_slip_area": "m^2",
        "energy_last_closed_loop": "J",
        "last_approach": "m",
        "dissipated_energy": "J",
        "locked_in_shear_rms": "Pa",
    }
    """SI unit of each dimensional scalar of :meth:`scalars`."""

    @property
    def steps(self) -> int:
        """Number of steps."""
        return len(self.displacement)

    @property
    def normal_force(self) -> float:
        """Normal force of the last step [N] (F_0 for :func:`solve_tangential`)."""
        return float(self.normal_load[-1])

    def step_of(self, point: int) -> int:
        """Return the step solved at the user's programme point ``point`` (negative counts from the end)."""
        points = np.flatnonzero(self.programme_index == (point % (self.programme_index.max() + 1)))
        return int(points[-1])

    def locked_in(self) -> dict[str, float]:
        """Shear locked in by the frictional normal loading (NaN without one).

        ``locked_in_stick_fraction``: stick area over contact area at its last step (Spence's
        (c/a)^2 for a sphere); ``locked_in_shear_rms``: rms ``|q|`` over the contact [Pa];
        ``locked_in_shear_ratio``: largest ``|q|`` / (mu p) inside the stick zone.
        """
        loading = self.loading
        names = ("locked_in_stick_fraction", "locked_in_shear_rms", "locked_in_shear_ratio")
        if loading is None or loading.steps - 1 not in loading.states:
            return dict.fromkeys(names, math.nan)
        state = loading.states[loading.steps - 1]
        contact = state.contact
        magnitude = np.hypot(state.shear_x, state.shear_y)[contact]
        ratio = state.normalised_shear[state.stick]
        return dict(
            zip(
                names,
                (
                    float(loading.stick_area[-1] / loading.contact_area[-1]),
                    float(np.sqrt(np.mean(magnitude**2))),
                    float(ratio.max()) if ratio.size else math.nan,
                ),
                strict=True,
            )
        )

    def _controlled(self, axis: int) -> np.ndarray:
        """Return the prescribed series along ``axis`` (force under force control, else displacement)."""
        series = self.force if self.parameters.get("control") == "force" else self.displacement
        return series[:, axis]

    def reversals(self, axis: int = 0) -> np.ndarray:
        """Return the indices of the steps where the prescribed path along ``axis`` changes direction."""
        return reversals(self._controlled(axis))

    def loops(self, axis: int = 0) -> list[tuple[int, int]]:
        """(start, stop) step indices of each closed loop.

        A loop runs from a reversal to the second turning point after it (a reversal, or the last
        step when the path ends where the loop began), e.g. stroke -> 0 -> stroke.
        """
        d = self._controlled(axis)
        turns = [int(t) for t in self.reversals(axis)]
        scale = float(np.ptp(d)) or 1.0
        if len(turns) >= 2 and abs(d[-1] - d[turns[-2]]) <= 1e-9 * scale and turns[-1] != self.steps - 1:
            turns.append(self.steps - 1)
        return [(turns[i], turns[i + 2]) for i in range(0, len(turns) - 2, 2)]

    def dissipated_energy(self, axis: int = 0) -> np.ndarray:
        """Energy dissipated in each closed loop, the loop's area: sum of F . d(delta) [J]."""
        energies = []
        for start, stop in self.loops(axis):
            d = self.displacement[start : stop + 1]
            f = self.force[start : stop + 1]
            energies.append(float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(d, axis=0))))
        return np.asarray(energies)

    @property
    def converged(self) -> bool:
        """True when every step met the tolerance (the solver raises rather than return otherwise)."""
        tolerance = self.parameters.get("tolerance")
        return tolerance is None or bool(np.all(self.residual <= tolerance))

    def scalars(self) -> dict[str, Any]:
        """Return the programme's scalars (SI; units in :attr:`UNITS`): its last step, loops and effort.

        The per-step series are in :meth:`to_xarray`.
        """
        energies = self.dissipated_energy()
        return {
            "steps": self.steps,
            "normal_force": self.normal_force,
            "last_delta_x": float(self.displacement[-1, 0]),
            "last_delta_y": float(self.displacement[-1, 1]),
            "last_force_x": float(self.force[-1, 0]),
            "last_force_y": float(self.force[-1, 1]),
            "last_contact_area": float(self.contact_area[-1]),
            "last_stick_area": float(self.stick_area[-1]),
            "last_slip_area": float(self.slip_area[-1]),
            "last_stick_fraction": float(self.stick_area[-1] / self.contact_area[-1]),
            "loops": len(energies),
            "energy_last_closed_loop": float(energies[-1]) if energies.size else math.nan,
            "last_approach": float(self.approach[-1]),
            "dissipated_energy": float(self.dissipation.sum()),
            **self.locked_in(),
            "iterations": int(self.iterations.sum()),
            "coupling_iterations": int(self.coupling_iterations.sum()),
            "residual": float(self.residual.max()),
        }

    def to_xarray(self):
        """Return an xarray Dataset: per-step series along ``step``, kept fields along ``kept_step, x, y``."""
        import xarray as xr

        data = {
            "delta_x": ("step", self.displacement[:, 0], {"units": "m"}),
            "delta_y": ("step", self.displacement[:, 1], {"units": "m"}),
            "force_x": ("step", self.force[:, 0], {"units": "N"}),
            "force_y": ("step", self.force[:, 1], {"units": "N"}),
            "contact_area": ("step", self.contact_area, {"units": "m^2"}),
            "stick_area": ("step", self.stick_area, {"units": "m^2"}),
            "slip_area": ("step", self.slip_area, {"units": "m^2"}),
            "normal_force": ("step", self.normal_load, {"units": "N"}),
            "approach": ("step", self.approach, {"units": "m"}),
            "dissipation": (
                "step",
                self.dissipation,
                {"units": "J", "long_name": "frictional work of the step"},
            ),
            "programme_index": ("step", self.programme_index, {"long_name": "programme point reached"}),
            "iterations": ("step", self.iterations),
            "residual": ("step", self.residual, {"units": "1", "long_name": "scale-free residual"}),
        }
        kept = sorted(self.states)
        units = {"shear_x": "Pa", "shear_y": "Pa", "pressure": "Pa", "slip_x": "m", "slip_y": "m"}
        dims = ("kept_step", "x", "y")
        for name, unit in units.items():
            data[name] = (
                dims,
                np.stack([getattr(self.states[k], name) for k in kept])
                if kept
                else np.empty((0, *self.topography.shape)),
                {"units": unit},
            )
        data["stick"] = (
            dims,
            np.stack([self.states[k].stick for k in kept])
            if kept
            else np.empty((0, *self.topography.shape), dtype=bool),
        )
        x, y = self.topography.coordinates()
        coords = {
            "step": np.arange(self.steps),
            "kept_step": np.asarray(kept, dtype=int),
            "x": ("x", x, {"units": "m"}),
            "y": ("y", y, {"units": "m"}),
        }
        attrs = {f"parameter_{k}": str(v) for k, v in self.parameters.items()}
        attrs["normal_force"] = self.normal_force
        return xr.Dataset(data, coords=coords, attrs=attrs)
