r"""Which theory predicts my surface: Persson, Bush-Gibson-Thomas and Greenwood-Williamson beside the BEM.

:func:`compare_theories` sweeps the nominal pressure on one surface, solves each load with the
boundary-element method (:func:`roughcontact.contact.solve_normal`, warm-started from the previous
load on one operator) and evaluates every theory from the surface's own spectrum
(:func:`~roughcontact.theory.spectrum.surface_spectrum`) at the same loads:

* the relative contact area: the BEM's raw pixel count and its perimeter-corrected area
  (:mod:`roughcontact.contact.area`), Persson's :math:`\operatorname{erf}(\sqrt2 p_0/(E^* g))`,
  Bush-Gibson-Thomas's small-load :math:`\sqrt{2\pi} p_0/(E^* g)` and Greenwood-Williamson's from the
  spectral moments (:mod:`~roughcontact.theory.persson`, :mod:`~roughcontact.theory.bgt`,
  :mod:`~roughcontact.theory.gw`);
* the mean gap: the BEM's mean of the gap field, Persson's (2007) mean separation and GW's
  separation of the flat from the mean plane;
* the distribution of contact pressures: the BEM's histogram and Persson's :math:`P(\sigma)`, both
  per nominal area;
* the area-load slope :math:`\kappa`: the least-squares slope through the origin of :math:`A/A_0`
  against :math:`p_0/(E^* g)` over the loads whose corrected area is at most
  ``kappa_max_fraction`` (10 % by default: the range where boundary-element studies find the area
  linear in the load, Hyun et al. 2004, Yastrebov et al. 2015),

  .. math:: \kappa = \frac{\sum_i a_i x_i}{\sum_i x_i^2}, \qquad a_i = A_i/A_0,\ x_i = p_i/(E^* g),

  beside Persson's :math:`\sqrt{8/\pi} = 1.596` and BGT's :math:`\sqrt{2\pi} = 2.507`.

One surface is one realisation. Over several (a study's ``realisations``, generated surfaces of
one spectrum), :func:`against_bem` judges each theory at each load against the BEM: the deviation
:math:`d_i = T_i/B_i - 1` of the theory's value :math:`T_i` from the BEM's :math:`B_i` on the same
realisation, its mean and Student's 95 % confidence interval over the realisations
(:func:`roughcontact.spread.spread`), and the verdict on the claim "the theory predicts the BEM mean":
the interval lies above 0 (the theory over-predicts), below 0 (it under-predicts) or holds 0
(``not established``: no deviation shown at this number of realisations). Pairing each theory with
the BEM on the same draw removes the scatter both share (a realisation of larger slopes has a
smaller area in both).

Where the theories apply: to an infinite, statistically homogeneous surface, which a periodic
BEM models. A window of a larger surface solved with a free boundary is a punch of the window's size:
its edge carries load the theories do not know of (``edge_load_share``), and its mean gap includes
the settlement of the half-space under the whole window (of order :math:`p_0 L/E^*`), which no
theory of the interface has, so the mean gap is not compared there.

References
----------
Persson (2001) doi:10.1063/1.1388626; Persson (2007) doi:10.1103/PhysRevLett.99.125502;
Bush, Gibson and Thomas (1975) doi:10.1016/0043-1648(75)90145-3; Greenwood and Williamson (1966)
doi:10.1098/rspa.1966.0242.

Hyun, S., Pei, L., Molinari, J.-F. and Robbins, M. O. (2004). Finite-element analysis of contact
between elastic self-affine surfaces. Phys. Rev. E 70, 026117. doi:10.1103/PhysRevE.70.026117

Yastrebov, V. A., Anciaux, G. and Molinari, J.-F. (2015). From infinitesimal to full contact between
rough surfaces: evolution of the contact area. Int. J. Solids Struct. 52, 83-102.
doi:10.1016/j.ijsolstr.2014.09.019

Yastrebov, V. A., Anciaux, G. and Molinari, J.-F. (2017). On the accurate computation of the true
contact-area in mechanical contact of random rough surfaces. Tribol. Int. 114, 161-171.
doi:10.1016/j.triboint.2017.04.023

Prodanov, N., Dapp, W. B. and Müser, M. H. (2014). On the contact area and mean gap of rough,
elastic contacts: dimensional analysis, numerical corrections, and reference data. Tribol. Lett. 53,
433-448. doi:10.1007/s11249-013-0282-z
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from .._version import __version__
from ..display_html import NotebookDisplay
from ..errors import InputError
from ..materials import Material
from ..messages import as_messages, marked
from ..spread import Spread, Verdict, spread
from ..topography import Topography
from ..topography.statistics import rms_slope
from ..topography.surface import topography_argument
from .bgt import KAPPA as BGT_KAPPA
from .bgt import bgt_contact_fraction
from .gw import gw_at_pressure
from .persson import (
    GAMMA,
    persson_contact_fraction,
    persson_contact_fraction_magnified,
    persson_mean_separation,
    persson_pressure_distribution,
)
from .persson import KAPPA as PERSSON_KAPPA
from .spectrum import Spectrum, surface_spectrum

__all__ = [
    "KAPPA_MAX_FRACTION",
    "REDUCED_PRESSURES",
    "THEORIES",
    "TheoryComparison",
    "TheoryDeviation",
    "against_bem",
    "compare_theories",
    "kappa_fit",
]

REDUCED_PRESSURES = (0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4)
r"""Default loads :math:`p_0/(E^* g)`: from a contact of half a per cent to about half the surface."""

KAPPA_MAX_FRACTION = 0.1
r"""Largest corrected :math:`A/A_0` of a load in the small-load fit of :math:`\kappa`."""

THEORIES = {
    "persson": "Persson",
    "bgt": "Bush-Gibson-Thomas (small load)",
    "gw": "Greenwood-Williamson",
}
"""The theories compared, by key, and their names in tables and legends."""

PRESSURE_SPREAD = 2.0
r"""The histogram of contact pressures reaches this many :math:`E^* g` beyond the largest load (four of
the standard deviations :math:`E^* g/2` of Persson's distribution)."""


def kappa_fit(
    reduced_pressure, fraction, *, max_fraction: float = KAPPA_MAX_FRACTION, select=None
) -> tuple[float, int]:
    r"""Return the small-load slope :math:`\kappa` of ``fraction`` against ``reduced_pressure`` and its loads.

    The least-squares slope through the origin over the loads whose ``select`` (default
    ``fraction``) lies in :math:`(0, \mathrm{max\_fraction}]`:
    :math:`\kappa = \sum a_i x_i / \sum x_i^2`.

    Parameters
    ----------
    reduced_pressure, fraction : array_like
        :math:`x_i = p_i/(E^* g)` and :math:`a_i = A_i/A_0` per load.
    max_fraction : float
        The largest area fraction a load of the fit may have.
    select : array_like, optional
        The fractions that choose the loads (the corrected area, when ``fraction`` is the raw one).

    Returns
    -------
    kappa : float
        NaN where no load qualifies.
    loads : int
        The loads used.
    """
    x = np.asarray(reduced_pressure, dtype=float)
    a = np.asarray(fraction, dtype=float)
    chooser = a if select is None else np.asarray(select, dtype=float)
    used = (chooser > 0) & (chooser <= max_fraction) & np.isfinite(a) & (x > 0)
    if not used.any():
        return math.nan, 0
    return float(np.sum(a[used] * x[used]) / np.sum(x[used] ** 2)), int(used.sum())


@dataclass(frozen=True)
class TheoryComparison(NotebookDisplay):
    r"""The BEM and the theories of rough contact on one surface over a load sweep (SI).

    Attributes
    ----------
    topography : Topography
        The surface.
    spectrum : Spectrum
        Its modes (:func:`~roughcontact.theory.spectrum.surface_spectrum`).
    contact_modulus : float
        :math:`E^*` [Pa].
    boundary : str
        The BEM's boundary, ``"periodic"`` or ``"free"``.
    mean_pressure : ndarray
        Nominal pressures :math:`p_0` [Pa], ascending.
    contact_fraction, contact_fraction_corrected : ndarray
        The BEM's raw and perimeter-corrected :math:`A/A_0` [-].
    perimeter_switches : ndarray
        The contact/no-contact switches on the grid lines per load.
    mean_gap, max_pressure, approach : ndarray
        The BEM's mean gap [m], largest pressure [Pa] and approach [m] per load.
    iterations_per_load, residual_per_load : ndarray
        The solver's iterations and residual per load.
    persson_fraction, bgt_fraction, gw_fraction : ndarray
        The theories' :math:`A/A_0` [-].
    persson_mean_gap, gw_mean_gap : ndarray
        Persson's mean separation and GW's [m].
    pressure_edges : ndarray
        Edges of the bins of contact pressure, in :math:`\sigma/(E^* g)`.
    bem_pressure_density, persson_pressure_density : ndarray, shape (loads, bins)
        Contact pressures per nominal area and per unit :math:`\sigma/(E^* g)`: the BEM's histogram
        and Persson's :math:`P(\sigma) E^* g` at the bins' centres.
    magnification : ndarray
        :math:`\zeta = q/q_0` of Persson's area at magnification.
    persson_fraction_magnified : ndarray, shape (loads, magnifications)
        Persson's :math:`A(\zeta)/A_0` [-].
    rms_slope_finite_differences : float
        The forward-difference rms gradient of the grid (beside the spectral :math:`g`).
    tolerance, gamma, kappa_max_fraction : float
        The solver's tolerance, Persson's :math:`\gamma`, the fit's largest area.
    notes : tuple of str
        What the solves said about their range (each once).
    parameters : dict
        What was asked for and the package version.
    """

    topography: Topography
    spectrum: Spectrum
    contact_modulus: float
    boundary: str
    mean_pressure: np.ndarray
    contact_fraction: np.ndarray
    contact_fraction_corrected: np.ndarray
    perimeter_switches: np.ndarray
    mean_gap: np.ndarray
    max_pressure: np.ndarray
    approach: np.ndarray
    iterations_per_load: np.ndarray
    residual_per_load: np.ndarray
    persson_fraction: np.ndarray
    bgt_fraction: np.ndarray
    gw_fraction: np.ndarray
    persson_mean_gap: np.ndarray
    gw_mean_gap: np.ndarray
    pressure_edges: np.ndarray
    bem_pressure_density: np.ndarray
    persson_pressure_density: np.ndarray
    magnification: np.ndarray
    persson_fraction_magnified: np.ndarray
    rms_slope_finite_differences: float
    tolerance: float
    gamma: float = GAMMA
    kappa_max_fraction: float = KAPPA_MAX_FRACTION
    notes: tuple[str, ...] = ()
    parameters: dict[str, Any] = field(default_factory=dict)

    FIGURE = "theories.plot_theories"
    """The figure a notebook shows under the table of scalars (:mod:`roughcontact.display_html`)."""

    UNITS: ClassVar[dict[str, str]] = {
        "contact_modulus": "Pa",
        "m0": "m^2",
        "m4": "1/m^2",
        "rms_height": "m",
        "min_mean_pressure": "Pa",
        "max_mean_pressure": "Pa",
        "kappa": "",
        "kappa_raw": "",
        "kappa_persson": "",
        "kappa_bgt": "",
        "rms_gradient": "",
        "rms_gradient_finite_differences": "",
        "min_reduced_pressure": "",
        "max_reduced_pressure": "",
        "reduced_pressure": "",
        "mean_pressure": "Pa",
        "area_load_slope": "",
        "area_load_slope_raw": "",
        "mean_gap": "m",
        "max_pressure": "Pa",
        "approach": "m",
        "persson_mean_gap": "m",
        "gw_mean_gap": "m",
    }
    """SI unit of each scalar of :meth:`scalars` ("" for a dimensionless one; counts and labels left out)."""

    @property
    def rms_gradient(self) -> float:
        """The spectral rms gradient g of the surface [-] (the unit of the reduced pressure)."""
        return self.spectrum.rms_gradient

    @property
    def reduced_pressure(self) -> np.ndarray:
        r""":math:`p_0/(E^* g)` per load [-]."""
        return self.mean_pressure / (self.contact_modulus * self.rms_gradient)

    @property
    def converged(self) -> bool:
        """Always True: an unconverged solve raises instead of returning."""
        return bool(np.all(self.residual_per_load <= self.tolerance))

    @property
    def iterations(self) -> int:
        """Iterations of every solve of the sweep."""
        return int(self.iterations_per_load.sum())

    @property
    def residual(self) -> float:
        """The largest residual of the sweep's solves."""
        return float(self.residual_per_load.max())

    @property
    def kappa(self) -> tuple[float, int]:
        r"""The BEM's small-load :math:`\kappa` of the corrected area and its loads (:func:`kappa_fit`)."""
        return kappa_fit(
            self.reduced_pressure, self.contact_fraction_corrected, max_fraction=self.kappa_max_fraction
        )

    @property
    def kappa_raw(self) -> float:
        r"""The same fit of the raw pixel count, over the same loads."""
        return kappa_fit(
            self.reduced_pressure,
            self.contact_fraction,
            max_fraction=self.kappa_max_fraction,
            select=self.contact_fraction_corrected,
        )[0]

    @property
    def gap_compared(self) -> bool:
        """Whether the BEM's mean gap is the theories' (a periodic surface; not a free window)."""
        return self.boundary == "periodic"

    def load_scalars(self, index: int) -> dict[str, Any]:
        """Return the BEM's and the theories' values at the load ``index`` (SI; see :meth:`scalars`)."""
        x = float(self.reduced_pressure[index])
        raw, corrected = float(self.contact_fraction[index]), float(self.contact_fraction_corrected[index])
        return {
            "reduced_pressure": x,
            "mean_pressure": float(self.mean_pressure[index]),
            "contact_fraction": raw,
            "contact_fraction_corrected": corrected,
            "perimeter_switches": int(self.perimeter_switches[index]),
            "area_load_slope": corrected / x,
            "area_load_slope_raw": raw / x,
            "mean_gap": float(self.mean_gap[index]),
            "max_pressure": float(self.max_pressure[index]),
            "approach": float(self.approach[index]),
            "persson_fraction": float(self.persson_fraction[index]),
            "bgt_fraction": float(self.bgt_fraction[index]),
            "gw_fraction": float(self.gw_fraction[index]),
            "persson_mean_gap": float(self.persson_mean_gap[index]),
            "gw_mean_gap": float(self.gw_mean_gap[index]),
            "gap_compared": self.gap_compared,
        }

    def scalars(self) -> dict[str, Any]:
        r"""Return the BEM's :math:`\kappa` (a sweep) or the values at its one load, and the spectrum (SI).

        A sweep of several loads: ``kappa`` (corrected area) and ``kappa_raw`` (pixel count) with
        ``kappa_loads`` (:func:`kappa_fit`), the number and range of the loads. One load (a study's
        case; its kappa is fitted over the cases of a realisation): the BEM's and the theories' values
        there (:meth:`load_scalars`: the raw and corrected areas and their ``area_load_slope``, the
        mean gaps, Persson's, BGT's and GW's areas). Both: ``kappa_persson`` (1.596) and
        ``kappa_bgt`` (2.507), the spectral ``rms_gradient`` :math:`g` beside the grid's
        forward-difference ``rms_gradient_finite_differences``, the moments and the bandwidth.
        """
        moments = self.spectrum.moments
        reduced = self.reduced_pressure
        if self.mean_pressure.size == 1:
            head = self.load_scalars(0)
        else:
            kappa, loads = self.kappa
            head = {
                "kappa": kappa,
                "kappa_raw": self.kappa_raw,
                "kappa_loads": loads,
                "loads": int(self.mean_pressure.size),
                "min_mean_pressure": float(self.mean_pressure.min()),
                "max_mean_pressure": float(self.mean_pressure.max()),
                "min_reduced_pressure": float(reduced.min()),
                "max_reduced_pressure": float(reduced.max()),
            }
        return head | {
            "kappa_persson": PERSSON_KAPPA,
            "kappa_bgt": BGT_KAPPA,
            "rms_gradient": self.rms_gradient,
            "rms_gradient_finite_differences": self.rms_slope_finite_differences,
            "rms_height": math.sqrt(moments.m0),
            "m0": moments.m0,
            "m2": moments.m2,
            "m4": moments.m4,
            "bandwidth": moments.m0 * moments.m4 / moments.m2**2,
            "contact_modulus": self.contact_modulus,
            "boundary": self.boundary,
            "iterations": self.iterations,
            "residual": self.residual,
        }

    @as_messages
    def range_warnings(self) -> list[str]:
        """Say where the comparison leaves the range of the BEM or of the theories (empty when it does not).

        What the solves said (small slopes, resolution of the area, loads on an edge), each once; a
        free window (the theories are of an infinite surface: its mean gap is not compared); a
        spectrum whose spectral and finite-difference gradients differ by more than 10 % (power up
        to the pixel: the grid does not resolve the shortest waves it holds, and the BEM's answer
        depends on it); no load small enough for the fit of kappa.
        """
        notes = list(self.notes)
        if self.boundary == "free":
            notes.append(
                "free window: the BEM solves the scan as a punch of its own size, whose edge may carry load, "
                "and its mean gap includes the settlement of the half-space under the whole window; the "
                "theories are of an infinite surface of the scan's spectrum, so the areas are compared "
                "(read the edge's share of the load) and the mean gap is not. «boundary=periodic» repeats "
                "the scan instead (its jump across the edges then makes contact lines of its own)."
            )
        spectral, differences = self.rms_gradient, self.rms_slope_finite_differences
        if abs(differences / spectral - 1.0) > 0.1:
            notes.append(
                f"the rms gradient from the spectrum, {spectral:.3g}, and from forward differences, "
                f"{differences:.3g}, differ by {100 * abs(differences / spectral - 1):.0f} %: the surface "
                "holds power up to the pixel, which the grid does not resolve; the reduced pressure uses the "
                "spectral one, and the BEM's areas depend on the pixel."
            )
        if self.mean_pressure.size > 1 and self.kappa[1] == 0:
            notes.append(
                f"no load has a corrected contact area of at most {100 * self.kappa_max_fraction:g} %: "
                "kappa is not fitted; add smaller loads."
            )
        return notes

    def to_xarray(self):
        """Return the curves per load, pressure histograms and Persson's magnification; scalars as attrs."""
        import xarray as xr

        centres = 0.5 * (self.pressure_edges[1:] + self.pressure_edges[:-1])
        load = ("load",)
        data = {
            "mean_pressure": (load, self.mean_pressure, {"units": "Pa"}),
            "reduced_pressure": (load, self.reduced_pressure, {"units": "1", "long_name": "p0 / (E* g)"}),
            "contact_fraction": (
                load,
                self.contact_fraction,
                {"units": "1", "long_name": "BEM, pixel count"},
            ),
            "contact_fraction_corrected": (
                load,
                self.contact_fraction_corrected,
                {"units": "1", "long_name": "BEM, corrected for the pixelated perimeter"},
            ),
            "perimeter_switches": (load, self.perimeter_switches, {"units": "1"}),
            "mean_gap": (load, self.mean_gap, {"units": "m"}),
            "max_pressure": (load, self.max_pressure, {"units": "Pa"}),
            "approach": (load, self.approach, {"units": "m"}),
            "iterations": (load, self.iterations_per_load, {"units": "1"}),
            "persson_fraction": (load, self.persson_fraction, {"units": "1"}),
            "bgt_fraction": (load, self.bgt_fraction, {"units": "1"}),
            "gw_fraction": (load, self.gw_fraction, {"units": "1"}),
            "persson_mean_gap": (load, self.persson_mean_gap, {"units": "m"}),
            "gw_mean_gap": (load, self.gw_mean_gap, {"units": "m"}),
            "bem_pressure_density": (
                ("load", "pressure_bin"),
                self.bem_pressure_density,
                {"units": "1", "long_name": "contact pressures per nominal area and unit sigma / (E* g)"},
            ),
            "persson_pressure_density": (
                ("load", "pressure_bin"),
                self.persson_pressure_density,
                {"units": "1"},
            ),
            "persson_fraction_magnified": (
                ("load", "magnification"),
                self.persson_fraction_magnified,
                {"units": "1"},
            ),
        }
        coords = {
            "pressure_bin": (
                "pressure_bin",
                centres,
                {"units": "1", "long_name": "sigma / (E* g), bin centre"},
            ),
            "pressure_edge": ("pressure_edge", self.pressure_edges, {"units": "1"}),
            "magnification": ("magnification", self.magnification, {"units": "1", "long_name": "q / q0"}),
        }
        attributes = {k: v for k, v in self.scalars().items()}
        attributes |= {
            "gap_compared": int(self.gap_compared),
            "gamma": self.gamma,
            "kappa_max_fraction": self.kappa_max_fraction,
            "spectrum_window": str(self.spectrum.window),
        }
        attributes |= {f"parameter_{k}": str(v) for k, v in self.parameters.items()}
        return xr.Dataset(data, coords=coords, attrs=attributes)


def _loads(modulus, gradient, reduced_pressures, mean_pressures) -> tuple[np.ndarray, str, list[float]]:
    if (reduced_pressures is None) == (mean_pressures is None):
        if mean_pressures is None:
            reduced_pressures = REDUCED_PRESSURES
        else:
            raise InputError(
                "mean_pressures", "both the loads and the reduced loads were given.", "give one of them."
            )
    name = "mean_pressures" if mean_pressures is not None else "reduced_pressures"
    values = np.asarray(
        mean_pressures if mean_pressures is not None else reduced_pressures, dtype=float
    ).ravel()
    if values.size == 0 or not np.all(np.isfinite(values) & (values > 0)):
        raise InputError(
            name, f"must be one or more positive numbers, got {values.tolist()}.", "e.g. [0.01, 0.05, 0.1]."
        )
    pressures = values if mean_pressures is not None else values * modulus * gradient
    return np.sort(pressures), name, [float(v) for v in values]


def _loads_said(first: float, last: float, unit: float) -> str:
    """Return ``at p0/(E* g) = 0.4: `` or ``from p0/(E* g) = 0.05 to 0.4 (as at 0.4): ``."""
    if first == last:
        return f"at p0/(E* g) = {last / unit:.3g}: "
    return f"from p0/(E* g) = {first / unit:.3g} to {last / unit:.3g} (as at {last / unit:.3g}): "


def compare_theories(
    topography: Topography,
    material: Material | float | None = None,
    *,
    reduced_pressures: Sequence[float] | None = None,
    mean_pressures: Sequence[float] | None = None,
    counter_body: Material | None = None,
    boundary: str | None = None,
    tolerance: float = 1e-8,
    gamma: float = GAMMA,
    kappa_max_fraction: float = KAPPA_MAX_FRACTION,
    bins: int = 48,
    magnifications: int = 32,
) -> TheoryComparison:
    r"""Sweep the load on one surface with the BEM and evaluate every theory beside it (module notes).

    Parameters
    ----------
    topography : Topography
        A map (heights [m]), levelled; a periodic one is solved periodic.
    material : Material or float
        The body (against a rigid flat unless ``counter_body``), or :math:`E^*` [Pa].
    reduced_pressures : sequence of float, optional
        Loads as :math:`p_0/(E^* g)` with :math:`g` the surface's spectral rms gradient (default
        :data:`REDUCED_PRESSURES`).
    mean_pressures : sequence of float, optional
        Loads in pascals instead.
    counter_body : Material, optional
        The flat's material (default rigid).
    boundary : {"periodic", "free"}, optional
        The BEM's boundary (default the topography's periodic flag).
    tolerance : float
        The solver's scale-free residual.
    gamma : float
        Persson's :math:`\gamma` of the mean separation (0.4).
    kappa_max_fraction : float
        Largest corrected :math:`A/A_0` of a load in the fit of :math:`\kappa` (0.1).
    bins : int
        Bins of the histogram of contact pressures.
    magnifications : int
        Points of Persson's area against magnification.

    Returns
    -------
    TheoryComparison

    Raises
    ------
    InputError
        A profile, a flat surface, no or both load lists, loads that are not positive.
    ConvergenceError
        A solve did not converge.

    References
    ----------
    Persson (2001) doi:10.1063/1.1388626; Bush, Gibson and Thomas (1975)
    doi:10.1016/0043-1648(75)90145-3; Greenwood and Williamson (1966) doi:10.1098/rspa.1966.0242;
    Yastrebov, Anciaux and Molinari (2017) doi:10.1016/j.triboint.2017.04.023
    """
    from ..contact.normal import compliance_for, solve_normal

    topography = topography_argument(topography, "topography")
    spectrum = surface_spectrum(topography)
    compliance = compliance_for(topography, material, counter_body=counter_body, boundary=boundary)
    modulus = compliance.contact_modulus
    g = spectrum.rms_gradient
    pressures, given, asked = _loads(modulus, g, reduced_pressures, mean_pressures)
    if not (isinstance(bins, int) and bins >= 4):
        raise InputError("bins", f"must be an integer >= 4, got {bins!r}.", "e.g. 48.")
    top = float(pressures.max()) / (modulus * g) + PRESSURE_SPREAD
    edges = np.linspace(0.0, top, bins + 1)
    centres = 0.5 * (edges[1:] + edges[:-1])
    solved, said, previous = [], {}, None
    for pressure in pressures:
        previous = solve_normal(
            topography,
            compliance=compliance,
            initial=previous,
            mean_pressure=float(pressure),
            tolerance=tolerance,
        )
        solved.append(previous)
        # each kind of note once, as the largest load says it; the comparison is elastic: no hardness
        for note in previous.range_warnings(advise_hardness=False):
            kind = re.sub(r"[0-9][0-9.e+-]*", "#", str(note))
            first = said.get(kind, (pressure, ""))[0]
            said[kind] = (first, pressure, note)
    notes = [
        (_loads_said(first, last, modulus * g) if len(pressures) > 1 else "") + marked(note)
        for first, last, note in said.values()
    ]
    reduced_contact = [r.pressure[r.contact_mask] / (modulus * g) for r in solved]
    density = np.array(
        [np.histogram(s, bins=edges)[0] / (topography.heights.size * np.diff(edges)) for s in reduced_contact]
    )
    persson_density = np.array(
        [
            persson_pressure_distribution(
                centres * modulus * g, mean_pressure=float(p), contact_modulus=modulus, rms_gradient=g
            )
            * modulus
            * g
            for p in pressures
        ]
    )
    try:
        gw = gw_at_pressure(pressures, contact_modulus=modulus, moments=spectrum.moments)
        gw_fraction, gw_gap = gw.contact_fraction, gw.mean_separation
    except InputError as error:
        gw_fraction = gw_gap = np.full(pressures.shape, math.nan)
        notes.append(f"Greenwood-Williamson not evaluated: {error.problem}")
    below = np.asarray(gw_gap) < 0
    if below.any():  # the summits' flat below the mean plane: its separation means nothing there
        gw_gap = np.where(below, math.nan, gw_gap)
        first = float(pressures[below].min() / (modulus * g))
        notes.append(
            f"Greenwood-Williamson's flat passes below the mean plane from p0/(E* g) = {first:.3g} on: its "
            "mean separation is beyond the model's range there (non-interacting summits of a fixed "
            "population) and is left out."
        )
    zeta = np.geomspace(1.0, max(spectrum.highest / spectrum.lowest, 1.0), magnifications)
    return TheoryComparison(
        topography=topography,
        spectrum=spectrum,
        contact_modulus=modulus,
        boundary=compliance.boundary,
        mean_pressure=pressures,
        contact_fraction=np.array([r.contact_fraction for r in solved]),
        contact_fraction_corrected=np.array([r.contact_fraction_corrected for r in solved]),
        perimeter_switches=np.array([r.perimeter_switches for r in solved]),
        mean_gap=np.array([r.mean_gap for r in solved]),
        max_pressure=np.array([float(r.pressure.max()) for r in solved]),
        approach=np.array([r.approach for r in solved]),
        iterations_per_load=np.array([r.iterations for r in solved]),
        residual_per_load=np.array([r.residual for r in solved]),
        persson_fraction=persson_contact_fraction(pressures, contact_modulus=modulus, rms_gradient=g),
        bgt_fraction=bgt_contact_fraction(pressures, contact_modulus=modulus, rms_gradient=g),
        gw_fraction=np.asarray(gw_fraction),
        persson_mean_gap=persson_mean_separation(
            pressures, contact_modulus=modulus, spectrum=spectrum, gamma=gamma
        ),
        gw_mean_gap=np.asarray(gw_gap),
        pressure_edges=edges,
        bem_pressure_density=density,
        persson_pressure_density=persson_density,
        magnification=zeta,
        persson_fraction_magnified=persson_contact_fraction_magnified(
            pressures, contact_modulus=modulus, spectrum=spectrum, magnification=zeta
        ),
        rms_slope_finite_differences=rms_slope(topography),
        tolerance=tolerance,
        gamma=gamma,
        kappa_max_fraction=kappa_max_fraction,
        notes=tuple(notes),
        parameters={given: asked, "version": __version__},
    )


# --- over realisations -----------------------------------------------------------------------------


@dataclass(frozen=True)
class TheoryDeviation:
    r"""One theory against the BEM at one load, over realisations (module notes).

    Attributes
    ----------
    theory : str
        Key of :data:`THEORIES`.
    quantity : str
        ``contact_fraction`` or ``mean_gap`` (or ``kappa``).
    reduced_pressure : float
        Mean :math:`p_0/(E^* g)` over the realisations (NaN for kappa).
    mean_pressure : float
        Mean :math:`p_0` [Pa] (NaN for kappa).
    theory_value : Spread
        The theory's value over the realisations (its own spectrum on each).
    bem : Spread
        The BEM's value over the realisations.
    deviation : Spread
        :math:`T_i/B_i - 1` over the realisations.
    verdict : Verdict
        The deviation's 95 % confidence interval of the mean against 0.
    """

    theory: str
    quantity: str
    reduced_pressure: float
    mean_pressure: float
    theory_value: Spread
    bem: Spread
    deviation: Spread
    verdict: Verdict

    @property
    def words(self) -> str:
        """What the theory does to the BEM mean: over-predicts, under-predicts, not established, ..."""
        return {
            "above": "over-predicts",
            "below": "under-predicts",
            "not established": "not established",
            "one realisation": "one realisation: no interval",
        }[self.verdict.word]

    def row(self) -> dict[str, Any]:
        """Return the table row: values, the BEM's interval, the deviation's interval and the verdict."""
        return {
            "theory": THEORIES.get(self.theory, self.theory),
            "quantity": self.quantity,
            "reduced_pressure": self.reduced_pressure,
            "mean_pressure": self.mean_pressure,
            "theory_value": self.theory_value.mean,
            "bem_mean": self.bem.mean,
            "bem_ci95_low": self.bem.ci95_low,
            "bem_ci95_high": self.bem.ci95_high,
            "deviation": self.deviation.mean,
            "deviation_ci95_low": self.deviation.ci95_low,
            "deviation_ci95_high": self.deviation.ci95_high,
            "n": self.deviation.n,
            "verdict": self.words,
            "interval": self.verdict.interval_name,
        }


def against_bem(
    theory: Mapping[str, Any],
    bem,
    *,
    quantity: str,
    reduced_pressure=None,
    mean_pressure=None,
    bounds: tuple[float, float] = (0.0, math.inf),
) -> list[TheoryDeviation]:
    r"""Judge each theory against the BEM at each load over realisations (module notes).

    Parameters
    ----------
    theory : mapping of str to array_like, shape (realisations, loads)
        Each theory's value on each realisation at each load (NaN where it has none).
    bem : array_like, shape (realisations, loads)
        The BEM's values.
    quantity : str
        What is compared (``contact_fraction``, ``mean_gap``, ``kappa``).
    reduced_pressure, mean_pressure : array_like, shape (realisations, loads), optional
        The loads (their means over the realisations label the rows).
    bounds : (float, float)
        The range of the quantity (the BEM's interval is cut there).

    Returns
    -------
    list of TheoryDeviation
        Per theory, per load.
    """
    bem = np.atleast_2d(np.asarray(bem, dtype=float))
    shape = bem.shape
    loads = [
        np.full(shape, math.nan) if values is None else np.atleast_2d(np.asarray(values, dtype=float))
        for values in (reduced_pressure, mean_pressure)
    ]
    found = []
    for name, values in theory.items():
        values = np.broadcast_to(np.atleast_2d(np.asarray(values, dtype=float)), shape)
        for j in range(shape[1]):
            with np.errstate(divide="ignore", invalid="ignore"):
                ratio = np.where(bem[:, j] > 0, values[:, j] / bem[:, j] - 1.0, math.nan)
            deviation = spread(ratio)  # unbounded: GW's separation falls below zero
            found.append(
                TheoryDeviation(
                    theory=name,
                    quantity=quantity,
                    reduced_pressure=float(np.nanmean(loads[0][:, j]))
                    if np.isfinite(loads[0][:, j]).any()
                    else math.nan,
                    mean_pressure=float(np.nanmean(loads[1][:, j]))
                    if np.isfinite(loads[1][:, j]).any()
                    else math.nan,
                    theory_value=spread(values[:, j]),
                    bem=spread(bem[:, j], bounds=bounds),
                    deviation=deviation,
                    verdict=deviation.verdict(0.0, of="mean"),
                )
            )
    return found
