"""Converted copies of instrument files: each file is parsed once, later reads take its copy.

Reading an instrument file goes through SurfaceTopography, whose import alone takes about a
second, and through the file's parser. :func:`roughcontact.topography.io.read_scan` keeps what it
made of a file (the heights as stored, NaN where undefined, in metres; the size; whether it is
periodic; its ``info``), and :func:`~roughcontact.topography.io.list_channels` the file's list of
channels, in ``$XDG_CACHE_HOME/roughcontact/files/`` (``~/.cache`` without
``XDG_CACHE_HOME``), and serves a later read of the same file with the same options from there,
in any process, without loading the readers.

The key of a copy is a BLAKE2b hash of

* the file's bytes: a file that changes has another key, and its old copy is never found again
  (it ages out, below);
* the file's path, as given (the ``info`` names it so) and resolved;
* every option of ``read_scan`` (channel, size, height unit, ``periodic``, ``treat_as_height``,
  ``override_file_values``);
* the readers' versions: roughcontact's, :data:`roughcontact.topography.io.READER_VERSION`
  (raised whenever ``read_scan`` makes something else of the same file) and SurfaceTopography's,
  and this module's :data:`FORMAT`.

A copy is ``KEY.json`` (size, periodicity and ``info``, or the channel list of
:func:`~roughcontact.topography.io.list_channels`, written as the native format writes ``info``,
tuples kept: :func:`~roughcontact.topography.native.encode_info`; and the heights' shape and
dtype) and ``KEY.npy`` (the heights, numpy's format, read without pickle).
Each is written through a temporary file renamed into place, the ``.json`` last, so a copy is
whole once its ``.json`` exists, also with several processes reading the same file at once. A
copy that does not load or does not match its ``.json`` counts as absent and is written again.
Only successful reads are kept: a file that is refused is refused again, by its reader. A
cache folder that cannot be written costs the next read its time, nothing else. A successful
read says nothing a copy would have to repeat: roughcontact's readers warn of nothing, and
SurfaceTopography's readers (and igor2, h5py under them) only log at debug level (how many header
rows a text reader skipped, how a binary header was parsed), so a read from a copy is as quiet. It
logs ``read NAME (scan) from its converted copy PATH`` at info level (``roughcontact -v`` shows it).

The folder is bounded: after each write, the copies used least recently are removed until it
holds at most :data:`LIMIT` bytes (a copy that is used is touched). Delete the folder to clear it.
The environment variable ``ROUGHCONTACT_FILE_CACHE`` gives another folder, or ``off`` (also
``0``, ``no`` or empty) to read every file afresh.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import logging
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from .._cache import cache_path
from .._files import replacing
from .._version import __version__
from ..errors import InputError
from .native import decode_info, encode_info

ENVIRONMENT_VARIABLE = "ROUGHCONTACT_FILE_CACHE"
"""The folder of the converted copies, or ``off`` for none."""

FORMAT = 1
"""Version of the copies' layout (raised when it changes, so old copies are not read)."""

LIMIT = 512 * 2**20
"""Largest size [bytes] of the folder; the copies used least recently are removed beyond it."""

_CHUNK = 1 << 20

logger = logging.getLogger(__name__)


def cache_folder() -> Path | None:
    """Return the folder of the converted copies, or None when ``ROUGHCONTACT_FILE_CACHE`` is off."""
    return cache_path(ENVIRONMENT_VARIABLE, "files")


