r"""The modes of a surface as the theories of rough contact read them: wavevectors and their power.

Persson's theory, Bush-Gibson-Thomas and Greenwood-Williamson all start from the power spectrum of
the surface. :func:`surface_spectrum` takes it from the 2D power spectral density of
:func:`roughcontact.topography.statistics.psd_2d` (the normalisation of Jacobs, Junge and Pastewka
2017, the one ``roughcontact inspect`` reports), and keeps each Fourier mode
:math:`\mathbf q = (q_x, q_y)` of the grid with the mean-square height it carries,

.. math::

    v(\mathbf q) = C(\mathbf q)\,\frac{\Delta q_x \Delta q_y}{(2\pi)^2} = \frac{C(\mathbf q)}{L_x L_y},
    \qquad \langle h^2\rangle = \sum_{\mathbf q \ne 0} v(\mathbf q)

(Parseval, exact on the grid; Persson's own spectrum is :math:`C_\mathrm{P} = C / (2\pi)^2`, so
:math:`v = C_\mathrm{P}\, \mathrm d^2 q`). The moments follow with the continuum derivative of each
mode, as the boundary-element kernel :math:`2/(E^* |\mathbf q|)` treats the modes:

.. math::

    g^2 = \langle |\nabla h|^2 \rangle = \sum_{\mathbf q} |\mathbf q|^2 v(\mathbf q), \qquad
    m_0 = \sum v, \quad
    m_2 = \tfrac12 \sum (q_x^2 + q_y^2)\, v = \tfrac12 g^2, \quad
    m_4 = \tfrac12 \sum (q_x^4 + q_y^4)\, v

with :math:`m_2` and :math:`m_4` per direction as in paper 002's eqs. 1-3
(:func:`~roughcontact.topography.statistics.spectral_moments`, which takes finite differences
instead: on a well-resolved surface they agree, on a surface with power up to the pixel the finite
differences read low, forward ones by :math:`(\sin(q\Delta/2)/(q\Delta/2))^2`). :math:`g` is the rms
gradient of the 2D surface, :math:`\sqrt 2` times the rms slope of one profile,
:math:`g = \sqrt{2 m_2}`: the :math:`\bar g` of the reduced pressure :math:`p/(E^* \bar g)` of Hyun et
al. (2004) and Persson (2006).

A periodic surface's spectrum is its own; a window of a larger surface (not periodic) is taken
with a Hann window (``psd_2d``'s default, scaled to keep the mean square height) so that the jump
across its edges does not leak power to every wavevector.

References
----------
Jacobs, T. D. B., Junge, T. and Pastewka, L. (2017). Quantitative characterization of surface
topography using spectral analysis. Surf. Topogr.: Metrol. Prop. 5, 013001.
doi:10.1088/2051-672X/aa51f8

Persson, B. N. J. (2006). Contact mechanics for randomly rough surfaces. Surf. Sci. Rep. 61, 201-227.
doi:10.1016/j.surfrep.2006.04.001
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..topography import Topography
from ..topography.statistics import SpectralMoments, psd_2d
from ..topography.surface import topography_argument

__all__ = ["NO_POWER", "Spectrum", "surface_spectrum"]

NO_POWER = 1e-12
"""A mode below this fraction of the strongest mode's power carries none (round-off at a band's end)."""


@dataclass(frozen=True)
class Spectrum:
    r"""The Fourier modes of a map and the mean-square height each carries (SI).

    Attributes
    ----------
    q : ndarray
        Wavevector magnitudes :math:`|\mathbf q|` [rad/m] of the modes, ascending, all > 0.
    variance : ndarray
        Mean-square height of each mode :math:`v = C/(L_x L_y)` [m^2].
    m4 : float
        Fourth spectral moment per direction :math:`\tfrac12\sum (q_x^4 + q_y^4) v` [1/m^2].
    window : str or None
        The window the spectrum was taken with (``"hann"`` for a window of a larger surface).
    """

    q: np.ndarray
    variance: np.ndarray
    m4: float
    window: str | None = None

    @property
    def m0(self) -> float:
        """Mean-square height [m^2]."""
        return float(self.variance.sum())

    @property
    def mean_square_gradient(self) -> float:
        r""":math:`g^2 = \sum |\mathbf q|^2 v` [-]."""
        return float(np.sum(self.q**2 * self.variance))

    @property
    def rms_gradient(self) -> float:
        r"""The rms gradient :math:`g = \sqrt{\langle|\nabla h|^2\rangle}` of the 2D surface [-]."""
        return math.sqrt(self.mean_square_gradient)

    @property
    def m2(self) -> float:
        """Mean-square slope per direction, ``g**2 / 2`` [-]."""
        return 0.5 * self.mean_square_gradient

    @property
    def moments(self) -> SpectralMoments:
        """m0 [m^2], m2 [-], m4 [1/m^2] of the modes (continuum derivatives)."""
        return SpectralMoments(m0=self.m0, m2=self.m2, m4=self.m4)

    @property
    def _carried(self) -> np.ndarray:
        """The modes that carry power: above :data:`NO_POWER` of the strongest (round-off is none)."""
        return self.variance > NO_POWER * self.variance.max()

    @property
    def lowest(self) -> float:
        """The lowest wavevector that carries power [rad/m] (Persson's :math:`q_0`)."""
        return float(self.q[self._carried][0])

    @property
    def highest(self) -> float:
        """The highest wavevector that carries power [rad/m] (Persson's :math:`q_1`)."""
        return float(self.q[self._carried][-1])

    def cumulative_gradient(self, q) -> np.ndarray:
        r"""Return the rms gradient of the modes up to ``q``, :math:`(\sum_{|\mathbf q'|\le q} q'^2 v)^{1/2}`.

        Parameters
        ----------
        q : float or array_like
            Wavevector magnitudes [rad/m].

        Returns
        -------
        ndarray
            :math:`g(q)` [-], the shape of ``q`` (at least 1D).
        """
        cumulative = np.concatenate([[0.0], np.cumsum(self.q**2 * self.variance)])
        index = np.searchsorted(self.q, np.atleast_1d(np.asarray(q, dtype=float)), side="right")
        return np.sqrt(cumulative[index])


def surface_spectrum(topography: Topography, *, window: str | None = "default") -> Spectrum:
    """Return the modes of a map and their power (module notes).

    Parameters
    ----------
    topography : Topography
        A map (heights [m]).
    window : {"default", "hann", None}
        As in :func:`~roughcontact.topography.statistics.psd_2d`: "default" is none for a periodic
        surface and Hann for a window of a larger one.

    Returns
    -------
    Spectrum

    Raises
    ------
    InputError
        For a profile (the theories here are of the contact of a 2D surface) or a flat surface.

    References
    ----------
    Jacobs, Junge and Pastewka (2017) doi:10.1088/2051-672X/aa51f8
    """
    topography = topography_argument(topography, "topography")
    if topography.dim != 2:
        raise InputError(
            "topography",
            "the theories of rough contact (Persson, Bush-Gibson-Thomas, Greenwood-Williamson) are of a "
            "2D surface; this is a profile.",
            "pass a map.",
        )
    qx, qy, psd = psd_2d(topography, window=window)
    used = None if window == "default" and topography.periodic else "hann" if window == "default" else window
    variance = psd / topography.area
    qx2, qy2 = np.meshgrid(qx**2, qy**2, indexing="ij")
    magnitude = np.sqrt(qx2 + qy2).ravel()
    keep = magnitude > 0
    order = np.argsort(magnitude[keep], kind="stable")
    q, power = magnitude[keep][order], variance.ravel()[keep][order]
    if not np.any(power > 0):
        raise InputError("topography", "the surface is flat: it has no spectrum.", "pass a rough surface.")
    m4 = 0.5 * float(np.sum((qx2**2 + qy2**2) * variance))
    return Spectrum(q=q, variance=power, m4=m4, window=used)
