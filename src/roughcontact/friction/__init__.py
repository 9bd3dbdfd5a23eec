"""Paper 000's model under its release-0.1 name: moved to :mod:`roughcontact.winkler_lj` (one release).

``roughcontact.friction.X`` still finds what it held, with a DeprecationWarning;
``roughcontact.friction.lennard_jones`` is :mod:`roughcontact.contact.lennard_jones`.
"""

from .._deprecation import moved

_HOMES = {
    name: "roughcontact.winkler_lj"
    for name in (
        "PAPER",
        "PRINTED",
        "FrictionSweep",
        "PronySeries",
        "Readings",
        "WinklerLJModel",
        "WinklerLJResult",
        "material_after_hold",
        "solve_winkler_lj",
        "standard_linear_solid",
        "winkler_lj_model",
        "work_of_adhesion",
    )
}


def __getattr__(name: str):
    """Serve a name that moved to :mod:`roughcontact.winkler_lj`, with a warning."""
    return moved(__name__, name, _HOMES)
