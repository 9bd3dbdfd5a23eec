r"""Synthetic surfaces as :class:`~roughcontact.topography.surface.Topography`, in SI units.

Self-affine and Gaussian random roughness, spheres, sinusoids, a flat punch, the raised island of
paper 002 and a rough sphere (AFM tip of paper 000, ball of paper 001).

Every generator takes SI arguments (lengths in metres) and returns a
:class:`~roughcontact.topography.surface.Topography`. ``shape`` is the number of grid points,
``(nx,)`` (or an int) for a profile along x and ``(nx, ny)`` for a map; ``size`` is the physical
extent [m], one value or one per axis. Grid point i sits at ``x = i * size / nx`` (first point at
0). Heights point out of the body, towards the counter-surface.

Random surfaces are made by Fourier filtering: real white noise is transformed with a real FFT,
multiplied by the square root of the target PSD and transformed back. Filtering the transform of
a real field keeps the Hermitian symmetry, so the heights are real, periodic with period ``size``,
and reproducible for a given ``seed`` (``numpy.random.default_rng(seed)``).

References
----------
Jacobs, T. D. B., Junge, T. and Pastewka, L. (2017). Quantitative characterization of surface
topography using spectral analysis. Surf. Topogr.: Metrol. Prop. 5, 013001.
doi:10.1088/2051-672X/aa51f8

Persson, B. N. J., Albohr, O., Tartaglino, U., Volokitin, A. I. and Tosatti, E. (2005). On the
nature of surface roughness with application to contact mechanics, sealing, rubber friction and
adhesion. J. Phys.: Condens. Matter 17, R1. doi:10.1088/0953-8984/17/1/R01
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
from scipy import fft

from ..checks import no_string, positive
from ..errors import InputError
from . import statistics
from .surface import Topography

__all__ = [
    "bisinusoid",
    "flat_punch",
    "gaussian_random",
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
            f"{size!r} is not {len(dims)} positive finite length(s).",
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


def _wavevector_magnitude(shape: tuple[int, ...], size: tuple[float, ...]) -> np.ndarray:
    """Return |q| [rad/m] on the real-FFT grid (last axis halved)."""
    axes = [2.0 * np.pi * fft.fftfreq(n, d=s / n) for n, s in zip(shape[:-1], size[:-1], strict=True)]
    axes.append(2.0 * np.pi * fft.rfftfreq(shape[-1], d=size[-1] / shape[-1]))
    grids = np.meshgrid(*axes, indexing="ij")
    return np.sqrt(sum(g**2 for g in grids))


def _filtered_noise(
    shape: tuple[int, ...],
    size: tuple[float, ...],
    psd_shape: Callable[[np.ndarray], np.ndarray],
    seed: int | None,
    field: str,
) -> np.ndarray:
    """Real periodic random heights whose PSD is proportional to ``psd_shape(|q|)`` (unscaled).

    The q = 0 component is always zero, so the heights have zero mean.
    """
    noise = np.random.default_rng(seed).standard_normal(shape)
    magnitude = _wavevector_magnitude(shape, size)
    amplitude = np.zeros(magnitude.shape)
    nonzero = magnitude > 0
    amplitude[nonzero] = np.sqrt(psd_shape(magnitude[nonzero]))
    heights = fft.irfftn(fft.rfftn(noise) * amplitude, s=shape)
    if not np.any(heights):
        raise InputError(
            field,
            "no wavevector of the grid lies in the requested band: the surface is flat.",
            "widen the band between short_cutoff and long_cutoff, or refine / enlarge the grid.",
        )
    return heights


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


def _self_affine_arguments(shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, rolloff):
    """Check and normalise the arguments of :func:`self_affine` (see :func:`check_arguments`)."""
    shape, size = _grid(shape, size)
    hurst = _hurst(hurst)
    rms_height, rms_slope = _one_target(rms_height, rms_slope)
    if short_cutoff is not None:
        short_cutoff = positive(short_cutoff, "short_cutoff", example="1e-8", unit="m")
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
    return shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, plateau


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

    The noise gives random phases and Rayleigh-distributed amplitudes about the target PSD. The
    heights are then multiplied by one factor so that the *discrete* statistics hit the target
    exactly (to round-off): Rq (:func:`~roughcontact.topography.statistics.rq`) for
    ``rms_height``, or the forward-difference rms slope
    (:func:`~roughcontact.topography.statistics.rms_slope`) for ``rms_slope``.

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
        Shortest wavelength lambda_s [m].
    long_cutoff : float, optional
        Longest self-affine wavelength lambda_L [m] (> short_cutoff).
    rolloff : float, optional
        Plateau level r >= 0 below q_L, as a fraction of C(q_L).
    seed : int, optional
        Seed of ``numpy.random.default_rng``; the same seed gives the same surface.

    Returns
    -------
    Topography
        Periodic surface with zero mean.

    Raises
    ------
    InputError
        Invalid grid, hurst, targets, cutoffs or rolloff, or a band that holds no wavevector.

    References
    ----------
    Jacobs, Junge and Pastewka (2017) doi:10.1088/2051-672X/aa51f8; Persson et al. (2005)
    doi:10.1088/0953-8984/17/1/R01
    """
    shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, plateau = _self_affine_arguments(
        shape, size, hurst, rms_height, rms_slope, short_cutoff, long_cutoff, rolloff
    )
    q_short = math.inf if short_cutoff is None else 2.0 * math.pi / short_cutoff
    q_long = 0.0 if long_cutoff is None else 2.0 * math.pi / long_cutoff
    exponent = 2.0 * (1.0 + hurst) if len(shape) == 2 else 1.0 + 2.0 * hurst

    def psd_shape(q: np.ndarray) -> np.ndarray:
        power_law = np.maximum(q, q_long) ** -exponent
        return np.where(q > q_short, 0.0, np.where(q < q_long, plateau * power_law, power_law))

    heights = _filtered_noise(shape, size, psd_shape, seed, "short_cutoff")
    info = {
        "name": "self-affine",
        "generator": "self_affine",
        "hurst": hurst,
        "seed": seed,
        "short_cutoff": short_cutoff,
        "long_cutoff": long_cutoff,
        "rolloff": rolloff,
    }
    return _scaled(Topography(heights, size, periodic=True, info=info), rms_height, rms_slope)


