r"""Synthetic surfaces as :class:`~roughcontact.topography.surface.Topography`, in SI units.

Self-affine and Gaussian random roughness, spheres, sinusoids, a flat punch, the raised island of
paper 002 and a rough sphere (AFM tip of paper 000, ball of paper 001).

Every generator takes SI arguments (lengths in metres) and returns a
:class:`~roughcontact.topography.surface.Topography`. ``shape`` is the number of grid points,
``(nx,)`` (or an int) for a profile along x and ``(nx, ny)`` for a map; ``size`` is the physical
extent [m], one value or one per axis. Grid point i sits at ``x = i * size / nx`` (first point at
0). Heights point out of the body, towards the counter-surface.

Random surfaces are made by Fourier filtering, heights = sum over wavevectors q of c_q exp(i q.r),
with c_q a complex Gaussian times the square root of the target PSD. The random generators draw
the c_q in one of two ``modes`` (:data:`MODES`):

``"grid"`` (default; the surfaces of earlier releases, bit for bit)
    Real white noise on the grid (``numpy.random.default_rng(seed)``) is transformed with a real
    FFT, filtered and transformed back, then scaled so that the grid's discrete rms hits the
    target exactly. Another grid draws other noise: another surface.
``"wavevector"``
    Each coefficient is drawn from (seed, integer wavevector k, q = 2 pi k / size) alone, by a
    counter-based hash (splitmix64 on 64-bit integers, two uniforms, Box-Muller), and the PSD is
    normalised on the lattice of all wavevectors in the band, not on the grid. The surface is then
    one continuum field whatever the grid: two grids of the same size, seed and band have equal
    coefficients in their shared modes (to round-off), and a coarse grid is a fine one low-passed
    and sampled. The Nyquist modes (``|k|`` = n / 2 along an axis of even n) are left out, so that a
    grid holds each of its modes whole. The band must end at a given wavelength (``short_cutoff``).

Both keep the Hermitian symmetry (``c_-q = conj(c_q)``), so the heights are real, periodic with
period ``size``, of zero mean, and reproducible for a given ``seed``. :func:`matched_moments`
solves the band of a self-affine PSD for given spectral moments (paper 002 eqs. 1-3).

References
----------
Jacobs, T. D. B., Junge, T. and Pastewka, L. (2017). Quantitative characterization of surface
topography using spectral analysis. Surf. Topogr.: Metrol. Prop. 5, 013001.
doi:10.1088/2051-672X/aa51f8

Persson, B. N. J., Albohr, O., Tartaglino, U., Volokitin, A. I. and Tosatti, E. (2005). On the
nature of surface roughness with application to contact mechanics, sealing, rubber friction and
adhesion. J. Phys.: Condens. Matter 17, R1. doi:10.1088/0953-8984/17/1/R01

Steele, G. L., Lea, D. and Flood, C. H. (2014). Fast splittable pseudorandom number generators.
OOPSLA '14, 453-472 (splitmix64). doi:10.1145/2660193.2660195
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import scipy
from scipy import fft

from ..checks import no_string, positive
from ..errors import InputError
from . import statistics
from .surface import Topography

__all__ = [
    "MIN_PIXELS_PER_SHORT_WAVELENGTH",
    "MODES",
    "bisinusoid",
    "flat_punch",
    "gaussian_random",
    "matched_moments",
    "matched_psd",
    "raised_island",
    "self_affine",
    "sinusoid",
    "sphere",
    "sphere_with_roughness",
]

_PERIOD_TOLERANCE = 1e-9  # relative: a size within this of a whole number of wavelengths is periodic


# --- validation ----------------------------------------------------------------------------------


def _grid(
    shape: int | tuple[int, ...], size: float | tuple[float, ...]
) -> tuple[tuple[int, ...], tuple[float, ...]]:
    """Validate ``shape`` (1 or 2 ints >= 2) and ``size`` (positive lengths [m], one or one per axis)."""
    dims = (shape,) if isinstance(shape, (int, np.integer)) else tuple(shape)
    integers = all(isinstance(n, (int, np.integer)) and not isinstance(n, bool) for n in dims)
    if len(dims) not in (1, 2) or not integers or min(dims) < 2:
        raise InputError(
            "shape",
            f"{shape!r} is not 1 or 2 integers >= 2.",
            "give (nx,) for a profile or (nx, ny) for a map, at least 2 points per axis.",
        )
    no_string(size, "size")
    lengths = np.atleast_1d(np.asarray(size, dtype=float))
    if lengths.size == 1:
        lengths = np.repeat(lengths, len(dims))
    if lengths.shape != (len(dims),) or not np.all(np.isfinite(lengths)) or np.any(lengths <= 0):
        raise InputError(
            "size",
            f"{np.asarray(size, dtype=float).tolist()} is not {len(dims)} positive finite length(s).",
            "give the physical size in metres, one value or one per axis.",
        )
    return tuple(int(n) for n in dims), tuple(float(s) for s in lengths)


def grid_of(shape, size) -> tuple[tuple[int, ...], tuple[float, ...]]:
    """Return the (shape, size [m]) a generator makes of its ``shape`` and ``size`` arguments, checked."""
    return _grid(shape, size)


def _hurst(hurst: float) -> float:
    hurst = float(hurst)
    if not 0 < hurst <= 1:
        raise InputError(
            "hurst",
            f"Hurst exponent {hurst!r} is outside (0, 1].",
            "give 0 < hurst <= 1 (0.8 is typical of many engineering surfaces).",
        )
    return hurst


def _per_axis(value: float | tuple[float, ...], dim: int, field: str, example: str) -> tuple[float, ...]:
    """Validate one positive length [m] or one per axis."""
    values = np.atleast_1d(np.asarray(value, dtype=float))
    if values.size == 1:
        values = np.repeat(values, dim)
    if values.shape != (dim,):
        raise InputError(field, f"got {values.size} values for {dim} axes.", f"give one value or {dim}.")
    return tuple(positive(v, field, example=example, unit="m") for v in values)


# --- random fields -------------------------------------------------------------------------------

MODES = ("grid", "wavevector")
"""How a random generator draws its surface (``modes=``): noise on the grid, or a draw per wavevector."""

_GOLDEN = np.uint64(0x9E3779B97F4A7C15)  # splitmix64's increment (2^64 / golden ratio)
_MIX = (np.uint64(30), np.uint64(0xBF58476D1CE4E5B9), np.uint64(27), np.uint64(0x94D049BB133111EB))
_GAUSSIAN_TAIL = 1e-18  # "wavevector" Gaussian PSD: modes with C(q) / C(0) below this are left out
_SHELL_TOLERANCE = 1e-9  # relative: lattice wavevectors closer than this in |q| form one shell
_LATTICE_LIMIT = 40_000_000  # wavevectors in the box around a band (its lattice sum holds ~3/4 of them)


def _modes(modes: str) -> str:
    if modes not in MODES:
        raise InputError(
            "modes",
            f"unknown modes {modes!r}.",
            "choose 'grid' (white noise on the grid) or 'wavevector' (one draw per wavevector, the same "
            "surface on every grid).",
        )
    return modes


def _band(short_cutoff: float | None, modes: str) -> tuple[float | None, str]:
    """Check ``short_cutoff`` [m] and ``modes``: a grid-independent draw needs a band with an end."""
    modes = _modes(modes)
    if short_cutoff is not None:
        short_cutoff = positive(short_cutoff, "short_cutoff", example="1e-8", unit="m")
    elif modes == "wavevector":
        raise InputError(
            "short_cutoff",
            "modes='wavevector' needs the band to end at a given wavelength; without short_cutoff it runs to "
            "the corners of the grid, so the surface (its normalisation) would depend on the grid.",
            "give short_cutoff [m] (e.g. 4 pixels of the finest grid you will use), or use modes='grid'.",
        )
    return short_cutoff, modes


def _flat_band(field: str) -> InputError:
    return InputError(
        field,
        "no wavevector of the grid lies in the requested band: the surface is flat.",
        "widen the band between short_cutoff and long_cutoff, or refine / enlarge the grid.",
    )


def _wavevector_magnitude(shape: tuple[int, ...], size: tuple[float, ...]) -> np.ndarray:
    """Return ``|q|`` [rad/m] on the real-FFT grid (last axis halved)."""
    axes = [2.0 * np.pi * fft.fftfreq(n, d=s / n) for n, s in zip(shape[:-1], size[:-1], strict=True)]
    axes.append(2.0 * np.pi * fft.rfftfreq(shape[-1], d=size[-1] / shape[-1]))
    grids = np.meshgrid(*axes, indexing="ij")
    return np.sqrt(sum(g**2 for g in grids))


def _integer_wavevectors(shape: tuple[int, ...]) -> list[np.ndarray]:
    """Return the integer wavevector components k of the real-FFT layout (last axis halved), broadcastable."""
    axes = [np.rint(fft.fftfreq(n, d=1.0 / n)).astype(np.int64) for n in shape[:-1]]
    axes.append(np.arange(shape[-1] // 2 + 1, dtype=np.int64))
    return np.meshgrid(*axes, indexing="ij", sparse=True)


def _lattice_magnitude(wavevectors: list[np.ndarray], size: tuple[float, ...]) -> np.ndarray:
    """Return ``|q|`` = 2 pi |(k_x / L_x, k_y / L_y)| [rad/m], the same float for the same k on every grid."""
    return 2.0 * np.pi * np.sqrt(sum((k / s) ** 2 for k, s in zip(wavevectors, size, strict=True)))


def _half_lattice(size: tuple[float, ...], q_max: float, field: str) -> tuple[list[np.ndarray], np.ndarray]:
    """Return the wavevectors 0 < ``|q|`` <= ``q_max`` of the period ``size`` (one of each +-k), and ``|q|``.

    Integer components (k_x[, k_y]) of q = 2 pi (k_x / L_x, k_y / L_y); the half is k_y > 0, or
    k_y = 0 and k_x > 0 (k > 0 for a profile). Sums of even functions of q over the lattice are
    twice the sums over this half. A band of more than :data:`_LATTICE_LIMIT` wavevectors (far
    beyond any grid) is refused, naming ``field``.
    """
    reach = [int(q_max * s / (2.0 * np.pi)) + 1 for s in size]
    if math.prod(2 * r + 1 for r in reach) > _LATTICE_LIMIT:
        raise InputError(
            field,
            f"the band holds about {math.prod(reach):.3g} wavevectors of the {size} m period, more than any "
            "grid could hold.",
            "check the lengths and their unit (metres): the shortest wavelength is far below the pixel size.",
        )
    if len(size) == 1:
        wavevectors = [np.arange(1, reach[0] + 1, dtype=np.int64)]
    else:
        kx, ky = np.meshgrid(
            np.arange(-reach[0], reach[0] + 1, dtype=np.int64),
            np.arange(reach[1] + 1, dtype=np.int64),
            indexing="ij",
        )
        half = (ky > 0) | (kx > 0)
        wavevectors = [kx[half], ky[half]]
    magnitude = _lattice_magnitude(wavevectors, size)
    inside = magnitude <= q_max
    return [k[inside] for k in wavevectors], magnitude[inside]


def _splitmix64(state: np.ndarray) -> np.ndarray:
    """Return splitmix64's output for each uint64 ``state`` (Steele et al. 2014), wrapping mod 2^64."""
    shift_a, multiply_a, shift_b, multiply_b = _MIX
    state = state + _GOLDEN
    state = (state ^ (state >> shift_a)) * multiply_a
    state = (state ^ (state >> shift_b)) * multiply_b
    return state ^ (state >> np.uint64(31))


