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

The generators live in this package's modules, by what they make: :mod:`.random_fields`
(:func:`self_affine`, :func:`gaussian_random`, drawn by :mod:`.noise`), :mod:`.matched`
(:func:`matched_moments`, :func:`matched_psd`), :mod:`.shapes` (:func:`sphere`, :func:`sinusoid`,
:func:`bisinusoid`, :func:`flat_punch`) and :mod:`.composite` (:func:`raised_island`,
:func:`sphere_with_roughness`); :mod:`.grid` checks the arguments they share. Import them from here.

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

from collections.abc import Mapping
from typing import Any

from .composite import raised_island, raised_island_arguments, sphere_with_roughness
from .grid import grid_of as grid_of  # the checked grid of a generator's arguments (study validation)
from .matched import MIN_PIXELS_PER_SHORT_WAVELENGTH, matched_moments, matched_moments_arguments, matched_psd
from .noise import MODES
from .random_fields import gaussian_random, gaussian_random_arguments, self_affine, self_affine_arguments
from .shapes import (
    bisinusoid,
    bisinusoid_arguments,
    flat_punch,
    flat_punch_arguments,
    sinusoid,
    sinusoid_arguments,
    sphere,
    sphere_arguments,
)

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


# --- random fields -------------------------------------------------------------------------------


# --- deterministic shapes ------------------------------------------------------------------------


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
        self_affine_arguments(
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
        gaussian_random_arguments(
            shape, size, options["rms_height"], options["correlation_length"], options.get("modes", "grid")
        )
    elif generator == "matched_moments":
        matched_moments_arguments(
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
        sphere_arguments(
            shape, size, options["radius"], options.get("centre"), kind, options.get("periodic", False)
        )
        if generator == "sphere_with_roughness":
            cutoffs = (options.get("short_cutoff"), options.get("long_cutoff"))
            self_affine_arguments(
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
        sinusoid_arguments(shape, size, options["amplitude"], options["wavelength"], options.get("axis", 0))
    elif generator == "bisinusoid":
        bisinusoid_arguments(shape, size, options["amplitude"], options["wavelength"])
    elif generator == "flat_punch":
        flat_punch_arguments(shape, size, options["radius"], options["depth"], options.get("centre"))
    elif generator == "raised_island":
        raised_island_arguments(
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
