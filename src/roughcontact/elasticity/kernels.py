r"""Fourier-space influence kernels of elastic bodies loaded by surface pressure.

Conventions (the only place they are written down; every solver relies on them)
------------------------------------------------------------------------------
* Grids: array axis 0 is x, axis 1 is y; ``shape = (nx, ny)``, ``size = (Lx, Ly)`` [m],
  pixel spacing ``size / shape``; pressures are pixel values (piecewise constant on the pixel).
* Signs: pressure p > 0 pushes into the body; the surface displacement u > 0 points into the
  body (it opens the gap). Displacements are returned with zero mean for periodic surfaces
  (the q = 0 mode of a periodic half-space is undetermined; the rigid-body approach absorbs it).
* DFT: ``scipy.fft.rfft2`` / ``irfft2`` with the default ("backward") normalisation, over
  axes (0, 1). A kernel ``K`` is the array that multiplies ``rfft2(p)`` so that
  ``u = irfft2(K * rfft2(p), s=shape)``; it carries every factor (pixel area, modulus).
* Wavevectors q = 2 pi / wavelength [rad/m]; |q| = sqrt(qx^2 + qy^2).

Periodic half-space
    The Fourier coefficients obey u(q) = 2 p(q) / (E* |q|) (Johnson 1985, sec. 13.2; Stanley
    and Kato 1997), where E* is the contact modulus of the pair, 1/E* = sum (1 - nu_i^2)/E_i.
    With the backward DFT the coefficients of p and u are ``rfft2(.) / N``, so the kernel is
    ``2 / (E* |q|)`` with no pixel factor, and 0 at q = 0.

Free (non-periodic) half-space
    The exact surface displacement of pixel-wise uniform pressure is the discrete convolution
    of p with Love's (1929) influence coefficients (uniform pressure on a rectangle, Johnson
    1985 eq. 3.25),

    .. math:: D(x, y) = \frac{1}{\pi E^*} \iint_{pixel} \frac{d\xi\, d\eta}{\sqrt{(x-\xi)^2 + (y-\eta)^2}},

    evaluated on a grid of (2 nx, 2 ny) points with wrap-around (negative offsets in the upper
    half) and transformed once. Zero-padding p to (2 nx, 2 ny) makes the circular convolution
    the exact linear one on the original window (Liu, Wang and Liu 2000, "DC-FFT").

Thin layers
    An elastic layer of thickness t bonded to a rigid base, and an elastic film perfectly
    bonded to an elastic half-space, change the periodic kernel by a factor of q t (see
    :func:`layer_on_rigid_base_factor` and :func:`film_on_substrate_factor`).

References
----------
Johnson, K. L. (1985). Contact Mechanics. Cambridge University Press. doi:10.1017/CBO9781139171731
Love, A. E. H. (1929). Phil. Trans. R. Soc. A 228, 377-420. doi:10.1098/rsta.1929.0009
Stanley, H. M. and Kato, T. (1997). J. Tribol. 119, 481-485. doi:10.1115/1.2833523
Liu, S., Wang, Q. and Liu, G. (2000). Wear 243, 101-111. doi:10.1016/S0043-1648(00)00427-0
"""

from __future__ import annotations

import numpy as np
from scipy import fft

from ..errors import InputError

BOUNDARIES = ("periodic", "free")


SUB_GRIDS_KEPT = 8
"""Sub-grid operators an operator keeps (the least recently built is dropped first)."""


