r"""Study kind ``asperity``: McCool asperity parameters and the statistical KKE load-unload of one surface.

One case is a rough surface against a flat (seed paper 002, sections IV-V):

* the spectral moments m0, m2, m4 (eqs. 1-3), from a study topography (``topography``, through
  :func:`~roughcontact.topography.statistics.spectral_moments`) or given (``m0``, ``m2``, ``m4``);
* McCool's summit radius R_asp = 0.375 sqrt(pi / m4) (eq. 4) and summit height deviation
  sigma_s = sqrt(1 - 0.8968 m2^2 / (m0 m4)) sqrt(m0) (eq. 5), the composite modulus E' (eq. 7),
  K = 0.454 + 0.41 nu (eq. 8), the critical interference omega_c = (pi K H / 2E')^2 R_asp (eq. 6),
  the Hertz load at omega_c and the plasticity index psi = sqrt(sigma_s / omega_c) (eq. 9), all from
  :func:`~roughcontact.asperity.parameters.asperity_parameters`;
* with ``max_force`` and ``nominal_area``, the statistical Kadin-Kogut-Etsion load-unload curve
  (:func:`~roughcontact.asperity.statistical_load_unload`): Gaussian (or measured) summit heights,
  each summit loaded on the chosen law (``kogut_etsion`` by default; ``paper002_eq10`` is eq. 10
  read as W / W_c = 1.32 (omega / omega_c - 1)^1.27 + 1 with W_c the Hertz load at omega_c) and
  unloaded on eq. 11, W = W_max ((omega - omega_res) / (omega_max - omega_res))^n_p with
  n_p = 1.5 (omega_max / omega_c)^-0.0331 and omega_res(omega_max) of Etsion, Kligerman and Kadin
  (2005), which the paper does not give.

Eq. 7 is printed with (1 - nu); the default ``modulus_form = "standard"`` uses (1 - nu^2), the only
reading that reproduces the paper's omega_c = 0.0125 um and psi = 1.86 (E' = 7.97 GPa); the printed
form is kept as ``modulus_form = "paper002_eq7_printed"``. The printed E' = 8.31 GPa matches neither.

Assumptions stated by the models: the flat is smooth (its roughness is not added to the summits'),
the summits are spherical with McCool's mean radius, the asperities do not interact, and the bulk
under them does not deform. The interference is zero at ``reference_force`` on loading (paper 002
marks omega = 0 at 25 uN), or is measured from the summits' mean plane without one.

Scalars: the asperity parameters (plain names: ``summit_radius``, ``summit_height_std``,
``contact_modulus``, ``critical_interference``, ``plasticity_index``, ...) and, with a curve, the
peak interference and the ``interference_at_return_force`` (where unloading comes back to the
``return_force``: ``reference_force``, paper 002's 25 uN; not a residual interference at zero load,
which a Gaussian population does not reach), both also over omega_c. Dataset: the curve
(``branch``, ``approach`` (the interference), ``interference_ratio``, ``separation``, ``force``,
``contact_area``, ``number_of_contacts``, ``plastic_fraction``) on the dimension ``point``.

Figures: ``load_interference`` (paper 002 Fig. 7: load against omega / omega_c, loading solid,
unloading dashed, with the measured curve of ``[analysis.compare]``) and ``contact_area`` (real
contact area against load, loading and unloading). Table: ``paper002`` (section IV: printed values against
this study's, for the cases with ``paper002 = true``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import AfterValidator, Field, model_validator
from pydantic_core import PydanticCustomError

from ...asperity.load_unload import LOADING_LAWS, StatisticalLoadUnload
from ...asperity.parameters import AsperityParameters
from ..kind import CaseOutput, CaseParameters, Kind, figure, fill_from_paper
from ..schema import Area, Force, InverseArea, MaterialName, Pressure, Strict, TopographyName


def _positive(unit: str):
    def check(value: float) -> float:
        if not (math.isfinite(value) and value > 0):
            raise PydanticCustomError(
                "quantity",
                "must be positive, got {value}",
                {
                    "value": f"{value:.6g} {unit}".strip(),
                    "fix": "spectral moments are > 0 (paper 002 eqs. 1-3)",
                },
            )
        return value

    return AfterValidator(check)


class AsperityKeys(CaseParameters):
    """Keys of a ``model = "asperity"`` analysis (SI after validation).

    Attributes
    ----------
    topography : str, optional
        A study topography whose moments (eqs. 1-3) are used; or give ``m0``, ``m2``, ``m4``.
    m0, m2, m4 : float, optional
        Spectral moments [m^2], [-], [1/m^2] (``m0 = "0.00213279 um^2"``, ``m4 = "0.0171036 1/um^2"``).
    material : str
        The rough, softer body (its hardness sets omega_c, its nu sets K).
    counter_body : str, optional
        The flat (default: rigid).
    hardness, yield_strength : float, optional
        Overrides of the material's H and S_y [Pa] (S_y only enters the Jackson-Green law).
    modulus_form : {"standard", "paper002_eq7_printed"}
        E' of eq. 7 with (1 - nu^2) (default) or with (1 - nu) as printed.
    max_force, nominal_area : float, optional
        Peak load [N] and nominal area [m^2] of the load-unload curve (both or neither).
    law : str
        Loading law of one summit (:data:`~roughcontact.asperity.load_unload.LOADING_LAWS`).
    distribution : {"gaussian", "measured"}
        Summit heights: Gaussian of sigma_s, or the 8-neighbour maxima of ``topography``.
    reference_force : float, optional
        Load of zero interference [N] (paper 002: 25 uN); both branches end there.
    steps : int
        Points per branch of the curve.
    paper002 : bool
        Fill in paper 002's printed moments (unless ``topography``), the film and punch, the loads
        and the island's area (:func:`roughcontact.papers.paper002.asperity_keys`) where the
        analysis leaves them out, and add the case to the ``paper002`` table (section IV's printed
        values against ours).
    """

    topography: TopographyName | None = None
    m0: Annotated[Area, _positive("m^2")] | None = None
    m2: Annotated[float, _positive("")] | None = None
    m4: Annotated[InverseArea, _positive("1/m^2")] | None = None
    material: MaterialName
    counter_body: MaterialName | None = None
    hardness: Pressure | None = None
    yield_strength: Pressure | None = None
    modulus_form: Literal["standard", "paper002_eq7_printed"] = "standard"
    max_force: Force | None = None
    nominal_area: Area | None = None
    law: Literal[LOADING_LAWS] = "kogut_etsion"  # type: ignore[valid-type]
    distribution: Literal["gaussian", "measured"] = "gaussian"
    reference_force: Force | None = None
    steps: int = Field(default=40, ge=2)
    paper002: bool = False

    @model_validator(mode="before")
    @classmethod
    def _paper002_scenario(cls, data: Any) -> Any:
        from ...papers.paper002 import asperity_keys

        def keys(given: Mapping[str, Any]) -> dict[str, Any]:
            keys = asperity_keys()
            if "topography" in given:  # the moments are the surface's own
                keys = {k: v for k, v in keys.items() if k not in ("m0", "m2", "m4")}
            return keys

        return fill_from_paper(data, "paper002", keys)

    @model_validator(mode="after")
    def _consistent(self) -> AsperityKeys:
        moments = [k for k in ("m0", "m2", "m4") if getattr(self, k) is not None]
        if (self.topography is None) == (not moments) or (moments and len(moments) != 3):
            found = (
                ", ".join(f"«{k}»" for k in (["topography"] if self.topography is not None else []) + moments)
                or "none"
            )
            raise PydanticCustomError(
                "quantity",
                "give exactly one of «topography» or the three moments «m0», «m2», «m4» (found {found})",
                {
                    "found": found,
                    "fix": "e.g. «topography=scan», or «m0=0.00213 um^2», «m2=0.0023», «m4=0.0171 1/um^2»",
                },
            )
        if moments:
            from ...errors import InputError
            from ...topography.statistics import mccool_parameters

            try:
                mccool_parameters(m0=self.m0, m2=self.m2, m4=self.m4)
            except InputError as error:
                raise PydanticCustomError(
                    "quantity", "«m0», «m2», «m4»: {detail}", {"detail": error.problem, "fix": error.fix}
                ) from None
        if (self.max_force is None) != (self.nominal_area is None):
            raise PydanticCustomError(
                "quantity",
                "a load-unload curve needs both «max_force» and «nominal_area»",
                {"fix": "e.g. «max_force=1000 uN» and «nominal_area=625 um^2» (25 um x 25 um)"},
            )
        if self.reference_force is not None and (
            self.max_force is None or not 0 < self.reference_force < self.max_force
        ):
            raise PydanticCustomError(
                "quantity",
                "«reference_force» must lie between 0 and «max_force»",
                {"fix": "e.g. «reference_force=25 uN» with «max_force=1000 uN»"},
            )
        if self.distribution == "measured" and self.topography is None:
            raise PydanticCustomError(
                "quantity",
                "«distribution=measured» takes the summit heights of a surface",
                {"fix": "give a surface («topography»), or use «distribution=gaussian»"},
            )
        return self


class MeasuredCurve(Strict):
    """``[analysis.compare]``: a measured load-interference curve drawn with the models' curves.

    ``measured_curve`` is a CSV file of interference and load rows below a header line that gives
    their units (``interference [nm],load [uN]``, or ``interference_m,force_N``), read by
    :func:`roughcontact.experiment.load_curve.read_load_curve` when the study is validated; its
    zero of interference should follow the analyses' (paper 002: zero at 25 uN).
    """

    measured_curve: Path

    def check(self) -> None:
        """Read the curve at validation time: a file without units fails before the cases run."""
        from ...experiment.load_curve import read_load_curve

        read_load_curve(self.measured_curve)


def _moments(parameters: AsperityKeys, inputs) -> tuple[dict[str, float], object]:
    """Return the moments of the case (SI) and its topography (None for given moments)."""
    if parameters.topography is None:
        return {"m0": parameters.m0, "m2": parameters.m2, "m4": parameters.m4}, None
    from ...topography.statistics import spectral_moments

    surface = inputs.topography(parameters.topography)
    found = spectral_moments(surface)
    return {"m0": found.m0, "m2": found.m2, "m4": found.m4}, surface


def run(parameters: AsperityKeys, inputs) -> CaseOutput:
    """Asperity parameters (equations 4-9) and, with ``max_force``, the KKE load-unload curve."""
    from ...asperity import statistical_load_unload
    from ...asperity.greenwood_williamson import summits_of
    from ...asperity.parameters import asperity_parameters
    from ...topography.statistics import mccool_parameters

    moments, surface = _moments(parameters, inputs)
    sample = inputs.material(parameters.material)
    found = asperity_parameters(
        **moments,
        sample=sample,
        counter_body=inputs.material(parameters.counter_body),
        hardness=parameters.hardness,
        modulus_form=parameters.modulus_form,
    )
    scalars = found.scalars()
    if parameters.max_force is None:
        return CaseOutput(scalars)
    statistical = statistical_load_unload(
        summits_of(mccool_parameters(**moments), parameters.distribution, surface),
        contact_modulus=found.contact_modulus,
        hardness=sample.hardness if parameters.hardness is None else parameters.hardness,
        poissons_ratio=sample.poissons_ratio,
        max_force=parameters.max_force,
        nominal_area=parameters.nominal_area,
        law=parameters.law,
        yield_strength=(
            sample.yield_strength if parameters.yield_strength is None else parameters.yield_strength
        ),
        reference_force=parameters.reference_force,
        steps=parameters.steps,
    )
    curve = statistical.scalars()
    omega_c = found.critical_interference
    scalars |= {
        "peak_force": curve["peak_force"],
        "peak_interference": curve["peak_interference"],
        "interference_at_return_force": curve["interference_at_return_force"],
        "return_force": curve["return_force"],
        "peak_interference_over_omega_c": curve["peak_interference"] / omega_c,
        "interference_at_return_force_over_omega_c": curve["interference_at_return_force"] / omega_c,
        "peak_contact_area": curve["peak_contact_area"],
        "peak_number_of_contacts": curve["peak_number_of_contacts"],
        "plastic_fraction_at_peak": curve["plastic_fraction_at_peak"],
    }
    return CaseOutput(scalars, statistical.to_xarray())


# --- figures and tables --------------------------------------------------------------------------


def measured_of(records, context) -> dict | None:
    """Return the measured curve of the analysis' ``[analysis.compare]`` table, or None."""
    compare = context.compare
    if compare is None or getattr(compare, "measured_curve", None) is None:
        return None
    from ...experiment.load_curve import read_load_curve

    return read_load_curve(Path(compare.measured_curve))