def _seed_key(seed: int | None) -> np.uint64:
    """Return the 64-bit key of ``seed`` (``numpy.random.SeedSequence``; None: fresh entropy)."""
    try:
        return np.random.SeedSequence(seed).generate_state(1, dtype=np.uint64)[0]
    except (TypeError, ValueError):
        raise InputError(
            "seed",
            f"{seed!r} is not a non-negative integer.",
            "give an integer >= 0, or None for a fresh draw.",
        ) from None


def _wavevector_draws(wavevectors: list[np.ndarray], key: np.uint64) -> np.ndarray:
    """Return a unit complex Gaussian (E|z|^2 = 1) for each integer wavevector, a function of (key, k) only.

    Counter-based: the key and the components are chained through splitmix64, two further outputs
    give two uniforms in (0, 1] (53 bits) and Box-Muller gives z = sqrt(-ln u1) exp(2 pi i u2).
    """
    state = np.full(np.broadcast_shapes(*(np.shape(k) for k in wavevectors)), key, dtype=np.uint64)
    for k in wavevectors:
        state = _splitmix64(state ^ np.asarray(k, dtype=np.int64).view(np.uint64))
    first = _splitmix64(state)
    uniforms = [
        ((bits >> np.uint64(11)).astype(float) + 1.0) * 2.0**-53 for bits in (first, _splitmix64(first))
    ]
    return np.sqrt(-np.log(uniforms[0])) * np.exp(2j * np.pi * uniforms[1])