def sub_grid_operator(operator, cache: dict, window, build):
    """Return ``operator``'s counterpart on a ``window`` sub-grid with the same pixels.

    For the operators' ``window`` methods: on a free surface the response of a point depends only
    on its offset from each loaded pixel, so a zero-padded operator of the sub-grid gives at its
    points the displacements the whole grid's gives to tractions that vanish outside it. The
    whole grid's window is ``operator`` itself; others are ``build(shape, size)`` [m], kept in
    ``cache`` (at most :data:`SUB_GRIDS_KEPT`: a growing contact asks for a new box now and then,
    and each operator holds FFT buffers of twice its box).

    Raises
    ------
    InputError
        On a periodic surface (every pixel of a period interacts with the others' images) or a
        window that does not fit in the grid.
    """
    shape, size = operator.shape, operator.size
    window = (int(window[0]), int(window[1]))
    if operator.boundary != "free":
        raise InputError(
            "boundary", "a periodic surface has no sub-grid operator.", "use the whole grid's operator."
        )
    if not (0 < window[0] <= shape[0] and 0 < window[1] <= shape[1]):
        raise InputError("window", f"{window} does not fit in the grid {tuple(shape)}.", None)
    if window == tuple(shape):
        return operator
    if window not in cache:
        while len(cache) >= SUB_GRIDS_KEPT:
            cache.pop(next(iter(cache)))
        cache[window] = build(window, (window[0] * size[0] / shape[0], window[1] * size[1] / shape[1]))
    return cache[window]


