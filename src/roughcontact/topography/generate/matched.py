"""Random maps matched to a measurement: to given spectral moments (paper 002) or to a scan's PSD."""

from __future__ import annotations

import functools
import math
from collections.abc import Callable

import numpy as np
import scipy

from ...checks import positive
from ...errors import InputError
from .. import statistics
from ..surface import Topography
from .grid import checked_hurst, grid_of
from .noise import checked_modes, filtered_noise, half_lattice, wavevector_magnitude
from .random_fields import self_affine

_SHELL_TOLERANCE = 1e-9  # relative: lattice wavevectors closer than this in |q| form one shell


MIN_PIXELS_PER_SHORT_WAVELENGTH = 19
"""Pixels per shortest wavelength that :func:`matched_moments` asks of its grid.

The centred second difference of :func:`~roughcontact.topography.statistics.spectral_moments`
sees a wave of wavevector q along an axis with (sin(qh/2) / (qh/2))^4 of its mean square
curvature; at 19 pixels per wavelength (qh = 2 pi / 19) that is 0.982, so the measured m4 is low
by at most 2 % whatever the spectrum (18.1 pixels reach 2 % exactly).
"""


_MATCH_TOLERANCE = 0.02  # relative: largest bandwidth error of the lattice band matched_moments settles on


def _band_integral(order: int, log_magnification: float, exponent: float) -> float:
    """Return J_n = int_0^zeta x^(n+1) c(x) dx of the unit plateau-and-power-law PSD c.

    c(x) = 1 for x < 1 and x^-exponent for 1 <= x <= zeta (x = q / q_L, zeta = q_s / q_L, given as
    ln zeta), so the continuum I_n = int q^(n+1) C(q) dq / (2 pi) of C = C0 c(q / q_L) is
    C0 q_L^(n+2) J_n / (2 pi).
    """
    power = order + 2 - exponent
    tail = log_magnification if abs(power) < 1e-12 else math.expm1(power * log_magnification) / power
    return 1.0 / (order + 2) + tail


def _continuum_band(ratio: float, bandwidth: float, hurst: float) -> tuple[float, float]:
    """Return (q_L, q_s) [rad/m] whose continuum moments have m2 / m0 = ``ratio`` and the ``bandwidth``."""
    exponent = 2.0 * (1.0 + hurst)

    def integrals(log_magnification: float) -> list[float]:
        return [_band_integral(n, log_magnification, exponent) for n in (0, 2, 4)]

    def excess(log_magnification: float) -> float:
        j0, j2, j4 = integrals(log_magnification)
        return 1.5 * j0 * j4 / j2**2 - bandwidth  # alpha = (3/2) I0 I4 / I2^2: 2 at zeta = 1, ~zeta^(2H)

    upper = 1.0
    while excess(upper) < 0:
        upper *= 2.0
        if upper > 128.0:  # zeta = e^128: no spectrum a grid could hold
            raise InputError(
                "hurst",
                f"with hurst={hurst:g} the bandwidth alpha = {bandwidth:.4g} needs q_s / q_L beyond e^128.",
                "use a larger hurst (alpha grows as (q_s / q_L)^(2 H)), or check m0, m2, m4.",
            )
    log_magnification = scipy.optimize.brentq(excess, 0.0, upper, xtol=1e-14)
    j0, j2, _ = integrals(log_magnification)
    q_long = math.sqrt(2.0 * ratio * j0 / j2)  # m2 / m0 = (I2 / 2) / I0 = q_L^2 J2 / (2 J0)
    return q_long, q_long * math.exp(log_magnification)


