"""Paper 000's model: Winkler-layer springs with the Lennard-Jones law, adhesive and mechanical friction.

* :mod:`.prepare`: :func:`winkler_lj_model` (the composite surface, its moduli and energies) and
  :func:`solve_winkler_lj` for one load;
* :mod:`.options`: :class:`WinklerLJOptions`, the model's options beside its two bodies (the
  layer, the law's range, the surface energies, the readings, the hold, the gap field);
* :mod:`.model`: :class:`WinklerLJModel` (eq. 2's separation at a load, eqs. 8-17's friction,
  sweeps, the normal curve);
* :mod:`.results`: :class:`WinklerLJResult` (friction at one load), :class:`FrictionSweep`,
  :class:`WinklerNormalCurve`;
* :mod:`.bem`: the boundary-element gap field at a load (``gap_model="bem"``);
* :mod:`.readings`: every disputed reading of the paper, as :class:`Readings`;
* :mod:`.viscoelastic`: the hold-time relaxation of the surface's modulus.

The Lennard-Jones law itself (eqs. 5-7, 14, 16) is with the other interaction laws, in
:mod:`roughcontact.contact.lennard_jones`.
"""

from .model import WinklerLJModel
from .options import WinklerLJOptions
from .prepare import solve_winkler_lj, surface_energy_of, winkler_lj_model, work_of_adhesion
from .readings import PAPER, PRINTED, Readings
from .results import FrictionSweep, WinklerLJResult, WinklerNormalCurve
from .viscoelastic import PronySeries, material_after_hold, standard_linear_solid

__all__ = [
    "PAPER",
    "PRINTED",
    "FrictionSweep",
    "PronySeries",
    "Readings",
    "WinklerLJModel",
    "WinklerLJOptions",
    "WinklerLJResult",
    "WinklerNormalCurve",
    "material_after_hold",
    "solve_winkler_lj",
    "standard_linear_solid",
    "surface_energy_of",
    "winkler_lj_model",
    "work_of_adhesion",
]
