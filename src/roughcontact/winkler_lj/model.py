r"""Winkler-layer + Lennard-Jones adhesive friction model of paper 000, equation by equation.

The two rough surfaces are merged into one composite surface z_i (paper 000, Fig. 1;
:func:`roughcontact.topography.process.combine`) that faces a rigid flat at distance d from its
base. Each pixel is a spring (a cuboid of top area S = pixel area and height h, the Winkler layer):

* eq. 1: composite modulus E (:func:`roughcontact.winkler_lj.springs.composite_modulus`);
* eqs. 3-4: spring stress P = E / (k h) dz, k from :func:`roughcontact.winkler_lj.springs.winkler_factor`;
* eqs. 5-7: attractive stress f(l) of the n = 2, m = 8 Lennard-Jones law
  (:mod:`roughcontact.contact.lennard_jones`), with dgamma from the surface energies;
* eq. 2: force balance sum P_i S - sum f(l_i) S = N for the separation d (default reading),
  solved by bracketing and :func:`scipy.optimize.brentq` on the apex overlap, with the heights
  sorted once and cumulative sums for the mechanical springs;
* eq. 8: extension dz_i = f(l_i) k h / E of the springs in strictly adhesive contact;
* eqs. 9-15: lateral force Q_i = sqrt(2 W_i / (H_i c)) that makes the shear work Q ds / 2 of a
  cuboid (height H_i, shear compliance ds = c Q H_i) equal to the energy W_i that breaks its
  adhesive bond (eq. 14 at l_ia = d - z_i - dz_i), for the springs bonded within the adhesive
  range (default: the Dugdale zone of eq. 7, l_ia <= 1.974 eps; ``readings.adhesive_range``);
* eqs. 16-17: the same for springs in mechanical contact, with the energy from the distance l_im
  where the repulsion of eq. 7 carries the spring's stress P_i;
* friction F = sum Q (adhesive part + mechanical part) and mu = F / N.

Every disputed reading is a field of :class:`~roughcontact.winkler_lj.readings.Readings`; the
derivations are in :doc:`/winkler_lj`. Hold time: pass ``relaxation`` (E(t), e.g. a
:class:`~roughcontact.winkler_lj.viscoelastic.PronySeries`) and ``hold_time``.

References
----------
Seed paper 000, "Simulation model for frictional contact of two elastic surfaces in micro/nanoscale
and its validation", eqs. 1-17.
K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, section 5.9 (elastic
foundation). doi:10.1017/CBO9781139171731.
J. A. Greenwood, Proc. R. Soc. Lond. A 453 (1997) 1277-1297. doi:10.1098/rspa.1997.0070.
L. A. Girifalco, R. J. Good, J. Phys. Chem. 61 (1957) 904-909. doi:10.1021/j150553a013.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize

from .._deprecation import renamed
from ..checks import positive
from ..contact import lennard_jones as lj
from ..errors import InputError
from ..materials import Material, check_material
from ..topography import Topography
from ..topography.process import combine
from ..topography.surface import topography_argument
from .bem import BEM_LOAD_RTOL, GAP_MODELS, bem_state_at_load
from .readings import Readings
from .results import FrictionSweep, WinklerLJResult, WinklerNormalCurve
from .springs import composite_modulus, winkler_factor
from .viscoelastic import material_after_hold

BALANCE_RTOL = 1e-9
"""Largest force-balance residual of eq. 2 (relative to its largest term) of a converged solve.

Brent's method brackets the apex overlap to a few ulps of the layer thickness, which leaves a
residual near round-off (~1e-15); above this the solve did not converge.
"""


def surface_energy_of(value: float | None, body: Material | None, field_name: str) -> float:
    """Return the surface energy [J/m^2] given, else the body's; refuse none and a non-positive one."""
    if value is None and body is not None:
        value = body.surface_energy
    if value is None:
        raise InputError(
            field_name,
            "no surface energy given" + (f" and {body.name!r} has none." if body is not None else "."),
            "give the body's surface energy (e.g. '50 mJ/m^2'; in Python SI, 0.05 J/m^2), "
            "or a material that has one.",
        )
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise InputError(
            field_name,
            f"{value!r} J/m^2 is not a positive surface energy.",
            "surface energies are positive: tens of mJ/m^2 for oxides and silicon (0.05 J/m^2 in SI).",
        )
    return value


def _tip_radius(value: float | None, tip: Topography | None, readings: Readings) -> float | None:
    """R of the half-sphere tip: ``value``, else the radius ``tip`` was generated with; None if unused."""
    if readings.base != "half_sphere":
        return None if value is None else positive(value, "tip_radius", example="1e-6", unit="m")
    if value is None and tip is not None:
        value = tip.info.get("radius")
    if value is None:
        raise InputError(
            "tip_radius",
            "readings.base='half_sphere' measures z_i and d from the base of the half-sphere tip, "
            "and no tip radius is known.",
            "give tip_radius (paper 000: 1e-6 m, a 2 um diameter tip) or a counter topography "
            "generated as a sphere.",
        )
    return positive(value, "tip_radius", example="1e-6", unit="m")


