r"""Elastic-plastic contact with plasticity in the volume: J2 flow below a rough surface.

A rough body (a half-space, or paper 002's film on its substrate) is pressed by a rigid flat
through a programme of forces or approaches; the material below the surface yields by von Mises
(J2) plasticity with linear isotropic hardening. The plastic strain lives in a volume of
``layers`` cells below every pixel (:mod:`roughcontact.elasticity.eigenstrain`) and is kept from
step to step, so unloading follows a different path from loading, a residual interference remains
at zero load and the body keeps a residual stress (paper 002, Figs. 7-9).

Each step solves, for the plastic strain increment :math:`\Delta\varepsilon^p` of the step, the
fixed point of Jacq et al. (2002) and Frérot et al. (2019):

1. the elastic contact of the surface lowered by the residual displacement
   :math:`u^{res}(\varepsilon^p_n + \Delta\varepsilon^p)` gives the pressure p
   (:func:`roughcontact.contact._constrained_cg.solve`, force or approach control);
2. the trial stress of the step is :math:`\sigma^{tr} = \sigma(p)
   + \sigma^{res}(\varepsilon^p_n + \Delta\varepsilon^p) + C\Delta\varepsilon^p`,
   i.e. :math:`C(\varepsilon_{n+1} - \varepsilon^p_n)` with the total strain of the current iterate;
3. the radial return of :math:`\sigma^{tr}` from the state at the start of the step (yield
   strength :math:`\sigma_y + H\bar\varepsilon^p_n`) gives the next increment,
   :math:`\Delta\varepsilon^p = \tfrac32 \Delta\gamma\, s^{tr}/q^{tr}` with
   :math:`\Delta\gamma = \langle q^{tr} - \sigma_y - H\bar\varepsilon^p_n\rangle/(3\mu + H)`
   (Simo and Hughes 1998, box 3.2).

The iteration is accelerated by Anderson mixing (Walker and Ni 2011) and stops when the increment
changes by less than ``tolerance`` times the yield strain :math:`\sigma_y/E` everywhere; a step that
does not get there raises :class:`~roughcontact.errors.ConvergenceError`. Where nothing yields the
first iterate is the elastic solution, exactly.

Small strains throughout (no pile-up geometry, no large rotations); the plastic zone must stay
inside the discretised volume (checked: a yielded bottom layer is an error that names the depth to
give).

References
----------
Jacq, C., Nélias, D., Lormand, G. and Girodin, D. (2002). J. Tribol. 124, 653-667.
doi:10.1115/1.1467920
Frérot, L., Bonnet, M., Molinari, J.-F. and Anciaux, G. (2019). Comput. Methods Appl. Mech. Eng.
351, 951-976. doi:10.1016/j.cma.2019.04.006
Simo, J. C. and Hughes, T. J. R. (1998). Computational Inelasticity, sec. 3.3.
doi:10.1007/b98904
Walker, H. F. and Ni, P. (2011). Anderson acceleration for fixed-point iterations. SIAM J. Numer.
Anal. 49, 1715-1735. doi:10.1137/10078356X
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numba as nb
import numpy as np

from .._version import __version__
from ..display_html import NotebookDisplay
from ..elasticity import eigenstrain
from ..elasticity.halfspace import ElasticLayer
from ..elasticity.stress import StressField, subsurface_stress
from ..errors import ConvergenceError, InputError
from ..materials import Material
from ..messages import as_messages
from ..progress import tracked
from ..topography import Topography
from ..units import format_si
from . import _constrained_cg
from .normal import compliance_for

VOLUME_UNITS = {
    "peak_force": "N",
    "peak_interference": "m",
    "residual_interference": "m",
    "peak_contact_area": "m^2",
    "max_pressure": "Pa",
    "max_von_mises": "Pa",
    "max_residual_von_mises": "Pa",
    "max_plastic_strain": "",
    "plastic_dissipation": "J",
    "yield_strength": "Pa",
    "hardening_modulus": "Pa",
    "depth": "m",
}
"""SI units of the scalars of :class:`VolumePlasticResult`."""


@dataclass(frozen=True)
class J2Plasticity:
    """Von Mises plasticity with linear isotropic hardening (elastic-perfectly plastic when H = 0).

    Parameters
    ----------
    yield_strength : float
        Initial uniaxial yield strength sigma_y [Pa] (paper 002 Table I: SU-8 0.165 GPa).
    hardening_modulus : float
        Slope H of yield strength against equivalent plastic strain [Pa], >= 0.
    """

    yield_strength: float
    hardening_modulus: float = 0.0

    def check(self, material: Material) -> None:
        """Raise :class:`InputError` unless 0 < sigma_y < E and H >= 0 (``material`` is the plastic body)."""
        y, e = self.yield_strength, material.youngs_modulus
        if not (np.isfinite(y) and 0.0 < y < e):
            raise InputError(
                "yield_strength",
                f"must be positive and below the Young's modulus ({format_si(e, 'Pa')}), got {y!r} Pa.",
                "give the uniaxial yield strength in Pa, e.g. '165 MPa'.",
            )
        if not (np.isfinite(self.hardening_modulus) and self.hardening_modulus >= 0.0):
            raise InputError(
                "hardening_modulus",
                f"must be >= 0, got {self.hardening_modulus!r} Pa.",
                "give 0 for elastic-perfectly plastic, or the hardening slope in Pa.",
            )


@nb.njit(cache=True, nogil=True)
def _radial_return(trial, alpha, mu, yield_strength, hardening, increment, dgamma):
    """Radial return of every cell: write the plastic strain increment (6, n) and d(alpha) (n).

    ``trial`` holds the trial stresses (6, n) [Pa] (tensor components xx yy zz xy xz yz),
    ``alpha`` the equivalent plastic strain at the start of the step.
    """
    for i in range(alpha.size):
        mean = (trial[0, i] + trial[1, i] + trial[2, i]) / 3.0
        sxx, syy, szz = trial[0, i] - mean, trial[1, i] - mean, trial[2, i] - mean
        sxy, sxz, syz = trial[3, i], trial[4, i], trial[5, i]
        q = np.sqrt(1.5 * (sxx * sxx + syy * syy + szz * szz + 2.0 * (sxy * sxy + sxz * sxz + syz * syz)))
        excess = q - (yield_strength + hardening * alpha[i])
        if excess <= 0.0:
            dgamma[i] = 0.0
            for c in range(6):
                increment[c, i] = 0.0
            continue
        g = excess / (3.0 * mu + hardening)
        dgamma[i] = g
        scale = 1.5 * g / q
        increment[0, i] = scale * sxx
        increment[1, i] = scale * syy
        increment[2, i] = scale * szz
        increment[3, i] = scale * sxy
        increment[4, i] = scale * sxz
        increment[5, i] = scale * syz


def von_mises(stress: np.ndarray) -> np.ndarray:
    """Return the von Mises stress [Pa] of tensor components (6, ...)."""
    return StressField(np.zeros(1), stress, (1.0, 1.0)).von_mises()


class _Anderson:
    """Anderson mixing of a fixed point x = G(x) with ``memory`` past iterates (Walker and Ni 2011)."""

    def __init__(self, memory: int = 5):
        self.memory = memory
        self.previous = None  # (x, g) of the last call
        self.dg, self.df = [], []

    def reset(self) -> None:
        self.previous, self.dg, self.df = None, [], []

    def __call__(self, x: np.ndarray, g: np.ndarray) -> np.ndarray:
        f = g - x
        if self.previous is not None:
            x_old, g_old = self.previous
            self.dg.append(g - g_old)
            self.df.append(f - (g_old - x_old))
            if len(self.df) > self.memory:
                self.dg.pop(0)
                self.df.pop(0)
        self.previous = (x, g)
        if not self.df:
            return g
        # least squares min |f - DF gamma| by its normal equations (m x m; the vectors are long)
        gram = np.array([[a @ b for b in self.df] for a in self.df])
        gamma = np.linalg.lstsq(gram, np.array([a @ f for a in self.df]), rcond=1e-12)[0]
        step = g.copy()
        for weight, column in zip(gamma, self.dg, strict=True):
            step -= weight * column
        return step


@dataclass(frozen=True)
class VolumePlasticResult(NotebookDisplay):
    """A programme of elastic-plastic contact steps with plasticity in the volume (all SI).

    Attributes
    ----------
    topography : Topography
        The surface that was loaded.
    branch : ndarray of str
        "loading" or "unloading" per step.
    approach, force, contact_area : ndarray
        Per step: approach of the flat [m] from the first touch of the undeformed surface, normal
        force [N], real contact area [m^2].
    pressure, residual_displacement : ndarray
        Per step (steps, nx, ny): contact pressure [Pa] and the surface displacement [m] of the
        plastic strain (into the body positive) at that step.
    depths : ndarray
        Cell-centre depths [m] of the volume.
    von_mises, plastic_strain_equivalent : ndarray
        Per step (steps, layers, nx, ny), float32: von Mises stress [Pa] of the total stress and the
        accumulated equivalent plastic strain [-] at the cell centres.
    peak_stress, final_stress, plastic_strain : ndarray
        Stress tensors (6, layers, nx, ny) [Pa] at the peak step and the last step (at zero load:
        the residual stress), and the final plastic strain tensor [-] (order xx yy zz xy xz yz).
    dissipation : ndarray
        Plastic work of each step [J], sum of sigma : d(eps_p) dV.
    iterations, residuals : ndarray
        Fixed-point iterations and final residual of each step.
    contact_iterations : int
        Conjugate-gradient iterations of all the contact solves together.
    plasticity : J2Plasticity
    material : Material
        The plastic body (the film when ``substrate`` was given).
    tolerance : float
    parameters : dict
        What was asked for and the package version.
    """

    topography: Topography
    branch: np.ndarray
    approach: np.ndarray
    force: np.ndarray
    contact_area: np.ndarray
    pressure: np.ndarray
    residual_displacement: np.ndarray
    depths: np.ndarray
    von_mises: np.ndarray
    plastic_strain_equivalent: np.ndarray
    peak_stress: np.ndarray
    final_stress: np.ndarray
    plastic_strain: np.ndarray
    dissipation: np.ndarray
    iterations_per_step: np.ndarray
    residuals: np.ndarray
    contact_iterations: int
    plasticity: J2Plasticity
    material: Material
    tolerance: float
    parameters: dict = field(default_factory=dict)

    UNITS: ClassVar[dict[str, str]] = VOLUME_UNITS
    """SI unit of each dimensional scalar of :meth:`scalars`."""

    @property
    def peak(self) -> int:
        """Index of the step with the largest force."""
        return int(np.argmax(self.force))

    @property
    def converged(self) -> bool:
        """True: every step met its tolerance (the solver raises otherwise)."""
        return bool(np.all(self.residuals <= self.tolerance))

    @property
    def iterations(self) -> int:
        """Fixed-point iterations of all steps together."""
        return int(self.iterations_per_step.sum())

    @property
    def residual(self) -> float:
        """Largest final fixed-point residual of the steps (in units of the yield strain)."""
        return float(self.residuals.max())

    @property
    def residual_interference(self) -> float:
        """Approach [m] at which the surface, as the last step left it, first touches the flat."""
        heights = self.topography.heights
        return float(np.min(heights.max() - heights + self.residual_displacement[-1]))

    @as_messages
    def range_warnings(self, *, small_strain: float = 0.05, depth_margin: float = 0.75) -> list[str]:
        """Say where this solution leaves the range of its model (empty when it does not).

        * Equivalent plastic strain above ``small_strain``: the model is small-strain (no change
          of geometry, no pile-up, a rigid flat), so the plastic zone is qualitative there.
        * A plastic zone deeper than ``depth_margin`` of the volume: the solver stops only when
          the bottom layer yields, but the truncated volume already stiffens the cells above it.

        Parameters
        ----------
        small_strain : float
            Largest equivalent plastic strain that counts as small (default 5 %).
        depth_margin : float
            Fraction of the volume's depth the plastic zone may reach unremarked (default 0.75).
        """
        notes = []
        strain = float(self.plastic_strain_equivalent.max())
        if strain > small_strain:
            notes.append(
                f"largest equivalent plastic strain {strain:.2g} (over {small_strain:g}): beyond the "
                "small-strain volume model (no geometry change, no pile-up); read the plastic zone "
                "qualitatively, or lower the load."
            )
        yielded = np.flatnonzero(
            (self.plastic_strain_equivalent.max(axis=0) > 0).reshape(self.depths.size, -1).any(axis=1)
        )
        depth = self.scalars()["depth"]
        if yielded.size and self.depths[yielded[-1]] > depth_margin * depth:
            notes.append(
                f"the plastic zone reaches {format_si(float(self.depths[yielded[-1]]), 'm')} of the "
                f"{format_si(depth, 'm')} volume: check with a deeper one, e.g. depth = "
                f"'{format_si(2 * depth, 'm')}' (and twice the layers)."
            )
        return notes

    def curve(self) -> dict[str, np.ndarray]:
        """Return the path, one entry per step (branch, approach, force, contact area, peak stresses)."""
        return {
            "branch": self.branch,
            "approach": self.approach,
            "force": self.force,
            "contact_area": self.contact_area,
            "max_pressure": self.pressure.reshape(len(self.force), -1).max(axis=1),
            "max_von_mises": self.von_mises.reshape(len(self.force), -1).max(axis=1).astype(float),
            "dissipation": np.cumsum(self.dissipation),
        }

    def scalars(self) -> dict[str, float]:
        """Return the peak and residual interference, stresses and dissipation (SI; :attr:`UNITS`)."""
        peak = self.peak
        return {
            "peak_force": float(self.force[peak]),
            "peak_interference": float(self.approach[peak]),
            "residual_interference": self.residual_interference,
            "peak_contact_area": float(self.contact_area[peak]),
            "max_pressure": float(self.pressure.max()),
            "max_von_mises": float(self.von_mises.max()),
            "max_residual_von_mises": float(von_mises(self.final_stress).max()),
            "max_plastic_strain": float(self.plastic_strain_equivalent[-1].max()),
            "plastic_dissipation": float(self.dissipation.sum()),
            "yield_strength": self.plasticity.yield_strength,
            "hardening_modulus": self.plasticity.hardening_modulus,
            "depth": float(self.depths[-1] + 0.5 * (self.depths[-1] - self.depths[-2]))
            if self.depths.size > 1
            else float(2 * self.depths[0]),
            "iterations": self.iterations,
            "residual": self.residual,
        }

    def to_xarray(self):
        """Return the curve as an ``xarray.Dataset`` on the dimension ``point`` (SI, with units)."""
        import xarray as xr

        units = {
            "approach": "m",
            "force": "N",
            "contact_area": "m^2",
            "max_pressure": "Pa",
            "max_von_mises": "Pa",
            "dissipation": "J",
        }
        curve = self.curve()
        data = {"branch": ("point", np.asarray(curve.pop("branch")).astype(str))}
        for name, values in curve.items():
            data[name] = ("point", np.asarray(values, dtype=float), {"units": units[name]})
        return xr.Dataset(data, attrs=self.scalars())


class _Body:
    """The plastic body's operators: surface compliance, eigenstrain operator, pressure stress."""

    def __init__(
        self, topography, material, plasticity, *, depth, layers, substrate, film_thickness, boundary
    ):
        self.material = material
        layer = None
        if substrate is not None:
            layer = ElasticLayer(film_thickness, material, base=substrate)
        self.compliance = compliance_for(
            topography, None if layer else material, layer=layer, boundary=boundary
        )
        self.boundary = self.compliance.boundary
        self.column = eigenstrain.column(
            depth, layers, material, film_thickness=film_thickness, substrate=substrate
        )
        self.operator = eigenstrain.EigenstrainOperator(
            topography.shape, topography.size, self.column, boundary=self.boundary
        )
        self.layer = layer
        self.shape = topography.shape
        self.size = topography.size

    def pressure_stress(self, pressure: np.ndarray) -> np.ndarray:
        """Stress (6, layers, nx, ny) [Pa] of the pressure alone at the cell centres (exact in depth)."""
        return subsurface_stress(
            pressure,
            self.size,
            self.column.centres,
            poissons_ratio=self.material.poissons_ratio,
            boundary=self.boundary,
            layer=self.layer,
        ).components


