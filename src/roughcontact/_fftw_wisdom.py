"""FFTW wisdom kept on disk: a measured plan is made once per machine and grid, not once per process.

FFTW's measured plans (``FFTW_MEASURE``, used from :data:`roughcontact._backend.MEASURE_FROM`
points) time trial transforms: about 1 s per plan at 1024^2 and 3 s at 2048^2, and a free
768 x 576 confocal scan's solve plans for about 5 s before a 2.5 s solve. FFTW remembers what it
learnt (its *wisdom*) for the life of the process; this module keeps it in a file, so that the
next process (the next ``roughcontact contact`` or study run, a Dask worker) plans from it in
milliseconds (Frigo and Johnson 2005, sec. "wisdom").

The file is ``$XDG_CACHE_HOME/roughcontact/fftw-wisdom-<machine>.json`` (``~/.cache`` without
``XDG_CACHE_HOME``), one per processor model and pyFFTW version, since wisdom describes what was
fastest on one machine. The environment variable ``ROUGHCONTACT_FFTW_WISDOM`` gives another path,
or ``off`` to keep wisdom in memory only. A file that cannot be read, parsed or written only costs
the planning time: it is ignored, and rewritten after the next measured plan. Writes go to a
temporary file renamed into place, so processes planning at once never leave a torn file.
"""

from __future__ import annotations

import base64
import functools
import hashlib
import json
import os
import platform
import tempfile
from pathlib import Path

from ._cache import cache_path

ENVIRONMENT_VARIABLE = "ROUGHCONTACT_FFTW_WISDOM"
"""Path of the wisdom file, or ``off`` (also ``0``, ``no`` or empty) for none."""

_loaded: set[Path] = set()


def wisdom_path() -> Path | None:
    """Return the wisdom file of this machine, or None when it is switched off (module docstring)."""
    return cache_path(ENVIRONMENT_VARIABLE, f"fftw-wisdom-{_machine_key()}.json")


@functools.cache
def _machine_key() -> str:
    """Return a short hash of the processor model, the architecture and the pyFFTW version (read once)."""
    model = platform.processor()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        from importlib.metadata import version

        pyfftw_version = version("pyFFTW")
    except Exception:  # pragma: no cover - metadata missing
        pyfftw_version = "unknown"
    text = f"{platform.machine()}|{model}|{pyfftw_version}"
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def load(pyfftw) -> bool:
    """Give FFTW the wisdom of the file, once per process and path; return whether any was imported."""
    path = wisdom_path()
    if path is None or path in _loaded:
        return False
    _loaded.add(path)
    try:
        parts = json.loads(path.read_text())["wisdom"]
        wisdom = tuple(base64.b64decode(part, validate=True) for part in parts)
        if len(wisdom) != len(pyfftw.export_wisdom()):  # double, single, long double
            return False
        return bool(any(pyfftw.import_wisdom(wisdom)))
    except (OSError, ValueError, KeyError, TypeError, IndexError):  # missing or damaged: plan afresh
        return False


def save(pyfftw) -> bool:
    """Write FFTW's current wisdom (what it loaded and what it learnt since) to the file.

    Returns whether it was written; an unwritable cache (read-only home) is not an error.
    """
    path = wisdom_path()
    if path is None:
        return False
    text = json.dumps({"wisdom": [base64.b64encode(part).decode() for part in pyfftw.export_wisdom()]})
    temporary = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile("w", dir=path.parent, delete=False, suffix=".tmp") as handle:
            temporary = handle.name
            handle.write(text)
        os.replace(temporary, path)
    except OSError:
        if temporary is not None:
            Path(temporary).unlink(missing_ok=True)
        return False
    _loaded.add(path)
    return True