def _within_half_sphere(surface: Topography, tip: Topography | None, radius: float) -> np.ndarray:
    """Pixels under the half-sphere tip: within ``radius`` of its apex (the tip's highest point).

    Without a tip topography on the composite's grid the apex is the composite's highest point.
    """
    apex_heights = surface.heights if tip is None or tip.shape != surface.shape else tip.heights
    apex = np.unravel_index(int(np.argmax(apex_heights)), apex_heights.shape)
    squared = sum(
        ((np.arange(n) - a) * h).reshape([-1 if k == axis else 1 for k in range(surface.dim)]) ** 2
        for axis, (n, a, h) in enumerate(zip(surface.shape, apex, surface.spacing, strict=True))
    )
    return squared <= radius * radius


def work_of_adhesion(
    surface_energy_1: float, surface_energy_2: float, *, reading: str = "girifalco_good"
) -> float:
    r"""Work of adhesion dgamma of two surfaces [J/m^2] (paper 000, below equation 7).

    ``"girifalco_good"`` (default): dgamma = 2 sqrt(gamma1 gamma2), the dispersive
    (Berthelot / Girifalco-Good) estimate of gamma1 + gamma2 - gamma12, which gives 2 gamma for two
    identical surfaces. ``"printed"``: dgamma = sqrt(gamma1 gamma2), as printed (half of it).

    Parameters
    ----------
    surface_energy_1, surface_energy_2 : float
        Surface free energies [J/m^2].
    reading : {"girifalco_good", "printed"}
        See above.

    Returns
    -------
    float
        dgamma [J/m^2].

    References
    ----------
    L. A. Girifalco, R. J. Good, J. Phys. Chem. 61 (1957) 904-909. doi:10.1021/j150553a013.
    J. N. Israelachvili, *Intermolecular and Surface Forces*, 3rd ed., 2011, ch. 17.
    doi:10.1016/C2009-0-21560-1.
    """
    factor = 2.0 if reading == "girifalco_good" else 1.0
    return factor * math.sqrt(surface_energy_1 * surface_energy_2)


