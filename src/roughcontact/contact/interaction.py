r"""Interaction laws of the gap for adhesive contact: Maugis-Dugdale, exponential, Lennard-Jones 9-3.

A law gives the interaction energy per unit area phi(g) of two surfaces at gap g [m] and its
traction p(g) = -d phi / d g [Pa], positive in compression, negative (tensile) where the surfaces
attract. The work of adhesion is w = -phi at contact (g = 0):

=================  ============================================  ======================================
law                phi(g)                                        contact
=================  ============================================  ======================================
Maugis-Dugdale     -w (1 - g / rho) for g < rho, 0 beyond         hard wall g >= 0; tension w / rho
exponential        -w exp(-g / rho)                               hard wall g >= 0; w / rho at contact
Lennard-Jones 9-3  -(8 w / 3) [eps^2 / (2 l^2) - eps^8 / (8 l^8)]  l = g + eps; repulsion below eps
=================  ============================================  ======================================

The Lennard-Jones law is paper 000's eq. 7 (the n = 2, m = 8 energy of two half-spaces,
:mod:`roughcontact.contact.lennard_jones`); its gap g is counted from the equilibrium distance
eps, so that g = 0 is contact for every law. It has no hard wall: the repulsion of its 1/l^9 term
keeps the surfaces apart, and the solver bounds l >= eps / 2 (a compression of 1344 w / eps;
reaching it is reported as an error, see :mod:`roughcontact.contact.adhesive`).

Each law's ``length`` is its range (rho, or eps) and ``peak_tension`` its largest tension sigma0;
``stiffness`` is d^2 phi / d g^2 = -dp/dg, which the solver's preconditioner and step length use
where it is positive (the Lennard-Jones repulsion and the top of its attraction).
The Maugis parameter of a sphere uses sigma0 (Maugis 1992); for the Lennard-Jones law
sigma0 = 16 w / (9 sqrt(3) eps) ~ 1.026 w / eps.

References
----------
Maugis, D. (1992). J. Colloid Interface Sci. 150, 243-269. doi:10.1016/0021-9797(92)90285-T
Greenwood, J. A. (1997). Proc. R. Soc. Lond. A 453, 1277-1297. doi:10.1098/rspa.1997.0070
Rey, V., Anciaux, G. and Molinari, J.-F. (2017). Comput. Mech. 60, 69-81 (exponential and
Maugis-Dugdale laws with a hard wall). doi:10.1007/s00466-017-1392-5
Seed paper 000, eqs. 5-7.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..checks import positive
from . import lennard_jones as lj

INTERACTION_FRACTION = 0.01
"""Pixels under a tension of at least this fraction of the law's peak tension count as interacting
(the interaction area; exact for Maugis-Dugdale, whose tension is sigma0 or 0)."""

LJ_CLOSEST = 0.5
"""Smallest distance l / eps the Lennard-Jones law is evaluated at (the solver's bound)."""


@dataclass(frozen=True)
class _Law:
    work_of_adhesion: float
    length: float

    name: ClassVar[str]
    hard_wall: ClassVar[bool] = True

    def __post_init__(self):
        positive(self.work_of_adhesion, "work_of_adhesion", example="0.1 J/m^2", unit="J/m^2")
        positive(self.length, "length", example="1e-9", unit="m")
        object.__setattr__(self, "work_of_adhesion", float(self.work_of_adhesion))
        object.__setattr__(self, "length", float(self.length))

    @property
    def lowest_gap(self) -> float:
        """Smallest admissible gap [m]: 0 with a hard wall."""
        return 0.0

    def in_contact(self, gap: np.ndarray) -> np.ndarray:
        """Where the surfaces touch: at the wall, g <= 0 (in repulsion, g < 0, for Lennard-Jones)."""
        return gap <= 0.0 if self.hard_wall else gap < 0.0

    def describe(self) -> str:
        """One line naming the law and its parameters (SI)."""
        return (
            f"{self.name} (w = {self.work_of_adhesion:.4g} J/m^2, {self._length_name} = {self.length:.4g} m)"
        )

    _length_name: ClassVar[str] = "rho"


@dataclass(frozen=True)
class MaugisDugdale(_Law):
    r"""Maugis-Dugdale law: constant tension sigma0 = w / rho over 0 <= g < rho, hard wall at g = 0.

    .. math:: \phi(g) = -w\,(1 - g/\rho)\ (g < \rho), \qquad 0\ (g \ge \rho)

    Parameters
    ----------
    work_of_adhesion : float
        w [J/m^2].
    length : float
        Range rho [m] (Maugis' h0), so that sigma0 rho = w.
    """

    name: ClassVar[str] = "Maugis-Dugdale"

    @property
    def peak_tension(self) -> float:
        """sigma0 = w / rho [Pa]."""
        return self.work_of_adhesion / self.length

    def energy(self, gap: np.ndarray) -> np.ndarray:
        """phi(g) [J/m^2]."""
        return -self.work_of_adhesion * np.clip(1.0 - gap / self.length, 0.0, None)

    def traction(self, gap: np.ndarray) -> np.ndarray:
        """p(g) = -dphi/dg [Pa]: -sigma0 inside the range, 0 beyond."""
        return np.where(gap < self.length, -self.peak_tension, 0.0)

    def stiffness(self, gap: np.ndarray) -> np.ndarray:
        """d^2 phi / d g^2 [Pa/m]: 0 (constant tension; the drop at rho is not a stiffness)."""
        return np.zeros_like(gap, dtype=float)


@dataclass(frozen=True)
class Exponential(_Law):
    r"""Exponential law with a hard wall: phi(g) = -w exp(-g / rho), tension w / rho at contact.

    The law of tamaas' ``ExponentialAdhesionFunctional`` and Adhesion's ``Exponential`` (Rey et
    al. 2017).

    Parameters
    ----------
    work_of_adhesion : float
        w [J/m^2].
    length : float
        Decay length rho [m].
    """

    name: ClassVar[str] = "exponential"

    @property
    def peak_tension(self) -> float:
        """The tension w / rho at contact [Pa]."""
        return self.work_of_adhesion / self.length

    def energy(self, gap: np.ndarray) -> np.ndarray:
        """phi(g) [J/m^2]."""
        return -self.work_of_adhesion * np.exp(-gap / self.length)

    def traction(self, gap: np.ndarray) -> np.ndarray:
        """p(g) = -(w / rho) exp(-g / rho) [Pa]."""
        return -self.peak_tension * np.exp(-gap / self.length)

    def stiffness(self, gap: np.ndarray) -> np.ndarray:
        """d^2 phi / d g^2 = -(w / rho^2) exp(-g / rho) [Pa/m] (negative: the tension falls with g)."""
        return -(self.peak_tension / self.length) * np.exp(-gap / self.length)


@dataclass(frozen=True)
class LennardJones(_Law):
    r"""Lennard-Jones 9-3 law of paper 000 equation 7, with the gap counted from the equilibrium distance.

    .. math:: \phi(g) = -\frac{8w}{3}\left[\frac{\varepsilon^2}{2l^2}
              - \frac{\varepsilon^8}{8l^8}\right], \qquad l = g + \varepsilon,

    traction p = -f(l) with f the attractive stress of eq. 7
    (:func:`roughcontact.contact.lennard_jones.attractive_stress`); phi(0) = -w.

    Parameters
    ----------
    work_of_adhesion : float
        w (paper 000's dgamma) [J/m^2].
    length : float
        Equilibrium distance eps [m] (paper 000: 2 nm; about 0.3 nm for atomically smooth solids).
    """

    name: ClassVar[str] = "Lennard-Jones 9-3"
    hard_wall: ClassVar[bool] = False
    _length_name: ClassVar[str] = "eps"

    @property
    def peak_tension(self) -> float:
        """16 w / (9 sqrt(3) eps) [Pa], at l = 3^(1/6) eps."""
        return lj.PEAK_STRESS_FACTOR * self.work_of_adhesion / self.length

    @property
    def lowest_gap(self) -> float:
        """-eps / 2: the solver's bound l >= eps / 2 [m]."""
        return (LJ_CLOSEST - 1.0) * self.length

    def energy(self, gap: np.ndarray) -> np.ndarray:
        """phi(g) [J/m^2]."""
        return -lj.separation_energy(gap + self.length, self.work_of_adhesion, self.length)

    def traction(self, gap: np.ndarray) -> np.ndarray:
        """p(g) [Pa]: repulsive (> 0) below the equilibrium distance, tensile beyond."""
        return -lj.attractive_stress(gap + self.length, self.work_of_adhesion, self.length)

    def stiffness(self, gap: np.ndarray) -> np.ndarray:
        """d^2 phi / d g^2 = (8 w / 3 eps^2) [9 (eps/l)^10 - 3 (eps/l)^4] [Pa/m]: 16 w / eps^2 at g = 0.

        Positive below the peak tension (l < 3^(1/6) eps), growing as l^-10 in repulsion.
        """
        ratio = self.length / (gap + self.length)
        fourth = ratio**4
        scale = 8.0 * self.work_of_adhesion / (3.0 * self.length**2)
        return scale * fourth * (9.0 * fourth * ratio * ratio - 3.0)


LAWS = {"maugis_dugdale": MaugisDugdale, "exponential": Exponential, "lennard_jones": LennardJones}
"""The laws by their study-file names."""


def cohesive_zone_length(law: _Law, contact_modulus: float) -> float:
    r"""Length of the cohesive zone at the edge of an adhesive contact [m]: (pi / 4) E* w / sigma0^2.

    The Dugdale zone of a crack in plane strain with energy release rate w = K^2 / (2 E*)
    (Maugis 1992; Johnson 1985 sec. 5.5), with sigma0 the law's peak tension. The boundary-element
    grid must resolve it (a few pixels) for the pull-off of a JKR-like contact to be mesh-independent.

    Parameters
    ----------
    law : interaction law
    contact_modulus : float
        E* [Pa].

    Returns
    -------
    float
        [m]
    """
    return 0.25 * math.pi * contact_modulus * law.work_of_adhesion / law.peak_tension**2
