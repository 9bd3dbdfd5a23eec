r"""Residual stress and surface displacement of a plastic (eigen)strain field below a surface.

The volume-plasticity solver (:mod:`roughcontact.contact.volume_plastic`) needs, for a field of
plastic strain :math:`\varepsilon^p` in a volume below the surface, the stress it leaves in the
body with the surface free of traction (the residual stress) and the surface displacement it
causes (which changes the gap). This is the eigenstrain method of Jacq et al. (2002) and Frérot
et al. (2019). The volume is a stack of ``layers`` cells of thickness ``depth / layers`` under each
surface pixel; the plastic strain is constant in each cell.

How it is computed (per in-plane Fourier mode, a depth discretisation)
    In the plane the fields are Fourier series (``rfft2`` of the grid, zero-padded twice for a free
    boundary, as the surface kernels are). For a wavevector k = (kx, ky) the displacement
    u(z) = (u_x, u_y, u_z) obeys an ordinary differential equation in depth z (positive into the
    body). It is solved by finite elements with linear shape functions on the cell faces (Galerkin,
    exact integration), so the elastic problem of each mode is a block-tridiagonal system of 3 x 3
    blocks:

    .. math::

        \varepsilon = B_0 u + B_1 u', \quad
        \int \delta\varepsilon^H C\,\varepsilon\, dz = \int \delta\varepsilon^H C\,\varepsilon^p\, dz
        + \delta u(0)^H t,

    with :math:`B_0 u = (i k_x u_x, i k_y u_y, 0, i(k_y u_x + k_x u_y), i k_x u_z, i k_y u_z)`,
    :math:`B_1 u' = (0, 0, u_z', 0, u_x', u_y')` (Voigt order xx, yy, zz, xy, xz, yz, engineering
    shears), C the isotropic stiffness and t a surface traction (zero for the residual problem).
    Below the discretised column the body continues as a homogeneous half-space, represented
    exactly by its surface stiffness (a Dirichlet-to-Neumann condition): in the frame (xi along k,
    eta across, z) with k = |k|,

    .. math::

        S = \frac{2 k \mu}{\lambda + 3\mu}
            \begin{pmatrix} \lambda + 2\mu & -i\mu \\ i\mu & \lambda + 2\mu \end{pmatrix}
            \ \text{on}\ (u_\xi, u_z), \qquad S_{\eta\eta} = \mu k,

    the inverse of the Boussinesq-Cerruti compliance :math:`u_z = (1-\nu) t_z/(\mu k)`,
    :math:`u_\xi = (1-\nu) t_\xi/(\mu k) + i(1/2-\nu) t_z/(\mu k)` (derived for this module with
    the decaying solutions :math:`(A + Bz)e^{-kz}`; Johnson 1985 sec. 2.7-2.8 in 2D). So a film of
    one material on a substrate of another is the same computation with the film's moduli in the
    elements and the substrate's in S. The stress is evaluated at the cell centres,
    :math:`\sigma = C(B_0\bar u + B_1 u' - \varepsilon^p)`.

    The mean mode (k = 0) is solved in closed form: the surface is free, so sigma_iz = 0 at every
    depth; the mean in-plane strains of a periodic body are zero, which leaves
    :math:`\varepsilon_{zz} = (\lambda\,\mathrm{tr}\,\varepsilon^p
    + 2\mu\varepsilon^p_{zz})/(\lambda + 2\mu)`,
    :math:`\gamma_{xz} = \gamma^p_{xz}`, :math:`\gamma_{yz} = \gamma^p_{yz}` and the mean surface
    displacement :math:`u_z(0) = -\int_0^\infty \varepsilon_{zz}\, dz` (zero displacement deep
    down: the half-space's far field is the reference).

Why finite elements in depth rather than the closed-form Mindlin kernels with a depth quadrature
    of Frérot et al.: the same column takes a film on a substrate (paper 002's SU-8 on silicon)
    without new kernels, and its error is a plain mesh error in depth that the validation tests
    measure and that falls as the cells shrink (second order in the cell thickness). The surface
    pressure's own stress in a homogeneous half-space is taken from the exact Fourier solution
    (:func:`~roughcontact.elasticity.stress.subsurface_stress`); in a film it comes from this column
    loaded by the traction (:meth:`EigenstrainOperator.traction_stress`).

Boundaries: periodic fields are exact in the plane. A free window is zero-padded to twice its size
per axis, as the surface kernels are: the plastic zone is one of a periodic array of images a
padded window apart, an error that falls as the window grows against the plastic zone.

References
----------
Jacq, C., Nélias, D., Lormand, G. and Girodin, D. (2002). Development of a three-dimensional
semi-analytical elastic-plastic contact code. J. Tribol. 124, 653-667. doi:10.1115/1.1467920
Frérot, L., Bonnet, M., Molinari, J.-F. and Anciaux, G. (2019). A Fourier-accelerated volume
integral method for elastoplastic contact. Comput. Methods Appl. Mech. Eng. 351, 951-976.
doi:10.1016/j.cma.2019.04.006
Johnson, K. L. (1985). Contact Mechanics, secs. 2.7-2.8. doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

from dataclasses import dataclass

import numba as nb
import numpy as np
from scipy import fft

from .._backend import resolve_workers
from ..errors import InputError
from ..materials import Material
from .kernels import BOUNDARIES, wavevectors

COMPONENTS = ("xx", "yy", "zz", "xy", "xz", "yz")
"""Order of the six tensor components of strain and stress arrays (shape (6, layers, nx, ny))."""


def lame(material: Material) -> tuple[float, float]:
    """Return Lamé's first parameter lambda and the shear modulus mu [Pa] of an isotropic material."""
    e, nu = material.youngs_modulus, material.poissons_ratio
    return e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), e / (2.0 * (1.0 + nu))


