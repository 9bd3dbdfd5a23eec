r"""Persson's theory of the contact of a randomly rough elastic surface with a flat.

Persson (2001) follows the distribution :math:`P(\sigma, \zeta)` of contact pressures while the
roughness is added wavelength by wavelength, the magnification :math:`\zeta = q/q_0` running from the
lowest wavevector :math:`q_0` (a flat: every point at the nominal pressure :math:`p_0`) to the
shortest one resolved. Each band of roughness adds pressure fluctuations, so :math:`P` spreads by
diffusion,

.. math::

    \frac{\partial P}{\partial \zeta} = f(\zeta)\, \frac{\partial^2 P}{\partial \sigma^2}, \qquad
    P(\sigma, 1) = \delta(\sigma - p_0),

whose variance grows by what full contact of the added band would give: a mode of amplitude
:math:`\hat h` pressed flat needs :math:`\hat p = E^* |\mathbf q| \hat h / 2`, so the pressure variance
of full contact is :math:`\tfrac14 E^{*2} g^2(\zeta)`, with :math:`g^2(\zeta) = \sum_{|\mathbf q| \le
\zeta q_0} |\mathbf q|^2 v(\mathbf q)` the mean-square gradient of the modes resolved
(:mod:`roughcontact.theory.spectrum`; Persson writes it :math:`2 G p_0^2` with
:math:`G = \frac{\pi}{4} (E^*/p_0)^2 \int_{q_0}^{\zeta q_0} q^3 C_\mathrm P(q)\, \mathrm dq`).
A point that loses contact does not return: :math:`P(0, \zeta) = 0`. The method of images then gives

.. math::

    P(\sigma) = \frac{1}{\sqrt{2\pi V}}
    \left[ e^{-(\sigma - p_0)^2/(2V)} - e^{-(\sigma + p_0)^2/(2V)} \right],
    \qquad V = \tfrac14 E^{*2} g^2,

for :math:`\sigma > 0` (:func:`persson_pressure_distribution`; Persson 2001, and the closed forms of
Manners and Greenwood 2006). The boundary condition is what keeps the load: integrating the
diffusion equation by parts, :math:`\partial_\zeta \int_0^\infty \sigma P\, \mathrm d\sigma =
f(\zeta) P(0, \zeta) = 0`, so the mean pressure stays :math:`p_0` at every magnification. The weight of
:math:`P` is the area in contact:

.. math::

    \frac{A}{A_0} = \int_0^\infty P(\sigma)\, \mathrm d\sigma
    = \operatorname{erf}\!\left(\frac{p_0}{\sqrt{2V}}\right)
    = \operatorname{erf}\!\left(\frac{\sqrt 2\, p_0}{E^* g}\right)

(:func:`persson_contact_fraction`; at magnification :math:`\zeta`, :math:`g(\zeta)` in place of
:math:`g`: :func:`persson_contact_fraction_magnified`). At small load
:math:`A/A_0 \to \kappa\, p_0/(E^* g)` with :math:`\kappa = 2\sqrt2/\sqrt\pi = \sqrt{8/\pi} = 1.596`
(:data:`KAPPA`); under large load it tends to full contact, :math:`1 - A/A_0 \approx
e^{-x^2}/(x\sqrt\pi)`, :math:`x = \sqrt2 p_0/(E^* g)`.

The mean separation :math:`\bar u` of the surfaces (Persson 2007) follows from the elastic energy
stored in the interface, :math:`U_\mathrm{el} \approx \frac{A_0 E^*}{4} \int \mathrm d^2q\, q\,
C_\mathrm P(q)\, W(q, p_0)` with :math:`W = P(q) [\gamma + (1 - \gamma) P^2(q)]`, :math:`P(q)` the
contact area at magnification :math:`q/q_0` and :math:`\gamma \approx 0.4` a correction for the
energy of the partly touching bands; the load does the work, :math:`p_0 A_0\, \mathrm d\bar u =
-\mathrm dU_\mathrm{el}`, so

.. math::

    \bar u(p_0) = \sqrt\pi \int_{q_0}^{q_1} \mathrm dq\, q^2 C_\mathrm P(q)\, w(q)
    \int_{p_0}^\infty \frac{\mathrm dp'}{p'} \left[\gamma + 3 (1 - \gamma) P^2(q, p')\right]
    e^{-(w(q) p'/E^*)^2},

:math:`w(q) = (\pi \int_{q_0}^{q} q'^3 C_\mathrm P\, \mathrm dq')^{-1/2} = \sqrt 2 / g(q)` and
:math:`P(q, p) = \operatorname{erf}(w(q) p/E^*)`. On the modes of a grid (:func:`persson_mean_separation`)
the outer integral is the sum :math:`\frac{1}{2\sqrt\pi}\sum_{\mathbf q} |\mathbf q|\, v\, w\,
J(w p_0/E^*)`, and the inner one a function of its lower limit only,
:math:`J(x_0) = \int_{x_0}^\infty \frac{\mathrm dx}{x} [\gamma + 3(1 - \gamma) \operatorname{erf}^2 x]
e^{-x^2}`, tabulated once. For small loads :math:`\bar u \approx u_0 \ln(\beta E^*/p_0)` with
:math:`u_0 = \gamma \frac{1}{2\sqrt\pi}\sum |\mathbf q| v w`; full contact closes the gap,
:math:`\bar u \to 0`. Almqvist et al. (2011) compare it with boundary-element and molecular
dynamics solutions.

The theory is of an infinite, statistically homogeneous, Gaussian surface under small slopes; the
flat is rigid (or the modulus is the pair's :math:`E^*`) and there is no adhesion.

References
----------
Persson, B. N. J. (2001). Theory of rubber friction and contact mechanics. J. Chem. Phys. 115,
3840-3861. doi:10.1063/1.1388626

Persson, B. N. J. (2006). Contact mechanics for randomly rough surfaces. Surf. Sci. Rep. 61, 201-227.
doi:10.1016/j.surfrep.2006.04.001

Manners, W. and Greenwood, J. A. (2006). Some observations on Persson's diffusion theory of elastic
contact. Wear 261, 600-610. doi:10.1016/j.wear.2006.01.007

Persson, B. N. J. (2007). Relation between interfacial separation and load: a general theory of
contact mechanics. Phys. Rev. Lett. 99, 125502. doi:10.1103/PhysRevLett.99.125502

Almqvist, A., Campañá, C., Prodanov, N. and Persson, B. N. J. (2011). Interfacial separation between
elastic solids with randomly rough surfaces: comparison between theory and numerical techniques.
J. Mech. Phys. Solids 59, 2355-2369. doi:10.1016/j.jmps.2011.08.004
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np
from scipy import special

from ..checks import positive
from ..errors import InputError
from .spectrum import Spectrum

__all__ = [
    "GAMMA",
    "KAPPA",
    "persson_contact_fraction",
    "persson_contact_fraction_magnified",
    "persson_mean_separation",
    "persson_pressure_distribution",
]

KAPPA = math.sqrt(8.0 / math.pi)
r"""Persson's small-load slope of :math:`A/A_0` against :math:`p_0/(E^* g)`, :math:`\sqrt{8/\pi} = 1.596`."""

