r"""The GPU backend (CuPy): device transforms and the reduction kernels the contact engines share.

Imported only through :func:`roughcontact._device.gpu_module`, when a caller asks for
``device="gpu"``; nothing else in the package imports CuPy. The engines keep one algorithm for
both devices: the constrained conjugate gradients of :mod:`roughcontact.contact._constrained_cg`
run the same iteration on numpy arrays with numba kernels, or on CuPy arrays with the CUDA
kernels of :mod:`roughcontact.contact._cg_kernels_gpu`, whose passes have the same arguments
and results.

- :class:`DeviceFFT2` is :class:`roughcontact._backend.RealFFT2`'s staged interface on the GPU
  (cuFFT through ``cupyx.scipy.fft``; cuFFT plans are cached by CuPy for the life of the
  process): a zero-padded input buffer the solver writes into, a Fourier multiplier, and the
  quadratic form by Parseval's theorem.
- :func:`compile_kernels` and :func:`reduction` run the fused passes: every thread walks the grid
  with a stride, keeps its partial sums in registers, reduces them across its warp with shuffles
  and adds them to a small float64 array with one atomic operation per warp (a maximum of
  non-negative doubles through the integer ``atomicMax`` of their bit patterns, which order as
  the numbers do). Each pass reads its arrays once, as the numba passes do. The order of the
  atomic additions varies between runs, so the sums, and the iterates, agree between runs and
  with the CPU to round-off, not bit for bit.

References
----------
Okuta, R., Unno, Y., Nishino, D., Hido, S. and Loomis, C. (2017). CuPy: a NumPy-compatible
library for NVIDIA GPU calculations. Proc. LearningSys (NIPS 2017).
"""

from __future__ import annotations

import contextlib
import functools

import cupy
import numpy as np
from cupyx.scipy import fft as _fft

from ._backend import PRECISIONS, quadratic_form_weights
from .errors import InputError

THREADS = 256
"""Threads per block of the reduction passes (a multiple of the warp size)."""
BLOCKS_PER_PROCESSOR = 8
"""Blocks per multiprocessor of a pass: enough resident warps to hide memory latency; more blocks
only add atomic operations."""

REDUCTIONS = r"""
#define FULL_MASK 0xffffffffu
__device__ __forceinline__ double warp_sum(double v) {
    for (int offset = 16; offset > 0; offset >>= 1) v += __shfl_down_sync(FULL_MASK, v, offset);
    return v;
}
__device__ __forceinline__ double warp_max(double v) {
    for (int offset = 16; offset > 0; offset >>= 1) v = fmax(v, __shfl_down_sync(FULL_MASK, v, offset));
    return v;
}
// Every thread of the warp must call these (after its grid-stride loop).
__device__ __forceinline__ void add_to(double* out, double v) {
    v = warp_sum(v);
    if ((threadIdx.x & 31) == 0) atomicAdd(out, v);
}
__device__ __forceinline__ void max_to(double* out, double v) {  // v >= 0: bits order as values
    v = warp_max(v);
    if ((threadIdx.x & 31) == 0)
        atomicMax((unsigned long long*)out, (unsigned long long)__double_as_longlong(v));
}
#define GRID_LOOP(k, n) \
    for (long long k = blockIdx.x * (long long)blockDim.x + threadIdx.x; k < (n); \
         k += (long long)gridDim.x * blockDim.x)
"""

_POWER = r"""
template <typename R>
__global__ void weighted_power(const R* spectrum, const R* weights, long long n, double* out) {
    double total = 0.0;
    GRID_LOOP(k, n) {
        double re = spectrum[2 * k], im = spectrum[2 * k + 1];
        total += (double)weights[k] * (re * re + im * im);
    }
    add_to(out, total);
}
"""


def check_device() -> None:
    """Raise :class:`InputError` unless CuPy sees a CUDA device."""
    try:
        count = cupy.cuda.runtime.getDeviceCount()
    except cupy.cuda.runtime.CUDARuntimeError as error:
        count, reason = 0, str(error)
    else:
        reason = "no device"
    if count < 1:
        raise InputError(
            "device",
            f"device 'gpu' asked for, but CUDA finds no GPU ({reason}).",
            "use device='cpu', or run on a machine with an NVIDIA GPU and its driver.",
            fixes={"cli": "leave --device out (the CPU), or run on a machine with a GPU."},
        )


