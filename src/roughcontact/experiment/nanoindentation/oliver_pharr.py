r"""Oliver-Pharr modulus and hardness from a load-displacement curve, with the viscous hold-creep correction.

Seed paper 001 measures the moduli of its HDPE and POM balls by nanoindentation (Berkovich tip,
10 mN, 20 mN/min loading and unloading, 60 s hold; HDPE 0.98 GPa, POM 1.38 GPa, Table 2) and
evaluates the curves with Oliver and Pharr's method plus the viscous correction of Tang and
Ngan, its eqs. 5-8:

.. math::

    \frac{1}{S_e} = \frac{1}{S} + \frac{\dot d}{|\dot F|}                     \quad (5)

    E_r = \frac{\sqrt{\pi}}{2 \beta} \frac{S_e}{\sqrt{A_c(d_c)}}              \quad (6)

    d_c = d_{max} - \epsilon \frac{F_{max}}{S_e}                              \quad (7)

    \frac{1 - \nu_s^2}{E_s} = \frac{1}{E_r} - \frac{1 - \nu_i^2}{E_i}        \quad (8)

and the hardness, the mean pressure under the indenter at the maximum load (Oliver and Pharr
1992 and 2004), on the same contact area as eq. 6:

.. math::

    H = \frac{F_{max}}{A_c(d_c)}

S is the apparent stiffness dF/dd at the onset of unloading, from a power law
F = alpha (d - d_f)^m fitted to the upper part of the unloading curve (Oliver and Pharr 1992);
d_dot is the creep rate at the end of the hold at maximum load and F_dot the unloading rate at
the start of unloading (Tang and Ngan 2003: the creep carries on at its end-of-hold rate into
the unloading, so the measured displacement rate there is F_dot / S_e + d_dot). The three fits
are in :mod:`.fits`.

Choices where the paper is silent or wrong (see :doc:`the nanoindentation page </nanoindentation>`):

* ``rate_sign="magnitude"`` (default) uses ``|F_dot|`` in eq. 5: creep makes the apparent
  stiffness too high, and the correction must lower it. The paper prints the signed unloading
  rate; with F_dot < 0 that raises the stiffness instead. ``rate_sign="printed"`` keeps that
  literal form for reproducing it.
* The area function is not given: the default is the ideal Berkovich A_c = 24.5 d_c^2
  (:func:`berkovich_area`); pass ``area_function`` for a calibrated tip. beta = 1 as printed.
  The hardness uses the same A_c(d_c), with d_c from the corrected stiffness S_e (paper 001
  reports no hardness); ``uncorrected_hardness`` takes d_c from S, as plain Oliver-Pharr does.
* The unloading power law is fitted between 20 % and 95 % of F_max (``fit_range``).
* The creep rate at the end of the hold comes from the hold law of Feng and Ngan (2002)
  fitted to the whole hold (``creep_fit="tang_ngan"``), or from a straight line through its
  last ``creep_window`` (``creep_fit="linear"``); see :func:`.fits.fit_creep`.
* Without a time column, sample numbers stand in for time (uniform sampling assumed): the
  ratio d_dot / F_dot in eq. 5 is then still right, the rates themselves are per sample.

Everything is SI inside; :func:`.files.read_indentation_csv` converts the file's units once.

References
----------
W. C. Oliver and G. M. Pharr, "An improved technique for determining hardness and elastic modulus
using load and displacement sensing indentation experiments", J. Mater. Res. 7 (1992) 1564-1583.
doi:10.1557/JMR.1992.1564.
W. C. Oliver and G. M. Pharr, "Measurement of hardness and elastic modulus by instrumented
indentation: advances in understanding and refinements to methodology", J. Mater. Res. 19 (2004)
3-20. doi:10.1557/jmr.2004.19.1.3.
B. Tang and A. H. W. Ngan, "Accurate measurement of tip-sample contact size during nanoindentation
of viscoelastic materials", J. Mater. Res. 18 (2003) 1141-1148. doi:10.1557/JMR.2003.0156.
Seed paper 001, eqs. 5-8, Fig. 7 and Table 2. doi:10.1115/1.4045900
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...checks import poissons_ratio_checked, positive
from ...display_html import NotebookDisplay
from ...errors import InputError
from ...materials import Material, contact_modulus, get_material
from .curve import IndentationCurve, Segments, detect_segments
from .fits import MIN_FIT_POINTS, CreepFit, UnloadingFit, fit_creep, fit_unloading, unloading_rate

EPSILON_BERKOVICH = 0.75
"""Geometric constant epsilon of eq. 7 for a Berkovich (paraboloid-like) tip, as paper 001 uses."""

BERKOVICH_AREA_COEFFICIENT = 24.5
"""Ideal Berkovich area function A_c = 24.5 d_c^2 (paper 001 does not give its calibrated one)."""

RATE_SIGNS = ("magnitude", "printed")
"""Readings of eq. 5's unloading rate (``rate_sign`` of :func:`oliver_pharr`): ``|F_dot|`` or signed F_dot."""


