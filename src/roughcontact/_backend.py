"""FFT backend: real 2D FFT convolutions with FFTW (pyFFTW) when it imports, else scipy.fft.

:class:`RealFFT2` applies a Fourier multiplier to a real field: rfft2 (of the field zero-padded
to the transform shape), multiply by a kernel, irfft2, crop. With pyFFTW it executes two FFTW
plans on aligned buffers owned by the object and copies the result out; otherwise it calls
``scipy.fft`` (pocketfft). The backend is chosen by the ``backend`` argument, else by the
environment variable ``ROUGHCONTACT_FFT`` (``fftw``, ``scipy`` or ``auto``), else ``auto``
(FFTW when pyFFTW imports).

FFTW configuration, from timings on a 2-core machine (``benchmarks/fft_backend.py``):

- planner effort ``FFTW_ESTIMATE`` (no planning time) below :data:`MEASURE_FROM` points of the
  transform; ``FFTW_MEASURE`` (timed trial transforms, at most :data:`PLANNING_TIME_LIMIT` per
  plan; about 1 s at 1024^2, 3 s at 2048^2) from there on, where ESTIMATE plans are no faster
  than pocketfft (1024^2) or slower (2048^2) and MEASURE plans are 15-25 % faster. Below, the
  planning would cost more than it saves over one solve (0.3 s at 256^2 to save 0.2 ms per
  transform). FFTW keeps the wisdom of every plan for the life of the process, so a later
  operator of the same shape and thread count (a load path, repeated solves) plans in a
  millisecond, and :mod:`roughcontact._fftw_wisdom` keeps it on disk for the next process;
- one thread below :data:`THREADS_FROM` points, where a second thread gains nothing;
- OpenMP threads that sleep at barriers (``OMP_WAIT_POLICY=PASSIVE``, see
  :func:`pyfftw_module`), which keeps a transform from stalling when another process
  keeps a core busy.

References
----------
Frigo, M. and Johnson, S. G. (2005). The design and implementation of FFTW3. Proc. IEEE 93,
216-231. doi:10.1109/JPROC.2004.840301
"""

from __future__ import annotations

import contextlib
import functools
import os
import sys
import threading
import time

import numba as nb
import numpy as np
from scipy import fft as _scipy_fft

from . import _fftw_wisdom
from .errors import InputError


@functools.cache
def pyfftw_module():
    """Return pyFFTW, imported at the first call (None if it does not import), quietly and quickly.

    Imported when a transform first asks for it, not with this module, so that a process that
    never transforms (``roughcontact --help``, reading a file) does not pay for it. Two settings
    hold for the import only:

    - its OpenMP threads sleep, not spin, at barriers. The pyFFTW wheels bundle their own OpenMP
      runtime (libgomp), which reads ``OMP_WAIT_POLICY`` once, when pyFFTW loads it. With the
      default (spinning) policy, a transform on 2 threads while another process keeps a core
      busy waits for the scheduler at every barrier (measured here: 30 ms instead of 1 ms per
      256^2 pair, 1 s for a 33^2 one). The variable is set to ``PASSIVE`` unless the user has set it;
    - its Dask interface is left out: ``pyfftw.interfaces`` imports ``dask.array`` (0.4-0.5 s)
      whenever Dask is installed, and roughcontact calls the FFTW plans directly. A process
      that has imported ``dask.array.fft`` already keeps it.
    """
    chosen = "OMP_WAIT_POLICY" in os.environ
    if not chosen:
        os.environ["OMP_WAIT_POLICY"] = "PASSIVE"
    dask_fft_absent = "dask.array.fft" not in sys.modules
    if dask_fft_absent:
        sys.modules["dask.array.fft"] = None  # import of it raises ImportError: pyFFTW skips it
    try:
        import pyfftw
    except ImportError:  # pragma: no cover - depends on the environment
        return None
    finally:
        if not chosen:
            del os.environ["OMP_WAIT_POLICY"]
        if dask_fft_absent and sys.modules.get("dask.array.fft", 0) is None:
            del sys.modules["dask.array.fft"]
    return pyfftw