GAMMA = 0.4
r"""Persson's (2007) :math:`\gamma`: the share of a band's elastic energy kept where partly in contact."""


def checked_pressures(mean_pressure) -> np.ndarray:
    """Return the nominal pressures [Pa] a theory takes as an array (at least 1D), each finite and >= 0."""
    pressure = np.atleast_1d(np.asarray(mean_pressure, dtype=float))
    if not np.all(np.isfinite(pressure) & (pressure >= 0)):
        raise InputError(
            "mean_pressure", f"must be finite and >= 0, got {mean_pressure!r}.", "e.g. 20e6 (Pa)."
        )
    return pressure


def persson_contact_fraction(mean_pressure, *, contact_modulus: float, rms_gradient: float) -> np.ndarray:
    r"""Persson's relative contact area :math:`A/A_0 = \operatorname{erf}(\sqrt2\, p_0/(E^* g))`.

    Parameters
    ----------
    mean_pressure : float or array_like
        Nominal pressure :math:`p_0` [Pa], >= 0.
    contact_modulus : float
        :math:`E^*` [Pa].
    rms_gradient : float
        :math:`g`, the rms gradient of the 2D surface over the resolved band [-]
        (:attr:`~roughcontact.theory.spectrum.Spectrum.rms_gradient`; :math:`\sqrt{2 m_2}`).

    Returns
    -------
    ndarray
        :math:`A/A_0` [-] per pressure (at least 1D).

    References
    ----------
    Persson (2001) doi:10.1063/1.1388626; Persson (2006) doi:10.1016/j.surfrep.2006.04.001
    """
    positive(contact_modulus, "contact_modulus", example=1e9, unit="Pa")
    positive(rms_gradient, "rms_gradient", example="0.1 (dimensionless)")
    return special.erf(math.sqrt(2.0) * checked_pressures(mean_pressure) / (contact_modulus * rms_gradient))


