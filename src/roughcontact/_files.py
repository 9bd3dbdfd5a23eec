"""Files: checking that an input file is there, writing an output whole or not at all.

:func:`replacing` (a temporary file beside the target, renamed into place) is used by the native
topography format (:mod:`roughcontact.topography.native`) and by the study store
(:mod:`roughcontact.study.store`); :func:`existing_file` and :func:`first_line` by the topography
readers (:mod:`roughcontact.topography.io`, :mod:`roughcontact.topography.native`). Imports nothing
heavy.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from .errors import UnsupportedFormatError


def _process_umask() -> int:
    """Return the process' umask, read from /proc where Linux has it, else set back at once."""
    with contextlib.suppress(OSError, ValueError):
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("Umask:"):
                return int(line.split()[1], 8)
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


_FILE_MODE = 0o666 & ~_process_umask()
"""Mode of the files written: what ``open()`` would give under the user's umask (0644 under 022).
Read once, at import, in the main thread (changing the umask to read it is not thread-safe)."""


@contextlib.contextmanager
def replacing(path: Path) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it into place on success, remove it on failure.

    So a killed or failed write leaves either the whole file or none (a ``.NAME.*.part`` leftover
    of a killed process can be recognised by its name). The folder is created if it is missing.
    The file gets the mode the user's umask gives (``mkstemp`` alone would make it owner-only).
    """
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".part")
    os.fchmod(handle, _FILE_MODE)
    os.close(handle)
    try:
        yield Path(temporary)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def existing_file(path: str | os.PathLike, *, empty_fix: str) -> Path:
    """Return ``path`` as a Path, refusing what is not a readable non-empty file.

    Parameters
    ----------
    path : str or path-like
        The input file.
    empty_fix : str
        The fix offered for an empty (0 bytes) file.

    Raises
    ------
    UnsupportedFormatError
        No such file, a folder, or an empty file; the field is the path.
    """
    path = Path(path)
    if not path.exists():
        raise UnsupportedFormatError(str(path), "no such file.", "check the path and the file name.")
    if path.is_dir():
        raise UnsupportedFormatError(
            str(path), "is a folder, not a file.", "give the path of one topography file inside it."
        )
    if path.stat().st_size == 0:
        raise UnsupportedFormatError(str(path), "the file is empty (0 bytes).", empty_fix)
    return path


def not_a_folder(path: Path) -> str | None:
    """Say why ``path`` cannot be an output folder (it or a folder above it is a file); None if it can."""
    for place in (path, *path.parents):
        if place.exists() and not place.is_dir():
            where = "is" if place == path else f"is inside {place}, which is"
            return f"{path} {where} a file, not a folder."
    return None


def read_text(path: Path, *, holds: str, utf8_only: bool = False) -> str:
    """Return a text file's content; refuse a binary file (an instrument file given as a table, say).

    UTF-8 (with or without a byte-order mark); else Latin-1, which an old export may use for its
    ``µ``, unless ``utf8_only`` (TOML is UTF-8 by definition).

    Parameters
    ----------
    path : Path
    holds : str
        What the file should hold, for the fix (``"a study file (TOML)"``).
    utf8_only : bool

    Raises
    ------
    UnsupportedFormatError
        A file with NUL bytes or, with ``utf8_only``, one that is not UTF-8; the field is the path.
    """
    content = Path(path).read_bytes()
    if b"\x00" in content:
        raise UnsupportedFormatError(str(path), "is a binary file, not text.", f"give {holds}.")
    try:
        return content.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        if utf8_only:
            raise UnsupportedFormatError(
                str(path),
                f"is not UTF-8 text (byte {error.start} is {content[error.start]:#04x}).",
                f"give {holds}.",
            ) from None
        return content.decode("latin-1")


def first_line(error: BaseException, limit: int = 160) -> str:
    """Return the first line of an exception's text (its type name if it has none), cut to ``limit``."""
    text = str(error).strip().splitlines()
    line = text[0].strip() if text else type(error).__name__
    return line if len(line) <= limit else line[: limit - 3] + "..."