def berkovich_area(contact_depth: float) -> float:
    """Projected contact area of an ideal Berkovich tip, A_c = 24.5 d_c^2 [m^2].

    Parameters
    ----------
    contact_depth : float
        Contact depth d_c [m].

    Returns
    -------
    float
        A_c [m^2].
    """
    return BERKOVICH_AREA_COEFFICIENT * contact_depth**2


@dataclass(frozen=True)
class IndentationResult(NotebookDisplay):
    """Oliver-Pharr analysis with the viscous correction (paper 001 equations 5-8), SI units.

    Attributes
    ----------
    stiffness : float
        Apparent unloading stiffness S = dF/dd at d_max from the power-law fit [N/m].
    corrected_stiffness : float
        S_e of eq. 5 [N/m] (equal to S without creep correction).
    max_depth, max_load : float
        d_max [m] and F_max [N] at the onset of unloading.
    contact_depth : float
        d_c of eq. 7 [m].
    contact_area : float
        A_c(d_c) [m^2].
    hardness : float
        H = F_max / A_c(d_c) [Pa] (Oliver and Pharr 2004), on the corrected contact area.
    reduced_modulus : float
        E_r of eq. 6 [Pa].
    youngs_modulus : float
        Sample modulus E_s of eq. 8 [Pa].
    uncorrected_reduced_modulus, uncorrected_youngs_modulus, uncorrected_hardness : float
        The same with S in place of S_e (plain Oliver-Pharr) [Pa].
    creep_rate : float
        d_dot at the end of the hold [m/s; m per sample when ``time_basis`` is ``"sample"``].
    unloading_rate : float
        Signed F_dot at the onset of unloading [N/s; N per sample when ``time_basis`` is
        ``"sample"``] (negative).
    time_basis : str
        ``"time"`` or ``"sample"`` (no time column: rates are per sample).
    unloading_fit : UnloadingFit
    creep_fit : CreepFit
    segments : Segments
    curve : IndentationCurve
    options : dict
        rate_sign, epsilon, beta, poissons_ratio, indenter name and its modulus and ratio.

    Notes
    -----
    Follows the result protocol of :mod:`roughcontact.results`: :meth:`scalars`, :attr:`UNITS`
    and :meth:`to_xarray`. :attr:`UNITS` gives the rates (``creep_rate``, ``unloading_rate``,
    ``creep_fit_k``) per second; a curve without a time column (``time_basis == "sample"``)
    has them per sample instead, m/sample and N/sample (only their ratio enters eq. 5).
    ``fit_alpha`` [N/m^fit_exponent] and ``creep_fit_a`` [m/s^(1/3)] have units of fitted or
    fractional powers, which no unit string of :mod:`roughcontact.units` writes, and are left
    out of :attr:`UNITS`.
    """

    stiffness: float
    corrected_stiffness: float
    max_depth: float
    max_load: float
    contact_depth: float
    contact_area: float
    hardness: float
    reduced_modulus: float
    youngs_modulus: float
    uncorrected_reduced_modulus: float
    uncorrected_youngs_modulus: float
    uncorrected_hardness: float
    creep_rate: float
    unloading_rate: float
    time_basis: str
    unloading_fit: UnloadingFit
    creep_fit: CreepFit
    segments: Segments
    curve: IndentationCurve
    options: dict

    FIGURE = "indentation.plot_indentation"
    """The figure a notebook shows under the table of scalars (:mod:`roughcontact.display_html`)."""

    UNITS: ClassVar[dict[str, str]] = {
        "stiffness": "N/m",
        "corrected_stiffness": "N/m",
        "max_depth": "m",
        "max_load": "N",
        "contact_depth": "m",
        "contact_area": "m^2",
        "hardness": "Pa",
        "reduced_modulus": "Pa",
        "youngs_modulus": "Pa",
        "uncorrected_reduced_modulus": "Pa",
        "uncorrected_youngs_modulus": "Pa",
        "uncorrected_hardness": "Pa",
        "creep_rate": "m/s",
        "unloading_rate": "N/s",
        "fit_final_depth": "m",
        "fit_rms_residual": "N",
        "creep_fit_d0": "m",
        "creep_fit_k": "m/s",
        "indenter_youngs_modulus": "Pa",
    }
    """SI unit of each dimensional scalar of :meth:`scalars` (rates per sample without a time column)."""

    def scalars(self) -> dict:
        """Return the scalar results and options as a flat dict (SI; JSON-ready).

        The plain names of :attr:`UNITS` and the dimensionless or label ones: ``time_basis``,
        ``fit_exponent``, ``fit_range_low`` and ``fit_range_high`` (fractions of F_max),
        ``fit_points``, ``creep_fit`` (the method) with its coefficients ``creep_fit_*``,
        ``fit_alpha`` (see the class notes), and the options ``rate_sign``, ``epsilon``,
        ``beta``, ``poissons_ratio``, ``indenter``, ``indenter_poissons_ratio``.
        """
        fit = self.unloading_fit
        return {
            "stiffness": self.stiffness,
            "corrected_stiffness": self.corrected_stiffness,
            "max_depth": self.max_depth,
            "max_load": self.max_load,
            "contact_depth": self.contact_depth,
            "contact_area": self.contact_area,
            "hardness": self.hardness,
            "reduced_modulus": self.reduced_modulus,
            "youngs_modulus": self.youngs_modulus,
            "uncorrected_reduced_modulus": self.uncorrected_reduced_modulus,
            "uncorrected_youngs_modulus": self.uncorrected_youngs_modulus,
            "uncorrected_hardness": self.uncorrected_hardness,
            "creep_rate": self.creep_rate,
            "unloading_rate": self.unloading_rate,
            "time_basis": self.time_basis,
            "fit_alpha": fit.alpha,
            "fit_final_depth": fit.final_depth,
            "fit_exponent": fit.exponent,
            "fit_range_low": fit.fit_range[0],
            "fit_range_high": fit.fit_range[1],
            "fit_points": fit.points,
            "fit_rms_residual": fit.rms_residual,
            "creep_fit": self.creep_fit.method,
            **{f"creep_fit_{k}": v for k, v in self.creep_fit.parameters.items()},
            **self.options,
        }

    def segment_labels(self) -> np.ndarray:
        """Return the segment of each sample: ``"loading"``, ``"hold"``, ``"unloading"`` or ``"none"``.

        The onset of unloading, the last point of the hold, counts as unloading; samples after
        an explicit end of the unloading (:meth:`Segments.from_indices`) are ``"none"``.
        """
        size = self.curve.depth.size
        labels = np.full(size, "none", dtype="<U9")
        hold, unloading = self.segments.hold, self.segments.unloading
        labels[: hold.start] = "loading"
        labels[hold.start : unloading.start] = "hold"
        labels[unloading] = "unloading"
        return labels

    def to_xarray(self):
        """Return the curve and the fitted unloading power law as an ``xarray.Dataset`` (SI).

        Variables on the dimension ``sample``: ``depth`` [m], ``load`` [N], ``time`` [s] (where
        the curve has a time column), ``segment`` (:meth:`segment_labels`), ``fit_load`` [N]
        (the power law F = alpha (d - d_f)^m at the measured depths of the unloading samples,
        NaN elsewhere) and ``in_fit_range`` (1 for the unloading samples the power law was
        fitted to, between ``fit_range_low`` and ``fit_range_high`` of F_max). Each has a
        ``units`` attribute; the attributes of the dataset are :meth:`scalars`.
        """
        import xarray as xr

        curve, fit = self.curve, self.unloading_fit
        labels = self.segment_labels()
        unloading = labels == "unloading"
        fit_load = np.full(curve.depth.size, np.nan)
        fit_load[unloading] = fit.load(curve.depth[unloading])
        low, high = fit.fit_range
        fitted = unloading & (curve.load >= low * self.max_load) & (curve.load <= high * self.max_load)
        data = {
            "depth": ("sample", curve.depth, {"units": "m", "long_name": "depth into the sample"}),
            "load": ("sample", curve.load, {"units": "N", "long_name": "load"}),
        }
        if curve.time is not None:
            data["time"] = ("sample", curve.time, {"units": "s", "long_name": "time"})
        data |= {
            "segment": ("sample", labels, {"units": "1", "long_name": "loading, hold or unloading"}),
            "fit_load": (
                "sample",
                fit_load,
                {"units": "N", "long_name": "unloading power law alpha (d - d_f)^m at the sample depths"},
            ),
            "in_fit_range": (
                "sample",
                fitted.astype(np.int8),
                {"units": "1", "long_name": "1 where the power law was fitted"},
            ),
        }
        return xr.Dataset(data, attrs=self.scalars())


