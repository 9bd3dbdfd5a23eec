"""The models a study (and a command) can run, one module each: ``model = "..."`` in a study file.

====================  ===========================================================================
``model``             what one case is
====================  ===========================================================================
``statistics``        a topography's roughness statistics and spectral moments (paper 002 eqs. 1-5)
``normal``            an elastic (or elastic-perfectly-plastic) normal contact (paper 001 eq. 4)
``load_unload``       an elastic-plastic load-unload of a surface or paper 002's island (Fig. 7)
``asperity``          McCool parameters and the statistical KKE load-unload (paper 002)
``friction``          the Winkler-layer Lennard-Jones friction at one load (paper 000)
``adhesion``          an adhesive load-unload cycle (BEM), pull-off; paper 000's springs beside
``presliding``        a rough ball's partial-slip loops under paper 001's or your programme, K_L
``loop_analysis``     a measured friction loop: stroke, mu, eq. 9 fit, K_L (paper 001)
``nanoindentation``   Oliver-Pharr modulus with the hold-creep correction (paper 001 eqs. 5-8)
``theories``          Persson, Bush-Gibson-Thomas and Greenwood-Williamson beside the BEM over a load sweep
====================  ===========================================================================

Each module defines its model once: the validated parameters, ``run``, the units of its scalars,
its figures and tables (:class:`~roughcontact.study.kind.Kind`). A study runs it over many cases;
a command of the command line runs it as a study of one (or a few) cases. Adding a model is one
module here and one line in :data:`MODULES`.

Modules are imported when a study names their kind, so a study of one kind does not pay for the
others' imports.
"""

from __future__ import annotations

from importlib import import_module

from ..kind import Kind

MODULES = {
    "statistics": "statistics",
    "normal": "normal",
    "load_unload": "load_unload",
    "asperity": "asperity",
    "friction": "friction",
    "adhesion": "adhesion",
    "presliding": "presliding",
    "loop_analysis": "loop_analysis",
    "nanoindentation": "nanoindentation",
    "theories": "theories",
}
"""Model name -> module of this package that defines its ``KIND``."""

ALIASES = {"tangential_path": "presliding"}
"""Names of release 0.1 -> the model that took them over (a study naming one gets a note)."""


def kind_names(*, aliases: bool = False) -> list[str]:
    """Names of the models (with the deprecated aliases when ``aliases``)."""
    return list(MODULES) + (list(ALIASES) if aliases else [])


def get_kind(name: str) -> Kind:
    """Return the :class:`~roughcontact.study.kind.Kind` called ``name`` (or by an alias of it)."""
    name = ALIASES.get(name, name)
    return import_module(f"{__name__}.{MODULES[name]}").KIND
