r"""Subsurface stress of an elastic half-space under a surface pressure, by FFT, and von Mises.

A single Fourier mode of pressure, p cos(k xi) with xi along the wavevector, is uniform along
the perpendicular direction eta, so the body is in plane strain in the (xi, z) plane. Its Airy
stress function phi = (p/k^2)(1 + k z) e^{-kz} cos(k xi) (z >= 0 into the body; the one that
decays with depth and leaves the surface free of shear) gives, with tension positive,

.. math::

    \sigma_{zz} = -p (1 + kz) e^{-kz}, \quad
    \sigma_{\xi\xi} = -p (1 - kz) e^{-kz}, \quad
    \sigma_{\eta\eta} = \nu(\sigma_{\xi\xi} + \sigma_{zz}) = -2\nu p e^{-kz}

(times cos k xi) and sigma_xi_z = -p k z e^{-kz} sin(k xi) (Johnson 1985 sec. 2.7 for the
plane-strain form). The components in x, y follow by rotating with n = k/|k|. The mean
pressure (k = 0) gives sigma_zz = -p and, for uniaxial strain, sigma_xx = sigma_yy =
-nu/(1 - nu) p.

Boundaries: a periodic pressure field is exact. For a free (finite) pressure patch the field is
zero-padded by ``padding`` per axis, i.e. the patch is one of a periodic array of images one
padded window apart; the error falls as the padding grows (``padding=2`` puts the nearest
image a window away; Hertz axis stresses agree to about 2 % of p0 with ``padding=4``).

Shear tractions q = (q_x, q_y) on the surface (paper 001's partial slip, friction) are split per
mode into a component along the wavevector, a plane-strain problem with the Airy function
(q/k) z e^{-kz}, giving sigma_zz = -q k z e^{-kz}, sigma_xixi = q (kz - 2) e^{-kz},
sigma_xiz = q (1 - kz) e^{-kz} and sigma_etaeta = nu (sigma_xixi + sigma_zz) (for a surface
shear stress q sin(k xi); Johnson 1985 sec. 2.8 in 2D), and a component across it, an antiplane
shear u_eta ~ e^{-kz} with sigma_etaz = q e^{-kz} and sigma_xieta from it. A uniform shear
traction gives a uniform shear stress through the depth.

References
----------
Johnson, K. L. (1985). Contact Mechanics, secs. 2.7 and 3.4. doi:10.1017/CBO9781139171731
Stanley, H. M. and Kato, T. (1997). J. Tribol. 119, 481-485. doi:10.1115/1.2833523
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import fft

from ..errors import InputError
from .kernels import film_stress_modes, wavevectors

COMPONENTS = ("xx", "yy", "zz", "xy", "xz", "yz")


@dataclass(frozen=True)
class StressField:
    """Stress tensor components [Pa] on horizontal planes (tension positive).

    Attributes
    ----------
    depths : ndarray
        Depths z [m] below the surface, shape (nz,).
    components : ndarray
        Shape (6, nz, nx, ny) in the order xx, yy, zz, xy, xz, yz.
    size : (float, float)
        Physical size of the window [m].
    """

    depths: np.ndarray
    components: np.ndarray
    size: tuple[float, float]

    def component(self, name: str) -> np.ndarray:
        """Return one component ("xx", "zz", "xz", ...) as an array (nz, nx, ny) [Pa]."""
        return self.components[COMPONENTS.index(name)]

    def von_mises(self) -> np.ndarray:
        """Return the von Mises equivalent stress [Pa], shape (nz, nx, ny)."""
        xx, yy, zz, xy, xz, yz = self.components
        return np.sqrt(
            0.5 * ((xx - yy) ** 2 + (yy - zz) ** 2 + (zz - xx) ** 2) + 3.0 * (xy**2 + xz**2 + yz**2)
        )

    def max_von_mises(self) -> tuple[float, tuple[float, float, float]]:
        """Return the largest von Mises stress [Pa] and its location (x, y, z) [m]."""
        vm = self.von_mises()
        index = np.unravel_index(np.argmax(vm), vm.shape)
        nz, nx, ny = vm.shape
        x = index[1] * self.size[0] / nx
        y = index[2] * self.size[1] / ny
        return float(vm[index]), (x, y, float(self.depths[index[0]]))


def _local_modes(q, z, normal, along, across, nu):
    """Local (xi, eta, z) stress spectra of one plane at depth z, tension positive.

    ``normal`` is the spectrum of sigma_zz(0) = -p, ``along`` / ``across`` those of the surface
    shear stresses sigma_xi_z(0) and sigma_eta_z(0) (= -q_xi, -q_eta).
    """
    qz = q * z
    decay = np.exp(-qz)
    # Normal traction (plane strain in xi-z).
    xixi = (1.0 - qz) * normal
    etaeta = 2.0 * nu * normal
    zz = (1.0 + qz) * normal
    xiz = -1j * qz * normal
    # Shear along xi (plane strain in xi-z).
    xixi = xixi + 1j * (qz - 2.0) * along
    etaeta = etaeta - 2j * nu * along
    zz = zz - 1j * qz * along
    xiz = xiz + (1.0 - qz) * along
    # Shear across (antiplane).
    etaz = across
    xieta = -1j * across
    return tuple(decay * c for c in (xixi, etaeta, zz, xieta, xiz, etaz))


def _film_modes(q, z, normal, layer):
    """Local (xi, eta, z) stress spectra at depth z of a film on its substrate under ``normal`` = -p."""
    film, substrate = layer.material, layer.base
    transfer = np.zeros((4,) + q.shape, dtype=complex)
    positive = q > 0
    modes = film_stress_modes(
        q[positive],
        z,
        layer.thickness,
        film.youngs_modulus,
        film.poissons_ratio,
        substrate.youngs_modulus,
        substrate.poissons_ratio,
    )
    for row, mode in enumerate(modes):
        transfer[row][positive] = mode
    xixi, etaeta, zz, xiz = (t * normal for t in transfer)
    return xixi, etaeta, zz, np.zeros_like(normal), xiz, np.zeros_like(normal)


def subsurface_stress(
    pressure: np.ndarray,
    size: tuple[float, float],
    depths: np.ndarray | list[float],
    *,
    poissons_ratio: float,
    traction: tuple[np.ndarray, np.ndarray] | None = None,
    boundary: str = "periodic",
    padding: int = 2,
    layer=None,
) -> StressField:
    """Stress below the surface caused by pixel-wise surface tractions.

    Parameters
    ----------
    pressure : ndarray
        Surface pressure [Pa], shape (nx, ny), compression positive.
    size : (float, float)
        Physical size of the window [m].
    depths : array_like
        Depths z >= 0 [m] of the planes to evaluate.
    poissons_ratio : float
        Poisson's ratio of the body.
    traction : (ndarray, ndarray), optional
        Shear tractions (q_x, q_y) [Pa] acting on the body's surface (force per area on the body,
        in +x / +y), e.g. friction from a counter-body sliding in +x.
    boundary : {"periodic", "free"}
        Periodic tractions, or a finite patch (zero-padded).
    padding : int
        Padding factor per axis for ``boundary="free"`` (>= 2).
    layer : ElasticLayer, optional
        The body is a film bonded to an elastic substrate (``ElasticLayer(thickness, film,
        base=substrate)``): the pressure's stress is that of the film on its substrate
        (:func:`~roughcontact.elasticity.kernels.film_stress_modes`), and ``poissons_ratio`` is
        ignored. Shear tractions are not supported with a layer.

    Returns
    -------
    StressField
    """
    depths = np.atleast_1d(np.asarray(depths, dtype=float))
    if np.any(depths < 0) or not np.all(np.isfinite(depths)):
        raise InputError("depths", "depths must be finite and >= 0.", "give depths below the surface in m.")
    if boundary not in ("periodic", "free"):
        raise InputError("boundary", f"unknown boundary {boundary!r}.", "use 'periodic' or 'free'.")
    nx, ny = pressure.shape
    factor = 1 if boundary == "periodic" else max(int(padding), 2)
    shape = (factor * nx, factor * ny)
    window = (factor * size[0], factor * size[1])
    qx, qy = wavevectors(shape, window)
    q = np.sqrt(qx**2 + qy**2)
    with np.errstate(invalid="ignore", divide="ignore"):
        cx, cy = np.where(q > 0, qx / q, 0.0), np.where(q > 0, qy / q, 0.0)

    def spectrum(field):
        return fft.rfft2(field, s=shape, workers=-1)

    normal = -spectrum(pressure)  # sigma_zz(0) = -p
    if traction is None:
        shear_x = shear_y = np.zeros_like(normal)
    else:
        if traction[0].shape != pressure.shape or traction[1].shape != pressure.shape:
            raise InputError("traction", "traction fields must have the pressure's shape.", None)
        shear_x, shear_y = -spectrum(traction[0]), -spectrum(traction[1])  # sigma_iz(0) = -q_i
    along = cx * shear_x + cy * shear_y
    across = -cy * shear_x + cx * shear_y
    nu = poissons_ratio
    if layer is not None:
        if traction is not None:
            raise InputError(
                "traction", "shear tractions on a film are not supported.", "leave traction out."
            )
        if isinstance(layer.base, str):
            raise InputError("layer", "the stress of a layer on a rigid base is not implemented.", None)
    out = np.empty((6, depths.size, nx, ny))
    # Mean lateral stress: uniaxial strain under a periodic (infinite) load; zero for a finite patch,
    # whose lateral stresses integrate to zero over a horizontal plane (Boussinesq).
    lateral_mean = nu / (1.0 - nu) * normal[0, 0] if boundary == "periodic" else 0.0
    for i, z in enumerate(depths):
        if layer is None:
            xixi, etaeta, zz, xieta, xiz, etaz = _local_modes(q, z, normal, along, across, nu)
        else:
            xixi, etaeta, zz, xieta, xiz, etaz = _film_modes(q, z, normal, layer)
            body = layer.material if z <= layer.thickness else layer.base
            nu = body.poissons_ratio
            lateral_mean = nu / (1.0 - nu) * normal[0, 0] if boundary == "periodic" else 0.0
        fields = (
            cx**2 * xixi + cy**2 * etaeta - 2 * cx * cy * xieta,
            cy**2 * xixi + cx**2 * etaeta + 2 * cx * cy * xieta,
            zz,
            cx * cy * (xixi - etaeta) + (cx**2 - cy**2) * xieta,
            cx * xiz - cy * etaz,
            cy * xiz + cx * etaz,
        )
        # q = 0 has no direction: uniform normal and shear stresses through the depth.
        fields[0][0, 0] = fields[1][0, 0] = lateral_mean
        fields[3][0, 0] = 0.0
        fields[2][0, 0] = normal[0, 0]
        fields[4][0, 0], fields[5][0, 0] = shear_x[0, 0], shear_y[0, 0]
        for c, field in enumerate(fields):
            out[c, i] = fft.irfft2(field, s=shape, workers=-1)[:nx, :ny]
    return StressField(depths, out, (float(size[0]), float(size[1])))