def _lattice_band(
    size: tuple[float, float], m0: float, m2: float, m4: float, hurst: float
) -> dict[str, float]:
    """Return the band whose expected moments on the lattice of the period ``size`` are m0, m2 and m4.

    The expected moments of the field are sums over the lattice modes q = 2 pi (k_x / L_x, k_y /
    L_y) of C(q) / A times 1, (q_x^2 + q_y^2) / 2, (q_x^4 + q_y^4) / 2 (paper 002 eqs. 1-3 with
    continuum derivatives). q_s only matters through the shells of modes it takes in: for each
    band of shells, q_L is solved (brentq) for m2 / m0 and the bandwidth follows; the shells are
    bisected for the bandwidth, and q_s is put halfway to the next shell. The continuum solution
    (:func:`_continuum_band`) sizes the lattice and the messages.
    """
    exponent = 2.0 * (1.0 + hurst)
    ratio, bandwidth = m2 / m0, m0 * m4 / m2**2
    q_long_continuum, q_short_continuum = _continuum_band(ratio, bandwidth, hurst)
    wavevectors, magnitude = half_lattice(size, 1.5 * q_short_continuum, "size")  # room to refine q_s
    order = np.argsort(magnitude, kind="stable")
    magnitude = magnitude[order]
    qx, qy = (2.0 * np.pi * k[order] / s for k, s in zip(wavevectors, size, strict=True))
    weights = (np.ones(magnitude.size), (qx**2 + qy**2) / 2.0, (qx**4 + qy**4) / 2.0)
    plateau = [np.concatenate(([0.0], np.cumsum(w))) for w in weights]
    tail = [np.concatenate(([0.0], np.cumsum(w * magnitude**-exponent))) for w in weights]
    # modes in the band of shells 0..j; the outermost shell may be cut by the lattice's reach
    ends = np.flatnonzero(np.diff(magnitude) > _SHELL_TOLERANCE * magnitude[1:]) + 1

    def sums(q_long: float, end: int) -> list[float]:
        start = int(np.searchsorted(magnitude, q_long))  # modes below q_L: on the plateau C0
        return [p[start] + q_long**exponent * (t[end] - t[start]) for p, t in zip(plateau, tail, strict=True)]

    @functools.cache
    def solve(shell: int) -> tuple[float, float]:
        """Bandwidth and q_L of the band of shells 0..shell (-inf: too narrow, +inf: too wide)."""
        end = int(ends[shell])

        def excess(q_long: float) -> float:
            s0, s2, _ = sums(q_long, end)
            return s2 / s0 - ratio

        if excess(magnitude[0]) > 0:  # even without a plateau the band is too rough in slope
            return math.inf, math.nan
        if excess(magnitude[end - 1]) < 0:  # even a flat disc is too smooth in slope
            return -math.inf, math.nan
        q_long = scipy.optimize.brentq(excess, magnitude[0], magnitude[end - 1], rtol=1e-13)
        s0, s2, s4 = sums(q_long, end)
        return s0 * s4 / s2**2, q_long

    last = ends.size - 1
    if last < 0 or solve(last)[0] < bandwidth:
        raise InputError(
            "size",
            f"the wavevectors of a {size[0]:.4g} m x {size[1]:.4g} m period reach no band of bandwidth "
            f"{bandwidth:.4g}.",
            "use a larger size.",
        )
    low, high = 0, last  # the first band of shells whose bandwidth reaches the target
    while low < high:
        middle = (low + high) // 2
        low, high = (low, middle) if solve(middle)[0] >= bandwidth else (middle + 1, high)
    reached = [shell for shell in (low - 1, low) if shell >= 0 and math.isfinite(solve(shell)[0])]
    shell = min(reached, key=lambda s: abs(solve(s)[0] / bandwidth - 1.0), default=None)
    matched, q_long = solve(low if shell is None else shell)
    if abs(matched / bandwidth - 1.0) > _MATCH_TOLERANCE and math.isinf(solve(low)[0]):
        raise InputError(
            "hurst",
            f"with hurst={hurst:g} the band of these moments has its roll-off at q_L = "
            f"{q_long_continuum:.4g} rad/m (continuum), too close to the lowest wavevector 2 pi / size = "
            f"{2.0 * math.pi / max(size):.4g} rad/m for the period's lattice to match m0, m2 and m4 "
            f"(the nearest band reaches a bandwidth {matched:.4g} for {bandwidth:.4g}).",
            "use a larger hurst (q_L rises with it), or a larger size.",
        )
    if abs(matched / bandwidth - 1.0) > _MATCH_TOLERANCE:
        raise InputError(
            "size",
            f"the shells of wavevectors of a {max(size):.4g} m period are too sparse: the nearest band has "
            f"a bandwidth {matched:.4g} for {bandwidth:.4g}.",
            "use a larger size.",
        )
    end = int(ends[shell])
    s0, _, s4 = sums(q_long, end)
    return {
        "q_long": float(q_long),
        "q_short": float(0.5 * (magnitude[end - 1] + magnitude[end])),
        "prefactor": float(m0 * math.prod(size) / (2.0 * s0)),  # C0 [m^4]: m0 = 2 C0 s0 / A
        "expected_m4": float(m0 * s4 / s0),
    }


