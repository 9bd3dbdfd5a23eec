"""Surface compliance operator: pressure -> normal surface displacement, by FFT.

:class:`SurfaceCompliance` builds a kernel of :mod:`roughcontact.elasticity.kernels` once and
applies it with :class:`roughcontact._backend.RealFFT2` (FFTW through pyFFTW when it imports,
else ``scipy.fft``; ``ROUGHCONTACT_FFT=scipy`` forces the latter; all cores by default). It is
the only operator the contact solvers call; one application costs one rfft2 + irfft2 pair (of
the padded grid for a free boundary). With ``device="gpu"`` the contact solver's transforms run
on the GPU instead (:class:`roughcontact._gpu.DeviceFFT2`, cuFFT through CuPy), through the same
staged interface.
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .._backend import PRECISIONS, RealFFT2, resolve_workers
from .._device import check_storage, gpu_module, resolve_device
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
        """F(``|q|`` t): the layer's compliance relative to a half-space of the layer's material."""
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


def _stiffness(kernel: np.ndarray) -> np.ndarray:
    """Return 1 / kernel [Pa/m] where the kernel is positive; a zero mean mode gets the smallest stiffness."""
    inverse = np.zeros_like(kernel)
    positive = kernel > 0
    inverse[positive] = 1.0 / kernel[positive]
    if not positive.flat[0]:
        inverse.flat[0] = inverse[positive].min() if positive.any() else 0.0
    return inverse


def _compliance(material: Material | None) -> float:
    """(1 - nu^2) / E of a half-space [1/Pa]; 0 for a rigid body (None)."""
    return 0.0 if material is None else (1.0 - material.poissons_ratio**2) / material.youngs_modulus


@dataclass(frozen=True)
class StagedCompliance:
    """A :class:`SurfaceCompliance` held by one iterative solve (from :meth:`SurfaceCompliance.staged`).

    Attributes
    ----------
    pressure : ndarray
        Float64 view of the grid's shape: write a pressure p [Pa] here, then
        :meth:`displacement` returns K p [m].
    approximate : ndarray
        Float32 view of the grid's shape: write a field here, then :meth:`precondition` returns
        M of it (M the Fourier inverse of K, single precision).
    direction : ndarray
        Float32 view of the grid's shape: write a field f here, then :meth:`quadratic_form`
        returns f . K f. On a periodic grid the same memory as :attr:`approximate`.

    Results are views into the transforms' buffers, valid until the matching input is written
    again (on a periodic grid they share its memory).
    """

    pressure: np.ndarray
    approximate: np.ndarray
    direction: np.ndarray
    _double: RealFFT2
    _single: RealFFT2
    _window: RealFFT2
    _kernel: np.ndarray
    _inverse: np.ndarray
    _weights: np.ndarray

    def displacement(self) -> np.ndarray:
        """Return K p [m] of :attr:`pressure` (double precision)."""
        return self._double.apply_staged(self._kernel)

    def precondition(self) -> np.ndarray:
        """Return M f of :attr:`approximate` (single precision)."""
        return self._window.apply_staged(self._inverse)

    def quadratic_form(self) -> float:
        """Return f . K f of :attr:`direction` (Parseval, one single-precision forward transform)."""
        return self._single.power_staged(self._weights)


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
    fft_measure : bool, optional
        FFTW planner effort of the operator's transforms (:class:`~roughcontact._backend.RealFFT2`'s
        ``measure``; default by size). :meth:`coarse` operators are estimated: they run a few
        iterations, and a measured plan costs about a second at 1024^2.
    device : {"cpu", "gpu"}, optional
        Where the contact solver's iteration runs (:func:`roughcontact._device.resolve_device`;
        default ``ROUGHCONTACT_DEVICE``, else the CPU). :meth:`__call__` and :meth:`inverse`
        always run on the CPU.
    precision : {"double", "single"}
        Precision of the solver's fields and of K p: float32 (``"single"``, GPU only) halves the
        memory of the largest grids; the engine's sums stay float64 either way.

    Attributes
    ----------
    transform_shape : (int, int)
        Grid of the FFTs: ``shape``, or twice it for a free boundary (zero padding).

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
        fft_measure: bool | None = None,
        device: str | None = None,
        precision: str = "double",
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
                "contact_modulus",
                f"must be positive and finite, got {float(contact_modulus):g} Pa.",
                "give E* in Pa.",
            )
        self.shape = (int(shape[0]), int(shape[1]))
        self.size = (float(size[0]), float(size[1]))
        self.contact_modulus = float(contact_modulus)
        self.boundary = boundary
        self.layer = layer
        self.workers = resolve_workers(workers)
        padded = (2 * self.shape[0], 2 * self.shape[1])
        self.transform_shape = self.shape if boundary == "periodic" else padded
        self._counter_body = counter_body
        self._fft_backend, self._fft_measure = fft_backend, fft_measure
        self.device = resolve_device(device)
        self.precision = check_storage(precision, self.device)
        self._windows: dict[tuple[int, int], SurfaceCompliance] = {}
        self.kernel = self._kernel(boundary)
        self._derived = {}  # made on first use: inverse kernel, single-precision transform and kernels
        options = dict(input_shape=self.shape, backend=fft_backend, measure=fft_measure)
        self._fft = RealFFT2(self.transform_shape, self.workers, **options)

    def _kernel(self, boundary: str) -> np.ndarray:
        """Return the compliance kernel [m/Pa] on the transform grid of ``boundary`` (rfft2 layout).

        "periodic": the window's own grid, as a period; "free": the zero-padded grid. A layer's
        factor multiplies the half-space kernel (class notes).
        """
        if boundary == "periodic":
            kernel = kernels.periodic_halfspace_kernel(self.shape, self.size, self.contact_modulus)
            shape, size = self.shape, self.size
        else:
            kernel = kernels.free_halfspace_kernel(self.shape, self.size, self.contact_modulus)
            shape, size = (2 * self.shape[0], 2 * self.shape[1]), (2 * self.size[0], 2 * self.size[1])
        layer = self.layer
        if layer is not None:
            layer_compliance = _compliance(layer.material)
            counter_compliance = _compliance(self._counter_body)
            q = kernels.wavevector_magnitude(shape, size)
            ratio = (layer.factor(q) * layer_compliance + counter_compliance) * self.contact_modulus
            kernel = kernel * ratio
            if isinstance(layer.base, str) and self._counter_body is None:
                m = layer.material
                kernel[0, 0] = kernels.layer_winkler_compliance(
                    layer.thickness, m.youngs_modulus, m.poissons_ratio, base=layer.base
                )
        return kernel

    @cached_property
    def self_compliance(self) -> float:
        """K_ii [m/Pa]: a pixel's displacement under its own unit pressure (the operator's diagonal).

        The same at every pixel (the operator is translation-invariant); computed once, without a
        transform: the inverse transform of the kernel at the origin, the mean of the kernel over
        the whole spectrum, whose columns 1 .. (n - 1) / 2 the rfft layout holds once for two.
        """
        n = self.transform_shape[1]
        doubled = np.ones(self.kernel.shape[1])
        doubled[1 : (n + 1) // 2] = 2.0  # the column n/2 of an even n is its own mirror
        return float(self.kernel.sum(axis=0) @ doubled) / (self.transform_shape[0] * n)

    def window(self, shape) -> SurfaceCompliance:
        """Return the half-space operator on a ``shape`` sub-grid of this free surface (same pixels).

        Exact on the sub-grid (:func:`~roughcontact.elasticity.kernels.sub_grid_operator`). Built once per
        shape (the last :data:`~roughcontact.elasticity.kernels.SUB_GRIDS_KEPT` are kept).

        Raises
        ------
        InputError
            On a periodic surface, or with a layer (a free layer's kernel is the padded grid's
            periodic one times a factor, so it depends on the padded grid).
        """
        if self.layer is not None:
            raise InputError(
                "layer", "a layered body has no exact sub-grid operator.", "use the whole grid's."
            )
        return kernels.sub_grid_operator(self, self._windows, shape, self._on_grid)

    def coarse(self) -> SurfaceCompliance:
        """Return this body's operator on the grid coarsened 2 x 2 (pixels twice as wide).

        The same material, layer, counter-body and boundary; used by the coarse-to-fine cascade
        (:mod:`roughcontact.contact._box`). For a free grid with odd sides the last row or column is
        left out. Built once.

        Raises
        ------
        InputError
            A periodic grid with an odd side (its period is not a whole number of coarse pixels).
        """
        if "coarse" not in self._derived:
            if self.boundary == "periodic" and (self.shape[0] % 2 or self.shape[1] % 2):
                raise InputError(
                    "shape", f"a periodic {self.shape} grid has no 2 x 2 coarsening.", "use even sides."
                )
            shape = (self.shape[0] // 2, self.shape[1] // 2)
            spacing = (self.size[0] / self.shape[0], self.size[1] / self.shape[1])
            size = (2 * shape[0] * spacing[0], 2 * shape[1] * spacing[1])
            self._derived["coarse"] = self._on_grid(shape, size, fft_measure=False)
        return self._derived["coarse"]

    def _on_grid(self, shape, size, fft_measure=None) -> SurfaceCompliance:
        """Return this body's operator on another grid (the builder of :meth:`window` and :meth:`coarse`).

        Modulus or layer, counter-body, boundary, threads and FFT backend are this operator's.
        """
        return SurfaceCompliance(
            shape,
            size,
            None if self.layer is not None else self.contact_modulus,
            layer=self.layer,
            counter_body=self._counter_body,
            boundary=self.boundary,
            workers=self.workers,
            fft_backend=self._fft_backend,
            fft_measure=fft_measure,
            device=self.device,
            precision=self.precision,
        )

    def __call__(self, pressure: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        """Return the surface displacement [m] (into the body) of ``pressure`` [Pa].

        In double precision; into ``out`` (a float64 array of the grid's shape) when given, else
        a new array.
        """
        return self._fft.convolve(pressure, self.kernel, out)

    def inverse(self, displacement: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        """Apply the inverse kernel: the pressure [Pa] of a displacement [m] (used as a preconditioner).

        Exact for a periodic half-space (the mean mode, undetermined there, is given the stiffness
        of the longest wavelength); for a free boundary the inverse of the zero-padded operator,
        restricted to the window, which approximates the inverse of the free operator.
        """
        return self._fft.convolve(displacement, self.inverse_kernel(), out)

    def inverse_kernel(self) -> np.ndarray:
        """Return the stiffness kernel 1 / K [Pa/m], made once.

        The mean mode of a periodic half-space (zero compliance) gets the stiffness of the longest
        wavelength (see :meth:`inverse`).
        """
        if "inverse" not in self._derived:
            self._derived["inverse"] = _stiffness(self.kernel)
        return self._derived["inverse"]

    @contextlib.contextmanager
    def staged(self):
        """Hold the operator's transforms for one iterative solve: yields a :class:`StagedCompliance`.

        The contact solver writes its fields straight into the FFT input buffers and reads the
        results where the transforms leave them (:meth:`roughcontact._backend.RealFFT2.staged`).
        The preconditioner and the quadratic form run in single precision (float32 FFTs, about
        twice as fast on large grids, relative error about 1e-7): both only steer the iteration
        (a direction and a step length), while the displacement K p, which defines the gap and
        the residual, stays in double precision. Planning happens here on first use.

        The preconditioner M is the Fourier inverse of the operator taken as periodic on the
        window's own grid: for a periodic grid the exact inverse of K; for a free boundary an
        approximation that differs from the inverse of the zero-padded operator near the window's
        edges only (``|q|`` is a local operator: its kernel decays as 1/r^3), at a quarter of the
        transform size. Measured against the padded inverse: the same iteration counts within
        one or two on free Hertz and rough-ball cases, 256^2 to 1024^2.
        """
        if "single" not in self._derived:
            double, single, window, stiffness = self._transforms()
            self._derived["kernel/N"] = double.prepared(self.kernel)
            self._derived["inverse/N single"] = window.prepared(stiffness)
            self._derived["quadratic single"] = single.quadratic_form_weights(self.kernel)
            self._derived["double"], self._derived["single"], self._derived["window"] = double, single, window
        double, single, window = (self._derived[name] for name in ("double", "single", "window"))
        with double.staged() as pressure, single.staged() as direction, window.staged() as approximate:
            yield StagedCompliance(
                pressure=pressure,
                approximate=approximate,
                direction=direction,
                _double=double,
                _single=single,
                _window=window,
                _kernel=self._derived["kernel/N"],
                _inverse=self._derived["inverse/N single"],
                _weights=self._derived["quadratic single"],
            )

    def _transforms(self):
        """Return the solver's transforms (K p, t.K t, M g) and the preconditioner's stiffness kernel.

        On the CPU :class:`~roughcontact._backend.RealFFT2` (K p on this operator's own transform),
        on the GPU :class:`~roughcontact._gpu.DeviceFFT2`; see :meth:`staged`.
        """
        periodic = self.boundary == "periodic"
        stiffness = self.inverse_kernel() if periodic else _stiffness(self._kernel("periodic"))
        if self.device == "gpu":
            device_fft = gpu_module().DeviceFFT2
            double = device_fft(self.transform_shape, input_shape=self.shape, precision=self.precision)
            single = device_fft(self.transform_shape, input_shape=self.shape, precision="single")
            window = single if periodic else device_fft(self.shape, precision="single")
            return double, single, window, stiffness
        options = dict(backend=self._fft.backend, precision="single", measure=self._fft_measure)
        single = RealFFT2(self.transform_shape, self.workers, input_shape=self.shape, **options)
        window = single if periodic else RealFFT2(self.shape, self.workers, **options)
        return self._fft, single, window, stiffness

    def plan(self) -> None:
        """Make the FFT plans of every transform the contact solver uses (double and single precision).

        Otherwise they are made on first use; FFTW's measured plans take about a second each on
        1024^2 grids and more above, so timing a solve without its set-up means planning first.
        """
        with self.staged():
            pass

    @property
    def field_dtype(self):
        """The dtype of the contact solver's fields: float64, or float32 with ``precision="single"``."""
        return PRECISIONS[self.precision][0]

    @property
    def pixel_area(self) -> float:
        """Area of one pixel [m^2]."""
        return self.size[0] * self.size[1] / (self.shape[0] * self.shape[1])