def solve_elastic_plastic(
    topography: Topography,
    material: Material,
    *,
    forces=None,
    approaches=None,
    yield_strength: float | None = None,
    hardening_modulus: float = 0.0,
    depth: float,
    layers: int = 16,
    substrate: Material | None = None,
    film_thickness: float | None = None,
    boundary: str | None = None,
    tolerance: float = 1e-6,
    contact_tolerance: float = 1e-10,
    max_iterations: int = 200,
    branch=None,
) -> VolumePlasticResult:
    """Solve a programme of contact steps with J2 plasticity in the volume (module docstring).

    Parameters
    ----------
    topography : Topography
        Surface [m], heights towards the rigid flat.
    material : Material
        The plastic body (with ``substrate``: the film). Its ``yield_strength`` is used unless
        ``yield_strength`` is given.
    forces, approaches : array_like
        Exactly one: the programme of normal forces [N] (load control) or approaches [m] from the
        first touch of the undeformed surface (approach control), one per step, in order.
    yield_strength : float, optional
        Initial yield strength sigma_y [Pa].
    hardening_modulus : float
        Linear isotropic hardening slope H [Pa] (0: elastic-perfectly plastic).
    depth : float
        Depth [m] of the discretised volume (the plastic zone must stay inside it).
    layers : int
        Cells through the depth (equal thickness).
    substrate : Material, optional
        The elastic substrate that a film of ``film_thickness`` [m] of ``material`` is bonded to.
    boundary : {"periodic", "free"}, optional
        Default: the topography's periodic flag.
    tolerance : float
        Largest change of the plastic strain increment between iterates, in units of the yield
        strain sigma_y / E, at convergence.
    contact_tolerance : float
        Tolerance of each elastic contact solve.
    max_iterations : int
        Fixed-point iterations per step before :class:`ConvergenceError`.
    branch : sequence of str, optional
        Label of each step ("loading"/"unloading"); default from the sign of the force change.

    Returns
    -------
    VolumePlasticResult

    Raises
    ------
    InputError
        Not exactly one programme, NaN or negative targets, bad plastic constants, a plastic zone
        that reaches the bottom of the volume (with the depth to give instead).
    ConvergenceError
        A step did not converge (residual and iterations reported).
    """
    yield_strength = material.yield_strength if yield_strength is None else yield_strength
    if yield_strength is None:
        raise InputError(
            "yield_strength", "no yield strength given and the material has none.", "pass e.g. '165 MPa'."
        )
    plasticity = J2Plasticity(float(yield_strength), float(hardening_modulus))
    plasticity.check(material)
    kind, targets = _programme(forces, approaches)
    body = _Body(
        topography,
        material,
        plasticity,
        depth=depth,
        layers=layers,
        substrate=substrate,
        film_thickness=film_thickness,
        boundary=boundary,
    )
    lam, mu = eigenstrain.lame(material)
    cells = body.column.cells
    shape = (6, cells) + topography.shape
    heights = topography.heights
    separation = heights.max() - heights
    pixel_area = topography.pixel_area
    volume = body.column.thickness[:, None, None] * pixel_area
    yield_strain = plasticity.yield_strength / material.youngs_modulus

    strain = np.zeros(shape)  # plastic strain at the start of the step
    alpha = np.zeros(shape[1:])  # equivalent plastic strain
    residual_stress, lift = body.operator(strain)
    pressure = None
    record = {k: [] for k in ("approach", "force", "area", "p", "u", "vm", "eq", "w", "it", "res")}
    peak_stress, peak_force = None, -np.inf
    contact_iterations = 0
    anderson = _Anderson()
    increment = np.empty((6, alpha.size))
    dgamma = np.empty(alpha.size)
    for target in tracked(targets, what="elastic-plastic steps"):
        x = np.zeros(shape)
        current_stress, current_lift = residual_stress, lift
        anderson.reset()
        for iteration in range(1, max_iterations + 1):  # noqa: B007 (recorded below)
            contact = _contact(
                body.compliance,
                separation + current_lift,
                kind,
                target,
                pixel_area,
                pressure,
                contact_tolerance,
            )
            contact_iterations += contact.iterations
            pressure = contact.pressure
            trial = (
                body.pressure_stress(pressure) + current_stress + eigenstrain.isotropic_stress(x, material)
            )
            _radial_return(
                trial.reshape(6, -1),
                alpha.ravel(),
                mu,
                plasticity.yield_strength,
                plasticity.hardening_modulus,
                increment,
                dgamma,
            )
            g = increment.reshape(shape).copy()
            change = float(np.max(np.abs(g - x))) / yield_strain
            if change <= tolerance:
                break
            x = anderson(x.ravel(), g.ravel()).reshape(shape)
            current_stress, current_lift = body.operator(strain + x)
        else:
            raise ConvergenceError("solve_elastic_plastic", change, max_iterations, tolerance)
        stress = trial - eigenstrain.isotropic_stress(g, material)
        yielded = dgamma.reshape(alpha.shape) > 0
        if yielded[-1].any():
            unit = "N" if kind == "force" else "m"
            raise InputError(
                "depth",
                f"the plastic zone reaches the bottom layer of the volume ({format_si(depth, 'm')}) at "
                f"step {len(record['force']) + 1} ({kind} {format_si(target, unit)}); "
                f"{len(record['force'])} step(s) had converged"
                + (f", up to {format_si(max(record['force']), 'N')}." if record["force"] else "."),
                f"give a deeper volume, e.g. «depth={format_si(2 * depth, 'm')}» (and twice the «layers» to "
                "keep the cells).",
            )
        strain = strain + g
        dissipation = float(np.sum(_contract(stress, g) * volume))
        alpha = alpha + dgamma.reshape(alpha.shape)
        residual_stress, lift = body.operator(strain)
        force = float(pressure.sum() * pixel_area)
        record["approach"].append(contact.approach)
        record["force"].append(force)
        record["area"].append(float(np.count_nonzero(pressure > 0) * pixel_area))
        record["p"].append(pressure)
        record["u"].append(lift)
        record["vm"].append(von_mises(stress).astype(np.float32))
        record["eq"].append(alpha.astype(np.float32))
        record["w"].append(dissipation)
        record["it"].append(iteration)
        record["res"].append(change)
        if force > peak_force:
            peak_force, peak_stress = force, stress.astype(np.float32)
    forces_done = np.array(record["force"])
    if branch is None:
        branch = np.where(np.arange(forces_done.size) <= int(np.argmax(forces_done)), "loading", "unloading")
    return VolumePlasticResult(
        topography=topography,
        branch=np.asarray(branch),
        approach=np.array(record["approach"]),
        force=forces_done,
        contact_area=np.array(record["area"]),
        pressure=np.array(record["p"]),
        residual_displacement=np.array(record["u"]),
        depths=body.column.centres,
        von_mises=np.array(record["vm"]),
        plastic_strain_equivalent=np.array(record["eq"]),
        peak_stress=peak_stress,
        final_stress=stress.astype(np.float32),
        plastic_strain=strain,
        dissipation=np.array(record["w"]),
        iterations_per_step=np.array(record["it"]),
        residuals=np.array(record["res"]),
        contact_iterations=contact_iterations,
        plasticity=plasticity,
        material=material,
        tolerance=tolerance,
        parameters={
            kind: list(map(float, targets)),
            "depth": float(depth),
            "layers": int(layers),
            "boundary": body.boundary,
            "version": __version__,
        },
    )