def _modulus(stiffness, max_depth, max_load, epsilon, beta, area_function, field_name):
    contact_depth = max_depth - epsilon * max_load / stiffness  # eq. 7
    if not contact_depth > 0:
        raise InputError(
            field_name,
            f"gives a contact depth d_c = d_max - eps F_max / S = {contact_depth:.4g} m <= 0 "
            f"(d_max = {max_depth:.4g} m, F_max = {max_load:.4g} N, S = {stiffness:.4g} N/m).",
            "check the depth and load units and the zero of the depth, and epsilon.",
        )
    area = float(area_function(contact_depth))
    if not (math.isfinite(area) and area > 0):
        raise InputError(
            "area_function",
            f"returned {area!r} m^2 at d_c = {contact_depth:.4g} m.",
            "return a positive area in m^2.",
        )
    reduced = math.sqrt(math.pi) / (2.0 * beta) * stiffness / math.sqrt(area)  # eq. 6
    return contact_depth, area, reduced


def _youngs(reduced: float, indenter: Material, poissons_ratio: float) -> float:
    try:
        return reduced_modulus_to_youngs(reduced, indenter, poissons_ratio)  # eq. 8
    except InputError as error:
        if error.field != "reduced_modulus":
            raise
        raise InputError(
            "reduced_modulus",
            f"E_r = {reduced:.4g} Pa from the data is not below the indenter's own "
            f"E_i/(1-nu_i^2) = {contact_modulus(indenter):.4g} Pa: the sample would need a negative "
            "compliance.",
            "check the depth and load units (a depth in nm read as um makes E_r 1000x too high), the "
            "indenter, the area function and the frame compliance.",
        ) from None