def matched_moments_arguments(shape, size, m0, m2, m4, hurst, modes="wavevector", coarse="refuse"):
    """Check the arguments of :func:`matched_moments` and solve its band (see :func:`check_arguments`)."""
    shape, size = grid_of(shape, size)
    if len(shape) != 2:
        raise InputError(
            "shape", "matched_moments makes a map (paper 002's moments are areal).", "give shape=(nx, ny)."
        )
    m0 = positive(m0, "m0", example="2e-15", unit="m^2")
    m2 = positive(m2, "m2", example="0.0023 (dimensionless)")
    m4 = positive(m4, "m4", example="1.7e10", unit="1/m^2")
    hurst, modes = checked_hurst(hurst), checked_modes(modes)
    bandwidth = m0 * m4 / m2**2
    if bandwidth < 2.0:
        floor = (
            "no isotropic surface has alpha < 1.5 (Nayak 1971)"
            if bandwidth < 1.5
            else "a plateau and power law with a hard cutoff reaches alpha >= 2 only (2: a flat disc, "
            "q_L = q_s), whatever the hurst"
        )
        raise InputError(
            "m4",
            f"the bandwidth alpha = m0 m4 / m2^2 = {bandwidth:.4g}: {floor}.",
            "check m0, m2 and m4 (their units: m^2, -, 1/m^2); this generator needs alpha >= 2.",
        )
    if coarse not in ("refuse", "truncate"):
        raise InputError("coarse", f"unknown choice {coarse!r}.", "use 'refuse' or 'truncate'.")
    if coarse == "truncate" and modes != "wavevector":
        raise InputError(
            "coarse",
            "'truncate' keeps one field on every grid, which needs modes='wavevector'.",
            "use modes='wavevector', or coarse='refuse'.",
        )
    band = _lattice_band(size, m0, m2, m4, hurst)
    wavelength = 2.0 * math.pi / band["q_short"]
    pixels = [wavelength * n / s for n, s in zip(shape, size, strict=True)]
    if min(pixels) < MIN_PIXELS_PER_SHORT_WAVELENGTH and coarse == "refuse":
        needed = tuple(math.ceil(MIN_PIXELS_PER_SHORT_WAVELENGTH * s / wavelength) for s in size)
        raise InputError(
            "shape",
            f"the shortest wavelength of the band, {wavelength:.4g} m, spans {min(pixels):.3g} pixels: "
            f"spectral_moments' second differences would measure m4 more than 2 % low.",
            f"use {MIN_PIXELS_PER_SHORT_WAVELENGTH}+ pixels per shortest wavelength: shape >= {needed}.",
        )
    return shape, size, m0, m2, m4, hurst, modes, band