def isotropic_stress(strain: np.ndarray, material: Material) -> np.ndarray:
    """Return C : strain [Pa] for tensor strain components (6, ...) in :data:`COMPONENTS` order."""
    lam, mu = lame(material)
    trace = strain[0] + strain[1] + strain[2]
    stress = 2.0 * mu * strain
    stress[:3] += lam * trace
    return stress


@dataclass(frozen=True)
class Column:
    """The depth discretisation under every pixel: elements, their moduli and the base half-space.

    Attributes
    ----------
    edges : ndarray
        Node depths [m], 0 at the surface, increasing; the first ``cells`` elements are the cells.
    cells : int
        Number of cells (elements that carry plastic strain and where stress is evaluated).
    lam, mu : ndarray
        Lamé parameters [Pa] of each element.
    base : (float, float)
        Lamé parameters [Pa] of the half-space below the last node.
    """

    edges: np.ndarray
    cells: int
    lam: np.ndarray
    mu: np.ndarray
    base: tuple[float, float]

    @property
    def centres(self) -> np.ndarray:
        """Depths [m] of the cell centres."""
        return 0.5 * (self.edges[: self.cells] + self.edges[1 : self.cells + 1])

    @property
    def thickness(self) -> np.ndarray:
        """Cell thicknesses [m]."""
        return np.diff(self.edges[: self.cells + 1])


def column(
    depth: float,
    layers: int,
    material: Material,
    *,
    film_thickness: float | None = None,
    substrate: Material | None = None,
) -> Column:
    """Return the column of ``layers`` equal cells down to ``depth`` in ``material``.

    With ``substrate``, ``material`` is a film of ``film_thickness`` bonded to a ``substrate``
    half-space: elements growing by 1.5 per element continue the film from ``depth`` to its base.

    Raises
    ------
    InputError
        Depth not positive, fewer than 1 layer, a film thinner than the volume (the plastic cells
        must lie in the film) or than one cell.
    """
    if not (np.isfinite(depth) and depth > 0):
        raise InputError("depth", f"must be positive, got {depth!r}.", "give the volume's depth in m.")
    if int(layers) < 1:
        raise InputError("layers", f"need at least one layer, got {layers!r}.", "e.g. layers=16.")
    layers = int(layers)
    edges = list(np.linspace(0.0, depth, layers + 1))
    film = material
    base = material
    if substrate is not None:
        if film_thickness is None or not film_thickness > 0:
            raise InputError("film_thickness", "a substrate needs the film's thickness.", "give it in m.")
        cell = depth / layers
        if film_thickness < cell:
            raise InputError(
                "film_thickness",
                f"the film ({film_thickness:.3g} m) is thinner than one depth layer ({cell:.3g} m).",
                "use more layers or a smaller depth.",
            )
        if film_thickness < depth * (1 - 1e-12):
            raise InputError(
                "depth",
                f"the plastic volume ({depth:.3g} m) reaches below the film ({film_thickness:.3g} m).",
                f"give depth <= film_thickness ({film_thickness:.3g} m); the substrate stays elastic.",
            )
        step = cell
        while edges[-1] < film_thickness * (1 - 1e-9):
            step *= 1.5
            edges.append(min(edges[-1] + step, film_thickness))
        base = substrate
    lam_f, mu_f = lame(film)
    count = len(edges) - 1
    return Column(
        edges=np.asarray(edges, dtype=float),
        cells=layers,
        lam=np.full(count, lam_f),
        mu=np.full(count, mu_f),
        base=lame(base),
    )


