"""roughcontact's own topography format: a NetCDF-4 file that round-trips a Topography exactly.

The file (HDF5, written with the ``h5netcdf`` engine) holds the heights [m] as float64 on
coordinates ``x`` (and ``y``) [m], and as attributes the physical size [m], the periodic flag,
the metadata ``info`` as JSON and a format marker (:data:`NATIVE_FORMAT`) with a version
(:data:`NATIVE_VERSION`). :func:`save_topography` writes it atomically, :func:`load_topography`
reads it back exactly as saved; :func:`is_native_file` and :func:`read_native` let
:func:`roughcontact.topography.io.read_topography` read it beside the instrument formats.
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from .._files import existing_file, first_line, replacing
from ..errors import InputError, UnsupportedFormatError
from .surface import Topography, topography_argument

__all__ = [
    "NATIVE_FORMAT",
    "NATIVE_VERSION",
    "channel_name",
    "is_native_file",
    "load_topography",
    "read_native",
    "save_topography",
]

NATIVE_FORMAT = "roughcontact-topography"
"""Value of the ``format`` attribute that marks a roughcontact topography file."""
NATIVE_VERSION = 1
"""Version of the format written (``format_version`` attribute); the only one read."""

_HDF5_MAGIC = b"\x89HDF\r\n\x1a\n"
_MASKS = {
    "filled": "1 where the height was interpolated, not measured",
    "specks": "1 at measured points standing alone amid undefined ones",
}
"""The masks of a topography kept beside its heights when it has them (optional variables)."""

_TUPLE_TAG = "__tuple__"  # JSON has no tuples: {"__tuple__": [...]} keeps info round trips exact
_DEFAULT_CHANNEL = "heights"
_EMPTY_FIX = "write the file again with save_topography()."

PathLike = str | os.PathLike


def save_topography(topography: Topography, path: PathLike) -> None:
    """Write a topography to roughcontact's own NetCDF format, atomically.

    The file holds ``heights`` [m] (float64) on coordinates ``x`` (and ``y``) [m] at the grid
    points ``i * spacing``, and attributes ``format = "roughcontact-topography"``,
    ``format_version = 1``, ``size`` [m], ``periodic`` (0 or 1) and ``info`` (JSON; tuples are
    written as ``{"__tuple__": [...]}`` so that they come back as tuples). The file is written
    under a temporary name in the target folder and renamed into place
    (:func:`roughcontact._files.replacing`), so a failed write leaves no partial file and an
    existing file intact.

    Parameters
    ----------
    topography : Topography
        Surface to save; its ``info`` must hold only str, numbers, None, lists, tuples and dicts
        with str keys.
    path : str or path-like
        Output file, conventionally ending in ``.nc``.

    Raises
    ------
    InputError
        Not a Topography, info that JSON cannot hold exactly, a missing or unwritable folder.
    """
    topography = topography_argument(topography, "topography")
    import xarray as xr

    if not isinstance(topography, Topography):
        raise InputError(
            "topography",
            f"expected a Topography, got {type(topography).__name__}.",
            "read or generate a Topography first.",
        )
    path = Path(path)
    dims = ("x", "y")[: topography.dim]
    coordinates = {d: (d, c, {"units": "m"}) for d, c in zip(dims, topography.coordinates(), strict=True)}
    heights = (dims, np.asarray(topography.heights, dtype=np.float64), {"units": "m", "long_name": "height"})
    dataset = xr.Dataset(
        {"heights": heights},
        coords=coordinates,
        attrs={
            "format": NATIVE_FORMAT,
            "format_version": NATIVE_VERSION,
            "size": list(topography.size),
            "size_units": "m",
            "periodic": int(topography.periodic),
            "info": encode_info(topography.info),
        },
    )
    masks = {
        name: (dims, getattr(topography, name).astype(np.uint8), {"long_name": meaning})
        for name, meaning in _MASKS.items()
        if getattr(topography, name) is not None
    }
    dataset = dataset.assign(masks)
    encoding = {name: {"_FillValue": None} for name in (*dims, "heights", *masks)}
    _write_atomically(dataset, path, encoding)


def load_topography(path: PathLike) -> Topography:
    """Load a topography written by :func:`save_topography`, exactly as it was saved.

    Parameters
    ----------
    path : str or path-like
        A roughcontact ``.nc`` file.

    Returns
    -------
    Topography
        Heights [m], size [m], periodic flag and info as saved.

    Raises
    ------
    UnsupportedFormatError
        A missing or empty file, a file that is not NetCDF, a NetCDF file without the roughcontact
        format marker, or one written by a newer format version.
    """
    import xarray as xr

    path = existing_file(path, empty_fix=_EMPTY_FIX)
    try:
        with xr.open_dataset(path, engine="h5netcdf") as dataset:
            dataset.load()
    except Exception as error:  # any failure of the HDF5 stack means the same to the user
        raise UnsupportedFormatError(
            str(path),
            f"cannot be opened as a NetCDF file ({first_line(error)}).",
            "load .nc files written by save_topography(); read instrument files with read_topography().",
        ) from error
    attrs = dataset.attrs
    if attrs.get("format") != NATIVE_FORMAT or "heights" not in dataset:
        raise UnsupportedFormatError(
            str(path),
            f"is NetCDF but not a roughcontact topography (no format marker {NATIVE_FORMAT!r}).",
            "read instrument files with read_topography(); write this format with save_topography().",
        )
    version = attrs.get("format_version")
    if version != NATIVE_VERSION:
        raise UnsupportedFormatError(
            str(path),
            f"has format version {version}; this roughcontact reads version {NATIVE_VERSION}.",
            "open it with the roughcontact version that wrote it.",
        )
    size = tuple(float(s) for s in np.atleast_1d(attrs["size"]))
    masks = {name: dataset[name].values.astype(bool) for name in _MASKS if name in dataset}
    return Topography(
        dataset["heights"].values,
        size,
        periodic=bool(attrs["periodic"]),
        info=decode_info(attrs["info"]),
        **masks,
    )


def is_native_file(path: PathLike) -> bool:
    """Whether ``path`` is an HDF5 file carrying roughcontact's format marker.

    Reads only the file's signature and attributes; a damaged HDF5 file counts as not native
    (it is left to the instrument readers, which report it).
    """
    path = Path(path)
    with path.open("rb") as stream:
        if stream.read(len(_HDF5_MAGIC)) != _HDF5_MAGIC:
            return False
    import h5netcdf  # only for an HDF5 file (an instrument file's read does not load it)

    try:
        with h5netcdf.File(path, "r") as handle:
            return handle.attrs.get("format") == NATIVE_FORMAT
    except Exception:  # a damaged HDF5 file is left to SurfaceTopography, which reports it
        return False


def channel_name(topography: Topography) -> str:
    """Name of the single channel of a roughcontact file: the ``channel`` it was read from, else "heights"."""
    return str(topography.info.get("channel", _DEFAULT_CHANNEL))


def read_native(path: PathLike, *, channel: int | str | None = None) -> Topography:
    """Load a roughcontact ``.nc`` file as :func:`roughcontact.topography.io.read_topography` reads it.

    Parameters
    ----------
    path : str or path-like
        A roughcontact ``.nc`` file.
    channel : int or str, optional
        The file's single channel: None, 0 or its name (:func:`channel_name`).

    Returns
    -------
    Topography
        As :func:`load_topography` returns it.

    Raises
    ------
    UnsupportedFormatError
        As :func:`load_topography`.
    InputError
        Any other channel.
    """
    path = Path(path)
    topography = load_topography(path)
    if channel not in (None, 0, channel_name(topography)):
        raise InputError(
            "channel", f"{path.name} is a roughcontact file with a single channel.", "leave channel out."
        )
    return topography


# --- info encoding and the atomic write ----------------------------------------------------------


def encode_info(info: Mapping[str, Any]) -> str:
    """Return ``info`` as JSON, tuples tagged so that they are restored as tuples."""

    def encode(value: Any, where: str) -> Any:
        if isinstance(value, Mapping):
            for key in value:
                if not isinstance(key, str):
                    raise InputError(
                        "topography.info", f"key {key!r} in {where} is not a string.", "use str keys in info."
                    )
            return {k: encode(v, f"{where}[{k!r}]") for k, v in value.items()}
        if isinstance(value, tuple):
            return {_TUPLE_TAG: [encode(v, where) for v in value]}
        if isinstance(value, list):
            return [encode(v, where) for v in value]
        if isinstance(value, np.generic):
            return value.item()
        if value is None or isinstance(value, str | bool | int | float):
            return value
        raise InputError(
            "topography.info",
            f"{where} holds a {type(value).__name__}, which the .nc format cannot store.",
            "keep info to str, numbers, None, lists, tuples and dicts with str keys.",
        )

    return json.dumps(encode(dict(info), "info"))


def decode_info(text: str) -> dict[str, Any]:
    """Return the ``info`` that :func:`encode_info` wrote, its tuples restored as tuples."""

    def restore(mapping: dict) -> Any:
        return tuple(mapping[_TUPLE_TAG]) if mapping.keys() == {_TUPLE_TAG} else mapping

    return json.loads(text, object_hook=restore)


def _write_atomically(dataset, path: Path, encoding: dict) -> None:
    """Write ``dataset`` through :func:`roughcontact._files.replacing` (temporary file, then rename).

    The folder must exist (it is not created); a failed write is an :class:`InputError` naming the path.
    """
    if not path.parent.is_dir():
        raise InputError(
            "path", f"folder {path.parent} does not exist.", "create it first or choose another path."
        )
    try:
        with replacing(path) as temporary:
            dataset.to_netcdf(temporary, engine="h5netcdf", encoding=encoding)
    except OSError as error:
        raise InputError(
            "path", f"cannot write {path}: {first_line(error)}", "choose a writable folder with free space."
        ) from error
