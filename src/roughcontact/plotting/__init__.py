"""Figures, with matplotlib only here and imported lazily by callers.

Every function takes results (or a topography) and an optional ``ax`` and returns
``(fig, ax)``; nothing is shown and no global pyplot state is touched.
"""

from .topography import plot_heights, plot_overview, plot_psd

__all__ = ["plot_heights", "plot_overview", "plot_psd"]
