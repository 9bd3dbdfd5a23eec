"""The asperity parameters of a surface and a pair of materials, in one record (paper 002 equations 4-9)."""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import ClassVar

from ..display_html import NotebookDisplay
from ..errors import InputError
from ..materials import Material, compliance_sum, contact_modulus
from ..topography.statistics import mccool_parameters
from . import elastic_plastic as ep


@dataclass(frozen=True)
class AsperityParameters(NotebookDisplay):
    """Summit statistics and elastic-plastic scales of a rough surface against a counter-body (SI).

    Attributes
    ----------
    m0, m2, m4 : float
        Spectral moments [m^2], [-], [1/m^2].
    bandwidth : float
        alpha = m0 m4 / m2^2 [-].
    summit_density : float
        eta [1/m^2].
    summit_radius : float
        R_asp [m] (eq. 4).
    summit_height_std : float
        sigma_s [m] (eq. 5).
    summit_mean_offset : float
        Summits' mean plane above the surface mean plane [m].
    contact_modulus : float
        E' [Pa] (eq. 7 in the chosen form).
    contact_pressure_factor : float
        K [-] (eq. 8).
    critical_interference : float
        omega_c [m] (eq. 6).
    critical_load : float
        P_c [N], the Hertz load at omega_c.
    plasticity_index : float
        psi [-] (eq. 9).
    """

    m0: float
    m2: float
    m4: float
    bandwidth: float
    summit_density: float
    summit_radius: float
    summit_height_std: float
    summit_mean_offset: float
    contact_modulus: float
    contact_pressure_factor: float
    critical_interference: float
    critical_load: float
    plasticity_index: float

    UNITS: ClassVar[dict[str, str]] = {
        "m0": "m^2",
        "m4": "1/m^2",
        "summit_density": "1/m^2",
        "summit_radius": "m",
        "summit_height_std": "m",
        "summit_mean_offset": "m",
        "contact_modulus": "Pa",
        "critical_interference": "m",
        "critical_load": "N",
    }
    """SI unit of each dimensional scalar of :meth:`scalars` (the others are dimensionless)."""

    def scalars(self) -> dict[str, float]:
        """Return the fields as a plain dict (SI; units in :attr:`UNITS`)."""
        return asdict(self)

    def to_xarray(self):
        """Return the parameters as an ``xarray.Dataset`` of scalar variables with their units."""
        import xarray as xr

        return xr.Dataset(
            {
                name: ((), value, {"units": self.UNITS.get(name, "1")})
                for name, value in self.scalars().items()
            }
        )


def printed_contact_modulus(a: Material, b: Material | None = None) -> float:
    r"""E' of paper 002 equation 7 as printed, with (1 - nu) where Hertz has (1 - nu^2) [Pa].

    .. math:: \frac{1}{E'} = \frac{1 - \nu_1}{E_1} + \frac{1 - \nu_2}{E_2}

    Kept only to trace the printed text (``modulus_form="paper002_eq7_printed"``): it does not
    reproduce the paper's own numbers. For Table I (SU-8 7.64 GPa / 0.22 against diamond
    1140 GPa / 0.07) Hertz's E* gives 7.97 GPa, which reproduces the paper's omega_c = 0.0125 um
    (eq. 6) and psi = 1.86; this form gives 9.72 GPa; the printed value 8.31 GPa matches neither.

    References
    ----------
    Seed paper 002, eq. 7 (printed with a typo).
    """
    return 1.0 / compliance_sum(a, b, lambda m: (1.0 - m.poissons_ratio) / m.youngs_modulus)


MODULUS_FORMS = {"standard": contact_modulus, "paper002_eq7_printed": printed_contact_modulus}
"""The readings of paper 002's E' (eq. 7): Hertz's E* (standard), or the equation as printed."""


def asperity_parameters(
    *,
    m0: float,
    m2: float,
    m4: float,
    sample: Material,
    counter_body: Material | None = None,
    hardness: float | None = None,
    modulus_form: str = "standard",
) -> AsperityParameters:
    """McCool summit statistics, E', K, omega_c, P_c and psi from the moments and the materials.

    Parameters
    ----------
    m0, m2, m4 : float
        Spectral moments [m^2], [-], [1/m^2] (paper 002 eqs. 1-3).
    sample : Material
        The rough, softer body (its Poisson's ratio enters K, its hardness omega_c).
    counter_body : Material, optional
        The flat (default rigid).
    hardness : float, optional
        H [Pa] (default ``sample.hardness``).
    modulus_form : {"standard", "paper002_eq7_printed"}
        E' of eq. 7: Hertz's :func:`~roughcontact.materials.contact_modulus` (default), or the
        equation as printed, :func:`printed_contact_modulus`.

    Returns
    -------
    AsperityParameters

    Raises
    ------
    InputError
        Moments with alpha < 0.8968 (field ``m2``), no hardness, invalid materials.
    """
    hardness = sample.hardness if hardness is None else hardness
    if hardness is None:
        raise InputError("hardness", "the sample material has no hardness.", "pass hardness= in Pa.")
    mccool = mccool_parameters(m0=m0, m2=m2, m4=m4)
    if modulus_form not in MODULUS_FORMS:
        raise InputError(
            "modulus_form", f"unknown form {modulus_form!r}.", f"choose one of {sorted(MODULUS_FORMS)}."
        )
    modulus = MODULUS_FORMS[modulus_form](sample, counter_body)
    scales = dict(
        hardness=hardness,
        poissons_ratio=sample.poissons_ratio,
        contact_modulus=modulus,
        radius=mccool.summit_radius,
    )
    omega_c = ep.critical_interference(**scales)
    return AsperityParameters(
        m0=m0,
        m2=m2,
        m4=m4,
        bandwidth=mccool.bandwidth,
        summit_density=mccool.summit_density,
        summit_radius=mccool.summit_radius,
        summit_height_std=mccool.summit_height_std,
        summit_mean_offset=mccool.summit_mean_offset,
        contact_modulus=modulus,
        contact_pressure_factor=ep.contact_pressure_factor(sample.poissons_ratio),
        critical_interference=omega_c,
        critical_load=ep.critical_load(**scales),
        plasticity_index=ep.plasticity_index(mccool.summit_height_std, omega_c),
    )