BACKENDS = ("auto", "fftw", "scipy")
ENVIRONMENT_VARIABLE = "ROUGHCONTACT_FFT"
MEASURE_FROM = 1 << 20
"""Transform size (points) from which FFTW plans are measured rather than estimated."""
PLANNING_TIME_LIMIT = 10.0
"""Upper bound [s] of the planning time of one FFTW_MEASURE plan."""
WISDOM_SAVED_FROM = 0.05
"""Planning time [s] of a measured pair of plans above which the wisdom file is rewritten (a pair
found in the wisdom takes about a millisecond; :mod:`roughcontact._fftw_wisdom`)."""
THREADS_FROM = 1 << 15
"""Transform size (points) from which FFTW runs on ``workers`` threads; smaller ones on one thread."""
PRECISIONS = {"double": (np.float64, np.complex128), "single": (np.float32, np.complex64)}
"""Real and complex dtypes of each transform precision."""


THREADS_VARIABLE = "ROUGHCONTACT_FFT_THREADS"
"""Environment variable with the default FFT thread count (the study runner sets it for its Dask
workers, so that the workers of one machine share its cores instead of each taking all of them)."""


def resolve_workers(workers: int | None) -> int:
    """Return the thread count: -k means all cores but k - 1 (as in scipy.fft).

    ``None``: the environment variable :data:`THREADS_VARIABLE` when set, else all cores.
    """
    cores = os.cpu_count() or 1
    if workers is None:
        text = os.environ.get(THREADS_VARIABLE, "").strip()
        try:
            workers = int(text) if text else -1
        except ValueError:
            raise InputError(
                THREADS_VARIABLE, f"got {text!r}.", "set a whole number of threads, e.g. 1, or unset it."
            ) from None
    workers = int(workers)
    return max(cores + 1 + workers if workers < 0 else workers, 1)


def fft_backend(backend: str | None = None) -> str:
    """Return the backend that ``backend`` selects: ``"fftw"`` or ``"scipy"``.

    Parameters
    ----------
    backend : {"auto", "fftw", "scipy"}, optional
        ``None``: the environment variable ``ROUGHCONTACT_FFT``, else ``"auto"``. ``"auto"`` is
        ``"fftw"`` when pyFFTW imports, else ``"scipy"``; ``"fftw"`` without pyFFTW raises
        :class:`~roughcontact.errors.InputError`.
    """
    if backend is None:
        backend = os.environ.get(ENVIRONMENT_VARIABLE, "auto").strip().lower() or "auto"
    if backend not in BACKENDS:
        raise InputError(
            "fft_backend",
            f"unknown FFT backend {backend!r}.",
            f"use one of {BACKENDS} (or unset {ENVIRONMENT_VARIABLE}).",
        )
    if backend == "auto":
        return "fftw" if pyfftw_module() is not None else "scipy"
    if backend == "fftw" and pyfftw_module() is None:
        raise InputError(
            "fft_backend",
            "the FFTW backend needs pyFFTW, which does not import.",
            "pip install pyFFTW, or use 'scipy'.",
        )
    return backend


