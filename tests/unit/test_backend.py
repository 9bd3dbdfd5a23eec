"""FFT backend: FFTW (pyFFTW) and scipy.fft give the same operator and contact solution; fallback."""

import os

import numpy as np
import pytest
from scipy import fft

from roughcontact import _backend, _fftw_wisdom
from roughcontact._backend import RealFFT2, fft_backend
from roughcontact.contact import solve_normal
from roughcontact.contact.normal import compliance_for
from roughcontact.elasticity.halfspace import ElasticLayer, SurfaceCompliance
from roughcontact.errors import InputError
from roughcontact.materials import Material
from roughcontact.topography.generate import self_affine

# pyFFTW is a declared dependency; without it only the fallback test runs
needs_fftw = pytest.mark.skipif(_backend.pyfftw_module() is None, reason="pyFFTW does not import")

SHAPES = [(32, 32), (33, 33), (24, 37), (37, 24), (7, 1)]


def _relative(a, b):
    return np.max(np.abs(a - b)) / np.max(np.abs(b))


def _pair(shape, boundary, **options):
    operators = {}
    for backend in ("fftw", "scipy"):
        operators[backend] = SurfaceCompliance(
            shape, (1e-4, 2.5e-4), 1e9, boundary=boundary, fft_backend=backend, **options
        )
    return operators


@needs_fftw
@pytest.mark.parametrize("boundary", ["periodic", "free"])
@pytest.mark.parametrize("shape", SHAPES)
def test_backends_agree(shape, boundary):
    operators = _pair(shape, boundary, workers=2)
    assert operators["fftw"]._fft.backend == "fftw" and operators["scipy"]._fft.backend == "scipy"
    field = np.random.default_rng(3).random(shape)
    for apply in ("__call__", "inverse"):
        results = {b: getattr(op, apply)(field) for b, op in operators.items()}
        assert results["fftw"].shape == shape and results["fftw"].dtype == np.float64
        assert _relative(results["fftw"], results["scipy"]) < 1e-12


@needs_fftw
def test_layer_operator_agrees():
    layer = ElasticLayer(2e-6, Material(youngs_modulus=1e9, poissons_ratio=0.3), "bonded")
    operators = {
        b: SurfaceCompliance((20, 30), (1e-4, 1e-4), layer=layer, boundary="free", fft_backend=b)
        for b in ("fftw", "scipy")
    }
    field = np.random.default_rng(4).random((20, 30))
    assert _relative(operators["fftw"](field), operators["scipy"](field)) < 1e-12


@needs_fftw
@pytest.mark.parametrize("boundary", ["periodic", "free"])
def test_results_are_not_overwritten_by_later_calls(boundary):
    shape = (16, 22)
    fftw, scipy = _pair(shape, boundary).values()
    rng = np.random.default_rng(5)
    fields = [rng.random(shape) for _ in range(4)]
    kept = [fftw(f) for f in fields] + [fftw.inverse(f) for f in fields]
    expected = [scipy(f) for f in fields] + [scipy.inverse(f) for f in fields]
    for got, want in zip(kept, expected, strict=True):
        assert _relative(got, want) < 1e-12
        assert got.base is None or not np.shares_memory(got, kept[-1])
    assert len({id(k) for k in kept}) == len(kept)
    for a in range(len(kept)):
        for b in range(a + 1, len(kept)):
            assert not np.shares_memory(kept[a], kept[b])


@needs_fftw
def test_input_is_not_modified_and_padding_stays_zero():
    pair = RealFFT2((12, 18), input_shape=(6, 9), backend="fftw")
    kernel = np.random.default_rng(6).random(pair.spectrum_shape)
    reference = RealFFT2((12, 18), input_shape=(6, 9), backend="scipy")
    for seed in range(3):
        field = np.random.default_rng(seed).random((6, 9))
        copy = field.copy()
        out = pair.convolve(field, kernel)
        np.testing.assert_array_equal(field, copy)
        assert _relative(out, reference.convolve(field, kernel)) < 1e-12


@needs_fftw
def test_environment_variable_and_argument(monkeypatch):
    monkeypatch.setenv("ROUGHCONTACT_FFT", "scipy")
    assert fft_backend() == "scipy"
    assert SurfaceCompliance((8, 8), (1.0, 1.0), 1e9)._fft.backend == "scipy"
    assert fft_backend("fftw") == "fftw"
    monkeypatch.setenv("ROUGHCONTACT_FFT", "fftw")
    assert fft_backend() == "fftw"
    monkeypatch.delenv("ROUGHCONTACT_FFT")
    assert fft_backend() == "fftw"
    with pytest.raises(InputError, match="fft_backend"):
        fft_backend("mkl")
    with pytest.raises(InputError, match="field"):
        RealFFT2((8, 8), backend="fftw").convolve(np.zeros((8, 7)), np.ones((8, 5)))