def _wavevector_coefficients(
    shape: tuple[int, ...], wavevectors: list[np.ndarray], seed: int | None
) -> np.ndarray:
    """Return the unit complex Gaussian of each mode of the real-FFT layout, drawn from (seed, k).

    Hermitian: on the k_y = 0 column of a map the mode -k is the conjugate of the draw of k (k_x > 0
    drawn). The q = 0 mode and the Nyquist modes (``|k|`` = n / 2 along an axis of even n) are zero, so
    every mode a grid holds has the same coefficient on every grid that holds it.
    """
    wavevectors = np.broadcast_arrays(*wavevectors)
    mirrored = (wavevectors[-1] == 0) & (wavevectors[0] < 0)
    draws = _wavevector_draws([np.where(mirrored, -k, k) for k in wavevectors], _seed_key(seed))
    draws = np.where(mirrored, np.conj(draws), draws)
    dropped = np.all([k == 0 for k in wavevectors], axis=0)
    for k, n in zip(wavevectors, shape, strict=True):
        if n % 2 == 0:
            dropped |= np.abs(k) == n // 2
    draws[dropped] = 0.0
    return draws


def _filtered_noise(
    shape: tuple[int, ...],
    size: tuple[float, ...],
    psd_shape: Callable[[np.ndarray], np.ndarray],
    seed: int | None,
    field: str,
    modes: str = "grid",
) -> np.ndarray:
    """Real periodic random heights sum_q c_q exp(i q.r) with E|c_q|^2 proportional to ``psd_shape(|q|)``.

    ``"grid"``: the real FFT of white noise on the grid times sqrt(psd_shape), E|c_q|^2 =
    psd_shape / N for N grid points (unscaled: the caller rescales). ``"wavevector"``: c_q = z_q
    sqrt(psd_shape(``|q|``)) with z_q of :func:`_wavevector_coefficients`, so E|c_q|^2 = psd_shape
    exactly. The q = 0 component is always zero, so the heights have zero mean.
    """
    if modes == "grid":
        spectrum = fft.rfftn(np.random.default_rng(seed).standard_normal(shape))
        magnitude = _wavevector_magnitude(shape, size)
    else:
        wavevectors = _integer_wavevectors(shape)
        spectrum = math.prod(shape) * _wavevector_coefficients(shape, wavevectors, seed)
        magnitude = _lattice_magnitude(wavevectors, size)
    amplitude = np.zeros(magnitude.shape)
    nonzero = magnitude > 0
    amplitude[nonzero] = np.sqrt(psd_shape(magnitude[nonzero]))
    heights = fft.irfftn(spectrum * amplitude, s=shape)
    if not np.any(heights):
        raise _flat_band(field)
    return heights


