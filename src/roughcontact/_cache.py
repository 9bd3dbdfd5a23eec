"""Where roughcontact keeps what one process learns for the next: FFTW wisdom, converted files.

Everything lives under ``$XDG_CACHE_HOME/roughcontact`` (``~/.cache/roughcontact`` without
``XDG_CACHE_HOME``), the XDG base directory convention for data that may be deleted at any time
at the cost of recomputing it. Each kind of cache also has an environment variable that gives
another path, or switches it off.
"""

from __future__ import annotations

import os
from pathlib import Path

OFF = ("", "off", "0", "no")
"""Values of a cache's environment variable that switch it off (case-insensitive)."""


def cache_root() -> Path:
    """Return roughcontact's cache folder: ``$XDG_CACHE_HOME/roughcontact`` (default ``~/.cache``)."""
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "roughcontact"


def cache_path(variable: str, name: str) -> Path | None:
    """Return a cache's path: the environment ``variable``'s, else ``name`` in :func:`cache_root`.

    None when the variable says off (:data:`OFF`): the cache is not kept on disk.
    """
    value = os.environ.get(variable)
    if value is None:
        return cache_root() / name
    value = value.strip()
    return None if value.lower() in OFF else Path(value).expanduser()