def test_fallback_without_pyfftw(monkeypatch):
    monkeypatch.setattr(_backend, "pyfftw_module", lambda: None)
    monkeypatch.delenv("ROUGHCONTACT_FFT", raising=False)
    assert fft_backend() == "scipy"
    with pytest.raises(InputError, match="pyFFTW"):
        fft_backend("fftw")
    operator = SurfaceCompliance((10, 14), (1e-4, 1e-4), 1e9, boundary="free")
    assert operator._fft.backend == "scipy"
    field = np.random.default_rng(7).random((10, 14))
    spectrum = fft.rfft2(field, s=(20, 28)) * operator.kernel
    reference = fft.irfft2(spectrum, s=(20, 28))[:10, :14]
    assert _relative(operator(field), reference) < 1e-12


@needs_fftw
def test_solve_normal_same_pressure_with_both_backends(monkeypatch):
    surface = self_affine((64, 64), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=11)
    results = {}
    for backend in ("fftw", "scipy"):
        monkeypatch.setenv("ROUGHCONTACT_FFT", backend)
        operator = compliance_for(surface, 1e9)
        assert operator._fft.backend == backend
        results[backend] = solve_normal(surface, mean_pressure=5e6, tolerance=1e-12, compliance=operator)
    assert results["fftw"].iterations == results["scipy"].iterations
    assert _relative(results["fftw"].pressure, results["scipy"].pressure) < 1e-10


@needs_fftw
@pytest.mark.parametrize("boundary", ["periodic", "free"])
def test_measured_multithreaded_plans_agree(monkeypatch, boundary):
    """The large-grid configuration (FFTW_MEASURE, several threads), exercised on a small grid."""
    monkeypatch.setattr(_backend, "MEASURE_FROM", 1)
    monkeypatch.setattr(_backend, "THREADS_FROM", 1)
    operators = _pair((30, 45), boundary, workers=2)
    assert operators["fftw"]._fft.planner == "FFTW_MEASURE"
    field = np.random.default_rng(8).random((30, 45))
    for _ in range(2):
        assert _relative(operators["fftw"](field), operators["scipy"](field)) < 1e-12


@pytest.mark.parametrize("backend", ["fftw", "scipy"])
@pytest.mark.parametrize("boundary", ["periodic", "free"])
@pytest.mark.parametrize("shape", SHAPES)
def test_staged_operators_match_the_plain_calls(shape, boundary, backend):
    """K p in double precision exactly as ``__call__``; M f and f.K f in single precision within 1e-6.

    M is the inverse of the operator taken as periodic on the window, for either boundary.
    """
    if backend == "fftw" and _backend.pyfftw_module() is None:
        pytest.skip("pyFFTW does not import")
    size = (1e-4, 2.5e-4)
    operator = SurfaceCompliance(shape, size, 1e9, boundary=boundary, fft_backend=backend)
    periodic = SurfaceCompliance(shape, size, 1e9, boundary="periodic", fft_backend=backend)
    rng = np.random.default_rng(8)
    p, f = rng.random(shape), rng.standard_normal(shape)
    with operator.staged() as ops:
        assert ops.pressure.dtype == np.float64 and ops.approximate.dtype == np.float32
        assert ops.direction.dtype == np.float32
        ops.pressure[...] = p
        displacement = ops.displacement().copy()  # a view: operator(p) reuses the buffer
        ops.approximate[...] = f
        preconditioned = ops.precondition().copy()
        ops.direction[...] = f
        assert ops.quadratic_form() == pytest.approx(np.vdot(f, operator(f)), rel=1e-6, abs=0)
    assert _relative(displacement, operator(p)) < 1e-13
    assert _relative(preconditioned, periodic.inverse(f)) < 1e-6


@pytest.mark.parametrize("backend", ["fftw", "scipy"])
@pytest.mark.parametrize(
    "shape, input_shape", [((32, 32), None), ((24, 37), None), ((7, 1), None), ((24, 38), (12, 19))]
)
def test_parseval_quadratic_form_in_double_precision(shape, input_shape, backend):
    """sum w |rfft2 f|^2 = f . irfft2(K rfft2 f) to round-off, for even and odd widths and padded fields."""
    if backend == "fftw" and _backend.pyfftw_module() is None:
        pytest.skip("pyFFTW does not import")
    pair = RealFFT2(shape, input_shape=input_shape, backend=backend)
    rng = np.random.default_rng(9)
    kernel = rng.random(pair.spectrum_shape)
    kernel[:, 0] = kernel[::-1, 0][np.r_[-1, : shape[0] - 1]]  # K(q) = K(-q) on the self-conjugate column
    field = rng.standard_normal(pair.input_shape)
    weights = pair.quadratic_form_weights(kernel)
    with pair.staged() as staged:
        staged[...] = field
        power = pair.power_staged(weights)
    assert power == pytest.approx(np.vdot(field, pair.convolve(field, kernel)), rel=1e-12, abs=0)