def _normalised_noise(
    shape: tuple[int, ...],
    size: tuple[float, ...],
    psd_shape: Callable[[np.ndarray], np.ndarray],
    q_max: float,
    target: float,
    slope: bool,
    seed: int | None,
    field: str,
) -> np.ndarray:
    """Return ``"wavevector"`` heights whose PSD is normalised on the lattice, not on the grid.

    Every mode 0 < ``|q|`` <= q_max of the period ``size`` (held by the grid or not) gets the variance
    E|c_q|^2 = target^2 psd_shape(``|q|``) / sum_lattice w(q) psd_shape(``|q|``), w = 1 (``target`` the rms
    height [m]) or ``|q|``^2 (``target`` the rms gradient [-], continuum derivative): the expected
    mean square of the continuum field is target^2, and the same number on every grid.
    """
    _, magnitude = _half_lattice(size, q_max, field)
    total = 2.0 * float(np.sum(psd_shape(magnitude) * (magnitude**2 if slope else 1.0)))
    if total == 0:
        raise _flat_band(field)
    scale = target**2 / total
    return _filtered_noise(
        shape, size, lambda q: np.where(q <= q_max, scale * psd_shape(q), 0.0), seed, field, "wavevector"
    )


def _scaled(topography: Topography, rms_height: float | None, rms_slope: float | None) -> Topography:
    """Rescale heights so the discrete Rq (or default rms slope) equals the target exactly."""
    if rms_height is not None:
        factor = rms_height / statistics.rq(topography)
    else:
        factor = rms_slope / statistics.rms_slope(topography)
    return topography.with_heights(topography.heights * factor)


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