@dataclass(frozen=True, eq=False)
class WinklerLJModel:
    """A prepared surface and its constants; :meth:`~WinklerLJModel.solve` gives the friction at a load.

    Build it with :func:`winkler_lj_model`. The heights are sorted once, so repeated solves
    (load sweeps, crossover search) cost one pass over the adhesive springs per residual
    evaluation.
    """

    topography: Topography
    readings: Readings
    epsilon: float
    layer_thickness: float
    contact_modulus: float
    winkler_factor: float
    shear_modulus: float
    work_of_adhesion: float
    _depth: np.ndarray = field(repr=False)  # z_max - z, ascending
    _cumulative_depth: np.ndarray = field(repr=False)  # [0, d0, d0 + d1, ...]
    _compression_at_depth: np.ndarray = field(repr=False)  # j d_j - sum_{i<j} d_i, summed compression at d_j
    _rank: np.ndarray = field(repr=False)  # grid-shaped position of each pixel, sorted (n: not modelled)
    tip_radius: float | None = None  # R of the half-sphere tip (readings.base="half_sphere")
    gap_model: str = "winkler"  # gap field of the friction sums: "winkler" (eq. 2) or "bem"
    bem_boundary: str = "free"  # boundary of the boundary-element window (gap_model="bem")

    # --- constants --------------------------------------------------------------------------
    @property
    def spring_stiffness(self) -> float:
        """E / (k h): stress per unit compression of a spring (equation 3) [Pa/m]."""
        return self.contact_modulus / (self.winkler_factor * self.layer_thickness)

    @property
    def spring_area(self) -> float:
        """S, the top area of one cuboid (the pixel area) [m^2]."""
        return self.topography.pixel_area

    @property
    def adhesive_range(self) -> float:
        """Largest bond distance l_ia of a spring that adds adhesive friction [m] (inf: every spring).

        ``readings.adhesive_range="maugis_dugdale"``: eps (1 + 9 sqrt(3) / 16), the edge of the
        Dugdale zone of eq. 7 (:func:`~roughcontact.contact.lennard_jones.dugdale_range`);
        ``"all_springs"``: inf. ``readings.adhesive_cutoff`` (on the gap l_i) applies on top.
        """
        if self.readings.adhesive_range == "maugis_dugdale":
            return lj.dugdale_range(self.epsilon)
        return math.inf

    @property
    def base_depth(self) -> float:
        """Depth of the base, from which z_i and d are measured, below the highest point [m].

        ``readings.base="lowest_point"``: the lowest point of the composite surface;
        ``"half_sphere"``: the tip radius R (the equatorial plane of the half sphere of paper 000,
        section 3.1, whose apex is the highest point).
        """
        return self._depth[-1] if self.readings.base == "lowest_point" else self.tip_radius

    @property
    def _wall(self) -> float:
        return self.epsilon if self.readings.contact == "epsilon" else 0.0

    @property
    def _balance_area(self) -> float:
        return self.spring_area if self.readings.balance_terms == "forces" else 1.0

    @property
    def _adhesion_sign(self) -> float:
        return -1.0 if self.readings.adhesion_sign == "attractive" else 1.0

    # --- eq. 2 --------------------------------------------------------------------------------
    def _split(self, approach: float) -> tuple[int, int]:
        """Numbers of springs in mechanical contact and within the adhesive cutoff (sorted order)."""
        mechanical = int(np.searchsorted(self._depth, approach, side="right"))
        reach = self.readings.adhesive_cutoff - self._wall + approach
        within = self._depth.size
        if math.isfinite(reach):
            within = int(np.searchsorted(self._depth, reach, side="right"))
        if self.readings.base == "half_sphere":  # springs below the half sphere's base are not modelled
            within = min(within, int(np.searchsorted(self._depth, self.tip_radius, side="right")))
        return mechanical, max(within, mechanical)

    def _attraction(self, gap: np.ndarray) -> np.ndarray:
        stress = lj.attractive_stress(gap, self.work_of_adhesion, self.epsilon)
        return np.maximum(stress, 0.0) if self.readings.contact == "zero_gap" else stress

    def _terms(self, approach: float) -> tuple[float, float]:
        """Sum of spring stresses (eq. 3) and of attractive stresses (eq. 7) at an apex overlap [Pa]."""
        mechanical, within = self._split(approach)
        compression = mechanical * approach - self._cumulative_depth[mechanical]
        gap = self._depth[mechanical:within] + (self._wall - approach)
        return self.spring_stiffness * compression, float(self._attraction(gap).sum())

    def net_normal_force(self, approach: float) -> float:
        """Return the normal force that equation 2 balances at an apex overlap ``approach`` [m], N(approach).

        Parameters
        ----------
        approach : float
            Overlap of the highest point with the contact wall [m] (negative: apart).

        Returns
        -------
        float
            sum P S -/+ sum F S [N] (sign from ``readings.adhesion_sign``); negative = net tension.
        """
        mechanical, attraction = self._terms(approach)
        return self._balance_area * (mechanical + self._adhesion_sign * attraction)

    def load_capacity(self) -> float:
        """Largest load the layer carries: the highest spring compressed by the whole layer thickness [N]."""
        return self.net_normal_force(self.layer_thickness)

    def _solve_approach(self, load: float) -> tuple[float, int]:
        """Return the apex overlap that balances ``load`` (eq. 2) and the evaluations of eq. 2 it took."""
        evaluations = [0]

        def residual(approach: float) -> float:
            evaluations[0] += 1
            return self.net_normal_force(approach) - load

        high = self.layer_thickness
        if residual(high) < 0:
            raise InputError(
                "normal_force",
                f"{load:.4g} N is more than the layer carries ({self.load_capacity():.4g} N with the "
                f"highest spring compressed by the whole layer thickness {self.layer_thickness:.4g} m).",
                "lower the load, or check the layer thickness and the moduli (the linear Winkler layer "
                "is meaningless at such strains).",
            )
        tolerance = 4.0 * np.finfo(float).eps * self.layer_thickness
        rtol = 4.0 * np.finfo(float).eps
        bracket = self._local_bracket(residual, load)
        if bracket is not None:
            root = optimize.brentq(residual, *bracket, xtol=tolerance, rtol=rtol, maxiter=500)
            return root, evaluations[0]
        low = 0.0
        step = self.epsilon
        reach = 100.0 * max(self.topography.size)
        while residual(low) > 0:  # only when adhesion carries load (adhesion_sign="printed")
            low, step = low - step, 2.0 * step
            if -low > reach:
                raise InputError(
                    "normal_force",
                    f"adhesion alone carries {load:.4g} N with the flat more than {reach:.3g} m "
                    "(100 scan sizes) away: the surface never reaches the flat.",
                    "use adhesion_sign='attractive' (adhesion adds to the load) or a larger load.",
                )
        root = optimize.brentq(residual, low, high, xtol=tolerance, rtol=rtol, maxiter=500)
        return root, evaluations[0]

    def _overlap_for(self, force: float) -> float:
        """Apex overlap at which the springs alone carry ``force`` (inverse of the piecewise-linear sum)."""
        target = force / (self._balance_area * self.spring_stiffness)  # summed compression [m]
        count = max(int(np.searchsorted(self._compression_at_depth, target, side="left")), 1)
        return (target + self._cumulative_depth[count]) / count

    def _local_bracket(self, residual: Callable[[float], float], load: float) -> tuple[float, float] | None:
        """Bracket the root near the springs-only solution, corrected once for adhesion; None if not found.

        Two residual evaluations usually bracket the root within the change of the adhesive term,
        so Brent's method needs a few more instead of some twenty from [0, h].
        """
        first = self._overlap_for(load)
        first_residual = residual(first)  # the adhesive term at ``first``
        second = self._overlap_for(load - first_residual)
        second_residual = residual(second)
        if first_residual * second_residual <= 0:
            return (first, second) if first <= second else (second, first)
        step = max(abs(second - first), 1e-9 * self.epsilon)
        direction = 1.0 if second_residual < 0 else -1.0
        for _ in range(60):
            trial = second + direction * step
            if not 0.0 <= trial <= self.layer_thickness:
                return None
            if residual(trial) * second_residual <= 0:
                return (second, trial) if second <= trial else (trial, second)
            second, step = trial, 4.0 * step
        return None

    # --- eqs. 8-17 ----------------------------------------------------------------------------
    def _shear_compliance(self, cuboid_height: np.ndarray) -> float | np.ndarray:
        """Return ds / (Q H) [1/N]: 1 / (G S) for simple shear, 1 / (2 C G S) for eq. 12 (C from eq. 10)."""
        base = 1.0 / (self.shear_modulus * self.spring_area)
        if self.readings.shear == "simple_shear":
            return base
        tangent = cuboid_height / self.topography.spacing[0]
        return base * (tangent * tangent + 1.0) / (2.0 * tangent)

    def _lateral_force(self, energy: np.ndarray, height: np.ndarray, cuboid_height: np.ndarray) -> np.ndarray:
        """Q = sqrt(2 W / (H c)) from W = Q ds / 2 and ds = c Q H (eqs. 9, 12, 13, 15, 17) [N]."""
        work = energy * (self.spring_area if self.readings.energy_area == "times_area" else 1.0)
        return np.sqrt(2.0 * work / (height * self._shear_compliance(cuboid_height)))

    def solve(self, normal_force: float) -> WinklerLJResult:
        """Solve equation 2 for the separation at ``normal_force`` and return the friction (equations 8-17).

        With ``gap_model="bem"`` eq. 2 is replaced by the adhesive boundary-element solution
        (:func:`bem_state_at_load`: the elastic half-space under the same composite surface, E*
        and ``LennardJones(dgamma, epsilon)``, the state on the loading branch that carries the
        load within :data:`BEM_LOAD_RTOL`), and eqs. 8-17 take its fields: pixels in repulsion
        (g < 0) are the mechanical springs with P_i the BEM pressure; the others within
        ``readings.adhesive_cutoff`` are adhesive, with the bond distance l_ia = g + epsilon (the
        gap is already deformed: no eq. 8 extension is subtracted); the cuboid extension is
        dz_i = -p_i k h / E (eq. 8 for adhesive pixels, the compression for mechanical ones).
        Eq. 2's own readings (``balance_terms``, ``adhesion_sign``, ``contact``) have no role
        there; their non-default values are refused by :func:`winkler_lj_model`.

        Parameters
        ----------
        normal_force : float
            Normal load N [N], > 0 (mu = F / N needs a compressive load).

        Returns
        -------
        WinklerLJResult

        Raises
        ------
        InputError
            A load that is not positive and finite, or more than :meth:`load_capacity`.
        """
        load = float(normal_force)
        if not (math.isfinite(load) and load > 0):
            raise InputError(
                "normal_force",
                f"{load!r} N is not a positive finite load.",
                "give a compressive load > 0 (mu = F / N); use net_normal_force() for tensile states.",
            )
        if self.gap_model == "bem":
            return self._solve_bem(load)
        approach, evaluations = self._solve_approach(load)
        count, within = self._split(approach)  # sorted order: [0, count) mechanical, [count, within) adhesive
        n, depth = self._depth.size, self._depth
        stiffness, eps, gamma = self.spring_stiffness, self.epsilon, self.work_of_adhesion
        base = self.base_depth
        separation = base + self._wall - approach

        compression = approach - depth[:count]
        adhesive_gap = depth[count:within] + (self._wall - approach)
        attraction = self._attraction(adhesive_gap)
        extension = np.zeros(n)
        extension[:count] = -compression
        extension[count:within] = attraction / stiffness  # eq. 8

        # cuboid height (eqs. 10, 15) and the height in eq. 17, for the active springs [0, within)
        if self.readings.cuboid_height == "layer":
            cuboid = self.layer_thickness + extension[:within]
        else:
            cuboid = (base - depth[:within]) + extension[:within]
        height = cuboid.copy()
        if self.readings.mechanical_height == "printed_separation":
            height[:count] = separation

        # energies to break the bonds (eqs. 14, 16)
        energy = np.empty(within)
        bond_distance = adhesive_gap - extension[count:within]  # l_ia
        pulled_in = int(np.count_nonzero(bond_distance <= eps))
        bonded = bond_distance <= self.adhesive_range  # within the Dugdale zone (default) or all
        energy[count:] = np.where(
            bonded, lj.separation_energy(np.maximum(bond_distance, eps), gamma, eps), 0.0
        )
        stress_mech = stiffness * compression
        signed = lj.separation_energy(lj.repulsive_distance(stress_mech, gamma, eps), gamma, eps)  # e(l_im)
        if self.readings.mechanical_energy == "two_stage":
            energy[:count] = 2.0 * gamma - signed
            negative = 0
        else:
            energy[:count] = np.maximum(signed, 0.0)
            negative = int(np.count_nonzero(signed < 0))

        collapsed = int(np.count_nonzero((height <= 0) | (cuboid <= 0)))
        if collapsed:
            which = "cuboid_height" if np.any(cuboid <= 0) else "mechanical_height"
            raise InputError(
                f"readings.{which}",
                f"the printed height (z_i + dz_i from the lowest point, or d) is not positive "
                f"for {collapsed} springs at {load:.4g} N: they are compressed below the lowest point.",
                "use the default reading (the layer height h + dz_i) or a smaller load.",
            )
        lateral = np.zeros(n)
        lateral[:within] = self._lateral_force(energy, height, cuboid)
        stress = np.zeros(n)
        stress[:count] = stress_mech
        stress[count:within] = -attraction

        area = self._balance_area
        mechanical_force = area * float(stress_mech.sum())
        adhesive_force = area * float(attraction.sum())
        balance = mechanical_force + self._adhesion_sign * adhesive_force - load
        scale = max(mechanical_force, adhesive_force, load)
        mechanical_friction = float(lateral[:count].sum())
        adhesive_friction = float(lateral[count:within].sum())
        rank = self._rank
        bonded_sorted = np.zeros(n, dtype=bool)
        bonded_sorted[count:within] = bonded

        def to_grid(values: np.ndarray, outside: float = 0.0) -> np.ndarray:  # rank n: not modelled
            return np.append(values, outside)[rank]

        return WinklerLJResult(
            normal_force=load,
            separation=float(separation),
            approach=float(approach),
            mechanical=rank < count,
            adhesive=(rank >= count) & (rank < within),
            bonded=to_grid(bonded_sorted, False),
            gap=to_grid(depth + (self._wall - approach), math.inf),
            stress=to_grid(stress),
            extension=to_grid(extension),
            lateral_force=to_grid(lateral),
            mechanical_force=mechanical_force,
            adhesive_force=adhesive_force,
            adhesive_friction=adhesive_friction,
            mechanical_friction=mechanical_friction,
            residual=abs(balance) / scale,
            iterations=evaluations,
            tolerance=BALANCE_RTOL,
            max_strain=float(compression.max(initial=0.0) / self.layer_thickness),
            negative_energy_springs=negative,
            pulled_in_springs=pulled_in,
            parameters=self.parameters(),
            topography=self.topography,
        )

    def parameters(self) -> dict:
        """Return the model's constants and readings as a dictionary (SI)."""
        return {
            "contact_modulus": self.contact_modulus,
            "winkler_factor": self.winkler_factor,
            "shear_modulus": self.shear_modulus,
            "work_of_adhesion": self.work_of_adhesion,
            "spring_stiffness": self.spring_stiffness,
            "epsilon": self.epsilon,
            "layer_thickness": self.layer_thickness,
            "spring_area": self.spring_area,
            "readings": self.readings,
        }

    # --- sweeps -------------------------------------------------------------------------------
    def sweep(self, normal_forces: Sequence[float]) -> FrictionSweep:
        """Solve at each load and collect friction, its parts and mu.

        Parameters
        ----------
        normal_forces : sequence of float
            Normal loads [N], each > 0.

        Returns
        -------
        FrictionSweep
        """
        results = [self.solve(load) for load in normal_forces]

        def column(name: str) -> np.ndarray:
            return np.array([r.scalars()[name] for r in results])

        return FrictionSweep(
            normal_force=column("normal_force"),
            friction=column("friction"),
            adhesive_friction=column("adhesive_friction"),
            mechanical_friction=column("mechanical_friction"),
            mu=column("mu"),
            separation=column("separation"),
            mechanical_springs=column("mechanical_springs").astype(int),
            adhesive_springs=column("adhesive_springs").astype(int),
            bonded_springs=column("bonded_springs").astype(int),
        )

    def crossover_load(self, low: float | None = None, high: float | None = None) -> float | None:
        """Load at which mechanical friction overtakes adhesive friction [N], by root finding.

        Brent's method on log N of mechanical_friction - adhesive_friction. The difference jumps
        where a spring changes from adhesive to mechanical contact, so the root is located to
        within one such switch (relative tolerance 1e-9 on N otherwise).

        Parameters
        ----------
        low, high : float, optional
            Bracket [N]; default 1e-6 and 0.999 times :meth:`load_capacity`.

        Returns
        -------
        float or None
            The crossover load, or None when the sign of the difference does not change in the
            bracket (mechanical friction dominates already at ``low``, or never up to ``high``).

        Raises
        ------
        InputError
            When a printed reading refuses a state inside the bracket (see :meth:`solve`).
        """
        capacity = self.load_capacity()
        low = 1e-6 * capacity if low is None else float(low)
        high = 0.999 * capacity if high is None else float(high)

        def difference(log_load: float) -> float:
            result = self.solve(math.exp(log_load))
            return result.mechanical_friction - result.adhesive_friction

        a, b = math.log(low), math.log(high)
        if difference(a) > 0 or difference(b) < 0:
            return None
        return math.exp(optimize.brentq(difference, a, b, rtol=1e-9, xtol=1e-12))

    def pull_off_force(self) -> float:
        """Largest net tension the model sustains, max over the separation of -N [N].

        Scans the apex overlap over [-2 eps, eps] on 401 points and refines the best one with a
        bounded Brent search.

        Returns
        -------
        float
            Pull-off force [N] (> 0 when adhesion can hold the bodies together).
        """
        return -self._pull_off()[1]

    def _pull_off(self) -> tuple[float, float]:
        """Apex overlap [m] and net force [N] of the most tensile state (see :meth:`pull_off_force`)."""
        grid = np.linspace(-2.0 * self.epsilon, self.epsilon, 401)
        values = np.array([self.net_normal_force(a) for a in grid])
        best = int(np.argmin(values))
        step = grid[1] - grid[0]
        refined = optimize.minimize_scalar(
            self.net_normal_force,
            bounds=(grid[best] - step, grid[best] + step),
            method="bounded",
            options={"xatol": 1e-6 * step},
        )
        if refined.fun < values[best]:
            return float(refined.x), float(refined.fun)
        return float(grid[best]), float(values[best])

    # --- beside the adhesive boundary-element solution ------------------------------------------
    def _overlap_of(self, approach: float) -> float:
        """Apex overlap with the contact wall at an approach counted from l = epsilon at the apex."""
        return approach - self.epsilon + self._wall

    def normal_curve(self, approach: Sequence[float]) -> WinklerNormalCurve:
        """Return the normal force, contact and interaction areas (equation 2) over a programme of approaches.

        The approach is that of :func:`roughcontact.contact.solve_adhesive`: from the first touch
        of the undeformed composite surface (the highest spring at l = epsilon), so both models
        can be drawn on one axis. The springs have no hysteresis (each feels only its own load),
        so the order of the programme does not matter.

        Parameters
        ----------
        approach : sequence of float
            Approaches [m] (negative: apart).

        Returns
        -------
        WinklerNormalCurve
        """
        from ..contact.interaction import INTERACTION_FRACTION

        approach = np.atleast_1d(np.asarray(approach, dtype=float))
        threshold = INTERACTION_FRACTION * lj.PEAK_STRESS_FACTOR * self.work_of_adhesion / self.epsilon
        force, contact, interacting = [], [], []
        for value in approach:
            overlap = self._overlap_of(float(value))
            force.append(self.net_normal_force(overlap))
            mechanical, within = self._split(overlap)
            gap = self._depth[mechanical:within] + (self._wall - overlap)
            contact.append(mechanical * self.spring_area)
            interacting.append(np.count_nonzero(self._attraction(gap) >= threshold) * self.spring_area)
        overlap, pull = self._pull_off()
        return WinklerNormalCurve(
            approach=approach,
            force=np.array(force),
            contact_area=np.array(contact),
            interaction_area=np.array(interacting),
            pull_off_force=-pull,
            pull_off_approach=overlap + self.epsilon - self._wall,
            parameters=self.parameters(),
        )

    def _solve_bem(self, load: float) -> WinklerLJResult:
        """Eqs. 8-17 on the gap and pressure of the adhesive BEM at ``load`` (``gap_model="bem"``)."""
        from ..contact.interaction import LennardJones

        eps, gamma, stiffness = self.epsilon, self.work_of_adhesion, self.spring_stiffness
        law = LennardJones(gamma, eps)
        bem = bem_state_at_load(self.topography, self.contact_modulus, law, load, boundary=self.bem_boundary)
        pressure, bem_gap = (values.ravel() for values in bem.maps["end"])
        approach = float(bem.approach[-1])
        distance = bem_gap + eps  # l = g + eps: the deformed distance, the bond distance l_ia
        rank = self._rank.ravel()
        n = self._depth.size
        depth = np.full(rank.size, math.inf)
        depth[rank < n] = self._depth[rank[rank < n]]
        base = self.base_depth
        modelled = (rank < n) & (depth <= (base if self.readings.base == "half_sphere" else math.inf))
        mechanical = modelled & (bem_gap < 0.0)  # in repulsion, as the BEM counts its contact area
        adhesive = modelled & ~mechanical & (distance <= self.readings.adhesive_cutoff)
        separation = base + eps - approach
        extension = np.where(mechanical | adhesive, -pressure / stiffness, 0.0)  # eq. 8 at the BEM stress
        if self.readings.cuboid_height == "layer":
            cuboid = self.layer_thickness + extension
        else:
            cuboid = (base - depth) + extension
        height = cuboid.copy()
        if self.readings.mechanical_height == "printed_separation":
            height[mechanical] = separation
        bonded = adhesive & (distance <= self.adhesive_range)
        energy = np.zeros(rank.size)
        energy[bonded] = lj.separation_energy(np.maximum(distance[bonded], eps), gamma, eps)
        compression = np.maximum(pressure[mechanical], 0.0)
        signed = lj.separation_energy(lj.repulsive_distance(compression, gamma, eps), gamma, eps)
        if self.readings.mechanical_energy == "two_stage":
            energy[mechanical] = 2.0 * gamma - signed
            negative = 0
        else:
            energy[mechanical] = np.maximum(signed, 0.0)
            negative = int(np.count_nonzero(signed < 0))
        active = mechanical | bonded
        if np.any((height[active] <= 0) | (cuboid[active] <= 0)):
            raise InputError(
                "readings.cuboid_height",
                f"the printed height is not positive for some springs at {load:.4g} N.",
                "use the default reading (the layer height h + dz_i) or a smaller load.",
            )
        lateral = np.zeros(rank.size)
        lateral[active] = self._lateral_force(energy[active], height[active], cuboid[active])
        stress = np.where(mechanical | adhesive, pressure, 0.0)
        area = self.spring_area
        mechanical_force = area * float(compression.sum())
        adhesive_force = -area * float(pressure[adhesive].sum())
        mechanical_friction = float(lateral[mechanical].sum())
        adhesive_friction = float(lateral[adhesive].sum())
        shape = self.topography.shape
        return WinklerLJResult(
            normal_force=load,
            separation=float(separation),
            approach=approach,
            mechanical=mechanical.reshape(shape),
            adhesive=adhesive.reshape(shape),
            bonded=bonded.reshape(shape),
            gap=np.where(modelled, distance, math.inf).reshape(shape),
            stress=stress.reshape(shape),
            extension=extension.reshape(shape),
            lateral_force=lateral.reshape(shape),
            mechanical_force=mechanical_force,
            adhesive_force=adhesive_force,
            adhesive_friction=adhesive_friction,
            mechanical_friction=mechanical_friction,
            residual=abs(float(bem.force[-1]) - load) / load,
            iterations=int(np.sum(bem.iterations)),
            tolerance=BEM_LOAD_RTOL,
            max_strain=float(compression.max(initial=0.0) / stiffness / self.layer_thickness),
            negative_energy_springs=negative,
            pulled_in_springs=int(np.count_nonzero(adhesive & (distance <= eps))),
            parameters=self.parameters(),
            topography=self.topography,
            gap_model="bem",
            bem=bem,
        )


