"""Named readings of the disputed equations of paper 000 (the Winkler-Lennard-Jones friction model).

Paper 000 has unit and sign problems and gaps (see :doc:`/winkler_lj` for the derivations).
Every disputed choice is a field of :class:`Readings`; the default of each field is the physically
consistent reading and the paper's printed form is always one of the choices. :data:`PRINTED`
selects the printed form everywhere (where the paper is silent, the choice closest to its text);
:data:`PAPER` is the paper's own reading, the printed choices that give its headline results on
its own scenario (see :doc:`/winkler_lj`, "The paper's own reading"). :meth:`Readings.preset`
returns either by name (:data:`PRESETS`).

=====================  =======================  =====================================================
field                  default                  alternatives (printed form first)
=====================  =======================  =====================================================
balance_terms          ``forces``               ``pressures_printed``: eqs. 2, 3, 7 summed as stresses
adhesion_sign          ``attractive``           ``printed``: sum P + sum F = N with F > 0 attractive
winkler_factor         ``uniaxial_strain``      ``paper000_eq4_printed``: denominator 1 - nu1 nu2
work_of_adhesion       ``girifalco_good``       ``printed``: sqrt(gamma1 gamma2) instead of 2 sqrt(...)
contact                ``epsilon``              ``zero_gap``: wall at l = 0, eq. 7 cut at 0 inside eps
shear                  ``simple_shear``         ``eq12_printed``: diagonal strain C(alpha) of eqs. 10-12
cuboid_height          ``layer``                ``printed``: z_i + dz_i from the lowest point
energy_area            ``times_area``           ``printed``: energy per area in eqs. 13, 15, 17
mechanical_height      ``cuboid``               ``printed_separation``: 1/d in eq. 17
mechanical_energy      ``two_stage``            ``eq16_signed``: eq. 16's signed integral
shear_poisson          ``geometric``            ``surface``, ``counter``: which nu enters G
adhesive_range         ``maugis_dugdale``       ``all_springs``: every spring not in mechanical contact
base                   ``lowest_point``         ``half_sphere``: the base of section 3.1's half-sphere tip
adhesive_cutoff        ``inf``                  a distance [m] beyond which springs do not count
=====================  =======================  =====================================================
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, fields, replace

from ..errors import InputError

CHOICES: dict[str, tuple[str, ...]] = {
    "balance_terms": ("forces", "pressures_printed"),
    "adhesion_sign": ("attractive", "printed"),
    "winkler_factor": ("uniaxial_strain", "paper000_eq4_printed"),
    "work_of_adhesion": ("girifalco_good", "printed"),
    "contact": ("epsilon", "zero_gap"),
    "shear": ("simple_shear", "eq12_printed"),
    "cuboid_height": ("layer", "printed"),
    "energy_area": ("times_area", "printed"),
    "mechanical_height": ("cuboid", "printed_separation"),
    "mechanical_energy": ("two_stage", "eq16_signed"),
    "shear_poisson": ("geometric", "surface", "counter"),
    "adhesive_range": ("maugis_dugdale", "all_springs"),
    "base": ("lowest_point", "half_sphere"),
}
"""Allowed values of each string field of :class:`Readings`; the first is the default."""


@dataclass(frozen=True)
class Readings:
    """How each disputed equation of paper 000 is read; see the module table and :doc:`/winkler_lj`.

    Parameters
    ----------
    balance_terms : {"forces", "pressures_printed"}
        Eqs. 3 and 7 are stresses; ``"forces"`` multiplies them by the spring area S before they
        enter the force balance of eq. 2. ``"pressures_printed"`` sums the stresses against N as
        printed: dimensionally inconsistent, so its results depend on the unit system (SI here).
    adhesion_sign : {"attractive", "printed"}
        ``"attractive"``: the attraction of eq. 7 (F > 0) pulls the bodies together and adds to the
        load, sum P - sum F = N. ``"printed"``: eq. 2 as printed, sum P + sum F = N (adhesion
        carrying load, which follows only if eq. 5 is read with the opposite sign).
    winkler_factor : {"uniaxial_strain", "paper000_eq4_printed"}
        Denominator of eq. 4, see :func:`roughcontact.winkler_lj.springs.winkler_factor`.
    work_of_adhesion : {"girifalco_good", "printed"}
        dgamma = 2 sqrt(gamma1 gamma2) (Girifalco-Good / Berthelot: 2 gamma for identical
        surfaces) or sqrt(gamma1 gamma2) as printed below eq. 7.
    contact : {"epsilon", "zero_gap"}
        When a spring is in mechanical contact. ``"epsilon"``: where the undeformed gap
        l_i = d - z_i is <= epsilon (a hard wall at the zero of eq. 7, paper: "no initial
        mechanical contact l_i > epsilon"). ``"zero_gap"``: where l_i <= 0; springs with
        0 < l_i < epsilon then feel no force (eq. 7's repulsive branch is cut) and carry the full
        energy dgamma.
    shear : {"simple_shear", "eq12_printed"}
        Shear compliance of a cuboid of height H: simple shear ds = Q H / (G S), or eq. 12
        ds = Q H / (2 C G S), which equates the diagonal strain of eq. 10 with the 45-degree
        principal strain of eq. 11 (equal only for a cube, C = 1/2).
    cuboid_height : {"layer", "printed"}
        Height H of the sheared cuboid in eqs. 10-15: the Winkler layer thickness plus the
        spring's extension, h + dz_i, or z_i + dz_i as printed with z_i from the lowest point.
    energy_area : {"times_area", "printed"}
        Eqs. 14 and 16 are energies per area; ``"times_area"`` multiplies them by S before
        equating them with the work of eq. 13, so Q is in N. ``"printed"`` leaves them per area
        (Q then carries N/m, read as N).
    mechanical_height : {"cuboid", "printed_separation"}
        Height in eq. 17: the same cuboid height as in eq. 15, or 1/d as printed.
    mechanical_energy : {"two_stage", "eq16_signed"}
        Energy to break a mechanical contact held at l_im < epsilon: the text's two stages,
        ``|work from l_im to epsilon|`` + dgamma = 2 dgamma - e(l_im), or eq. 16 as printed,
        e(l_im), which turns negative above a stress of 16 dgamma / epsilon (such springs then
        add no friction and are counted in the result).
    shear_poisson : {"geometric", "surface", "counter"}
        Poisson's ratio in G = E / (2 (1 + nu)) with E from eq. 1: sqrt(nu1 nu2) as in eq. 4,
        the surface's nu1, or the counter-body's nu2.
    adhesive_range : {"maugis_dugdale", "all_springs"}
        Which springs in adhesive contact add adhesive friction (eqs. 9-15). ``"maugis_dugdale"``:
        those whose bond distance l_ia is at most epsilon + dgamma / max f = (1 + 9 sqrt(3) / 16)
        epsilon ~ 1.974 epsilon, the edge of the Dugdale zone with the peak stress and the work of
        adhesion of eq. 7 (Maugis 1992); farther springs still feel eq. 7's attraction in eq. 2 but
        hold no bond to break. ``"all_springs"``: every spring not in mechanical contact (the
        paper's "l_i > epsilon"; the sum over a sphere then grows like the log of the scan size and
        over a flat like its area, see :doc:`/winkler_lj`; the earlier default).
    base : {"lowest_point", "half_sphere"}
        The base level from which z_i and d are measured (eq. 8: "d is the distance between the
        flat surface and the base of the rough surface"), which enters the printed heights
        (``cuboid_height="printed"``: z_i + dz_i; ``mechanical_height="printed_separation"``: d).
        ``"lowest_point"``: the lowest pixel of the composite surface in the scan window, so that
        d grows with the window around a sphere (R = 1 um: d = 1 um in a 2 um window, 6.25 um at
        the corners of a 5 um one). ``"half_sphere"``: section 3.1 models the tip "as a half
        sphere", whose base is its equatorial plane, a tip radius R below its apex; z_i and d are
        measured from that plane (d = R + the apex gap, whatever the window), and only the springs
        under the half sphere (within R of the tip's apex, above its base) are modelled, in eq. 2
        and in the friction, so that the result does not change with the window once the tip is
        inside it. R is the model's ``tip_radius`` (default: the radius the tip was generated with).
    adhesive_cutoff : float
        Gap [m] beyond which springs are neither in eq. 2 nor in the friction (default: none,
        ``inf``).

    Raises
    ------
    InputError
        An unknown value (the message lists the allowed ones) or a cutoff that is not positive.
    """

    balance_terms: str = "forces"
    adhesion_sign: str = "attractive"
    winkler_factor: str = "uniaxial_strain"
    work_of_adhesion: str = "girifalco_good"
    contact: str = "epsilon"
    shear: str = "simple_shear"
    cuboid_height: str = "layer"
    energy_area: str = "times_area"
    mechanical_height: str = "cuboid"
    mechanical_energy: str = "two_stage"
    shear_poisson: str = "geometric"
    adhesive_range: str = "maugis_dugdale"
    base: str = "lowest_point"
    adhesive_cutoff: float = math.inf

    def __post_init__(self):
        for name, allowed in CHOICES.items():
            value = getattr(self, name)
            if value not in allowed:
                raise InputError(
                    f"readings.{name}", f"unknown reading {value!r}.", f"choose one of {list(allowed)}."
                )
        cutoff = float(self.adhesive_cutoff)
        if not cutoff > 0:
            raise InputError(
                "readings.adhesive_cutoff",
                f"{self.adhesive_cutoff!r} is not a positive distance.",
                "give a gap in metres (e.g. 20e-9) or inf for no cutoff.",
            )
        object.__setattr__(self, "adhesive_cutoff", cutoff)

    @classmethod
    def preset(cls, name: str) -> Readings:
        """Return a named set of readings: ``"default"``, ``"paper"`` (:data:`PAPER`), ``"printed"``.

        ``"printed"`` is :data:`PRINTED`, every equation as printed.

        Raises
        ------
        InputError
            An unknown name (field ``reading``; the message lists the presets).
        """
        if name not in PRESETS:
            raise InputError("reading", f"unknown preset {name!r}.", f"choose one of {list(PRESETS)}.")
        return PRESETS[name]

    @classmethod
    def from_strings(cls, items: Iterable[str], *, preset: str = "default") -> Readings:
        """Build readings from ``"name=value"`` strings (a study's ``readings`` table, a command's options).

        Parameters
        ----------
        items : iterable of str
            e.g. ``["contact=zero_gap", "adhesive_cutoff=2e-8"]``; the cutoff is in metres.
        preset : str
            The readings that the items change (:meth:`preset`); the fields not named keep its value.

        Returns
        -------
        Readings

        Raises
        ------
        InputError
            A malformed item or an unknown name or value.
        """
        known = [f.name for f in fields(cls)]
        values: dict[str, object] = {}
        for item in items:
            name, separator, value = item.partition("=")
            name = name.strip().replace("-", "_")
            if not separator or name not in known:
                raise InputError(
                    "readings", f"cannot read {item!r}.", f"write NAME=VALUE with NAME one of {known}."
                )
            if name != "adhesive_cutoff":
                values[name] = value.strip()
                continue
            try:
                values[name] = float(value)
            except ValueError:
                raise InputError(
                    "readings",
                    f"adhesive_cutoff {value!r} is not a number.",
                    "give metres, e.g. 2e-8, or inf.",
                ) from None
        return replace(cls.preset(preset), **values)

    def changed(self) -> dict[str, object]:
        """Return the fields that differ from the defaults, ``{name: value}``."""
        default = Readings()
        return {
            f.name: getattr(self, f.name)
            for f in fields(self)
            if getattr(self, f.name) != getattr(default, f.name)
        }


PRINTED = Readings(
    balance_terms="pressures_printed",
    adhesion_sign="printed",
    winkler_factor="paper000_eq4_printed",
    work_of_adhesion="printed",
    shear="eq12_printed",
    cuboid_height="printed",
    energy_area="printed",
    mechanical_height="printed_separation",
    mechanical_energy="eq16_signed",
    shear_poisson="surface",
    adhesive_range="all_springs",
)
"""Every equation as printed in paper 000 (``contact="epsilon"`` is the printed text's criterion;
the paper does not say which Poisson's ratio enters G, ``"surface"`` is the closest to its text;
``adhesive_range="all_springs"`` reads "strictly adhesive contact" as the text's l_i > epsilon)."""


PAPER = Readings(
    winkler_factor="paper000_eq4_printed",
    work_of_adhesion="printed",
    shear="eq12_printed",
    mechanical_height="printed_separation",
    shear_poisson="surface",
    adhesive_range="all_springs",
    base="half_sphere",
)
"""The paper's own reading: the printed choices that give paper 000's headline results on its scenario.

Printed eq. 4 (k), dgamma = sqrt(gamma1 gamma2), eq. 12's shear compliance, eq. 15 summed over every
adhesive spring of the tip, eq. 17 with 1/d, G with the surface's nu (as :data:`PRINTED`), and the
half-sphere tip of section 3.1: z_i and d measured from its base, a tip radius below its apex, and
only the springs under it modelled, so that d = R + the apex gap and nothing depends on the scan
window once the tip is inside it. Kept from the default, as the paper's own text or its units
require: forces in eq. 2 (``balance_terms``) and the attraction adding to the load
(``adhesion_sign``; the "sign of eq. 5"), the wall at epsilon (the printed text's criterion), the
cuboid height of eq. 15 = the Winkler layer plus the extension (the text: "its height being the
height of the Winkler's layer"; Fig. 3: "z_i is the height of the layer"), energies times S
(eqs. 15, 17 give N/m otherwise), and the two stages of the text for eq. 16. On paper 000's
scenario: adhesive friction about 19 times the mechanical part at 10 uN and a crossover near
640 uN (paper: about 40 times, about 600 uN); :doc:`/winkler_lj` tabulates each choice."""

PRESETS: dict[str, Readings] = {"default": Readings(), "paper": PAPER, "printed": PRINTED}
"""Named sets of readings (a study's ``reading`` key, ``roughcontact friction --reading NAME``)."""