class EigenstrainOperator:
    """The linear map from a plastic strain field to its residual stress and surface displacement.

    Parameters
    ----------
    shape : (int, int)
        Surface grid (nx, ny).
    size : (float, float)
        Physical size (Lx, Ly) [m].
    column : Column
        Depth discretisation and moduli (:func:`column`).
    boundary : {"periodic", "free"}
        Periodic body, or a window of a free surface (zero-padded twice per axis).
    workers : int, optional
        FFT threads (default all cores).

    Notes
    -----
    One application costs ``6 layers`` forward and ``6 layers + 1`` inverse real FFTs of the
    (padded) grid and one block-tridiagonal solve of ``3 (elements + 1)`` unknowns per wavevector.
    Layers whose plastic strain is zero everywhere skip their forward transforms.
    """

    def __init__(self, shape, size, column: Column, *, boundary: str = "periodic", workers=None):
        if boundary not in BOUNDARIES:
            raise InputError("boundary", f"unknown boundary {boundary!r}.", f"use one of {BOUNDARIES}.")
        self.shape = (int(shape[0]), int(shape[1]))
        self.size = (float(size[0]), float(size[1]))
        self.column = column
        self.boundary = boundary
        factor = 1 if boundary == "periodic" else 2
        self.transform_shape = (factor * self.shape[0], factor * self.shape[1])
        qx, qy = wavevectors(self.transform_shape, (factor * self.size[0], factor * self.size[1]))
        spectral = (self.transform_shape[0], self.transform_shape[1] // 2 + 1)
        self._kx = np.ascontiguousarray(np.broadcast_to(qx, spectral)).ravel()
        self._ky = np.ascontiguousarray(np.broadcast_to(qy, spectral)).ravel()
        self._spectral = spectral
        self._workers = resolve_workers(workers)

    @property
    def depths(self) -> np.ndarray:
        """Cell-centre depths [m] where stresses are given."""
        return self.column.centres

    def _forward(self, fields: np.ndarray) -> np.ndarray:
        return fft.rfft2(fields, s=self.transform_shape, workers=self._workers)

    def _inverse(self, spectra: np.ndarray) -> np.ndarray:
        out = fft.irfft2(spectra, s=self.transform_shape, workers=self._workers)
        return out[..., : self.shape[0], : self.shape[1]]

    def _solve(self, load: np.ndarray, traction: np.ndarray, periodic_lateral: bool):
        c = self.column
        nk = self._kx.size
        stress = np.empty((6, c.cells, nk), dtype=np.complex128)
        surface = np.empty((3, nk), dtype=np.complex128)
        _columns(
            self._kx,
            self._ky,
            np.diff(c.edges),
            c.lam,
            c.mu,
            c.base[0],
            c.base[1],
            load,
            traction,
            periodic_lateral,
            stress,
            surface,
        )
        return stress.reshape((6, c.cells) + self._spectral), surface.reshape((3,) + self._spectral)

    def __call__(self, plastic_strain: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Return the residual stress (6, layers, nx, ny) [Pa] and surface displacement u_z (nx, ny) [m].

        Parameters
        ----------
        plastic_strain : ndarray
            Tensor components (6, layers, nx, ny) in :data:`COMPONENTS` order [-].
        """
        c = self.column
        expected = (6, c.cells) + self.shape
        if plastic_strain.shape != expected:
            raise InputError("plastic_strain", f"shape {plastic_strain.shape}, expected {expected}.", None)
        nk = self._kx.size
        load = np.zeros((6, c.cells, nk), dtype=np.complex128)
        active = np.flatnonzero(np.any(plastic_strain != 0.0, axis=(0, 2, 3)))
        if active.size:
            lam, mu = c.lam[active, None, None], c.mu[active, None, None]
            strain = plastic_strain[:, active]
            trace = strain[0] + strain[1] + strain[2]
            eigenstress = 2.0 * mu * strain  # C : eps_p with tensor shears -> engineering stress
            eigenstress[:3] += lam * trace
            load[:, active] = self._forward(eigenstress).reshape(6, active.size, nk)
        stress, surface = self._solve(load, np.zeros((3, nk), dtype=np.complex128), True)
        return self._inverse(stress), self._inverse(surface[2])

    def traction_stress(self, pressure: np.ndarray, periodic_lateral: bool | None = None) -> np.ndarray:
        """Return the stress (6, layers, nx, ny) [Pa] at the cell centres under a surface pressure [Pa].

        The elastic solution of the column (film on substrate included) for the pressure alone;
        the mean lateral stress of the k = 0 mode is that of uniaxial strain for a periodic body and
        zero for a free window (as :func:`~roughcontact.elasticity.stress.subsurface_stress`).
        """
        if pressure.shape != self.shape:
            raise InputError("pressure", f"shape {pressure.shape}, expected {self.shape}.", None)
        c = self.column
        nk = self._kx.size
        traction = np.zeros((3, nk), dtype=np.complex128)
        traction[2] = self._forward(pressure).ravel()
        lateral = self.boundary == "periodic" if periodic_lateral is None else periodic_lateral
        load = np.zeros((6, c.cells, nk), dtype=np.complex128)
        stress, _ = self._solve(load, traction, lateral)
        return self._inverse(stress)


@nb.njit(cache=True, nogil=True)
def _element(kx, ky, lam, mu, h, kaa, kab, kbb):
    """Fill the 3 x 3 blocks of one linear element's stiffness (module docstring) for mode (kx, ky)."""
    # P = B0^H C B0 (real symmetric), Q = B0^H C B1, R = B1^H C B1 = diag(mu, mu, lam + 2 mu):
    # kaa = P h/3 - (Q + Q^H)/2 + R/h, kbb = P h/3 + (Q + Q^H)/2 + R/h, kab = P h/6 + (Q - Q^H)/2 - R/h.
    pxx = kx * kx * (lam + 2 * mu) + ky * ky * mu
    pyy = ky * ky * (lam + 2 * mu) + kx * kx * mu
    pxy = kx * ky * (lam + mu)
    pzz = mu * (kx * kx + ky * ky)
    p = ((pxx, pxy, 0.0), (pxy, pyy, 0.0), (0.0, 0.0, pzz))
    rr = (mu / h, mu / h, (lam + 2 * mu) / h)
    # Q has q[0,2] = -i kx lam, q[1,2] = -i ky lam, q[2,0] = -i kx mu, q[2,1] = -i ky mu.
    sym_x = 0.5j * kx * (mu - lam)  # (Q + Q^H)/2 at [0,2]; its conjugate at [2,0]
    sym_y = 0.5j * ky * (mu - lam)
    skew_x = -0.5j * kx * (lam + mu)  # (Q - Q^H)/2 at [0,2] and at [2,0]
    skew_y = -0.5j * ky * (lam + mu)
    for i in range(3):
        for j in range(3):
            kaa[i, j] = p[i][j] * h / 3
            kbb[i, j] = p[i][j] * h / 3
            kab[i, j] = p[i][j] * h / 6
        kaa[i, i] += rr[i]
        kbb[i, i] += rr[i]
        kab[i, i] -= rr[i]
    kaa[0, 2] -= sym_x
    kaa[1, 2] -= sym_y
    kaa[2, 0] -= np.conj(sym_x)
    kaa[2, 1] -= np.conj(sym_y)
    kbb[0, 2] += sym_x
    kbb[1, 2] += sym_y
    kbb[2, 0] += np.conj(sym_x)
    kbb[2, 1] += np.conj(sym_y)
    kab[0, 2] += skew_x
    kab[1, 2] += skew_y
    kab[2, 0] += skew_x
    kab[2, 1] += skew_y


@nb.njit(cache=True, nogil=True)
def _base_stiffness(kx, ky, lam, mu, s):
    """Fill the 3 x 3 surface stiffness of a half-space for mode (kx, ky) != 0 (module docstring)."""
    k = np.sqrt(kx * kx + ky * ky)
    c, n = kx / k, ky / k
    a = 2 * k * mu * (lam + 2 * mu) / (lam + 3 * mu)
    b = 2 * k * mu * mu / (lam + 3 * mu)
    g = mu * k
    s[0, 0] = c * c * a + n * n * g
    s[1, 1] = n * n * a + c * c * g
    s[0, 1] = s[1, 0] = c * n * (a - g)
    s[2, 2] = a
    s[0, 2] = -1j * b * c
    s[1, 2] = -1j * b * n
    s[2, 0] = 1j * b * c
    s[2, 1] = 1j * b * n


@nb.njit(cache=True, nogil=True)
def _invert3(a, out):
    """Write the inverse of a 3 x 3 complex matrix ``a`` into ``out`` (cofactors)."""
    out[0, 0] = a[1, 1] * a[2, 2] - a[1, 2] * a[2, 1]
    out[0, 1] = a[0, 2] * a[2, 1] - a[0, 1] * a[2, 2]
    out[0, 2] = a[0, 1] * a[1, 2] - a[0, 2] * a[1, 1]
    out[1, 0] = a[1, 2] * a[2, 0] - a[1, 0] * a[2, 2]
    out[1, 1] = a[0, 0] * a[2, 2] - a[0, 2] * a[2, 0]
    out[1, 2] = a[0, 2] * a[1, 0] - a[0, 0] * a[1, 2]
    out[2, 0] = a[1, 0] * a[2, 1] - a[1, 1] * a[2, 0]
    out[2, 1] = a[0, 1] * a[2, 0] - a[0, 0] * a[2, 1]
    out[2, 2] = a[0, 0] * a[1, 1] - a[0, 1] * a[1, 0]
    det = a[0, 0] * out[0, 0] + a[0, 1] * out[1, 0] + a[0, 2] * out[2, 0]
    for i in range(3):
        for j in range(3):
            out[i, j] /= det


@nb.njit(cache=True, nogil=True)
def _columns(kx, ky, h, lam, mu, base_lam, base_mu, load, traction, periodic_lateral, stress, surface):
    """Solve each mode's column (module docstring): eigenstress ``load`` (6, cells, nk), traction (3, nk).

    Writes the cell-centre stress spectra (6, cells, nk) and the surface displacement (3, nk).
    Block Thomas per mode: eliminate downwards keeping inv(Schur complement) of every node, then
    substitute upwards; the 3 x 3 products are written out so that nothing is allocated per mode.
    """
    cells = load.shape[1]
    elements = h.size
    nodes = elements + 1
    kaa = np.empty((3, 3), dtype=np.complex128)
    kab = np.empty((3, 3), dtype=np.complex128)
    kbb = np.empty((3, 3), dtype=np.complex128)
    base = np.zeros((3, 3), dtype=np.complex128)
    schur = np.empty((3, 3), dtype=np.complex128)
    w = np.empty((3, 3), dtype=np.complex128)
    inverse = np.empty((nodes, 3, 3), dtype=np.complex128)
    upper = np.empty((elements, 3, 3), dtype=np.complex128)
    below = np.empty((nodes, 3, 3), dtype=np.complex128)
    rhs = np.zeros((nodes, 3), dtype=np.complex128)
    u = np.empty((nodes, 3), dtype=np.complex128)
    r = np.empty(3, dtype=np.complex128)
    for j in range(kx.size):
        if kx[j] == 0.0 and ky[j] == 0.0:
            _mean_mode(
                h, lam, mu, load[:, :, j], traction[:, j], periodic_lateral, stress[:, :, j], surface[:, j]
            )
            continue
        rhs[:] = 0.0
        rhs[0, :] = traction[:, j]
        below[0] = 0.0
        for e in range(elements):
            _element(kx[j], ky[j], lam[e], mu[e], h[e], kaa, kab, kbb)
            below[e] += kaa
            below[e + 1] = kbb
            upper[e] = kab
            if e < cells:
                _eigen_load(kx[j], ky[j], h[e], load[:, e, j], rhs[e], rhs[e + 1])
        _base_stiffness(kx[j], ky[j], base_lam, base_mu, base)
        below[nodes - 1] += base
        # Downwards: schur_i = K_ii - K_i,i-1 inv_{i-1} K_i-1,i, rhs_i -= K_i,i-1 inv_{i-1} rhs_{i-1}.
        _invert3(below[0], inverse[0])
        for i in range(1, nodes):
            # w = K_i,i-1 inv_{i-1} with K_i,i-1 = upper[i-1]^H
            for a in range(3):
                for b in range(3):
                    acc = 0.0j
                    for c in range(3):
                        acc += np.conj(upper[i - 1, c, a]) * inverse[i - 1, c, b]
                    w[a, b] = acc
            for a in range(3):
                for b in range(3):
                    acc = below[i, a, b]
                    for c in range(3):
                        acc -= w[a, c] * upper[i - 1, c, b]
                    schur[a, b] = acc
                acc = rhs[i, a]
                for c in range(3):
                    acc -= w[a, c] * rhs[i - 1, c]
                rhs[i, a] = acc
            _invert3(schur, inverse[i])
        # Upwards: u_i = inv_i (rhs_i - K_i,i+1 u_i+1).
        for i in range(nodes - 1, -1, -1):
            for a in range(3):
                acc = rhs[i, a]
                if i < nodes - 1:
                    for c in range(3):
                        acc -= upper[i, a, c] * u[i + 1, c]
                r[a] = acc
            for a in range(3):
                u[i, a] = inverse[i, a, 0] * r[0] + inverse[i, a, 1] * r[1] + inverse[i, a, 2] * r[2]
        surface[:, j] = u[0]
        for e in range(cells):
            _cell_stress(kx[j], ky[j], lam[e], mu[e], h[e], u[e], u[e + 1], load[:, e, j], stress[:, e, j])


@nb.njit(cache=True, nogil=True)
def _eigen_load(kx, ky, h, s, top, bottom):
    """Add one cell's eigenstress load (h/2) B0^H s -+ B1^H s to its top and bottom nodes (Voigt s)."""
    b0x = -1j * (kx * s[0] + ky * s[3])
    b0y = -1j * (ky * s[1] + kx * s[3])
    b0z = -1j * (kx * s[4] + ky * s[5])
    top[0] += 0.5 * h * b0x - s[4]
    top[1] += 0.5 * h * b0y - s[5]
    top[2] += 0.5 * h * b0z - s[2]
    bottom[0] += 0.5 * h * b0x + s[4]
    bottom[1] += 0.5 * h * b0y + s[5]
    bottom[2] += 0.5 * h * b0z + s[2]


@nb.njit(cache=True, nogil=True)
def _cell_stress(kx, ky, lam, mu, h, ua, ub, eigenstress, out):
    """Write sigma = C(B0 u_mid + B1 u') - C eps_p at a cell centre (Voigt order)."""
    m0, m1, m2 = 0.5 * (ua[0] + ub[0]), 0.5 * (ua[1] + ub[1]), 0.5 * (ua[2] + ub[2])
    d0, d1, d2 = (ub[0] - ua[0]) / h, (ub[1] - ua[1]) / h, (ub[2] - ua[2]) / h
    exx, eyy, ezz = 1j * kx * m0, 1j * ky * m1, d2
    trace = exx + eyy + ezz
    out[0] = lam * trace + 2 * mu * exx - eigenstress[0]
    out[1] = lam * trace + 2 * mu * eyy - eigenstress[1]
    out[2] = lam * trace + 2 * mu * ezz - eigenstress[2]
    out[3] = mu * 1j * (ky * m0 + kx * m1) - eigenstress[3]
    out[4] = mu * (d0 + 1j * kx * m2) - eigenstress[4]
    out[5] = mu * (d1 + 1j * ky * m2) - eigenstress[5]


@nb.njit(cache=True, nogil=True)
def _mean_mode(h, lam, mu, load, traction, periodic_lateral, stress, surface):
    """Solve the k = 0 mode in closed form (module docstring): sigma_iz = -t_i, no mean in-plane strain."""
    surface[:] = 0.0
    for e in range(load.shape[1]):
        m = lam[e] + 2 * mu[e]
        # Eigenstress C eps_p = s; sigma_zz = m e_zz + lam tr(eps_p-plane) ... solved for e_zz:
        # sigma_zz = m e_zz - s_zz = -t_z  ->  e_zz = (s_zz - t_z) / m.
        ezz = (load[2, e] - traction[2]) / m
        gxz = (load[4, e] - traction[0]) / mu[e]
        gyz = (load[5, e] - traction[1]) / mu[e]
        lateral = lam[e] * ezz
        if not periodic_lateral:
            lateral = lam[e] / m * load[2, e]  # the traction's mean lateral stress taken as zero
        stress[0, e] = lateral - load[0, e]
        stress[1, e] = lateral - load[1, e]
        stress[2, e] = -traction[2]
        stress[3, e] = -load[3, e]
        stress[4, e] = -traction[0]
        stress[5, e] = -traction[1]
        surface[0] -= h[e] * gxz
        surface[1] -= h[e] * gyz
        surface[2] -= h[e] * ezz
