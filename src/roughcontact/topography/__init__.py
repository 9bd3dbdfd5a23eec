"""Surfaces: the :class:`Topography` container, instrument readers, generators, processing and statistics.

The submodules hold the functions: ``io`` (read instrument files), ``native`` (save/load roughcontact's
own NetCDF format), ``generate`` (synthetic surfaces), ``process`` (detrend, sphere removal, crop,
resample, combine) and ``statistics`` (roughness parameters, spectral moments, McCool asperity
parameters, PSD). The most used are re-exported here.
"""

from .io import list_channels, read_topography
from .native import load_topography, save_topography
from .process import combine, detrend, level, remove_sphere
from .statistics import mccool_parameters, spectral_moments, summary
from .surface import Topography

__all__ = [
    "Topography",
    "combine",
    "detrend",
    "level",
    "list_channels",
    "load_topography",
    "mccool_parameters",
    "read_topography",
    "remove_sphere",
    "save_topography",
    "spectral_moments",
    "summary",
]