def oliver_pharr(
    curve: IndentationCurve,
    *,
    indenter: Material | str = "diamond berkovich",
    poissons_ratio: float = 0.5,
    epsilon: float = EPSILON_BERKOVICH,
    beta: float = 1.0,
    area_function: Callable[[float], float] = berkovich_area,
    fit_range: tuple[float, float] = (0.2, 0.95),
    rate_sign: str = "magnitude",
    creep_fit: str = "tang_ngan",
    creep_window: float = 0.2,
    rate_window: float = 0.2,
    hold_tolerance: float = 0.01,
    segments: Segments | None = None,
) -> IndentationResult:
    """Sample modulus and hardness from a load-hold-unload curve: Oliver-Pharr with Tang-Ngan's correction.

    Implements seed paper 001 eqs. 5-8 and the hardness H = F_max / A_c(d_c) on the same contact
    area (Oliver and Pharr 2004; see the module docstring for the equations and choices).

    Parameters
    ----------
    curve : IndentationCurve
        The record in SI (:func:`read_indentation_csv` or ``IndentationCurve(depth, load, time)``).
    indenter : Material or str
        Indenter (default ``"diamond berkovich"``: 1141 GPa, 0.07, as paper 001).
    poissons_ratio : float
        Sample nu_s of eq. 8 (paper 001: 0.5 for the polymers).
    epsilon : float
        eq. 7's geometric constant (0.75).
    beta : float
        Tip-shape factor dividing eq. 6 (1, as printed; 1.034 is often used for Berkovich tips).
    area_function : callable
        A_c [m^2] of d_c [m]; default the ideal Berkovich 24.5 d_c^2 (paper 001 gives none).
    fit_range : (float, float)
        Fractions of F_max between which the unloading power law is fitted (default 20-95 %).
    rate_sign : {"magnitude", "printed"}
        ``"magnitude"`` (default): 1/S_e = 1/S + d_dot/``|F_dot|``, the correct reading that lowers
        the stiffness when the sample creeps. ``"printed"``: the paper's literal d_dot/F_dot with
        the signed (negative) unloading rate, which raises it instead; for reproduction only.
    creep_fit : {"tang_ngan", "linear", "none"}
        How the end-of-hold creep rate is found (:func:`fit_creep`); ``"none"``: no correction.
    creep_window : float
        Fraction of the hold for ``creep_fit="linear"``.
    rate_window : float
        The unloading rate is the slope of F(t) over the unloading points above (1 - rate_window) F_max.
    hold_tolerance : float
        Band around F_max that counts as the hold when the segments are detected.
    segments : Segments, optional
        Loading / hold / unloading index ranges; detected from the load when not given.

    Returns
    -------
    IndentationResult

    Raises
    ------
    InputError
        Bad options; too few points, no unloading, depth not falling with the load, no hold with
        creep correction on; a corrected compliance that is not positive; a contact depth that is
        not positive; a reduced modulus the indenter cannot give (negative sample compliance).
    """
    if rate_sign not in RATE_SIGNS:
        raise InputError("rate_sign", f"unknown value {rate_sign!r}.", f"choose one of {RATE_SIGNS}.")
    for name, value in (("epsilon", epsilon), ("beta", beta)):
        if not (isinstance(value, int | float) and math.isfinite(value) and value > 0):
            raise InputError(
                name, f"{value!r} is not a positive number.", f"e.g. {name}=1.0 (epsilon: 0.75)."
            )
    if isinstance(indenter, str):
        indenter = get_material(indenter)
    if not isinstance(curve, IndentationCurve):
        raise InputError(
            "curve",
            f"expected an IndentationCurve, got {type(curve).__name__}.",
            "wrap the arrays: IndentationCurve(depth, load, time).",
        )
    segments = segments or detect_segments(curve, hold_tolerance=hold_tolerance)
    depth, load, clock = curve.depth, curve.load, curve.clock
    loading = slice(segments.loading.start, segments.loading.stop)
    if (
        np.ptp(depth[loading]) > 0
        and depth[loading].size > 2
        and np.corrcoef(depth[loading], load[loading])[0, 1] < 0
    ):
        raise InputError(
            "depth",
            "decreases while the load increases on loading.",
            "give the depth positive into the sample (multiply it by -1), or check the columns.",
        )
    onset = segments.unloading.start
    d_max, f_max = float(depth[onset]), float(load[onset])
    if not f_max > 0:
        raise InputError(
            "load",
            f"is {f_max:.4g} N at the onset of unloading.",
            "check the sign and the column of the load.",
        )
    un = segments.unloading
    d_un, f_un, t_un = depth[un], load[un], clock[un]
    if d_un.size < MIN_FIT_POINTS or f_un.min() > fit_range[0] * f_max:
        raise InputError(
            "unloading",
            f"no unloading segment down to {fit_range[0]:.0%} of F_max after the maximum load.",
            "give the whole record including the unloading (or the segments), or raise fit_range's "
            "lower end.",
        )
    fit = fit_unloading(d_un, f_un, f_max, fit_range)
    stiffness = fit.stiffness(d_max)
    if not stiffness > 0:
        raise InputError(
            "unloading",
            f"the fitted stiffness at d_max is {stiffness:.4g} N/m.",
            "check the unloading data and fit_range.",
        )
    hold = segments.hold
    creep = fit_creep(clock[hold], depth[hold], creep_fit, window=creep_window)
    f_dot = unloading_rate(t_un, f_un, f_max, rate_window)
    denominator = abs(f_dot) if rate_sign == "magnitude" else f_dot
    compliance = 1.0 / stiffness + creep.rate / denominator  # eq. 5
    if not compliance > 0:
        raise InputError(
            "rate_sign",
            f"eq. 5 gives a corrected compliance 1/S_e = {compliance:.4g} m/N <= 0 "
            f"(S = {stiffness:.4g} N/m, d_dot = {creep.rate:.4g}, F_dot = {f_dot:.4g}).",
            "use rate_sign='magnitude' (the printed signed form over-corrects), or check the hold segment.",
        )
    corrected = 1.0 / compliance
    d_c, area, reduced = _modulus(
        corrected, d_max, f_max, epsilon, beta, area_function, "corrected_stiffness"
    )
    youngs = _youngs(reduced, indenter, poissons_ratio)
    _, plain_area, reduced_plain = _modulus(
        stiffness, d_max, f_max, epsilon, beta, area_function, "stiffness"
    )
    youngs_plain = _youngs(reduced_plain, indenter, poissons_ratio)
    return IndentationResult(
        stiffness=stiffness,
        corrected_stiffness=corrected,
        max_depth=d_max,
        max_load=f_max,
        contact_depth=d_c,
        contact_area=area,
        hardness=f_max / area,
        reduced_modulus=reduced,
        youngs_modulus=youngs,
        uncorrected_reduced_modulus=reduced_plain,
        uncorrected_youngs_modulus=youngs_plain,
        uncorrected_hardness=f_max / plain_area,
        creep_rate=creep.rate,
        unloading_rate=f_dot,
        time_basis="time" if curve.time is not None else "sample",
        unloading_fit=fit,
        creep_fit=creep,
        segments=segments,
        curve=curve,
        options={
            "rate_sign": rate_sign,
            "epsilon": float(epsilon),
            "beta": float(beta),
            "poissons_ratio": float(poissons_ratio),
            "indenter": indenter.name,
            "indenter_youngs_modulus": indenter.youngs_modulus,
            "indenter_poissons_ratio": indenter.poissons_ratio,
        },
    )


