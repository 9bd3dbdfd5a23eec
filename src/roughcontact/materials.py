"""Materials and the composite elastic moduli of a pair of contacting bodies.

A :class:`Material` holds SI values (Pa, J/m^2) and validates them once. The composite
quantities of a pair are plain functions, each named for what it is and carrying its
equation and source:

=====================================  ===========================================================
:func:`contact_modulus`                Hertz E*, 1/E* = sum (1 - nu^2)/E (Johnson 1985)
:func:`johnson_shear_modulus`          Johnson's G*, 1/G* = sum (2 - nu)/G
:func:`dundurs_beta`                   Dundurs' second bimaterial parameter beta
:func:`compliance_sum`                 the sum of a compliance term over the deformable bodies
=====================================  ===========================================================

The papers' own forms live with their models: paper 000's eq. 1 and eq. 4
(:mod:`roughcontact.winkler_lj.springs`), paper 001's G_s
(:func:`roughcontact.contact.presliding.effective_shear_modulus_paper001`), paper 002's printed
eq. 7 (:func:`roughcontact.asperity.parameters.printed_contact_modulus`) and the Oliver-Pharr
sample modulus (:func:`roughcontact.experiment.nanoindentation.oliver_pharr.reduced_modulus_to_youngs`);
their old names here are kept one release with a DeprecationWarning.

Functions that take two bodies accept ``None`` for the second one: a rigid counter-body
(infinite modulus), whose compliance terms vanish.

The papers' materials are in :data:`MATERIALS` (read-only) and :func:`get_material`.
Paper typos that concern moduli are documented beside the functions and in :doc:`/materials`.

References
----------
Johnson, K. L. (1985). *Contact Mechanics*. Cambridge University Press.
doi:10.1017/CBO9781139171731

Seed paper 000: "Simulation model for frictional contact of two elastic surfaces in micro/nanoscale
and its validation" (DOI not given in the seed text).

Seed paper 001: "Evaluation of pre-sliding behavior at a rough interface: modeling and experiment",
ASME J. Appl. Mech. (2020). doi:10.1115/1.4045900

Seed paper 002: "Contact stress analysis of lightly compressed thin films: modeling and
experimentation" (DOI not given in the seed text).
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from numbers import Real
from types import MappingProxyType

from ._deprecation import moved
from .checks import poissons_ratio_checked, positive
from .errors import InputError
from .units import quantity


def material_problems(
    youngs_modulus, poissons_ratio, hardness=None, yield_strength=None, surface_energy=None
) -> list[InputError]:
    """Return every problem of a material's values (empty when they make a material).

    What :class:`Material` checks, all at once: a study reports a negative modulus and a Poisson's
    ratio of 0.6 together, not one after the other.
    """
    checks = [
        lambda: positive(youngs_modulus, "youngs_modulus", example="70e9", unit="Pa"),
        lambda: poissons_ratio_checked(poissons_ratio),
    ]
    if hardness is not None:
        checks.append(lambda: positive(hardness, "hardness", example="0.462e9", unit="Pa"))
    if yield_strength is not None:
        checks.append(lambda: positive(yield_strength, "yield_strength", example="0.165e9", unit="Pa"))
    if surface_energy is not None:
        checks.append(
            lambda: positive(surface_energy, "surface_energy", example="0.072", unit="J/m^2", allow_zero=True)
        )
    problems = []
    for check in checks:
        try:
            check()
        except InputError as error:
            problems.append(error)
    return problems


@dataclass(frozen=True)
class Material:
    """An isotropic linear-elastic material, optionally with plastic and surface properties.

    Parameters
    ----------
    youngs_modulus : float
        Young's modulus E [Pa], positive and finite.
    poissons_ratio : float
        Poisson's ratio nu [-], in (-1, 0.5]; 0.5 is an incompressible material.
    name : str
        Human-readable name.
    hardness : float, optional
        Indentation hardness H [Pa].
    yield_strength : float, optional
        Uniaxial yield strength Y [Pa].
    surface_energy : float, optional
        Surface (free) energy gamma [J/m^2]; zero is allowed.
    source : str
        Citation of the values (paper, table or section).

    Raises
    ------
    InputError
        A modulus, hardness or yield strength that is not positive and finite, a surface energy
        that is negative or not finite, or a Poisson's ratio outside (-1, 0.5].
    """

    youngs_modulus: float
    poissons_ratio: float
    name: str = ""
    hardness: float | None = None
    yield_strength: float | None = None
    surface_energy: float | None = None
    source: str = ""

    def __post_init__(self):
        problems = material_problems(
            self.youngs_modulus, self.poissons_ratio, self.hardness, self.yield_strength, self.surface_energy
        )
        if len(problems) == 1:
            raise problems[0]
        if problems:
            raise InputError(
                problems[0].field,
                f"{len(problems)} problems: " + " ".join(str(p) for p in problems),
                problems[0].fix,
            )

    @property
    def shear_modulus(self) -> float:
        """Shear modulus G = E / (2 (1 + nu)) [Pa]."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poissons_ratio))

    @classmethod
    def from_units(
        cls,
        *,
        youngs_modulus: str | float,
        poissons_ratio: float,
        name: str = "",
        hardness: str | float | None = None,
        yield_strength: str | float | None = None,
        surface_energy: str | float | None = None,
        source: str = "",
    ) -> Material:
        """Build a material from quantities written with units, e.g. ``youngs_modulus="70 GPa"``.

        Parameters
        ----------
        youngs_modulus : str or float
            Pressure such as ``"70 GPa"`` (a bare number is taken as Pa).
        poissons_ratio : float
            Poisson's ratio [-].
        name, source : str
            As in :class:`Material`.
        hardness, yield_strength : str or float, optional
            Pressures such as ``"0.462 GPa"``.
        surface_energy : str or float, optional
            Energy per area such as ``"72 mJ/m^2"``.

        Returns
        -------
        Material
            The material in SI units.

        Raises
        ------
        UnitError
            A unit that is unknown or of the wrong dimension (the message names the field).
        """

        def si(value, dimension, field):
            return None if value is None else quantity(value, dimension, field=field)

        return cls(
            youngs_modulus=si(youngs_modulus, "pressure", "youngs_modulus"),
            poissons_ratio=poissons_ratio,
            name=name,
            hardness=si(hardness, "pressure", "hardness"),
            yield_strength=si(yield_strength, "pressure", "yield_strength"),
            surface_energy=si(surface_energy, "surface_energy", "surface_energy"),
            source=source,
        )