def _surfacetopography_version() -> str:
    """Return SurfaceTopography's installed version, read from its metadata (not imported)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("SurfaceTopography")
    except PackageNotFoundError:  # pragma: no cover - a declared dependency
        return "none"


class ConvertedCopy:
    """The converted copy of one file: what a reading made of it, to load or to store.

    Parameters
    ----------
    path : Path
        The instrument file (existing).
    what : str
        What the reading made: ``"scan"`` (:func:`~roughcontact.topography.io.read_scan`) or
        ``"channels"`` (:func:`~roughcontact.topography.io.list_channels`); part of the key.
    options : mapping
        The options of the reading (JSON-ready values: str, numbers, bools, None, lists).
    reader_version : int
        :data:`roughcontact.topography.io.READER_VERSION`.
    folder : Path, optional
        The cache folder (default :func:`cache_folder`; None there: no copy is kept).
    """

    def __init__(
        self,
        path: Path,
        what: str,
        options: Mapping[str, Any],
        reader_version: int,
        folder: Path | None = None,
    ):
        self.folder = cache_folder() if folder is None else folder
        self.what = what
        self.given = str(path)  # as the info names it
        self.path = Path(path).resolve()
        self.key = None if self.folder is None else self._key(what, options, reader_version)

    def _key(self, what: str, options: Mapping[str, Any], reader_version: int) -> str:
        digest = hashlib.blake2b(digest_size=20)
        said = [FORMAT, reader_version, __version__, _surfacetopography_version(), what, self.given]
        digest.update(
            json.dumps([*said, str(self.path), dict(sorted(options.items()))], default=repr).encode()
        )
        with self.path.open("rb") as stream:
            while chunk := stream.read(_CHUNK):
                digest.update(chunk)
        return digest.hexdigest()

    def _files(self) -> tuple[Path, Path]:
        return self.folder / f"{self.key}.npy", self.folder / f"{self.key}.json"

    def load(self, *keys: str) -> tuple[dict[str, Any], np.ndarray | None] | None:
        """Return the copy's record and its heights (None if it has none); None where there is no copy.

        A damaged or partial copy is None too, as is a record without each of ``keys`` (the keys
        the reading stores): it is written again after the next reading.
        """
        if self.key is None:
            return None
        heights_file, record_file = self._files()
        try:
            stored = json.loads(record_file.read_text())
            heights = None
            if stored["heights"] is not None:
                heights = np.load(heights_file, allow_pickle=False)
                if [list(heights.shape), str(heights.dtype)] != stored["heights"]:
                    return None
            record = decode_info(stored["record"])
        except (OSError, EOFError, ValueError, KeyError, TypeError):  # EOFError: an empty .npy
            return None
        if not isinstance(record, dict) or not set(keys) <= record.keys():
            return None
        for file in (heights_file, record_file):  # used now: the last to be pruned
            with contextlib.suppress(OSError):
                os.utime(file)
        logger.info("read %s (%s) from its converted copy %s", Path(self.given).name, self.what, record_file)
        return record, heights

    def store(self, record: Mapping[str, Any], heights: np.ndarray | None = None) -> None:
        """Keep what a reading made: a ``record`` and the heights, if any.

        The record holds str keys and str, numbers, None, tuples, lists and dicts. Nothing is kept
        when the cache is off or cannot be written.
        """
        if self.key is None:
            return
        heights_file, record_file = self._files()
        try:
            stored = {
                "file": self.given,
                "heights": None if heights is None else [list(heights.shape), str(heights.dtype)],
                "record": encode_info(record),
            }
            self.folder.mkdir(parents=True, exist_ok=True)
            if heights is not None:
                with replacing(heights_file) as temporary, temporary.open("wb") as stream:
                    np.save(stream, heights, allow_pickle=False)
            with replacing(record_file) as temporary:
                temporary.write_text(json.dumps(stored))
            prune(self.folder)
        except (OSError, InputError) as error:  # a read-only or full disk, a record the copy cannot hold
            logger.debug("no converted copy of %s kept in %s: %s", self.path.name, self.folder, error)


def prune(folder: Path, limit: int | None = None) -> int:
    """Remove the copies used least recently until ``folder`` holds at most ``limit`` bytes; return how many.

    ``limit`` defaults to :data:`LIMIT` (read at the call). A copy's two files go together; files
    that are not copies (other names, the temporary files of writes under way) are left alone.
    """
    limit = LIMIT if limit is None else limit
    copies: dict[str, list[Path]] = {}
    for file in folder.iterdir():
        if file.suffix in (".npy", ".json") and not file.name.startswith("."):
            copies.setdefault(file.stem, []).append(file)

    def stat(file: Path) -> tuple[float, int]:
        try:
            found = file.stat()
        except OSError:  # removed by another process meanwhile
            return 0.0, 0
        return found.st_mtime, found.st_size

    sizes = {key: [stat(file) for file in files] for key, files in copies.items()}
    total = sum(size for stats in sizes.values() for _, size in stats)
    removed = 0
    for key in sorted(copies, key=lambda key: max(time for time, _ in sizes[key])):
        if total <= limit:
            break
        for file in sorted(copies[key], key=lambda file: file.suffix != ".json"):  # its record first
            file.unlink(missing_ok=True)
        total -= sum(size for _, size in sizes[key])
        removed += 1
    return removed