@renamed(counter="counter_body", counter_surface="counter_topography")
def winkler_lj_model(
    topography: Topography,
    material: Material,
    counter_body: Material | None = None,
    *,
    layer_thickness: float,
    counter_topography: Topography | None = None,
    epsilon: float = 2e-9,
    surface_energy: float | None = None,
    counter_surface_energy: float | None = None,
    readings: Readings | None = None,
    resample: bool = False,
    relaxation: Callable[[float], float] | None = None,
    hold_time: float = 0.0,
    tip_radius: float | None = None,
    gap_model: str = "winkler",
    bem_boundary: str = "free",
) -> WinklerLJModel:
    """Prepare the Winkler-Lennard-Jones model of a surface (or two merged surfaces) against a flat.

    Parameters
    ----------
    topography : Topography
        2D heights [m] of the rough surface (paper 000: the polysilicon scan).
    material : Material
        Body of ``topography`` (E1, nu1, gamma1).
    counter_body : Material, optional
        Counter-body (E2, nu2, gamma2); ``None`` is rigid (then ``counter_surface_energy`` is needed).
    layer_thickness : float
        Winkler layer height h [m] (paper 000: the thickness of the measured layer, 50 nm).
    counter_topography : Topography, optional
        Topography of the counter-body (paper 000: the AFM tip); merged with ``topography`` by
        :func:`roughcontact.topography.process.combine`.
    epsilon : float
        Equilibrium distance of eq. 7 [m] (paper 000: 2 nm), > 0.
    surface_energy, counter_surface_energy : float, optional
        gamma1, gamma2 [J/m^2]; default the materials' ``surface_energy``.
    readings : Readings, optional
        Readings of the disputed equations (default :class:`Readings()`).
    resample : bool
        Interpolate two topographies of different pixel sizes onto a common grid instead of
        refusing them.
    relaxation : callable, optional
        E(t) [Pa] of the surface material (hold time); e.g. a PronySeries.
    hold_time : float
        Time held in contact before sliding [s]; used with ``relaxation``.
    tip_radius : float, optional
        Radius R of the half-sphere tip [m], used only with ``readings.base="half_sphere"``;
        default the ``radius`` the counter topography was generated with
        (:func:`~roughcontact.topography.generate.sphere_with_roughness`).
    gap_model : {"winkler", "bem"}
        The gap field of the friction sums (eqs. 8-17): ``"winkler"`` (default, paper 000): the
        springs' l_i = d - z_i - dz_i from eq. 2; ``"bem"``: the adhesive boundary-element
        solution's gap and pressure at the same load (see :meth:`WinklerLJModel.solve`; each
        solve runs the boundary-element solver, seconds on 64^2).
    bem_boundary : {"free", "periodic"}
        Boundary of the boundary-element window with ``gap_model="bem"`` (default free).

    Returns
    -------
    WinklerLJModel

    Raises
    ------
    InputError
        A 1D or mismatched topography (without ``resample``), epsilon or layer thickness not
        positive, a missing, zero or negative surface energy, an invalid Poisson's ratio for eq. 4,
        ``readings.base="half_sphere"`` without a tip radius, an unknown ``gap_model`` or
        ``bem_boundary``, ``gap_model="bem"`` with a non-default reading of eq. 2.
    """
    topography = topography_argument(topography, "topography")
    readings = Readings() if readings is None else readings
    _check_gap_model(gap_model, bem_boundary, readings)
    tip_radius = _tip_radius(tip_radius, counter_topography, readings)
    check_material(material, "material")
    check_material(counter_body, "counter_body", rigid=True)
    if not isinstance(topography, Topography) or topography.dim != 2:
        raise InputError("topography", "expected a 2D Topography.", "pass a height map (nx, ny) in metres.")
    surface = topography
    if counter_topography is not None:
        try:
            surface = combine(topography, counter_topography, resample=resample)
        except InputError as error:
            raise InputError(
                "counter_topography",
                error.problem,
                "pass resample=True to interpolate both onto a common grid, "
                "or bring the scans to one grid first.",
            ) from error
    epsilon = positive(epsilon, "epsilon", example="2e-9", unit="m")
    layer_thickness = positive(layer_thickness, "layer_thickness", example="50e-9", unit="m")
    gamma_1 = surface_energy_of(surface_energy, material, "surface_energy")
    gamma_2 = surface_energy_of(counter_surface_energy, counter_body, "counter_surface_energy")
    if relaxation is not None:
        material = material_after_hold(material, relaxation, hold_time)
    nu_1 = material.poissons_ratio
    if counter_body is None:
        modulus = material.youngs_modulus / (1.0 - nu_1**2)
        nu_2 = nu_1
    else:
        nu_2 = counter_body.poissons_ratio
        modulus = composite_modulus(material.youngs_modulus, nu_1, counter_body.youngs_modulus, nu_2)
    k = winkler_factor(nu_1, nu_2, reading=readings.winkler_factor)
    if k <= 0:
        raise InputError(
            "poissons_ratio",
            f"eq. 4 gives k = {k:.3g} for nu = {nu_1}, {nu_2}: the springs would be rigid.",
            "the Winkler layer needs compressible materials (nu < 0.5).",
        )
    shear_nu = {"geometric": math.sqrt(nu_1 * nu_2), "surface": nu_1, "counter": nu_2}[readings.shear_poisson]
    modelled = np.arange(surface.heights.size)
    if readings.base == "half_sphere":
        modelled = np.flatnonzero(_within_half_sphere(surface, counter_topography, tip_radius))
    heights = surface.heights.ravel()[modelled]
    order = np.argsort(-heights, kind="stable")
    depth = heights.max() - heights[order]
    cumulative = np.concatenate(([0.0], np.cumsum(depth)))
    rank = np.full(surface.heights.size, depth.size, dtype=np.intp)
    rank[modelled[order]] = np.arange(depth.size)
    return WinklerLJModel(
        topography=surface,
        readings=readings,
        epsilon=epsilon,
        layer_thickness=layer_thickness,
        contact_modulus=modulus,
        winkler_factor=k,
        shear_modulus=modulus / (2.0 * (1.0 + shear_nu)),
        work_of_adhesion=work_of_adhesion(gamma_1, gamma_2, reading=readings.work_of_adhesion),
        _depth=depth,
        _cumulative_depth=cumulative,
        _compression_at_depth=np.arange(depth.size) * depth - cumulative[:-1],
        _rank=rank.reshape(surface.shape),
        tip_radius=tip_radius,
        gap_model=gap_model,
        bem_boundary=bem_boundary,
    )