def persson_contact_fraction_magnified(
    mean_pressure, *, contact_modulus: float, spectrum: Spectrum, magnification
) -> np.ndarray:
    r"""Persson's area at magnification :math:`\zeta`, :math:`\operatorname{erf}(\sqrt2 p_0/(E^* g(\zeta)))`.

    The roughness is seen up to the wavevector :math:`\zeta q_0` (:math:`q_0` the lowest wavevector
    with power, :attr:`~roughcontact.theory.spectrum.Spectrum.lowest`); :math:`g(\zeta)` the rms
    gradient of those modes. At :math:`\zeta = 1` a single band: at :math:`\zeta \ge q_1/q_0` the whole
    resolved band, :func:`persson_contact_fraction`.

    Parameters
    ----------
    mean_pressure : float or array_like
        :math:`p_0` [Pa], >= 0.
    contact_modulus : float
        :math:`E^*` [Pa].
    spectrum : Spectrum
        The surface's modes (:func:`~roughcontact.theory.spectrum.surface_spectrum`).
    magnification : float or array_like
        :math:`\zeta \ge 1`.

    Returns
    -------
    ndarray, shape (pressures, magnifications)
        :math:`A(\zeta)/A_0` [-]; 1 where no mode is resolved yet.

    References
    ----------
    Persson (2001) doi:10.1063/1.1388626
    """
    positive(contact_modulus, "contact_modulus", example=1e9, unit="Pa")
    zeta = np.atleast_1d(np.asarray(magnification, dtype=float))
    if not np.all(np.isfinite(zeta) & (zeta >= 1)):
        raise InputError("magnification", f"must be >= 1, got {magnification!r}.", "e.g. [1, 10, 100].")
    gradient = spectrum.cumulative_gradient(zeta * spectrum.lowest)
    pressure = checked_pressures(mean_pressure)[:, None]
    with np.errstate(divide="ignore"):
        argument = np.where(gradient > 0, math.sqrt(2.0) * pressure / (contact_modulus * gradient), np.inf)
    return special.erf(argument)


def persson_pressure_distribution(
    pressure, *, mean_pressure: float, contact_modulus: float, rms_gradient: float
) -> np.ndarray:
    r"""Persson's distribution of contact pressures per nominal area, :math:`P(\sigma)` [1/Pa] (module notes).

    .. math::

        P(\sigma) = \frac{1}{\sqrt{2\pi V}}
        \left[e^{-(\sigma - p_0)^2/(2V)} - e^{-(\sigma + p_0)^2/(2V)}\right],
        \qquad V = \tfrac14 E^{*2} g^2

    for :math:`\sigma \ge 0`; its integral is :math:`A/A_0` (the rest of the nominal area, out of
    contact, carries :math:`\sigma = 0`) and its mean :math:`p_0`. In reduced units
    :math:`s = \sigma/(E^* g)` multiply by :math:`E^* g`.

    Parameters
    ----------
    pressure : float or array_like
        Contact pressures :math:`\sigma` [Pa] where to evaluate it.
    mean_pressure : float
        :math:`p_0` [Pa].
    contact_modulus : float
        :math:`E^*` [Pa].
    rms_gradient : float
        :math:`g` [-].

    Returns
    -------
    ndarray
        :math:`P(\sigma)` [1/Pa]; 0 at negative pressures.

    References
    ----------
    Persson (2001) doi:10.1063/1.1388626; Manners and Greenwood (2006) doi:10.1016/j.wear.2006.01.007
    """
    positive(contact_modulus, "contact_modulus", example=1e9, unit="Pa")
    positive(rms_gradient, "rms_gradient", example="0.1 (dimensionless)")
    (p0,) = checked_pressures(mean_pressure)
    sigma = np.atleast_1d(np.asarray(pressure, dtype=float))
    variance = 0.25 * (contact_modulus * rms_gradient) ** 2
    density = (
        np.exp(-((sigma - p0) ** 2) / (2 * variance)) - np.exp(-((sigma + p0) ** 2) / (2 * variance))
    ) / (math.sqrt(2 * math.pi * variance))
    return np.where(sigma >= 0, density, 0.0)


