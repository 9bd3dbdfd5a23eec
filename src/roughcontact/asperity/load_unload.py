r"""Statistical elastic-plastic load-unload of a rough surface against a flat (Kadin, Kligerman and Etsion).

The summits of a :class:`~roughcontact.asperity.greenwood_williamson.SummitDistribution` are loaded
by a rigid flat approaching to a minimum separation d_min and then withdrawn. On loading each
summit of height z carries the single-asperity load P(omega) of the chosen law at omega = z - d.
Each summit remembers its maximum interference omega_max = z - d_min; on unloading it follows
paper 002 eq. 11,

.. math:: P = P(\omega_{max})\left(\frac{\omega - \omega_{res}}{\omega_{max} - \omega_{res}}\right)^{n},
          \qquad n = 1.5\,(\omega^*_{max})^{-0.0331},

with omega_res(omega_max) of Etsion, Kligerman and Kadin (2005), and its contact area falls from
the loading law's area at omega_max as

.. math:: A = A(\omega_{max})\left(\frac{\omega - \omega_{res}}{\omega_{max} - \omega_{res}}\right)^{m_A},
          \qquad m_A = (\omega^*_{max})^{-0.12}

(:func:`~roughcontact.asperity.elastic_plastic.unloading_area`; the coefficient is recalled, not
verified against the papers' text). Summing over the population on the nominal area A_n gives the
load-interference curves of both branches, the real contact area on both, the number of contacts
and the fraction of plastically deformed summits (omega_max > omega_c) among those touching. A
summit's area and load vanish together at its omega_res. Summits that stay below omega_c unload on
their Hertz curve (A = pi R omega), so a purely elastic population unloads along its loading curve.

The Gaussian has no highest summit, so both branches run between the peak and a small floor load:
``reference_force`` where given (paper 002 marks omega = 0 at W = 25 uN, the smallest load its
nanoindenter resolves, so the curves span what the experiment sees), else ``threshold`` times the
peak. Approaches are measured from the separation at which the loading branch carries
``reference_force``, or from the summits' mean plane (approach = -d) without one. The unloading
branch ends where it falls back to the floor load, the *return force*; the interference there is
``interference_at_return_force`` (paper 002: at 25 uN). It is not a residual interference at zero
load: the Gaussian population's load vanishes only asymptotically, so the model has none at finite
separation (without ``reference_force`` the return force is 1e-6 of the peak, and the two nearly
coincide). The deterministic load-unload
(:class:`~roughcontact.contact.load_unload.LoadUnloadResult`) reports both: its
``residual_interference`` at zero load and its own ``interference_at_return_force``, the one to
compare with this model's.

References
----------
.. [KKE] Y. Kadin, Y. Kligerman and I. Etsion, "Unloading an elastic-plastic contact of rough
   surfaces", J. Mech. Phys. Solids 54 (2006) 2652-2674. doi:10.1016/j.jmps.2006.07.005
.. [EKK] I. Etsion, Y. Kligerman and Y. Kadin, Int. J. Solids Struct. 42 (2005) 3716-3729.
   doi:10.1016/j.ijsolstr.2004.12.006
.. [P002] Seed paper 002, section V and Fig. 7.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import optimize

from ..checks import positive
from ..display_html import NotebookDisplay
from ..errors import InputError
from . import elastic_plastic as ep
from .greenwood_williamson import SummitDistribution

LOADING_LAWS = ("kogut_etsion", "paper002_eq10", "jackson_green", "hertz")
LAW_NAMES = {
    "kogut_etsion": "Kogut-Etsion",
    "paper002_eq10": "paper 002 eq. 10",
    "jackson_green": "Jackson-Green",
    "hertz": "Hertz",
}
"""Each loading law in a reader's words (legends and reports)."""
_NEGLIGIBLE = 1e-9  # probability of summits beyond the fits' range that may be left out


