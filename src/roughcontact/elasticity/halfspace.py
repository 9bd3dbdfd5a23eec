"""Surface compliance operator: pressure -> normal surface displacement, by FFT.

:class:`SurfaceCompliance` builds a kernel of :mod:`roughcontact.elasticity.kernels` once and
applies it with :class:`roughcontact._backend.RealFFT2` (FFTW through pyFFTW when it imports,
else ``scipy.fft``; ``ROUGHCONTACT_FFT=scipy`` forces the latter; all cores by default). It is
the only operator the contact solvers call; one application costs one rfft2 + irfft2 pair (of
the padded grid for a free boundary).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._backend import RealFFT2, resolve_workers
from ..errors import InputError
from ..materials import Material
from . import kernels


@dataclass(frozen=True)
class ElasticLayer:
    """An elastic layer of finite thickness on a rigid base or bonded to an elastic substrate.

    Parameters
    ----------
    thickness : float
        Layer thickness [m] (paper 000: 50 nm polysilicon; paper 002: 6.3 um SU-8).
    material : Material
        The layer's elastic constants.
    base : {"bonded", "frictionless"} or Material
        A rigid base the layer is bonded to or slides freely on, or the elastic substrate
        (a half-space) the layer is perfectly bonded to.
    """

    thickness: float
    material: Material
    base: str | Material = "bonded"

    def __post_init__(self):
        if not (np.isfinite(self.thickness) and self.thickness > 0):
            raise InputError("thickness", f"must be positive, got {self.thickness!r}.", "give it in m.")
        if isinstance(self.base, str) and self.base not in kernels.LAYER_BASES:
            raise InputError(
                "base", f"unknown base {self.base!r}.", f"use {kernels.LAYER_BASES} or a substrate Material."
            )

    def factor(self, q: np.ndarray) -> np.ndarray:
        """F(|q| t): the layer's compliance relative to a half-space of the layer's material."""
        m = self.material
        if isinstance(self.base, str):
            return kernels.layer_on_rigid_base_factor(q * self.thickness, m.poissons_ratio, base=self.base)
        return kernels.film_on_substrate_factor(
            q * self.thickness,
            m.youngs_modulus,
            m.poissons_ratio,
            self.base.youngs_modulus,
            self.base.poissons_ratio,
        )


def _compliance(material: Material | None) -> float:
    """(1 - nu^2) / E of a half-space [1/Pa]; 0 for a rigid body (None)."""
    return 0.0 if material is None else (1.0 - material.poissons_ratio**2) / material.youngs_modulus


class SurfaceCompliance:
    """Linear map from pixel pressures [Pa] to surface displacements [m] of elastic bodies.

    Parameters
    ----------
    shape : (int, int)
        Grid (nx, ny).
    size : (float, float)
        Physical size (Lx, Ly) [m]; the period for ``boundary="periodic"``.
    contact_modulus : float, optional
        E* [Pa] of two half-spaces, 1/E* = sum (1 - nu_i^2)/E_i
        (:func:`roughcontact.materials.contact_modulus`). Give this or ``layer``.
    layer : ElasticLayer, optional
        The body is a layer (on a rigid base or an elastic substrate) instead of a half-space.
    counter_body : Material, optional
        With ``layer``: the other body, an elastic half-space (default: rigid).
    boundary : {"periodic", "free"}
        Periodic surface, or a window of a free (non-periodic) surface, zero-padded.
    workers : int, optional
        FFT threads (default: all cores).
    fft_backend : {"auto", "fftw", "scipy"}, optional
        FFT library (:func:`roughcontact._backend.fft_backend`; default: the environment
        variable ``ROUGHCONTACT_FFT``, else FFTW when pyFFTW imports). Same result to round-off.

    Notes
    -----
    With a layer the kernel is the half-space kernel of E* times
    ``[F(q t) c_layer + c_counter] / (c_layer + c_counter)`` with c = (1 - nu^2)/E, i.e. the
    layer's compliance plus the counter-body's. For a layer on a rigid base against a rigid
    counter-body the q = 0 term is the Winkler (q -> 0) limit, so the mean displacement (the
    approach) is measured from the base, not left undetermined as for a half-space. For a free
    boundary the factor multiplies the zero-padded Love kernel: exact for the periodic images
    of the padded window, and a close approximation of a free layer when its thickness is small
    compared with the window.
    """

    def __init__(
        self,
        shape: tuple[int, int],
        size: tuple[float, float],
        contact_modulus: float | None = None,
        *,
        layer: ElasticLayer | None = None,
        counter_body: Material | None = None,
        boundary: str = "periodic",
        workers: int | None = None,
        fft_backend: str | None = None,
    ):
        if boundary not in kernels.BOUNDARIES:
            raise InputError("boundary", f"unknown boundary {boundary!r}.", "use 'periodic' or 'free'.")
        if (contact_modulus is None) == (layer is None):
            raise InputError(
                "contact_modulus",
                "give exactly one of contact_modulus and layer.",
                "pass E* [Pa] or a layer.",
            )
        if layer is not None:
            layer_compliance, counter_compliance = _compliance(layer.material), _compliance(counter_body)
            contact_modulus = 1.0 / (layer_compliance + counter_compliance)
        if not (np.isfinite(contact_modulus) and contact_modulus > 0):
            raise InputError(
                "contact_modulus", f"must be positive and finite, got {contact_modulus!r}.", "give E* in Pa."
            )
        self.shape = (int(shape[0]), int(shape[1]))
        self.size = (float(size[0]), float(size[1]))
        self.contact_modulus = float(contact_modulus)
        self.boundary = boundary
        self.layer = layer
        self.workers = resolve_workers(workers)
        if boundary == "periodic":
            self._fft_shape = self.shape
            kernel = kernels.periodic_halfspace_kernel(self.shape, self.size, self.contact_modulus)
            fft_size = self.size
        else:
            self._fft_shape = (2 * self.shape[0], 2 * self.shape[1])
            kernel = kernels.free_halfspace_kernel(self.shape, self.size, self.contact_modulus)
            fft_size = (2 * self.size[0], 2 * self.size[1])
        if layer is not None:
            q = kernels.wavevector_magnitude(self._fft_shape, fft_size)
            ratio = (layer.factor(q) * layer_compliance + counter_compliance) * self.contact_modulus
            kernel = kernel * ratio
            if isinstance(layer.base, str) and counter_body is None:
                m = layer.material
                kernel[0, 0] = kernels.layer_winkler_compliance(
                    layer.thickness, m.youngs_modulus, m.poissons_ratio, base=layer.base
                )
        self.kernel = kernel
        self._inverse_kernel = None
        self._quadratic_weights = None
        self._fft = RealFFT2(self._fft_shape, self.workers, input_shape=self.shape, backend=fft_backend)

    def __call__(self, pressure: np.ndarray) -> np.ndarray:
        """Return the surface displacement [m] (into the body) of ``pressure`` [Pa] (a new array)."""
        return self._fft.convolve(pressure, self.kernel)

    def quadratic_form(self, pressure: np.ndarray) -> float:
        """Return p . K p [Pa m], the pressure-weighted displacement summed over the pixels.

        Computed in Fourier space (Parseval) at the cost of one forward transform, a third of
        ``np.vdot(pressure, self(pressure))``'s; the step length of the contact solver needs
        nothing else of K t.
        """
        if self._quadratic_weights is None:
            self._quadratic_weights = self._fft.quadratic_form_weights(self.kernel)
        return self._fft.quadratic_form(pressure, self._quadratic_weights)

    def inverse(self, displacement: np.ndarray) -> np.ndarray:
        """Apply the inverse kernel: the pressure [Pa] of a displacement [m] (used as a preconditioner).

        Exact for a periodic half-space (the mean mode, undetermined there, is given the stiffness
        of the longest wavelength); for a free boundary the inverse of the zero-padded operator,
        restricted to the window, which approximates the inverse of the free operator.
        """
        if self._inverse_kernel is None:
            inverse = np.zeros_like(self.kernel)
            positive = self.kernel > 0
            inverse[positive] = 1.0 / self.kernel[positive]
            if not positive.flat[0]:
                inverse.flat[0] = inverse[positive].min() if positive.any() else 0.0
            self._inverse_kernel = inverse
        return self._fft.convolve(displacement, self._inverse_kernel)

    @property
    def pixel_area(self) -> float:
        """Area of one pixel [m^2]."""
        return self.size[0] * self.size[1] / (self.shape[0] * self.shape[1])
