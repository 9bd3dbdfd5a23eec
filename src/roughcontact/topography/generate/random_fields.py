"""Random rough surfaces: self-affine (fractal) and Gaussian-correlated, in either of the two ``modes``."""

from __future__ import annotations

import math

import numpy as np

from ...checks import positive
from ...errors import InputError
from ..surface import Topography
from .grid import checked_hurst, grid_of
from .noise import checked_band, checked_modes, random_surface

_GAUSSIAN_TAIL = 1e-18  # "wavevector" Gaussian PSD: modes with C(q) / C(0) below this are left out


def _one_target(rms_height: float | None, rms_slope: float | None) -> tuple[float | None, float | None]:
    if (rms_height is None) == (rms_slope is None):
        raise InputError(
            "rms_height",
            "give exactly one of rms_height and rms_slope.",
            "pass rms_height [m] or rms_slope [-], not both and not neither.",
        )
    if rms_height is not None:
        return positive(rms_height, "rms_height", example="1e-9", unit="m"), None
    return None, positive(rms_slope, "rms_slope", example="0.1 (dimensionless)")


def self_affine_arguments(
    shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, rolloff, modes="grid"
):
    """Check and normalise the arguments of :func:`self_affine` (see :func:`check_arguments`)."""
    shape, size = grid_of(shape, size)
    hurst = checked_hurst(hurst)
    rms_height, rms_slope = _one_target(rms_height, rms_slope)
    short_cutoff, modes = checked_band(short_cutoff, modes)
    if long_cutoff is not None:
        long_cutoff = positive(long_cutoff, "long_cutoff", example="1e-6", unit="m")
    if short_cutoff is not None and long_cutoff is not None and long_cutoff <= short_cutoff:
        raise InputError(
            "long_cutoff",
            f"{long_cutoff!r} m is not longer than short_cutoff {short_cutoff!r} m.",
            "give long_cutoff > short_cutoff.",
        )
    plateau = 0.0
    if rolloff is not None:
        plateau = positive(rolloff, "rolloff", example="0 (no plateau) or 1 (flat plateau)", allow_zero=True)
    return shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, plateau, modes


def self_affine(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    hurst: float,
    rms_height: float | None = None,
    rms_slope: float | None = None,
    short_cutoff: float | None = None,
    long_cutoff: float | None = None,
    rolloff: float | None = None,
    seed: int | None = None,
    modes: str = "grid",
) -> Topography:
    r"""Periodic, isotropic, self-affine random surface by Fourier filtering.

    The target PSD is a power law between the long and short cutoff wavevectors
    :math:`q_L = 2\pi/\lambda_L` and :math:`q_s = 2\pi/\lambda_s`:

    .. math::

        C(q) \propto \begin{cases}
            r\, q_L^{-\beta} & 0 < q < q_L \quad (\text{roll-off plateau, } r = \text{rolloff})\\
            q^{-\beta} & q_L \le q \le q_s \\
            0 & q > q_s \text{ and } q = 0
        \end{cases}

    with :math:`\beta = 2(1 + H)` for a map (2D isotropic PSD) and :math:`\beta = 1 + 2H` for a
    profile (1D PSD of the same self-affine process). ``rolloff=None`` means no plateau (C = 0
    below q_L, as ``rolloff=0``); ``rolloff=1`` is a flat continuation (Persson et al. 2005; Jacobs
    et al. 2017). Without ``long_cutoff`` the power law starts at the lowest wavevector 2 pi / size;
    without ``short_cutoff`` it runs to the corners of the grid.

    The draw gives random phases and Rayleigh-distributed amplitudes about the target PSD; how,
    and how the result is scaled, is ``modes`` (module notes):

    * ``"grid"``: white noise on the grid, then one factor so that the *discrete* statistics hit
      the target exactly (to round-off): Rq (:func:`~roughcontact.topography.statistics.rq`) for
      ``rms_height``, or the forward-difference rms slope
      (:func:`~roughcontact.topography.statistics.rms_slope`) for ``rms_slope``. Another grid
      gives another surface.
    * ``"wavevector"``: each Fourier coefficient is drawn from (seed, wavevector) and the PSD is
      normalised on the lattice of wavevectors q = 2 pi k / size (integer k): the expected
      variance summed over every lattice mode 0 < q <= q_s is ``rms_height**2`` (or the expected
      mean square gradient, continuum derivative, sum of q^2 times the mode's variance, is
      ``rms_slope**2``). The surface is then one continuum field that every grid samples: grids
      share the coefficients of their common modes to round-off, and a grid that does not hold
      the whole band (q_s beyond its Nyquist wavevector) is the Fourier truncation of a finer
      one, with a smaller rms. The discrete Rq scatters about the target as the draw does.
      Needs ``short_cutoff``: without it the band, hence the normalisation, follows the grid.

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny), each >= 2.
    size : float or tuple of float
        Physical size = period [m].
    hurst : float
        Hurst exponent H in (0, 1].
    rms_height : float, optional
        Target rms height Rq [m]. Exactly one of rms_height, rms_slope.
    rms_slope : float, optional
        Target rms slope (gradient) [-].
    short_cutoff : float, optional
        Shortest wavelength lambda_s [m] (required with ``modes="wavevector"``).
    long_cutoff : float, optional
        Longest self-affine wavelength lambda_L [m] (> short_cutoff).
    rolloff : float, optional
        Plateau level r >= 0 below q_L, as a fraction of C(q_L).
    seed : int, optional
        Seed (>= 0); the same seed gives the same surface. ``"grid"``: of
        ``numpy.random.default_rng``; ``"wavevector"``: keyed by ``numpy.random.SeedSequence``.
    modes : {"grid", "wavevector"}
        White noise on the grid (default, the surfaces of earlier releases) or one draw per
        wavevector (the same surface on every grid).

    Returns
    -------
    Topography
        Periodic surface with zero mean; ``info["modes"]`` records ``modes``.

    Raises
    ------
    InputError
        Invalid grid, hurst, targets, cutoffs, rolloff or modes, ``modes="wavevector"`` without
        ``short_cutoff``, or a band that holds no wavevector.

    References
    ----------
    Jacobs, Junge and Pastewka (2017) doi:10.1088/2051-672X/aa51f8; Persson et al. (2005)
    doi:10.1088/0953-8984/17/1/R01
    """
    shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, plateau, modes = (
        self_affine_arguments(
            shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, rolloff, modes
        )
    )
    q_short = math.inf if short_cutoff is None else 2.0 * math.pi / short_cutoff
    q_long = 0.0 if long_cutoff is None else 2.0 * math.pi / long_cutoff
    exponent = 2.0 * (1.0 + hurst) if len(shape) == 2 else 1.0 + 2.0 * hurst

    def psd_shape(q: np.ndarray) -> np.ndarray:
        power_law = np.maximum(q, q_long) ** -exponent
        return np.where(q > q_short, 0.0, np.where(q < q_long, plateau * power_law, power_law))

    info = {
        "name": "self-affine",
        "generator": "self_affine",
        "hurst": hurst,
        "seed": seed,
        "short_cutoff": short_cutoff,
        "long_cutoff": long_cutoff,
        "rolloff": rolloff,
        "modes": modes,
    }
    return random_surface(
        shape, size, psd_shape, q_short, rms_height, rms_slope, seed, modes, "short_cutoff", info
    )


