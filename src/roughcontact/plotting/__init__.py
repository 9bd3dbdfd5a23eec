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

from .._lazy import attach_stub

__getattr__, __dir__, __all__ = attach_stub(__name__)  # the names: __init__.pyi
