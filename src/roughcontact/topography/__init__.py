"""Surfaces: the :class:`Topography` container, instrument readers, generators, processing and statistics.

The submodules hold the functions: ``io`` (read instrument files), ``native`` (save/load roughcontact's
own NetCDF format), ``generate`` (synthetic surfaces), ``process`` (detrend, sphere removal, crop,
resample, combine) and ``statistics`` (roughness parameters, spectral moments, McCool asperity
parameters, PSD). The most used are named here and load on first use (:mod:`roughcontact._lazy`),
so that importing one submodule does not import the others.
"""

from .._lazy import lazy_names

_HOMES = {
    "Topography": ".surface",
    "combine": ".process",
    "detrend": ".process",
    "level": ".process",
    "list_channels": ".io",
    "load_topography": ".native",
    "mccool_parameters": ".statistics",
    "read_topography": ".io",
    "remove_sphere": ".process",
    "save_topography": ".native",
    "spectral_moments": ".statistics",
    "summary": ".statistics",
}
"""Public name -> the submodule that defines it (imported on first use)."""

__all__ = sorted(_HOMES)

__getattr__, __dir__ = lazy_names(__name__, _HOMES)