def gaussian_random_arguments(shape, size, rms_height, correlation_length, modes="grid"):
    """Check and normalise the arguments of :func:`gaussian_random`."""
    shape, size = grid_of(shape, size)
    rms_height = positive(rms_height, "rms_height", example="1e-9", unit="m")
    correlation_length = positive(correlation_length, "correlation_length", example="1e-7", unit="m")
    return shape, size, rms_height, correlation_length, checked_modes(modes)


def gaussian_random(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    rms_height: float,
    correlation_length: float,
    seed: int | None = None,
    modes: str = "grid",
) -> Topography:
    r"""Periodic Gaussian random surface with a Gaussian autocorrelation function.

    .. math:: R(r) = h_\mathrm{rms}^2 \exp(-r^2/\xi^2) \quad\Longleftrightarrow\quad
              C(q) \propto \exp(-q^2 \xi^2 / 4)

    (the PSD is the Fourier transform of the ACF, in 1D and 2D alike up to the prefactor). With
    ``modes="grid"`` heights are rescaled so the discrete Rq equals ``rms_height`` exactly; the ACF
    follows the target only statistically and for ``correlation_length`` well between the pixel
    size and the period. With ``modes="wavevector"`` (see :func:`self_affine`) the PSD is
    normalised on the lattice of wavevectors 2 pi k / size up to q xi = 2 sqrt(ln 1e18) = 12.9
    (C / C(0) = 1e-18; beyond, the modes are left out): the expected variance of that field is
    ``rms_height**2`` on every grid.

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny).
    size : float or tuple of float
        Physical size = period [m].
    rms_height : float
        Rq [m].
    correlation_length : float
        xi [m]: the ACF falls to 1/e of its peak at r = xi.
    seed : int, optional
        Seed (>= 0), see :func:`self_affine`.
    modes : {"grid", "wavevector"}
        White noise on the grid (default) or one draw per wavevector, see :func:`self_affine`.

    Returns
    -------
    Topography
        Periodic surface with zero mean; ``info["modes"]`` records ``modes``.

    References
    ----------
    Whitehouse, D. J. and Archard, J. F. (1970). The properties of random surfaces of significance
    in their contact. Proc. R. Soc. A 316, 97-121. doi:10.1098/rspa.1970.0068
    """
    shape, size, rms_height, correlation_length, modes = gaussian_random_arguments(
        shape, size, rms_height, correlation_length, modes
    )

    def psd_shape(q: np.ndarray) -> np.ndarray:
        return np.exp(-((q * correlation_length) ** 2) / 4.0)

    info = {
        "name": "gaussian",
        "generator": "gaussian_random",
        "correlation_length": correlation_length,
        "seed": seed,
        "modes": modes,
    }
    reach = 2.0 * math.sqrt(math.log(1.0 / _GAUSSIAN_TAIL)) / correlation_length
    return random_surface(
        shape, size, psd_shape, reach, rms_height, None, seed, modes, "correlation_length", info
    )
