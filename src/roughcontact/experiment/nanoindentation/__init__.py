"""Nanoindentation: Oliver-Pharr modulus with the viscous hold-creep correction of seed paper 001.

Seed paper 001 measures the moduli of its HDPE and POM balls by nanoindentation and evaluates
the load-displacement curves with Oliver and Pharr's method plus Tang and Ngan's viscous
correction, its eqs. 5-8. The modules, one job each:

:mod:`.curve`
    :class:`IndentationCurve`, one record in SI units, and its :class:`Segments` (loading, hold
    at maximum load, unloading) from :func:`detect_segments`.
:mod:`.files`
    :func:`read_indentation_csv` (any instrument's CSV export, units from the header) and
    :func:`write_indentation_csv`.
:mod:`.fits`
    The three fits that feed eq. 5: the unloading power law (:func:`fit_unloading`, Oliver and
    Pharr 1992), the end-of-hold creep rate (:func:`fit_creep`, Feng and Ngan 2002; Tang and
    Ngan 2003) and the unloading rate (:func:`unloading_rate`).
:mod:`.oliver_pharr`
    Eqs. 5-8 and the choices where the paper is silent: :func:`oliver_pharr` and its
    :class:`IndentationResult`, the Berkovich constants and :func:`berkovich_area`.
:mod:`.synthetic`
    :func:`synthetic_indentation_curve`, curves of known modulus (eqs. 6-8 backwards).

Everything is SI inside; :func:`read_indentation_csv` converts the file's units once.

Examples
--------
A creeping HDPE-like curve of 0.98 GPa: plain Oliver-Pharr overrates it, eq. 5 corrects it.

>>> from roughcontact.experiment.nanoindentation import oliver_pharr, synthetic_indentation_curve
>>> result = oliver_pharr(synthetic_indentation_curve(0.98e9, creep_rate=1e-9), fit_range=(0.8, 1.0))
>>> round(result.uncorrected_youngs_modulus / 1e9, 2), round(result.youngs_modulus / 1e9, 2)
(1.03, 0.98)

References
----------
Seed paper 001, eqs. 5-8, Fig. 7 and Table 2. doi:10.1115/1.4045900
"""

from .curve import MIN_POINTS, IndentationCurve, Segments, detect_segments
from .files import read_indentation_csv, write_indentation_csv
from .fits import (
    CREEP_FITS,
    MIN_FIT_POINTS,
    CreepFit,
    UnloadingFit,
    fit_creep,
    fit_unloading,
    unloading_rate,
)
from .oliver_pharr import (
    BERKOVICH_AREA_COEFFICIENT,
    EPSILON_BERKOVICH,
    RATE_SIGNS,
    IndentationResult,
    berkovich_area,
    oliver_pharr,
)
from .synthetic import synthetic_indentation_curve

__all__ = [
    "BERKOVICH_AREA_COEFFICIENT",
    "CREEP_FITS",
    "EPSILON_BERKOVICH",
    "MIN_FIT_POINTS",
    "MIN_POINTS",
    "RATE_SIGNS",
    "CreepFit",
    "IndentationCurve",
    "IndentationResult",
    "Segments",
    "UnloadingFit",
    "berkovich_area",
    "detect_segments",
    "fit_creep",
    "fit_unloading",
    "oliver_pharr",
    "read_indentation_csv",
    "synthetic_indentation_curve",
    "unloading_rate",
    "write_indentation_csv",
]