def test_the_thread_variable_sets_the_default_fft_threads(monkeypatch):
    """ROUGHCONTACT_FFT_THREADS (set by the study runner for its Dask workers) is the default thread count."""
    THREADS_VARIABLE, resolve_workers = _backend.THREADS_VARIABLE, _backend.resolve_workers
    cores = os.cpu_count() or 1
    monkeypatch.delenv(THREADS_VARIABLE, raising=False)
    assert resolve_workers(None) == cores
    monkeypatch.setenv(THREADS_VARIABLE, "1")
    assert resolve_workers(None) == 1
    assert resolve_workers(3) == 3  # an explicit count wins
    monkeypatch.setenv(THREADS_VARIABLE, "all")
    with pytest.raises(InputError) as error:
        resolve_workers(None)
    assert error.value.field == THREADS_VARIABLE


def test_local_cluster_workers_share_the_cores():
    from roughcontact.study.run import _worker_threads

    cores = os.cpu_count() or 1
    for workers in (1, 2, cores, 4 * cores):
        env = _worker_threads(workers)
        assert int(env[_backend.THREADS_VARIABLE]) == max(cores // workers, 1) == int(env["OMP_NUM_THREADS"])


@needs_fftw
def test_measured_plans_keep_their_wisdom_in_a_file_for_the_next_process(monkeypatch, tmp_path):
    """A measured plan writes FFTW's wisdom to the file; another process (here: after FFTW forgot it)
    imports it from there."""
    import json
    import shutil

    monkeypatch.setenv(_fftw_wisdom.ENVIRONMENT_VARIABLE, str(tmp_path / "wisdom.json"))
    monkeypatch.setattr(_backend, "WISDOM_SAVED_FROM", 0.0)  # this small plan counts as measured
    transform = RealFFT2((48, 40), measure=True)
    field = np.random.default_rng(3).random((48, 40))
    kernel = np.ones(transform.spectrum_shape)
    assert np.allclose(transform.convolve(field, kernel), field, rtol=0, atol=1e-12)
    parts = json.loads((tmp_path / "wisdom.json").read_text())["wisdom"]
    assert len(parts) == 3 and parts[0]
    shutil.copy(tmp_path / "wisdom.json", tmp_path / "next.json")
    monkeypatch.setenv(_fftw_wisdom.ENVIRONMENT_VARIABLE, str(tmp_path / "next.json"))
    _backend.pyfftw_module().forget_wisdom()
    assert _fftw_wisdom.load(_backend.pyfftw_module())
    assert not _fftw_wisdom.load(_backend.pyfftw_module())  # once per process and path


@needs_fftw
@pytest.mark.parametrize("content", ["not json", '{"wisdom": ["%%%"]}', '{"other": 1}'])
def test_a_damaged_wisdom_file_only_costs_the_planning(monkeypatch, tmp_path, content):
    path = tmp_path / "wisdom.json"
    path.write_text(content)
    monkeypatch.setenv(_fftw_wisdom.ENVIRONMENT_VARIABLE, str(path))
    monkeypatch.setattr(_backend, "WISDOM_SAVED_FROM", 0.0)
    field = np.random.default_rng(4).random((30, 20))
    transform = RealFFT2((30, 20), measure=True)
    assert np.allclose(transform.convolve(field, np.ones(transform.spectrum_shape)), field, atol=1e-12)
    assert "wisdom" in path.read_text() and path.read_text() != content  # rewritten, whole


def test_wisdom_can_be_switched_off_and_an_unwritable_cache_is_no_error(monkeypatch, tmp_path):
    monkeypatch.setenv(_fftw_wisdom.ENVIRONMENT_VARIABLE, "off")
    assert _fftw_wisdom.wisdom_path() is None
    assert not _fftw_wisdom.save(_backend.pyfftw_module()) and not _fftw_wisdom.load(_backend.pyfftw_module())
    blocker = tmp_path / "a file"
    blocker.write_text("")
    monkeypatch.setenv(_fftw_wisdom.ENVIRONMENT_VARIABLE, str(blocker / "wisdom.json"))
    if _backend.pyfftw_module() is not None:
        assert not _fftw_wisdom.save(_backend.pyfftw_module())
    assert list(tmp_path.iterdir()) == [blocker]  # no temporary file left behind
    monkeypatch.delenv(_fftw_wisdom.ENVIRONMENT_VARIABLE)
    default = _fftw_wisdom.wisdom_path()
    assert default.parent.name == "roughcontact" and default.name.startswith("fftw-wisdom-")