def reduced_modulus_to_youngs(reduced_modulus: float, indenter: Material, poissons_ratio: float) -> float:
    r"""Young's modulus of an indented sample from its reduced modulus (Oliver-Pharr) [Pa].

    .. math:: \frac{1 - \nu_s^2}{E_s} = \frac{1}{E_r} - \frac{1 - \nu_i^2}{E_i}

    Parameters
    ----------
    reduced_modulus : float
        Measured reduced modulus E_r [Pa].
    indenter : Material
        Indenter tip, e.g. ``get_material("diamond berkovich")`` (1141 GPa, 0.07).
    poissons_ratio : float
        Poisson's ratio of the sample nu_s [-] (paper 001 takes 0.5 for the polymers).

    Returns
    -------
    float
        Sample Young's modulus E_s [Pa].

    Raises
    ------
    InputError
        A non-positive reduced modulus, an invalid Poisson's ratio, or a reduced modulus not
        below the indenter's own E_i / (1 - nu_i^2) (the sample would need a negative compliance).

    References
    ----------
    W. C. Oliver and G. M. Pharr, J. Mater. Res. 7 (1992) 1564-1583. doi:10.1557/JMR.1992.1564.
    Seed paper 001, eq. 8. doi:10.1115/1.4045900
    """
    positive(reduced_modulus, "reduced_modulus", example="3e9", unit="Pa")
    poissons_ratio_checked(poissons_ratio)
    sample_compliance = 1.0 / reduced_modulus - 1.0 / contact_modulus(indenter)  # (1 - nu_i^2) / E_i
    if sample_compliance <= 0:
        raise InputError(
            "reduced_modulus",
            f"{reduced_modulus:.4g} Pa is not below the indenter's own modulus "
            f"E_i/(1-nu_i^2) = {contact_modulus(indenter):.4g} Pa.",
            "check the units of the reduced modulus and the indenter properties.",
        )
    return (1.0 - poissons_ratio**2) / sample_compliance