ElasticMaterial = Material
"""Alias of :class:`Material` for code that only needs the elastic constants."""


# --- composite quantities ------------------------------------------------------------------------


def compliance_sum(a: Material, b: Material | None, term: Callable[[Material], float]) -> float:
    """Return ``term(a) + term(b)`` over the deformable bodies (``b=None``: rigid, no term) [1/Pa].

    The composite moduli of a pair are its inverse with their own ``term``: (1 - nu^2)/E for
    Hertz's E*, (2 - nu)/G for Johnson's G*, ... The bodies are checked to be materials.
    """
    return sum(term(body) for body in _deformable_bodies(a, b))


def _deformable_bodies(a: Material, b: Material | None) -> tuple[Material, ...]:
    """Check the pair and return its deformable bodies (``b=None`` is rigid and left out)."""
    for field, body in (("a", a), ("b", b)):
        if not (isinstance(body, Material) or (field == "b" and body is None)):
            raise InputError(
                field,
                f"expected a Material, got {type(body).__name__}.",
                "pass Material(youngs_modulus=..., poissons_ratio=...) or get_material(name)"
                + (" (or None for a rigid counter-body)." if field == "b" else "."),
            )
    return (a,) if b is None else (a, b)


def _hertz_compliance(material: Material) -> float:
    return (1.0 - material.poissons_ratio**2) / material.youngs_modulus


def contact_modulus(a: Material, b: Material | None = None, *, form: str = "standard") -> float:
    r"""Hertz contact (composite, reduced) modulus E* of two elastic bodies [Pa].

    .. math:: \frac{1}{E^*} = \frac{1 - \nu_1^2}{E_1} + \frac{1 - \nu_2^2}{E_2}

    Parameters
    ----------
    a : Material
        First body.
    b : Material or None
        Second body; ``None`` is a rigid counter-body (E* = E1 / (1 - nu1^2)).
    form : {"standard"}
        Release 0.1 also took ``"paper002_eq7_printed"``, paper 002's eq. 7 as printed; that
        reading lives with the asperity model now
        (:func:`roughcontact.asperity.parameters.printed_contact_modulus`) and is served here one
        more release with a DeprecationWarning.

    Returns
    -------
    float
        E* [Pa].

    Raises
    ------
    InputError
        If ``a`` or ``b`` is not a Material, or ``form`` is unknown.

    References
    ----------
    K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, section 4.2 (Hertz theory).
    doi:10.1017/CBO9781139171731.
    Seed paper 000, eq. 1.
    """
    if form == "paper002_eq7_printed":
        import warnings

        warnings.warn(
            "contact_modulus(form='paper002_eq7_printed') is now "
            "roughcontact.asperity.parameters.printed_contact_modulus; the form goes in the next release.",
            DeprecationWarning,
            stacklevel=2,
        )
        return 1.0 / compliance_sum(a, b, lambda m: (1.0 - m.poissons_ratio) / m.youngs_modulus)
    if form != "standard":
        raise InputError("form", f"unknown form {form!r}.", "leave form out (the Hertz E*).")
    return 1.0 / compliance_sum(a, b, _hertz_compliance)


