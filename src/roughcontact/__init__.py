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
cheap: the names are loaded when first used, from the homes its type stub ``__init__.pyi`` gives
them (the one list of the public names, :mod:`roughcontact._lazy`).
"""

from ._lazy import attach_stub
from .display_html import draw_thumbnails_with


def _thumbnail(name: str, result) -> bytes:
    """Draw a result's thumbnail for a notebook (:mod:`roughcontact.plotting` loaded only then)."""
    from .plotting.notebook import thumbnail

    return thumbnail(name, result)


draw_thumbnails_with(_thumbnail)  # the figures are a floor above display_html: registered from here

__getattr__, __dir__, __all__ = attach_stub(__name__)  # the names and their homes: __init__.pyi