def compile_kernels(code: str, names: tuple[str, ...]) -> dict[str, cupy.RawKernel]:
    """Compile CUDA C++ ``code`` (after :data:`REDUCTIONS`) and return its kernels by template name."""
    module = cupy.RawModule(code=REDUCTIONS + code, options=("-std=c++17",), name_expressions=names)
    return {name: module.get_function(name) for name in names}


@functools.cache
def _blocks_at_most() -> int:
    processors = cupy.cuda.Device().attributes["MultiProcessorCount"]
    return BLOCKS_PER_PROCESSOR * processors


def reduction(kernel: cupy.RawKernel, points: int, arguments: tuple, results: int) -> np.ndarray:
    """Launch a reduction pass over ``points`` grid points; return its ``results`` float64 sums on the host.

    ``arguments`` are the kernel's, less its last one, the output array (zeroed here).
    """
    out = cupy.zeros(results, dtype=cupy.float64)
    blocks = max(min((points + THREADS - 1) // THREADS, _blocks_at_most()), 1)
    kernel((blocks,), (THREADS,), (*arguments, out))
    return out.get()


@functools.cache
def _power_kernels() -> dict[str, cupy.RawKernel]:
    return compile_kernels(_POWER, ("weighted_power<float>", "weighted_power<double>"))


def row_stride(array: cupy.ndarray) -> np.int64:
    """Return the distance between rows of a 2D view whose rows are contiguous, in elements."""
    if array.strides[1] != array.itemsize:
        raise ValueError("a row of a kernel argument must be contiguous")
    return np.int64(array.strides[0] // array.itemsize)


def c_type(dtype) -> str:
    """Return the C type of a real dtype (``float`` or ``double``)."""
    return {np.dtype(np.float32): "float", np.dtype(np.float64): "double"}[np.dtype(dtype)]


class DeviceFFT2:
    """Fourier multiplier of a real 2D field on the GPU, with the staged API of ``RealFFT2``.

    Parameters
    ----------
    shape : (int, int)
        Transform shape (the periodic grid, or the zero-padded grid).
    input_shape : (int, int), optional
        Shape of the staged field, at most ``shape`` (default ``shape``); the margin stays zero.
    precision : {"double", "single"}
        Precision of the transforms and of the staged field.
    """

    def __init__(self, shape, *, input_shape=None, precision: str = "double"):
        self.shape = (int(shape[0]), int(shape[1]))
        self.input_shape = self.shape if input_shape is None else (int(input_shape[0]), int(input_shape[1]))
        self.real_dtype, _ = PRECISIONS[precision]
        self._buffer = None

    @property
    def size(self) -> int:
        """Number of points N of the transform grid."""
        return self.shape[0] * self.shape[1]

    @contextlib.contextmanager
    def staged(self):
        """Yield the staged input: a view of shape ``input_shape`` into the zero-margined buffer."""
        if self._buffer is None:
            self._buffer = cupy.zeros(self.shape, dtype=self.real_dtype)
        m0, m1 = self.input_shape
        yield self._buffer[:m0, :m1]

    def prepared(self, kernel: np.ndarray) -> cupy.ndarray:
        """Return ``kernel / N`` on the device, in ``real_dtype``."""
        return cupy.asarray(np.asarray(kernel) / self.size, dtype=self.real_dtype)

    def quadratic_form_weights(self, kernel: np.ndarray) -> cupy.ndarray:
        """Return the weights of :meth:`power_staged` (``_backend.quadratic_form_weights``)."""
        return cupy.asarray(quadratic_form_weights(self.shape, kernel, self.real_dtype))

    def apply_staged(self, prepared_kernel: cupy.ndarray) -> cupy.ndarray:
        """Return irfft2(kernel rfft2(staged)) unnormalised, cropped: a view valid until the next call."""
        spectrum = _fft.rfft2(self._buffer)
        spectrum *= prepared_kernel
        result = _fft.irfft2(spectrum, s=self.shape, norm="forward", overwrite_x=True)
        m0, m1 = self.input_shape
        return result[:m0, :m1]

    def power_staged(self, weights: cupy.ndarray) -> float:
        """Return sum w |rfft2(staged)|^2, accumulated in float64."""
        spectrum = _fft.rfft2(self._buffer)
        real = spectrum.view(self.real_dtype)  # interleaved (re, im) pairs
        kernel = _power_kernels()[f"weighted_power<{c_type(self.real_dtype)}>"]
        return float(reduction(kernel, spectrum.size, (real, weights, np.int64(spectrum.size)), 1)[0])
