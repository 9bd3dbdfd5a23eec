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
    pressure's own stress is taken from the exact Fourier solution, of the half-space or of the film on
    its substrate (:func:`~roughcontact.elasticity.stress.subsurface_stress`);
    :meth:`EigenstrainOperator.traction_stress` gives the column's own, which converges to it (the
    tests compare the two).

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
from ..units import format_si
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
                f"the film ({format_si(film_thickness, 'm')}) is thinner than one depth layer "
                f"({format_si(cell, 'm')}).",
                "use more layers or a smaller depth.",
            )
        if film_thickness < depth * (1 - 1e-12):
            raise InputError(
                "depth",
                f"the plastic volume ({format_si(depth, 'm')}) reaches below the film "
                f"({format_si(film_thickness, 'm')}).",
                f"give depth <= '{format_si(film_thickness, 'm')}' (the film); the substrate stays elastic.",
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
    The columns are factored once, at construction (block Thomas in the frame of each wavevector,
    real 2 x 2 and scalar blocks: 9 floats per mode and node, 52 MB for a free 128^2 window of
    22 nodes). One application then costs ``6 layers`` forward and ``6 layers + 1`` inverse real
    FFTs of the (padded) grid and a forward and backward sweep per mode (measured here: 0.13 s for
    the sweeps of a free 128^2 window with 32 layers, 5x less than solving the complex 3 x 3
    system afresh). Layers whose plastic strain is zero everywhere skip their forward transforms.
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
        nodes = column.edges.size
        magnitude = np.hypot(self._kx, self._ky)
        self._factors = (
            np.empty((magnitude.size, nodes, 3)),
            np.empty((magnitude.size, nodes, 4)),
            np.empty((magnitude.size, nodes)),
            np.empty((magnitude.size, nodes)),
        )
        _factor(magnitude, np.diff(column.edges), column.lam, column.mu, *column.base, *self._factors)
        self._pressure_response = {}

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
            self._factors,
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
        lateral = self.boundary == "periodic" if periodic_lateral is None else periodic_lateral
        if lateral not in self._pressure_response:
            # the stress of a unit pressure spectrum, once: every later pressure is a product
            c, nk = self.column, self._kx.size
            unit = np.zeros((3, nk), dtype=np.complex128)
            unit[2] = 1.0
            empty = np.zeros((6, c.cells, nk), dtype=np.complex128)
            self._pressure_response[lateral] = self._solve(empty, unit, lateral)[0]
        return self._inverse(self._pressure_response[lateral] * self._forward(pressure))


# --- the column solve, per mode, in the frame (xi along k, eta across, z) ----------------------------
#
# In that frame the Navier system splits into the in-plane (P-SV) pair (u_xi, u_z) and the
# antiplane (SH) u_eta. With u_xi = i v the P-SV blocks are real and symmetric, so each mode is a
# real block-tridiagonal system of 2 x 2 blocks plus a real tridiagonal one, with complex right-hand
# sides. Its factorisation depends only on |k| and the column; it is computed once per operator.
# Element blocks (linear element of thickness h, module docstring, after u_xi = i v):
#   kaa = [[k^2 (lam+2mu) h/3 + mu/h,  k (lam-mu)/2], [k (lam-mu)/2,  k^2 mu h/3 + (lam+2mu)/h]]
#   kbb = [[k^2 (lam+2mu) h/3 + mu/h, -k (lam-mu)/2], [-k (lam-mu)/2, k^2 mu h/3 + (lam+2mu)/h]]
#   kab = [[k^2 (lam+2mu) h/6 - mu/h, -k (lam+mu)/2], [k (lam+mu)/2,  k^2 mu h/6 - (lam+2mu)/h]]
#   SH: kaa = kbb = k^2 mu h/3 + mu/h, kab = k^2 mu h/6 - mu/h.
# Base half-space: [[a, -b], [-b, a]] (P-SV) and mu k (SH), a and b of _base_stiffness.


@nb.njit(cache=True, nogil=True)
def _psv_blocks(k, lam, mu, h):
    """Return the P-SV element blocks (kaa, kbb, kab) as 2 x 2 tuples of floats (comment above)."""
    m = lam + 2 * mu
    d_xi, d_z = k * k * m * h / 3 + mu / h, k * k * mu * h / 3 + m / h
    o_xi, o_z = k * k * m * h / 6 - mu / h, k * k * mu * h / 6 - m / h
    c = 0.5 * k * (lam - mu)
    e = 0.5 * k * (lam + mu)
    return (d_xi, c, c, d_z), (d_xi, -c, -c, d_z), (o_xi, -e, e, o_z)


@nb.njit(cache=True, nogil=True)
def _sh_blocks(k, mu, h):
    """Return the SH element blocks (diagonal, off-diagonal)."""
    return k * k * mu * h / 3 + mu / h, k * k * mu * h / 6 - mu / h


@nb.njit(cache=True, nogil=True)
def _base(k, lam, mu):
    """Return the half-space surface stiffness a, b (P-SV [[a, -b], [-b, a]]) and g (SH) for |k| > 0."""
    return 2 * k * mu * (lam + 2 * mu) / (lam + 3 * mu), 2 * k * mu * mu / (lam + 3 * mu), mu * k


@nb.njit(cache=True, nogil=True, parallel=True)
def _factor(k, h, lam, mu, base_lam, base_mu, psv_inverse, psv_w, sh_inverse, sh_w):
    """Factor every mode's column (block Thomas): inverse Schur complements and K_i,i-1 inv_i-1.

    ``psv_inverse`` (nk, nodes, 3) holds the symmetric 2 x 2 inverses (xx, xz, zz), ``psv_w``
    (nk, nodes, 4) the 2 x 2 multipliers (row-major; node 0 unused), ``sh_*`` (nk, nodes) the SH ones.
    """
    elements = h.size
    nodes = elements + 1
    for j in nb.prange(k.size):
        kj = k[j]
        if kj == 0.0:
            continue
        # Schur complement of node i: diagonal blocks minus w K_i-1,i.
        s00, s01, s11 = 0.0, 0.0, 0.0
        q = 0.0
        for i in range(nodes):
            d00 = d01 = d11 = 0.0
            dq = 0.0
            if i < elements:
                a, _, _ = _psv_blocks(kj, lam[i], mu[i], h[i])
                d00, d01, d11 = a[0], a[1], a[3]
                dq = _sh_blocks(kj, mu[i], h[i])[0]
            if i > 0:
                _, b, o = _psv_blocks(kj, lam[i - 1], mu[i - 1], h[i - 1])
                d00 += b[0]
                d01 += b[1]
                d11 += b[3]
                sd, so = _sh_blocks(kj, mu[i - 1], h[i - 1])
                dq += sd
                # w = K_i,i-1 inv_i-1 with K_i,i-1 = o^T
                i00, i01, i11 = psv_inverse[j, i - 1, 0], psv_inverse[j, i - 1, 1], psv_inverse[j, i - 1, 2]
                w00 = o[0] * i00 + o[2] * i01
                w01 = o[0] * i01 + o[2] * i11
                w10 = o[1] * i00 + o[3] * i01
                w11 = o[1] * i01 + o[3] * i11
                psv_w[j, i, 0], psv_w[j, i, 1], psv_w[j, i, 2], psv_w[j, i, 3] = w00, w01, w10, w11
                d00 -= w00 * o[0] + w01 * o[2]
                d01 -= w00 * o[1] + w01 * o[3]
                d11 -= w10 * o[1] + w11 * o[3]
                wq = so * sh_inverse[j, i - 1]
                sh_w[j, i] = wq
                dq -= wq * so
            if i == nodes - 1:
                a, b, g = _base(kj, base_lam, base_mu)
                d00 += a
                d01 -= b
                d11 += a
                dq += g
            det = d00 * d11 - d01 * d01
            s00, s01, s11 = d11 / det, -d01 / det, d00 / det
            psv_inverse[j, i, 0], psv_inverse[j, i, 1], psv_inverse[j, i, 2] = s00, s01, s11
            q = 1.0 / dq
            sh_inverse[j, i] = q


@nb.njit(cache=True, nogil=True, parallel=True)
def _columns(kx, ky, h, lam, mu, factors, load, traction, periodic_lateral, stress, surface):
    """Solve each mode's column with its factors: eigenstress ``load`` (6, cells, nk), traction (3, nk).

    Writes the cell-centre stress spectra (6, cells, nk) and the surface displacement (3, nk).
    """
    psv_inverse, psv_w, sh_inverse, sh_w = factors
    cells = load.shape[1]
    elements = h.size
    nodes = elements + 1
    for j in nb.prange(kx.size):
        if kx[j] == 0.0 and ky[j] == 0.0:
            _mean_mode(
                h, lam, mu, load[:, :, j], traction[:, j], periodic_lateral, stress[:, :, j], surface[:, j]
            )
            continue
        k = np.sqrt(kx[j] * kx[j] + ky[j] * ky[j])
        c, n = kx[j] / k, ky[j] / k
        rv = np.zeros(nodes, dtype=np.complex128)  # P-SV right-hand side, v row (u_xi = i v)
        rz = np.zeros(nodes, dtype=np.complex128)
        re = np.zeros(nodes, dtype=np.complex128)  # SH
        # surface traction, rotated; the v row of a load b_xi is -i b_xi
        rv[0] = -1j * (c * traction[0, j] + n * traction[1, j])
        re[0] = -n * traction[0, j] + c * traction[1, j]
        rz[0] = traction[2, j]
        for e in range(cells):
            sxx, syy, szz = load[0, e, j], load[1, e, j], load[2, e, j]
            sxy, sxz, syz = load[3, e, j], load[4, e, j], load[5, e, j]
            s_xixi = c * c * sxx + n * n * syy + 2 * c * n * sxy
            s_xieta = c * n * (syy - sxx) + (c * c - n * n) * sxy
            s_xiz = c * sxz + n * syz
            s_etaz = -n * sxz + c * syz
            half = 0.5 * h[e]
            # (h/2) B0^H s -+ B1^H s in the rotated frame: B0^H s = -i k (s_xixi, s_xieta, s_xiz)
            b_xi = -1j * k * s_xixi * half
            b_eta = -1j * k * s_xieta * half
            b_z = -1j * k * s_xiz * half
            rv[e] += -1j * (b_xi - s_xiz)
            rv[e + 1] += -1j * (b_xi + s_xiz)
            re[e] += b_eta - s_etaz
            re[e + 1] += b_eta + s_etaz
            rz[e] += b_z - szz
            rz[e + 1] += b_z + szz
        # forward sweep
        for i in range(1, nodes):
            w00, w01, w10, w11 = psv_w[j, i, 0], psv_w[j, i, 1], psv_w[j, i, 2], psv_w[j, i, 3]
            pv, pz = rv[i - 1], rz[i - 1]
            rv[i] -= w00 * pv + w01 * pz
            rz[i] -= w10 * pv + w11 * pz
            re[i] -= sh_w[j, i] * re[i - 1]
        # back substitution: u_i = inv_i (r_i - K_i,i+1 u_i+1)
        for i in range(nodes - 1, -1, -1):
            tv, tz, te = rv[i], rz[i], re[i]
            if i < elements:
                _, _, o = _psv_blocks(k, lam[i], mu[i], h[i])
                tv -= o[0] * rv[i + 1] + o[1] * rz[i + 1]
                tz -= o[2] * rv[i + 1] + o[3] * rz[i + 1]
                te -= _sh_blocks(k, mu[i], h[i])[1] * re[i + 1]
            i00, i01, i11 = psv_inverse[j, i, 0], psv_inverse[j, i, 1], psv_inverse[j, i, 2]
            rv[i] = i00 * tv + i01 * tz  # now the solution v, u_z, u_eta of node i
            rz[i] = i01 * tv + i11 * tz
            re[i] = sh_inverse[j, i] * te
        surface[0, j] = c * 1j * rv[0] - n * re[0]
        surface[1, j] = n * 1j * rv[0] + c * re[0]
        surface[2, j] = rz[0]
        for e in range(cells):
            m_xi, m_eta, m_z = (
                0.5j * (rv[e] + rv[e + 1]),
                0.5 * (re[e] + re[e + 1]),
                0.5 * (rz[e] + rz[e + 1]),
            )
            d_xi = 1j * (rv[e + 1] - rv[e]) / h[e]
            d_eta, d_z = (re[e + 1] - re[e]) / h[e], (rz[e + 1] - rz[e]) / h[e]
            e_xixi = 1j * k * m_xi
            trace = e_xixi + d_z
            t_xixi = lam[e] * trace + 2 * mu[e] * e_xixi
            t_etaeta = lam[e] * trace
            t_zz = lam[e] * trace + 2 * mu[e] * d_z
            t_xieta = mu[e] * 1j * k * m_eta
            t_xiz = mu[e] * (d_xi + 1j * k * m_z)
            t_etaz = mu[e] * d_eta
            stress[0, e, j] = c * c * t_xixi + n * n * t_etaeta - 2 * c * n * t_xieta - load[0, e, j]
            stress[1, e, j] = n * n * t_xixi + c * c * t_etaeta + 2 * c * n * t_xieta - load[1, e, j]
            stress[2, e, j] = t_zz - load[2, e, j]
            stress[3, e, j] = c * n * (t_xixi - t_etaeta) + (c * c - n * n) * t_xieta - load[3, e, j]
            stress[4, e, j] = c * t_xiz - n * t_etaz - load[4, e, j]
            stress[5, e, j] = n * t_xiz + c * t_etaz - load[5, e, j]


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