def _contract(stress: np.ndarray, strain: np.ndarray) -> np.ndarray:
    """Return sigma : eps for tensor components (6, ...) (shear components counted twice)."""
    return np.sum(stress[:3] * strain[:3], axis=0) + 2.0 * np.sum(stress[3:] * strain[3:], axis=0)


def _programme(forces, approaches) -> tuple[str, np.ndarray]:
    if (forces is None) == (approaches is None):
        raise InputError("forces", "give exactly one of forces and approaches.", "e.g. forces=[1e-4, 2e-4].")
    kind, values = ("force", forces) if forces is not None else ("approach", approaches)
    values = np.atleast_1d(np.asarray(values, dtype=float))
    if values.size == 0 or not np.all(np.isfinite(values)) or np.any(values < 0):
        raise InputError(
            kind + "s",
            f"must be finite and >= 0, got {values.tolist()!r}.",
            "give one non-negative value per step.",
        )
    return kind, values


@dataclass(frozen=True)
class _Contact:
    pressure: np.ndarray
    approach: float
    iterations: int


def _contact(compliance, separation, kind, target, pixel_area, initial, tolerance) -> _Contact:
    """Elastic contact of ``separation`` [m] (any offset) at a force or approach from its zero."""
    offset = float(separation.min())
    shifted = separation - offset
    if kind == "force" and target == 0.0:
        return _Contact(np.zeros_like(separation), offset, 0)
    if kind == "approach" and target <= offset:
        return _Contact(np.zeros_like(separation), float(target), 0)
    options = dict(
        pixel_area=pixel_area, initial_pressure=initial, tolerance=tolerance, solver="elastic-plastic contact"
    )
    if kind == "force":
        raw = _constrained_cg.solve(compliance, shifted, force=float(target), **options)
    else:
        raw = _constrained_cg.solve(compliance, shifted, approach=float(target) - offset, **options)
    return _Contact(raw.pressure.reshape(separation.shape), raw.approach + offset, raw.iterations)
