"""The version of roughcontact, and the identity of the code that is running.

``__version__`` is the installed package's version (``0+unknown`` in a source tree that is not
installed). It stays the same across the commits of a development checkout, so a stored result
cannot be matched to the code that computed it by the version alone: :func:`code_identity` adds a
fingerprint of the package's source files (a SHA-256 over their paths and contents, computed once
per process, about 10 ms) and, in a git checkout, the commit. The study runner stores it with every
case and recomputes a case whose fingerprint is not the running code's.
"""

from __future__ import annotations

import functools
import hashlib
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

try:
    __version__ = version("roughcontact")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

_PACKAGE = Path(__file__).resolve().parent


@functools.cache
def code_fingerprint() -> str:
    """Return a SHA-256 (16 hex digits) of the package's ``.py`` files: their relative paths and contents."""
    digest = hashlib.sha256()
    for path in sorted(_PACKAGE.rglob("*.py")):
        digest.update(path.relative_to(_PACKAGE).as_posix().encode())
        digest.update(b"\0")
        digest.update(path.read_bytes())
        digest.update(b"\0")
    return digest.hexdigest()[:16]


def _git_commit() -> str | None:
    """Return the commit of the git checkout the package lives in (read from .git), else None."""
    for folder in _PACKAGE.parents:
        git = folder / ".git"
        if git.is_dir():
            try:
                head = (git / "HEAD").read_text().strip()
                if head.startswith("ref: "):
                    ref = git / head[5:]
                    if ref.is_file():
                        return ref.read_text().strip()[:12]
                    packed = git / "packed-refs"
                    for line in packed.read_text().splitlines() if packed.is_file() else ():
                        if line.endswith(" " + head[5:]):
                            return line.split()[0][:12]
                    return None
                return head[:12]
            except OSError:
                return None
    return None


@functools.cache
def code_identity() -> dict[str, str | None]:
    """Return ``{"version", "fingerprint", "commit"}`` of the running code (commit None outside git)."""
    return {"version": __version__, "fingerprint": code_fingerprint(), "commit": _git_commit()}
