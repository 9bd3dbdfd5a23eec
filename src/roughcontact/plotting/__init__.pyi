"""The public names of :mod:`roughcontact.plotting`, each re-exported from its module: the one list of them.

Type checkers and IDEs read this stub; the package reads it too (:func:`roughcontact._lazy.attach_stub`):
the names here are its ``__all__``, each loaded from its module on first use.
"""

from .asperity import (
    plot_area_load as plot_area_load,
)
from .asperity import (
    plot_load_interference as plot_load_interference,
)
from .asperity import (
    plot_von_mises_maps as plot_von_mises_maps,
)
from .cases import ResultCase as ResultCase
from .cases import as_cases as as_cases
from .cases import figure_caption as figure_caption
from .contact import (
    plot_contact_area as plot_contact_area,
)
from .contact import (
    plot_contact_overview as plot_contact_overview,
)
from .contact import (
    plot_gap as plot_gap,
)
from .contact import (
    plot_load_approach as plot_load_approach,
)
from .contact import (
    plot_pressure as plot_pressure,
)
from .contact import (
    plot_von_mises as plot_von_mises,
)
from .friction import (
    plot_friction_vs_load as plot_friction_vs_load,
)
from .friction import (
    plot_mu_boxes as plot_mu_boxes,
)
from .friction import (
    plot_mu_means as plot_mu_means,
)
from .topography import plot_heights as plot_heights
from .topography import plot_overview as plot_overview
from .topography import plot_psd as plot_psd

__all__: list[str]