@dataclass(frozen=True)
class StatisticalLoadUnload(NotebookDisplay):
    """Load-unload curves of a statistical asperity model (SI).

    Attributes
    ----------
    branch : ndarray of str
        "loading" or "unloading" per point.
    separation : ndarray
        d from the summits' mean plane [m].
    approach : ndarray
        Interference of the surface [m], from the reference (see module notes).
    force : ndarray
        Load [N].
    contact_area : ndarray
        Real contact area [m^2], on both branches (unloading: the summed
        :func:`~roughcontact.asperity.elastic_plastic.unloading_area`); equal to the loading area at
        the peak and vanishing with the load.
    number_of_contacts : ndarray
        Summits in contact [-].
    plastic_fraction : ndarray
        Fraction of the touching summits that were loaded beyond omega_c [-].
    interference_at_return_force : float
        Interference [m] at which the unloading branch falls back to ``return_force`` (module
        notes; formerly ``residual_interference``, a name that now means the interference at zero
        load only, which this model does not reach).
    return_force : float
        The floor load where both branches end [N]: ``reference_force`` (paper 002: 25 uN), or
        ``threshold`` x the peak without one.
    critical_interference : float
        omega_c [m] (Chang-Etsion-Bogy, from the hardness).
    critical_load : float
        P_c [N], the Hertz load at omega_c.
    law : str
        The loading law.
    """

    branch: np.ndarray
    separation: np.ndarray
    approach: np.ndarray
    force: np.ndarray
    contact_area: np.ndarray
    number_of_contacts: np.ndarray
    plastic_fraction: np.ndarray
    interference_at_return_force: float
    return_force: float
    critical_interference: float
    critical_load: float
    law: str

    @property
    def peak(self) -> int:
        """Index of the peak load: the last point of the loading branch."""
        return int(np.flatnonzero(self.branch == "loading")[-1])

    @property
    def residual_interference(self) -> float:
        """The former name of :attr:`interference_at_return_force` (kept one release, with a warning).

        It was the interference at the return force (25 uN in paper 002), not at zero load; the name
        ``residual_interference`` now means the latter only (the deterministic model's).
        """
        warnings.warn(
            "StatisticalLoadUnload.residual_interference is now .interference_at_return_force (the "
            "interference where unloading returns to the floor load, not at zero load); the old name "
            "goes in the next release.",
            DeprecationWarning,
            stacklevel=2,
        )
        return self.interference_at_return_force

    UNITS: ClassVar[dict[str, str]] = {
        "peak_force": "N",
        "peak_interference": "m",
        "interference_at_return_force": "m",
        "return_force": "N",
        "peak_contact_area": "m^2",
        "critical_interference": "m",
        "critical_load": "N",
    }
    """SI unit of each dimensional scalar of :meth:`scalars`."""

    CURVE_UNITS: ClassVar[dict[str, tuple[str, str]]] = {
        "approach": ("m", "interference, zero at reference_force on loading"),
        "interference_ratio": ("", "interference over omega_c"),
        "separation": ("m", "flat to the summits' mean plane"),
        "force": ("N", "load"),
        "contact_area": ("m^2", "real contact area"),
        "number_of_contacts": ("", "summits in contact"),
        "plastic_fraction": ("", "fraction of the touching summits loaded beyond omega_c"),
    }
    """Unit and meaning of each variable of :meth:`curve` and :meth:`to_xarray`."""

    def scalars(self) -> dict[str, float | str]:
        """Return the peak, the interference at the return force and the scales (SI; :attr:`UNITS`)."""
        peak = self.peak
        return {
            "law": self.law,
            "peak_force": float(self.force[peak]),
            "peak_interference": float(self.approach[peak]),
            "interference_at_return_force": self.interference_at_return_force,
            "return_force": self.return_force,
            "peak_contact_area": float(self.contact_area[peak]),
            "peak_number_of_contacts": float(self.number_of_contacts[peak]),
            "plastic_fraction_at_peak": float(self.plastic_fraction[peak]),
            "critical_interference": self.critical_interference,
            "critical_load": self.critical_load,
        }

    def to_xarray(self):
        """Return the curve as an ``xarray.Dataset`` on the dimension ``point`` (SI, with units)."""
        import xarray as xr

        curve = self.curve()
        data = {"branch": ("point", np.asarray(curve["branch"]).astype(str))}
        for name, (unit, meaning) in self.CURVE_UNITS.items():
            values = np.asarray(curve[name], dtype=float)
            data[name] = ("point", values, {"units": unit, "long_name": meaning})
        attributes = {"law": self.law, "critical_interference": self.critical_interference}
        return xr.Dataset(data, attrs=attributes)

    def curve(self) -> dict[str, np.ndarray]:
        """Return the curve as a dict (the keys of ``LoadUnloadResult.curve()`` plus more), SI."""
        return {
            "branch": self.branch,
            "approach": self.approach,
            "interference_ratio": self.approach / self.critical_interference,
            "separation": self.separation,
            "force": self.force,
            "contact_area": self.contact_area,
            "number_of_contacts": self.number_of_contacts,
            "plastic_fraction": self.plastic_fraction,
        }


