r"""Study kind ``nanoindentation``: a sample's modulus and hardness from a load-displacement curve.

One case is one indentation record (a CSV of depth, load and, where recorded, time; columns found
by name, units from the header or the ``*_unit`` keys;
:func:`~roughcontact.experiment.nanoindentation.read_indentation_csv`) analysed by
:func:`~roughcontact.experiment.nanoindentation.oliver_pharr`: Oliver and Pharr's method with
Tang and Ngan's correction for the creep at the end of the hold, as paper 001 measures its balls'
moduli (Table 2, eqs. 5-8), and the hardness on the same contact area (Oliver and Pharr 2004):

.. math::

    \frac{1}{S_e} = \frac{1}{S} + \frac{\dot d}{|\dot F|} \quad (5), \qquad
    E_r = \frac{\sqrt{\pi}}{2 \beta} \frac{S_e}{\sqrt{A_c(d_c)}} \quad (6), \qquad
    d_c = d_{max} - \epsilon \frac{F_{max}}{S_e} \quad (7), \qquad
    \frac{1 - \nu_s^2}{E_s} = \frac{1}{E_r} - \frac{1 - \nu_i^2}{E_i} \quad (8), \qquad
    H = \frac{F_{max}}{A_c(d_c)}.

The readings where the paper is wrong or silent are named keys: ``rate_sign`` (``magnitude``,
default: |F_dot| in eq. 5, so creep lowers the stiffness; ``printed``: the signed unloading rate
as printed, which raises it), ``creep_fit`` (the t^(1/3) hold law of Feng and Ngan, a line on the
end of the hold, or none) and the ideal Berkovich area A_c = 24.5 d_c^2 (the paper gives none).
The file is read when the study is validated.

Scalars: :meth:`~roughcontact.experiment.nanoindentation.IndentationResult.scalars` (the sample's
Young's modulus and the hardness with and without the correction, the reduced modulus,
stiffnesses, contact depth and area, the rates). Dataset: its ``to_xarray()`` (the curve, its
segments and the fitted unloading law). Figure: ``indentation`` (the curve, the fit and the
tangent at the onset of unloading, paper 001 Fig. 7).

References
----------
Oliver and Pharr (1992), doi:10.1557/JMR.1992.1564; Oliver and Pharr (2004),
doi:10.1557/jmr.2004.19.1.3; Tang and Ngan (2003), doi:10.1557/JMR.2003.0156;
seed paper 001, eqs. 5-8, Fig. 7, Table 2 (doi:10.1115/1.4045900).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Literal

from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...experiment.nanoindentation import CREEP_FITS, RATE_SIGNS, IndentationResult
from ..kind import CaseOutput, CaseParameters, Kind, figure
from ..schema import MaterialName


class NanoindentationParameters(CaseParameters):
    """Keys of a ``model = "nanoindentation"`` analysis.

    Attributes
    ----------
    curve : Path
        The record: a CSV of depth, load and (optional) time, relative to the study file.
    depth_column, load_column, time_column : str, optional
        Header of a column (without its unit) where it is not found by name.
    depth_unit, load_unit, time_unit : str, optional
        Unit of a column, overriding its header's (e.g. ``"nm"``, ``"mN"``, ``"s"``).
    indenter : str
        The tip's material (default ``"diamond berkovich"``: 1141 GPa, 0.07, as paper 001).
    poissons_ratio : float
        The sample's nu_s in eq. 8 (paper 001: 0.5 for its polymers).
    epsilon, beta : float
        Eq. 7's geometric constant (0.75) and eq. 6's tip-shape factor (1, as printed).
    fit_range : list of float
        Fractions of F_max between which the unloading power law is fitted (default 0.2, 0.95).
    rate_sign : {"magnitude", "printed"}
        Eq. 5 with |F_dot| (default) or with the signed rate as printed.
    creep_fit : {"tang_ngan", "linear", "none"}
        How the creep rate at the end of the hold is found.
    """

    curve: Path
    depth_column: str | None = None
    load_column: str | None = None
    time_column: str | None = None
    depth_unit: str | None = None
    load_unit: str | None = None
    time_unit: str | None = None
    indenter: MaterialName = "diamond berkovich"
    poissons_ratio: Annotated[float, Field(gt=-1.0, le=0.5)] = 0.5
    epsilon: Annotated[float, Field(gt=0.0)] = 0.75
    beta: Annotated[float, Field(gt=0.0)] = 1.0
    fit_range: list[float] = Field(default_factory=lambda: [0.2, 0.95], min_length=2, max_length=2)
    rate_sign: Literal[RATE_SIGNS] = "magnitude"  # type: ignore[valid-type]
    creep_fit: Literal[CREEP_FITS] = "tang_ngan"  # type: ignore[valid-type]

    @model_validator(mode="after")
    def _fit_range(self) -> NanoindentationParameters:
        low, high = self.fit_range
        if not 0.0 <= low < high <= 1.0:
            raise PydanticCustomError(
                "quantity",
                "fit_range {low} {high} is not 0 <= LOW < HIGH <= 1",
                {"low": low, "high": high, "fix": "e.g. fit_range = [0.2, 0.95]"},
            )
        return self


POSITIVE = (
    "youngs_modulus",
    "reduced_modulus",
    "uncorrected_youngs_modulus",
    "uncorrected_reduced_modulus",
    "hardness",
    "uncorrected_hardness",
    "max_depth",
    "max_load",
    "contact_depth",
)
"""Scalars that cannot be negative although their names do not say so (moduli, hardness, depths, load):
a spread over several curves (measured spots zipped with ``replicate``) stays above 0."""


def _read(parameters: NanoindentationParameters):
    from ...experiment.nanoindentation import read_indentation_csv

    return read_indentation_csv(
        parameters.curve,
        depth_column=parameters.depth_column,
        load_column=parameters.load_column,
        time_column=parameters.time_column,
        depth_unit=parameters.depth_unit,
        load_unit=parameters.load_unit,
        time_unit=parameters.time_unit,
    )


def check(parameters: NanoindentationParameters) -> None:
    """Read the record at validation time (its errors name the file, the column or the unit)."""
    _read(parameters)


def run(parameters: NanoindentationParameters, inputs) -> CaseOutput:
    """Analyse the record: Oliver-Pharr with the hold-creep correction (equations 5-8), and the hardness."""
    from ...experiment.nanoindentation import oliver_pharr

    result = oliver_pharr(
        _read(parameters),
        indenter=inputs.material(parameters.indenter),
        poissons_ratio=parameters.poissons_ratio,
        epsilon=parameters.epsilon,
        beta=parameters.beta,
        fit_range=tuple(parameters.fit_range),
        rate_sign=parameters.rate_sign,
        creep_fit=parameters.creep_fit,
    )
    return CaseOutput(result.scalars(), result.to_xarray())


KIND = Kind(
    name="nanoindentation",
    summary="sample modulus and hardness from a load-displacement curve: Oliver-Pharr with the hold-creep "
    "correction (paper 001 eqs. 5-8)",
    parameters=NanoindentationParameters,
    run=run,
    units=IndentationResult.UNITS,
    figures={"indentation": figure("indentation.indentation_figure")},
    check=check,
    headline=("youngs_modulus", "uncorrected_youngs_modulus", "reduced_modulus", "hardness", "contact_depth"),
    bounds=dict.fromkeys(POSITIVE, (0.0, math.inf)),
    references=(
        "paper001",
        "oliver1992",
        "tang2003",
        "feng2002",
    ),
)
