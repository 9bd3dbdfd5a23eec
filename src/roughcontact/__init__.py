"""roughcontact: contact mechanics of rough surfaces from measured topographies.

The public API is curated here; everything is in SI units (m, Pa, N, J/m^2).
Importing the package has no side effects (no logging set-up, no files touched).
"""

from importlib.metadata import PackageNotFoundError, version

from .errors import ConvergenceError, InputError, UnitError, UnsupportedFormatError
from .materials import Material, contact_modulus, get_material
from .topography import Topography, load_topography, read_topography, save_topography
from .units import quantity

try:
    __version__ = version("roughcontact")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

__all__ = [
    "ConvergenceError",
    "InputError",
    "Material",
    "Topography",
    "UnitError",
    "UnsupportedFormatError",
    "contact_modulus",
    "get_material",
    "load_topography",
    "quantity",
    "read_topography",
    "save_topography",
]