def wavevectors(shape: tuple[int, int], size: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Return ``(qx, qy)`` [rad/m] of the rfft2 layout, broadcastable to ``(nx, ny // 2 + 1)``."""
    qx = 2.0 * np.pi * fft.fftfreq(shape[0], d=size[0] / shape[0])[:, None]
    qy = 2.0 * np.pi * fft.rfftfreq(shape[1], d=size[1] / shape[1])[None, :]
    return qx, qy


def wavevector_magnitude(shape: tuple[int, int], size: tuple[float, float]) -> np.ndarray:
    """Return |q| [rad/m] on the rfft2 grid, shape ``(nx, ny // 2 + 1)``."""
    qx, qy = wavevectors(shape, size)
    return np.sqrt(qx**2 + qy**2)


def periodic_halfspace_kernel(
    shape: tuple[int, int], size: tuple[float, float], contact_modulus: float
) -> np.ndarray:
    r"""Kernel 2 / (E* |q|) of a periodic elastic half-space (0 at q = 0) [m/Pa].

    Parameters
    ----------
    shape : (int, int)
        Grid points (nx, ny).
    size : (float, float)
        Period (Lx, Ly) [m].
    contact_modulus : float
        E* [Pa], 1/E* = sum (1 - nu_i^2) / E_i.

    Returns
    -------
    ndarray
        Shape ``(nx, ny // 2 + 1)``; ``u = irfft2(K * rfft2(p), s=shape)``.
    """
    q = wavevector_magnitude(shape, size)
    kernel = np.zeros_like(q)
    nonzero = q > 0
    kernel[nonzero] = 2.0 / (contact_modulus * q[nonzero])
    return kernel


def _corner_integral(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    r"""Signed :math:`\int_0^x\int_0^y (\xi^2+\eta^2)^{-1/2} d\eta\, d\xi` (odd in x and in y)."""
    ax, ay = np.abs(x), np.abs(y)
    with np.errstate(divide="ignore", invalid="ignore"):
        value = ax * np.arcsinh(ay / ax) + ay * np.arcsinh(ax / ay)
    value = np.where((ax == 0) | (ay == 0), np.where(ax == 0, ay * 0, 0.0), value)
    # On an axis one of the two terms is 0 * asinh(inf); the other is exactly 0 there too.
    return np.sign(x) * np.sign(y) * np.nan_to_num(value)


def love_influence_coefficients(
    shape: tuple[int, int], spacing: tuple[float, float], contact_modulus: float
) -> np.ndarray:
    r"""Real-space influence coefficients D[i, j] [m/Pa] on a wrap-around grid of ``shape``.

    ``D[i, j]`` is the displacement at offset (i dx, j dy) (indices above shape/2 are negative
    offsets) caused by unit pressure on the pixel centred at the origin (Love 1929):

    .. math:: D = \frac{1}{\pi E^*}\,[I(x+a, y+b) - I(x+a, y-b) - I(x-a, y+b) + I(x-a, y-b)]

    with a = dx/2, b = dy/2 and I the corner integral of 1/r. The four terms are I on one grid of
    half-integer offsets, differenced, and D is even in x and in y: I is evaluated on the
    quadrant of non-negative offsets only (a sixteenth of the four full-grid evaluations).
    """
    dx, dy = spacing
    half = (shape[0] // 2 + 1, shape[1] // 2 + 1)  # |offset| 0 .. shape // 2 in pixels
    x = (np.arange(half[0] + 1) - 0.5)[:, None] * dx  # x +- dx/2 for the offsets 0 .. half - 1
    y = (np.arange(half[1] + 1) - 0.5)[None, :] * dy
    corner = _corner_integral(x, y)
    quadrant = corner[1:, 1:] - corner[1:, :-1] - corner[:-1, 1:] + corner[:-1, :-1]
    rows = np.minimum(np.arange(shape[0]), shape[0] - np.arange(shape[0]))  # |offset| of each index
    columns = np.minimum(np.arange(shape[1]), shape[1] - np.arange(shape[1]))
    return quadrant[rows[:, None], columns[None, :]] / (np.pi * contact_modulus)


def free_halfspace_kernel(
    shape: tuple[int, int], size: tuple[float, float], contact_modulus: float
) -> np.ndarray:
    """Kernel of a free elastic half-space on the zero-padded grid ``(2 nx, 2 ny)`` [m/Pa].

    Apply it to ``rfft2(p, s=(2 nx, 2 ny))`` and keep ``[:nx, :ny]`` of the inverse transform.

    Parameters
    ----------
    shape : (int, int)
        Grid points of the (unpadded) window.
    size : (float, float)
        Physical size of the window [m].
    contact_modulus : float
        E* [Pa].

    Returns
    -------
    ndarray
        Shape ``(2 nx, ny + 1)`` (rfft2 layout of the padded grid).
    """
    spacing = (size[0] / shape[0], size[1] / shape[1])
    padded = (2 * shape[0], 2 * shape[1])
    return fft.rfft2(love_influence_coefficients(padded, spacing, contact_modulus)).real


LAYER_BASES = ("bonded", "frictionless")


def layer_on_rigid_base_factor(qt: np.ndarray, poissons_ratio: float, *, base: str = "bonded") -> np.ndarray:
    r"""Surface compliance of an elastic layer on a rigid base relative to the half-space, F(q t).

    A periodic pressure p(q) on a layer of thickness t (Young's modulus E, Poisson's ratio nu)
    resting on a rigid base gives ``u(q) = 2 (1 - nu^2) / (E q) * F(q t) * p(q)`` (plane-strain
    Airy function solution; by isotropy the same for every direction of q). With
    kappa = 3 - 4 nu and s = q t, for a base that is

    ``"bonded"`` (no slip at the base)
        .. math:: F = \frac{\kappa \sinh 2s - 2s}{\kappa \cosh 2s + 2 s^2 + (1 + \kappa^2)/2}

    ``"frictionless"`` (free slip at the base)
        .. math:: F = \frac{\cosh 2s - 1}{\sinh 2s + 2s}

    F -> 1 for s -> infinity (half-space). For s -> 0, F -> (1 - 2 nu) s / (2 (1 - nu)^2)
    (bonded), whose u is the uniaxial-strain (Winkler) limit
    u = p t (1 + nu)(1 - 2 nu) / ((1 - nu) E), and F -> s/2 (frictionless), u = p t (1 - nu^2)/E.
    The expressions were derived with the Airy stress function (cos(qx) times
    (A + B z) e^{qz} + (C + D z) e^{-qz}) and agree with the classical results for layers
    (Johnson 1985 sec. 5.9 cites them; Carbone and Mangialardi 2008 use the bonded one).

    Parameters
    ----------
    qt : ndarray
        |q| times the layer thickness [-], >= 0.
    poissons_ratio : float
        Poisson's ratio of the layer.
    base : {"bonded", "frictionless"}
        Interface with the rigid base.

    Returns
    -------
    ndarray
        F(q t) [-], same shape as ``qt``.

    References
    ----------
    Johnson, K. L. (1985). Contact Mechanics, sec. 5.9. doi:10.1017/CBO9781139171731
    Carbone, G. and Mangialardi, L. (2008). J. Mech. Phys. Solids 56, 684-706.
    doi:10.1016/j.jmps.2007.05.009
    """
    s = np.asarray(qt, dtype=float)
    # Large s: divide numerator and denominator by cosh(2s) to avoid overflow (F -> 1).
    with np.errstate(over="ignore"):
        sech = 1.0 / np.cosh(np.minimum(2.0 * s, 700.0))
    tanh = np.tanh(2.0 * s)
    if base == "bonded":
        kappa = 3.0 - 4.0 * poissons_ratio
        return (kappa * tanh - 2.0 * s * sech) / (kappa + (2.0 * s**2 + (1.0 + kappa**2) / 2.0) * sech)
    if base == "frictionless":
        with np.errstate(invalid="ignore"):
            factor = (1.0 - sech) / (tanh + 2.0 * s * sech)
        return np.where(s > 0, factor, 0.0)
    raise InputError("base", f"unknown layer base {base!r}.", f"use one of {LAYER_BASES}.")


def layer_winkler_compliance(
    thickness: float, youngs_modulus: float, poissons_ratio: float, *, base: str = "bonded"
) -> float:
    """Mean displacement per mean pressure of a layer on a rigid base (the q -> 0 limit) [m/Pa].

    ``"bonded"``: uniaxial strain, t (1 + nu)(1 - 2 nu) / ((1 - nu) E); ``"frictionless"``:
    t (1 - nu^2) / E (the limits of :func:`layer_on_rigid_base_factor`).
    """
    nu = poissons_ratio
    if base == "bonded":
        return thickness * (1.0 + nu) * (1.0 - 2.0 * nu) / ((1.0 - nu) * youngs_modulus)
    if base == "frictionless":
        return thickness * (1.0 - nu**2) / youngs_modulus
    raise InputError("base", f"unknown layer base {base!r}.", f"use one of {LAYER_BASES}.")


def _airy_basis(z: np.ndarray, youngs_modulus: float, poissons_ratio: float) -> np.ndarray:
    r"""Fields (v, w, sigma_zz, sigma_xz) of the four Airy modes at depth z (q = 1), shape (4, 4, ...).

    Modes f(z) = e^{z}, z e^{z}, e^{-z}, z e^{-z} of phi = cos(x) f(z); u_x = v sin x,
    u_z = w cos x (z into the body), sigma_zz = s_zz cos x, sigma_xz = s_xz sin x.
    """
    c = (1.0 + poissons_ratio) / youngs_modulus
    nu = poissons_ratio
    ep, em = np.exp(z), np.exp(-z)
    return np.array(
        [
            [c * ep, c * (z + 2 - 2 * nu) * ep, c * em, c * (z + 2 * nu - 2) * em],
            [-c * ep, -c * (z + 2 * nu - 1) * ep, c * em, c * (z - 2 * nu + 1) * em],
            [-ep, -z * ep, -em, -z * em],
            [ep, (z + 1) * ep, -em, -(z - 1) * em],
        ]
    )


FILM_MODES_LIMIT = 700.0
"""Largest q t solved with the film's Airy modes; above it a mode sees a half-space (e^{-700})."""


def _film_modes(
    s, film_youngs_modulus, film_poissons_ratio, substrate_youngs_modulus, substrate_poissons_ratio
):
    """Solve the film-on-substrate Airy system for sigma_zz(0) = -1 at each q t = ``s`` (q = 1 units).

    Returns the coefficients (n, 6) (four film modes scaled by ``film_scale``, two decaying
    substrate modes scaled by ``substrate_scale``), ``film_scale`` (4, n) and ``substrate_scale`` (n).
    """
    film_surface = _airy_basis(np.zeros_like(s), film_youngs_modulus, film_poissons_ratio)
    film_interface = _airy_basis(s, film_youngs_modulus, film_poissons_ratio)
    substrate = _airy_basis(s, substrate_youngs_modulus, substrate_poissons_ratio)
    grow = np.exp(-s)  # scale of the growing film modes
    film_scale = np.array([grow, grow, np.ones_like(s), np.ones_like(s)])
    substrate_scale = np.exp(s)  # decaying substrate modes measured from the interface
    matrix = np.zeros((s.size, 6, 6))
    rhs = np.zeros((s.size, 6))
    matrix[:, 0, :4] = (film_surface[2] * film_scale).T  # sigma_zz(0) = -p
    matrix[:, 1, :4] = (film_surface[3] * film_scale).T  # sigma_xz(0) = 0
    rhs[:, 0] = -1.0
    for row, field in enumerate(range(4), start=2):  # continuity of v, w, s_zz, s_xz at z = t
        matrix[:, row, :4] = (film_interface[field] * film_scale).T
        matrix[:, row, 4:] = -(substrate[field][2:] * substrate_scale).T
    return np.linalg.solve(matrix, rhs[..., None])[..., 0], film_scale, substrate_scale


def film_stress_modes(
    q: np.ndarray,
    depth: float,
    thickness: float,
    film_youngs_modulus: float,
    film_poissons_ratio: float,
    substrate_youngs_modulus: float,
    substrate_poissons_ratio: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    r"""Stress at ``depth`` of a film bonded to a substrate under a surface pressure mode, per sigma_zz(0).

    For the pressure p cos(q xi) on a film of ``thickness`` t perfectly bonded to a substrate
    half-space, the stresses at depth z (in the film for z <= t, in the substrate below) are those of
    the Airy modes of :func:`film_on_substrate_factor` with its coefficients (for q t above
    :data:`FILM_MODES_LIMIT` the half-space's, which the film is at those wavelengths):
    sigma_xixi = f''(z), sigma_zz = -f(z), sigma_xiz = f'(z) (times cos, cos and sin of q xi; q = 1
    units) and sigma_etaeta = nu (sigma_xixi + sigma_zz) (plane strain). Returned as complex spectra
    relative to the spectrum of sigma_zz(0) = -p, as
    :func:`~roughcontact.elasticity.stress.subsurface_stress` uses them (the half-space limit is
    (1 - qz) e^{-qz}, 2 nu e^{-qz}, (1 + qz) e^{-qz} and -i qz e^{-qz}).

    Parameters
    ----------
    q : ndarray
        Wavevector magnitudes |q| [rad/m], > 0.
    depth, thickness : float
        Depth z >= 0 and film thickness t > 0 [m].
    film_youngs_modulus, film_poissons_ratio, substrate_youngs_modulus, substrate_poissons_ratio : float
        Elastic constants [Pa, -].

    Returns
    -------
    (xixi, etaeta, zz, xiz) : ndarrays shaped like ``q``

    References
    ----------
    Johnson, K. L. (1985), sec. 2.7 (Airy functions of a periodic surface load). Perriot, A. and
    Barthel, E. (2004). J. Mater. Res. 19, 600-608. doi:10.1557/jmr.2004.19.2.600
    """
    q = np.asarray(q, dtype=float)
    s, inverse = np.unique(q * thickness, return_inverse=True)
    deep = s > FILM_MODES_LIMIT  # the film is a half-space there (module notes)
    s = np.minimum(s, FILM_MODES_LIMIT)
    coefficients, film_scale, substrate_scale = _film_modes(
        s, film_youngs_modulus, film_poissons_ratio, substrate_youngs_modulus, substrate_poissons_ratio
    )
    qz = s * depth / thickness
    in_film = depth <= thickness
    if in_film:
        ep, em = np.exp(qz), np.exp(-qz)
        modes = [
            (ep, ep, ep),  # f, f', f'' of e^z
            (qz * ep, (qz + 1) * ep, (qz + 2) * ep),
            (em, -em, em),
            (qz * em, (1 - qz) * em, (qz - 2) * em),
        ]
        weights = [coefficients[:, i] * film_scale[i] for i in range(4)]
        nu = film_poissons_ratio
    else:
        em = np.exp(-qz)
        modes = [(em, -em, em), (qz * em, (1 - qz) * em, (qz - 2) * em)]
        weights = [coefficients[:, 4 + i] * substrate_scale for i in range(2)]
        nu = substrate_poissons_ratio
    f = sum(w * m[0] for w, m in zip(weights, modes, strict=True))
    df = sum(w * m[1] for w, m in zip(weights, modes, strict=True))
    d2f = sum(w * m[2] for w, m in zip(weights, modes, strict=True))
    # relative to sigma_zz(0) = -1: sigma = (value) x (-1) x ... ; sigma_zz(z) = -f, so zz / zz(0) = f
    xixi, zz, xiz = -d2f, f, 1j * df
    if deep.any():
        if not in_film:
            raise InputError(
                "depth", "stress below a film at q t > 700 is not resolved.", "use fewer pixels."
            )
        z = np.unique(q * thickness)[deep] * depth / thickness
        decay = np.exp(-z)
        xixi[deep], zz[deep], xiz[deep] = (1 - z) * decay, (1 + z) * decay, -1j * z * decay
    etaeta = nu * (xixi + zz)
    return tuple(part[inverse].reshape(q.shape) for part in (xixi, etaeta, zz, xiz))


def film_on_substrate_factor(
    qt: np.ndarray,
    film_youngs_modulus: float,
    film_poissons_ratio: float,
    substrate_youngs_modulus: float,
    substrate_poissons_ratio: float,
) -> np.ndarray:
    r"""Compliance of a film bonded to an elastic half-space relative to the film's half-space, F(q t).

    ``u(q) = 2 (1 - nu_f^2) / (E_f q) * F(q t) * p(q)`` for a film of thickness t perfectly
    bonded (continuous displacements and tractions) to a substrate half-space. F -> 1 as
    q t -> infinity and F -> E_f (1 - nu_s^2) / (E_s (1 - nu_f^2)) as q t -> 0 (the substrate
    alone). Each distinct q t is solved as the 6 x 6 linear system of the Airy modes (four in
    the film, the two decaying ones in the substrate; growing modes scaled by e^{-s} so the
    system stays well conditioned for thick films). The closed form of this system is the
    classical one of the layered half-space (e.g. Perriot and Barthel 2004); the linear solve
    avoids transcribing it.

    Parameters
    ----------
    qt : ndarray
        |q| times the film thickness [-], >= 0.
    film_youngs_modulus, film_poissons_ratio, substrate_youngs_modulus, substrate_poissons_ratio : float
        Elastic constants [Pa, -].

    Returns
    -------
    ndarray
        F(q t) [-], same shape as ``qt``.

    References
    ----------
    Perriot, A. and Barthel, E. (2004). J. Mater. Res. 19, 600-608. doi:10.1557/jmr.2004.19.2.600
    """
    qt = np.asarray(qt, dtype=float)
    s, inverse = np.unique(np.minimum(qt, 40.0), return_inverse=True)  # F(40) = 1 to 1e-16
    coefficients, film_scale, _ = _film_modes(
        s, film_youngs_modulus, film_poissons_ratio, substrate_youngs_modulus, substrate_poissons_ratio
    )
    film_surface = _airy_basis(np.zeros_like(s), film_youngs_modulus, film_poissons_ratio)
    surface_w = np.einsum("ks,sk->s", film_surface[1] * film_scale, coefficients[:, :4])
    reference = 2.0 * (1.0 - film_poissons_ratio**2) / film_youngs_modulus
    return (surface_w / reference)[inverse].reshape(qt.shape)
