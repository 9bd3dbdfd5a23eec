"""The analysis kinds a study file can name (``model = "..."``), one module each.

========================  =====================================================================
``model``                 what one case is
========================  =====================================================================
``statistics``            a topography's roughness statistics and spectral moments (paper 002 eqs. 1-5)
``normal``                an elastic (or elastic-perfectly-plastic) normal contact (paper 001 eq. 4)
``load_unload``           an elastic-plastic load-unload of a surface or paper 002's island (Fig. 7)
``asperity``              McCool parameters and the statistical KKE load-unload (paper 002)
``friction``              the Winkler-layer Lennard-Jones friction at one load (paper 000)
``presliding``            a rough ball's partial-slip loops and K_L against Mindlin (paper 001)
``tangential_path``       a rough ball under the user's own displacement or force programme (CSV)
========================  =====================================================================

Modules are imported when a study names their kind, so a study of one kind does not pay for the
others' imports.
"""

from __future__ import annotations

from importlib import import_module

from ..kind import Kind

_MODULES = {
    "statistics": "statistics",
    "normal": "normal",
    "load_unload": "load_unload",
    "asperity": "asperity",
    "friction": "friction",
    "presliding": "presliding",
    "tangential_path": "tangential_path",
}


def kind_names() -> list[str]:
    """Names of the kinds whose module is present."""
    from importlib.util import find_spec

    return [name for name, module in _MODULES.items() if find_spec(f"{__name__}.{module}") is not None]


def get_kind(name: str) -> Kind:
    """Return the :class:`~roughcontact.study.kind.Kind` called ``name`` (its module's ``KIND``)."""
    return import_module(f"{__name__}.{_MODULES[name]}").KIND