def johnson_shear_modulus(a: Material, b: Material | None = None) -> float:
    r"""Johnson's composite shear modulus G* of the Mindlin tangential contact [Pa].

    .. math:: \frac{1}{G^*} = \frac{2 - \nu_1}{G_1} + \frac{2 - \nu_2}{G_2}

    With it the Mindlin (1949) tangential compliance of a circular contact of radius a reads
    delta_x = 3 mu P / (16 a G*) [1 - (1 - Q / (mu P))^(2/3)] and the initial lateral stiffness is
    8 a G*. Relation to paper 001: G_s = 4 G* (:func:`effective_shear_modulus_paper001`).

    Parameters
    ----------
    a : Material
        First body.
    b : Material or None
        Second body; ``None`` is rigid.

    Returns
    -------
    float
        G* [Pa].

    References
    ----------
    K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, section 7.2
    (tangential loading of a Hertz contact). doi:10.1017/CBO9781139171731.
    R. D. Mindlin, "Compliance of elastic bodies in contact", J. Appl. Mech. 16 (1949) 259-268.
    doi:10.1115/1.4009973
    """
    return 1.0 / compliance_sum(a, b, lambda m: (2.0 - m.poissons_ratio) / m.shear_modulus)


def dundurs_beta(a: Material, b: Material | None = None) -> float:
    r"""Dundurs' second bimaterial parameter beta [-] (plane strain).

    .. math:: \beta = \frac{1}{2}\,
              \frac{(1 - 2\nu_1)/G_1 - (1 - 2\nu_2)/G_2}{(1 - \nu_1)/G_1 + (1 - \nu_2)/G_2}

    Sign convention: Johnson's (1985, section 5.4), which is Dundurs' (1969) with body 1 = ``a``;
    beta > 0 when body ``a`` is the more compliant in the (1 - 2 nu)/G sense. It is antisymmetric,
    beta(a, b) = -beta(b, a), zero for identical bodies and for two incompressible ones
    (nu = 0.5), and lies in [-1/2, 1/2] when both 0 <= nu <= 0.5 (auxetic materials can
    exceed it). It couples normal pressure with tangential
    displacement: with beta = 0 normal and tangential contact problems decouple. Against a rigid
    body (``b=None``) beta = (1 - 2 nu1) / (2 (1 - nu1)).

    Parameters
    ----------
    a : Material
        Body 1.
    b : Material or None
        Body 2; ``None`` is rigid.

    Returns
    -------
    float
        beta [-].

    References
    ----------
    J. Dundurs, discussion of "Edge-bonded dissimilar orthogonal elastic wedges under normal and
    shear loading", J. Appl. Mech. 36 (1969) 650-652. doi:10.1115/1.3564739.
    K. L. Johnson, *Contact Mechanics*, 1985, section 5.4. doi:10.1017/CBO9781139171731
    """

    def terms(body: Material | None) -> tuple[float, float]:
        if body is None:
            return 0.0, 0.0
        return (
            (1.0 - 2.0 * body.poissons_ratio) / body.shear_modulus,
            (1.0 - body.poissons_ratio) / body.shear_modulus,
        )

    _deformable_bodies(a, b)
    (mismatch_a, compliance_a), (mismatch_b, compliance_b) = terms(a), terms(b)
    return 0.5 * (mismatch_a - mismatch_b) / (compliance_a + compliance_b)


# --- the papers' materials -----------------------------------------------------------------------


def _library(*materials: Material) -> Mapping[str, Material]:
    return MappingProxyType({m.name.lower(): m for m in materials})