def matched_moments(
    shape: tuple[int, int],
    size: float | tuple[float, float],
    *,
    m0: float,
    m2: float,
    m4: float,
    hurst: float = 0.8,
    seed: int | None = None,
    modes: str = "wavevector",
    coarse: str = "refuse",
) -> Topography:
    r"""Make a self-affine map whose expected spectral moments m0, m2, m4 are given (paper 002 equations 1-3).

    The PSD is isotropic, a flat roll-off plateau below :math:`q_L`, a power law of the Hurst
    exponent ``hurst`` above it, and a hard cutoff at :math:`q_s` (:func:`self_affine` with
    ``rolloff=1``):

    .. math::

        C(q) = C_0 \begin{cases} 1 & q < q_L \\ (q/q_L)^{-2(1+H)} & q_L \le q \le q_s \\
               0 & q > q_s \end{cases}

    For such a PSD the continuum moments of a profile are :math:`m_0 = I_0`, :math:`m_2 = I_2/2`
    and :math:`m_4 = 3 I_4 / 8`, with :math:`I_n = \int q^{n+1} C(q)\,dq / 2\pi`, so the bandwidth
    :math:`\alpha = m_0 m_4 / m_2^2 = 3 I_0 I_4 / (2 I_2^2)` depends on :math:`\zeta = q_s / q_L`
    alone: 2 for a flat disc (:math:`\zeta = 1`), growing as :math:`\zeta^{2H}`. brentq on these
    power-law integrals gives :math:`\zeta` from :math:`\alpha`, :math:`q_L` from :math:`m_2/m_0`
    and :math:`C_0` from :math:`m_0`.

    What is matched is then the *expected* moments of the field on the lattice of wavevectors
    :math:`2\pi (k_x/L_x, k_y/L_y)` of the period ``size`` (the sums over its modes that the
    continuum integrals approximate; on paper 002's 25 um square the continuum solution is 1.5 %
    off in m0 there): q_L is solved again on the lattice for m2 / m0 and q_s bisected over the
    shells of lattice modes for the bandwidth, starting from the continuum band. m0 and m2 are
    matched exactly, m4 to within one shell of modes (``info["expected_m4"]``; refused beyond
    2 %). The derivatives are continuum ones: the heights' finite-difference moments
    (:func:`~roughcontact.topography.statistics.spectral_moments`) come close only on a grid that
    resolves q_s, so a grid with fewer than :data:`MIN_PIXELS_PER_SHORT_WAVELENGTH` (19) pixels per
    shortest wavelength 2 pi / q_s is refused: the second difference could read m4 more than 2 %
    low (the forward-difference m2 at most 0.9 % low). For paper 002's moments (H = 0.8, q_s =
    2 pi / 1.07 um) the expected m4 reads 0.8 % low at 19 pixels and 0.6 % at 512^2 on the 25 um
    square (22 pixels), m2 0.2 % and 0.15 %. A realisation scatters about the expected moments, most
    in m0, which the few modes near q_L carry: on that square the standard deviations of one
    realisation are 12 % (m0), 5 % (m2) and 3.5 % (m4). Average over seeds.

    Parameters
    ----------
    shape : tuple of int
        Grid points (nx, ny) of a map.
    size : float or tuple of float
        Physical size = period [m].
    m0 : float
        Mean square height [m^2] (paper 002 eq. 1).
    m2 : float
        Mean square slope per direction [-] (eq. 2).
    m4 : float
        Mean square curvature per direction [1/m^2] (eq. 3).
    hurst : float
        Hurst exponent H in (0, 1] of the power law.
    seed : int, optional
        Seed (>= 0), see :func:`self_affine`.
    modes : {"wavevector", "grid"}
        One draw per wavevector (default: the same surface on every grid that resolves q_s) or
        white noise on the grid (then Rq is exactly sqrt(m0), m2 and m4 in expectation).
    coarse : {"refuse", "truncate"}
        A grid with fewer than 19 pixels per shortest wavelength: refused (default), or, with
        ``modes="wavevector"``, drawn as the same field truncated at the grid's Nyquist
        wavevector (``info["resolved"]`` False): the coarse grids of a mesh-convergence study,
        whose finite-difference moments then read low.

    Returns
    -------
    Topography
        Periodic surface with zero mean. ``info`` holds the targets ``m0``, ``m2``, ``m4``, the
        band ``q_long``, ``q_short`` [rad/m] (and as wavelengths ``long_cutoff``, ``short_cutoff``
        [m]), ``hurst``, ``rolloff`` (1), the plateau ``prefactor`` C0 [m^4] (PSD normalised as
        Jacobs et al. 2017: <z^2> = sum of C(q) / area) and ``expected_m4``.

    Raises
    ------
    InputError
        A profile or a grid too coarse for q_s (``shape``), moments that are not positive or have a
        bandwidth below 2 (``m4``), a roll-off that the period's lattice cannot hold with this
        ``hurst`` (``hurst``: a larger one raises q_L), or a period whose lattice is too sparse
        (``size``).

    References
    ----------
    Seed paper 002, eqs. 1-3. Nayak, P. R. (1971). Random process model of rough surfaces.
    J. Lubr. Technol. 93, 398-407. doi:10.1115/1.3451150. Jacobs, Junge and Pastewka (2017)
    doi:10.1088/2051-672X/aa51f8
    """
    shape, size, m0, m2, m4, hurst, modes, band = matched_moments_arguments(
        shape, size, m0, m2, m4, hurst, modes, coarse
    )
    wavelength = 2.0 * math.pi / band["q_short"]
    resolved = (
        min(wavelength * n / s for n, s in zip(shape, size, strict=True)) >= MIN_PIXELS_PER_SHORT_WAVELENGTH
    )
    surface = self_affine(
        shape,
        size,
        hurst=hurst,
        rms_height=math.sqrt(m0),
        short_cutoff=2.0 * math.pi / band["q_short"],
        long_cutoff=2.0 * math.pi / band["q_long"],
        rolloff=1.0,
        seed=seed,
        modes=modes,
    )
    info = {
        **dict(surface.info),
        "name": "matched moments",
        "generator": "matched_moments",
        "m0": m0,
        "m2": m2,
        "m4": m4,
        **band,
        "resolved": resolved,
    }
    return Topography(surface.heights, size, periodic=True, info=info)