def _paper002_table(records, context):
    """Section IV of paper 002: printed values against this study's cases (``paper002 = true``).

    ``this_case`` is the stored value of the case (its moments, materials and ``modulus_form``);
    ``printed_inputs_standard`` and ``printed_inputs_eq7_printed`` recompute section IV from the
    printed moments and Table I in both readings of eq. 7
    (:func:`roughcontact.papers.paper002.comparison`). The rough-tip row adds the flat's 10 nm to
    sigma_s in quadrature (``this_case`` and ``printed_inputs_standard``) or linearly (the paper's
    2.06, ``printed_inputs_eq7_printed`` column).
    """
    from ...papers import paper002

    chosen = [r for r in records if r.parameters.get("paper002")]
    if not chosen:
        return None
    rows = []
    reference = paper002.comparison()
    for record in chosen:
        values = dict(record.scalars)
        sigma, omega_c = values["summit_height_std"], values["critical_interference"]
        values["plasticity_index_rough_tip"] = math.sqrt(math.hypot(sigma, paper002.TIP_ROUGHNESS) / omega_c)
        for row in reference:
            ours = values.get(row.key)
            rows.append(
                {
                    "case": record["case"],
                    "modulus_form": record.parameters.get("modulus_form"),
                    "quantity": row.key,
                    "symbol": row.symbol,
                    "unit": row.unit,
                    "paper": row.paper,
                    "this_case": ours,
                    "relative_deviation": (
                        None if row.paper is None or ours is None else ours / row.paper - 1.0
                    ),
                    "printed_inputs_standard": row.standard,
                    "printed_inputs_eq7_printed": row.printed_eq7,
                }
            )
    return rows


UNITS = AsperityParameters.UNITS | StatisticalLoadUnload.UNITS
"""Scalar name -> SI unit (the parameters' units come from their schema)."""

KIND = Kind(
    name="asperity",
    summary="McCool asperity parameters (R_asp, sigma_s, E', K, omega_c, psi) and the statistical KKE "
    "load-unload (paper 002)",
    parameters=AsperityKeys,
    run=run,
    units=UNITS,
    figures={
        "load_interference": figure("asperity.asperity_load_interference_figure", {"measured": measured_of}),
        "contact_area": figure("asperity.asperity_contact_area_figure"),
    },
    tables={"paper002": _paper002_table},
    compare=MeasuredCurve,
    headline=(
        "summit_radius",
        "summit_height_std",
        "critical_interference",
        "plasticity_index",
        "peak_interference",
    ),
    renamed={"surface": "topography", "counter": "counter_body"},
    references=(
        "paper002",
        "greenwood1966",
        "nayak1971",
        "mccool1986",
        "chang1987",
        "kogut2002",
        "jackson2005",
        "etsion2005",
        "kadin2006",
    ),
)
