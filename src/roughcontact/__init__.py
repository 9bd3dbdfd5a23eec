"""roughcontact: contact mechanics of rough surfaces from measured topographies.

The names of the common jobs, all in SI units (m, Pa, N, J/m^2)::

    import roughcontact as rc

    scan = rc.read_topography("scan.di")                       # heights and size in metres
    ball = rc.generate.sphere_with_roughness(256, 1.1e-3, radius=5e-3, rms_height=3e-6, seed=1)
    pressure = rc.quantity("20 MPa", "pressure")
    contact = rc.solve_normal(scan, rc.get_material("polysilicon"), mean_pressure=pressure)
    contact.scalars(), contact.UNITS, contact.to_xarray()      # every result speaks this one protocol

* surfaces: :class:`Topography`, :func:`read_topography`, :func:`save_topography`,
  :func:`load_topography`, :mod:`generate`, :func:`spectral_moments`;
* materials: :class:`Material`, :func:`get_material`, :func:`contact_modulus`;
* models: :func:`solve_normal`, :func:`solve_tangential`, :func:`solve_frictional`, :func:`load_unload`,
  :func:`solve_adhesive`, :func:`solve_winkler_lj` (paper 000), :func:`statistical_load_unload` (paper 002),
  :func:`presliding` (paper 001), :func:`analyse_loop`, :func:`oliver_pharr`;
* studies: :func:`load_study`, :func:`answer` (in memory or into a folder), :func:`run_study`;
* units and errors: :func:`quantity`, :class:`InputError`, :class:`UnitError`,
  :class:`UnsupportedFormatError`, :class:`ConvergenceError`.

Everything else is in the subpackages, each with its own ``__all__``. Importing the package is
cheap and has no side effects: the names are loaded when first used.
"""

from ._lazy import lazy_names
from ._version import __version__
from .display_html import draw_thumbnails_with
from .errors import ConvergenceError, InputError, UnitError, UnsupportedFormatError
from .units import quantity


def _thumbnail(name: str, result) -> bytes:
    """Draw a result's thumbnail for a notebook (:mod:`roughcontact.plotting` loaded only then)."""
    from .plotting.notebook import thumbnail

    return thumbnail(name, result)


draw_thumbnails_with(_thumbnail)  # the figures are a floor above display_html: registered from here

_HOMES = {
    "generate": "roughcontact.topography",
    "Topography": "roughcontact.topography",
    "read_topography": "roughcontact.topography",
    "save_topography": "roughcontact.topography",
    "load_topography": "roughcontact.topography",
    "spectral_moments": "roughcontact.topography",
    "Material": "roughcontact.materials",
    "get_material": "roughcontact.materials",
    "contact_modulus": "roughcontact.materials",
    "solve_normal": "roughcontact.contact",
    "solve_tangential": "roughcontact.contact",
    "solve_frictional": "roughcontact.contact",
    "solve_adhesive": "roughcontact.contact",
    "load_unload": "roughcontact.contact",
    "solve_winkler_lj": "roughcontact.winkler_lj",
    "statistical_load_unload": "roughcontact.asperity",
    "presliding": "roughcontact.contact",
    "analyse_loop": "roughcontact.experiment.friction_loop",
    "oliver_pharr": "roughcontact.experiment.nanoindentation",
    "load_study": "roughcontact.study",
    "run_study": "roughcontact.study",
    "answer": "roughcontact.study",
}
"""Public name -> the module that defines it, or holds it as a submodule (imported on first use)."""

__all__ = [
    "ConvergenceError",
    "InputError",
    "Material",
    "Topography",
    "UnitError",
    "UnsupportedFormatError",
    "__version__",
    "analyse_loop",
    "answer",
    "contact_modulus",
    "generate",
    "get_material",
    "load_study",
    "load_topography",
    "load_unload",
    "oliver_pharr",
    "presliding",
    "quantity",
    "read_topography",
    "run_study",
    "save_topography",
    "solve_adhesive",
    "solve_normal",
    "solve_tangential",
    "solve_frictional",
    "solve_winkler_lj",
    "spectral_moments",
    "statistical_load_unload",
]


__getattr__, __dir__ = lazy_names(__name__, _HOMES)
