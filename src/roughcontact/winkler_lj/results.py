"""The results of paper 000's Winkler-Lennard-Jones model: friction at one load, a sweep, a normal curve."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from ..contact.adhesive_result import AdhesiveResult
from ..contact.trust import contact_shares, share_warnings
from ..display_html import NotebookDisplay
from ..messages import as_messages
from ..topography import Topography


@dataclass(frozen=True, eq=False)
class WinklerLJResult(NotebookDisplay):
    """Friction of the Winkler-Lennard-Jones model at one normal load (SI).

    Attributes
    ----------
    normal_force : float
        Normal load N [N].
    separation : float
        d: distance from the flat to the base of the composite surface [m]: its lowest point, or
        the base of the half-sphere tip (``readings.base``).
    approach : float
        Overlap of the highest point with the contact wall (epsilon or 0, see ``readings.contact``) [m];
        > 0 when springs are compressed.
    mechanical, adhesive : ndarray of bool
        Springs in mechanical contact and in strictly adhesive contact, i.e. feeling the attraction
        of eq. 7 in eq. 2 (disjoint; springs beyond ``readings.adhesive_cutoff`` are in neither).
    bonded : ndarray of bool
        The adhesive springs within the adhesive range (``readings.adhesive_range``): only they add
        adhesive friction (eq. 15); the other adhesive springs have Q = 0.
    gap : ndarray
        Undeformed gap l_i = d - z_i [m]; with ``gap_model="bem"`` the boundary-element solution's
        (deformed) distance l = g + epsilon, which is then also the bond distance l_ia.
    stress : ndarray
        Normal stress on each spring [Pa]: compression (> 0) of mechanical springs, minus the
        attraction of eq. 7 on adhesive ones, 0 elsewhere.
    extension : ndarray
        Spring extension dz_i [m]: eq. 8 for adhesive springs (> 0, towards the flat), minus the
        compression for mechanical ones.
    lateral_force : ndarray
        Q_i [N] (eqs. 15 and 17); 0 on adhesive springs that are not bonded.
    mechanical_force, adhesive_force : float
        Sum of the spring forces P_i S [N] and of the attractions f(l_i) S [N] (stresses summed
        without S under ``balance_terms="pressures_printed"``).
    adhesive_friction, mechanical_friction : float
        Sums of Q_i over bonded adhesive springs and over mechanical springs [N]; ``friction``
        (their sum) and ``mu`` (friction / normal_force, the coefficient of friction the model
        gives) are properties.
    residual : float
        Force-balance residual of eq. 2 at ``separation``, relative to the largest term (with
        ``gap_model="bem"``: the boundary-element load's relative error).
    iterations : int
        Evaluations of eq. 2 the root find took (with ``gap_model="bem"``: the boundary-element
        solver's iterations over its programme).
    tolerance : float
        The residual a converged solve stays within (:attr:`converged`).
    max_strain : float
        Largest compression of a spring relative to the layer thickness.
    negative_energy_springs : int
        Mechanical springs whose eq. 16 energy was negative (only ``mechanical_energy="eq16_signed"``);
        they add no friction.
    pulled_in_springs : int
        Adhesive springs whose bond distance l_ia = l_i - dz_i is at or below epsilon (eq. 8
        extension reaching the zero of eq. 7, or ``contact="zero_gap"`` springs inside epsilon);
        their bond energy is taken at epsilon, dgamma.
    parameters : dict
        Derived constants and inputs: contact_modulus, winkler_factor, shear_modulus,
        work_of_adhesion, spring_stiffness (E / (k h), Pa/m), epsilon, layer_thickness,
        spring_area, readings.
    topography : Topography
        The composite surface.
    gap_model : {"winkler", "bem"}
        The gap field the friction sums used: the Winkler springs' (paper 000) or the adhesive
        boundary-element solution's at the same load (see :meth:`WinklerLJModel.solve`).
    bem : AdhesiveResult or None
        With ``gap_model="bem"``: the boundary-element programme whose last state carries the load.
    """

    normal_force: float
    separation: float
    approach: float
    mechanical: np.ndarray
    adhesive: np.ndarray
    bonded: np.ndarray
    gap: np.ndarray
    stress: np.ndarray
    extension: np.ndarray
    lateral_force: np.ndarray
    mechanical_force: float
    adhesive_force: float
    adhesive_friction: float
    mechanical_friction: float
    residual: float
    max_strain: float
    negative_energy_springs: int
    pulled_in_springs: int
    parameters: dict = field(repr=False)
    topography: Topography = field(repr=False)
    gap_model: str = "winkler"
    bem: Any = field(default=None, repr=False)
    iterations: int = 0
    tolerance: float = 1e-9

    UNITS: ClassVar[dict[str, str]] = {
        "normal_force": "N",
        "friction": "N",
        "adhesive_friction": "N",
        "mechanical_friction": "N",
        "separation": "m",
        "approach": "m",
        "mechanical_force": "N",
        "adhesive_force": "N",
        "bem_force": "N",
    }
    """SI units of the dimensional entries of :meth:`scalars`."""

    @property
    def friction(self) -> float:
        """Adhesive plus mechanical friction [N]."""
        return self.adhesive_friction + self.mechanical_friction

    @property
    def mu(self) -> float:
        """The coefficient of friction, friction / normal_force."""
        return self.friction / self.normal_force

    @property
    def converged(self) -> bool:
        """True when the residual is within the solve's tolerance (a failed root find raises instead)."""
        return bool(self.residual <= self.tolerance)

    def scalars(self) -> dict[str, float]:
        """Return the scalar results as a flat dictionary (SI; units in :attr:`UNITS`).

        With ``gap_model="bem"`` also ``gap_model`` (the gap field the friction sums used; the
        attribute names it in either case), ``bem_force`` (the boundary-element solution's normal
        force, equal to ``normal_force`` within :data:`BEM_LOAD_RTOL`) and ``bem_load_error``
        (``|bem_force - N|`` / N).
        """
        extra = {}
        if self.bem is not None:
            force = float(self.bem.force[-1])
            extra = {
                "gap_model": self.gap_model,
                "bem_force": force,
                "bem_load_error": abs(force - self.normal_force) / self.normal_force,
            }
        return (
            {
                "normal_force": self.normal_force,
                "mu": self.mu,
                "friction": self.friction,
                "adhesive_friction": self.adhesive_friction,
                "mechanical_friction": self.mechanical_friction,
                "separation": self.separation,
                "approach": self.approach,
                "mechanical_springs": int(self.mechanical.sum()),
                "adhesive_springs": int(self.adhesive.sum()),
                "bonded_springs": int(self.bonded.sum()),
                "mechanical_force": self.mechanical_force,
                "adhesive_force": self.adhesive_force,
                "residual": self.residual,
                "max_strain": self.max_strain,
                "negative_energy_springs": self.negative_energy_springs,
                "pulled_in_springs": self.pulled_in_springs,
            }
            | extra
            | self.shares
        )

    @property
    def shares(self) -> dict[str, float]:
        """Shares of the compressive load and of the contact on filled points and specks.

        :func:`roughcontact.contact.trust.contact_shares` of the spring stresses (compression); a
        Winkler layer has no window edge (its springs do not act on one another).
        """
        return contact_shares(self.stress, self.topography, "periodic")

    @as_messages
    def range_warnings(self) -> list[str]:
        """Say when the load rests on filled points or specks (:func:`~.contact.trust.share_warnings`)."""
        return share_warnings(self.shares, self.topography, "periodic")

    def to_xarray(self):
        """Return an ``xarray.Dataset``: spring fields on (x, y), scalars and parameters as attributes."""
        import xarray as xr

        grid = dict(zip(("x", "y"), self.topography.coordinates(), strict=True))
        fields_ = {
            "heights": (self.topography.heights, "m"),
            "gap": (self.gap, "m"),
            "stress": (self.stress, "Pa"),
            "extension": (self.extension, "m"),
            "lateral_force": (self.lateral_force, "N"),
            "mechanical": (self.mechanical.astype(np.int8), ""),
            "adhesive": (self.adhesive.astype(np.int8), ""),
            "bonded": (self.bonded.astype(np.int8), ""),
        }
        data = {name: (("x", "y"), values, {"units": unit}) for name, (values, unit) in fields_.items()}
        attributes = dict(self.scalars()) | {"gap_model": self.gap_model}
        attributes.update({k: v for k, v in self.parameters.items() if k != "readings"})
        attributes.update({f"reading_{k}": str(v) for k, v in vars(self.parameters["readings"]).items()})
        coords = {axis: (axis, values, {"units": "m"}) for axis, values in grid.items()}
        return xr.Dataset(data, coords=coords, attrs=attributes)


@dataclass(frozen=True, eq=False)
class FrictionSweep(NotebookDisplay):
    """Friction of the model over a list of loads (arrays of one value per load, SI)."""

    normal_force: np.ndarray
    friction: np.ndarray
    adhesive_friction: np.ndarray
    mechanical_friction: np.ndarray
    mu: np.ndarray
    separation: np.ndarray
    mechanical_springs: np.ndarray
    adhesive_springs: np.ndarray
    bonded_springs: np.ndarray

    FIGURE = "friction.plot_friction_vs_load"
    """The figure a notebook shows under the table of scalars (:mod:`roughcontact.display_html`)."""

    UNITS: ClassVar[dict[str, str]] = {
        "normal_force_min": "N",
        "normal_force_max": "N",
        "friction_min": "N",
        "friction_max": "N",
    }
    """SI units of the dimensional scalars."""

    _CURVE_UNITS: ClassVar[dict[str, str]] = {
        "friction": "N",
        "adhesive_friction": "N",
        "mechanical_friction": "N",
        "mu": "",
        "separation": "m",
        "mechanical_springs": "",
        "adhesive_springs": "",
        "bonded_springs": "",
    }

    def scalars(self) -> dict[str, float | int]:
        """Return the sweep's span: its points, the range of the loads, of friction and of mu."""
        return {
            "points": int(self.normal_force.size),
            "normal_force_min": float(np.min(self.normal_force)),
            "normal_force_max": float(np.max(self.normal_force)),
            "friction_min": float(np.min(self.friction)),
            "friction_max": float(np.max(self.friction)),
            "mu_min": float(np.min(self.mu)),
            "mu_max": float(np.max(self.mu)),
        }

    def to_xarray(self):
        """Return an ``xarray.Dataset`` indexed by ``normal_force`` [N]."""
        import xarray as xr

        data = {
            name: ("normal_force", getattr(self, name), {"units": unit})
            for name, unit in self._CURVE_UNITS.items()
        }
        return xr.Dataset(data, coords={"normal_force": ("normal_force", self.normal_force, {"units": "N"})})


@dataclass(frozen=True, eq=False)
class WinklerNormalCurve(NotebookDisplay):
    """Normal force of the Winkler-Lennard-Jones model against the flat's approach (SI, per approach).

    The approach is counted as :func:`roughcontact.contact.solve_adhesive` counts it: from the first
    touch of the undeformed composite surface (the highest spring at l = epsilon), i.e. minus the
    change of the separation d from its value there. The springs have no hysteresis: eq. 2 takes
    the attraction of eq. 7 at each spring's undeformed gap and the compression of the mechanical
    springs, so each spring feels only its own load, the force is one function of the approach,
    loading and unloading follow the same curve, and nothing jumps.

    Attributes
    ----------
    approach : ndarray
        The flat's approach [m] (negative: apart).
    force : ndarray
        Net normal force of eq. 2, sum P S - sum f S [N] (compressive positive).
    contact_area : ndarray
        Area of the springs in mechanical contact [m^2].
    interaction_area : ndarray
        Area of the adhesive springs whose attraction is at least
        :data:`~roughcontact.contact.interaction.INTERACTION_FRACTION` of the peak of eq. 7 [m^2]
        (the criterion of :class:`~roughcontact.contact.AdhesiveResult`).
    pull_off_force, pull_off_approach : float
        Most tensile force [N] (positive) and the approach where it acts [m], from
        :meth:`WinklerLJModel.pull_off_force`'s search.
    parameters : dict
        The model's constants (:meth:`WinklerLJModel.parameters`).
    """

    approach: np.ndarray
    force: np.ndarray
    contact_area: np.ndarray
    interaction_area: np.ndarray
    pull_off_force: float
    pull_off_approach: float
    parameters: dict = field(repr=False)

    UNITS: ClassVar[dict[str, str]] = {
        name: AdhesiveResult.UNITS[name]
        for name in (
            "pull_off_force",
            "pull_off_approach",
            "max_force",
            "max_approach",
            "max_contact_area",
            "work_of_adhesion",
        )
    } | {"epsilon": "m"}
    """The cycle's vocabulary is the adhesive BEM's (:attr:`AdhesiveResult.UNITS`), side by side."""

    def scalars(self) -> dict[str, Any]:
        """Return the headline numbers (SI), see ``UNITS``."""
        return {
            "pull_off_force": self.pull_off_force,
            "pull_off_approach": self.pull_off_approach,
            "max_force": float(self.force.max()),
            "max_approach": float(self.approach.max()),
            "max_contact_area": float(self.contact_area.max()),
            "work_of_adhesion": self.parameters["work_of_adhesion"],
            "epsilon": self.parameters["epsilon"],
        }

    def to_xarray(self):
        """Return the force, contact and interaction areas against the approach (dimension ``step``)."""
        import xarray as xr

        data = {
            "approach": ("step", self.approach, {"units": "m"}),
            "force": ("step", self.force, {"units": "N"}),
            "contact_area": ("step", self.contact_area, {"units": "m^2"}),
            "interaction_area": ("step", self.interaction_area, {"units": "m^2"}),
        }
        return xr.Dataset(data, attrs=self.scalars())