MATERIALS: Mapping[str, Material] = _library(
    Material(
        110e9,
        0.22,
        "polysilicon",
        source="seed paper 000, section 4 (E by Oliver-Pharr nanoindentation; nu from its ref. 38)",
    ),
    Material(
        70e9,
        0.17,
        "SiO2",
        surface_energy=72e-3,
        source="seed paper 000, section 4 (E, nu from its ref. 37; 72 mJ/m^2 used for the cantilever "
        "tip, from its ref. 40)",
    ),
    Material(130e9, 0.28, "silicon wafer", source="seed paper 001, Table 2 (supplier values)"),
    Material(0.98e9, 0.5, "HDPE", source="seed paper 001, Table 2 (nanoindentation, nu assumed 0.5)"),
    Material(1.38e9, 0.5, "POM", source="seed paper 001, Table 2 (nanoindentation, nu assumed 0.5)"),
    Material(
        7.64e9,
        0.22,
        "SU-8",
        hardness=0.462e9,
        yield_strength=0.165e9,
        source="seed paper 002, Table I (E, H, Y measured; nu from Kim et al.)",
    ),
    Material(1140e9, 0.07, "diamond flat tip", source="seed paper 002, Table I (Hysitron)"),
    Material(1141e9, 0.07, "diamond Berkovich", source="seed paper 001, text of eq. 8"),
)
"""Read-only library of the seed papers' materials, keyed by lower-case name."""


def get_material(name: str) -> Material:
    """Return a material of :data:`MATERIALS` by name, case-insensitively.

    Parameters
    ----------
    name : str
        e.g. ``"SU-8"``, ``"sio2"``, ``"Diamond Berkovich"``; underscores count as spaces.

    Returns
    -------
    Material
        The library entry.

    Raises
    ------
    InputError
        Unknown name; the message lists the known ones.
    """
    key = " ".join(str(name).replace("_", " ").lower().split())
    if key not in MATERIALS:
        raise InputError(
            "material",
            f"unknown material {name!r}.",
            f"use one of {[m.name for m in MATERIALS.values()]} or define a Material.",
        )
    return MATERIALS[key]


def check_material(value, field: str, *, rigid: bool = False, modulus: bool = False) -> None:
    """Refuse what is not a :class:`Material` where a function takes one, with a fix that works as typed.

    Parameters
    ----------
    value : object
        What was passed.
    field : str
        The parameter's name (``"material"``, ``"counter_body"``).
    rigid : bool
        None is accepted (a rigid body).
    modulus : bool
        A number is accepted (the contact modulus E* [Pa]).

    Raises
    ------
    InputError
        A library name as a string (fix: ``get_material('SiO2')``), a modulus with a unit as a string
        (fix: ``quantity('70 GPa')``), or anything else, naming ``field``.
    """
    if isinstance(value, Material) or (rigid and value is None):
        return
    if modulus and isinstance(value, Real) and not isinstance(value, bool):
        return
    takes = (
        "a Material"
        + (" or the contact modulus E* in Pa" if modulus else "")
        + (" or None (rigid)" if rigid else "")
    )
    if isinstance(value, str):
        key = " ".join(value.replace("_", " ").lower().split())
        if key in MATERIALS:
            fix = f"pass {field}=get_material({value!r}) (from roughcontact import get_material)."
        elif modulus and _is_pressure(value):
            fix = f"pass {field}=quantity({value!r}) (from roughcontact import quantity)."
        else:
            close = difflib.get_close_matches(key, list(MATERIALS), n=1)
            hint = f"did you mean get_material({MATERIALS[close[0]].name!r})? " if close else ""
            fix = (
                f"{hint}pass {field}=get_material(NAME) with one of {[m.name for m in MATERIALS.values()]}, "
                "or Material(youngs_modulus=..., poissons_ratio=...)."
            )
        raise InputError(field, f"got the string {value!r}; Python takes {takes}.", fix)
    raise InputError(
        field,
        f"got {type(value).__name__} {value!r}; Python takes {takes}.",
        f"pass {field}=get_material(NAME) or Material(youngs_modulus=..., poissons_ratio=...).",
    )


def _is_pressure(text: str) -> bool:
    try:
        quantity(text, "pressure")
    except InputError:
        return False
    return True


_MOVED = {
    "composite_modulus": "roughcontact.winkler_lj.springs",
    "winkler_factor": "roughcontact.winkler_lj.springs",
    "effective_shear_modulus_paper001": "roughcontact.contact.presliding",
    "reduced_modulus_to_youngs": "roughcontact.experiment.nanoindentation.oliver_pharr",
}
"""Paper formulas that moved to their models in issue 33 -> their new module."""


def __getattr__(name: str):
    """Serve a moved paper formula from its new home, with a DeprecationWarning."""
    return moved(__name__, name, _MOVED)
