"""Figures, with matplotlib only here and imported lazily by callers.

Every function takes results (or a topography) and an optional ``ax`` and returns
``(fig, ax)``; nothing is shown and no global pyplot state is touched.
"""

from .asperity import plot_area_load, plot_load_interference, plot_von_mises_maps
from .contact import (
    plot_contact_area,
    plot_contact_overview,
    plot_gap,
    plot_load_approach,
    plot_pressure,
    plot_von_mises,
)
from .friction import plot_friction_vs_load, plot_mu_boxes, plot_mu_means
from .topography import plot_heights, plot_overview, plot_psd

__all__ = [
    "plot_area_load",
    "plot_contact_area",
    "plot_contact_overview",
    "plot_friction_vs_load",
    "plot_gap",
    "plot_heights",
    "plot_load_approach",
    "plot_load_interference",
    "plot_mu_boxes",
    "plot_mu_means",
    "plot_overview",
    "plot_pressure",
    "plot_psd",
    "plot_von_mises",
    "plot_von_mises_maps",
]
