r"""Statistics of a :class:`~roughcontact.topography.surface.Topography`, in SI units.

Amplitude parameters, slopes, curvatures, spectral moments, McCool asperity parameters, power
spectra, autocorrelation and summits.

All inputs are SI (heights and lengths in metres) and so are all outputs.

Conventions
-----------
* Every amplitude quantity is taken about the mean plane: ``z = heights - heights.mean()``.
  No tilt is removed here; level first (:func:`roughcontact.topography.process.level`).
* Two families of roughness names, as a profilometer and an areal instrument report them
  (:func:`summary`). Areal parameters of ISO 25178-2 (Sa, Sq, Ssk, Sku, Sz, Sdq, Sdr) use every
  point of a map. Profile parameters of ISO 4287 (Ra, Rq, Rsk, Rku, Rt, Rdq) use the profiles
  along x (the first axis), each about its own mean line, pooled over all the profiles of a map
  (:func:`profile_parameters`; the "from profile" convention of SurfaceTopography's ``Rq``). For
  a profile the two readings coincide and only the R names are given. On a map Rq differs from
  Sq: the profile means, and any variation across the profiles, are not in Rq.
* Finite differences. Second derivatives always use the compact centred stencil
  ``(z[i+1] - 2 z[i] + z[i-1]) / h**2`` (O(h^2); for a sinusoid of wavevector k the mean square
  is low by ``(sin(kh/2)/(kh/2))**4 ~ 1 - (kh)**2/6``). Being centred, the x and y terms of the
  Laplacian sit on the same point. First derivatives (``derivative=``):

  ``"forward"`` (default)
      ``(z[i+1] - z[i]) / h``: the slope of the segment between two neighbours, as in
      SurfaceTopography. Its mean square is low by ``(sin(kh/2)/(kh/2))**2 ~ 1 - (kh)**2/12``:
      O(h^2) for the averages used here, 4x smaller than the central error, and it still sees the
      Nyquist wave (0.64 of its slope). It is the default because rough surfaces carry power up to
      the pixel scale: on a self-affine map (H = 0.8, power up to the corners of the grid) the
      central rms slope is 11 % below the forward one (benchmarks/statistics.py).
  ``"central"``
      ``(z[i+1] - z[i-1]) / (2 h)`` (np.gradient in the interior): centred on the grid point, but
      its mean square is low by ``(sin(kh)/(kh))**2 ~ 1 - (kh)**2/3`` and it is blind to the
      Nyquist wave.

  Periodic surfaces wrap around (every point has a derivative); on non-periodic surfaces only
  the points whose whole stencil lies on the grid are averaged (no one-sided edge stencils).
* Power spectra use the wavevector ``q = 2 pi / wavelength`` [rad/m] and the normalisation of
  Jacobs, Junge and Pastewka (2017): ``h~(q) = dx dy sum h exp(-i q.r)`` and
  ``C(q) = |h~(q)|**2 / area``, so that Parseval reads
  ``m0 = sum_q C(q) dqx dqy / (2 pi)**2`` (2D, exact on the grid) and
  ``m0 = sum_q C1D(q) dq / (2 pi)`` over the two-sided spectrum (1D).

References
----------
Nayak, P. R. (1971). Random process model of rough surfaces. J. Lubr. Technol. 93, 398-407.
doi:10.1115/1.3451150

McCool, J. I. (1986). Comparison of models for the contact of rough surfaces. Wear 107, 37-60.
doi:10.1016/0043-1648(86)90045-1

Jacobs, T. D. B., Junge, T. and Pastewka, L. (2017). Quantitative characterization of surface
topography using spectral analysis. Surf. Topogr.: Metrol. Prop. 5, 013001.
doi:10.1088/2051-672X/aa51f8

ISO 25178-2:2012 (areal) and ISO 4287:1997 (profile) surface texture parameters.

Seed paper 002, eqs. 1-5 (spectral moments and McCool parameters of the SU-8 island).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy
from scipy import fft

from ..checks import positive
from ..errors import InputError
from .plausible import is_flat
from .surface import Topography, topography_argument

__all__ = [
    "McCoolParameters",
    "SpectralMoments",
    "Summits",
    "autocorrelation",
    "mccool_parameters",
    "mccool_parameters_of",
    "psd_1d",
    "psd_2d",
    "psd_radial",
    "profile_parameters",
    "ra",
    "rku",
    "rms_curvature",
    "rms_slope",
    "rq",
    "rsk",
    "rz",
    "sdr",
    "spectral_moments",
    "summary",
    "summits",
]

DERIVATIVES = ("central", "forward")
WINDOWS = ("hann", None)
MCCOOL_MIN_BANDWIDTH = 0.8968  # sigma_s = 0 at this bandwidth (McCool 1986; paper 002 eq. 5)


# --- amplitude parameters ------------------------------------------------------------------------


def _centred(topography: Topography) -> np.ndarray:
    """Heights about the mean plane [m]."""
    return topography.heights - topography.heights.mean()


def ra(topography: Topography) -> float:
    """Arithmetic mean deviation over every point [m]: ``mean(|z - mean(z)|)``.

    Sa of ISO 25178-2 for a map, Ra of ISO 4287 for a profile. (It is also what AFM software
    labels "Ra" for an image, the reading :func:`~roughcontact.topography.process.scale_to_ra`
    takes for paper 000's samples.)
    """
    return float(np.abs(_centred(topography)).mean())


def rq(topography: Topography) -> float:
    """Root mean square height over every point [m]: ``sqrt(mean((z - mean(z))**2)) = sqrt(m0)``.

    Sq of ISO 25178-2 for a map, Rq of ISO 4287 for a profile.
    """
    return float(np.sqrt(np.mean(_centred(topography) ** 2)))


def _standardised_moment(z: np.ndarray, order: int, heights: np.ndarray) -> float:
    """``<z**order> / <z**2>**(order/2)`` of heights ``z`` about their mean line(s); flat -> InputError."""
    variance = np.mean(z**2)
    if variance <= (np.finfo(float).eps * np.abs(heights).max()) ** 2:
        raise InputError(
            "topography",
            "the surface is flat (Rq = 0): skewness and kurtosis are undefined.",
            "pass a rough surface.",
        )
    return float(np.mean(z**order) / variance ** (order / 2))


def rsk(topography: Topography) -> float:
    """Skewness over every point (Ssk of a map, Rsk of a profile), dimensionless.

    ``mean(z**3) / Rq**3`` with z about the mean.

    Raises
    ------
    InputError
        For a flat surface (Rq = 0).
    """
    return _standardised_moment(_centred(topography), 3, topography.heights)


def rku(topography: Topography) -> float:
    """Kurtosis over every point (Sku of a map, Rku of a profile), dimensionless.

    ``mean(z**4) / Rq**4`` (3 for a Gaussian surface).

    Raises
    ------
    InputError
        For a flat surface (Rq = 0).
    """
    return _standardised_moment(_centred(topography), 4, topography.heights)


def rz(topography: Topography) -> float:
    """Peak-to-valley height [m]: ``max(z) - min(z)`` over the whole profile or map.

    This is ISO 25178-2 Sz for maps (maximum height of the scale-limited surface) and the total
    height Rt of ISO 4287 for profiles; it is *not* the ISO 4287 Rz averaged over five sampling
    lengths. It does not depend on the mean plane.
    """
    return float(np.ptp(topography.heights))


# --- finite differences --------------------------------------------------------------------------


def _check_derivative(derivative: str) -> None:
    if derivative not in DERIVATIVES:
        raise InputError(
            "derivative", f"unknown finite-difference scheme {derivative!r}.", f"choose one of {DERIVATIVES}."
        )


def _shifted(heights: np.ndarray, axis: int, shift: int, periodic: bool) -> np.ndarray:
    """Return ``heights[i + shift]`` along ``axis``; wrapped if periodic, else zero-filled (masked later)."""
    if periodic:
        return np.roll(heights, -shift, axis=axis)
    out = np.zeros_like(heights)
    n = heights.shape[axis]
    src = [slice(None)] * heights.ndim
    dst = [slice(None)] * heights.ndim
    src[axis] = slice(max(shift, 0), n + min(shift, 0))
    dst[axis] = slice(max(-shift, 0), n - max(shift, 0))
    out[tuple(dst)] = heights[tuple(src)]
    return out


_FIRST = {"central": ((1, 0.5), (-1, -0.5)), "forward": ((1, 1.0), (0, -1.0))}  # (shift, weight) / h
_SECOND = ((1, 1.0), (0, -2.0), (-1, 1.0))  # (shift, weight) / h**2


def _derivatives(
    topography: Topography, order: int, derivative: str = "forward"
) -> tuple[list[np.ndarray], np.ndarray]:
    """Finite-difference derivatives of order 1 or 2 along each axis and the mask of valid points.

    Returns one array per axis (``d^order z / dx_k^order`` [m^(1-order)]) and a boolean mask of the
    points where every stencil lies on the grid (all True for a periodic surface). ``derivative``
    picks the first-derivative scheme; second derivatives are always centred.
    """
    _check_derivative(derivative)
    heights = topography.heights
    stencil = _FIRST[derivative] if order == 1 else _SECOND
    valid = np.ones(heights.shape, dtype=bool)
    slopes = []
    for axis, spacing in enumerate(topography.spacing):
        slopes.append(
            sum(w * _shifted(heights, axis, s, topography.periodic) for s, w in stencil) / spacing**order
        )
        if not topography.periodic:
            low, high = min(s for s, _ in stencil), max(s for s, _ in stencil)
            edge = [slice(None)] * heights.ndim
            edge[axis] = slice(0, -low) if low < 0 else slice(0, 0)
            valid[tuple(edge)] = False
            edge[axis] = slice(heights.shape[axis] - high, None)
            valid[tuple(edge)] = False
    if not valid.any():
        raise InputError(
            "topography",
            f"grid {heights.shape} is too small for {derivative} differences "
            f"of order {order} on a non-periodic surface.",
            "use a larger grid (at least 3 points per axis).",
        )
    return slopes, valid


def rms_slope(topography: Topography, *, derivative: str = "forward") -> float:
    r"""Root mean square slope (gradient) [dimensionless].

    .. math:: h'_\mathrm{rms} = \sqrt{\langle (\partial z/\partial x)^2 + (\partial z/\partial y)^2\rangle}

    (Sdq of ISO 25178-2 for maps, Rdq of ISO 4287 for profiles: only the x term). For maps this is
    ``sqrt(2 m2)`` with m2 of paper 002 eq. 2; for profiles ``sqrt(m2)``.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).
    derivative : {"central", "forward"}
        Finite-difference scheme, see the module notes.

    References
    ----------
    ISO 25178-2:2012 (Sdq); Jacobs et al. (2017) doi:10.1088/2051-672X/aa51f8
    """
    slopes, valid = _derivatives(topography, 1, derivative)
    return float(np.sqrt(np.mean(sum(s**2 for s in slopes)[valid])))


def rms_curvature(topography: Topography) -> float:
    r"""Root mean square curvature [1/m].

    Maps: the rms of the mean curvature in the small-slope approximation,

    .. math:: \kappa_\mathrm{rms} = \sqrt{\langle (\nabla^2 z / 2)^2 \rangle}

    (half the rms Laplacian, the definition of SurfaceTopography's ``rms_curvature_from_area`` and
    of Jacobs et al. 2017); profiles: ``sqrt(<(d^2 z/dx^2)^2>)`` (Rddq), which equals ``sqrt(m4)``.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]); second derivatives by the centred three-point stencil.

    References
    ----------
    Jacobs, Junge and Pastewka (2017), Surf. Topogr.: Metrol. Prop. 5, 013001.
    doi:10.1088/2051-672X/aa51f8
    """
    curvatures, valid = _derivatives(topography, 2)
    laplacian = sum(curvatures)
    factor = 0.5 if topography.dim == 2 else 1.0
    return float(factor * np.sqrt(np.mean(laplacian[valid] ** 2)))


def sdr(topography: Topography) -> float:
    r"""Developed interfacial area ratio Sdr of a map (ISO 25178-2), dimensionless (0.01 is 1 %).

    .. math:: S_{dr} = \left\langle \sqrt{1 + (\partial z/\partial x)^2 + (\partial z/\partial y)^2}
              \right\rangle - 1

    the true area of the surface over its projected area, less one, with forward differences
    (each pixel's two segment slopes; on a non-periodic map the last row and column are left out).
    It grows as Sdq^2 / 2 for small slopes.

    Raises
    ------
    InputError
        For a profile (Sdr is an areal parameter).
    """
    if topography.dim != 2:
        raise InputError("topography", "Sdr is an areal parameter; this is a profile.", "pass a map.")
    slopes, valid = _derivatives(topography, 1, "forward")
    return float(np.mean(np.sqrt(1.0 + sum(s**2 for s in slopes))[valid]) - 1.0)


def profile_parameters(topography: Topography) -> dict[str, float]:
    """ISO 4287 profile parameters along x, pooled over the profiles of a map, SI.

    Each profile (a line of the first axis; for a map ``heights[:, j]``) is taken about its own
    mean line, and the averages run over every point of every profile, as SurfaceTopography's
    ``Rq`` does (so Rq**2 is the mean of the profiles' Rq**2):

    ``Ra = <|z|>``, ``Rq = sqrt(<z**2>)``, ``Rsk = <z**3> / Rq**3``, ``Rku = <z**4> / Rq**4``,
    ``Rdq = sqrt(<(dz/dx)**2>)`` (forward differences) and ``Rt`` the mean over the profiles of
    their highest peak to lowest valley (over the whole profile: the evaluation length is the scan,
    no sampling lengths are cut, so no ISO Rz is given). For a single profile these are the
    parameters of that profile.

    Returns
    -------
    dict of str to float
        "Ra", "Rq" [m], "Rsk", "Rku" (left out when a profile is flat, as in :func:`summary`),
        "Rt" [m], "Rdq" [dimensionless].
    """
    heights = topography.heights
    z = heights - heights.mean(axis=0, keepdims=True)
    if topography.periodic:
        dzdx = (np.roll(heights, -1, axis=0) - heights) / topography.spacing[0]
    else:
        dzdx = np.diff(heights, axis=0) / topography.spacing[0]
    result = {"Ra": float(np.abs(z).mean()), "Rq": float(np.sqrt(np.mean(z**2)))}
    try:
        result |= {"Rsk": _standardised_moment(z, 3, heights), "Rku": _standardised_moment(z, 4, heights)}
    except InputError:
        pass  # flat profiles: skewness and kurtosis undefined, left out as documented
    return result | {
        "Rt": float(np.ptp(heights, axis=0).mean()),
        "Rdq": float(np.sqrt(np.mean(dzdx**2))),
    }


# --- spectral moments and McCool -----------------------------------------------------------------


@dataclass(frozen=True)
class SpectralMoments:
    """Spectral moments of a surface (paper 002 equations 1-3), SI.

    Attributes
    ----------
    m0 : float
        Mean square height [m^2].
    m2 : float
        Mean square slope per direction [dimensionless].
    m4 : float
        Mean square curvature per direction [1/m^2].
    """

    m0: float
    m2: float
    m4: float


def spectral_moments(topography: Topography, *, derivative: str = "forward") -> SpectralMoments:
    r"""Zeroth, second and fourth spectral moments, exactly as paper 002 equations 1-3.

    .. math::

        m_0 = \langle z^2 \rangle, \quad
        m_2 = \tfrac12\left(\langle z_x^2\rangle + \langle z_y^2\rangle\right), \quad
        m_4 = \tfrac12\left(\langle z_{xx}^2\rangle + \langle z_{yy}^2\rangle\right)

    with z about its mean and the averages over the grid (over the points where the stencil fits
    for a non-periodic surface). For a profile only the x terms are kept (no factor 1/2). For an
    isotropic surface these are the moments of a single profile (Nayak 1971).

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).
    derivative : {"central", "forward"}
        First-derivative scheme for m2 (module notes); m4 always uses the centred second
        difference.

    Returns
    -------
    SpectralMoments
        m0 [m^2], m2 [-], m4 [1/m^2].

    References
    ----------
    Seed paper 002, eqs. 1-3. Nayak (1971) doi:10.1115/1.3451150. McCool (1986)
    doi:10.1016/0043-1648(86)90045-1
    """
    topography = topography_argument(topography, "topography")
    m0 = float(np.mean(_centred(topography) ** 2))
    averages = []
    for order in (1, 2):
        derivatives, valid = _derivatives(topography, order, derivative)
        averages.append(float(np.mean([np.mean(d[valid] ** 2) for d in derivatives])))
    return SpectralMoments(m0=m0, m2=averages[0], m4=averages[1])


@dataclass(frozen=True)
class McCoolParameters:
    r"""Asperity (summit) parameters of a Gaussian isotropic surface from its spectral moments, SI.

    Attributes
    ----------
    bandwidth : float
        Nayak's bandwidth parameter :math:`\alpha = m_0 m_4 / m_2^2` [-].
    summit_density : float
        Summit density :math:`\eta = m_4 / (6\pi\sqrt3\, m_2)` [1/m^2].
    summit_radius : float
        Mean summit radius of curvature :math:`R = 0.375\sqrt{\pi/m_4}` [m] (paper 002 eq. 4).
    summit_height_std : float
        Standard deviation of summit heights
        :math:`\sigma_s = \sqrt{1 - 0.8968/\alpha}\,\sqrt{m_0}` [m] (paper 002 eq. 5).
    summit_mean_offset : float
        Height of the summits' mean plane above the surface mean plane,
        :math:`y_s = 4\sqrt{m_0}/\sqrt{\pi\alpha}` [m].
    """

    bandwidth: float
    summit_density: float
    summit_radius: float
    summit_height_std: float
    summit_mean_offset: float


def mccool_parameters(*, m0: float, m2: float, m4: float) -> McCoolParameters:
    r"""McCool's asperity parameters from the spectral moments (paper 002 equations 4-5).

    .. math::

        \alpha = \frac{m_0 m_4}{m_2^2}, \quad
        \eta = \frac{m_4}{6\pi\sqrt3\, m_2}, \quad
        R = 0.375\sqrt{\frac{\pi}{m_4}}, \quad
        \sigma_s = \sqrt{1 - \frac{0.8968}{\alpha}}\sqrt{m_0}, \quad
        y_s = \frac{4\sqrt{m_0}}{\sqrt{\pi\alpha}}

    The density is Nayak's (1971) summit density of an isotropic Gaussian surface; R, sigma_s and
    y_s are McCool's (1986) large-bandwidth approximations for the summits (R is the mean summit
    radius, ``y_s`` the distance from the surface mean plane up to the mean plane of the summits).
    Paper 002 prints eqs. 4-5 and reproduces R = 5.08 um and sigma_s = 0.0431 um from its moments.

    Parameters
    ----------
    m0 : float
        Mean square height [m^2].
    m2 : float
        Mean square slope per direction [dimensionless].
    m4 : float
        Mean square curvature per direction [1/m^2].

    Returns
    -------
    McCoolParameters
        bandwidth [-], summit_density [1/m^2], summit_radius [m], summit_height_std [m],
        summit_mean_offset [m].

    Raises
    ------
    InputError
        A moment that is not positive and finite (field: that moment), or a bandwidth below 0.8968
        where sigma_s would be imaginary (field: ``m2``; the three moments are then inconsistent,
        e.g. from a grid too coarse for the curvatures).

    References
    ----------
    McCool, J. I. (1986). Wear 107, 37-60. doi:10.1016/0043-1648(86)90045-1
    Nayak, P. R. (1971). J. Lubr. Technol. 93, 398-407. doi:10.1115/1.3451150
    Seed paper 002, eqs. 4-5.
    """
    m0 = positive(m0, "m0", example="2.1e-15", unit="m^2")
    m2 = positive(m2, "m2", example="2.3e-3 (mean square slope, dimensionless)")
    m4 = positive(m4, "m4", example="1.7e10", unit="1/m^2")
    bandwidth = m0 * m4 / m2**2
    if bandwidth < MCCOOL_MIN_BANDWIDTH:
        raise InputError(
            "m2",
            f"bandwidth alpha = m0 m4 / m2^2 = {bandwidth:.4g} is below "
            f"{MCCOOL_MIN_BANDWIDTH}, so sigma_s is undefined.",
            "check the units of the moments (SI: m^2, -, 1/m^2) and that they come from one "
            "surface on a grid fine enough to resolve its curvatures.",
        )
    return McCoolParameters(
        bandwidth=bandwidth,
        summit_density=m4 / (6.0 * math.pi * math.sqrt(3.0) * m2),
        summit_radius=0.375 * math.sqrt(math.pi / m4),
        summit_height_std=math.sqrt(1.0 - MCCOOL_MIN_BANDWIDTH / bandwidth) * math.sqrt(m0),
        summit_mean_offset=4.0 * math.sqrt(m0) / math.sqrt(math.pi * bandwidth),
    )


def mccool_parameters_of(topography: Topography, *, derivative: str = "forward") -> McCoolParameters:
    """McCool parameters of a surface: :func:`spectral_moments` then :func:`mccool_parameters`.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).
    derivative : str
        Finite difference of the slopes and curvatures, as in :func:`spectral_moments`.

    Raises
    ------
    InputError
        (field ``topography``) for a flat surface or one whose moments give alpha < 0.8968.
    """
    moments = spectral_moments(topography, derivative=derivative)
    try:
        return mccool_parameters(m0=moments.m0, m2=moments.m2, m4=moments.m4)
    except InputError as error:
        raise InputError(
            "topography",
            f"its spectral moments are unusable ({error.field}: {error.problem})",
            "pass a rough, non-flat surface sampled finely enough to resolve its curvatures.",
        ) from error


# --- power spectra --------------------------------------------------------------------------------


def _default_window(topography: Topography, window: str | None) -> str | None:
    if window == "default":
        return None if topography.periodic else "hann"
    if window not in WINDOWS:
        raise InputError("window", f"unknown window {window!r}.", "choose 'hann', None or 'default'.")
    return window


def _windowed(topography: Topography, axes: tuple[int, ...], window: str | None) -> np.ndarray:
    """Mean-removed heights, multiplied by a Hann window along ``axes`` normalised to mean(w^2) = 1."""
    z = _centred(topography)
    if window is None:
        return z
    for axis in axes:
        w = scipy.signal.windows.hann(z.shape[axis], sym=False)
        w /= np.sqrt(np.mean(w**2))
        z = z * np.expand_dims(w, tuple(a for a in range(z.ndim) if a != axis))
    return z


def psd_1d(
    topography: Topography, *, window: str | None = "default", workers: int = -1
) -> tuple[np.ndarray, np.ndarray]:
    r"""One-dimensional power spectral density along x (averaged over the y-lines of a map).

    .. math:: C^\mathrm{1D}(q) = \frac{1}{L_x}\left|\Delta x \sum_i z_i e^{-i q x_i}\right|^2

    with z the heights about the global mean plane (not per line, so that Parseval gives the m0 of
    the whole surface). The spectrum is two-sided and even; the non-negative wavevectors are
    returned. Parseval (no window): ``m0 = (dq / 2 pi) sum_{all q} C1D(q)``, i.e.
    ``m0 = (dq / 2 pi) (C[0] + 2 sum C[1:-1] + C[-1])`` for even n (last entry: Nyquist, counted
    once) and ``(dq / 2 pi) (C[0] + 2 sum C[1:])`` for odd n, with ``dq = 2 pi / Lx``.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).
    window : {"default", "hann", None}
        "default": none for periodic surfaces, "hann" for non-periodic ones (to suppress the
        leakage of the jump at the edges). The Hann window is scaled to mean(w^2) = 1 so the
        spectrum keeps the surface's mean square height on average (not exactly).
    workers : int
        Threads for scipy.fft (-1: all cores).

    Returns
    -------
    q : ndarray
        Wavevectors ``2 pi k / Lx`` [rad/m], k = 0 .. n//2.
    psd : ndarray
        C1D(q) [m^3].

    References
    ----------
    Jacobs, Junge and Pastewka (2017) doi:10.1088/2051-672X/aa51f8
    """
    window = _default_window(topography, window)
    z = _windowed(topography, (0,), window)
    n, spacing = topography.shape[0], topography.spacing[0]
    spectrum = np.abs(fft.rfft(z, axis=0, workers=workers)) ** 2 * spacing**2 / topography.size[0]
    psd = spectrum.mean(axis=1) if topography.dim == 2 else spectrum
    q = 2.0 * np.pi * fft.rfftfreq(n, d=spacing)
    return q, psd


def psd_2d(
    topography: Topography, *, window: str | None = "default", workers: int = -1
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r"""Two-dimensional power spectral density on the full DFT grid (numpy FFT order).

    .. math:: C^\mathrm{2D}(\mathbf q) = \frac{1}{L_x L_y}\left|\Delta x\Delta y
              \sum_{ij} z_{ij} e^{-i\mathbf q\cdot\mathbf r_{ij}}\right|^2

    Parseval (no window) is exact: ``m0 = psd.sum() * dqx * dqy / (2 pi)**2`` with
    ``dqx = 2 pi / Lx``, ``dqy = 2 pi / Ly``.

    Parameters
    ----------
    topography : Topography
        A map (heights [m]).
    window : {"default", "hann", None}
        As in :func:`psd_1d`; the Hann window is the product of one per axis.
    workers : int
        Threads for scipy.fft (-1: all cores).

    Returns
    -------
    qx, qy : ndarray
        Wavevectors [rad/m] along x and y (``2 pi fftfreq``).
    psd : ndarray, shape (nx, ny)
        C2D(q) [m^4].

    Raises
    ------
    InputError
        For a profile (use :func:`psd_1d`).

    References
    ----------
    Jacobs, Junge and Pastewka (2017) doi:10.1088/2051-672X/aa51f8
    """
    if topography.dim != 2:
        raise InputError("topography", "a 2D PSD needs a map, got a profile.", "use psd_1d for profiles.")
    window = _default_window(topography, window)
    z = _windowed(topography, (0, 1), window)
    psd = np.abs(fft.fft2(z, workers=workers)) ** 2 * topography.pixel_area**2 / topography.area
    qx, qy = (
        2.0 * np.pi * fft.fftfreq(n, d=h) for n, h in zip(topography.shape, topography.spacing, strict=True)
    )
    return qx, qy, psd


def psd_radial(
    topography: Topography,
    nbins: int | None = None,
    *,
    ring_ratio: float | None = None,
    window: str | None = "default",
    workers: int = -1,
) -> tuple[np.ndarray, np.ndarray]:
    r"""Radially averaged 2D power spectral density :math:`C^\mathrm{iso}(q)` of a map.

    The wavevectors of :func:`psd_2d` (except q = 0, which carries only the removed mean) are put
    into ``nbins`` equal-width bins of :math:`|\mathbf q|` from 0 to the largest :math:`|\mathbf q|`
    on the grid (corners included, so every wavevector is counted once); each bin returns the mean
    :math:`|\mathbf q|` and the mean C2D of its wavevectors; empty bins are dropped. Isotropic
    Parseval then reads approximately ``m0 ~ integral C(q) q dq / (2 pi)`` (exact only as a sum over
    the full grid, see :func:`psd_2d`). Above the Nyquist wavevector ``pi / max(spacing)`` the bins
    see only the corners of the grid: fit exponents below it.

    Parameters
    ----------
    topography : Topography
        A map (heights [m]).
    nbins : int, optional
        Number of bins; default ``max(shape) // 2``.
    ring_ratio : float, optional
        Instead of equal-width bins, rings whose outer ``|q|`` is ``ring_ratio`` (> 1) times their inner
        one, from the lowest wavevector up: narrow on a log scale, so a ring's mean C is C at its
        mean q even where C falls steeply, and the lowest rings hold single lattice circles.
    window, workers
        As in :func:`psd_2d`.

    Returns
    -------
    q : ndarray
        Mean wavevector magnitude per bin [rad/m].
    psd : ndarray
        C_iso(q) [m^4].

    References
    ----------
    Jacobs, Junge and Pastewka (2017) doi:10.1088/2051-672X/aa51f8
    """
    if ring_ratio is not None and not ring_ratio > 1:
        raise InputError("ring_ratio", f"must be > 1, got {ring_ratio}.", "e.g. 1.1 (10 % wide rings).")
    qx, qy, psd = psd_2d(topography, window=window, workers=workers)
    if nbins is None:
        nbins = max(topography.shape) // 2
    if isinstance(nbins, bool) or not isinstance(nbins, (int, np.integer)) or nbins < 1:
        raise InputError("nbins", f"must be a positive integer, got {nbins}.", "give e.g. 64, or None.")
    magnitude = np.hypot(qx[:, None], qy[None, :]).ravel()
    values = psd.ravel()
    keep = magnitude > 0
    magnitude, values = magnitude[keep], values[keep]
    if ring_ratio is None:
        index = np.minimum((magnitude / magnitude.max() * nbins).astype(int), nbins - 1)
    else:
        index = np.floor(np.log(magnitude / magnitude.min()) / np.log(ring_ratio) + 1e-9).astype(int)
        nbins = int(index.max()) + 1
    counts = np.bincount(index, minlength=nbins)
    filled = counts > 0
    q = np.bincount(index, weights=magnitude, minlength=nbins)[filled] / counts[filled]
    return q, np.bincount(index, weights=values, minlength=nbins)[filled] / counts[filled]


def autocorrelation(topography: Topography, *, workers: int = -1) -> tuple[np.ndarray, np.ndarray]:
    r"""Height autocorrelation function along x (averaged over the y-lines of a map).

    .. math:: R(r) = \langle z(x)\, z(x + r) \rangle, \qquad R(0) = m_0

    with z about the mean plane [m^2]. Periodic surfaces: circular correlation, averaged over all
    n points. Non-periodic: zero-padded correlation divided by the number of overlapping pairs
    ``n - k`` at lag k (unbiased estimator, noisy at large lags).

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).
    workers : int
        Threads for scipy.fft (-1: all cores).

    Returns
    -------
    lag : ndarray
        Lags ``k * dx`` [m], k = 0 .. n//2.
    acf : ndarray
        R(lag) [m^2].
    """
    z = _centred(topography)
    n = topography.shape[0]
    length = n if topography.periodic else 2 * n
    spectrum = np.abs(fft.rfft(z, n=length, axis=0, workers=workers)) ** 2
    correlation = fft.irfft(spectrum, n=length, axis=0, workers=workers)[: n // 2 + 1]
    if correlation.ndim == 2:
        correlation = correlation.mean(axis=1)
    pairs = n if topography.periodic else n - np.arange(n // 2 + 1)
    return np.arange(n // 2 + 1) * topography.spacing[0], correlation / pairs


# --- summits ---------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Summits:
    """Local maxima of a surface.

    Attributes
    ----------
    indices : ndarray of int, shape (count, dim)
        Grid indices of the summits.
    positions : ndarray, shape (count, dim)
        Their coordinates [m].
    heights : ndarray, shape (count,)
        Their heights above the mean plane [m].
    """

    indices: np.ndarray
    positions: np.ndarray
    heights: np.ndarray

    @property
    def count(self) -> int:
        """Number of summits."""
        return len(self.heights)


def summits(topography: Topography) -> Summits:
    """Find the summits: points strictly higher than all their neighbours.

    Neighbours are the 8 surrounding pixels of a map (2 for a profile). Periodic surfaces wrap
    around; on non-periodic ones the edge points are never summits (their neighbourhood is
    incomplete). Plateaus (equal neighbours) give no summit.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).

    Returns
    -------
    Summits
        Indices, positions [m] and heights about the mean plane [m] of the summits.

    References
    ----------
    Greenwood, J. A. and Williamson, J. B. P. (1966). Proc. R. Soc. A 295, 300-319.
    doi:10.1098/rspa.1966.0242 (summits as 8-neighbour maxima: Greenwood 1984, doi:10.1098/rspa.1984.0006)
    """
    z = _centred(topography)
    is_summit = np.ones(z.shape, dtype=bool)
    for shift in np.ndindex(*(3,) * z.ndim):
        offset = tuple(s - 1 for s in shift)
        if any(offset):
            is_summit &= z > np.roll(z, offset, axis=tuple(range(z.ndim)))
    if not topography.periodic:
        interior = np.zeros(z.shape, dtype=bool)
        interior[(slice(1, -1),) * z.ndim] = True
        is_summit &= interior
    indices = np.argwhere(is_summit)
    positions = indices * np.asarray(topography.spacing)
    return Summits(indices=indices, positions=positions, heights=z[is_summit])


# --- summary ---------------------------------------------------------------------------------------


_AREAL = "areal, ISO 25178-2"
_PROFILE = "profiles along x, ISO 4287"

SUMMARY = {
    "Sa": ("m", f"arithmetic mean height ({_AREAL})"),
    "Sq": ("m", f"root mean square height ({_AREAL})"),
    "Ssk": ("", f"skewness ({_AREAL})"),
    "Sku": ("", f"kurtosis ({_AREAL})"),
    "Sz": ("m", f"maximum height, highest peak to lowest pit ({_AREAL})"),
    "Sdq": ("", f"root mean square gradient ({_AREAL})"),
    "Sdr": ("", f"developed interfacial area ratio, 0.01 = 1 % ({_AREAL})"),
    "Ra": ("m", f"arithmetic mean deviation ({_PROFILE})"),
    "Rq": ("m", f"root mean square deviation ({_PROFILE})"),
    "Rsk": ("", f"skewness ({_PROFILE})"),
    "Rku": ("", f"kurtosis ({_PROFILE})"),
    "Rt": ("m", f"total height of the profile ({_PROFILE})"),
    "Rdq": ("", f"root mean square slope ({_PROFILE})"),
    "rms_slope": ("", "rms slope sqrt(2 m2), sqrt(m2) for a profile (paper 002)"),
    "rms_curvature": ("1/m", "rms curvature"),
    "m0": ("m^2", "spectral moment m0 (paper 002 eq. 1)"),
    "m2": ("", "spectral moment m2 (eq. 2)"),
    "m4": ("1/m^2", "spectral moment m4 (eq. 3)"),
    "bandwidth": ("", "bandwidth parameter alpha = m0 m4 / m2^2"),
    "summit_density": ("1/m^2", "summit density eta (McCool; a profile: of the isotropic surface it cuts)"),
    "summit_radius": ("m", "summit radius R_asp (eq. 4)"),
    "summit_height_std": ("m", "summit height deviation sigma_s (eq. 5)"),
}
"""Each entry of :func:`summary`: its SI unit ("" for a dimensionless one) and what it is."""


def summary(topography: Topography) -> dict[str, float]:
    """All scalar statistics of a surface, SI (the entries and units of :data:`SUMMARY`).

    A map gets the areal parameters of ISO 25178-2 (Sa, Sq, Ssk, Sku, Sz, Sdq, Sdr) and the
    profile parameters of ISO 4287 along x (:func:`profile_parameters`); a profile gets the profile
    parameters only. Then the rms slope and curvature, paper 002's spectral moments and McCool's
    summit parameters. Default (forward) first differences.
    Entries that are undefined for this surface are left out rather than set to NaN: the
    skewness and kurtosis of a flat surface, and the McCool entries when the moments give
    alpha < 0.8968 or a zero moment.

    A flat surface (:func:`~roughcontact.topography.plausible.is_flat`: its heights vary by
    round-off of their magnitude at most) has every amplitude, slope, curvature and moment 0 and
    none of the entries that need a roughness (skewness, kurtosis, McCool's summits): computed, its
    round-off would read as a roughness of 1e-25 m with summits of gigametres.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).

    Returns
    -------
    dict of str to float
    """
    if is_flat(topography.heights):
        areal = ("Sa", "Sq", "Sz", "Sdq", "Sdr") if topography.dim == 2 else ()
        names = (*areal, "Ra", "Rq", "Rt", "Rdq", "rms_slope", "rms_curvature", "m0", "m2", "m4")
        return dict.fromkeys(names, 0.0)
    result = {}
    slope = rms_slope(topography)
    if topography.dim == 2:
        result = {"Sa": ra(topography), "Sq": rq(topography)}
        try:
            result |= {"Ssk": rsk(topography), "Sku": rku(topography)}
        except InputError:
            pass  # flat surface: skewness and kurtosis undefined, left out as documented
        result |= {"Sz": rz(topography), "Sdq": slope, "Sdr": sdr(topography)}
    result |= profile_parameters(topography)
    result |= {
        "rms_slope": slope,
        "rms_curvature": rms_curvature(topography),
    }
    moments = spectral_moments(topography)
    result |= {"m0": moments.m0, "m2": moments.m2, "m4": moments.m4}
    try:
        mccool = mccool_parameters(m0=moments.m0, m2=moments.m2, m4=moments.m4)
    except InputError:
        return result  # McCool entries undefined for these moments, left out as documented
    return result | {
        "bandwidth": mccool.bandwidth,
        "summit_density": mccool.summit_density,
        "summit_radius": mccool.summit_radius,
        "summit_height_std": mccool.summit_height_std,
    }
