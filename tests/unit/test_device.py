"""The device switch on a machine without a GPU: clear refusals, and nothing GPU-related imported."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

from roughcontact._device import DEVICE_VARIABLE, check_storage, resolve_device
from roughcontact.contact import solve_normal
from roughcontact.errors import InputError
from roughcontact.topography import Topography


def _has_cupy() -> bool:
    try:
        import cupy  # noqa: F401
    except ImportError:
        return False
    return True


def _surface():
    heights = np.random.default_rng(0).standard_normal((32, 32)) * 1e-9
    return Topography(heights, (1e-6, 1e-6), periodic=True)


def test_unknown_device_is_refused_with_the_choices(monkeypatch):
    with pytest.raises(InputError, match="unknown device 'tpu'") as error:
        resolve_device("tpu")
    assert error.value.field == "device"
    monkeypatch.setenv(DEVICE_VARIABLE, "fpga")
    with pytest.raises(InputError, match=DEVICE_VARIABLE):
        solve_normal(_surface(), 1e9, mean_pressure=1e6)


def test_cpu_is_the_default_and_the_variable_is_read(monkeypatch):
    monkeypatch.delenv(DEVICE_VARIABLE, raising=False)
    assert resolve_device(None) == "cpu"
    monkeypatch.setenv(DEVICE_VARIABLE, " CPU ")
    assert resolve_device(None) == "cpu"


@pytest.mark.skipif(_has_cupy(), reason="CuPy imports here")
def test_gpu_without_cupy_names_the_extra():
    with pytest.raises(InputError, match=r"roughcontact\[gpu\]") as error:
        solve_normal(_surface(), 1e9, mean_pressure=1e6, device="gpu")
    assert "CuPy" in error.value.problem
    assert "--device" in error.value.text("cli")


def test_single_precision_is_a_gpu_option():
    with pytest.raises(InputError, match="GPU option"):
        check_storage("single", "cpu")
    with pytest.raises(InputError, match="unknown precision"):
        check_storage("half", "gpu")
    with pytest.raises(InputError, match="GPU option"):
        solve_normal(_surface(), 1e9, mean_pressure=1e6, precision="single")


def test_a_cpu_solve_imports_nothing_of_the_gpu():
    code = textwrap.dedent(
        """
        import sys
        import numpy as np
        from roughcontact.contact import solve_normal
        from roughcontact.topography import Topography
        t = Topography(np.random.default_rng(0).standard_normal((64, 64)) * 1e-9, (1e-6, 1e-6), periodic=True)
        solve_normal(t, 1e9, mean_pressure=1e6)
        leaked = [m for m in sys.modules if m.startswith("cupy") or m.endswith(("_gpu", "_cg_kernels_gpu"))]
        print(leaked)
        """
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


@pytest.mark.skipif(_has_cupy(), reason="CuPy imports here")
def test_study_on_the_gpu_is_refused_at_validation(tmp_path):
    from roughcontact.study import StudyError
    from roughcontact.study.config import build_study

    document = {
        "study": {"name": "g", "device": "gpu"},
        "topographies": {"s": {"generate": "self_affine", "shape": [32, 32], "size": ["1 um", "1 um"],
                               "hurst": 0.8, "rms_height": "1 nm", "seed": 1}},
        "analysis": [{"name": "c", "model": "normal", "topography": "s", "material": "SiO2",
                      "mean_pressure": "1 MPa"}],
    }  # fmt: skip
    with pytest.raises(StudyError, match=r"roughcontact\[gpu\]"):
        build_study(document, folder=tmp_path, text="", source="test")


def test_cli_contact_gpu_without_cupy_is_a_clear_error(tmp_path, capsys):
    if _has_cupy():
        pytest.skip("CuPy imports here")
    from roughcontact.cli import main

    heights = tmp_path / "s.txt"
    np.savetxt(heights, np.random.default_rng(1).standard_normal((32, 32)))
    code = main(
        ["contact", str(heights), "--size", "1 um", "--height-unit", "nm", "--material", "SiO2",
         "--pressure", "1 MPa", "--device", "gpu"]
    )  # fmt: skip
    assert code != 0
    err = capsys.readouterr().err
    assert "CuPy" in err and "--device" in err


def test_cli_run_gpu_without_cupy_stops_before_any_case(tmp_path, capsys):
    if _has_cupy():
        pytest.skip("CuPy imports here")
    from roughcontact.cli import main

    study = tmp_path / "s.toml"
    study.write_text(
        '[study]\nname = "g"\n[topographies.s]\ngenerate = "self_affine"\nshape = [32, 32]\n'
        'size = ["1 um", "1 um"]\nhurst = 0.8\nrms_height = "1 nm"\nseed = 1\n'
        '[[analysis]]\nname = "c"\nmodel = "normal"\ntopography = "s"\nmaterial = "SiO2"\n'
        'mean_pressure = "1 MPa"\n'
    )
    code = main(["run", str(study), "-o", str(tmp_path / "out"), "--device", "gpu"])
    assert code != 0
    assert "CuPy" in capsys.readouterr().err
    assert not (tmp_path / "out" / "results.csv").exists()
