"""The public names of :mod:`roughcontact.topography`, each re-exported from its module: the one list of them.

Type checkers and IDEs read this stub; the package reads it too (:func:`roughcontact._lazy.attach_stub`):
the names here are its ``__all__``, each loaded from its module on first use.
"""

from .io import list_channels as list_channels
from .io import read_topography as read_topography
from .native import load_topography as load_topography
from .native import save_topography as save_topography
from .process import combine as combine
from .process import detrend as detrend
from .process import level as level
from .process import remove_sphere as remove_sphere
from .statistics import mccool_parameters as mccool_parameters
from .statistics import spectral_moments as spectral_moments
from .statistics import summary as summary
from .surface import Topography as Topography

__all__: list[str]