_LOWEST, _HIGHEST, _POINTS = -30.0, 2.5, 40_001
"""The table of J: ln x from -30 to 2.5 (x from 1e-13 to 12; beyond, exp(-x^2) < 1e-60)."""


@cache
def _separation_table(gamma: float) -> tuple[np.ndarray, np.ndarray]:
    r"""Return ln x and :math:`J(x)` on a grid of ln x (module notes), by the trapezoidal rule in ln x."""
    t = np.linspace(_LOWEST, _HIGHEST, _POINTS)
    x = np.exp(t)
    integrand = (gamma + 3.0 * (1.0 - gamma) * special.erf(x) ** 2) * np.exp(-(x**2))  # d(ln x) = dx / x
    steps = 0.5 * (integrand[1:] + integrand[:-1]) * np.diff(t)
    tail = np.concatenate([np.cumsum(steps[::-1])[::-1], [0.0]])
    return t, tail


def _separation_integral(x: np.ndarray, gamma: float) -> np.ndarray:
    """J(x) for x > 0: the table, with J ~ J(x_min) + gamma ln(x_min / x) below it (erf -> 0, exp -> 1)."""
    t, table = _separation_table(gamma)
    log_x = np.log(x)
    inside = np.interp(np.clip(log_x, _LOWEST, _HIGHEST), t, table)
    return inside + gamma * np.maximum(_LOWEST - log_x, 0.0)


def persson_mean_separation(
    mean_pressure, *, contact_modulus: float, spectrum: Spectrum, gamma: float = GAMMA
) -> np.ndarray:
    r"""Persson's (2007) mean interfacial separation :math:`\bar u(p_0)` [m] (module notes).

    .. math::

        \bar u = \frac{1}{2\sqrt\pi} \sum_{\mathbf q} |\mathbf q|\, v(\mathbf q)\, w(q)\,
        J\!\left(\frac{w(q)\, p_0}{E^*}\right), \qquad w(q) = \frac{\sqrt2}{g(q)}

    the sum over the modes of the grid of
    :math:`\sqrt\pi \int \mathrm dq\, q^2 C_\mathrm P w \int_{p_0}^\infty \ldots`, with :math:`g(q)`
    the rms gradient of the modes up to :math:`|\mathbf q|` (itself included).

    Parameters
    ----------
    mean_pressure : float or array_like
        :math:`p_0` [Pa], > 0 (the separation diverges logarithmically at zero load).
    contact_modulus : float
        :math:`E^*` [Pa].
    spectrum : Spectrum
        The surface's modes (:func:`~roughcontact.theory.spectrum.surface_spectrum`).
    gamma : float
        Persson's correction of the energy of partly touching bands (0.4 in Persson 2007; 1 leaves
        it out, 0 < gamma <= 1).

    Returns
    -------
    ndarray
        :math:`\bar u` [m] per pressure (at least 1D): the distance between the flat and the mean
        plane of the deformed surface.

    References
    ----------
    Persson (2007) doi:10.1103/PhysRevLett.99.125502; Almqvist et al. (2011)
    doi:10.1016/j.jmps.2011.08.004
    """
    positive(contact_modulus, "contact_modulus", example=1e9, unit="Pa")
    if not (math.isfinite(gamma) and 0 < gamma <= 1):
        raise InputError("gamma", f"must lie in (0, 1], got {gamma!r}.", "Persson (2007) uses 0.4.")
    pressure = checked_pressures(mean_pressure)
    if np.any(pressure <= 0):
        raise InputError(
            "mean_pressure", "the mean separation diverges at zero load.", "give pressures > 0 Pa."
        )
    carried = spectrum.variance > 0
    q, v = spectrum.q[carried], spectrum.variance[carried]
    w = math.sqrt(2.0) / spectrum.cumulative_gradient(q)
    weight = q * v * w / (2.0 * math.sqrt(math.pi))
    return np.array([float(weight @ _separation_integral(w * p / contact_modulus, gamma)) for p in pressure])
