"""Figures, with matplotlib only here; importing the package loads none of it.

Two families, both returning matplotlib objects and touching no global pyplot state:

* ``plot_*(result, ax=None)`` draw one result (or a topography) on optional axes and return
  ``(fig, ax)``;
* ``*_figure(cases, ...)`` draw a study's figure from several cases (stored case records, or
  results wrapped by :func:`as_cases`) and return a ``Figure`` or None; each carries the caption
  the report prints under it (:func:`figure_caption`). The study kinds wire these, so every figure
  of ``roughcontact run`` can be drawn from Python.

Names load from their modules on first use.
"""

from .._lazy import lazy_names

_HOMES = {
    "as_cases": ".cases",
    "figure_caption": ".cases",
    "ResultCase": ".cases",
    "plot_area_load": ".asperity",
    "plot_load_interference": ".asperity",
    "plot_von_mises_maps": ".asperity",
    "plot_contact_area": ".contact",
    "plot_contact_overview": ".contact",
    "plot_gap": ".contact",
    "plot_load_approach": ".contact",
    "plot_pressure": ".contact",
    "plot_von_mises": ".contact",
    "plot_friction_vs_load": ".friction",
    "plot_mu_boxes": ".friction",
    "plot_mu_means": ".friction",
    "plot_heights": ".topography",
    "plot_overview": ".topography",
    "plot_psd": ".topography",
}
"""Public name -> its module in this package (imported on first use)."""

__all__ = sorted(_HOMES)


__getattr__, __dir__ = lazy_names(__name__, _HOMES)