def _check_gap_model(gap_model: str, boundary: str, readings: Readings) -> None:
    if gap_model not in GAP_MODELS:
        raise InputError("gap_model", f"unknown gap model {gap_model!r}.", f"use one of {list(GAP_MODELS)}.")
    if boundary not in ("free", "periodic"):
        raise InputError("bem_boundary", f"unknown boundary {boundary!r}.", "use 'free' or 'periodic'.")
    if gap_model == "bem":
        changed = {
            k: v for k, v in readings.changed().items() if k in ("balance_terms", "adhesion_sign", "contact")
        }
        if changed:
            raise InputError(
                "gap_model",
                f"gap_model='bem' replaces eq. 2 by the boundary-element solution, so the readings of "
                f"eq. 2 {changed} have no meaning there.",
                "leave balance_terms, adhesion_sign and contact at their defaults, "
                "or use gap_model='winkler'.",
            )


@renamed(counter="counter_body", load="normal_force")
def solve_winkler_lj(
    topography: Topography,
    material: Material,
    counter_body: Material | None = None,
    *,
    normal_force: float,
    layer_thickness: float,
    counter_topography: Topography | None = None,
    epsilon: float = 2e-9,
    surface_energy: float | None = None,
    counter_surface_energy: float | None = None,
    readings: Readings | None = None,
    resample: bool = False,
    relaxation: Callable[[float], float] | None = None,
    hold_time: float = 0.0,
    tip_radius: float | None = None,
    gap_model: str = "winkler",
    bem_boundary: str = "free",
) -> WinklerLJResult:
    """Friction of a surface against a flat at one normal load (paper 000).

    ``winkler_lj_model(...).solve(normal_force)``: the model's parameters are those of
    :func:`winkler_lj_model`, which documents them.

    Parameters
    ----------
    topography : Topography
        Rough surface [m].
    material, counter_body : Material
        The two bodies (``counter_body=None``: rigid flat).
    normal_force : float
        Normal load N [N], > 0.
    layer_thickness, counter_topography, epsilon, surface_energy, counter_surface_energy, readings,
    resample, relaxation, hold_time, tip_radius, gap_model, bem_boundary
        As in :func:`winkler_lj_model`.

    Returns
    -------
    WinklerLJResult
    """
    model = winkler_lj_model(
        topography,
        material,
        counter_body,
        layer_thickness=layer_thickness,
        counter_topography=counter_topography,
        epsilon=epsilon,
        surface_energy=surface_energy,
        counter_surface_energy=counter_surface_energy,
        readings=readings,
        resample=resample,
        relaxation=relaxation,
        hold_time=hold_time,
        tip_radius=tip_radius,
        gap_model=gap_model,
        bem_boundary=bem_boundary,
    )
    return model.solve(normal_force)
