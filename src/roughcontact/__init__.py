"""roughcontact: contact mechanics of rough surfaces from measured topographies.

The public API is curated here; everything is in SI units (m, Pa, N, J/m^2).
Importing the package does no work and has no side effects.
"""

from importlib.metadata import PackageNotFoundError, version

from .errors import ConvergenceError, InputError, UnitError, UnsupportedFormatError
from .topography import Topography
from .units import quantity

try:
    __version__ = version("roughcontact")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

__all__ = [
    "ConvergenceError",
    "InputError",
    "Topography",
    "UnitError",
    "UnsupportedFormatError",
    "quantity",
]
