"""The public names of :mod:`roughcontact`, each re-exported from its home: the one list of them.

Type checkers and IDEs read this stub; the package reads it too, when imported
(:func:`roughcontact._lazy.attach_stub`): the names here are its ``__all__``, each loaded from its
home on first use. A new public name is one line here.
"""

from ._version import __version__ as __version__
from .asperity import statistical_load_unload as statistical_load_unload
from .contact import (
    load_unload as load_unload,
)
from .contact import (
    presliding as presliding,
)
from .contact import (
    solve_adhesive as solve_adhesive,
)
from .contact import (
    solve_frictional as solve_frictional,
)
from .contact import (
    solve_normal as solve_normal,
)
from .contact import (
    solve_tangential as solve_tangential,
)
from .errors import (
    ConvergenceError as ConvergenceError,
)
from .errors import (
    InputError as InputError,
)
from .errors import (
    UnitError as UnitError,
)
from .errors import (
    UnsupportedFormatError as UnsupportedFormatError,
)
from .experiment.friction_loop import analyse_loop as analyse_loop
from .experiment.nanoindentation import oliver_pharr as oliver_pharr
from .materials import Material as Material
from .materials import contact_modulus as contact_modulus
from .materials import get_material as get_material
from .study import answer as answer
from .study import load_study as load_study
from .study import run_study as run_study
from .topography import (
    Topography as Topography,
)
from .topography import generate as generate
from .topography import (
    load_topography as load_topography,
)
from .topography import (
    read_topography as read_topography,
)
from .topography import (
    save_topography as save_topography,
)
from .topography import (
    spectral_moments as spectral_moments,
)
from .units import quantity as quantity
from .winkler_lj import solve_winkler_lj as solve_winkler_lj

__all__: list[str]