def _lattice_variance(psd: Callable[[np.ndarray], np.ndarray], shape, size) -> float:
    """Return the sum over the grid's nonzero wavevectors of C(``|q|``) / area (Jacobs et al. 2017)."""
    magnitude = wavevector_magnitude(shape, size)
    weights = np.full(magnitude.shape, 2.0)  # the real FFT's half plane: each column stands for two
    weights[..., 0] = 1.0
    if shape[-1] % 2 == 0:
        weights[..., -1] = 1.0
    nonzero = magnitude > 0
    return float(np.sum(weights[nonzero] * psd(magnitude[nonzero])) / math.prod(size))


def matched_psd(
    template: Topography,
    *,
    shape: int | tuple[int, int] | None = None,
    size: float | tuple[float, float] | None = None,
    seed: int | None = None,
    ring_ratio: float = 1.1,
) -> Topography:
    r"""Make a random map with the radially averaged PSD of a measured scan (a stand-in for more spots).

    The template's isotropic PSD :math:`C(q)` is its radial PSD
    (:func:`~roughcontact.topography.statistics.psd_radial`, default window) over rings of ``|q|``
    that grow by ``ring_ratio`` (narrow: a ring's mean C is C at its mean q to a few per cent even
    where C falls as q^-3.6; the lowest rings hold single lattice circles), interpolated
    linearly in log q - log C; below its lowest wavevector it continues flat (a roll-off plateau:
    the scan says nothing about longer waves), beyond its last ring with power it is zero. White
    noise on the new grid is filtered by :math:`\sqrt{C}` (:func:`self_affine`'s
    ``modes="grid"``, random phases and Rayleigh amplitudes) and scaled so that its *expected* Rq
    is the template's times :math:`\sqrt{S_\mathrm{new} / S_\mathrm{template}}`, S the sum of
    the interpolated C over each grid's wavevectors divided by its area: on the template's own
    grid the template's Rq, on a larger or finer one the variance the PSD adds there. One draw's
    Rq scatters about it as another spot's would (forcing it exact would bias every other ring:
    the few longest waves carry most of the variance). The
    template's anisotropy and non-Gaussian heights are not reproduced (isotropic, Gaussian).

    Parameters
    ----------
    template : Topography
        A measured map (levelled as it is to be used).
    shape, size : optional
        Grid (an int: square) and size [m] of the new surface; default the template's.
    seed : int, optional
        Seed of ``numpy.random.default_rng``.
    ring_ratio : float
        Ratio of the outer to the inner ``|q|`` of a ring of the template's radial PSD (> 1).

    Returns
    -------
    Topography
        Periodic surface with zero mean; ``info`` records the template's name and Rq.

    Raises
    ------
    InputError
        A profile template (``template``), or a grid that holds no wavevector of the band.

    References
    ----------
    Jacobs, Junge and Pastewka (2017) doi:10.1088/2051-672X/aa51f8
    """
    if template.dim != 2:
        raise InputError("template", "matched_psd needs a map (an isotropic 2D PSD).", "give a 2D scan.")
    shape = template.shape if shape is None else (shape, shape) if isinstance(shape, int) else shape
    shape, size = grid_of(shape, template.size if size is None else size)
    q, psd = statistics.psd_radial(template, ring_ratio=ring_ratio)
    keep = psd > 1e-12 * psd.max()  # round-off beyond a band's end is no power
    log_q, log_c = np.log(q[keep]), np.log(psd[keep])

    def interpolated(magnitude: np.ndarray) -> np.ndarray:
        inside = magnitude <= q[keep].max() * math.sqrt(ring_ratio)  # to the outer edge of its last ring
        values = np.exp(np.interp(np.log(np.maximum(magnitude, q[keep].min())), log_q, log_c))
        return np.where(inside, values, 0.0)

    heights = filtered_noise(shape, size, interpolated, seed, "shape")
    variance = _lattice_variance(interpolated, shape, size)
    ratio = variance / _lattice_variance(interpolated, template.shape, template.size)
    target = statistics.rq(template) * math.sqrt(ratio)
    # white noise of unit variance filtered by sqrt(C): E[mean h^2] = sum over the full grid of C / N
    expected = variance * math.prod(size) / math.prod(shape)
    info = {
        "name": f"matched PSD of {template.info.get('name', 'a scan')}",
        "generator": "matched_psd",
        "seed": seed,
        "template_rq": statistics.rq(template),
    }
    return Topography(heights * target / math.sqrt(expected), size, periodic=True, info=info)
