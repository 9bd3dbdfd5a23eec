"""Power spectra (1D, 2D, radially averaged) and the autocorrelation, normalised as Jacobs et al. (2017)."""

from __future__ import annotations

import numpy as np
import scipy
from scipy import fft

from ...errors import InputError
from ..surface import Topography
from .amplitude import centred

WINDOWS = ("hann", None)


def _default_window(topography: Topography, window: str | None) -> str | None:
    if window == "default":
        return None if topography.periodic else "hann"
    if window not in WINDOWS:
        raise InputError("window", f"unknown window {window!r}.", "choose 'hann', None or 'default'.")
    return window


def _windowed(topography: Topography, axes: tuple[int, ...], window: str | None) -> np.ndarray:
    """Mean-removed heights, multiplied by a Hann window along ``axes`` normalised to mean(w^2) = 1."""
    z = centred(topography)
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
    z = centred(topography)
    n = topography.shape[0]
    length = n if topography.periodic else 2 * n
    spectrum = np.abs(fft.rfft(z, n=length, axis=0, workers=workers)) ** 2
    correlation = fft.irfft(spectrum, n=length, axis=0, workers=workers)[: n // 2 + 1]
    if correlation.ndim == 2:
        correlation = correlation.mean(axis=1)
    pairs = n if topography.periodic else n - np.arange(n // 2 + 1)
    return np.arange(n // 2 + 1) * topography.spacing[0], correlation / pairs