class RealFFT2:
    """Fourier multiplier of a real 2D field: irfft2(kernel * rfft2(field zero-padded to ``shape``)).

    Parameters
    ----------
    shape : (int, int)
        Transform shape (the periodic grid, or the zero-padded grid).
    workers : int, optional
        Threads (default: all cores).
    input_shape : (int, int), optional
        Shape of the fields passed to :meth:`convolve`, at most ``shape``: they are zero-padded to
        ``shape`` and the result is cropped back (default: ``shape``).
    backend : {"auto", "fftw", "scipy"}, optional
        See :func:`fft_backend` (default: ``ROUGHCONTACT_FFT``, else ``"auto"``).
    precision : {"double", "single"}
        Floating-point precision of the transforms. ``"single"`` (float32, relative round-off
        about 1e-7) moves half the bytes and runs about twice as fast on large grids; for
        approximate operators such as a preconditioner, never for a result. Inputs and outputs
        are float64 either way; kernels should be given in the transform's precision
        (:attr:`real_dtype`) to avoid a conversion per call.
    measure : bool, optional
        FFTW plans by timed trial transforms (``FFTW_MEASURE``) or by estimate (``FFTW_ESTIMATE``,
        no planning time). Default: measured from :data:`MEASURE_FROM` points. Estimate for a
        transform that runs a few times only (the coarse levels of a cascade).

    Notes
    -----
    The FFTW plans are made on first use (``FFTW_MEASURE`` plans overwrite their buffers and
    take up to seconds on large grids). Calls are serialised by a lock since the buffers are
    shared; every result is a fresh array, or the caller's ``out``, never a view of a buffer.
    """

    def __init__(
        self,
        shape: tuple[int, int],
        workers: int | None = None,
        *,
        input_shape: tuple[int, int] | None = None,
        backend: str | None = None,
        precision: str = "double",
        measure: bool | None = None,
    ):
        if precision not in PRECISIONS:
            raise InputError(
                "precision", f"unknown precision {precision!r}.", f"use one of {tuple(PRECISIONS)}."
            )
        self.precision = precision
        self.real_dtype, self._complex_dtype = PRECISIONS[precision]
        self.shape = (int(shape[0]), int(shape[1]))
        self.input_shape = self.shape if input_shape is None else (int(input_shape[0]), int(input_shape[1]))
        if not all(0 < m <= s for m, s in zip(self.input_shape, self.shape, strict=True)):
            raise InputError("input_shape", f"{self.input_shape} must be positive and at most {self.shape}.")
        self.spectrum_shape = (self.shape[0], self.shape[1] // 2 + 1)
        self.workers = resolve_workers(workers)
        self.backend = fft_backend(backend)
        if measure is None:
            measure = self.shape[0] * self.shape[1] >= MEASURE_FROM
        self.planner = "FFTW_MEASURE" if measure else "FFTW_ESTIMATE"
        self._plans = None
        self._scipy_input = None
        self._lock = threading.RLock()  # re-entrant: a staged() holder may call convolve()

    def _plan(self):
        pyfftw = pyfftw_module()
        real_in = pyfftw.zeros_aligned(self.shape, dtype=self.real_dtype)
        spectrum = pyfftw.empty_aligned(self.spectrum_shape, dtype=self._complex_dtype)
        # a padded input keeps its zero margin: the forward plan preserves its input and the
        # backward plan writes into a separate buffer.
        padded = self.input_shape != self.shape
        real_out = pyfftw.empty_aligned(self.shape, dtype=self.real_dtype) if padded else real_in
        threads = self.workers if self.shape[0] * self.shape[1] >= THREADS_FROM else 1
        options = {"axes": (0, 1), "threads": threads, "planning_timelimit": PLANNING_TIME_LIMIT}
        measured = self.planner == "FFTW_MEASURE"
        if measured:
            _fftw_wisdom.load(pyfftw)  # the plans measured by earlier processes on this machine
        start = time.perf_counter()
        forward = pyfftw.FFTW(real_in, spectrum, flags=(self.planner,), **options)
        flags = (self.planner, "FFTW_DESTROY_INPUT")
        backward = pyfftw.FFTW(spectrum, real_out, direction="FFTW_BACKWARD", flags=flags, **options)
        if measured and time.perf_counter() - start > WISDOM_SAVED_FROM:
            _fftw_wisdom.save(pyfftw)  # a plan that was measured, not found in the wisdom
        real_in[...] = 0.0  # planning may have written into the buffers
        return real_in, spectrum, real_out, forward, backward

    def convolve(self, field: np.ndarray, kernel: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        """Return irfft2(kernel * rfft2(field)) on the transform grid, cropped to ``input_shape``.

        Parameters
        ----------
        field : ndarray, shape ``input_shape``
            Real field (any unit).
        kernel : ndarray, shape ``(shape[0], shape[1] // 2 + 1)``
            Fourier multiplier on the rfft2 half-spectrum (real or complex).
        out : ndarray, optional
            Float64 array of shape ``input_shape`` to write the result into (a work array reused
            by an iteration: a fresh large array costs page faults on first touch).

        Returns
        -------
        ndarray, shape ``input_shape``
            ``out``, or a new float64 array.
        """
        field = self._checked(field)
        with self._lock:
            self._stage()[...] = field
            result = np.empty(self.input_shape) if out is None else out
            np.multiply(self._apply(kernel), 1.0 / self.size, out=result)
        return result

    @property
    def size(self) -> int:
        """Number of points N of the transform grid (irfft2 normalises by 1/N)."""
        return self.shape[0] * self.shape[1]

    @contextlib.contextmanager
    def staged(self):
        """Hold the transform for the calling thread and yield its staged input.

        The input is a writable view of shape ``input_shape`` into the transform's own input
        buffer (``real_dtype``): an iterative solver writes its field there in the same pass
        that computes it, then calls :meth:`apply_staged` or :meth:`power_staged`, and reads
        the result where it lies, saving a copy in and a copy out per transform. The view is
        valid inside the ``with`` block only; the output of :meth:`apply_staged` may share its
        memory (periodic grids transform in place), so read it before writing the next input.
        """
        with self._lock:
            yield self._stage()

    def prepared(self, kernel: np.ndarray) -> np.ndarray:
        """Return ``kernel / N`` in ``real_dtype``: the multiplier that :meth:`apply_staged` needs."""
        return np.ascontiguousarray(np.asarray(kernel) / self.size, dtype=self.real_dtype)

    def apply_staged(self, prepared_kernel: np.ndarray) -> np.ndarray:
        """Transform the staged input, multiply by a :meth:`prepared` kernel, transform back.

        Inside :meth:`staged` only. Returns a view of shape ``input_shape`` (``real_dtype``) that
        is valid until the staged input is written or the transform is used again.
        """
        return self._apply(prepared_kernel)

    def forward_staged(self) -> np.ndarray:
        """Return rfft2 of the staged input; inside :meth:`staged` only.

        The spectrum is the transform's own buffer (a new array with scipy): valid until the
        next transform, and it may be modified in place before :meth:`backward_staged`.
        """
        return self._forward_stage()

    def backward_staged(self, spectrum: np.ndarray) -> np.ndarray:
        """Return irfft2 of ``spectrum`` unnormalised (N times numpy's), cropped; inside :meth:`staged` only.

        A view of the transform's output buffer (periodic grids: the staged input's memory),
        valid until the next transform; ``spectrum`` may be the buffer :meth:`forward_staged`
        returned, else it is copied there (and destroyed by FFTW).
        """
        return self._backward(spectrum)

    def power_staged(self, weights: np.ndarray) -> float:
        """Return sum w |rfft2(staged input)|^2; inside :meth:`staged` only.

        With w from :meth:`quadratic_form_weights` this is the quadratic form f . K f of the staged
        field f: one forward transform instead of the pair (and the elementwise product) of
        ``f . convolve(f, K)``, equal to it to the round-off of :attr:`precision`.
        """
        return _weighted_power(self._forward_stage(), weights)

    def _checked(self, field: np.ndarray) -> np.ndarray:
        field = np.asarray(field)
        if field.shape != self.input_shape:
            raise InputError("field", f"shape {field.shape}, expected {self.input_shape}.")
        return field

    def _buffers(self):
        """Return (real input, spectrum, real output, forward plan, backward plan); plan on first use."""
        if self._plans is None:
            self._plans = self._plan()
        return self._plans

    def _stage(self) -> np.ndarray:
        """Return the input field's place: the FFTW input buffer's window, or an array of its own (scipy)."""
        m0, m1 = self.input_shape
        if self.backend == "scipy":
            if self._scipy_input is None:
                self._scipy_input = np.zeros(self.input_shape, dtype=self.real_dtype)
            return self._scipy_input
        return self._buffers()[0][:m0, :m1]

    def _forward_stage(self) -> np.ndarray:
        """rfft2 of the staged input: the FFTW spectrum buffer (or a new array with scipy)."""
        if self.backend == "scipy":
            return _scipy_fft.rfft2(self._scipy_input, s=self.shape, workers=self.workers)
        _, spectrum, _, forward, _ = self._buffers()
        forward.execute()
        return spectrum

    def _backward(self, spectrum: np.ndarray) -> np.ndarray:
        """Unnormalised irfft2 (N times numpy's) of ``spectrum``, cropped to ``input_shape`` (a view)."""
        m0, m1 = self.input_shape
        if self.backend == "scipy":
            result = _scipy_fft.irfft2(spectrum, s=self.shape, workers=self.workers, norm="forward")
            return result[:m0, :m1]
        _, buffer, real_out, _, backward = self._buffers()
        if spectrum is not buffer:
            buffer[...] = spectrum
        backward.execute()
        return real_out[:m0, :m1]

    def _apply(self, kernel: np.ndarray) -> np.ndarray:
        spectrum = self._forward_stage()
        np.multiply(spectrum, kernel, out=spectrum)
        return self._backward(spectrum)

    def forward(self, field: np.ndarray) -> np.ndarray:
        """Return rfft2 of ``field`` zero-padded to ``shape`` (a new complex array).

        With :meth:`inverse` it applies a matrix of multipliers to several fields (e.g. the two
        shear components) at one forward transform per field and one inverse per output.
        """
        field = self._checked(field)
        with self._lock:
            self._stage()[...] = field
            spectrum = self._forward_stage()
            return spectrum.copy() if self.backend == "fftw" else spectrum

    def quadratic_form_weights(self, kernel: np.ndarray) -> np.ndarray:
        """Return the weights w that make :meth:`power_staged` equal f . irfft2(kernel * rfft2(f)).

        See :func:`quadratic_form_weights`; in :attr:`real_dtype`.
        """
        return quadratic_form_weights(self.shape, kernel, self.real_dtype)

    def inverse(self, spectrum: np.ndarray) -> np.ndarray:
        """Return irfft2 of a half-spectrum on ``shape``, cropped to ``input_shape`` (a new float64 array)."""
        with self._lock:
            result = np.empty(self.input_shape)
            np.multiply(self._backward(spectrum), 1.0 / self.size, out=result)
        return result


def quadratic_form_weights(shape: tuple[int, int], kernel: np.ndarray, dtype=np.float64) -> np.ndarray:
    """Return the weights w with sum w |rfft2(f)|^2 = f . irfft2(kernel * rfft2(f)) on a ``shape`` grid.

    By Parseval's theorem, for a real field f (zero-padded to ``shape``, N points) and a real
    multiplier K with K(q) = K(-q), sum_x f K f = (1/N) sum over the full spectrum of
    K |f^|^2; on the rfft2 half-spectrum the columns 0 < j < shape[1]/2 stand for two
    modes each (j and -j), the column 0 and, for an even width, the Nyquist column for one.
    So w = m_j K / N with that multiplicity m_j.
    """
    spectrum_shape = (shape[0], shape[1] // 2 + 1)
    kernel = np.asarray(kernel)
    if kernel.shape != spectrum_shape or np.iscomplexobj(kernel):
        raise InputError("kernel", f"must be a real array of shape {spectrum_shape}.")
    multiplicity = np.full(spectrum_shape[1], 2.0)
    multiplicity[0] = 1.0
    if shape[1] % 2 == 0:
        multiplicity[-1] = 1.0
    weights = kernel * multiplicity / (shape[0] * shape[1])
    return np.ascontiguousarray(weights, dtype=dtype)


@nb.njit(cache=True, nogil=True)
def _weighted_power(spectrum, weights):
    """Return sum w |s|^2 over a complex array s and a real array w of the same shape (one pass)."""
    total = 0.0
    s, w = spectrum.ravel(), weights.ravel()
    for i in range(s.size):
        total += w[i] * (s[i].real * s[i].real + s[i].imag * s[i].imag)
    return total
