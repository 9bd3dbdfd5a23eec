"""Where the contact engines run: the device switch and the array module of each device.

The CPU (numpy, numba, FFTW) is the default and the only requirement. ``device="gpu"`` (Python),
``--device gpu`` (command line), ``[study] device = "gpu"`` (study file) or the environment variable
:data:`DEVICE_VARIABLE` move the normal contact solver onto a CUDA GPU through CuPy, the optional
``roughcontact[gpu]`` extra: :func:`gpu_module` is the one place that imports it
(:mod:`roughcontact._gpu`), so nothing GPU-related is loaded unless a GPU is asked for.
"""

from __future__ import annotations

import os
import sys

import numpy as np

from .errors import InputError

DEVICES = ("cpu", "gpu")
"""Where the contact engines run: numpy on the CPU (the default and the only requirement), or CuPy
on a CUDA GPU (the optional ``roughcontact[gpu]`` extra, :mod:`roughcontact._gpu`)."""
DEVICE_VARIABLE = "ROUGHCONTACT_DEVICE"
"""Environment variable with the default device (``cpu`` or ``gpu``)."""
STORAGE = ("double", "single")
"""Storage precision of the engine's fields: float64, or float32 (GPU only) with float64 sums."""


def resolve_device(device: str | None = None) -> str:
    """Return the device that ``device`` selects, ``"cpu"`` or ``"gpu"``, checking that a GPU is there.

    Parameters
    ----------
    device : {"cpu", "gpu"}, optional
        ``None``: the environment variable :data:`DEVICE_VARIABLE`, else ``"cpu"``.

    Raises
    ------
    InputError
        An unknown device, or ``"gpu"`` where CuPy does not import or sees no GPU (the fix
        names the extra to install, or ``device="cpu"``).
    """
    if device is None:
        device = os.environ.get(DEVICE_VARIABLE, "cpu").strip().lower() or "cpu"
    if device not in DEVICES:
        raise InputError(
            "device",
            f"unknown device {device!r}.",
            f"use «device=cpu» or «device=gpu» (or unset {DEVICE_VARIABLE}).",
        )
    if device == "gpu":
        gpu_module()
    return device


def check_storage(storage: str, device: str) -> str:
    """Return ``storage`` (one of :data:`STORAGE`), refusing single precision on the CPU."""
    if storage not in STORAGE:
        raise InputError("precision", f"unknown precision {storage!r}.", f"use one of {STORAGE}.")
    if storage == "single" and device != "gpu":
        raise InputError(
            "precision",
            "single-precision fields are a GPU option (they halve the memory of the largest grids).",
            "use precision='double' on the CPU, or device='gpu'.",
        )
    return storage


def gpu_module():
    """Return :mod:`roughcontact._gpu` (CuPy and the device kernels), imported on first use.

    Raises
    ------
    InputError
        CuPy does not import, or it finds no CUDA device.
    """
    try:
        from . import _gpu
    except ImportError as error:
        raise InputError(
            "device",
            f"device 'gpu' needs CuPy, which does not import ({error}).",
            "pip install 'roughcontact[gpu]' (CuPy for CUDA 12; 'roughcontact[gpu-cuda13]' for CUDA 13), "
            "or use «device=cpu».",
        ) from error
    _gpu.check_device()
    return _gpu


def on_gpu(array) -> bool:
    """Whether ``array`` is a CuPy array (without importing CuPy)."""
    return type(array).__module__.startswith("cupy")


def namespace(array):
    """Return the array module of ``array``: numpy, or cupy for an array on the GPU."""
    return sys.modules["cupy"] if on_gpu(array) else np


def to_host(array) -> np.ndarray:
    """Return ``array`` as a numpy array (copied from the GPU when it lives there)."""
    return array.get() if on_gpu(array) else np.asarray(array)
