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
derivations are in :doc:`/winkler_lj`. Hold time: give the options ``relaxation`` (E(t), e.g. a
:class:`~roughcontact.winkler_lj.viscoelastic.PronySeries`) and ``hold_time``. The model is built
from the two bodies and its :class:`~roughcontact.winkler_lj.options.WinklerLJOptions` by
:func:`~roughcontact.winkler_lj.prepare.winkler_lj_model` (:mod:`.prepare`).

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

from ..contact import lennard_jones as lj
from ..errors import InputError
from ..topography import Topography
from .bem import BEM_LOAD_RTOL, bem_state_at_load
from .readings import Readings
from .results import FrictionSweep, WinklerLJResult, WinklerNormalCurve

BALANCE_RTOL = 1e-9
"""Largest force-balance residual of eq. 2 (relative to its largest term) of a converged solve.

Brent's method brackets the apex overlap to a few ulps of the layer thickness, which leaves a
residual near round-off (~1e-15); above this the solve did not converge.
"""


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