def _gaussian_random_arguments(shape, size, rms_height, correlation_length):
    """Check and normalise the arguments of :func:`gaussian_random`."""
    shape, size = _grid(shape, size)
    rms_height = positive(rms_height, "rms_height", example="1e-9", unit="m")
    correlation_length = positive(correlation_length, "correlation_length", example="1e-7", unit="m")
    return shape, size, rms_height, correlation_length


def gaussian_random(
    shape: int | tuple[int, ...],
    size: float | tuple[float, ...],
    *,
    rms_height: float,
    correlation_length: float,
    seed: int | None = None,
) -> Topography:
    r"""Periodic Gaussian random surface with a Gaussian autocorrelation function.

    .. math:: R(r) = h_\mathrm{rms}^2 \exp(-r^2/\xi^2) \quad\Longleftrightarrow\quad
              C(q) \propto \exp(-q^2 \xi^2 / 4)

    (the PSD is the Fourier transform of the ACF, in 1D and 2D alike up to the prefactor). Heights
    are rescaled so the discrete Rq equals ``rms_height`` exactly; the ACF follows the target only
    statistically and for ``correlation_length`` well between the pixel size and the period.

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
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    Topography
        Periodic surface with zero mean.

    References
    ----------
    Whitehouse, D. J. and Archard, J. F. (1970). The properties of random surfaces of significance
    in their contact. Proc. R. Soc. A 316, 97-121. doi:10.1098/rspa.1970.0068
    """
    shape, size, rms_height, correlation_length = _gaussian_random_arguments(
        shape, size, rms_height, correlation_length
    )
    heights = _filtered_noise(
        shape, size, lambda q: np.exp(-((q * correlation_length) ** 2) / 4.0), seed, "correlation_length"
    )
    info = {
        "name": "gaussian",
        "generator": "gaussian_random",
        "correlation_length": correlation_length,
        "seed": seed,
    }
    return _scaled(Topography(heights, size, periodic=True, info=info), rms_height, None)


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
    segment |x - centre| <= radius (a flat strip).

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


def _raised_island_arguments(shape, size, island_size, thickness, rms_height, hurst, substrate_height):
    """Check and normalise the arguments of :func:`raised_island`."""
    shape, size = _grid(shape, size)
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
    return shape, size, island_size, thickness, rms_height, hurst, substrate_height


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
) -> Topography:
    r"""Make a raised square island on a flat substrate, rough on top: the SU-8 sample of paper 002.

    Heights are ``substrate_height`` outside the island and ``substrate_height + thickness +
    roughness`` on it. The island is the square (segment, for a profile) of side ``island_size``
    centred on the grid point ``(n // 2) * spacing``: a point belongs to it when its distance to the
    centre along every axis is at most ``island_size / 2``. The roughness is a self-affine field
    (:func:`self_affine` on the whole grid, no cutoffs) restricted to the island, then shifted to
    zero mean and rescaled so its rms *over the island pixels* equals ``rms_height`` exactly.

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

    Returns
    -------
    Topography
        Non-periodic surface.

    References
    ----------
    Seed paper 002, section II (raised SU-8 squares, Fig. 2).
    """
    shape, size, island_size, thickness, rms_height, hurst, substrate_height = _raised_island_arguments(
        shape, size, island_size, thickness, rms_height, hurst, substrate_height
    )
    on_island = np.ones(shape, dtype=bool)
    for axis, (n, s) in enumerate(zip(shape, size, strict=True)):
        x = np.arange(n) * s / n - (n // 2) * s / n
        inside = np.abs(x) <= island_size / 2 * (1 + _PERIOD_TOLERANCE)
        on_island &= np.expand_dims(inside, tuple(a for a in range(len(shape)) if a != axis))
    heights = np.full(shape, substrate_height)
    heights[on_island] += thickness
    if rms_height > 0:
        roughness = self_affine(shape, size, hurst=hurst, rms_height=1.0, seed=seed).heights[on_island]
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
) -> Topography:
    """Rough sphere: :func:`sphere` plus :func:`self_affine` roughness of exact rms ``rms_height``.

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

    Returns
    -------
    Topography
        Non-periodic surface; the apex of the smooth body is at 0 at the grid point ``(n // 2) * spacing``.

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
    )
    info = {
        **dict(body.info),
        "name": f"rough {kind}",
        "generator": "sphere_with_roughness",
        "rms_height": rms_height,
        "hurst": hurst,
        "seed": seed,
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
        )
    elif generator == "gaussian_random":
        _gaussian_random_arguments(shape, size, options["rms_height"], options["correlation_length"])
    elif generator in ("sphere", "sphere_with_roughness"):
        kind = options.get("kind", "sphere" if generator == "sphere" else "paraboloid")
        _sphere_arguments(
            shape, size, options["radius"], options.get("centre"), kind, options.get("periodic", False)
        )
        if generator == "sphere_with_roughness":
            cutoffs = (options.get("short_cutoff"), options.get("long_cutoff"))
            _self_affine_arguments(
                shape, size, options.get("hurst", 0.8), options["rms_height"], None, *cutoffs, None
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
        )
