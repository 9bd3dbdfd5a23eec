"""Fourier-filtered random heights, drawn in either ``mode``: noise on the grid, or a draw per wavevector.

The machinery of the random generators (:mod:`.random_fields`, :mod:`.matched`); see
:mod:`roughcontact.topography.generate` for what the two modes are.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy import fft

from ...checks import positive
from ...errors import InputError
from .. import statistics
from ..surface import Topography

MODES = ("grid", "wavevector")
"""How a random generator draws its surface (``modes=``): noise on the grid, or a draw per wavevector."""


_GOLDEN = np.uint64(0x9E3779B97F4A7C15)  # splitmix64's increment (2^64 / golden ratio)


_MIX = (np.uint64(30), np.uint64(0xBF58476D1CE4E5B9), np.uint64(27), np.uint64(0x94D049BB133111EB))


_LATTICE_LIMIT = 40_000_000  # wavevectors in the box around a band (its lattice sum holds ~3/4 of them)


def checked_modes(modes: str) -> str:
    """Return ``modes`` if it is one of :data:`MODES`; InputError naming ``modes`` otherwise."""
    if modes not in MODES:
        raise InputError(
            "modes",
            f"unknown modes {modes!r}.",
            "choose 'grid' (white noise on the grid) or 'wavevector' (one draw per wavevector, the same "
            "surface on every grid).",
        )
    return modes


def checked_band(short_cutoff: float | None, modes: str) -> tuple[float | None, str]:
    """Check ``short_cutoff`` [m] and ``modes``: a grid-independent draw needs a band with an end."""
    modes = checked_modes(modes)
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


def wavevector_magnitude(shape: tuple[int, ...], size: tuple[float, ...]) -> np.ndarray:
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


def half_lattice(size: tuple[float, ...], q_max: float, field: str) -> tuple[list[np.ndarray], np.ndarray]:
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


def filtered_noise(
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
        magnitude = wavevector_magnitude(shape, size)
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


def normalised_noise(
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
    _, magnitude = half_lattice(size, q_max, field)
    total = 2.0 * float(np.sum(psd_shape(magnitude) * (magnitude**2 if slope else 1.0)))
    if total == 0:
        raise _flat_band(field)
    scale = target**2 / total
    return filtered_noise(
        shape, size, lambda q: np.where(q <= q_max, scale * psd_shape(q), 0.0), seed, field, "wavevector"
    )


def scaled_to(topography: Topography, rms_height: float | None, rms_slope: float | None) -> Topography:
    """Rescale heights so the discrete Rq (or default rms slope) equals the target exactly."""
    if rms_height is not None:
        factor = rms_height / statistics.rq(topography)
    else:
        factor = rms_slope / statistics.rms_slope(topography)
    return topography.with_heights(topography.heights * factor)


def random_surface(
    shape: tuple[int, ...],
    size: tuple[float, ...],
    psd_shape: Callable[[np.ndarray], np.ndarray],
    q_max: float | None,
    rms_height: float | None,
    rms_slope: float | None,
    seed: int | None,
    modes: str,
    field: str,
    info: dict,
) -> Topography:
    """Return a periodic random surface of PSD shape ``psd_shape`` drawn in ``modes``, with ``info``.

    ``"grid"``: noise on the grid (:func:`filtered_noise`) rescaled so that its rms height (or, with
    ``rms_height`` None, its rms slope) is the target exactly (:func:`scaled_to`). ``"wavevector"``:
    one draw per wavevector up to ``q_max`` [rad/m], normalised on the lattice
    (:func:`normalised_noise`). ``field`` names the argument that an empty band is blamed on.
    """
    if modes == "grid":
        heights = filtered_noise(shape, size, psd_shape, seed, field)
        return scaled_to(Topography(heights, size, periodic=True, info=info), rms_height, rms_slope)
    target, slope = (rms_height, False) if rms_height is not None else (rms_slope, True)
    heights = normalised_noise(shape, size, psd_shape, q_max, target, slope, seed, field)
    return Topography(heights, size, periodic=True, info=info)