@dataclass(frozen=True)
class _Population:
    distribution: SummitDistribution
    count: float  # summits on the nominal area
    omega_c: float
    load_c: float
    law: str
    contact_modulus: float
    jg: dict

    def _loading(self, omega: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Load [N] and area [m^2] of summits at interferences ``omega`` (>= 0) on the loading law."""
        radius = self.distribution.summit_radius
        w = omega / self.omega_c
        if self.law == "hertz":
            return 4.0 / 3.0 * self.contact_modulus * math.sqrt(radius) * omega**1.5, math.pi * radius * omega
        if self.law == "jackson_green":
            omega_jg = ep.jackson_green_critical_interference(**self.jg, radius=radius)
            w_jg = omega / omega_jg
            load_jg = 4.0 / 3.0 * self.contact_modulus * math.sqrt(radius) * omega_jg**1.5
            exponent_b = 0.14 * math.exp(23.0 * self.jg["yield_strength"] / self.contact_modulus)
            area = math.pi * radius * omega * np.maximum(w_jg / 1.9, 1.0) ** exponent_b
            return load_jg * ep.jackson_green_load(w_jg, radius=radius, **self.jg), area
        area = math.pi * radius * self.omega_c * ep.kogut_etsion_area(w)
        if self.law == "kogut_etsion":
            return self.load_c * ep.kogut_etsion_load(w), area
        return ep.paper002_eq10_load(w, critical_load=self.load_c), area

    def _touching(self, separation: float) -> tuple[np.ndarray, np.ndarray]:
        """Return indices and interferences of the summits in contact, without a negligible far tail."""
        omega = self.distribution.heights - separation
        inside = (omega > 0) & (omega <= ep.KOGUT_ETSION_MAX * self.omega_c)
        beyond = omega > ep.KOGUT_ETSION_MAX * self.omega_c
        if self.distribution.weights[beyond].sum() > _NEGLIGIBLE:
            raise InputError(
                "max_force",
                f"the load drives summits beyond omega* = {ep.KOGUT_ETSION_MAX:g} (probability "
                f"{self.distribution.weights[beyond].sum():.2g}), outside the fits of Kogut-Etsion and "
                "Etsion-Kligerman-Kadin.",
                "lower the peak load (or check hardness and moduli: psi = sqrt(sigma_s/omega_c) is large).",
            )
        return np.flatnonzero(inside), omega[inside]

    def loading(self, separation: float) -> tuple[float, float, float, float]:
        """Return force [N], area [m^2], contacts and plastic fraction at ``separation`` on loading."""
        index, omega = self._touching(separation)
        weights = self.distribution.weights[index]
        load, area = self._loading(omega)
        touching = weights.sum()
        yielded = omega > self.omega_c if self.law != "hertz" else np.zeros(omega.shape, dtype=bool)
        plastic = weights[yielded].sum() / touching if touching > 0 else 0.0
        return self.count * (weights @ load), self.count * (weights @ area), self.count * touching, plastic

    def unloading(self, separation: float, lowest: float) -> tuple[float, float, float, float]:
        """Return force [N], area [m^2], contacts and plastic fraction at ``separation`` after ``lowest``."""
        index, omega_max = self._touching(lowest)
        weights = self.distribution.weights[index]
        max_load, max_area = self._loading(omega_max)
        # Hertz summits never yield: they unload on their loading curve.
        w_max = omega_max / self.omega_c if self.law != "hertz" else np.zeros_like(omega_max)
        residual = ep.residual_interference_ratio(w_max) * omega_max
        omega = self.distribution.heights[index] - separation
        stretch = np.clip((omega - residual) / (omega_max - residual), 0.0, 1.0)
        load = max_load * stretch ** ep.unloading_exponent(w_max)
        area = max_area * stretch ** ep.unloading_area_exponent(w_max)  # elastic_plastic.unloading_area
        touching = load > 0
        in_contact = weights[touching].sum()
        plastic = weights[touching & (w_max > 1.0)].sum() / in_contact if in_contact > 0 else 0.0
        return self.count * (weights @ load), self.count * (weights @ area), self.count * in_contact, plastic


def _separation_at(force_of, target: float, high: float, scale: float) -> float:
    """Separation below ``high`` at which the monotonic ``force_of`` reaches ``target``."""
    low = high - scale
    while force_of(low) < target:
        high, low = low, low - scale
    return optimize.brentq(lambda d: force_of(d) - target, low, high, xtol=1e-12 * scale, rtol=1e-12)


def statistical_load_unload(
    distribution: SummitDistribution,
    *,
    contact_modulus: float,
    hardness: float,
    poissons_ratio: float,
    max_force: float,
    nominal_area: float,
    law: str = "kogut_etsion",
    yield_strength: float | None = None,
    reference_force: float | None = None,
    steps: int = 40,
    threshold: float = 1e-6,
) -> StatisticalLoadUnload:
    """Load a summit population to ``max_force`` against a rigid flat and unload it (KKE model).

    Parameters
    ----------
    distribution : SummitDistribution
        The summits (:func:`~roughcontact.asperity.gaussian_summits` or ``measured_summits``).
    contact_modulus : float
        E' [Pa].
    hardness : float
        H [Pa] of the softer body (sets omega_c and P_c).
    poissons_ratio : float
        nu [-] of the softer body (K = 0.454 + 0.41 nu).
    max_force : float
        Peak load [N].
    nominal_area : float
        A_n [m^2] (paper 002: the 25 um x 25 um island).
    law : {"kogut_etsion", "paper002_eq10", "jackson_green", "hertz"}
        Loading law of one summit; "paper002_eq10" is the sound reading of eq. 10 (and uses the
        Kogut-Etsion area); "jackson_green" needs ``yield_strength``; "hertz" is the purely elastic
        GW model (no summit yields, unloading retraces loading).
    yield_strength : float, optional
        S_y [Pa], for the Jackson-Green law.
    reference_force : float, optional
        Load [N] at which the approach is zero and both branches end (paper 002: 25 uN); default:
        approach = -d and the branches end at ``threshold`` x ``max_force``.
    steps : int
        Points per branch (>= 2).
    threshold : float
        Fraction of the peak load taken as "no load" at both ends without ``reference_force``.

    Returns
    -------
    StatisticalLoadUnload

    Raises
    ------
    InputError
        Unknown law, missing yield strength, non-positive inputs, nu outside (-1, 0.5], a reference
        force not below the peak, or a peak load that drives summits beyond omega* = 110.

    References
    ----------
    Kadin, Kligerman and Etsion (2006), doi:10.1016/j.jmps.2006.07.005. Seed paper 002, section V.
    """
    if law not in LOADING_LAWS:
        raise InputError("law", f"unknown loading law {law!r}.", f"use one of {LOADING_LAWS}.")
    if law == "jackson_green" and yield_strength is None:
        raise InputError("yield_strength", "the Jackson-Green law needs it.", "pass yield_strength in Pa.")
    positive(max_force, "max_force", example=1e-3, unit="N")
    positive(nominal_area, "nominal_area", example=625e-12, unit="m^2")
    positive(threshold, "threshold", example=1e-9)
    if reference_force is not None and not 0 < reference_force < max_force:
        raise InputError(
            "reference_force", f"{reference_force!r} N is not between 0 and the peak load.", "e.g. 25e-6."
        )
    if steps < 2:
        raise InputError("steps", f"need at least 2 points per branch, got {steps}.", "use steps >= 2.")
    scales = dict(
        hardness=hardness,
        poissons_ratio=poissons_ratio,
        contact_modulus=contact_modulus,
        radius=distribution.summit_radius,
    )
    population = _Population(
        distribution=distribution,
        count=distribution.summit_density * nominal_area,
        omega_c=ep.critical_interference(**scales),
        load_c=ep.critical_load(**scales),
        law=law,
        contact_modulus=contact_modulus,
        jg=dict(
            yield_strength=yield_strength, poissons_ratio=poissons_ratio, contact_modulus=contact_modulus
        ),
    )
    sigma = distribution.summit_height_std
    top = float(distribution.heights.max())
    floor = threshold * max_force if reference_force is None else reference_force
    lowest = _separation_at(lambda d: population.loading(d)[0], max_force, top, sigma)
    start = _separation_at(lambda d: population.loading(d)[0], floor, top, sigma)
    zero = 0.0 if reference_force is None else start
    end = _separation_at(lambda d: population.unloading(d, lowest)[0], floor, top, sigma)

    rows = []
    for d in np.linspace(start, lowest, steps):
        force, area, count, plastic = population.loading(float(d))
        rows.append(("loading", d, force, area, count, plastic))
    for d in np.linspace(lowest, end, steps)[1:]:
        force, area, count, plastic = population.unloading(float(d), lowest)
        rows.append(("unloading", d, force, area, count, plastic))
    branch, separation, force, area, count, plastic = (np.array(column) for column in zip(*rows, strict=True))
    return StatisticalLoadUnload(
        branch=branch,
        separation=separation,
        approach=zero - separation,
        force=force,
        contact_area=area,
        number_of_contacts=count,
        plastic_fraction=plastic,
        interference_at_return_force=zero - end,
        return_force=float(floor),
        critical_interference=population.omega_c,
        critical_load=population.load_c,
        law=law,
    )
