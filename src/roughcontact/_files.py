"""Writing files whole or not at all: a temporary file beside the target, renamed into place.

Used by the native topography format (:mod:`roughcontact.topography.io`) and by the study store
(:mod:`roughcontact.study.store`). Imports nothing heavy.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path


@contextlib.contextmanager
def replacing(path: Path) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it into place on success, remove it on failure.

    So a killed or failed write leaves either the whole file or none (a ``.NAME.*.part`` leftover
    of a killed process can be recognised by its name). The folder is created if it is missing.
    """
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".part")
    os.close(handle)
    try:
        yield Path(temporary)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
