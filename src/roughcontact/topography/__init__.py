"""Surfaces: the :class:`Topography` container, instrument readers, generators, processing and statistics.

The submodules hold the functions: ``io`` (read instrument files), ``native`` (save/load roughcontact's
own NetCDF format), ``generate`` (synthetic surfaces), ``process`` (detrend, sphere removal, crop,
resample, combine) and ``statistics`` (roughness parameters, spectral moments, McCool asperity
parameters, PSD). The most used are named here and load on first use (:mod:`roughcontact._lazy`),
so that importing one submodule does not import the others.
"""

from .._lazy import attach_stub

__getattr__, __dir__, __all__ = attach_stub(__name__)  # the names: __init__.pyi
