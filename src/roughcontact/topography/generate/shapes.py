"""Deterministic shapes: sphere (or paraboloid), sinusoid, bisinusoid and flat punch."""

from __future__ import annotations

import numpy as np

from ...checks import positive
from ...errors import InputError
from ..surface import Topography
from .grid import PERIOD_TOLERANCE, grid_of, per_axis


def _centre(shape: tuple[int, ...], size: tuple[float, ...], centre) -> tuple[float, ...]:
    """Return ``centre`` [m] checked, one finite coordinate per axis (default: the grid point mid-grid).

    The default centre is ``(n // 2) * spacing`` per axis, a grid point, so the apex is sampled.
    """
    if centre is None:
        return tuple((n // 2) * (s / n) for n, s in zip(shape, size, strict=True))
    checked = np.atleast_1d(np.asarray(centre, dtype=float))
    if checked.shape != (len(shape),) or not np.all(np.isfinite(checked)):
        raise InputError(
            "centre",
            f"{tuple(checked)} is not {len(shape)} finite coordinates.",
            f"give the apex position in metres, {len(shape)} values.",
        )
    return tuple(float(c) for c in checked)


def _radial_distance(
    shape: tuple[int, ...], size: tuple[float, ...], centre: tuple[float, ...], periodic: bool
) -> np.ndarray:
    """Return the distance [m] of each grid point from ``centre`` (checked by :func:`_centre`).

    Periodic grids use the minimum-image distance.
    """
    spacing = [s / n for n, s in zip(shape, size, strict=True)]
    squared = 0.0
    for axis, (n, h, c, s) in enumerate(zip(shape, spacing, centre, size, strict=True)):
        d = np.arange(n) * h - c
        if periodic:
            d = d - s * np.round(d / s)
        squared = squared + np.expand_dims(d**2, tuple(a for a in range(len(shape)) if a != axis))
    return np.sqrt(np.broadcast_to(squared, shape))


def _farthest(shape, size, centre: tuple[float, ...], periodic: bool) -> float:
    """Largest distance [m] of a grid point from ``centre`` (checked; minimum image when periodic)."""
    reach = []
    for n, c, s in zip(shape, centre, size, strict=True):
        d = np.array([0.0, (n - 1) * (s / n)]) - c
        reach.append(s / 2 if periodic else float(np.max(np.abs(d))))
    return float(np.sqrt(sum(r**2 for r in reach)))


def sphere_arguments(shape, size, radius, centre, kind, periodic):
    """Check and normalise the arguments of :func:`sphere`: (shape, size, radius, centre)."""
    shape, size = grid_of(shape, size)
    radius = positive(radius, "radius", example="5e-3", unit="m")
    if kind not in ("sphere", "paraboloid"):
        raise InputError("kind", f"unknown kind {kind!r}.", "choose 'sphere' or 'paraboloid'.")
    centre = _centre(shape, size, centre)
    farthest = _farthest(shape, size, centre, periodic)
    if kind == "sphere" and farthest > radius:
        raise InputError(
            "radius",
            f"the grid reaches {farthest:.6g} m from the apex, beyond the sphere radius {radius:.6g} m.",
            "use a smaller size, a larger radius, or kind='paraboloid'.",
        )
    return shape, size, radius, centre


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
    shape, size, radius, centre = sphere_arguments(shape, size, radius, centre, kind, periodic)
    distance = _radial_distance(shape, size, centre, periodic)
    if kind == "paraboloid":
        heights = -(distance**2) / (2.0 * radius)
    else:
        heights = np.sqrt(np.maximum(radius**2 - distance**2, 0.0)) - radius
    info = {"name": kind, "generator": "sphere", "radius": radius}
    return Topography(heights, size, periodic=periodic, info=info)


def _divides(size: tuple[float, ...], wavelength: tuple[float, ...]) -> bool:
    cycles = [s / w for s, w in zip(size, wavelength, strict=True)]
    return all(abs(c - round(c)) <= PERIOD_TOLERANCE * max(c, 1.0) for c in cycles)


def sinusoid_arguments(shape, size, amplitude, wavelength, axis):
    """Check and normalise the arguments of :func:`sinusoid`."""
    shape, size = grid_of(shape, size)
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
    shape, size, amplitude, wavelength = sinusoid_arguments(shape, size, amplitude, wavelength, axis)
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


def bisinusoid_arguments(shape, size, amplitude, wavelength):
    """Check and normalise the arguments of :func:`bisinusoid`."""
    shape, size = grid_of(shape, size)
    if len(shape) != 2:
        raise InputError("shape", "a bisinusoid needs a map (nx, ny).", "use sinusoid for a profile.")
    amplitude = positive(amplitude, "amplitude", example="1e-7", unit="m")
    return shape, size, amplitude, per_axis(wavelength, 2, "wavelength", "1e-5")


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
    shape, size, amplitude, wavelength = bisinusoid_arguments(shape, size, amplitude, wavelength)
    x, y = (np.arange(n) * s / n for n, s in zip(shape, size, strict=True))
    heights = amplitude * np.outer(
        np.cos(2.0 * np.pi * x / wavelength[0]), np.cos(2.0 * np.pi * y / wavelength[1])
    )
    info = {"name": "bisinusoid", "generator": "bisinusoid", "amplitude": amplitude, "wavelength": wavelength}
    return Topography(heights, size, periodic=_divides(size, wavelength), info=info)


def flat_punch_arguments(shape, size, radius, depth, centre=None):
    """Check and normalise the arguments of :func:`flat_punch`: (shape, size, radius, depth, centre)."""
    shape, size = grid_of(shape, size)
    radius = positive(radius, "radius", example="10e-6", unit="m")
    depth = positive(depth, "depth", example="1e-6", unit="m")
    return shape, size, radius, depth, _centre(shape, size, centre)


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
    shape, size, radius, depth, centre = flat_punch_arguments(shape, size, radius, depth, centre)
    heights = np.where(_radial_distance(shape, size, centre, False) <= radius, 0.0, -depth)
    info = {"name": "flat punch", "generator": "flat_punch", "radius": radius, "depth": depth}
    return Topography(heights, size, periodic=False, info=info)