def _self_affine_arguments(
    shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, rolloff, modes="grid"
):
    """Check and normalise the arguments of :func:`self_affine` (see :func:`check_arguments`)."""
    shape, size = _grid(shape, size)
    hurst = _hurst(hurst)
    rms_height, rms_slope = _one_target(rms_height, rms_slope)
    short_cutoff, modes = _band(short_cutoff, modes)
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
        _self_affine_arguments(
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
    if modes == "grid":
        heights = _filtered_noise(shape, size, psd_shape, seed, "short_cutoff")
        return _scaled(Topography(heights, size, periodic=True, info=info), rms_height, rms_slope)
    target, slope = (rms_height, False) if rms_height is not None else (rms_slope, True)
    heights = _normalised_noise(shape, size, psd_shape, q_short, target, slope, seed, "short_cutoff")
    return Topography(heights, size, periodic=True, info=info)


def _gaussian_random_arguments(shape, size, rms_height, correlation_length, modes="grid"):
    """Check and normalise the arguments of :func:`gaussian_random`."""
    shape, size = _grid(shape, size)
    rms_height = positive(rms_height, "rms_height", example="1e-9", unit="m")
    correlation_length = positive(correlation_length, "correlation_length", example="1e-7", unit="m")
    return shape, size, rms_height, correlation_length, _modes(modes)


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
    shape, size, rms_height, correlation_length, modes = _gaussian_random_arguments(
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
    if modes == "grid":
        heights = _filtered_noise(shape, size, psd_shape, seed, "correlation_length")
        return _scaled(Topography(heights, size, periodic=True, info=info), rms_height, None)
    reach = 2.0 * math.sqrt(math.log(1.0 / _GAUSSIAN_TAIL)) / correlation_length
    heights = _normalised_noise(shape, size, psd_shape, reach, rms_height, False, seed, "correlation_length")
    return Topography(heights, size, periodic=True, info=info)


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
    wavevectors, magnitude = _half_lattice(size, 1.5 * q_short_continuum, "size")  # room to refine q_s
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


def _matched_moments_arguments(shape, size, m0, m2, m4, hurst, modes="wavevector", coarse="refuse"):
    """Check the arguments of :func:`matched_moments` and solve its band (see :func:`check_arguments`)."""
    shape, size = _grid(shape, size)
    if len(shape) != 2:
        raise InputError(
            "shape", "matched_moments makes a map (paper 002's moments are areal).", "give shape=(nx, ny)."
        )
    m0 = positive(m0, "m0", example="2e-15", unit="m^2")
    m2 = positive(m2, "m2", example="0.0023 (dimensionless)")
    m4 = positive(m4, "m4", example="1.7e10", unit="1/m^2")
    hurst, modes = _hurst(hurst), _modes(modes)
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
    shape, size, m0, m2, m4, hurst, modes, band = _matched_moments_arguments(
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
    magnitude = _wavevector_magnitude(shape, size)
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
    shape, size = _grid(shape, template.size if size is None else size)
    q, psd = statistics.psd_radial(template, ring_ratio=ring_ratio)
    keep = psd > 1e-12 * psd.max()  # round-off beyond a band's end is no power
    log_q, log_c = np.log(q[keep]), np.log(psd[keep])

    def interpolated(magnitude: np.ndarray) -> np.ndarray:
        inside = magnitude <= q[keep].max() * math.sqrt(ring_ratio)  # to the outer edge of its last ring
        values = np.exp(np.interp(np.log(np.maximum(magnitude, q[keep].min())), log_q, log_c))
        return np.where(inside, values, 0.0)

    heights = _filtered_noise(shape, size, interpolated, seed, "shape")
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


# --- deterministic shapes ------------------------------------------------------------------------


def _radial_distance(
    shape: tuple[int, ...], size: tuple[float, ...], centre: tuple[float, ...] | None, periodic: bool
) -> np.ndarray:
    """Return the distance [m] of each grid point from ``centre`` (default: near the middle).

    The default centre is ``(n // 2) * spacing`` per axis, a grid point, so the apex is sampled.
    Periodic grids use the minimum-image distance.
    """
    spacing = [s / n for n, s in zip(shape, size, strict=True)]
    if centre is None:
        centre = tuple((n // 2) * h for n, h in zip(shape, spacing, strict=True))
    centre = np.atleast_1d(np.asarray(centre, dtype=float))
    if centre.shape != (len(shape),) or not np.all(np.isfinite(centre)):
        raise InputError(
            "centre",
            f"{tuple(centre)} is not {len(shape)} finite coordinates.",
            f"give the apex position in metres, {len(shape)} values.",
        )
    squared = 0.0
    for axis, (n, h, c, s) in enumerate(zip(shape, spacing, centre, size, strict=True)):
        d = np.arange(n) * h - c
        if periodic:
            d = d - s * np.round(d / s)
        squared = squared + np.expand_dims(d**2, tuple(a for a in range(len(shape)) if a != axis))
    return np.sqrt(np.broadcast_to(squared, shape))


def _farthest(shape, size, centre, periodic: bool) -> float:
    """Largest distance [m] of a grid point from ``centre`` (minimum image when periodic)."""
    spacing = [s / n for n, s in zip(shape, size, strict=True)]
    if centre is None:
        centre = tuple((n // 2) * h for n, h in zip(shape, spacing, strict=True))
    centre = np.atleast_1d(np.asarray(centre, dtype=float))
    if centre.shape != (len(shape),) or not np.all(np.isfinite(centre)):
        raise InputError(
            "centre",
            f"{tuple(centre)} is not {len(shape)} finite coordinates.",
            f"give the apex position in metres, {len(shape)} values.",
        )
    reach = []
    for n, h, c, s in zip(shape, spacing, centre, size, strict=True):
        d = np.array([0.0, (n - 1) * h]) - c
        reach.append(s / 2 if periodic else float(np.max(np.abs(d))))
    return float(np.sqrt(sum(r**2 for r in reach)))


def _sphere_arguments(shape, size, radius, centre, kind, periodic):
    """Check and normalise the arguments of :func:`sphere`."""
    shape, size = _grid(shape, size)
    radius = positive(radius, "radius", example="5e-3", unit="m")
    if kind not in ("sphere", "paraboloid"):
        raise InputError("kind", f"unknown kind {kind!r}.", "choose 'sphere' or 'paraboloid'.")
    farthest = _farthest(shape, size, centre, periodic)
    if kind == "sphere" and farthest > radius:
        raise InputError(
            "radius",
            f"the grid reaches {farthest:.6g} m from the apex, beyond the sphere radius {radius:.6g} m.",
            "use a smaller size, a larger radius, or kind='paraboloid'.",
        )
    return shape, size, radius


def sphere(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    radius: float,
    centre: tuple[float, ...] | None = None,
    kind: str = "sphere",
    periodic: bool = False,
) -> Topography:
    r"""Sphere (or cylinder, for a profile) with its apex at height 0.

    .. math::

        z_\mathrm{sphere}(r) = \sqrt{R^2 - r^2} - R, \qquad z_\mathrm{paraboloid}(r) = -\frac{r^2}{2R}

    with r the distance from ``centre`` (in-plane; periodic grids use the nearest image). The
    paraboloid is the small-slope (Hertz) approximation of the cap.

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny).
    size : float or tuple of float
        Physical size [m].
    radius : float
        Radius of curvature R [m].
    centre : tuple of float, optional
        Apex position [m]; default the grid point ``(n // 2) * spacing`` on each axis.
    kind : {"sphere", "paraboloid"}
        Exact spherical cap or paraboloid.
    periodic : bool
        Mark the result periodic (with minimum-image distances).

    Returns
    -------
    Topography

    Raises
    ------
    InputError
        ``kind="sphere"`` with a grid point farther than R from the centre (field ``radius``).

    References
    ----------
    Johnson, K. L. (1985). Contact Mechanics, ch. 4. Cambridge University Press.
    doi:10.1017/CBO9781139171731
    """
    shape, size, radius = _sphere_arguments(shape, size, radius, centre, kind, periodic)
    distance = _radial_distance(shape, size, centre, periodic)
    if kind == "paraboloid":
        heights = -(distance**2) / (2.0 * radius)
    else:
        heights = np.sqrt(np.maximum(radius**2 - distance**2, 0.0)) - radius
    info = {"name": kind, "generator": "sphere", "radius": radius}
    return Topography(heights, size, periodic=periodic, info=info)


def _divides(size: tuple[float, ...], wavelength: tuple[float, ...]) -> bool:
    cycles = [s / w for s, w in zip(size, wavelength, strict=True)]
    return all(abs(c - round(c)) <= _PERIOD_TOLERANCE * max(c, 1.0) for c in cycles)


def _sinusoid_arguments(shape, size, amplitude, wavelength, axis):
    """Check and normalise the arguments of :func:`sinusoid`."""
    shape, size = _grid(shape, size)
    amplitude = positive(amplitude, "amplitude", example="1e-7", unit="m")
    wavelength = positive(wavelength, "wavelength", example="1e-5", unit="m")
    if axis not in range(len(shape)):
        raise InputError(
            "axis", f"axis {axis!r} does not exist on a {len(shape)}D grid.", "use 0 (x), or 1 (y) for a map."
        )
    return shape, size, amplitude, wavelength


def sinusoid(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    amplitude: float,
    wavelength: float,
    axis: int = 0,
) -> Topography:
    r"""Single sinusoidal wave along one axis.

    .. math:: z = A \cos(2\pi x_\mathrm{axis} / \lambda)

    constant along the other axis. The result is periodic when ``size[axis]`` is a whole number of
    wavelengths (relative tolerance 1e-9). Closed forms: Rq = A / sqrt(2), and along ``axis``
    <z'^2> = (2 pi/lambda)^2 A^2 / 2, <z''^2> = (2 pi/lambda)^4 A^2 / 2.

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny).
    size : float or tuple of float
        Physical size [m].
    amplitude : float
        A [m] (half the peak-to-valley height).
    wavelength : float
        lambda [m].
    axis : int
        0 (x) or 1 (y, maps only).

    Returns
    -------
    Topography
    """
    shape, size, amplitude, wavelength = _sinusoid_arguments(shape, size, amplitude, wavelength, axis)
    x = np.arange(shape[axis]) * size[axis] / shape[axis]
    wave = amplitude * np.cos(2.0 * np.pi * x / wavelength)
    heights = np.broadcast_to(np.expand_dims(wave, tuple(a for a in range(len(shape)) if a != axis)), shape)
    info = {
        "name": "sinusoid",
        "generator": "sinusoid",
        "amplitude": amplitude,
        "wavelength": wavelength,
        "axis": axis,
    }
    return Topography(heights, size, periodic=_divides(size[axis : axis + 1], (wavelength,)), info=info)


def _bisinusoid_arguments(shape, size, amplitude, wavelength):
    """Check and normalise the arguments of :func:`bisinusoid`."""
    shape, size = _grid(shape, size)
    if len(shape) != 2:
        raise InputError("shape", "a bisinusoid needs a map (nx, ny).", "use sinusoid for a profile.")
    amplitude = positive(amplitude, "amplitude", example="1e-7", unit="m")
    return shape, size, amplitude, _per_axis(wavelength, 2, "wavelength", "1e-5")


def bisinusoid(
    shape: tuple[int, int],
    size: float | tuple[float, float],
    *,
    amplitude: float,
    wavelength: float | tuple[float, float],
) -> Topography:
    r"""Egg-box surface, the product of two cosines.

    .. math:: z = A \cos(2\pi x/\lambda_x)\cos(2\pi y/\lambda_y)

    Periodic when each size is a whole number of its wavelength (relative tolerance 1e-9). Closed
    forms: m0 = A^2/4, <z_x^2> = k_x^2 A^2/4, <z_xx^2> = k_x^4 A^2/4 (k = 2 pi / lambda), hence
    m2 = A^2 (k_x^2 + k_y^2)/8 and m4 = A^2 (k_x^4 + k_y^4)/8.

    Parameters
    ----------
    shape : tuple of int
        Grid points (nx, ny) of a map.
    size : float or tuple of float
        Physical size [m].
    amplitude : float
        A [m].
    wavelength : float or tuple of float
        lambda_x, lambda_y [m] (one value: both).

    Returns
    -------
    Topography
    """
    shape, size, amplitude, wavelength = _bisinusoid_arguments(shape, size, amplitude, wavelength)
    x, y = (np.arange(n) * s / n for n, s in zip(shape, size, strict=True))
    heights = amplitude * np.outer(
        np.cos(2.0 * np.pi * x / wavelength[0]), np.cos(2.0 * np.pi * y / wavelength[1])
    )
    info = {"name": "bisinusoid", "generator": "bisinusoid", "amplitude": amplitude, "wavelength": wavelength}
    return Topography(heights, size, periodic=_divides(size, wavelength), info=info)


def _flat_punch_arguments(shape, size, radius, depth):
    """Check and normalise the arguments of :func:`flat_punch`."""
    shape, size = _grid(shape, size)
    radius = positive(radius, "radius", example="10e-6", unit="m")
    return shape, size, radius, positive(depth, "depth", example="1e-6", unit="m")


def flat_punch(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    radius: float,
    depth: float,
    centre: tuple[float, ...] | None = None,
) -> Topography:
    """Flat circular punch face: height 0 within ``radius`` of the centre, ``-depth`` outside.

    A grid point at distance r belongs to the face when r <= radius. For a profile the face is the
    segment ``|x - centre|`` <= radius (a flat strip).

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny).
    size : float or tuple of float
        Physical size [m].
    radius : float
        Face radius a [m].
    depth : float
        Step down outside the face [m] (finite: the surroundings stay out of contact only while
        the approach is below it).
    centre : tuple of float, optional
        Face centre [m]; default the grid point ``(n // 2) * spacing``.

    Returns
    -------
    Topography
        Non-periodic surface.

    References
    ----------
    Johnson, K. L. (1985). Contact Mechanics, section 3.8 (rigid flat punch).
    doi:10.1017/CBO9781139171731
    """
    shape, size, radius, depth = _flat_punch_arguments(shape, size, radius, depth)
    heights = np.where(_radial_distance(shape, size, centre, False) <= radius, 0.0, -depth)
    info = {"name": "flat punch", "generator": "flat_punch", "radius": radius, "depth": depth}
    return Topography(heights, size, periodic=False, info=info)


def _raised_island_arguments(
    shape, size, island_size, thickness, rms_height, hurst, substrate_height, short_cutoff=None, modes="grid"
):
    """Check and normalise the arguments of :func:`raised_island`."""
    shape, size = _grid(shape, size)
    short_cutoff, modes = _band(short_cutoff, modes)
    island_size = positive(island_size, "island_size", example="25e-6", unit="m")
    thickness = positive(thickness, "thickness", example="1e-6", unit="m")
    rms_height = positive(rms_height, "rms_height", example="1e-9", unit="m", allow_zero=True)
    hurst = _hurst(hurst)
    substrate_height = float(substrate_height)
    if not math.isfinite(substrate_height):
        raise InputError("substrate_height", "must be finite.", "give a height in metres.")
    if island_size > min(size):
        raise InputError(
            "island_size",
            f"{island_size:.6g} m is wider than the scan {size} m.",
            "use a smaller island or a larger size.",
        )
    return shape, size, island_size, thickness, rms_height, hurst, substrate_height, short_cutoff, modes


def raised_island(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    island_size: float,
    thickness: float,
    rms_height: float = 0.0,
    hurst: float = 0.8,
    seed: int | None = None,
    substrate_height: float = 0.0,
    short_cutoff: float | None = None,
    modes: str = "grid",
) -> Topography:
    r"""Make a raised square island on a flat substrate, rough on top: the SU-8 sample of paper 002.

    Heights are ``substrate_height`` outside the island and ``substrate_height + thickness +
    roughness`` on it. The island is the square (segment, for a profile) of side ``island_size``
    centred on the grid point ``(n // 2) * spacing``: a point belongs to it when its distance to the
    centre along every axis is at most ``island_size / 2``. The roughness is a self-affine field
    (:func:`self_affine` on the whole grid, no long cutoff, ``short_cutoff`` and ``modes`` as given)
    restricted to the island, then shifted to zero mean and rescaled so its rms *over the island
    pixels* equals ``rms_height`` exactly. With ``modes="wavevector"`` the field is the same on
    every grid up to that one factor, which the grid's island pixels set.

    Paper 002: a 25 um x 25 um island, t = 6.3 um thick, scanned over 60 um x 60 um.

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny).
    size : float or tuple of float
        Physical size of the scan [m] (>= island_size).
    island_size : float
        Side of the square island [m].
    thickness : float
        Island height above the substrate [m].
    rms_height : float
        Rq of the island top [m] (0: smooth).
    hurst : float
        Hurst exponent of the roughness, in (0, 1].
    seed : int, optional
        Seed of the roughness.
    substrate_height : float
        Height of the substrate [m].
    short_cutoff : float, optional
        Shortest wavelength of the roughness [m] (default: to the corners of the grid; required
        with ``modes="wavevector"``).
    modes : {"grid", "wavevector"}
        How the roughness is drawn, see :func:`self_affine`.

    Returns
    -------
    Topography
        Non-periodic surface; ``info["modes"]`` records ``modes``.

    References
    ----------
    Seed paper 002, section II (raised SU-8 squares, Fig. 2).
    """
    shape, size, island_size, thickness, rms_height, hurst, substrate_height, short_cutoff, modes = (
        _raised_island_arguments(
            shape, size, island_size, thickness, rms_height, hurst, substrate_height, short_cutoff, modes
        )
    )
    on_island = np.ones(shape, dtype=bool)
    for axis, (n, s) in enumerate(zip(shape, size, strict=True)):
        x = np.arange(n) * s / n - (n // 2) * s / n
        inside = np.abs(x) <= island_size / 2 * (1 + _PERIOD_TOLERANCE)
        on_island &= np.expand_dims(inside, tuple(a for a in range(len(shape)) if a != axis))
    heights = np.full(shape, substrate_height)
    heights[on_island] += thickness
    if rms_height > 0:
        roughness = self_affine(
            shape, size, hurst=hurst, rms_height=1.0, seed=seed, short_cutoff=short_cutoff, modes=modes
        ).heights[on_island]
        roughness = roughness - roughness.mean()
        heights[on_island] += roughness * rms_height / np.sqrt(np.mean(roughness**2))
    info = {
        "name": "raised island",
        "generator": "raised_island",
        "island_size": island_size,
        "thickness": thickness,
        "rms_height": rms_height,
        "hurst": hurst,
        "seed": seed,
        "short_cutoff": short_cutoff,
        "modes": modes,
    }
    return Topography(heights, size, periodic=False, info=info)


def sphere_with_roughness(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    radius: float,
    rms_height: float,
    hurst: float = 0.8,
    seed: int | None = None,
    kind: str = "paraboloid",
    short_cutoff: float | None = None,
    long_cutoff: float | None = None,
    modes: str = "grid",
) -> Topography:
    """Rough sphere: :func:`sphere` plus :func:`self_affine` roughness of rms ``rms_height``.

    Models the AFM tip of paper 000 (a sphere with roughness, 20 nm pixels over 5 um scans) and
    the rough ball of paper 001 (whose "flattened roughness" is what remains after
    :func:`roughcontact.topography.process.remove_sphere`). The roughness is periodic with the
    grid size; the sum is not, so the result is marked non-periodic.

    Parameters
    ----------
    shape : int or tuple of int
        Grid points, (nx,) or (nx, ny).
    size : float or tuple of float
        Physical size [m].
    radius : float
        Radius of curvature R [m].
    rms_height : float
        Rq of the roughness [m] (> 0).
    hurst : float
        Hurst exponent in (0, 1].
    seed : int, optional
        Seed of the roughness.
    kind : {"paraboloid", "sphere"}
        Shape of the body, see :func:`sphere`.
    short_cutoff, long_cutoff : float, optional
        Roughness cutoffs [m], see :func:`self_affine`.
    modes : {"grid", "wavevector"}
        How the roughness is drawn, see :func:`self_affine` (``"wavevector"`` needs
        ``short_cutoff``; its rms is then ``rms_height`` in expectation, not exactly).

    Returns
    -------
    Topography
        Non-periodic surface; the apex of the smooth body is at 0 at the grid point ``(n // 2) * spacing``;
        ``info["modes"]`` records ``modes``.

    References
    ----------
    Seed paper 000 (AFM tip sphere and roughness); seed paper 001, section 4 (ball roughness).
    doi:10.1115/1.4045900
    """
    body = sphere(shape, size, radius=radius, kind=kind)
    roughness = self_affine(
        shape,
        size,
        hurst=hurst,
        rms_height=rms_height,
        seed=seed,
        short_cutoff=short_cutoff,
        long_cutoff=long_cutoff,
        modes=modes,
    )
    info = {
        **dict(body.info),
        "name": f"rough {kind}",
        "generator": "sphere_with_roughness",
        "rms_height": rms_height,
        "hurst": hurst,
        "seed": seed,
        "modes": modes,
    }
    return Topography(body.heights + roughness.heights, body.size, periodic=False, info=info)


def check_arguments(generator: str, shape, size, options: Mapping[str, Any]) -> None:
    """Run the checks the generator ``generator`` runs on its arguments, without generating anything.

    What a study file's validation calls for every generated topography of every case, so that
    ``roughcontact validate`` refuses what the run would (a Hurst exponent outside (0, 1], a
    sphere smaller than its grid, crossed cutoffs, ...). ``seed`` and options a generator does
    not check are ignored; ``options`` are the generator's other keyword arguments.

    Raises
    ------
    InputError
        As the generator would, naming the argument.
    """
    options = {key: value for key, value in options.items() if key != "seed"}
    if generator == "self_affine":
        _self_affine_arguments(
            shape,
            size,
            options["hurst"],
            options.get("rms_height"),
            options.get("rms_slope"),
            options.get("short_cutoff"),
            options.get("long_cutoff"),
            options.get("rolloff"),
            options.get("modes", "grid"),
        )
    elif generator == "gaussian_random":
        _gaussian_random_arguments(
            shape, size, options["rms_height"], options["correlation_length"], options.get("modes", "grid")
        )
    elif generator == "matched_moments":
        _matched_moments_arguments(
            shape,
            size,
            options["m0"],
            options["m2"],
            options["m4"],
            options.get("hurst", 0.8),
            options.get("modes", "wavevector"),
            options.get("coarse", "refuse"),
        )
    elif generator in ("sphere", "sphere_with_roughness"):
        kind = options.get("kind", "sphere" if generator == "sphere" else "paraboloid")
        _sphere_arguments(
            shape, size, options["radius"], options.get("centre"), kind, options.get("periodic", False)
        )
        if generator == "sphere_with_roughness":
            cutoffs = (options.get("short_cutoff"), options.get("long_cutoff"))
            _self_affine_arguments(
                shape,
                size,
                options.get("hurst", 0.8),
                options["rms_height"],
                None,
                *cutoffs,
                None,
                options.get("modes", "grid"),
            )
    elif generator == "sinusoid":
        _sinusoid_arguments(shape, size, options["amplitude"], options["wavelength"], options.get("axis", 0))
    elif generator == "bisinusoid":
        _bisinusoid_arguments(shape, size, options["amplitude"], options["wavelength"])
    elif generator == "flat_punch":
        _flat_punch_arguments(shape, size, options["radius"], options["depth"])
    elif generator == "raised_island":
        _raised_island_arguments(
            shape,
            size,
            options["island_size"],
            options["thickness"],
            options.get("rms_height", 0.0),
            options.get("hurst", 0.8),
            options.get("substrate_height", 0.0),
            options.get("short_cutoff"),
            options.get("modes", "grid"),
        )
